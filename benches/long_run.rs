//! Long-time energy behaviour: the variational integrator against Radau IIA over the same span
//! at comparable cost. For each model the variational integrator takes 10⁶ steps; Radau runs
//! over the same span at the tolerances listed. Printed: wall time and the largest energy
//! error |E − E0| over the first and the last 10% of the span.
//!
//! `cargo bench -p dirac-benches --bench long_run -- drift` measures instead the drift from the position
//! constraint of Radau on the pendulum over 10⁴ s, with and without projection.
//!
//! Run: `cargo bench -p dirac-benches --bench long_run`.

#![allow(missing_docs)]

use dirac_benches::zoo;

use std::ops::ControlFlow;
use std::time::Instant;

use dirac::State;
use dirac::prelude::*;
use zoo::*;

struct Windows {
    first: f64,
    last: f64,
}

fn variational<M: DenseModel>(model: &M, start: &State<M>, h: f64, steps: usize) -> (f64, Windows)
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let e0 = model.energy(0.0, &start.q, &start.v, &start.p);
    let span = h * steps as f64;
    let clock = Instant::now();
    let mut vi = Variational::new(model, h, VariationalOptions::default()).expect("valid");
    vi.start(0.0, start, span).expect("starts");
    let mut w = Windows { first: 0.0, last: 0.0 };
    for _ in 0..steps {
        vi.step().expect("steps");
        let s = vi.state();
        let e = (model.energy(vi.t(), &s.q, &s.v, &s.p) - e0).abs();
        if vi.t() <= 0.1 * span {
            w.first = w.first.max(e);
        } else if vi.t() >= 0.9 * span {
            w.last = w.last.max(e);
        }
    }
    (clock.elapsed().as_secs_f64(), w)
}

fn radau<M: DenseModel>(model: &M, start: &State<M>, span: f64, tol: f64) -> (f64, Windows, usize)
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let e0 = model.energy(0.0, &start.q, &start.v, &start.p);
    let clock = Instant::now();
    let mut radau = Radau::new(model, RadauOptions::tolerances(tol, tol)).expect("valid");
    let mut w = Windows { first: 0.0, last: 0.0 };
    let sol = radau
        .solve_observed(0.0, start, span, &Sampling::Times(vec![span]), |t, s| {
            let e = (model.energy(t, &s.q, &s.v, &s.p) - e0).abs();
            if t <= 0.1 * span {
                w.first = w.first.max(e);
            } else if t >= 0.9 * span {
                w.last = w.last.max(e);
            }
            ControlFlow::Continue(())
        })
        .expect("integrates");
    (clock.elapsed().as_secs_f64(), w, sol.stats.steps)
}

fn report<M: DenseModel>(name: &str, model: &M, start: &State<M>, h: f64, tols: &[f64])
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let steps = 1_000_000;
    let span = h * steps as f64;
    let (seconds, w) = variational(model, start, h, steps);
    println!("{name}, t in [0, {span}]");
    println!(
        "  variational h = {h}: {seconds:.3} s, 1000000 steps, |E-E0| first 10% {:.2e}, last 10% {:.2e}",
        w.first, w.last
    );
    for &tol in tols {
        let (seconds, w, steps) = radau(model, start, span, tol);
        println!(
            "  Radau tol = {tol:e}: {seconds:.3} s, {steps} steps, |E-E0| first 10% {:.2e}, last 10% {:.2e}",
            w.first, w.last
        );
    }
}

/// The pendulum over 10⁴ s with Radau, with and without projection onto the constraints after
/// accepted steps: the largest |φ(q)| (the rod's residual) and |E − E0| in the last 10% of the
/// span, the steps and the wall time.
fn drift() {
    let p = unit_pendulum();
    let start = horizontal_start(&p);
    let span = 1e4;
    println!("pendulum, t in [0, {span}], Radau with and without projection");
    for tol in [1e-6, 1e-8] {
        for projection in [false, true] {
            let options = RadauOptions { projection, ..RadauOptions::tolerances(tol, tol) };
            let clock = Instant::now();
            let (mut phi, mut energy) = (0.0f64, 0.0f64);
            let sol = Radau::new(&p, options)
                .expect("valid")
                .solve_observed(0.0, &start, span, &Sampling::Times(vec![span]), |t, s| {
                    if t >= 0.9 * span {
                        let r2 = s.q.norm_squared() - p.l * p.l;
                        phi = phi.max(r2.abs());
                        energy = energy.max(p.energy(t, &s.q, &s.v, &s.p).abs());
                    }
                    ControlFlow::Continue(())
                })
                .expect("integrates");
            println!(
                "  tol = {tol:e}, projection = {projection}: {:.3} s, {} steps, last 10%: max |phi| {phi:.2e}, max |E - E0| {energy:.2e}",
                clock.elapsed().as_secs_f64(),
                sol.stats.steps
            );
        }
    }
}

fn main() {
    if std::env::args().any(|a| a == "drift") {
        drift();
        return;
    }
    let chain = paper_chain();
    let start = paper_chain_start(&chain);
    report(
        "paper's torn chain (interconnected, degenerate)",
        &chain,
        &start,
        0.02,
        &[1e-5, 1e-6, 1e-7, 1e-8],
    );
    let p = unit_pendulum();
    let start = horizontal_start(&p);
    report("pendulum", &p, &start, 0.01, &[1e-4, 1e-5, 1e-6]);
}
