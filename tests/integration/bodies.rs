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

/// Two bodies hung by revolute joints about space's `y` axis: link 1 from a pivot at the
/// origin at `a1` above its centre, link 2 from link 1 at `b1` below link 1's centre and `a2`
/// above its own. Each joint holds a point of one body on a point of the other (three rows)
/// and keeps their `y` axes parallel (two rows): the pivot's rows are linear in the embedded
/// coordinates, the hinge's axis rows bilinear.
#[derive(Interconnection, Clone)]
#[dirac(holonomic(pivot_x) = link1.x + a1 * link1.r13, holonomic(pivot_y) = link1.y + a1 * link1.r23)]
#[dirac(holonomic(pivot_z) = link1.z + a1 * link1.r33)]
#[dirac(holonomic(pivot_axis_x) = link1.r12, holonomic(pivot_axis_z) = link1.r32)]
#[dirac(holonomic(hinge_x) = link1.x - b1 * link1.r13 - link2.x - a2 * link2.r13)]
#[dirac(holonomic(hinge_y) = link1.y - b1 * link1.r23 - link2.y - a2 * link2.r23)]
#[dirac(holonomic(hinge_z) = link1.z - b1 * link1.r33 - link2.z - a2 * link2.r33)]
// Link 1's y axis (its second column) across link 2's x and z axes.
#[dirac(holonomic(hinge_axis_1) = link1.r12 * link2.r11 + link1.r22 * link2.r21 + link1.r32 * link2.r31)]
#[dirac(holonomic(hinge_axis_3) = link1.r12 * link2.r13 + link1.r22 * link2.r23 + link1.r32 * link2.r33)]
struct SpatialDoublePendulum {
    link1: RigidBody,
    link2: RigidBody,
    a1: f64,
    b1: f64,
    a2: f64,
}

/// The same pendulum in its two joint angles (about `y`, zero hanging down), written by hand:
/// the centres at `(−a1 sin θ1, −a1 cos θ1)` and `(−l1 sin θ1 − a2 sin θ2, …)` in `(x, z)`,
/// `l1 = a1 + b1`, and each link's own inertia about `y`.
#[derive(LagrangeDirac)]
#[dirac(coordinates(th1 => w1, th2 => w2))]
#[dirac(define(l1) = a1 + b1)]
#[dirac(define(vx2) = -l1 * th1.cos() * w1 - a2 * th2.cos() * w2)]
#[dirac(define(vz2) = l1 * th1.sin() * w1 + a2 * th2.sin() * w2)]
#[dirac(lagrangian = 0.5 * (m1 * a1 * a1 + j1) * w1 * w1 + 0.5 * m2 * (vx2 * vx2 + vz2 * vz2) + 0.5 * j2 * w2 * w2
    + m1 * g * a1 * th1.cos() + m2 * g * (l1 * th1.cos() + a2 * th2.cos()))]
struct PlanarDoublePendulum {
    m1: f64,
    m2: f64,
    j1: f64,
    j2: f64,
    a1: f64,
    b1: f64,
    a2: f64,
    g: f64,
}

/// `R_y(θ)` as rows.
fn about_y(theta: f64) -> [[f64; 3]; 3] {
    let (s, c) = theta.sin_cos();
    [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]]
}

/// The spatial pendulum at joint angles `th` and rates `w`, with its constraints' multipliers
/// found by `consistent_state`.
fn spatial_start(model: &SpatialDoublePendulum, th: [f64; 2], w: [f64; 2]) -> State<SpatialDoublePendulum> {
    let (a1, b1, a2) = (model.a1, model.b1, model.a2);
    let l1 = a1 + b1;
    let centre1 = [-a1 * th[0].sin(), 0.0, -a1 * th[0].cos()];
    let velocity1 = [-a1 * th[0].cos() * w[0], 0.0, a1 * th[0].sin() * w[0]];
    let centre2 = [-l1 * th[0].sin() - a2 * th[1].sin(), 0.0, -l1 * th[0].cos() - a2 * th[1].cos()];
    let velocity2 = [
        -l1 * th[0].cos() * w[0] - a2 * th[1].cos() * w[1],
        0.0,
        l1 * th[0].sin() * w[0] + a2 * th[1].sin() * w[1],
    ];
    let (q1, v1) = model.link1.state(centre1, about_y(th[0]), velocity1, [0.0, w[0], 0.0]);
    let (q2, v2) = model.link2.state(centre2, about_y(th[1]), velocity2, [0.0, w[1], 0.0]);
    let (mut q, mut v) = (VecQ::<SpatialDoublePendulum>::zeros(), VecQ::<SpatialDoublePendulum>::zeros());
    q.rows_mut(0, 12).copy_from(&q1);
    q.rows_mut(12, 12).copy_from(&q2);
    v.rows_mut(0, 12).copy_from(&v1);
    v.rows_mut(12, 12).copy_from(&v2);
    consistent_state(model, 0.0, &q, &v, Consistency::default()).expect("a consistent start")
}

/// The joint angles of the spatial pendulum: `R e3 = (sin θ, 0, cos θ)`.
fn joint_angles(solution: &Solution<SpatialDoublePendulum, impl Sized>, k: usize) -> [f64; 2] {
    let angle = |link: &str| {
        let at = |name: &str| solution.column(&format!("{link}.{name}")).expect("a column")[k];
        at("r13").atan2(at("r33"))
    };
    [angle("link1"), angle("link2")]
}

fn double_pendulums() -> (SpatialDoublePendulum, PlanarDoublePendulum) {
    let (m1, m2, g) = (1.5, 0.8, 9.81);
    // Boxes: link 1 of 0.1 × 0.2 × 1.0 m, link 2 of 0.3 × 0.1 × 0.6 m.
    let box_moments = |m: f64, [x, y, z]: [f64; 3]| {
        [m * (y * y + z * z) / 12.0, m * (x * x + z * z) / 12.0, m * (x * x + y * y) / 12.0]
    };
    let (j1, j2) = (box_moments(m1, [0.1, 0.2, 1.0]), box_moments(m2, [0.3, 0.1, 0.6]));
    let (a1, b1, a2) = (0.5, 0.5, 0.3);
    let spatial = SpatialDoublePendulum {
        link1: RigidBody::new(m1, j1).with_gravity(g),
        link2: RigidBody::new(m2, j2).with_gravity(g),
        a1,
        b1,
        a2,
    };
    let planar = PlanarDoublePendulum { m1, m2, j1: j1[1], j2: j2[1], a1, b1, a2, g };
    (spatial, planar)
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
