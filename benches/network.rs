//! What assembling a model while the program runs costs: the zoo's LC ladder as a derived
//! interconnection (`Ladder`, an array of cells on the sparse path) and as a run-time
//! [`Network`](dirac::network::Network) of the same cells joined by name (`zoo::network_ladder`:
//! the same coordinates, rows and generated kernels, each part called through the network's
//! object-safe view). For N = 10³, 10⁴ and 10⁵ cells: the time per accepted Radau step of
//! each (tolerance 1e-6, `ErrorNorm::Max`, the same travelling pulse), alternating derived and
//! network runs, median of 5 runs of `max(20, 2·10⁵/N)` steps after 5 warm-up steps; the ratio
//! network / derived; and the time to build the network (`finish` included).
//!
//! Run: `cargo bench -p dirac-benches --bench network`.

#![allow(missing_docs)]

use std::time::Instant;

use dirac::State;
use dirac::network::Network;
use dirac::prelude::*;

use dirac_benches::zoo;

use zoo::{ladder_at_rest, network_ladder, unit_ladder};

/// Seconds per accepted step over `steps` steps after 5 warm-up steps.
fn per_step<M: LagrangeDirac>(model: &M, start: &State<M>, steps: usize) -> f64
where
    DefaultAllocator: Storage<M>,
{
    let options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(1e-6, 1e-6) };
    let mut radau = Radau::new(model, options).expect("valid options");
    radau.start(0.0, start, 1e6).expect("starts");
    for _ in 0..5 {
        radau.step().expect("steps");
    }
    let clock = Instant::now();
    for _ in 0..steps {
        radau.step().expect("steps");
    }
    clock.elapsed().as_secs_f64() / steps as f64
}

fn median(mut x: Vec<f64>) -> f64 {
    x.sort_by(f64::total_cmp);
    x[x.len() / 2]
}

fn main() {
    println!("| cells N | parts | derived time/step | network time/step | ratio | network build |");
    println!("|---:|---:|---:|---:|---:|---:|");
    for n in [1_000, 10_000, 100_000] {
        let ladder = unit_ladder(n);
        let clock = Instant::now();
        let network = network_ladder(n);
        let build = clock.elapsed().as_secs_f64();
        let centre = n as f64 / 3.0;
        let x: Vec<f64> = (1..=n).map(|j| (-((j as f64 - centre) / 5.0).powi(2)).exp()).collect();
        let s = ladder_at_rest(&ladder, &x);
        let mut start = State::<Network>::with_sizes(network.sizes());
        start.q.copy_from_slice(s.q.as_slice());
        start.v.copy_from_slice(s.v.as_slice());
        start.p.copy_from_slice(s.p.as_slice());
        start.lambda.copy_from_slice(s.lambda.as_slice());
        let steps = (200_000 / n).max(20);
        let (mut derived, mut run) = (Vec::new(), Vec::new());
        for _ in 0..5 {
            derived.push(per_step(&ladder, &s, steps));
            run.push(per_step(&network, &start, steps));
        }
        let ratios: Vec<f64> = run.iter().zip(&derived).map(|(a, b)| a / b).collect();
        println!(
            "| {n} | {} | {:.3} ms | {:.3} ms | **{:.2}** | {:.1} ms |",
            n + 1,
            median(derived) * 1e3,
            median(run) * 1e3,
            median(ratios),
            build * 1e3
        );
    }
}
