//! What the consistent start of a large network costs, against one Radau step of it: a
//! series-RL ladder (each section a series resistor and inductor, a shunt resistor to ground:
//! no node has capacitance, so every node voltage is a velocity that only the resistors fix)
//! and the LC ladder of the same size, from netlists, for N = 10², 10³, 10⁴ and 10⁵ sections.
//! The start must cost like a step: linear in N. Each time is the median of 5 starts (of 5
//! steps of 1e-6 s after a start, for the step), alternating the two ladders. The circuit's
//! DC operating point (where a `.tran` without `uic` starts, computed when the netlist becomes
//! a circuit) is timed with the reading of the netlist and the building of its network: the
//! column "RL circuit", against the same netlist with `uic` (no operating point).
//!
//! Run: `cargo bench -p dirac-benches --bench starts`.

#![allow(missing_docs)]

use std::time::Instant;

use dirac::prelude::*;
use dirac::spice;

/// The series-RL ladder of `n` sections behind a 1 V source.
fn rl_ladder(n: usize) -> String {
    let mut text = format!("RL ladder of {n} sections\nV1 n0 0 1\n");
    for i in 1..=n {
        text += &format!("R{i} n{} m{i} 1\nL{i} m{i} n{i} 1m\nRS{i} n{i} 0 100\n", i - 1);
    }
    text + ".tran 1u 5u\n.end\n"
}

/// Seconds to read `text` and build its circuit.
fn circuit_of(text: &str) -> (spice::Circuit, f64) {
    let clock = Instant::now();
    let circuit = spice::parse(text).expect("reads").circuit().expect("a circuit");
    (circuit, clock.elapsed().as_secs_f64())
}

/// The LC ladder of `n` sections behind a 1 V source, for comparison: every node has
/// capacitance.
fn lc_ladder(n: usize) -> String {
    let mut text = format!("LC ladder of {n} sections\nV1 n0 0 1\n");
    for i in 1..=n {
        text += &format!("L{i} n{} n{i} 1m\nC{i} n{i} 0 1u\n", i - 1);
    }
    text + ".tran 1u 5u\n.end\n"
}

fn median(mut x: Vec<f64>) -> f64 {
    x.sort_by(f64::total_cmp);
    x[x.len() / 2]
}

/// Seconds of one consistent start, and of one step after it (over 5 steps).
fn start_and_step(circuit: &spice::Circuit) -> (f64, f64) {
    let clock = Instant::now();
    let start = circuit.start().expect("a consistent start");
    let started = clock.elapsed().as_secs_f64();
    let options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(1e-6, 1e-6) };
    let mut radau = Radau::new(&circuit.network, options).expect("valid options");
    radau.start(0.0, &start, 1.0).expect("starts");
    let clock = Instant::now();
    for _ in 0..5 {
        radau.step().expect("steps");
    }
    (started, clock.elapsed().as_secs_f64() / 5.0)
}

fn main() {
    println!(
        "| sections N | unknowns (RL) | RL circuit (op) | RL circuit (uic) | RL start | RL start / N | RL step | LC start | LC step |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for n in [100, 1_000, 10_000, 100_000] {
        let (with_op, from_rest) = (rl_ladder(n), rl_ladder(n).replace(".tran 1u 5u", ".tran 1u 5u uic"));
        let (mut op_builds, mut uic_builds) = (Vec::new(), Vec::new());
        for _ in 0..5 {
            op_builds.push(circuit_of(&with_op).1);
            uic_builds.push(circuit_of(&from_rest).1);
        }
        // The start and the steps from rest (`uic`): from the operating point, where both
        // ladders rest, the steps would be as long as the run.
        let rl = circuit_of(&from_rest).0;
        let lc = circuit_of(&lc_ladder(n).replace(".tran 1u 5u", ".tran 1u 5u uic")).0;
        let (mut rl_runs, mut lc_runs) = (Vec::new(), Vec::new());
        for _ in 0..5 {
            rl_runs.push(start_and_step(&rl));
            lc_runs.push(start_and_step(&lc));
        }
        let starts = |runs: &[(f64, f64)]| median(runs.iter().map(|r| r.0).collect());
        let steps = |runs: &[(f64, f64)]| median(runs.iter().map(|r| r.1).collect());
        let sizes = rl.network.sizes();
        println!(
            "| {n} | {} | {:.4} s | {:.4} s | {:.4} s | {:.2e} s | {:.4} s | {:.4} s | {:.4} s |",
            sizes.nq + sizes.nc,
            median(op_builds),
            median(uic_builds),
            starts(&rl_runs),
            starts(&rl_runs) / n as f64,
            steps(&rl_runs),
            starts(&lc_runs),
            steps(&lc_runs)
        );
    }
}
