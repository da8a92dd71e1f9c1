//! Generated residual and Jacobian kernels against hand-written Rust and against forward-mode
//! automatic differentiation (num-dual), in one process, on seeded random states:
//!
//! - the paper's chain written as one model (n = 3);
//! - the 8-link pendulum of the test zoo in angle coordinates (n = 8, cos(θi − θj) terms);
//! - N-link pendulum chains in Cartesian coordinates with one rod multiplier per link
//!   (N = 2, 4, 8, 16: n = 2N, m = N).
//!
//! The hand-written kernels compute the same flat residual `f = (v, p − ∂L/∂v, ∂L/∂q + Aᵀλ,
//! A v)` and its Jacobian the way one would write them by hand (loops, each cos/sin once per
//! pair), writing only nonzero entries into a matrix zeroed once, as the generated code does.
//! The AD baseline evaluates one generic residual on `DualSVec` numbers; "generated F+J (CSC)"
//! writes the Jacobian's nonzeros packed in compressed sparse columns (`SparseJacobian`). Each
//! hand-written kernel is checked against the generated one before timing.
//!
//! Run: `cargo bench -p dirac-benches --bench kernels`.
//!
//! With `DIRAC_KERNEL_LOOP=<generated|hand-written> <model>` in the environment (models:
//! `paper`, `cartesian2`, `cartesian4`) and `DIRAC_KERNEL_CALLS=<k>`, the binary instead calls
//! that F+J kernel k times and exits, for counting instructions per call under valgrind
//! (`benches/count_instructions.sh`), where wall time at a few ns is too noisy to compare.

#![allow(missing_docs, clippy::needless_range_loop)]

#[path = "models/cartesian.rs"]
mod cartesian;
use dirac_benches::zoo;

use std::hint::black_box;

use cartesian::{Cartesian2, Cartesian4, Cartesian8, Cartesian16};
use criterion::{Criterion, criterion_group};
use dirac::nalgebra::{DefaultAllocator, SVector};
use dirac::prelude::*;
use num_dual::{DualNum, jacobian};
use zoo::{MassSpringChain, Pendulum8};

/// A flat residual written once for any number type, for the AD baseline.
trait Generic<const NY: usize> {
    fn residual<D: DualNum<Primitive = f64> + Copy>(&self, y: &SVector<D, NY>) -> SVector<D, NY>;
}

/// A hand-written residual and Jacobian.
trait Hand<const NY: usize> {
    fn residual(&self, y: &SVector<f64, NY>, f: &mut SVector<f64, NY>);
    fn jacobian(&self, y: &SVector<f64, NY>, j: &mut dirac::nalgebra::SMatrix<f64, NY, NY>);
}

// ---------------------------------------------------------------- the paper's chain, n = 3
impl Generic<9> for MassSpringChain {
    fn residual<D: DualNum<Primitive = f64> + Copy>(&self, y: &SVector<D, 9>) -> SVector<D, 9> {
        let (x, v, p) = ([y[0], y[1], y[2]], [y[3], y[4], y[5]], [y[6], y[7], y[8]]);
        let m = [self.m1, self.m2, self.m3];
        let (s2, s3) = (x[1] - x[0], x[2] - x[1]);
        SVector::from([
            v[0],
            v[1],
            v[2],
            p[0] - v[0] * m[0],
            p[1] - v[1] * m[1],
            p[2] - v[2] * m[2],
            -(x[0] * self.k1) + s2 * self.k2,
            -(s2 * self.k2) + s3 * self.k3,
            -(s3 * self.k3),
        ])
    }
}

impl Hand<9> for MassSpringChain {
    fn residual(&self, y: &SVector<f64, 9>, f: &mut SVector<f64, 9>) {
        let m = [self.m1, self.m2, self.m3];
        for i in 0..3 {
            f[i] = y[3 + i];
            f[3 + i] = y[6 + i] - m[i] * y[3 + i];
        }
        let (s2, s3) = (y[1] - y[0], y[2] - y[1]);
        f[6] = -self.k1 * y[0] + self.k2 * s2;
        f[7] = -self.k2 * s2 + self.k3 * s3;
        f[8] = -self.k3 * s3;
    }

    fn jacobian(&self, _y: &SVector<f64, 9>, j: &mut dirac::nalgebra::SMatrix<f64, 9, 9>) {
        let m = [self.m1, self.m2, self.m3];
        for i in 0..3 {
            j[(i, 3 + i)] = 1.0;
            j[(3 + i, 3 + i)] = -m[i];
            j[(3 + i, 6 + i)] = 1.0;
        }
        j[(6, 0)] = -self.k1 - self.k2;
        j[(6, 1)] = self.k2;
        j[(7, 0)] = self.k2;
        j[(7, 1)] = -self.k2 - self.k3;
        j[(7, 2)] = self.k3;
        j[(8, 1)] = self.k3;
        j[(8, 2)] = -self.k3;
    }
}

// --------------------------------------------------- the 8-link pendulum in angles, n = 8
/// `M_ij = (8 − max(i, j)) m l²`, `a_i = (8 − i) m l`.
fn pendulum8_coefficients(p: &Pendulum8) -> ([[f64; 8]; 8], [f64; 8]) {
    let mut mm = [[0.0; 8]; 8];
    let mut a = [0.0; 8];
    for i in 0..8 {
        for j in 0..8 {
            mm[i][j] = (8 - i.max(j)) as f64 * p.m * p.l * p.l;
        }
        a[i] = (8 - i) as f64 * p.m * p.l;
    }
    (mm, a)
}

impl Generic<24> for Pendulum8 {
    fn residual<D: DualNum<Primitive = f64> + Copy>(&self, y: &SVector<D, 24>) -> SVector<D, 24> {
        let (mm, a) = pendulum8_coefficients(self);
        let mut f = SVector::<D, 24>::from_element(D::from(0.0));
        for i in 0..8 {
            f[i] = y[8 + i];
            let mut lv = D::from(0.0);
            let mut lq = -(y[i].sin() * (self.g * a[i]));
            for j in 0..8 {
                let d = y[i] - y[j];
                lv += d.cos() * y[8 + j] * mm[i][j];
                lq -= d.sin() * y[8 + i] * y[8 + j] * mm[i][j];
            }
            f[8 + i] = y[16 + i] - lv;
            f[16 + i] = lq;
        }
        f
    }
}

impl Hand<24> for Pendulum8 {
    fn residual(&self, y: &SVector<f64, 24>, f: &mut SVector<f64, 24>) {
        let (mm, a) = pendulum8_coefficients(self);
        let w = &y.as_slice()[8..16];
        let mut lv = [0.0; 8];
        let mut lq = [0.0; 8];
        for i in 0..8 {
            lv[i] += mm[i][i] * w[i];
            lq[i] -= self.g * a[i] * y[i].sin();
            for j in i + 1..8 {
                let (s, c) = (y[i] - y[j]).sin_cos();
                let mij = mm[i][j];
                lv[i] += mij * c * w[j];
                lv[j] += mij * c * w[i];
                let t = mij * s * w[i] * w[j];
                lq[i] -= t;
                lq[j] += t;
            }
        }
        for i in 0..8 {
            f[i] = w[i];
            f[8 + i] = y[16 + i] - lv[i];
            f[16 + i] = lq[i];
        }
    }

    fn jacobian(&self, y: &SVector<f64, 24>, jac: &mut dirac::nalgebra::SMatrix<f64, 24, 24>) {
        let (mm, a) = pendulum8_coefficients(self);
        let w = &y.as_slice()[8..16];
        let mut diag_vq = [0.0; 8];
        let mut diag_qq = [0.0; 8];
        let mut diag_qv = [0.0; 8];
        for i in 0..8 {
            jac[(i, 8 + i)] = 1.0;
            jac[(8 + i, 16 + i)] = 1.0;
            jac[(8 + i, 8 + i)] = -mm[i][i];
            diag_qq[i] -= self.g * a[i] * y[i].cos();
        }
        for i in 0..8 {
            for j in i + 1..8 {
                let (s, c) = (y[i] - y[j]).sin_cos();
                let mij = mm[i][j];
                // f_v = p − L_v: ∂/∂ω and ∂/∂θ.
                jac[(8 + i, 8 + j)] = -mij * c;
                jac[(8 + j, 8 + i)] = -mij * c;
                jac[(8 + i, j)] = -mij * s * w[j];
                jac[(8 + j, i)] = mij * s * w[i];
                diag_vq[i] += mij * s * w[j];
                diag_vq[j] -= mij * s * w[i];
                // f_p = L_q.
                let cw = mij * c * w[i] * w[j];
                jac[(16 + i, j)] = cw;
                jac[(16 + j, i)] = cw;
                diag_qq[i] -= cw;
                diag_qq[j] -= cw;
                jac[(16 + i, 8 + j)] = -mij * s * w[i];
                jac[(16 + j, 8 + i)] = mij * s * w[j];
                diag_qv[i] -= mij * s * w[j];
                diag_qv[j] += mij * s * w[i];
            }
        }
        for i in 0..8 {
            jac[(8 + i, i)] = diag_vq[i];
            jac[(16 + i, i)] = diag_qq[i];
            jac[(16 + i, 8 + i)] = diag_qv[i];
        }
    }
}

// -------------------------------------------- N-link chains in Cartesian coordinates
/// Parameters and sizes of an N-link Cartesian chain.
struct Chain<const N: usize> {
    m: f64,
    g: f64,
}

/// The link vector `r_k − r_{k−1}` (with `r_{−1} = 0`) and its velocity, for link k.
fn link<D: Copy + std::ops::Sub<Output = D> + From<f64>>(q: &[D], v: &[D], k: usize) -> (D, D, D, D) {
    let (x, y, vx, vy) = (q[2 * k], q[2 * k + 1], v[2 * k], v[2 * k + 1]);
    if k == 0 {
        (x, y, vx, vy)
    } else {
        (x - q[2 * k - 2], y - q[2 * k - 1], vx - v[2 * k - 2], vy - v[2 * k - 1])
    }
}

macro_rules! cartesian_kernels {
    ($model:ident, $n:literal, $ny:literal) => {
        impl Generic<$ny> for $model {
            fn residual<D: DualNum<Primitive = f64> + Copy>(&self, y: &SVector<D, $ny>) -> SVector<D, $ny> {
                Chain::<$n> { m: self.m, g: self.g }.generic_residual(y)
            }
        }

        impl Hand<$ny> for $model {
            fn residual(&self, y: &SVector<f64, $ny>, f: &mut SVector<f64, $ny>) {
                Chain::<$n> { m: self.m, g: self.g }.residual(y, f);
            }

            fn jacobian(&self, y: &SVector<f64, $ny>, j: &mut dirac::nalgebra::SMatrix<f64, $ny, $ny>) {
                Chain::<$n> { m: self.m, g: self.g }.jacobian(y, j);
            }
        }
    };
}

impl<const N: usize> Chain<N> {
    fn generic_residual<D: DualNum<Primitive = f64> + Copy, const NY: usize>(
        &self,
        y: &SVector<D, NY>,
    ) -> SVector<D, NY> {
        let n = 2 * N;
        let s = y.as_slice();
        let (q, v, p, lambda) = (&s[..n], &s[n..2 * n], &s[2 * n..3 * n], &s[3 * n..]);
        let mut f = SVector::<D, NY>::from_element(D::from(0.0));
        for i in 0..n {
            f[i] = v[i];
            f[n + i] = p[i] - v[i] * self.m;
            if i % 2 == 1 {
                f[2 * n + i] = D::from(-self.m * self.g);
            }
        }
        for k in 0..N {
            let (dx, dy, dvx, dvy) = link(q, v, k);
            let (fx, fy) = (dx * lambda[k] * 2.0, dy * lambda[k] * 2.0);
            f[2 * n + 2 * k] += fx;
            f[2 * n + 2 * k + 1] += fy;
            if k > 0 {
                f[2 * n + 2 * k - 2] -= fx;
                f[2 * n + 2 * k - 1] -= fy;
            }
            f[3 * n + k] = (dx * dvx + dy * dvy) * 2.0;
        }
        f
    }

    fn residual<const NY: usize>(&self, y: &SVector<f64, NY>, f: &mut SVector<f64, NY>) {
        let n = 2 * N;
        let s = y.as_slice();
        let (q, v, p, lambda) = (&s[..n], &s[n..2 * n], &s[2 * n..3 * n], &s[3 * n..]);
        for i in 0..n {
            f[i] = v[i];
            f[n + i] = p[i] - self.m * v[i];
            f[2 * n + i] = if i % 2 == 1 { -self.m * self.g } else { 0.0 };
        }
        for k in 0..N {
            let (dx, dy, dvx, dvy) = link(q, v, k);
            let (fx, fy) = (2.0 * lambda[k] * dx, 2.0 * lambda[k] * dy);
            f[2 * n + 2 * k] += fx;
            f[2 * n + 2 * k + 1] += fy;
            if k > 0 {
                f[2 * n + 2 * k - 2] -= fx;
                f[2 * n + 2 * k - 1] -= fy;
            }
            f[3 * n + k] = 2.0 * (dx * dvx + dy * dvy);
        }
    }

    fn jacobian<const NY: usize>(&self, y: &SVector<f64, NY>, j: &mut dirac::nalgebra::SMatrix<f64, NY, NY>) {
        let n = 2 * N;
        let s = y.as_slice();
        let (q, v, lambda) = (&s[..n], &s[n..2 * n], &s[3 * n..]);
        for i in 0..n {
            j[(i, n + i)] = 1.0;
            j[(n + i, n + i)] = -self.m;
            j[(n + i, 2 * n + i)] = 1.0;
        }
        for c in 0..2 {
            // The diagonal of ∂(Aᵀλ)/∂q: 2 λ_k (+ 2 λ_{k+1}).
            for k in 0..N {
                let next = if k + 1 < N { lambda[k + 1] } else { 0.0 };
                j[(2 * n + 2 * k + c, 2 * k + c)] = 2.0 * (lambda[k] + next);
            }
        }
        for k in 0..N {
            let (dx, dy, dvx, dvy) = link(q, v, k);
            let row = 3 * n + k;
            let d = [dx, dy];
            let dv = [dvx, dvy];
            for c in 0..2 {
                j[(row, 2 * k + c)] = 2.0 * dv[c];
                j[(row, n + 2 * k + c)] = 2.0 * d[c];
                j[(2 * n + 2 * k + c, row)] = 2.0 * d[c];
                if k > 0 {
                    j[(row, 2 * k - 2 + c)] = -2.0 * dv[c];
                    j[(row, n + 2 * k - 2 + c)] = -2.0 * d[c];
                    j[(2 * n + 2 * k - 2 + c, row)] = -2.0 * d[c];
                    j[(2 * n + 2 * k + c, 2 * k - 2 + c)] = -2.0 * lambda[k];
                    j[(2 * n + 2 * k - 2 + c, 2 * k + c)] = -2.0 * lambda[k];
                }
            }
        }
    }
}

cartesian_kernels!(Cartesian2, 2, 14);
cartesian_kernels!(Cartesian4, 4, 28);
cartesian_kernels!(Cartesian8, 8, 56);
cartesian_kernels!(Cartesian16, 16, 112);

/// A seeded random state.
fn state<const NY: usize>(seed: u64) -> SVector<f64, NY> {
    let mut s = seed;
    SVector::from_fn(|_, _| {
        s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    })
}

/// Checks the three implementations against each other and times them. A macro, so every
/// size is concrete (generic code over the model would see nalgebra's storage as opaque).
macro_rules! bench_model {
    ($c:expr, $name:expr, $model:expr, $ny:literal) => {{
        let (c, name, model): (&mut Criterion, &str, _) = (&mut *$c, $name, $model);
        let y: SVector<f64, $ny> = state(7);
        let (mut f_gen, mut f_hand) = (SVector::<f64, $ny>::zeros(), SVector::<f64, $ny>::zeros());
        LagrangeDirac::residual(model, 0.0, &y, &mut f_gen);
        Hand::residual(model, &y, &mut f_hand);
        assert!((f_gen - f_hand).amax() < 1e-12, "{name}: hand-written residual differs");
        let mut j_gen = dirac::nalgebra::SMatrix::<f64, $ny, $ny>::zeros();
        let mut j_hand = dirac::nalgebra::SMatrix::<f64, $ny, $ny>::zeros();
        LagrangeDirac::jacobian(model, 0.0, &y, &mut j_gen);
        Hand::jacobian(model, &y, &mut j_hand);
        assert!((j_gen - j_hand).amax() < 1e-12, "{name}: hand-written Jacobian differs");
        let (f_ad, j_ad) = jacobian(|x| Generic::residual(model, &x), &y);
        assert!((f_ad - f_gen).amax() < 1e-12 && (j_ad - j_gen).amax() < 1e-12, "{name}: AD differs");
        let counts = operation_counts(model);
        println!(
            "{name}: generated operations: residual {}, Jacobian {}, both {}",
            counts.residual, counts.jacobian, counts.residual_and_jacobian
        );
        let mut group = c.benchmark_group(format!("kernels/{name}"));
        let mut f = SVector::<f64, $ny>::zeros();
        let mut j = dirac::nalgebra::SMatrix::<f64, $ny, $ny>::zeros();
        group.bench_function("generated F", |b| {
            b.iter(|| LagrangeDirac::residual(model, 0.0, black_box(&y), &mut f))
        });
        group.bench_function("hand-written F", |b| b.iter(|| Hand::residual(model, black_box(&y), &mut f)));
        group.bench_function("generated J", |b| {
            b.iter(|| LagrangeDirac::jacobian(model, 0.0, black_box(&y), &mut j))
        });
        group.bench_function("hand-written J", |b| b.iter(|| Hand::jacobian(model, black_box(&y), &mut j)));
        group.bench_function("generated F+J", |b| {
            b.iter(|| {
                LagrangeDirac::residual(model, 0.0, black_box(&y), &mut f);
                LagrangeDirac::jacobian(model, 0.0, black_box(&y), &mut j);
            })
        });
        let mut values = vec![0.0; stored_entries(model)];
        SparseJacobian::jacobian_csc(model, 0.0, &y, &mut values);
        group.bench_function("generated F+J (CSC)", |b| {
            b.iter(|| {
                LagrangeDirac::residual(model, 0.0, black_box(&y), &mut f);
                SparseJacobian::jacobian_csc(model, 0.0, black_box(&y), &mut values);
            })
        });
        group.bench_function("hand-written F+J", |b| {
            b.iter(|| {
                Hand::residual(model, black_box(&y), &mut f);
                Hand::jacobian(model, black_box(&y), &mut j);
            })
        });
        group.bench_function("num-dual F+J", |b| {
            b.iter(|| jacobian(|x| Generic::residual(model, &x), black_box(&y)))
        });
        group.finish();
    }};
}

fn stored_entries<M: SparseJacobian>(_: &M) -> usize
where
    DefaultAllocator: dirac::Storage<M>,
{
    M::JACOBIAN_ROW_INDICES.len()
}

fn operation_counts<M: DenseModel + Derivation>(_: &M) -> dirac::OperationCounts
where
    DefaultAllocator: dirac::Storage<M>,
{
    M::OPERATION_COUNTS
}

fn kernels(c: &mut Criterion) {
    bench_model!(
        c,
        "paper chain (n=3)",
        &MassSpringChain { m1: 1.0, m2: 2.0, m3: 3.0, k1: 4.0, k2: 5.0, k3: 6.0 },
        9
    );
    bench_model!(c, "8-link pendulum, angles (n=8)", &Pendulum8 { m: 0.5, l: 0.25, g: 9.81 }, 24);
    bench_model!(c, "Cartesian N=2 (n=4, m=2)", &Cartesian2 { m: 1.0, g: 9.81, l: 1.0 }, 14);
    bench_model!(c, "Cartesian N=4 (n=8, m=4)", &Cartesian4 { m: 1.0, g: 9.81, l: 1.0 }, 28);
    bench_model!(c, "Cartesian N=8 (n=16, m=8)", &Cartesian8 { m: 1.0, g: 9.81, l: 1.0 }, 56);
    bench_model!(c, "Cartesian N=16 (n=32, m=16)", &Cartesian16 { m: 1.0, g: 9.81, l: 1.0 }, 112);
}

/// Calls one model's F+J kernel `calls` times (the instruction-counting mode).
macro_rules! loop_model {
    ($generated:expr, $calls:expr, $model:expr, $ny:literal) => {{
        let model = $model;
        let y: SVector<f64, $ny> = state(7);
        let mut f = SVector::<f64, $ny>::zeros();
        let mut j = dirac::nalgebra::SMatrix::<f64, $ny, $ny>::zeros();
        for _ in 0..$calls {
            if $generated {
                LagrangeDirac::residual(model, 0.0, black_box(&y), &mut f);
                LagrangeDirac::jacobian(model, 0.0, black_box(&y), &mut j);
            } else {
                Hand::residual(model, black_box(&y), &mut f);
                Hand::jacobian(model, black_box(&y), &mut j);
            }
            black_box((&f, &j));
        }
    }};
}

fn instruction_loop(spec: &str) {
    let calls: u64 = std::env::var("DIRAC_KERNEL_CALLS").ok().and_then(|c| c.parse().ok()).unwrap_or(0);
    let (kind, model) = spec.split_once(' ').expect("DIRAC_KERNEL_LOOP=<generated|hand-written> <model>");
    let generated = match kind {
        "generated" => true,
        "hand-written" => false,
        other => panic!("unknown kernel kind {other}; expected generated or hand-written"),
    };
    match model {
        "paper" => loop_model!(
            generated,
            calls,
            &MassSpringChain { m1: 1.0, m2: 2.0, m3: 3.0, k1: 4.0, k2: 5.0, k3: 6.0 },
            9
        ),
        "cartesian2" => loop_model!(generated, calls, &Cartesian2 { m: 1.0, g: 9.81, l: 1.0 }, 14),
        "cartesian4" => loop_model!(generated, calls, &Cartesian4 { m: 1.0, g: 9.81, l: 1.0 }, 28),
        other => panic!("unknown model {other}; expected paper, cartesian2 or cartesian4"),
    }
}

criterion_group!(benches, kernels);

fn main() {
    if let Ok(spec) = std::env::var("DIRAC_KERNEL_LOOP") {
        instruction_loop(&spec);
        return;
    }
    benches();
    Criterion::default().configure_from_args().final_summary();
}
