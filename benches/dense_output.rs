//! The cost of Radau's solutions at equal sampled error, with the corrected dense output and
//! with RADAU5's collocation polynomial alone.
//!
//! Each problem is solved at rtol = atol = 10^(−k/2), k = 8..24, sampled 1000 times
//! (`Sampling::Every`), and its largest error over the samples (positions and velocities)
//! taken against its closed form: the Kepler orbit of eccentricity 0.6 over one period
//! (`zoo::kepler_exact`) and the bead on a turning rod over t ∈ [0, 2] (`zoo::bead_exact`).
//! Prints CSV `problem,output,tol,sampled_error,steps,evaluations,seconds` (seconds the median
//! of 21 solves), then for every sampled error from 1e-4 to 1e-10 the cheapest run of either
//! output that reaches it, and the ratio of their times and evaluations.
//!
//! Run: `cargo bench -p dirac-benches --bench dense_output`.

#![allow(missing_docs)]

use dirac_benches::zoo;

#[path = "support/median.rs"]
mod median;

use dirac::DenseOutput;
use dirac::State;
use dirac::prelude::*;
use median::median_seconds;
use zoo::{BeadOnRod, Kepler, bead_exact, kepler_exact};

struct Run {
    problem: &'static str,
    output: DenseOutput,
    tol: f64,
    error: f64,
    steps: usize,
    evaluations: usize,
    seconds: f64,
}

fn runs<M: LagrangeDirac + Hybrid>(
    problem: &'static str,
    model: &M,
    (start, t_end): (&State<M>, f64),
    exact: impl Fn(f64) -> [f64; 4],
) -> Vec<Run>
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut runs = Vec::new();
    for output in [DenseOutput::Corrected, DenseOutput::Collocation] {
        for k in 8..=24 {
            let tol = 10f64.powf(-k as f64 / 2.0);
            let options = RadauOptions { dense_output: output, ..RadauOptions::tolerances(tol, tol) };
            let solve = || {
                Radau::new(model, options)
                    .expect("valid")
                    .solve(0.0, start, t_end, &Sampling::Every(t_end / 1000.0))
                    .expect("integrates")
            };
            let solution = solve();
            let mut error = 0.0f64;
            for (i, &t) in solution.t().iter().enumerate() {
                let x = exact(t);
                let state = solution.state(i).expect("recorded");
                for c in 0..2 {
                    error = error.max((state.q[c] - x[c]).abs()).max((state.v[c] - x[2 + c]).abs());
                }
            }
            let stats = solution.stats;
            let (seconds, _) = median_seconds(|| solve().stats.steps);
            runs.push(Run {
                problem,
                output,
                tol,
                error,
                steps: stats.steps,
                evaluations: stats.residual_evaluations,
                seconds,
            });
        }
    }
    runs
}

fn main() {
    let x = kepler_exact(0.6, 0.0);
    let q = VecQ::<Kepler>::from([x[0], x[1]]);
    let kepler_start =
        consistent_state(&Kepler {}, 0.0, &q, &VecQ::<Kepler>::from([x[2], x[3]]), Consistency::default())
            .expect("consistent");
    let bead = BeadOnRod { m: 0.7, w: 1.3 };
    let q = VecQ::<BeadOnRod>::from([0.5, 0.0]);
    let bead_start = consistent_state(&bead, 0.0, &q, &VecQ::<BeadOnRod>::zeros(), Consistency::default())
        .expect("consistent");
    let mut all =
        runs("kepler", &Kepler {}, (&kepler_start, 2.0 * std::f64::consts::PI), |t| kepler_exact(0.6, t));
    all.extend(runs("bead", &bead, (&bead_start, 2.0), |t| bead_exact(bead.w, 0.5, t)));
    println!("problem,output,tol,sampled_error,steps,evaluations,seconds");
    for r in &all {
        println!(
            "{},{:?},{:.1e},{:.2e},{},{},{:.3e}",
            r.problem, r.output, r.tol, r.error, r.steps, r.evaluations, r.seconds
        );
    }
    println!();
    println!("problem,sampled_error,corrected_tol,collocation_tol,time_ratio,evaluation_ratio");
    for problem in ["kepler", "bead"] {
        for e in 4..=10 {
            let target = 10f64.powi(-e);
            let cheapest = |output: DenseOutput| {
                all.iter()
                    .filter(|r| r.problem == problem && r.output == output && r.error <= target)
                    .min_by(|a, b| a.seconds.total_cmp(&b.seconds))
            };
            match (cheapest(DenseOutput::Corrected), cheapest(DenseOutput::Collocation)) {
                (Some(a), Some(b)) => println!(
                    "{problem},{target:.0e},{:.1e},{:.1e},{:.2},{:.2}",
                    a.tol,
                    b.tol,
                    a.seconds / b.seconds,
                    a.evaluations as f64 / b.evaluations as f64
                ),
                _ => println!("{problem},{target:.0e},not reached by both"),
            }
        }
    }
}
