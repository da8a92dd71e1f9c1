//! What an adjoint gradient costs, in one process: the gradient of one objective with respect
//! to every parameter of an LC ladder (each cell's inductance and capacitance, `N_θ = 2N`)
//! against one plain solve of the same run, and against the forward sensitivities to all of
//! them, so that the ratios are free of the machine's speed.
//!
//! The ladder's cells differ (`l_j = 1 + 0.3 sin j`), it starts from a flux pulse at rest, and
//! runs over 5 s at `rtol = atol = 1e-8`; the objective is `½ |q(T)|²`. The adjoint side records
//! the run ([`Radau::record`]) and sweeps back ([`Recording::gradient`]); the forward side solves
//! with the sensitivities to all `N_θ` parameters and samples them at the end. Each pair is timed
//! in 11 alternating pairs and the ratio is the median of the pairs' ratios; the forward side
//! only up to 100 parameters. Ladders of 5, 50, 500 and 5000 cells: 10 to 10⁴ parameters. Run:
//! `cargo bench -p dirac-benches --bench adjoint`.
//!
//! `cargo bench -p dirac-benches --bench adjoint -- peers setup DIR` and `… -- peers DIR` are the
//! dirac side of the comparison with SUNDIALS IDAS's adjoint (`benches/peers/adjoint.sh`), at
//! equal achieved error. `setup` writes, for each ladder, into `DIR/<cells>/` the consistent
//! start `y0.txt`, its derivative `yp0.txt` (`(v, 0, ṗ, 0)`), the cells' `l.txt` and `c.txt`,
//! and `reference.txt`: the objective `∫ ½ |q|² dt` (a running cost) and its gradient, `l_j c_j`
//! a line, by dirac at `rtol = atol = 1e-12` (the IDAS driver reports how far its own tightest
//! gradient lies from it, an independent check). The timing run prints the work-precision CSV
//! `problem,tol,error,seconds,steps` (problem `ladder<cells>`) over tolerances 1e-5 to 1e-10:
//! the error is the largest difference from the reference gradient over its largest entry, the
//! seconds the median of 5 gradients (recording and sweep).
//!
//! [`Radau::record`]: dirac::Radau::record
//! [`Recording::gradient`]: dirac::adjoint::Recording::gradient

#![allow(missing_docs)]

use dirac_benches::zoo;

#[path = "support/paired.rs"]
mod paired;
#[path = "support/start.rs"]
mod start;

use std::hint::black_box;

use dirac::State;
use dirac::adjoint::Objective;
use dirac::prelude::*;
use paired::paired;
use start::{write_start, write_values};
use zoo::*;

fn options() -> RadauOptions {
    RadauOptions::tolerances(1e-8, 1e-8)
}

/// The sizes and tolerances of the comparison with IDAS, and the reference's tolerance.
const PEER_CELLS: [usize; 4] = [5, 50, 500, 5000];
const PEER_TOLERANCES: [f64; 6] = [1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10];
const REFERENCE_TOLERANCE: f64 = 1e-12;

/// The ladder of `n` cells of the comparison with IDAS, and its start.
fn peer_ladder(n: usize) -> (Ladder, State<Ladder>) {
    let mut ladder = unit_ladder(n);
    for (j, cell) in ladder.cells.iter_mut().enumerate() {
        cell.l = 1.0 + 0.3 * (j as f64).sin();
    }
    let start = ladder_at_rest(&ladder, &pulse(n));
    (ladder, start)
}

/// The indices of `l_j`, `c_j` (in that order, cell by cell) among the ladder's parameters:
/// found once, outside the timing (a search by name for each of 10⁴ parameters is quadratic).
fn peer_order(ladder: &Ladder) -> Vec<usize> {
    let names = ladder.parameter_names();
    let index: std::collections::HashMap<&str, usize> =
        names.iter().enumerate().map(|(k, name)| (name.as_str(), k)).collect();
    let at = |name: String| index[name.as_str()];
    (0..ladder.cells.len()).flat_map(|j| [at(format!("cells[{j}].l")), at(format!("cells[{j}].c"))]).collect()
}

/// `∫ ½ |q|² dt` over 5 s and its gradient, `l_j c_j` in `order`, at tolerance `tol`; and the
/// steps.
fn peer_gradient(ladder: &Ladder, start: &State<Ladder>, tol: f64, order: &[usize]) -> (Vec<f64>, usize) {
    let running = |_: f64, y: &State<Ladder>, out: &mut State<Ladder>| {
        out.q.copy_from(&y.q);
        0.5 * y.q.norm_squared()
    };
    let objective = Objective::running(&running);
    let mut radau = Radau::new(ladder, RadauOptions::tolerances(tol, tol)).expect("valid");
    let recording = radau.record(0.0, start, 5.0).expect("integrates");
    let g = recording.gradient(ladder, &objective).expect("a gradient");
    (std::iter::once(g.value).chain(order.iter().map(|&k| g.parameters[k])).collect(), recording.steps())
}

/// The dirac side of `benches/peers/adjoint.sh`: `setup` writes the problems and the reference
/// gradients; otherwise the work-precision rows against those references.
fn peers(dir: &std::path::Path, setup: bool) {
    if setup {
        for n in PEER_CELLS {
            let (ladder, start) = peer_ladder(n);
            let here = dir.join(n.to_string());
            std::fs::create_dir_all(&here).expect("a writable folder");
            write_start(&ladder, 0.0, &start, &here);
            write_values(&here.join("l.txt"), ladder.cells.iter().map(|c| c.l));
            write_values(&here.join("c.txt"), ladder.cells.iter().map(|c| c.c));
            let (reference, _) = peer_gradient(&ladder, &start, REFERENCE_TOLERANCE, &peer_order(&ladder));
            write_values(&here.join("reference.txt"), reference.into_iter());
        }
        return;
    }
    println!("problem,tol,error,seconds,steps");
    for n in PEER_CELLS {
        let (ladder, start) = peer_ladder(n);
        let text =
            std::fs::read_to_string(dir.join(n.to_string()).join("reference.txt")).expect("run setup first");
        let reference: Vec<f64> = text.split_whitespace().map(|x| x.parse().expect("a number")).collect();
        let scale = reference[1..].iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        let order = peer_order(&ladder);
        for tol in PEER_TOLERANCES {
            let (g, steps) = peer_gradient(&ladder, &start, tol, &order);
            let error =
                g[1..].iter().zip(&reference[1..]).fold(0.0_f64, |m, (a, b)| m.max((a - b).abs())) / scale;
            let mut times: Vec<f64> = (0..5)
                .map(|_| {
                    let clock = std::time::Instant::now();
                    black_box(peer_gradient(&ladder, &start, tol, &order));
                    clock.elapsed().as_secs_f64()
                })
                .collect();
            times.sort_by(f64::total_cmp);
            println!("ladder{n},{tol:e},{error:.3e},{:.6e},{steps}", times[2]);
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let Some(k) = args.iter().position(|a| a == "peers") {
        let setup = args.get(k + 1).is_some_and(|a| a == "setup");
        let dir = args.get(k + 1 + usize::from(setup)).expect("usage: adjoint peers [setup] DIR");
        peers(std::path::Path::new(dir), setup);
        return;
    }
    println!(
        "| cells | N_θ | steps | plain solve | adjoint gradient | ratio | forward sensitivities | ratio |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    let t_end = 5.0;
    for n in [5, 50, 500, 5000] {
        let mut ladder = unit_ladder(n);
        for (j, cell) in ladder.cells.iter_mut().enumerate() {
            cell.l = 1.0 + 0.3 * (j as f64).sin();
        }
        let start = ladder_at_rest(&ladder, &pulse(n));
        let count = ladder.parameter_count();
        let terminal = |_: f64, y: &State<Ladder>, out: &mut State<Ladder>| {
            out.clone_from(y);
            out.v.fill(0.0);
            out.p.fill(0.0);
            out.lambda.fill(0.0);
            0.5 * y.q.norm_squared()
        };
        let objective = Objective::terminal(&terminal);
        let sampling = Sampling::Times(vec![t_end]);
        let plain = || {
            let solution =
                Radau::new(&ladder, options()).expect("valid").solve(0.0, &start, t_end, &sampling);
            black_box(solution.expect("solves")).stats.steps
        };
        let adjoint = || {
            let mut radau = Radau::new(&ladder, options()).expect("valid");
            let recording = radau.record(0.0, &start, t_end).expect("integrates");
            black_box(recording.gradient(&ladder, &objective).expect("a gradient"));
            recording.steps()
        };
        assert_eq!(plain(), adjoint(), "the recording takes the plain solve's steps");
        let steps = plain();
        let (t_plain, t_adjoint, ratio) = paired(11, plain, adjoint);
        // The forward sensitivities to every parameter, up to 100 of them (beyond, their cost
        // only grows linearly: the crossover is far below).
        let forward = if count <= 100 {
            let wrt = Sensitivities::all_parameters(&ladder);
            let forward = || {
                let mut radau =
                    Radau::new(&ladder, options()).expect("valid").with_sensitivities(&wrt).expect("valid");
                let solution = radau.solve_with_sensitivities(0.0, &start, t_end, &sampling);
                black_box(solution.expect("solves")).stats.steps
            };
            let (_, t_forward, ratio) = paired(11, plain, forward);
            format!("{:.3} ms | {ratio:.2}", t_forward * 1e3)
        } else {
            "– | –".to_owned()
        };
        println!(
            "| {n} | {count} | {steps} | {:.3} ms | {:.3} ms | {ratio:.2} | {forward} |",
            t_plain * 1e3,
            t_adjoint * 1e3,
        );
    }
}
