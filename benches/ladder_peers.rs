//! dirac's Radau on the zoo's LC ladder at several tolerances, for the comparison with SUNDIALS
//! IDA and its sparse direct solver KLU in `benches/peers/ladder.sh`: CSV
//! `problem,tol,error,seconds,steps`, the error the largest nodal flux error at t = 10 against
//! the exact modal solution (`zoo::modal_solution`, each eigenpair checked against the ladder's
//! matrix), seconds the median of 3 solves from the consistent start.
//!
//! `cargo bench -p dirac-benches --bench ladder_peers -- setup DIR` writes what the IDA driver needs, computed
//! here so that both solvers start from the same state and are judged by the same reference:
//! `y0.txt` and `yp0.txt` (the consistent state `y = (q, v, p, λ)` and its derivative
//! `(v, 0, ṗ, 0)`), `nodes.txt` (the slot of each node flux `cells[j].b` in `y`) and `ref.txt`
//! (the exact fluxes at t = 10).
//!
//! The number of cells is `DIRAC_LADDER_CELLS` (default 10⁴).

#![allow(missing_docs)]

use std::io::Write;
use std::time::Instant;

use dirac::prelude::*;

use dirac_benches::zoo;

#[path = "support/start.rs"]
mod start;

use start::write_start;
use zoo::{Cell, Ladder, ladder_at_rest, modal_solution, pulse, unit_ladder};

const T_END: f64 = 10.0;

fn write(path: std::path::PathBuf, values: impl Iterator<Item = String>) {
    let mut f = std::io::BufWriter::new(std::fs::File::create(&path).expect("a writable file"));
    for v in values {
        writeln!(f, "{v}").expect("written");
    }
}

fn nodes(ladder: &Ladder, n: usize) -> Vec<usize> {
    (0..n).map(|j| ladder.cells(j, Cell::B).index()).collect()
}

fn main() {
    let n: usize = std::env::var("DIRAC_LADDER_CELLS").ok().and_then(|s| s.parse().ok()).unwrap_or(10_000);
    let ladder = unit_ladder(n);
    let x0 = pulse(n);
    let start = ladder_at_rest(&ladder, &x0);
    let args: Vec<String> = std::env::args().collect();
    if let Some(k) = args.iter().position(|a| a == "setup") {
        let dir = std::path::PathBuf::from(&args[k + 1]);
        let sizes = ladder.sizes();
        write_start(&ladder, 0.0, &start, &dir);
        write(dir.join("nodes.txt"), nodes(&ladder, n).into_iter().map(|i| i.to_string()));
        write(
            dir.join("ref.txt"),
            modal_solution(&x0, 1.0, 1.0, T_END).into_iter().map(|v| format!("{v:.17e}")),
        );
        println!("{} {} {}", sizes.nq, sizes.nc, sizes.nh);
        return;
    }
    let exact = modal_solution(&x0, 1.0, 1.0, T_END);
    let slots = nodes(&ladder, n);
    println!("problem,tol,error,seconds,steps");
    for tol in [1e-4, 1e-5, 1e-6, 1e-7, 1e-8] {
        let options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(tol, tol) };
        let mut times = Vec::new();
        let (mut error, mut steps) = (0.0, 0);
        for _ in 0..3 {
            let clock = Instant::now();
            let mut radau = Radau::new(&ladder, options).expect("valid options");
            let sol = radau.solve(0.0, &start, T_END, &Sampling::Times(vec![T_END])).expect("integrates");
            times.push(clock.elapsed().as_secs_f64());
            let end = sol.last().expect("a sample");
            error = slots.iter().zip(&exact).map(|(&i, x)| (end.q[i] - x).abs()).fold(0.0, f64::max);
            steps = sol.stats.steps;
        }
        times.sort_by(f64::total_cmp);
        println!("ladder,{tol:e},{error:.3e},{:.6e},{steps}", times[1]);
    }
}
