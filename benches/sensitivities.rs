//! What forward sensitivities cost, in one process: a solve with `N_θ` sensitivities against
//! one plain solve of the same model, so that the ratio is free of the machine's speed. The
//! alternatives it is set against are `1 + N_θ` plain solves (what forward differences of
//! whole simulations cost: a gradient from one-sided differences) and `1 + 2 N_θ` (central
//! differences, which the accuracy of a fit usually needs).
//!
//! - the five-mass chain `MassSpringChain5` (ten parameters) over 20 s with `N_θ` = 1, 2, 5, 10;
//! - the interconnected chain of the paper (six parameters) over 20 s with all six;
//! - the pendulum in Cartesian coordinates (holonomic) over 10 s with its three parameters;
//! - the rolling disk (nonholonomic) over 10 s with its four parameters;
//! - the 8-link pendulum (nonlinear, eight angles) over 5 s with one and with its three
//!   parameters, and with its eight initial angles;
//! - the LC ladder (an array of cells, on the sparse path) of 10, 100 and 1000 cells over 5 s,
//!   with the initial fluxes of four nodes (arrays of subsystems expose no parameters).
//!
//! Every solve is at `rtol = atol = 1e-8`, recording the state every 0.1 s. The two solves of a
//! row are timed in 31 alternating pairs, and the ratio is the median of the pairs' ratios. Run:
//! `cargo bench -p dirac-benches --bench sensitivities` (`-- WORD` for the rows whose model names WORD).

#![allow(missing_docs)]

use dirac_benches::zoo;

#[path = "support/paired.rs"]
mod paired;

use std::hint::black_box;

use dirac::State;
use dirac::Storage;
use dirac::nalgebra::DefaultAllocator;
use dirac::prelude::*;
use paired::paired;
use zoo::*;

fn options() -> RadauOptions {
    RadauOptions::tolerances(1e-8, 1e-8)
}

/// One row: the median times of a plain solve and of one with the first `count` parameters'
/// sensitivities, and the ratio.
fn row<M: Parameters + Hybrid>(name: &str, model: &M, start: &State<M>, t_end: f64, count: usize)
where
    DefaultAllocator: Storage<M>,
{
    let names = model.parameter_names();
    let chosen: Vec<&str> = names.iter().take(count).map(String::as_str).collect();
    let wrt = Sensitivities::new(model).parameters(&chosen).expect("parameters");
    row_wrt(name, model, start, t_end, &wrt);
}

/// One row for the sensitivities `wrt`.
fn row_wrt<M: Parameters + Hybrid>(
    name: &str,
    model: &M,
    start: &State<M>,
    t_end: f64,
    wrt: &Sensitivities<M>,
) where
    DefaultAllocator: Storage<M>,
{
    // `cargo bench -p dirac-benches --bench sensitivities -- WORD` runs only the rows whose model names WORD.
    if let Some(word) = std::env::args().skip(1).find(|a| !a.starts_with('-'))
        && !name.contains(&word)
    {
        return;
    }
    let count = wrt.names().len();
    let sampling = Sampling::Every(0.1);
    let plain = || {
        let solution = Radau::new(model, options()).expect("valid").solve(0.0, start, t_end, &sampling);
        black_box(solution.expect("solves")).stats.steps
    };
    let with = || {
        let mut radau = Radau::new(model, options()).expect("valid").with_sensitivities(wrt).expect("valid");
        let solution = radau.solve_with_sensitivities(0.0, start, t_end, &sampling);
        black_box(solution.expect("solves")).stats.steps
    };
    assert_eq!(plain(), with(), "the sensitivities leave the steps alone");
    let steps = plain();
    let (plain, with, ratio) = paired(31, plain, with);
    println!(
        "| {name} | {count} | {steps} | {:.3} ms | {:.3} ms | {ratio:.2} | {} | {} | {:.2} |",
        plain * 1e3,
        with * 1e3,
        1 + count,
        1 + 2 * count,
        ratio / (1 + count) as f64,
    );
}

/// The paper chain's `x1(20)` and its sensitivities to its six parameters, to set beside the
/// peer's (`benches/peers/idas_sens.c`).
fn final_sensitivities(chain: &Chain, start: &State<Chain>) {
    let wrt = Sensitivities::all_parameters(chain);
    let mut radau = Radau::new(chain, options()).expect("valid").with_sensitivities(&wrt).expect("valid");
    let solution = radau.solve_with_sensitivities(0.0, start, 20.0, &Sampling::Every(0.1)).expect("solves");
    let x1 = Chain::left(Primitive1::X1);
    let last = solution.len() - 1;
    let d: Vec<String> = wrt
        .names()
        .iter()
        .map(|name| format!("{:.8}", solution.dq(x1, name).expect("recorded")[last]))
        .collect();
    println!();
    println!(
        "dirac x1(20) = {:.10}, d x1(20)/d({}) = {}",
        solution.q(x1)[last],
        wrt.names().join(", "),
        d.join(" ")
    );
}

fn main() {
    println!(
        "| model | N_θ | steps | plain solve | with sensitivities | ratio | forward differences | central differences | ratio / (1 + N_θ) |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    let chain = MassSpringChain5 {
        m1: 1.0,
        m2: 2.0,
        m3: 1.5,
        m4: 1.0,
        m5: 0.5,
        k1: 4.0,
        k2: 5.0,
        k3: 6.0,
        k4: 3.0,
        k5: 2.0,
    };
    let mut q = VecQ::<MassSpringChain5>::zeros();
    q[0] = 0.1;
    let start = consistent_state(&chain, 0.0, &q, &VecQ::<MassSpringChain5>::zeros(), Consistency::default())
        .expect("consistent");
    for count in [1, 2, 5, 10] {
        row("five-mass chain", &chain, &start, 20.0, count);
    }
    let paper = paper_chain();
    row("paper chain (interconnected)", &paper, &paper_chain_start(&paper), 20.0, 6);
    final_sensitivities(&paper, &paper_chain_start(&paper));
    let pendulum = Pendulum { m: 1.3, g: 9.81, l: 0.7 };
    row("pendulum (holonomic)", &pendulum, &horizontal_start(&pendulum), 10.0, 3);
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let v = VecQ::<RollingDisk>::new(0.6, 0.0, 2.0, 1.0);
    let start = consistent_state(&disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
        .expect("consistent");
    row("rolling disk (nonholonomic)", &disk, &start, 10.0, 4);
    let links = Pendulum8 { m: 0.5, l: 0.25, g: 9.81 };
    let q = VecQ::<Pendulum8>::from_fn(|i, _| 0.3 + 0.05 * i as f64);
    let start = consistent_state(&links, 0.0, &q, &VecQ::<Pendulum8>::zeros(), Consistency::default())
        .expect("consistent");
    for count in [1, 3] {
        row("8-link pendulum (nonlinear)", &links, &start, 5.0, count);
    }
    let angles = [
        Pendulum8::TH1,
        Pendulum8::TH2,
        Pendulum8::TH3,
        Pendulum8::TH4,
        Pendulum8::TH5,
        Pendulum8::TH6,
        Pendulum8::TH7,
        Pendulum8::TH8,
    ];
    let wrt = angles.into_iter().fold(Sensitivities::new(&links), |w, c| w.initial_position(c));
    row_wrt("8-link pendulum (nonlinear), initial angles", &links, &start, 5.0, &wrt);
    for n in [10, 100, 1000] {
        let ladder = unit_ladder(n);
        let centre = n as f64 / 3.0;
        let x: Vec<f64> = (1..=n).map(|j| (-((j as f64 - centre) / 5.0).powi(2)).exp()).collect();
        let start = ladder_at_rest(&ladder, &x);
        let wrt = (0..4)
            .fold(Sensitivities::new(&ladder), |w, j| w.initial_position(ladder.cells(j * n / 4, Cell::B)));
        row_wrt(&format!("LC ladder, {n} cells (sparse)"), &ladder, &start, 5.0, &wrt);
    }
}
