//! Rigid bodies in space (`dirac::components::bodies`) against closed forms: a free
//! asymmetric body against Jacobi's elliptic-function solution of Euler's equations.

use dirac::State;
use dirac::components::bodies::RigidBody;
use dirac::prelude::*;

use crate::every_method::{Fineness, Method};
use crate::zoo::bodies::{
    PlanarDoublePendulum, SpatialDoublePendulum, Stewart, double_pendulums, spatial_start,
};

/// Jacobi's `sn, cn, dn` of `u` with parameter `m = k²`, by the arithmetic-geometric mean
/// (descending Landen transformation; Abramowitz and Stegun 16.4). Written here, apart from
/// everything dirac computes; `elliptic_functions_satisfy_their_differential_equations`
/// checks it.
fn sn_cn_dn(u: f64, m: f64) -> (f64, f64, f64) {
    let (mut a, mut c) = (vec![1.0], vec![m.sqrt()]);
    let (mut an, mut bn, mut cn) = (1.0f64, (1.0 - m).sqrt(), m.sqrt());
    while cn.abs() > 1e-17 && a.len() < 40 {
        (an, bn, cn) = (0.5 * (an + bn), (an * bn).sqrt(), 0.5 * (an - bn));
        a.push(an);
        c.push(cn);
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

/// The joint angles of the spatial pendulum: `R e3 = (sin θ, 0, cos θ)`.
fn joint_angles(solution: &Solution<SpatialDoublePendulum, impl Sized>, k: usize) -> [f64; 2] {
    let angle = |link: &str| {
        let at = |name: &str| solution.column(&format!("{link}.{name}")).expect("a column")[k];
        at("r13").atan2(at("r33"))
    };
    [angle("link1"), angle("link2")]
}

#[test]
fn a_double_pendulum_of_two_bodies_and_two_revolute_joints_is_the_planar_one() {
    let (spatial, planar) = double_pendulums();
    let (th, w) = ([0.9, -0.4], [0.3, 1.1]);
    let times: Vec<f64> = (1..=20).map(|k| 0.1 * k as f64).collect();
    let tight = RadauOptions { projection: true, ..RadauOptions::tolerances(1e-13, 1e-13) };
    let start = spatial_start(&spatial, th, w);
    let bodies = Radau::new(&spatial, tight)
        .expect("valid options")
        .solve(0.0, &start, 2.0, &Sampling::Times(times.clone()))
        .expect("it swings");
    let mut state = State::<PlanarDoublePendulum>::zeros();
    state.set_q(PlanarDoublePendulum::TH1, th[0]).set_q(PlanarDoublePendulum::TH2, th[1]);
    state.set_v(PlanarDoublePendulum::TH1, w[0]).set_v(PlanarDoublePendulum::TH2, w[1]);
    let planar_start =
        consistent_state(&planar, 0.0, &state.q, &state.v, Consistency::default()).expect("a start");
    let reference = Radau::new(&planar, RadauOptions::tolerances(1e-13, 1e-13))
        .expect("valid options")
        .solve(0.0, &planar_start, 2.0, &Sampling::Times(times))
        .expect("it swings");
    let mut error = 0.0f64;
    for k in 0..bodies.len() {
        let got = joint_angles(&bodies, k);
        error = error.max((got[0] - reference.q(PlanarDoublePendulum::TH1)[k]).abs());
        error = error.max((got[1] - reference.q(PlanarDoublePendulum::TH2)[k]).abs());
    }
    let drift = bodies.holonomic_residual().iter().fold(0.0f64, |m, x| m.max(x.abs()));
    println!(
        "bodies against the planar model: max |Δθ| = {error:.2e}; largest holonomic residual {drift:.1e}"
    );
    assert!(error < 1e-10, "{error:e}");
    assert!(drift < 1e-14, "{drift:e}");
}

#[test]
fn joints_and_bodies_have_the_derivatives_their_differences_say() {
    // Every generated block of the body and of the composite's holonomic rows (A = ∂φ/∂q,
    // ∂(A v)/∂q, ∂(Aᵀμ)/∂q, and ∂φ/∂θ for the joints' offsets) against central differences,
    // at random states (off the constraints: the blocks hold everywhere).
    let (spatial, _) = double_pendulums();
    let body = RigidBody::new(1.3, [0.2, 0.3, 0.4]).with_products([0.01, -0.02, 0.03]).with_gravity(9.81);
    crate::util::check_jacobian_by_differences(&body, 41, 3);
    crate::blocks::check_blocks(&body, 42);
    crate::sensitivities::check_parameter_derivatives(&body, 43, 2);
    crate::util::check_jacobian_by_differences(&spatial, 44, 2);
    crate::blocks::check_blocks(&spatial, 45);
    crate::sensitivities::check_parameter_derivatives(&spatial, 46, 2);
}

#[test]
fn the_spatial_double_pendulum_keeps_its_joints_in_every_method() {
    // Every method against the tight planar solution, its joints and rotations held to
    // round-off; the variational integrator's energy bounded over many swings.
    let (spatial, planar) = double_pendulums();
    let (th, w) = ([0.9, -0.4], [0.3, 1.1]);
    let mut state = State::<PlanarDoublePendulum>::zeros();
    state.set_q(PlanarDoublePendulum::TH1, th[0]).set_q(PlanarDoublePendulum::TH2, th[1]);
    state.set_v(PlanarDoublePendulum::TH1, w[0]).set_v(PlanarDoublePendulum::TH2, w[1]);
    let planar_start =
        consistent_state(&planar, 0.0, &state.q, &state.v, Consistency::default()).expect("a start");
    let times: Vec<f64> = (1..=10).map(|k| 0.1 * k as f64).collect();
    let reference = Radau::new(&planar, RadauOptions::tolerances(1e-13, 1e-13))
        .expect("valid options")
        .solve(0.0, &planar_start, 1.0, &Sampling::Times(times.clone()))
        .expect("it swings");
    let start = spatial_start(&spatial, th, w);
    each_integrator!(&spatial, Fineness::new(1e-10, 1e-10, 1e-4).projected(), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 1.0, &Sampling::Times(times.clone())).expect("it swings");
        let mut error = 0.0f64;
        for k in 0..solution.len() {
            let got = joint_angles(&solution, k);
            error = error.max((got[0] - reference.q(PlanarDoublePendulum::TH1)[k]).abs());
            error = error.max((got[1] - reference.q(PlanarDoublePendulum::TH2)[k]).abs());
        }
        let drift = solution.holonomic_residual().iter().fold(0.0f64, |m, x| m.max(x.abs()));
        println!("{}: max |Δθ| = {error:.2e}, largest holonomic residual {drift:.1e}", method.name());
        let bound = if method == Method::Variational { 1e-5 } else { 1e-7 };
        assert!(error < bound, "{}: {error:e}", method.name());
        assert!(drift < 1e-13, "{}: {drift:e}", method.name());
    });
}

/// A heavy top: a body whose point at `l` below its centre of mass, on its axis `e3`, is held
/// at the origin (a spherical joint to the ground, three rows linear in the coordinates).
#[derive(Interconnection)]
#[dirac(holonomic(pivot_x) = top.x - l * top.r13, holonomic(pivot_y) = top.y - l * top.r23)]
#[dirac(holonomic(pivot_z) = top.z - l * top.r33)]
struct HeavyTop {
    top: RigidBody,
    l: f64,
}

/// The closed form of the symmetric heavy top (Goldstein, Classical Mechanics §5.7): with
/// `u = cos θ`, `u̇² = f(u) = (1 − u²)(α − β u) − (b − a u)²`, whose roots `u1 ≤ u2 ≤ 1 < u3`
/// bound the nutation, `u = u1 + (u2 − u1) sn²(λ (t − t1), k)` with `λ = √(β (u3 − u1)) / 2`,
/// `k² = (u2 − u1)/(u3 − u1)`, and the precession `φ̇ = (b − a u)/(1 − u²)`.
struct Goldstein {
    u: [f64; 3],
    lambda: f64,
    m: f64,
    /// The time shift: `u(0)` is the root the top starts at.
    shift: f64,
    a: f64,
    b: f64,
}

impl Goldstein {
    /// The top of moments `i1` (about the pivot, across the axis) and `i3`, weight `m g l`,
    /// started at tilt `theta0` with no nutation rate, precessing at `precession` and spinning
    /// at `omega3` about its axis.
    fn new(i1: f64, i3: f64, mgl: f64, theta0: f64, precession: f64, omega3: f64) -> Goldstein {
        let u0 = theta0.cos();
        let (p_psi, p_phi) = (i3 * omega3, i1 * precession * theta0.sin().powi(2) + i3 * omega3 * u0);
        let energy = 0.5 * i1 * (precession * theta0.sin()).powi(2) + mgl * u0;
        let (a, b) = (p_psi / i1, p_phi / i1);
        let (alpha, beta) = (2.0 * energy / i1, 2.0 * mgl / i1);
        // f(u) = β u³ − (α + a²) u² + (2ab − β) u + (α − b²) = (u − u0)(β u² + c1 u + c0).
        let c1 = -(alpha + a * a) + beta * u0;
        let c0 = (2.0 * a * b - beta) + c1 * u0;
        let disc = (c1 * c1 - 4.0 * beta * c0).sqrt();
        let (r1, r2) = ((-c1 - disc) / (2.0 * beta), (-c1 + disc) / (2.0 * beta));
        let mut u = [u0, r1, r2];
        u.sort_by(f64::total_cmp);
        assert!(u[1] <= 1.0 && u[2] > 1.0, "roots {u:?}");
        let lambda = (beta * (u[2] - u[0])).sqrt() / 2.0;
        let m = (u[1] - u[0]) / (u[2] - u[0]);
        // Started at the upper root u2, half a nutation after the lower one.
        let starts_high = (u0 - u[1]).abs() < (u0 - u[0]).abs();
        let shift = if starts_high { complete_k(m) / lambda } else { 0.0 };
        Goldstein { u, lambda, m, shift, a, b }
    }

    fn cos_theta(&self, t: f64) -> f64 {
        let (sn, _, _) = sn_cn_dn(self.lambda * (t + self.shift), self.m);
        self.u[0] + (self.u[1] - self.u[0]) * sn * sn
    }

    /// The nutation's period, `2 K(k) / λ`.
    fn period(&self) -> f64 {
        2.0 * complete_k(self.m) / self.lambda
    }

    /// The precession over one nutation period: `∫ φ̇ dt` by the trapezoidal rule, exact to
    /// round-off for a smooth periodic integrand with this many points.
    fn precession_per_period(&self) -> f64 {
        let (n, period) = (4000, self.period());
        let rate = |t: f64| {
            let u = self.cos_theta(t);
            (self.b - self.a * u) / (1.0 - u * u)
        };
        (0..n).map(|k| rate(period * k as f64 / n as f64)).sum::<f64>() * period / n as f64
    }
}

/// The complete elliptic integral of the first kind, `K(m) = π / (2 AGM(1, √(1 − m)))`.
fn complete_k(m: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - m).sqrt());
    while (a - b).abs() > 1e-16 * a {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

/// The heavy top and its closed form: moments 0.3, 0.3, 0.5 kg m² about the centre of mass,
/// 1 kg at 0.4 m above the pivot, started at a tilt of 0.6 rad with a slow precession and a
/// spin of 12 rad/s; its start and the closed form.
fn heavy_top() -> (HeavyTop, State<HeavyTop>, Goldstein) {
    let (m, l, g, j1, j3) = (1.0, 0.4, 9.81, 0.3, 0.5);
    let (theta0, precession, omega3) = (0.6f64, 0.8, 12.0);
    let model = HeavyTop { top: RigidBody::new(m, [j1, j1, j3]).with_gravity(g), l };
    // R = R_x(θ0) (Euler angles z-x-z at φ = ψ = 0); Ω in the body's axes.
    let (s, c) = theta0.sin_cos();
    let rotation = [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]];
    // Ω = (θ̇, φ̇ sin θ, ψ̇ + φ̇ cos θ) at ψ = 0, with θ̇ = 0 and the last the spin ω3.
    let omega = [0.0, precession * s, omega3];
    let axis = [rotation[0][2], rotation[1][2], rotation[2][2]];
    let centre = axis.map(|x| l * x);
    // ẋ = l Ṙ e3 = l R (Ω × e3).
    let cross = [omega[1], -omega[0], 0.0];
    let velocity: [f64; 3] =
        std::array::from_fn(|i| l * (0..3).map(|k| rotation[i][k] * cross[k]).sum::<f64>());
    let (q, v) = model.top.state(centre, rotation, velocity, omega);
    let start = consistent_state(&model, 0.0, &q, &v, Consistency::default()).expect("a consistent start");
    let closed = Goldstein::new(j1 + m * l * l, j3, m * g * l, theta0, precession, omega3);
    (model, start, closed)
}

/// The precession angle of the top's axis `R e3 = (sin φ sin θ, −cos φ sin θ, cos θ)`.
fn precession_angle(r13: f64, r23: f64) -> f64 {
    r13.atan2(-r23)
}

#[test]
fn a_heavy_symmetric_top_nutates_and_precesses_as_the_closed_form_says() {
    let (model, start, closed) = heavy_top();
    let period = closed.period();
    let per_period = closed.precession_per_period();
    println!(
        "nutation period {period:.6} s, precession per period {per_period:.6} rad, cos θ in [{:.6}, {:.6}]",
        closed.u[0], closed.u[1]
    );
    let times: Vec<f64> = (1..=60).map(|k| 3.0 * period * k as f64 / 60.0).collect();
    each_integrator!(&model, Fineness::new(1e-11, 1e-11, 1e-4).projected(), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 3.0 * period, &Sampling::Times(times.clone())).expect("it spins");
        let (r13, r23, r33) = (
            solution.column("top.r13").expect("a column"),
            solution.column("top.r23").expect("a column"),
            solution.column("top.r33").expect("a column"),
        );
        let mut nutation = 0.0f64;
        for (k, &t) in solution.t().iter().enumerate() {
            nutation = nutation.max((r33[k] - closed.cos_theta(t)).abs());
        }
        // The precession over each whole nutation period (every 20th sample), unwrapped.
        let mut precession = 0.0f64;
        let (mut phi, mut previous) = (0.0, precession_angle(start.q[5], start.q[8]));
        for k in 0..solution.len() {
            let now = precession_angle(r13[k], r23[k]);
            let mut step = now - previous;
            step -= (step / std::f64::consts::TAU).round() * std::f64::consts::TAU;
            phi += step;
            previous = now;
            if (k + 1) % 20 == 0 {
                precession = precession.max((phi - per_period * ((k + 1) / 20) as f64).abs());
            }
        }
        let drift = solution.holonomic_residual().iter().fold(0.0f64, |m, x| m.max(x.abs()));
        println!(
            "{}: max |cos θ − closed form| = {nutation:.2e}, precession per period off by {precession:.2e}, holonomic residual {drift:.1e}",
            method.name()
        );
        let bound = if method == Method::Variational { 1e-6 } else { 1e-9 };
        assert!(nutation < bound && precession < bound, "{}: {nutation:e}, {precession:e}", method.name());
        assert!(drift < 1e-13, "{}: {drift:e}", method.name());
    });
}

/// The momentum maps of the top's two symmetries, from its coordinates and momenta: turning
/// about space's `z` through the pivot (`δx = ẑ × x`, `δR = ẑ R`) and about its own axis
/// (`δR = R ê3`). Both leave the discrete Lagrangian and the constraints invariant, so the
/// variational integrator conserves them exactly (discrete Noether).
fn top_momenta(q: &VecQ<HeavyTop>, p: &VecQ<HeavyTop>) -> (f64, f64) {
    let r = |i: usize, j: usize| q[3 + 3 * i + j];
    let pr = |i: usize, j: usize| p[3 + 3 * i + j];
    let mut about_z = p[1] * q[0] - p[0] * q[1];
    let mut about_axis = 0.0;
    for j in 0..3 {
        about_z += pr(1, j) * r(0, j) - pr(0, j) * r(1, j);
    }
    for i in 0..3 {
        about_axis += pr(i, 0) * r(i, 1) - pr(i, 1) * r(i, 0);
    }
    (about_z, about_axis)
}

#[test]
fn a_million_variational_steps_of_the_heavy_top_keep_its_energy_and_its_two_momenta() {
    let (model, start, _) = heavy_top();
    let (h, steps) = (1e-3, 1_000_000);
    let mut variational = Variational::new(&model, h, VariationalOptions::default()).expect("a valid step");
    variational.start(0.0, &start, h * steps as f64).expect("it starts");
    let energy = |s: &State<HeavyTop>| model.energy(0.0, &s.q, &s.v, &s.p);
    let (e0, (z0, a0)) = (energy(&start), top_momenta(&start.q, &start.p));
    // The two momenta are not zero, so their conservation says something.
    assert!(z0.abs() > 0.1 && a0.abs() > 1.0, "{z0}, {a0}");
    let window = steps / 10;
    let (mut first, mut last, mut momenta, mut drift) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for k in 1..=steps {
        variational.step().expect("it steps");
        let s = variational.state();
        let error = (energy(s) - e0).abs();
        if k <= window {
            first = first.max(error);
        } else if k > steps - window {
            last = last.max(error);
        }
        let (z, a) = top_momenta(&s.q, &s.p);
        momenta = momenta.max((z - z0).abs()).max((a - a0).abs());
        if k % 1000 == 0 {
            let mut phi = VecH::<HeavyTop>::zeros();
            model.holonomic(0.0, &s.q, &mut phi);
            drift = drift.max(phi.amax());
        }
    }
    println!(
        "10⁶ steps: energy error {first:.2e} (first 10%), {last:.2e} (last 10%); momenta drift {momenta:.1e}; \
         holonomic residual {drift:.1e}"
    );
    assert!(last <= 1.2 * first && first < 1e-4, "energy: first 10% {first:e}, last 10% {last:e}");
    // Round-off: measured at 1.2e-13 after 10⁴ steps, 1.0e-12 after 10⁵, 1.1e-11 after 10⁶,
    // about a fiftieth of a rounding unit of the larger momentum (6 N m s) per step; the
    // bound is a tenth of one per step. A method that did not conserve them would drift by
    // its truncation error, as the energy's 1e-6 shows.
    let bound = 0.1 * f64::EPSILON * z0.abs().max(a0.abs()) * steps as f64;
    assert!(momenta < bound, "momenta drift {momenta:e} over {steps} steps, bound {bound:e}");
    assert!(drift < 1e-13, "holonomic residual {drift:e}");
}

/// A spatial closed loop, RSSR: a crank turning about space's `z` at the origin, a coupler on
/// ball joints at both ends, a rocker turning about space's `x` at `P = (0.2, 0.5, 0.3)`. The
/// crank and rocker are `2 c` and `2 r` long along their own `x` axes, the coupler `2 h`.
/// Three bodies, 16 rows of joints: two degrees of freedom, the loop's and the coupler's spin
/// about its own axis. 36 coordinates and 34 rows take more stack than dirac allows without
/// asking: `large`, run on a thread with a larger stack.
#[derive(Interconnection)]
#[dirac(large)]
#[dirac(holonomic(crank_x) = crank.x - c * crank.r11, holonomic(crank_y) = crank.y - c * crank.r21)]
#[dirac(holonomic(crank_z) = crank.z - c * crank.r31)]
#[dirac(holonomic(crank_axis_x) = crank.r13, holonomic(crank_axis_y) = crank.r23)]
#[dirac(holonomic(ball1_x) = crank.x + c * crank.r11 - coupler.x + h * coupler.r11)]
#[dirac(holonomic(ball1_y) = crank.y + c * crank.r21 - coupler.y + h * coupler.r21)]
#[dirac(holonomic(ball1_z) = crank.z + c * crank.r31 - coupler.z + h * coupler.r31)]
#[dirac(holonomic(ball2_x) = coupler.x + h * coupler.r11 - rocker.x - r * rocker.r11)]
#[dirac(holonomic(ball2_y) = coupler.y + h * coupler.r21 - rocker.y - r * rocker.r21)]
#[dirac(holonomic(ball2_z) = coupler.z + h * coupler.r31 - rocker.z - r * rocker.r31)]
#[dirac(holonomic(rocker_x) = rocker.x - r * rocker.r11 - 0.2, holonomic(rocker_y) = rocker.y - r * rocker.r21 - 0.5)]
#[dirac(holonomic(rocker_z) = rocker.z - r * rocker.r31 - 0.3)]
#[dirac(holonomic(rocker_axis_y) = rocker.r22, holonomic(rocker_axis_z) = rocker.r32)]
struct Rssr {
    crank: RigidBody,
    coupler: RigidBody,
    rocker: RigidBody,
    c: f64,
    h: f64,
    r: f64,
}

#[test]
fn a_spatial_closed_loop_keeps_its_joints_to_round_off_in_every_method() {
    let run = std::thread::Builder::new().stack_size(64 << 20).spawn(spatial_closed_loop).expect("a thread");
    run.join().expect("the loop runs");
}

fn spatial_closed_loop() {
    // A rod of mass m and length 2 l along its x axis, 2 cm thick.
    let rod = |m: f64, l: f64| {
        let across = m * (4.0 * l * l + 4e-4) / 12.0;
        RigidBody::new(m, [m * 8e-4 / 12.0, across, across]).with_gravity(9.81)
    };
    // The crank along x from the origin to (0.2, 0, 0); the rocker from P along −y to
    // (0.2, 0.2, 0.3); the coupler between the two ends.
    let (c, r) = (0.1, 0.15);
    let d = [0.0f64, 0.2, 0.3];
    let h = 0.5 * (d[1] * d[1] + d[2] * d[2]).sqrt();
    let model = Rssr { crank: rod(0.5, c), coupler: rod(0.8, h), rocker: rod(0.6, r), c, h, r };
    let (a, b) = (d[1] / (2.0 * h), d[2] / (2.0 * h));
    let crank = model.crank.state(
        [c, 0.0, 0.0],
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        [0.0; 3],
        [0.0; 3],
    );
    let coupler = model.coupler.state(
        [0.2, 0.1, 0.15],
        [[0.0, 1.0, 0.0], [a, 0.0, b], [b, 0.0, -a]],
        [0.0; 3],
        [0.0; 3],
    );
    let rocker = model.rocker.state(
        [0.2, 0.5 - r, 0.3],
        [[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
        [0.0; 3],
        [0.0; 3],
    );
    let mut q = VecQ::<Rssr>::zeros();
    for (k, part) in [crank.0, coupler.0, rocker.0].iter().enumerate() {
        q.rows_mut(12 * k, 12).copy_from(part);
    }
    let mut phi = VecH::<Rssr>::zeros();
    model.holonomic(0.0, &q, &mut phi);
    assert!(phi.amax() < 1e-15, "the start closes the loop: {phi}");
    // Started at rest: gravity swings it.
    let start =
        consistent_state(&model, 0.0, &q, &VecQ::<Rssr>::zeros(), Consistency::default()).expect("a start");
    let times: Vec<f64> = (1..=20).map(|k| 0.1 * k as f64).collect();
    let mut ends = Vec::new();
    each_integrator!(&model, Fineness::new(1e-10, 1e-10, 1e-4).projected(), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 2.0, &Sampling::Times(times.clone())).expect("it swings");
        let drift = solution.holonomic_residual().iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let energy = solution.energy();
        let energy_error = energy.iter().fold(0.0f64, |m, e| m.max((e - energy[0]).abs()));
        let crank_angle = solution.column("crank.r21").expect("a column")[solution.len() - 1]
            .atan2(solution.column("crank.r11").expect("a column")[solution.len() - 1]);
        println!(
            "{}: holonomic residual {drift:.1e}, energy error {energy_error:.1e}, crank at {crank_angle:.9} rad at t = 2",
            method.name()
        );
        assert!(drift < 1e-13, "{}: {drift:e}", method.name());
        assert!(
            energy_error < if method == Method::Variational { 1e-4 } else { 1e-8 },
            "{}: {energy_error:e}",
            method.name()
        );
        ends.push(crank_angle);
    });
    // The crank swung: not a motion held at rest.
    assert!(ends[0].abs() > 0.1, "{ends:?}");
    // Radau and the explicit method, independent, agree; the variational method to its order.
    assert!((ends[0] - ends[1]).abs() < 1e-7 && (ends[0] - ends[2]).abs() < 1e-4, "{ends:?}");
}

/// The 6-6 Stewart platform of the zoo, its six legs driven: six loops through the ground and
/// the platform, and the platform's six degrees of freedom all prescribed. Its pose at every
/// instant is the legs' alone (their lengths fix it), so the three methods, whatever their
/// dynamics' errors, must put it in the same place; and the legs and `RᵀR = I` hold to
/// round-off all along.
#[test]
fn a_stewart_platform_keeps_its_six_loops_to_round_off_in_every_method() {
    let model = Stewart { top: RigidBody::new(5.0, [0.3, 0.3, 0.5]).with_gravity(9.81) };
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let (q, v) = model.top.state([0.0, 0.0, 1.0], identity, [0.0; 3], [0.0; 3]);
    let start = consistent_state(&model, 0.0, &q, &v, Consistency::default()).expect("a start");
    let times: Vec<f64> = (1..=40).map(|k| 0.05 * k as f64).collect();
    let mut poses = Vec::new();
    each_integrator!(&model, Fineness::new(1e-10, 1e-10, 1e-3).projected(), |method, integrator| {
        let solution = integrator.solve(0.0, &start, 2.0, &Sampling::Times(times.clone())).expect("it moves");
        let drift = solution.holonomic_residual().iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let z = solution.column("top.z").expect("a column");
        let force = solution.column("lambda(leg1)").expect("the first leg's force");
        println!(
            "{}: holonomic residual {drift:.1e}; platform height {:.6} .. {:.6}; leg 1 force {:.3} at t = 2",
            method.name(),
            z.iter().fold(f64::MAX, |m, x| m.min(*x)),
            z.iter().fold(f64::MIN, |m, x| m.max(*x)),
            force[force.len() - 1]
        );
        assert!(drift < 1e-13, "{}: {drift:e}", method.name());
        poses.push(solution.last().expect("samples").q);
    });
    // The legs moved the platform: not a pose held at rest.
    assert!((poses[0][2] - start.q[2]).abs() > 1e-3, "{} {}", poses[0][2], start.q[2]);
    for pose in &poses[1..] {
        let apart = (pose - poses[0]).amax();
        assert!(apart < 1e-12, "the methods put the platform {apart:e} apart");
    }
}

#[test]
fn bodies_refuse_what_no_body_can_be() {
    // A body without mass, with a NaN moment, or under negative gravity is refused before it
    // runs, by the parameter's name; a start off SO(3) is put on it by `consistent_state` or
    // refused, never integrated as it is.
    let eye = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for (body, name) in [
        (RigidBody::new(0.0, [1.0, 2.0, 3.0]), "m"),
        (RigidBody::new(1.0, [1.0, f64::NAN, 3.0]), "jyy"),
        (RigidBody::new(1.0, [1.0, 2.0, 3.0]).with_gravity(-9.81), "g"),
    ] {
        let (q, v) = body.state([0.0; 3], eye, [0.0; 3], [0.0, 0.0, 1.0]);
        let mut start = State::<RigidBody>::zeros();
        start.q = q;
        start.v = v;
        match Radau::new(&body, RadauOptions::default())
            .map(|mut r| r.solve(0.0, &start, 1.0, &Sampling::Steps))
        {
            Err(SimError::InvalidParameter { name: n, .. })
            | Ok(Err(SimError::InvalidParameter { name: n, .. })) => {
                assert_eq!(n, name)
            }
            other => panic!("{name}: {:?}", other.map(|r| r.map(|s| s.len()))),
        }
    }
    let body = RigidBody::new(1.0, [1.0, 2.0, 3.0]);
    let skewed = [[1.0, 0.1, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let (q, v) = body.state([0.0; 3], skewed, [0.0; 3], [0.0, 0.0, 1.0]);
    let mut raw = State::<RigidBody>::zeros();
    raw.q = q;
    raw.v = v;
    let refused =
        Radau::new(&body, RadauOptions::default()).expect("valid").solve(0.0, &raw, 1.0, &Sampling::Steps);
    assert!(refused.is_err(), "a rotation off SO(3) is not integrated as it is");
    match consistent_state(&body, 0.0, &q, &v, Consistency::default()) {
        Ok(start) => {
            let mut phi = VecH::<RigidBody>::zeros();
            body.holonomic(0.0, &start.q, &mut phi);
            assert!(phi.amax() < 1e-12, "consistent_state puts the rotation on SO(3): {phi}");
        }
        Err(error) => println!("consistent_state refuses the skewed rotation: {error}"),
    }
}
