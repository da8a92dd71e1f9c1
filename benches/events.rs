//! What event location costs per step, in one process: the same run with and without events,
//! so the steps are the same and the difference is the location.
//!
//! - `events/radau`: the oscillator `x = cos t` over 100 s at tolerance 1e-8, stepped alone,
//!   and stepped with two event functions (`x = 0` either way, `v = 0` falling) located after
//!   every step (48 events, each found by the root finder on the dense output);
//! - `events/variational`: the same with the variational integrator, step 0.01.
//!
//! Run: `cargo bench -p dirac-benches --bench events`.

#![allow(missing_docs)]

use dirac_benches::zoo;

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use dirac::State;
use dirac::prelude::*;
use dirac::{Crossing, Events};
use zoo::Oscillator;

const T_END: f64 = 100.0;

/// Steps `integrator` to the end, locating the events after each step if there are any;
/// returns the steps and the events located.
fn run<I: Integrator<Oscillator>>(
    integrator: &mut I,
    start: &State<Oscillator>,
    events: Option<&mut Events<'_, Oscillator>>,
) -> usize {
    integrator.start(0.0, start, T_END).expect("starts");
    let mut located = 0;
    match events {
        None => {
            while !integrator.finished() {
                integrator.step().expect("steps");
            }
        }
        Some(events) => {
            events.begin(integrator.model(), 0.0, start).expect("begins");
            while !integrator.finished() {
                integrator.step().expect("steps");
                while events.locate(integrator).expect("locates").is_some() {
                    located += 1;
                }
            }
        }
    }
    located
}

fn events<'e>() -> Events<'e, Oscillator> {
    Events::new().on("x", Crossing::Either, |_, s: &State<Oscillator>, _| s.q(Oscillator::X)).on(
        "v",
        Crossing::Falling,
        |_, s: &State<Oscillator>, _| s.v(Oscillator::X),
    )
}

fn benches(c: &mut Criterion) {
    let model = Oscillator { m: 1.0, k: 1.0 };
    let mut start = State::<Oscillator>::zeros();
    start.set_q(Oscillator::X, 1.0);
    let options = RadauOptions::tolerances(1e-8, 1e-8);

    let mut radau = Radau::new(&model, options).expect("valid");
    let mut counted = events();
    let located = run(&mut radau, &start, Some(&mut counted));
    eprintln!(
        "radau: {} steps, {located} events, {} evaluations of event functions ({:.2} per step)",
        radau.stats().steps,
        counted.evaluations(),
        counted.evaluations() as f64 / radau.stats().steps as f64
    );
    let mut group = c.benchmark_group("events/radau");
    group.bench_function("without events", |b| {
        b.iter(|| run(&mut Radau::new(black_box(&model), options).expect("valid"), &start, None))
    });
    let mut set = events();
    group.bench_function("with two event functions", |b| {
        b.iter(|| run(&mut Radau::new(black_box(&model), options).expect("valid"), &start, Some(&mut set)))
    });
    group.finish();

    let h = 0.01;
    let mut variational = Variational::new(&model, h, VariationalOptions::default()).expect("valid");
    let located = run(&mut variational, &start, Some(&mut counted));
    eprintln!("variational: {} steps, {located} events", variational.stats().steps);
    let mut group = c.benchmark_group("events/variational");
    group.bench_function("without events", |b| {
        b.iter(|| {
            let mut variational =
                Variational::new(black_box(&model), h, VariationalOptions::default()).expect("valid");
            run(&mut variational, &start, None)
        })
    });
    group.bench_function("with two event functions", |b| {
        b.iter(|| {
            let mut variational =
                Variational::new(black_box(&model), h, VariationalOptions::default()).expect("valid");
            run(&mut variational, &start, Some(&mut set))
        })
    });
    group.finish();
}

criterion_group!(events_bench, benches);
criterion_main!(events_bench);
