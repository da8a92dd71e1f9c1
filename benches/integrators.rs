//! Integrator benchmarks, each ratio measured within this one process.
//!
//! - `newton/*`: one factorisation and solve of the Newton systems of a Radau step (real and
//!   complex), condensed (size n + m) against full (size 3n + m), on the paper's torn chain
//!   and on the 8-link pendulum of the test zoo.
//! - `radau/*`: a whole integration with each solver, same tolerances.
//!
//! Run: `cargo bench -p dirac-benches --bench integrators`.

#![allow(missing_docs)]

use dirac_benches::zoo;

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use dirac::State;
use dirac::nalgebra::{Complex, DefaultAllocator};
use dirac::prelude::*;
use dirac::runtime::newton::{Condensed, Full, NewtonSolver};
use zoo::*;

fn chain() -> Chain {
    paper_chain()
}

fn chain_start(model: &Chain) -> State<Chain> {
    let mut q = VecQ::<Chain>::zeros();
    q[0] = 0.1;
    consistent_state(model, 0.0, &q, &VecQ::<Chain>::zeros(), Consistency::default()).expect("consistent")
}

fn pendulum8() -> Pendulum8 {
    Pendulum8 { m: 0.5, l: 0.25, g: 9.81 }
}

fn pendulum8_start(model: &Pendulum8) -> State<Pendulum8> {
    let q = VecQ::<Pendulum8>::from_fn(|i, _| 0.3 + 0.05 * i as f64);
    consistent_state(model, 0.0, &q, &VecQ::<Pendulum8>::zeros(), Consistency::default()).expect("consistent")
}

fn newton_once<M: DenseModel, S: NewtonSolver<M, dirac::Dense>>(
    solver: &mut S,
    jac: &JacobianBlocks<M>,
    rhs: &VecY<M>,
) -> f64
where
    DefaultAllocator: dirac::Storage<M>,
{
    solver.factor(jac, 36.4, Complex::new(26.8, 30.5)).expect("nonsingular");
    let (mut a, mut b, mut c) = (rhs.clone(), rhs.clone(), rhs.clone());
    solver.solve(&mut a);
    solver.solve_complex(&mut b, &mut c);
    a[0] + b[0] + c[0]
}

fn newton_group<M: DenseModel>(c: &mut Criterion, name: &str, model: &M, start: &State<M>)
where
    DefaultAllocator: dirac::Storage<M>,
{
    let mut jac = JacobianBlocks::<M>::zeros();
    model.jacobian_blocks(0.0, &start.q, &start.v, &start.lambda, &mut jac);
    let rhs = VecY::<M>::from_fn(|i, _| (i as f64 * 0.3).sin());
    let mut group = c.benchmark_group(format!("newton/{name}"));
    let mut condensed = Condensed::<M>::default();
    group.bench_function("condensed", |b| {
        b.iter(|| newton_once(&mut condensed, black_box(&jac), black_box(&rhs)))
    });
    let mut full = Full::<M>::default();
    group.bench_function("full", |b| b.iter(|| newton_once(&mut full, black_box(&jac), black_box(&rhs))));
    group.finish();
}

fn radau_group<M: DenseModel>(c: &mut Criterion, name: &str, model: &M, start: &State<M>, t_end: f64)
where
    DefaultAllocator: dirac::Storage<M>,
{
    let options = RadauOptions::tolerances(1e-8, 1e-10);
    let mut group = c.benchmark_group(format!("radau/{name}"));
    group.sample_size(20);
    group.bench_function("condensed", |b| {
        b.iter(|| {
            let mut radau = Radau::new(model, options).expect("valid");
            radau.solve(0.0, start, t_end, &Sampling::Times(vec![t_end])).expect("integrates").stats.steps
        })
    });
    group.bench_function("full", |b| {
        b.iter(|| {
            let mut radau = Radau::with_solver(model, options, Full::<M>::default()).expect("valid");
            radau.solve(0.0, start, t_end, &Sampling::Times(vec![t_end])).expect("integrates").stats.steps
        })
    });
    group.finish();
}

fn benches(c: &mut Criterion) {
    let (chain, p8) = (chain(), pendulum8());
    let (chain_start, p8_start) = (chain_start(&chain), pendulum8_start(&p8));
    newton_group(c, "paper chain (n=4, m=1)", &chain, &chain_start);
    newton_group(c, "8-link pendulum (n=8, m=0)", &p8, &p8_start);
    radau_group(c, "paper chain, t in [0, 20]", &chain, &chain_start, 20.0);
    radau_group(c, "8-link pendulum, t in [0, 2]", &p8, &p8_start, 2.0);
}

criterion_group!(integrators, benches);
criterion_main!(integrators);
