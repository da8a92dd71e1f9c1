//! A robot on a free flyer against Pinocchio's: the map from Pinocchio's velocities (the base's
//! in its own axes, then the joints') to the rates of dirac's coordinates, and the comparison
//! of the mass matrix, gravity and bias torques through it. Shared by
//! `tests/integration/floating.rs` (the Panda) and `tests/references/talos_floating.sh` (Talos,
//! whose model takes too long to compile for CI).

use dirac::joint_space;
use dirac::nalgebra::{DMatrix, DVector, Matrix3, Vector3};
use dirac::prelude::*;

pub fn table(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines.next().expect("a header").split(',').map(str::to_owned).collect();
    let rows = lines.map(|l| l.split(',').map(|x| x.parse().expect("a number")).collect()).collect();
    (header, rows)
}

/// The largest entry of `a − b`, relative to the largest entry of `b` (or 1 if that is less).
fn relative_error(a: &DVector<f64>, b: &[f64]) -> f64 {
    let scale = b.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
    a.iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs())) / scale
}

pub fn hat(w: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -w.z, w.y, w.z, 0.0, -w.x, -w.y, w.x, 0.0)
}

/// The index of a coordinate by name.
pub fn coordinate<M: Named>(name: &str) -> usize {
    M::NAMES
        .coordinate_names()
        .iter()
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("no coordinate {name}"))
}

/// Pinocchio's free-flyer velocity `ν = (v, ω, q̇)` (`v` and `ω` in the base's axes, then the
/// joints in Pinocchio's order) as rates of dirac's coordinates: `ẋ = R v`, `Ṙ = R ω̂`, `q̇`.
/// Returns `G` with `rates = G ν` and `Ġ ν = (R ω̂ v, R ω̂ ω̂, 0)`, the part of the
/// coordinates' acceleration that `ν̇` does not give; `rows[k]` is the coordinate of joint `k`.
fn free_flyer<M: Named>(r: &Matrix3<f64>, nu: &[f64], joints: &[String]) -> (DMatrix<f64>, DVector<f64>) {
    let n = M::NAMES.coordinate_names().len();
    let x = ["x", "y", "z"].map(|a| coordinate::<M>(&format!("root_joint_{a}")));
    let rij = |i: usize, j: usize| coordinate::<M>(&format!("root_joint_r{}{}", i + 1, j + 1));
    let mut g = DMatrix::zeros(n, 6 + joints.len());
    for a in 0..3 {
        let e = Vector3::ith(a, 1.0);
        let (along, turn) = (r * e, r * hat(&e));
        for i in 0..3 {
            g[(x[i], a)] = along[i];
            for j in 0..3 {
                g[(rij(i, j), 3 + a)] = turn[(i, j)];
            }
        }
    }
    for (k, joint) in joints.iter().enumerate() {
        g[(coordinate::<M>(joint), 6 + k)] = 1.0;
    }
    let (v, w) = (Vector3::new(nu[0], nu[1], nu[2]), Vector3::new(nu[3], nu[4], nu[5]));
    let mut gdot_nu = DVector::zeros(n);
    let (linear, angular) = (r * hat(&w) * v, r * hat(&w) * hat(&w));
    for i in 0..3 {
        gdot_nu[x[i]] = linear[i];
        for j in 0..3 {
            gdot_nu[rij(i, j)] = angular[(i, j)];
        }
    }
    (g, gdot_nu)
}

/// A robot with a free-flyer root against Pinocchio's `crba`, `computeGeneralizedGravity` and
/// `nonLinearEffects` in its velocities `ν`: they are `Gᵀ M G`, `Gᵀ g` and
/// `Gᵀ (b(q, G ν) + M Ġ ν)` in dirac's (the constraint forces that hold `RᵀR = I` do no work
/// along `G`, so `Gᵀ` removes them). The worst relative errors of the three, over the file's
/// states.
pub fn against_pinocchio<M: DenseModel + Named>(model: &M, csv: &str) -> [f64; 3]
where
    DefaultAllocator: Storage<M>,
{
    let (header, rows) = table(csv);
    let first_rate = header.iter().position(|h| h == "base_vx").expect("the base's velocity");
    let joints = &header[12..first_rate];
    let nv = 6 + joints.len();
    assert_eq!(header.len(), 12 + joints.len() + nv + nv * nv + 2 * nv);
    let n = M::NAMES.coordinate_names().len();
    let mut worst = [0.0_f64; 3];
    for row in &rows {
        let r = Matrix3::from_row_slice(&row[3..12]);
        let nu = &row[first_rate..first_rate + nv];
        let mut q = VecQ::<M>::zeros();
        for (i, axis) in ["x", "y", "z"].into_iter().enumerate() {
            q[coordinate::<M>(&format!("root_joint_{axis}"))] = row[i];
            for j in 0..3 {
                q[coordinate::<M>(&format!("root_joint_r{}{}", i + 1, j + 1))] = r[(i, j)];
            }
        }
        for (k, joint) in joints.iter().enumerate() {
            q[coordinate::<M>(joint)] = row[12 + k];
        }
        let (g, gdot_nu) = free_flyer::<M>(&r, nu, joints);
        let rates = &g * DVector::from_column_slice(nu);
        let v = VecQ::<M>::from_column_slice(rates.as_slice());
        let mass = DMatrix::from_column_slice(n, n, joint_space::mass_matrix(model, 0.0, &q).as_slice());
        let gravity = DVector::from_column_slice(joint_space::gravity_torques(model, 0.0, &q).as_slice());
        let bias = DVector::from_column_slice(joint_space::bias_torques(model, 0.0, &q, &v).as_slice());
        let at = first_rate + nv;
        // Row-major in the file: the transpose's column-major entries.
        let m_nu = (g.transpose() * &mass * &g).transpose();
        let m_nu = DVector::from_column_slice(m_nu.as_slice());
        worst[0] = worst[0].max(relative_error(&m_nu, &row[at..at + nv * nv]));
        let at = at + nv * nv;
        worst[1] = worst[1].max(relative_error(&(g.transpose() * gravity), &row[at..at + nv]));
        let nle = g.transpose() * (bias + &mass * gdot_nu);
        worst[2] = worst[2].max(relative_error(&nle, &row[at + nv..at + 2 * nv]));
    }
    worst
}
