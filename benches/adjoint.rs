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
//! `cargo bench -p dirac-benches --bench adjoint -- peers DIR` is the dirac side of the comparison with SUNDIALS
//! IDAS's adjoint (`benches/peers/adjoint.sh`): for each ladder it writes into `DIR/<cells>/`
//! the consistent start `y0.txt`, its derivative `yp0.txt` (`(v, 0, ṗ, 0)`), the cells' `l.txt`
//! and `c.txt`, and `dirac.txt` (the objective `∫ ½ |q|² dt`, a running cost, and its gradient,
//! `l_j c_j` a line), and prints a CSV line `cells,n_theta,seconds,steps` with the median time of
//! 11 gradients (recording and sweep).
//!
//! [`Radau::record`]: dirac::Radau::record
//! [`Recording::gradient`]: dirac::adjoint::Recording::gradient

#![allow(missing_docs)]

#[path = "../tests/zoo/mod.rs"]
mod zoo;

#[path = "support/paired.rs"]
mod paired;
#[path = "support/start.rs"]
mod start;

use std::hint::black_box;

use dirac::adjoint::Objective;
use dirac::prelude::*;
use paired::paired;
use start::{write_start, write_values};
use zoo::*;

fn options() -> RadauOptions {
    RadauOptions::tolerances(1e-8, 1e-8)
}

/// The dirac side of `benches/peers/adjoint.sh`.
fn peers(dir: &std::path::Path) {
    println!("cells,n_theta,seconds,steps");
    for n in [5, 50, 500, 5000] {
        let mut ladder = unit_ladder(n);
        for (j, cell) in ladder.cells.iter_mut().enumerate() {
            cell.l = 1.0 + 0.3 * (j as f64).sin();
        }
        let start = ladder_at_rest(&ladder, &pulse(n));
        let here = dir.join(n.to_string());
        std::fs::create_dir_all(&here).expect("a writable folder");
        write_start(&ladder, 0.0, &start, &here);
        write_values(&here.join("l.txt"), ladder.cells.iter().map(|c| c.l));
        write_values(&here.join("c.txt"), ladder.cells.iter().map(|c| c.c));
        let running = |_: f64, y: &State<Ladder>, out: &mut State<Ladder>| {
            out.q.copy_from(&y.q);
            0.5 * y.q.norm_squared()
        };
        let objective = Objective::running(&running);
        let gradient = || {
            let mut radau = Radau::new(&ladder, options()).expect("valid");
            let recording = radau.record(0.0, &start, 5.0).expect("integrates");
            (recording.gradient(&ladder, &objective).expect("a gradient"), recording.steps())
        };
        let (g, steps) = gradient();
        let names = ladder.parameter_names();
        let at = |name: String| names.iter().position(|n| *n == name).expect("a parameter");
        let values = (0..n).flat_map(|j| [at(format!("cells[{j}].l")), at(format!("cells[{j}].c"))]);
        write_values(
            &here.join("dirac.txt"),
            std::iter::once(g.value).chain(values.map(|k| g.parameters[k])),
        );
        let mut times: Vec<f64> = (0..11)
            .map(|_| {
                let start = std::time::Instant::now();
                black_box(gradient());
                start.elapsed().as_secs_f64()
            })
            .collect();
        times.sort_by(f64::total_cmp);
        println!("{n},{},{:.6e},{steps}", 2 * n, times[5]);
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let Some(k) = args.iter().position(|a| a == "peers") {
        peers(std::path::Path::new(&args[k + 1]));
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
