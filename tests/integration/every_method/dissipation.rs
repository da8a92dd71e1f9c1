//! Dissipation through every integrator: Rayleigh functions, whose forces are `−∂R/∂v`, and
//! coordinates whose velocity no inertia fixes but a force does (an RC circuit's current, a
//! motor's current with no armature inductance, a massless node between a damper and a
//! spring). References: the closed forms of these linear circuits and mechanisms, derived in
//! each test's comment; the power balance `dE/dt = P_sources − P_dissipated` integrated with
//! Simpson's rule over the recorded samples.

use dirac::prelude::*;

use super::{Fineness, Method};

/// An RC circuit charged from a constant source `u`: `L = −q²/2C`, `R = ½ r i²`, `F = u`.
/// No inertia fixes the current: the momentum balance `0 = −q/C + u − r i` does.
#[derive(LagrangeDirac)]
#[dirac(coordinates(q => i))]
#[dirac(lagrangian = -0.5 * q * q / c)]
#[dirac(dissipation = 0.5 * r * i * i)]
#[dirac(force(q) = u)]
pub struct Rc {
    pub r: f64,
    pub c: f64,
    pub u: f64,
}

/// A DC motor without armature inductance driving an inertia against viscous friction: the
/// charge `q` (current `i`) and the angle `th` (speed `w`), coupled by the gyrator term
/// `k i th` (back EMF `k w`, torque `k i`). Balances: `k w = u − r i` and
/// `j ẇ = k i − b w`.
#[derive(LagrangeDirac)]
#[dirac(coordinates(q => i, th => w))]
#[dirac(lagrangian = 0.5 * j * w * w + k * i * th)]
#[dirac(dissipation = 0.5 * r * i * i + 0.5 * b * w * w)]
#[dirac(force(q) = u)]
pub struct Motor {
    pub r: f64,
    pub k: f64,
    pub j: f64,
    pub b: f64,
    pub u: f64,
}

/// A mass and a damper to a node `y` whose velocity has no inertia.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy), port(y))]
#[dirac(lagrangian = 0.5 * m * vx * vx)]
#[dirac(dissipation = 0.5 * c * (vx - vy).powi(2))]
pub struct MassDamper {
    pub m: f64,
    pub c: f64,
}

/// A spring from the wall to the node: nothing but a potential.
#[derive(LagrangeDirac)]
#[dirac(coordinates(z => vz), port(z))]
#[dirac(lagrangian = -0.5 * k * z * z)]
pub struct WallSpring {
    pub k: f64,
}

/// The mass pulls the massless node through the damper; the spring holds it.
#[derive(Interconnection)]
#[dirac(connect(left.y, right.z))]
pub struct MassDamperSpring {
    pub left: MassDamper,
    pub right: WallSpring,
}

/// A chain of three masses, springs between them and to the wall, dampers between
/// neighbours, driven at the first by `a sin(ω t)`.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x1 => v1, x2 => v2, x3 => v3))]
#[dirac(lagrangian = 0.5 * m * (v1 * v1 + v2 * v2 + v3 * v3)
    - 0.5 * k * (x1 * x1 + (x2 - x1).powi(2) + (x3 - x2).powi(2)))]
#[dirac(dissipation = 0.5 * c * ((v2 - v1).powi(2) + (v3 - v2).powi(2)) + 0.5 * c0 * v1 * v1)]
#[dirac(force(x1) = a * (omega * t).sin())]
pub struct DampedChain {
    pub m: f64,
    pub k: f64,
    pub c: f64,
    pub c0: f64,
    pub a: f64,
    pub omega: f64,
}

/// The accuracy each method reaches at the suite's settings.
fn tolerance(method: Method) -> f64 {
    if method == Method::Variational { 2e-5 } else { 1e-7 }
}

fn fineness() -> Fineness {
    Fineness::new(1e-10, 1e-12, 1e-3)
}

/// `∫ y dt` over equally spaced samples by Simpson's rule (an even number of intervals).
fn simpson(dt: f64, y: &[f64]) -> f64 {
    assert!(y.len() % 2 == 1, "an even number of intervals");
    let inner: f64 =
        y[1..y.len() - 1].iter().enumerate().map(|(k, y)| if k % 2 == 0 { 4.0 * y } else { 2.0 * y }).sum();
    dt / 3.0 * (y[0] + inner + y[y.len() - 1])
}

/// `q(t) = C U (1 − e^{−t/RC})` and `i = q̇`, from `q(0) = 0`: the current at the start is not
/// given but found, `U/R`.
#[test]
fn an_rc_circuit_charges_as_the_closed_form() {
    let rc = Rc { r: 2.0, c: 0.5, u: 3.0 };
    let start =
        consistent_state(&rc, 0.0, &VecQ::<Rc>::zeros(), &VecQ::<Rc>::zeros(), Consistency::default())
            .expect("the current is fixed by the resistor");
    assert!((start.v(Rc::Q) - 1.5).abs() < 1e-12, "i(0) = U/R: {}", start.v(Rc::Q));
    let times: Vec<f64> = (1..=20).map(|k| 0.2 * f64::from(k)).collect();
    each_integrator!(&rc, fineness(), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 4.0, &Sampling::Times(times.clone())).expect("integrates");
        let tau = rc.r * rc.c;
        for (k, &t) in solution.t().iter().enumerate() {
            let q = rc.c * rc.u * (1.0 - (-t / tau).exp());
            let i = rc.u / rc.r * (-t / tau).exp();
            let (eq, ei) = ((solution.q(Rc::Q)[k] - q).abs(), (solution.v(Rc::Q)[k] - i).abs());
            assert!(
                eq < tolerance(method) && ei < tolerance(method),
                "{method:?} at {t}: q {eq:e}, i {ei:e}"
            );
            // The resistor's power r i², and the source's u i.
            let dissipated = solution.dissipated_power()[k];
            assert!((dissipated - rc.r * i * i).abs() < 10.0 * tolerance(method), "{method:?}: {dissipated}");
            assert!((solution.power()[k] - rc.u * i).abs() < 10.0 * tolerance(method), "{method:?}");
        }
    });
}

/// `w(t) = w∞ (1 − e^{−t/τ})` with `w∞ = K U/(R B + K²)` and `τ = J R/(R B + K²)`: with
/// `i = (u − k w)/r` from the electrical balance, `j ẇ = k (u − k w)/r − b w`.
#[test]
fn a_motor_without_inductance_reaches_its_steady_speed() {
    let motor = Motor { r: 1.5, k: 0.8, j: 0.2, b: 0.1, u: 12.0 };
    let start = consistent_state(
        &motor,
        0.0,
        &VecQ::<Motor>::zeros(),
        &VecQ::<Motor>::zeros(),
        Consistency::default(),
    )
    .expect("the current is fixed by the armature's resistance");
    let denominator = motor.r * motor.b + motor.k * motor.k;
    let (speed, tau) = (motor.k * motor.u / denominator, motor.j * motor.r / denominator);
    let times: Vec<f64> = (1..=30).map(|k| 0.1 * f64::from(k)).collect();
    each_integrator!(&motor, fineness(), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 3.0, &Sampling::Times(times.clone())).expect("integrates");
        for (k, &t) in solution.t().iter().enumerate() {
            let w = speed * (1.0 - (-t / tau).exp());
            let i = (motor.u - motor.k * w) / motor.r;
            let (ew, ei) = ((solution.v(Motor::TH)[k] - w).abs(), (solution.v(Motor::Q)[k] - i).abs());
            assert!(ew < 10.0 * tolerance(method), "{method:?} at {t}: speed off by {ew:e}");
            assert!(ei < 10.0 * tolerance(method), "{method:?} at {t}: current off by {ei:e}");
        }
        let last = solution.last().expect("samples");
        assert!((last.v(Motor::TH) - speed).abs() < 0.05 * speed, "near the steady speed {speed}");
    });
}

/// `m v̇ = −c (v − ẏ)` and `0 = c (v − ẏ) − k y`: `(v, y)` solve `v̇ = −(k/m) y`,
/// `ẏ = v − (k/c) y`, whose characteristic polynomial `s² + (k/c) s + k/m` has, for `m = 5`,
/// `k = c = 1`, the real roots `s = (−1 ± √0.2)/2`. From `y(0) = 0`, `v(0) = 1`:
/// `y = α (e^{s₁t} − e^{s₂t})` with `α = 1/(s₁ − s₂)`, `v = ẏ + (k/c) y`.
#[test]
fn a_massless_node_between_a_damper_and_a_spring() {
    let system = MassDamperSpring { left: MassDamper { m: 5.0, c: 1.0 }, right: WallSpring { k: 1.0 } };
    let (x, y) = (MassDamperSpring::left(MassDamper::X), MassDamperSpring::left(MassDamper::Y));
    let mut v0 = VecQ::<MassDamperSpring>::zeros();
    v0[x.index()] = 1.0;
    let start =
        consistent_state(&system, 0.0, &VecQ::<MassDamperSpring>::zeros(), &v0, Consistency::default())
            .expect("the node's velocity is fixed by the damper");
    let (s1, s2) = ((-1.0 + 0.2f64.sqrt()) / 2.0, (-1.0 - 0.2f64.sqrt()) / 2.0);
    let alpha = 1.0 / (s1 - s2);
    assert!((start.v(y) - 1.0).abs() < 1e-12, "ẏ(0) = v(0) − (k/c) y(0) = 1: {}", start.v(y));
    let times: Vec<f64> = (1..=40).map(|k| 0.25 * f64::from(k)).collect();
    each_integrator!(&system, fineness(), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 10.0, &Sampling::Times(times.clone())).expect("integrates");
        for (k, &t) in solution.t().iter().enumerate() {
            let node = alpha * ((s1 * t).exp() - (s2 * t).exp());
            let speed = alpha * ((s1 + 1.0) * (s1 * t).exp() - (s2 + 1.0) * (s2 * t).exp());
            let position =
                alpha * ((s1 + 1.0) / s1 * ((s1 * t).exp() - 1.0) - (s2 + 1.0) / s2 * ((s2 * t).exp() - 1.0));
            let errors = [solution.q(y)[k] - node, solution.v(x)[k] - speed, solution.q(x)[k] - position];
            for e in errors {
                assert!(e.abs() < 10.0 * tolerance(method), "{method:?} at {t}: {errors:?}");
            }
        }
    });
}

/// `E(T) − E(0) = ∫ (P_sources − P_dissipated) dt` on the driven, damped chain, the integral
/// by Simpson's rule over samples every 1 ms (its error about 1e-12 here).
#[test]
fn the_power_balance_closes_with_a_rayleigh_function() {
    let chain = DampedChain { m: 1.0, k: 4.0, c: 0.3, c0: 0.1, a: 1.0, omega: 1.7 };
    let mut q0 = VecQ::<DampedChain>::zeros();
    q0[1] = 0.2;
    let start = consistent_state(&chain, 0.0, &q0, &VecQ::<DampedChain>::zeros(), Consistency::default())
        .expect("consistent");
    let dt = 1e-3;
    each_integrator!(&chain, fineness(), |method, integrator| {
        let solution = integrator.solve(0.0, &start, 4.0, &Sampling::Every(dt)).expect("integrates");
        let e = solution.energy();
        let net: Vec<f64> =
            solution.power().iter().zip(solution.dissipated_power()).map(|(p, d)| p - d).collect();
        assert!(
            solution.dissipated_power().iter().all(|&d| d >= 0.0),
            "{method:?}: dissipation takes power out"
        );
        let gap = e[e.len() - 1] - e[0] - simpson(dt, &net);
        let dissipated = simpson(dt, solution.dissipated_power());
        assert!(dissipated > 0.1, "{method:?}: the dampers work ({dissipated})");
        eprintln!("{method:?}: balance gap {gap:e}");
        assert!(gap.abs() < 10.0 * tolerance(method), "{method:?}: the balance is off by {gap:e}");
    });
}

/// The RC circuit with its source as an input.
#[derive(LagrangeDirac)]
#[dirac(coordinates(q => i), input(u), output(current) = i)]
#[dirac(lagrangian = -0.5 * q * q / c)]
#[dirac(dissipation = 0.5 * r * i * i)]
#[dirac(force(q) = u)]
pub struct RcInput {
    pub r: f64,
    pub c: f64,
    pub u: f64,
}

/// `r q̇ = u − q/C`: `A = −1/(RC)`, `B = 1/R`, and the current `C = −1/(RC)`, `D = 1/R`, the
/// current being eliminated from the state (no inertia). The motor's state is the charge,
/// the angle and the speed; its speed's eigenvalue is `−(RB + K²)/(JR)` (from the speed's
/// equation above) and the charge and angle add two zeros.
#[test]
fn the_linearisation_eliminates_velocities_fixed_by_forces() {
    let rc = RcInput { r: 2.0, c: 0.5, u: 0.0 };
    let rest = consistent_state(
        &rc,
        0.0,
        &VecQ::<RcInput>::zeros(),
        &VecQ::<RcInput>::zeros(),
        Consistency::default(),
    )
    .expect("at rest");
    let linear = linearize(&rc, 0.0, &rest).expect("linearises");
    let expected = [
        (linear.a[(0, 0)], -1.0),
        (linear.b[(0, 0)], 0.5),
        (linear.c[(0, 0)], -1.0),
        (linear.d[(0, 0)], 0.5),
    ];
    for (got, want) in expected {
        assert!((got - want).abs() < 1e-14, "{linear:?}");
    }
    assert_eq!(linear.velocities.ncols(), 0, "the current is not a state");
    let motor = Motor { r: 1.5, k: 0.8, j: 0.2, b: 0.1, u: 0.0 };
    let rest = consistent_state(
        &motor,
        0.0,
        &VecQ::<Motor>::zeros(),
        &VecQ::<Motor>::zeros(),
        Consistency::default(),
    )
    .expect("at rest");
    let linear = linearize(&motor, 0.0, &rest).expect("linearises");
    assert_eq!(linear.a.shape(), (3, 3));
    let mut eigenvalues: Vec<f64> = linear.a.complex_eigenvalues().iter().map(|z| z.re).collect();
    eigenvalues.sort_by(f64::total_cmp);
    let speed = -(motor.r * motor.b + motor.k * motor.k) / (motor.j * motor.r);
    assert!((eigenvalues[0] - speed).abs() < 1e-12, "{eigenvalues:?} against {speed}");
    assert!(eigenvalues[1].abs() < 1e-12 && eigenvalues[2].abs() < 1e-12, "{eigenvalues:?}");
}

/// The variational step is second order on a velocity the forces fix (its rows are the
/// momentum balance at the midpoint, the implicit midpoint rule): halving the step divides
/// the RC circuit's error at `t = 1` by four.
#[test]
fn the_variational_step_keeps_its_order_on_velocities_fixed_by_forces() {
    let rc = Rc { r: 2.0, c: 0.5, u: 3.0 };
    let start =
        consistent_state(&rc, 0.0, &VecQ::<Rc>::zeros(), &VecQ::<Rc>::zeros(), Consistency::default())
            .expect("consistent");
    let error = |h: f64| {
        let mut variational = Variational::new(&rc, h, VariationalOptions::default()).expect("valid step");
        let solution = variational.solve(0.0, &start, 1.0, &Sampling::Times(vec![1.0])).expect("integrates");
        (solution.q(Rc::Q)[0] - rc.c * rc.u * (1.0 - (-1.0f64).exp())).abs()
    };
    let (coarse, fine) = (error(0.02), error(0.01));
    let ratio = coarse / fine;
    assert!((3.8..4.2).contains(&ratio), "errors {coarse:e} and {fine:e}: ratio {ratio}");
}

/// The motor's armature as a subsystem: the charge `q` (current `i`) with the source `u` and
/// the resistor `r`, and the shaft angle `th` through the gyrator `k i th`; the shaft is its
/// port.
#[derive(LagrangeDirac)]
#[dirac(coordinates(q => i, th => w), port(th))]
#[dirac(lagrangian = k * i * th)]
#[dirac(dissipation = 0.5 * r * i * i)]
#[dirac(force(q) = u)]
pub struct Armature {
    pub r: f64,
    pub k: f64,
    pub u: f64,
}

/// The load: an inertia against viscous friction, its angle the port.
#[derive(LagrangeDirac)]
#[dirac(coordinates(phi => w), port(phi))]
#[dirac(lagrangian = 0.5 * j * w * w)]
#[dirac(dissipation = 0.5 * b * w * w)]
pub struct Load {
    pub j: f64,
    pub b: f64,
}

/// [`Motor`] torn into its armature and its load, joined at the shaft.
#[derive(Interconnection)]
#[dirac(connect(armature.th, load.phi))]
pub struct MotorAndLoad {
    pub armature: Armature,
    pub load: Load,
}

/// The power balance per subsystem on the motor torn at its shaft. Each subsystem records the
/// power its own Rayleigh function takes (`armature.dissipated_power = r i²`,
/// `load.dissipated_power = b w²`, checked against the recorded velocities), and each closes
/// its own balance with the power through its port, `⟨f, w⟩` from the interconnection force:
/// the armature stores nothing (`0 = u i − r i² + P_armature`, at every sample), the load
/// `½ j w²` (`ΔE = ∫ (P_load − b w²) dt`, Simpson's rule over samples every 1 ms); the
/// interconnection is lossless (`P_armature + P_load = 0`), and the whole closes as
/// `dE/dt = P_sources − P_dissipated`.
#[test]
fn the_power_balance_closes_per_subsystem_on_the_motor() {
    let motor =
        MotorAndLoad { armature: Armature { r: 1.5, k: 0.8, u: 12.0 }, load: Load { j: 0.2, b: 0.1 } };
    let (q, th) = (MotorAndLoad::armature(Armature::Q), MotorAndLoad::armature(Armature::TH));
    let phi = MotorAndLoad::load(Load::PHI);
    let zero = VecQ::<MotorAndLoad>::zeros();
    let start = consistent_state(&motor, 0.0, &zero, &zero, Consistency::default()).expect("from rest");
    let dt = 1e-3;
    each_integrator!(&motor, fineness(), |method, integrator| {
        let solution = integrator.solve(0.0, &start, 2.0, &Sampling::Every(dt)).expect("integrates");
        let column = |name: &str| solution.column(name).unwrap_or_else(|| panic!("a column `{name}`"));
        let (armature_loss, load_loss) =
            (column("out(armature.dissipated_power)"), column("out(load.dissipated_power)"));
        let (i, w) = (solution.v(q), solution.v(phi));
        let (torque_a, torque_l) = (
            solution.interconnection_force(th).expect("a port"),
            solution.interconnection_force(phi).expect("a port"),
        );
        let (Armature { r, u, .. }, Load { j, b }) = (&motor.armature, &motor.load);
        let bound = 10.0 * tolerance(method);
        let mut load_net = Vec::with_capacity(solution.len());
        for k in 0..solution.len() {
            let (p_armature, p_load) = (torque_a[k] * solution.v(th)[k], torque_l[k] * w[k]);
            let errors = [
                armature_loss[k] - r * i[k] * i[k],
                load_loss[k] - b * w[k] * w[k],
                u * i[k] - armature_loss[k] + p_armature,
                p_armature + p_load,
                solution.dissipated_power()[k] - armature_loss[k] - load_loss[k],
            ];
            assert!(errors.iter().all(|e| e.abs() < bound * 100.0), "{method:?} at sample {k}: {errors:?}");
            load_net.push(p_load - load_loss[k]);
        }
        let stored = 0.5 * j * (w[w.len() - 1].powi(2) - w[0].powi(2));
        let gap = stored - simpson(dt, &load_net);
        assert!(stored > 1.0, "{method:?}: the load spins up ({stored})");
        assert!(gap.abs() < bound, "{method:?}: the load's balance is off by {gap:e}");
        let e = solution.energy();
        let net: Vec<f64> =
            solution.power().iter().zip(solution.dissipated_power()).map(|(p, d)| p - d).collect();
        let whole = e[e.len() - 1] - e[0] - simpson(dt, &net);
        assert!(whole.abs() < bound, "{method:?}: the whole balance is off by {whole:e}");
    });
}

/// A massless node on a cubic damper, `F = −c ẏ³`, pushed away by a negative stiffness: its
/// balance `c ẏ³ = k y` is not affine in `ẏ`, so Newton's method solves it.
#[derive(LagrangeDirac)]
#[dirac(coordinates(y => vy))]
#[dirac(lagrangian = 0.5 * k * y * y)]
#[dirac(force(y) = -c * vy * vy * vy)]
pub struct CubicNode {
    pub k: f64,
    pub c: f64,
}

/// The derive solves a velocity that only the forces fix in closed form where its balance is
/// affine in it alone: the RC circuit's current (`i = (u − q/C)/r`) and the inductance-free
/// motor's (`i = (u − k w)/r`, through the gyrator's `L_vq`). Not the cubic damper's (not
/// affine), nor the massless node of a composite (its direction mixes coordinates through the
/// connection's row). The reference of each closed form is the model's own momentum balance,
/// evaluated by its residual kernel: zero at the velocity the closed form gives, from any
/// velocity it starts.
#[test]
fn velocities_that_only_forces_fix_are_solved_in_closed_form_where_affine() {
    assert_eq!(Rc::SOLVED_VELOCITIES, [Rc::Q.index()]);
    assert_eq!(Motor::SOLVED_VELOCITIES, [Motor::Q.index()]);
    assert!(CubicNode::SOLVED_VELOCITIES.is_empty());
    assert!(MassDamperSpring::SOLVED_VELOCITIES.is_empty());
    let motor = Motor { r: 1.5, k: 0.8, j: 0.2, b: 0.1, u: 12.0 };
    let lambda = VecC::<Motor>::zeros();
    for (th, w, i) in [(0.0, 0.0, 0.0), (1.3, -2.0, 7.0), (-0.4, 9.5, -3.0)] {
        let (q, mut v) = (VecQ::<Motor>::new(0.2, th), VecQ::<Motor>::new(i, w));
        let mut solved = v;
        motor.solved_velocities(0.0, &q, &v, &mut solved);
        assert!((solved[0] - (motor.u - motor.k * w) / motor.r).abs() < 1e-14, "{solved:?}");
        v[0] = solved[0];
        // The balance `d/dt (k th) = k w = u − r i`: `ṗ − L_vq v` with `p = k th`.
        let mut blocks = ResidualBlocks::<Motor>::zeros();
        motor.residual_blocks(0.0, &q, &v, &lambda, &mut blocks);
        let balance = blocks.momentum_rate[0] - motor.k * w;
        assert!(balance.abs() < 1e-13, "{balance:e}");
    }
    // Both paths through every integrator: the closed forms above (`an_rc_circuit_…`,
    // `a_motor_without_inductance_…`) and Newton's method here, against `ẏ = (k/c)^{1/3} y^{1/3}`
    // integrated in closed form from `y(0) = 1`: `y^{2/3} = 1 + (2/3) (k/c)^{1/3} t`.
    // Started from a moving guess: at rest the damper's `∂F/∂v = −3 c ẏ²` vanishes and fixes
    // nothing.
    let node = CubicNode { k: 2.0, c: 0.5 };
    let start = consistent_state(
        &node,
        0.0,
        &VecQ::<CubicNode>::new(1.0),
        &VecQ::<CubicNode>::new(1.0),
        Consistency::default(),
    )
    .expect("the node's velocity is fixed by the damper");
    let times: Vec<f64> = (1..=10).map(|k| 0.2 * f64::from(k)).collect();
    each_integrator!(&node, fineness(), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 2.0, &Sampling::Times(times.clone())).expect("integrates");
        for (k, &t) in solution.t().iter().enumerate() {
            let y = (1.0 + 2.0 / 3.0 * (node.k / node.c).cbrt() * t).powf(1.5);
            let e = (solution.q(CubicNode::Y)[k] - y).abs();
            assert!(e < 10.0 * tolerance(method) * y, "{method:?} at {t}: off by {e:e}");
        }
    });
}
