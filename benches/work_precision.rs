//! Work-precision data of dirac's Radau on the pendulum (error at t = 1 against the published
//! values of DESIGN.md §3) and the paper's torn chain (largest error of x1, x2, x3 at t = 20
//! against the exact modal solution), as CSV: `problem,tol,error,seconds,steps`, seconds the
//! median of 21 solves. `benches/peers/run.sh` runs it beside SUNDIALS IDA on the same
//! problems. With the argument `reference`, prints the chain's exact x1, x2, x3 at t = 20.
//!
//! Run: `cargo bench --bench work_precision`.

#![allow(missing_docs)]

#[path = "../tests/zoo/mod.rs"]
mod zoo;

#[path = "support/median.rs"]
mod median;

use dirac::nalgebra::{Matrix3, SymmetricEigen, Vector3};
use dirac::prelude::*;
use median::median_seconds;
use zoo::*;

/// x(t) of M ẍ = −K x from x(0) = (0.1, 0, 0) at rest, by the eigensystem of M^{-1/2} K M^{-1/2}.
fn chain_exact(t: f64) -> Vector3<f64> {
    let (m, k) = ([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]);
    let kk = Matrix3::new(k[0] + k[1], -k[1], 0.0, -k[1], k[1] + k[2], -k[2], 0.0, -k[2], k[2]);
    let l = Matrix3::from_diagonal(&Vector3::new(m[0], m[1], m[2]).map(|x: f64| 1.0 / x.sqrt()));
    let eig = SymmetricEigen::new(l * kk * l);
    let u0 = l.try_inverse().expect("diagonal") * Vector3::new(0.1, 0.0, 0.0);
    let mut u = Vector3::zeros();
    for i in 0..3 {
        let phi = eig.eigenvectors.column(i);
        u += phi * (phi.dot(&u0) * (eig.eigenvalues[i].sqrt() * t).cos());
    }
    l * u
}

fn main() {
    if std::env::args().any(|a| a == "reference") {
        let x = chain_exact(20.0);
        println!("{:.17e} {:.17e} {:.17e}", x[0], x[1], x[2]);
        return;
    }
    let tols = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10];
    println!("problem,tol,error,seconds,steps");
    let p = unit_pendulum();
    let start = horizontal_start(&p);
    for tol in tols {
        let mut error = 0.0;
        let (seconds, steps) = median_seconds(|| {
            let mut radau = Radau::new(&p, RadauOptions::tolerances(tol, tol)).expect("valid");
            let sol = radau.solve(0.0, &start, 1.0, &Sampling::Times(vec![1.0])).expect("integrates");
            let (x, y) = (sol.q(Pendulum::X)[0], sol.q(Pendulum::Y)[0]);
            error = f64::max((x + 0.986_291_751_131_875_3).abs(), (y + 0.165_010_853_125_541_17).abs());
            sol.stats.steps
        });
        println!("pendulum,{tol},{error:.3e},{seconds:.6e},{steps}");
    }
    let chain = paper_chain();
    let start = paper_chain_start(&chain);
    let exact = chain_exact(20.0);
    let masses = [Chain::left(Primitive1::X1), Chain::left(Primitive1::X2), Chain::right(Primitive2::X3)];
    for tol in tols {
        let mut error = 0.0;
        let (seconds, steps) = median_seconds(|| {
            let mut radau = Radau::new(&chain, RadauOptions::tolerances(tol, tol)).expect("valid");
            let sol = radau.solve(0.0, &start, 20.0, &Sampling::Times(vec![20.0])).expect("integrates");
            error =
                masses.iter().enumerate().map(|(i, c)| (sol.q(*c)[0] - exact[i]).abs()).fold(0.0, f64::max);
            sol.stats.steps
        });
        println!("chain,{tol},{error:.3e},{seconds:.6e},{steps}");
    }
}
