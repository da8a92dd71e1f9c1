//! A parameter sweep on all cores against the sequential loop, in one process: 1000 runs of
//! the zoo's pendulum (lengths 0.5 … 1.5 m, released at the horizontal, 10 s of Radau at
//! tolerance 1e-8), each returning the final position. Both give the same results, bit for
//! bit; the speed-up is the sequential time over the `dirac::ensemble::sweep` time (median of
//! 5 of each, alternating).
//!
//! Run: `cargo bench -p dirac-benches --bench ensemble`.

#![allow(missing_docs)]

use std::time::Instant;

use dirac::ensemble::sweep;
use dirac::prelude::*;

use dirac_benches::zoo;

use zoo::Pendulum;

/// One run: the pendulum of length `l`, its position after 10 s.
fn run(l: f64) -> (f64, f64) {
    let p = Pendulum { m: 1.0, g: 9.81, l };
    let q = VecQ::<Pendulum>::new(l, 0.0);
    let start = consistent_state(&p, 0.0, &q, &VecQ::<Pendulum>::zeros(), Consistency::default())
        .expect("a consistent start");
    let mut radau = Radau::new(&p, RadauOptions::tolerances(1e-8, 1e-8)).expect("valid options");
    let end = radau.solve(0.0, &start, 10.0, &Sampling::Times(vec![10.0])).expect("integrates");
    let last = end.last().expect("a sample");
    (last.q[0], last.q[1])
}

fn main() {
    let lengths: Vec<f64> = (0..1000).map(|i| 0.5 + i as f64 / 1000.0).collect();
    let (mut sequential, mut parallel) = (Vec::new(), Vec::new());
    for _ in 0..5 {
        let clock = Instant::now();
        let a: Vec<(f64, f64)> = lengths.iter().map(|&l| run(l)).collect();
        sequential.push(clock.elapsed().as_secs_f64());
        let clock = Instant::now();
        let b = sweep(&lengths, |&l| run(l));
        parallel.push(clock.elapsed().as_secs_f64());
        assert_eq!(a, b, "a sweep returns what the loop returns, in the same order");
    }
    sequential.sort_by(f64::total_cmp);
    parallel.sort_by(f64::total_cmp);
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!("1000-run pendulum sweep on {cores} cores");
    println!("sequential loop: {:.3} s", sequential[2]);
    println!("dirac::ensemble::sweep: {:.3} s", parallel[2]);
    println!("speed-up: {:.2}× (ideal {cores}×)", sequential[2] / parallel[2]);
}
