//! Rigid bodies in space (`dirac::components::bodies`) against closed forms: a free
//! asymmetric body against Jacobi's elliptic-function solution of Euler's equations.

use dirac::components::bodies::RigidBody;
use dirac::prelude::*;

use crate::every_method::{Fineness, Method};

/// Jacobi's `sn, cn, dn` of `u` with parameter `m = k²`, by the arithmetic-geometric mean
/// (descending Landen transformation; Abramowitz and Stegun 16.4). Written here, apart from
/// everything dirac computes; `elliptic_functions_satisfy_their_differential_equations`
/// checks it.
fn sn_cn_dn(u: f64, m: f64) -> (f64, f64, f64) {
    let mut a = vec![1.0];
    let mut c = vec![m.sqrt()];
    let mut b = (1.0 - m).sqrt();
    while c.last().unwrap().abs() > 1e-17 && a.len() < 40 {
        let (an, bn) = (*a.last().unwrap(), b);
        a.push(0.5 * (an + bn));
        c.push(0.5 * (an - bn));
        b = (an * bn).sqrt();
    }
    let n = a.len() - 1;
    let mut phi = 2f64.powi(n as i32) * a[n] * u;
    for i in (1..=n).rev() {
        phi = 0.5 * (phi + (c[i] / a[i] * phi.sin()).asin());
    }
    let (sn, cn) = (phi.sin(), phi.cos());
    // dn² = 1 − m sn² = cn² + (1 − m) sn², a sum of two squares, with no cancellation where
    // cn is small (A&S's cn / cos(φ₁ − φ₀) loses digits there).
    let dn = (cn * cn + (1.0 - m) * sn * sn).sqrt();
    (sn, cn, dn)
}

/// The angular velocity in the body's axes of a free body with principal moments
/// `j1 < j2 < j3` that turns at `(a, 0, c)` at `t = 0` (a, c > 0) with `M² > 2 E j2`: Landau
/// and Lifshitz, Mechanics §37.
struct EulerTop {
    j: [f64; 3],
    amplitude: [f64; 3],
    rate: f64,
    m: f64,
}

impl EulerTop {
    fn new(j: [f64; 3], a: f64, c: f64) -> EulerTop {
        let [j1, j2, j3] = j;
        let two_e = j1 * a * a + j3 * c * c;
        let mm = j1 * j1 * a * a + j3 * j3 * c * c;
        assert!(mm > two_e * j2, "the closed form below is the one for M² > 2 E j2");
        let amplitude = [
            ((two_e * j3 - mm) / (j1 * (j3 - j1))).sqrt(),
            ((two_e * j3 - mm) / (j2 * (j3 - j2))).sqrt(),
            ((mm - two_e * j1) / (j3 * (j3 - j1))).sqrt(),
        ];
        let rate = ((j3 - j2) * (mm - two_e * j1) / (j1 * j2 * j3)).sqrt();
        let m = (j2 - j1) * (two_e * j3 - mm) / ((j3 - j2) * (mm - two_e * j1));
        EulerTop { j, amplitude, rate, m }
    }

    fn omega(&self, t: f64) -> [f64; 3] {
        let (sn, cn, dn) = sn_cn_dn(self.rate * t, self.m);
        [self.amplitude[0] * cn, self.amplitude[1] * sn, self.amplitude[2] * dn]
    }

    /// The residual of Euler's equations `J Ω̇ = (J Ω) × Ω` at `t`, by central differences.
    fn euler_residual(&self, t: f64) -> f64 {
        let h = 1e-5;
        let (w, wp, wm) = (self.omega(t), self.omega(t + h), self.omega(t - h));
        let [j1, j2, j3] = self.j;
        let dw: Vec<f64> = (0..3).map(|i| (wp[i] - wm[i]) / (2.0 * h)).collect();
        let r = [
            j1 * dw[0] - (j2 - j3) * w[1] * w[2],
            j2 * dw[1] - (j3 - j1) * w[2] * w[0],
            j3 * dw[2] - (j1 - j2) * w[0] * w[1],
        ];
        r.iter().fold(0.0f64, |m, x| m.max(x.abs()))
    }
}

#[test]
fn elliptic_functions_satisfy_their_differential_equations() {
    // sn' = cn dn, cn' = −sn dn, dn' = −m sn cn, sn² + cn² = 1, dn² + m sn² = 1, and the
    // limit m = 0 (sin, cos, 1).
    for &m in &[0.0, 0.3, 0.9, 0.999_999] {
        for k in 0..40 {
            let u = -3.0 + 0.17 * k as f64;
            let (sn, cn, dn) = sn_cn_dn(u, m);
            assert!((sn * sn + cn * cn - 1.0).abs() < 1e-14);
            assert!((dn * dn + m * sn * sn - 1.0).abs() < 1e-14);
            let h = 1e-5;
            let (sp, cp, dp) = sn_cn_dn(u + h, m);
            let (sm, cm, dm) = sn_cn_dn(u - h, m);
            assert!(((sp - sm) / (2.0 * h) - cn * dn).abs() < 1e-9, "sn' at m = {m}, u = {u}");
            assert!(((cp - cm) / (2.0 * h) + sn * dn).abs() < 1e-9, "cn' at m = {m}, u = {u}");
            assert!(((dp - dm) / (2.0 * h) + m * sn * cn).abs() < 1e-9, "dn' at m = {m}, u = {u}");
            if m == 0.0 {
                assert!(
                    (sn - u.sin()).abs() < 1e-15 && (cn - u.cos()).abs() < 1e-15 && (dn - 1.0).abs() < 1e-15
                );
            }
        }
    }
}

/// A free body, its axes along space's, turning at `(a, 0, c)`: integrated by `method`, its
/// angular velocity in its own axes against the elliptic-function solution; returns the
/// largest difference, and the largest drift of `RᵀR = I`.
fn free_body_errors<I: Integrator<RigidBody>>(integrator: &mut I, top: &EulerTop, t_end: f64) -> (f64, f64) {
    let body = RigidBody::new(1.0, top.j);
    let [a, _, c] = top.omega(0.0);
    let eye = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let (q, v) = body.state([0.0; 3], eye, [0.0; 3], [a, 0.0, c]);
    let times: Vec<f64> = (1..=50).map(|k| t_end * k as f64 / 50.0).collect();
    let start = consistent_state(&body, 0.0, &q, &v, Consistency::default()).expect("a consistent start");
    let solution = integrator.solve(0.0, &start, t_end, &Sampling::Times(times)).expect("the body turns");
    let mut error = 0.0f64;
    for (k, &t) in solution.t().iter().enumerate() {
        let exact = top.omega(t);
        let got = [
            solution.output(RigidBody::WX)[k],
            solution.output(RigidBody::WY)[k],
            solution.output(RigidBody::WZ)[k],
        ];
        for i in 0..3 {
            error = error.max((got[i] - exact[i]).abs());
        }
    }
    let drift = solution.holonomic_residual().iter().fold(0.0f64, |m, x| m.max(x.abs()));
    (error, drift)
}

#[test]
fn a_free_asymmetric_body_turns_as_jacobis_elliptic_functions_say() {
    let j = [1.0, 2.0, 3.0];
    // k² = 1/3, then a tumble near the intermediate axis: k² = 1 − 10⁻⁴, where the body
    // lingers by its middle axis and flips over, once every 2 K(k) / rate ≈ 9 s.
    let generic = EulerTop::new(j, 1.0, 1.0);
    let tumble = EulerTop::new(j, 1.0, (1.0f64 / (3.0 * (1.0 - 1e-4))).sqrt());
    assert!((tumble.m - (1.0 - 1e-4)).abs() < 1e-12);
    for top in [&generic, &tumble] {
        for k in 0..100 {
            let r = top.euler_residual(0.1 * k as f64);
            assert!(r < 1e-8, "the closed form solves Euler's equations: {r:e} at k² = {}", top.m);
        }
    }
    let body = RigidBody::new(1.0, j);
    // Bounds: about five times what each method reached here. Near the separatrix an error in
    // the energy moves the flips in time, so the tumble's bounds are wider.
    for (top, t_end, adaptive, variational) in [(&generic, 10.0, 1e-9, 2e-5), (&tumble, 30.0, 1e-6, 2e-5)] {
        each_integrator!(&body, Fineness::new(1e-11, 1e-11, 1e-3).projected(), |method, integrator| {
            let (error, drift) = free_body_errors(&mut integrator, top, t_end);
            let bound = if method == Method::Variational { variational } else { adaptive };
            println!(
                "{}: k² = {:.7}: max |Ω − Ω_exact| = {error:.2e}, max |RᵀR − I| = {drift:.1e}",
                method.name(),
                top.m
            );
            assert!(error < bound, "{}: {error:e}", method.name());
            assert!(drift < 1e-14, "{}: the rotation left SO(3) by {drift:e}", method.name());
        });
    }
    // The variational integrator is of second order on the body: halving its step quarters
    // its error.
    let error_at = |h: f64| {
        let mut variational =
            Variational::new(&body, h, VariationalOptions::default()).expect("a valid step");
        free_body_errors(&mut variational, &generic, 10.0).0
    };
    let ratio = error_at(2e-3) / error_at(1e-3);
    assert!((3.8..4.2).contains(&ratio), "error ratio {ratio} on halving the step");
}
