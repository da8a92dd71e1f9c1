//! diffsol 0.18 (BDF, ESDIRK34, Tsit45) on the two problems of `benches/work_precision.rs`, in
//! the form a diffsol user would write them: explicit ODEs with a hand-written right-hand side
//! and an analytic Jacobian-vector product, dense nalgebra matrices and LU.
//!
//! - pendulum (m = 1, g = 9.81, l = 1, released at rest from the horizontal): Cartesian
//!   y = (x, y, vx, vy) with the multiplier eliminated at acceleration level (index-1 form),
//!   λ = m (g y − |v|²) / (2 |q|²), error at t = 1 against the published x(1), y(1).
//! - chain: the paper's three-mass chain with the massless tear coordinate eliminated, a linear
//!   ODE of six states, error of x1, x2, x3 at t = 20 against the exact modal solution (passed
//!   on the command line by run.sh, computed by `cargo bench -p dirac-benches --bench work_precision -- reference`).
//!
//! Both forms are smaller and easier than the index-2 DAE dirac's Radau and IDA integrate (13
//! unknowns for the chain), so the comparison favours diffsol. Its BDF initialises DAEs by
//! solving the algebraic rows for the algebraic unknowns, which index-2 multipliers (absent
//! from every algebraic row) do not allow.
//!
//! - pendulum8: the zoo's 8-link pendulum in its angles, `M(θ) θ̈ = r(θ, ω)` solved per
//!   evaluation, error of the angles at t = 2 against the reference `run.sh` passes (from
//!   `cargo bench -p dirac-benches --bench work_precision -- reference`).
//!
//! Prints CSV `problem,tol,error,seconds,steps` for the method named by the first argument
//! (`bdf`, `esdirk34` or `tsit45`); seconds is the median of 21 solves, each creating the
//! solver (with its initial step and Jacobian) and integrating to the end time.

#[path = "../../../support/median.rs"]
mod median;

use diffsol::{
    NalgebraLU, NalgebraMat, OdeBuilder, OdeEquationsImplicit, OdeSolverMethod, OdeSolverStopReason, Vector,
};
use median::median_seconds;

type M = NalgebraMat<f64>;

const G: f64 = 9.81;
const MASS: f64 = 1.0;

fn pendulum_rhs(y: &[f64], _p: &[f64], _t: f64, f: &mut [f64]) {
    let (x, z, vx, vz) = (y[0], y[1], y[2], y[3]);
    let lambda = MASS * (G * z - (vx * vx + vz * vz)) / (2.0 * (x * x + z * z));
    f[0] = vx;
    f[1] = vz;
    f[2] = 2.0 * x * lambda / MASS;
    f[3] = -G + 2.0 * z * lambda / MASS;
}

fn pendulum_jac_mul(y: &[f64], _p: &[f64], _t: f64, w: &[f64], jw: &mut [f64]) {
    let (x, z, vx, vz) = (y[0], y[1], y[2], y[3]);
    let r2 = x * x + z * z;
    let num = G * z - (vx * vx + vz * vz);
    let lambda = MASS * num / (2.0 * r2);
    let dl_dx = -MASS * num * x / (r2 * r2);
    let dl_dz = MASS * G / (2.0 * r2) - MASS * num * z / (r2 * r2);
    let dl_dvx = -MASS * vx / r2;
    let dl_dvz = -MASS * vz / r2;
    let dl = dl_dx * w[0] + dl_dz * w[1] + dl_dvx * w[2] + dl_dvz * w[3];
    jw[0] = w[2];
    jw[1] = w[3];
    jw[2] = 2.0 * (lambda * w[0] + x * dl) / MASS;
    jw[3] = 2.0 * (lambda * w[1] + z * dl) / MASS;
}

const MASSES: [f64; 3] = [1.0, 2.0, 3.0];
const SPRINGS: [f64; 3] = [4.0, 5.0, 6.0];

/// −M⁻¹ K x for the chain wall–k1–m1–k2–m2–k3–m3.
fn chain_accel(x: &[f64], a: &mut [f64]) {
    let [k1, k2, k3] = SPRINGS;
    a[0] = (-(k1 + k2) * x[0] + k2 * x[1]) / MASSES[0];
    a[1] = (k2 * x[0] - (k2 + k3) * x[1] + k3 * x[2]) / MASSES[1];
    a[2] = (k3 * x[1] - k3 * x[2]) / MASSES[2];
}

fn chain_rhs(y: &[f64], _p: &[f64], _t: f64, f: &mut [f64]) {
    f[..3].copy_from_slice(&y[3..]);
    chain_accel(&y[..3], &mut f[3..]);
}

fn chain_jac_mul(_y: &[f64], _p: &[f64], _t: f64, w: &[f64], jw: &mut [f64]) {
    jw[..3].copy_from_slice(&w[3..]);
    chain_accel(&w[..3], &mut jw[3..]);
}

/// The 8-link pendulum of the zoo (absolute angles from the downward vertical, equal masses m
/// at the joints, equal lengths l), as a diffsol user would write it: `M(θ) θ̈ = r(θ, ω)` with
/// `M_kj = (8 − max(k, j)) m l² cos(θ_k − θ_j)` and
/// `r_k = −Σ_j (8 − max(k, j)) m l² ω_j² sin(θ_k − θ_j) − (8 − k) m g l sin θ_k` (0-based),
/// solved by a Cholesky factorisation on the stack.
const LINKS: usize = 8;
const LINK_MASS: f64 = 0.5;
const LINK_LENGTH: f64 = 0.25;

fn pendulum8_rhs(y: &[f64], _p: &[f64], _t: f64, f: &mut [f64]) {
    let (theta, omega) = y.split_at(LINKS);
    let ml2 = LINK_MASS * LINK_LENGTH * LINK_LENGTH;
    let mut m = [[0.0; LINKS]; LINKS];
    let mut r = [0.0; LINKS];
    for k in 0..LINKS {
        r[k] = -((LINKS - k) as f64) * LINK_MASS * G * LINK_LENGTH * theta[k].sin();
        for j in 0..LINKS {
            let c = (LINKS - k.max(j)) as f64 * ml2;
            let (sin, cos) = (theta[k] - theta[j]).sin_cos();
            m[k][j] = c * cos;
            r[k] -= c * omega[j] * omega[j] * sin;
        }
    }
    // Cholesky M = L Lᵀ in place (lower triangle), then the two triangular solves.
    for j in 0..LINKS {
        let mut d = m[j][j];
        for k in 0..j {
            d -= m[j][k] * m[j][k];
        }
        let d = d.sqrt();
        m[j][j] = d;
        for i in j + 1..LINKS {
            let mut s = m[i][j];
            for k in 0..j {
                s -= m[i][k] * m[j][k];
            }
            m[i][j] = s / d;
        }
    }
    for i in 0..LINKS {
        for k in 0..i {
            r[i] -= m[i][k] * r[k];
        }
        r[i] /= m[i][i];
    }
    for i in (0..LINKS).rev() {
        for k in i + 1..LINKS {
            r[i] -= m[k][i] * r[k];
        }
        r[i] /= m[i][i];
    }
    f[..LINKS].copy_from_slice(omega);
    f[LINKS..].copy_from_slice(&r);
}

/// The Jacobian-vector product of the 8-link pendulum by a forward difference (its analytic
/// form, through the derivative of `M(θ)⁻¹`, is not what a user writes by hand); used only by
/// the implicit methods' Newton iterations. diffsol forms its dense Jacobian from one product
/// per column at the same `y`, so `f(y)` is kept from the last call and evaluated again only
/// when `y` changes (the right-hand side depends on neither `t` nor `p`): one right-hand side
/// per column, as a hand-written difference Jacobian would take.
fn pendulum8_jac_mul(y: &[f64], p: &[f64], t: f64, w: &[f64], jw: &mut [f64]) {
    thread_local! {
        static AT: std::cell::Cell<Option<([f64; 2 * LINKS], [f64; 2 * LINKS])>> =
            const { std::cell::Cell::new(None) };
    }
    let norm = w.iter().map(|x| x * x).sum::<f64>().sqrt();
    if norm == 0.0 {
        jw.fill(0.0);
        return;
    }
    let f0 = match AT.get() {
        Some((at, f0)) if at[..] == y[..] => f0,
        _ => {
            let (mut at, mut f0) = ([0.0; 2 * LINKS], [0.0; 2 * LINKS]);
            at.copy_from_slice(y);
            pendulum8_rhs(y, p, t, &mut f0);
            AT.set(Some((at, f0)));
            f0
        }
    };
    let eps = 1e-7 * (1.0 + y.iter().map(|x| x * x).sum::<f64>().sqrt()) / norm;
    let mut shifted = [0.0; 2 * LINKS];
    for i in 0..2 * LINKS {
        shifted[i] = y[i] + eps * w[i];
    }
    let mut f1 = [0.0; 2 * LINKS];
    pendulum8_rhs(&shifted, p, t, &mut f1);
    for i in 0..2 * LINKS {
        jw[i] = (f1[i] - f0[i]) / eps;
    }
}

/// Integrates `solver` to `t_end`; returns the final state and the number of steps.
fn run<'a, Eqn, S>(mut solver: S, t_end: f64) -> (Vec<f64>, usize)
where
    Eqn: OdeEquationsImplicit<T = f64> + 'a,
    S: OdeSolverMethod<'a, Eqn>,
{
    solver.set_stop_time(t_end).expect("stop time after start");
    while !matches!(solver.step().expect("diffsol step"), OdeSolverStopReason::TstopReached) {}
    let y = solver.state().y;
    ((0..y.len()).map(|i| y.get_index(i)).collect(), solver.get_statistics().number_of_steps)
}

/// Creates the solver named `$method` for `$problem` and integrates it to `$t_end`.
macro_rules! solve {
    ($problem:expr, $method:expr, $t_end:expr) => {
        match $method {
            "bdf" => run($problem.bdf::<NalgebraLU<f64>>().expect("bdf"), $t_end),
            "esdirk34" => run($problem.esdirk34::<NalgebraLU<f64>>().expect("esdirk34"), $t_end),
            "tsit45" => run($problem.tsit45().expect("tsit45"), $t_end),
            other => panic!("unknown method {other}; expected bdf, esdirk34 or tsit45"),
        }
    };
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 5 + LINKS {
        eprintln!("usage: dirac-peer-diffsol bdf|esdirk34|tsit45 x1(20) x2(20) x3(20) θ1(2) … θ8(2)");
        std::process::exit(2);
    }
    let method = args[1].as_str();
    let reference: Vec<f64> = args[2..].iter().map(|a| a.parse().expect("a number")).collect();
    let (chain_ref, pendulum8_ref) = reference.split_at(3);
    let tols = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10];
    println!("problem,tol,error,seconds,steps");
    for tol in tols {
        let problem = OdeBuilder::<M>::new()
            .rtol(tol)
            .atol([tol; 4])
            .rhs_implicit(pendulum_rhs, pendulum_jac_mul)
            .init(|_p, _t, y| y.copy_from_slice(&[1.0, 0.0, 0.0, 0.0]), 4)
            .build()
            .expect("pendulum problem");
        let (mut error, mut drift) = (0.0, 0.0);
        let (seconds, steps) = median_seconds(|| {
            let (y, steps) = solve!(problem, method, 1.0);
            error = f64::max((y[0] + 0.986_291_751_131_875_3).abs(), (y[1] + 0.165_010_853_125_541_17).abs());
            drift = (y[0] * y[0] + y[1] * y[1] - 1.0).abs();
            steps
        });
        println!("pendulum,{tol},{error:.3e},{seconds:.6e},{steps}");
        // The index-1 form keeps the constraint only to the integration error; shown on stderr.
        eprintln!("diffsol {method}, pendulum, tol {tol:e}: |x² + y² − 1| at t = 1 is {drift:.1e}");
    }
    for tol in tols {
        let problem = OdeBuilder::<M>::new()
            .rtol(tol)
            .atol([tol; 6])
            .rhs_implicit(chain_rhs, chain_jac_mul)
            .init(|_p, _t, y| y.copy_from_slice(&[0.1, 0.0, 0.0, 0.0, 0.0, 0.0]), 6)
            .build()
            .expect("chain problem");
        let mut error = 0.0;
        let (seconds, steps) = median_seconds(|| {
            let (y, steps) = solve!(problem, method, 20.0);
            error = (0..3).map(|i| (y[i] - chain_ref[i]).abs()).fold(0.0, f64::max);
            steps
        });
        println!("chain,{tol},{error:.3e},{seconds:.6e},{steps}");
    }
    for tol in tols {
        let problem = OdeBuilder::<M>::new()
            .rtol(tol)
            .atol([tol; 2 * LINKS])
            .rhs_implicit(pendulum8_rhs, pendulum8_jac_mul)
            .init(
                |_p, _t, y| {
                    let mut start = [0.0; 2 * LINKS];
                    for (i, theta) in start[..LINKS].iter_mut().enumerate() {
                        *theta = 0.3 + 0.05 * i as f64;
                    }
                    y.copy_from_slice(&start);
                },
                2 * LINKS,
            )
            .build()
            .expect("8-link pendulum problem");
        let mut error = 0.0;
        let (seconds, steps) = median_seconds(|| {
            let (y, steps) = solve!(problem, method, 2.0);
            error = (0..LINKS).map(|i| (y[i] - pendulum8_ref[i]).abs()).fold(0.0, f64::max);
            steps
        });
        println!("pendulum8,{tol},{error:.3e},{seconds:.6e},{steps}");
    }
}
