//! The variational integrator's cost per step against hand-written code, in one process:
//! velocity Verlet on an unconstrained regular model (the free two-mass spring, where the
//! scheme reduces to it) and RATTLE on the Cartesian pendulum. Both baselines are the textbook
//! algorithms written directly for their model.
//!
//! Run: `cargo bench -p dirac-benches --bench variational`.

#![allow(missing_docs)]

use dirac_benches::zoo;

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use dirac::State;
use dirac::prelude::*;
use zoo::*;

const STEPS: usize = 1000;
const H: f64 = 0.01;

/// Velocity Verlet for two masses joined by a spring of rest length d.
fn verlet_free_spring(s: &FreeSpring, mut x: [f64; 2], mut v: [f64; 2]) -> f64 {
    let accel = |x: [f64; 2]| {
        let f = s.k * (x[1] - x[0] - s.d);
        [f / s.m1, -f / s.m2]
    };
    let mut a = accel(x);
    for _ in 0..STEPS {
        for i in 0..2 {
            v[i] += 0.5 * H * a[i];
            x[i] += H * v[i];
        }
        a = accel(x);
        for i in 0..2 {
            v[i] += 0.5 * H * a[i];
        }
    }
    x[0] + v[1]
}

/// RATTLE for the pendulum x² + y² = l² under gravity: Newton on the position multiplier,
/// then the velocity projection.
fn rattle_pendulum(p: &Pendulum, mut q: [f64; 2], mut v: [f64; 2]) -> f64 {
    let (m, g, l) = (p.m, p.g, p.l);
    let force = [0.0, -m * g];
    for _ in 0..STEPS {
        // v_half = v + (h/2m)(F + 2 q λ), q1 = q + h v_half, |q1|² = l².
        let base = [v[0] + 0.5 * H * force[0] / m, v[1] + 0.5 * H * force[1] / m];
        let mut lambda = 0.0;
        let mut q1 = q;
        let mut vh = base;
        for _ in 0..20 {
            vh = [base[0] + H * q[0] * lambda / m, base[1] + H * q[1] * lambda / m];
            q1 = [q[0] + H * vh[0], q[1] + H * vh[1]];
            let phi = q1[0] * q1[0] + q1[1] * q1[1] - l * l;
            let dphi = 2.0 * (q1[0] * q[0] + q1[1] * q[1]) * H * H / m;
            let step = phi / dphi;
            lambda -= step;
            if step.abs() <= 1e-12 * (1.0 + lambda.abs()) {
                vh = [base[0] + H * q[0] * lambda / m, base[1] + H * q[1] * lambda / m];
                q1 = [q[0] + H * vh[0], q[1] + H * vh[1]];
                break;
            }
        }
        let w = [vh[0] + 0.5 * H * force[0] / m, vh[1] + 0.5 * H * force[1] / m];
        let mu = -(q1[0] * w[0] + q1[1] * w[1]) / (q1[0] * q1[0] + q1[1] * q1[1]);
        v = [w[0] + mu * q1[0], w[1] + mu * q1[1]];
        q = q1;
    }
    q[0] + v[1]
}

fn ours<M: DenseModel>(model: &M, start: &State<M>, options: VariationalOptions) -> f64
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut vi = Variational::new(model, H, options).expect("valid");
    vi.start(0.0, start, H * STEPS as f64).expect("starts");
    for _ in 0..STEPS {
        vi.step().expect("steps");
    }
    vi.state().q[0]
}

fn benches(c: &mut Criterion) {
    let general = VariationalOptions { use_structure: false, ..VariationalOptions::default() };
    let spring = FreeSpring { m1: 1.0, m2: 3.0, k: 7.0, d: 0.5 };
    let (x0, v0) = ([0.0, 1.2], [0.3, -0.7]);
    let start = consistent_state(
        &spring,
        0.0,
        &VecQ::<FreeSpring>::from(x0),
        &VecQ::<FreeSpring>::from(v0),
        Consistency::default(),
    )
    .expect("consistent");
    let mut group = c.benchmark_group("1000 steps/free spring");
    group.bench_function("hand-written velocity Verlet", |b| {
        b.iter(|| verlet_free_spring(black_box(&spring), x0, v0))
    });
    group.bench_function("dirac variational", |b| {
        b.iter(|| ours(black_box(&spring), &start, VariationalOptions::default()))
    });
    group.bench_function("dirac variational, general path", |b| {
        b.iter(|| ours(black_box(&spring), &start, general))
    });
    group.finish();

    let pendulum = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let (q0, w0) = ([0.6, -0.8], [0.8, 0.6]);
    let start = consistent_state(
        &pendulum,
        0.0,
        &VecQ::<Pendulum>::from(q0),
        &VecQ::<Pendulum>::from(w0),
        Consistency::default(),
    )
    .expect("consistent");
    let mut group = c.benchmark_group("1000 steps/pendulum");
    group.bench_function("hand-written RATTLE", |b| b.iter(|| rattle_pendulum(black_box(&pendulum), q0, w0)));
    group.bench_function("dirac variational", |b| {
        b.iter(|| ours(black_box(&pendulum), &start, VariationalOptions::default()))
    });
    group.bench_function("dirac variational, general path", |b| {
        b.iter(|| ours(black_box(&pendulum), &start, general))
    });
    group.finish();
}

criterion_group!(variational, benches);
criterion_main!(variational);
