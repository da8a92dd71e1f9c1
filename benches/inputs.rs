//! What inputs cost, in one process:
//!
//! - `held`: Radau on the forced spring with its force an input set to 0.5, against the same
//!   model with `force(x) = 0.5` written in (goal: ratio ≤ 1.1);
//! - `driven`: the force `0.5 sin(1.3 t)` set by a drive before every evaluation, against the
//!   same expression written in the model;
//! - `sampled`: a 100 Hz controller (`solve_sampled`, a restart every 10 ms) over 10 s, against
//!   the same run without sampling (the force held at its value).
//!
//! Run: `cargo bench -p dirac-benches --bench inputs`.

#![allow(missing_docs)]

use dirac_benches::zoo;

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use dirac::State;
use dirac::prelude::*;
use zoo::ForcedSpring;

/// The forced spring with its force written in as a constant.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(x => v), input(f))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x, force(x) = 0.5)]
struct ConstantForce {
    m: f64,
    k: f64,
    f: f64,
}

/// The forced spring with its force written in as a function of time.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x, force(x) = 0.5 * (1.3 * t).sin())]
struct TimeForce {
    m: f64,
    k: f64,
}

const T_END: f64 = 10.0;

fn options() -> RadauOptions {
    RadauOptions::tolerances(1e-8, 1e-8)
}

fn start<M: DenseModel>(model: &M) -> State<M>
where
    DefaultAllocator: Storage<M>,
{
    let q = VecQ::<M>::from_element(1.0);
    consistent_state(model, 0.0, &q, &VecQ::<M>::zeros(), Consistency::default()).expect("consistent")
}

fn steps<M: DenseModel>(radau: &mut Radau<'_, M>, start: &State<M>) -> usize
where
    DefaultAllocator: Storage<M>,
{
    radau.start(0.0, start, T_END).expect("starts");
    while !radau.finished() {
        radau.step().expect("steps");
    }
    radau.stats().steps
}

fn benches(c: &mut Criterion) {
    let spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.5 };
    let constant = ConstantForce { m: 1.0, k: 4.0, f: 0.0 };
    let (s_spring, s_constant) = (start(&spring), start(&constant));
    let mut group = c.benchmark_group("inputs/held");
    group.bench_function("input set to 0.5", |b| {
        b.iter(|| steps(&mut Radau::new(black_box(&spring), options()).expect("valid"), &s_spring))
    });
    group.bench_function("0.5 written in the model", |b| {
        b.iter(|| steps(&mut Radau::new(black_box(&constant), options()).expect("valid"), &s_constant))
    });
    group.finish();

    let timed = TimeForce { m: 1.0, k: 4.0 };
    let s_timed = start(&timed);
    let mut group = c.benchmark_group("inputs/driven");
    group.bench_function("drive 0.5 sin(1.3 t)", |b| {
        b.iter(|| {
            let mut model = spring.clone();
            let mut source =
                |t: f64, _: &State<ForcedSpring>, m: &mut ForcedSpring| m.f = 0.5 * (1.3 * t).sin();
            let mut radau = Radau::new(&mut model, options()).expect("valid");
            radau.drive(&mut source).expect("exclusive");
            steps(&mut radau, &s_spring)
        })
    });
    group.bench_function("0.5 sin(1.3 t) written in the model", |b| {
        b.iter(|| steps(&mut Radau::new(black_box(&timed), options()).expect("valid"), &s_timed))
    });
    group.finish();

    // Steps are what restarts change: one step at least per sample interval.
    let mut model = spring.clone();
    let mut radau = Radau::new(&mut model, options()).expect("valid");
    let sampled = radau
        .solve_sampled(0.0, &s_spring, T_END, 0.01, &Sampling::Times(vec![T_END]), |_, _, m| m.f = 0.5)
        .expect("integrates");
    let plain = Radau::new(&spring, options())
        .expect("valid")
        .solve(0.0, &s_spring, T_END, &Sampling::Times(vec![T_END]))
        .expect("integrates");
    eprintln!(
        "steps over 10 s: {} with a 100 Hz controller ({} Newton iterations, {} LU), {} without ({} Newton iterations, {} LU)",
        sampled.stats.steps,
        sampled.stats.newton_iterations,
        sampled.stats.factorizations,
        plain.stats.steps,
        plain.stats.newton_iterations,
        plain.stats.factorizations
    );
    let mut group = c.benchmark_group("inputs/sampled");
    group.bench_function("100 Hz controller, 10 s", |b| {
        b.iter(|| {
            let mut model = spring.clone();
            let mut radau = Radau::new(&mut model, options()).expect("valid");
            let solution = radau
                .solve_sampled(0.0, &s_spring, T_END, 0.01, &Sampling::Times(vec![T_END]), |_, _, m| {
                    m.f = 0.5
                })
                .expect("integrates");
            solution.stats.steps
        })
    });
    group.bench_function("no sampling, 10 s", |b| {
        b.iter(|| {
            let mut radau = Radau::new(black_box(&spring), options()).expect("valid");
            let solution =
                radau.solve(0.0, &s_spring, T_END, &Sampling::Times(vec![T_END])).expect("integrates");
            solution.stats.steps
        })
    });
    group.finish();
}

criterion_group!(inputs, benches);
criterion_main!(inputs);
