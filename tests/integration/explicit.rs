//! The explicit integrator (`Explicit`): order on exact solutions, constraints kept, dense
//! output, and clear errors where it does not apply.
//!
//! References, none computed by dirac: the pendulum's published x(1), y(1) (DESIGN.md §3); the
//! torn chain's exact modal solution (eigen-decomposition of M⁻¹K, as in
//! `benches/work_precision.rs`); the rolling disk's closed-form motion (constant spin and
//! turning rates, the contact point on a circle of radius r v_θ / v_φ).

use std::ops::ControlFlow;

use dirac::ExplicitStats;
use dirac::State;
use dirac::nalgebra::{Matrix3, SymmetricEigen, Vector3};
use dirac::prelude::*;

use crate::zoo::*;

/// The pendulum's published position at t = 1 (DESIGN.md §3), released from the horizontal.
const PENDULUM_AT_1: (f64, f64) = (-0.986_291_751_131_875_3, -0.165_010_853_125_541_17);

/// x1, x2, x3 of the chain wall–k1–m1–k2–m2–k3–m3 (m = 1, 2, 3; k = 4, 5, 6) at `t`, from
/// x1(0) = 0.1 at rest, by the eigensystem of M^{-1/2} K M^{-1/2}.
fn chain_exact(t: f64) -> Vector3<f64> {
    let (m, k) = ([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]);
    let kk = Matrix3::new(k[0] + k[1], -k[1], 0.0, -k[1], k[1] + k[2], -k[2], 0.0, -k[2], k[2]);
    let l = Matrix3::from_diagonal(&Vector3::new(m[0], m[1], m[2]).map(|x: f64| 1.0 / x.sqrt()));
    let eig = SymmetricEigen::new(l * kk * l);
    let u0 =
        Matrix3::from_diagonal(&Vector3::new(m[0], m[1], m[2]).map(f64::sqrt)) * Vector3::new(0.1, 0.0, 0.0);
    let mut u = Vector3::zeros();
    for i in 0..3 {
        let phi = eig.eigenvectors.column(i);
        u += phi * (phi.dot(&u0) * (eig.eigenvalues[i].sqrt() * t).cos());
    }
    l * u
}

fn chain_error(options: ExplicitOptions, t_end: f64) -> (f64, ExplicitStats) {
    let chain = paper_chain();
    let start = paper_chain_start(&chain);
    let mut explicit = Explicit::new(&chain, options).expect("valid options");
    let sol = explicit.solve(0.0, &start, t_end, &Sampling::Times(vec![t_end])).expect("integrates");
    let exact = chain_exact(t_end);
    let masses = [Chain::left(Primitive1::X1), Chain::left(Primitive1::X2), Chain::right(Primitive2::X3)];
    let error = masses.iter().enumerate().map(|(i, c)| (sol.q(*c)[0] - exact[i]).abs()).fold(0.0, f64::max);
    (error, sol.stats)
}

fn pendulum_error(options: ExplicitOptions) -> (f64, ExplicitStats) {
    let p = unit_pendulum();
    let mut explicit = Explicit::new(&p, options).expect("valid options");
    let sol =
        explicit.solve(0.0, &horizontal_start(&p), 1.0, &Sampling::Times(vec![1.0])).expect("integrates");
    let (x, y) = (sol.q(Pendulum::X)[0], sol.q(Pendulum::Y)[0]);
    ((x - PENDULUM_AT_1.0).abs().max((y - PENDULUM_AT_1.1).abs()), sol.stats)
}

/// The rolling disk's exact motion: v_θ, v_φ constant, φ = φ0 + v_φ t, and the contact point
/// runs on a circle, ẋ = r v_θ cos φ, ẏ = r v_θ sin φ.
fn disk_exact(disk: &RollingDisk, start: (f64, f64), t: f64) -> [f64; 4] {
    let (v_theta, v_phi) = start;
    let phi = v_phi * t;
    let radius = disk.r * v_theta / v_phi;
    [radius * phi.sin(), radius * (1.0 - phi.cos()), v_theta * t, phi]
}

fn disk_start(disk: &RollingDisk, (v_theta, v_phi): (f64, f64)) -> State<RollingDisk> {
    let mut v = VecQ::<RollingDisk>::zeros();
    v[RollingDisk::THETA.index()] = v_theta;
    v[RollingDisk::PHI.index()] = v_phi;
    v[RollingDisk::X.index()] = disk.r * v_theta;
    consistent_state(disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
        .expect("consistent")
}

fn disk_error(h: f64) -> f64 {
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let rates = (2.0, 1.5);
    let mut explicit = Explicit::new(&disk, ExplicitOptions::fixed(h)).expect("valid options");
    let sol =
        explicit.solve(0.0, &disk_start(&disk, rates), 4.0, &Sampling::Times(vec![4.0])).expect("integrates");
    let exact = disk_exact(&disk, rates, 4.0);
    let state = sol.state(0).expect("a sample");
    (0..4).map(|i| (state.q[i] - exact[i]).abs()).fold(0.0, f64::max)
}

/// The observed orders of a sequence of errors at halved steps.
fn orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect()
}

/// Fixed steps h, h/2, h/4 on three exact solutions: errors fall by about 2⁵ each time
/// (observed order within [4.6, 5.6]; an order 4 or 6 method falls outside): the holonomic
/// pendulum (projected every step), the nonholonomic rolling disk, and the interconnected
/// chain, whose second part is degenerate. The chain's ratios approach 2⁵ from above (5.6,
/// then 5.4) at the steps where its error is still well above round-off.
#[test]
fn fifth_order_on_holonomic_nonholonomic_and_interconnected_models() {
    let pendulum: Vec<f64> =
        [0.02, 0.01, 0.005].iter().map(|&h| pendulum_error(ExplicitOptions::fixed(h)).0).collect();
    let disk: Vec<f64> = [0.2, 0.1, 0.05].iter().map(|&h| disk_error(h)).collect();
    let chain: Vec<f64> =
        [0.05, 0.025, 0.0125].iter().map(|&h| chain_error(ExplicitOptions::fixed(h), 5.0).0).collect();
    for (name, errors) in [("pendulum", &pendulum), ("rolling disk", &disk), ("chain", &chain)] {
        for order in orders(errors) {
            assert!((4.6..=5.6).contains(&order), "{name}: observed order {order} from errors {errors:?}");
        }
    }
}

/// With step-size control the achieved error follows the tolerance: within 30× of it on the
/// pendulum and the chain, and tighter tolerances cost more steps.
#[test]
fn adaptive_steps_follow_the_tolerance() {
    let mut steps = 0;
    for tol in [1e-5, 1e-7, 1e-9] {
        let (error, stats) = pendulum_error(ExplicitOptions::tolerances(tol, tol));
        assert!(error < 30.0 * tol, "pendulum: error {error:e} at tolerance {tol:e}");
        assert!(stats.steps > steps, "pendulum: {} steps at {tol:e} after {steps}", stats.steps);
        steps = stats.steps;
        let (error, _) = chain_error(ExplicitOptions::tolerances(tol, tol), 20.0);
        assert!(error < 30.0 * tol, "chain: error {error:e} at tolerance {tol:e}");
    }
}

/// Over a hundred seconds (about 50 swings, 1900 steps at rtol 1e-6) the pendulum stays on
/// its rod and its velocity tangent to it at every step, to round-off: the projection keeps
/// the constraint residuals bounded where the acceleration-level stages alone would drift.
/// The same for the rolling disk's two nonholonomic rows.
#[test]
fn constraint_residuals_stay_at_round_off() {
    let p = unit_pendulum();
    let mut explicit = Explicit::new(&p, ExplicitOptions::default()).expect("valid options");
    explicit.start(0.0, &horizontal_start(&p), 100.0).expect("starts");
    let (mut phi, mut av) = (VecH::<Pendulum>::zeros(), 0.0f64);
    let mut worst_phi = 0.0f64;
    while !explicit.finished() {
        explicit.step().expect("steps");
        let s = explicit.state();
        p.holonomic(explicit.t(), &s.q, &mut phi);
        worst_phi = worst_phi.max(phi.amax());
        av = av.max((s.q[0] * s.v[0] + s.q[1] * s.v[1]).abs());
    }
    assert!(worst_phi <= 1e-14, "largest |x² + y² − 1| {worst_phi:e}");
    assert!(av <= 1e-13, "largest |x vx + y vy| {av:e}");
    assert!(explicit.stats().steps > 1000, "{:?}", explicit.stats());

    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let mut explicit = Explicit::new(&disk, ExplicitOptions::default()).expect("valid options");
    let sol =
        explicit.solve(0.0, &disk_start(&disk, (2.0, 1.5)), 100.0, &Sampling::Steps).expect("integrates");
    let mut worst = 0.0f64;
    for k in 0..sol.len() {
        let state = sol.state(k).expect("a sample");
        let mut a = dirac::nalgebra::Matrix2x4::<f64>::zeros();
        disk.constraint_matrix(sol.t()[k], &state.q, &mut a);
        worst = worst.max((a * state.v).amax());
    }
    assert!(worst <= 1e-14, "largest rolling-constraint residual {worst:e}");
}

/// Samples between steps come from the dense output (order 4), put on the constraints: on the
/// rolling disk at rtol 1e-10, 400 samples agree with the exact motion to 1e-8 and satisfy the
/// rolling constraints to round-off; the multipliers there are the forces that keep the
/// contact point on its circle, m r v_θ v_φ (centripetal, from the closed form).
#[test]
fn dense_output_follows_the_exact_solution() {
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let rates = (2.0, 1.5);
    let mut explicit =
        Explicit::new(&disk, ExplicitOptions::tolerances(1e-10, 1e-12)).expect("valid options");
    let sampling = Sampling::Every(0.01);
    let sol = explicit.solve(0.0, &disk_start(&disk, rates), 4.0, &sampling).expect("integrates");
    assert!(sol.len() > 400 && sol.stats.steps < 200, "{} samples, {:?}", sol.len(), sol.stats);
    let (mut worst, mut worst_force) = (0.0f64, 0.0f64);
    let force = disk.m * disk.r * rates.0 * rates.1;
    for k in 0..sol.len() {
        let state = sol.state(k).expect("a sample");
        let exact = disk_exact(&disk, rates, sol.t()[k]);
        worst = (0..4).map(|i| (state.q[i] - exact[i]).abs()).fold(worst, f64::max);
        let (lx, ly) = (state.lambda(RollingDisk::ROLL_X), state.lambda(RollingDisk::ROLL_Y));
        worst_force = worst_force.max(((lx * lx + ly * ly).sqrt() - force).abs());
    }
    assert!(worst < 1e-8, "largest sample error {worst:e}");
    assert!(worst_force < 1e-7 * force, "constraint force off by {worst_force:e} of {force}");
}

/// An input set between steps restarts the integration: a spring (m = 1, k = 4) at rest at
/// x = 1 whose force jumps to f = 2 at t = 1 follows the piecewise closed form
/// x = cos 2t, then x = ½ + (x(1) − ½) cos 2(t − 1) + (ẋ(1)/2) sin 2(t − 1).
#[test]
fn inputs_set_between_steps_restart_the_integration() {
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let start = consistent_state(
        &spring,
        0.0,
        &VecQ::<ForcedSpring>::from([1.0]),
        &VecQ::<ForcedSpring>::zeros(),
        Consistency::default(),
    )
    .expect("consistent");
    let mut explicit = Explicit::new(&mut spring, ExplicitOptions::tolerances(1e-10, 1e-12)).expect("valid");
    explicit.start(0.0, &start, 1.0).expect("starts");
    while !explicit.finished() {
        explicit.step().expect("steps");
    }
    explicit.update(|m| m.f = 2.0).expect("an exclusive model");
    explicit.restart_until(3.0).expect("restarts");
    while !explicit.finished() {
        explicit.step().expect("steps");
    }
    let (x1, v1) = ((2.0f64).cos(), -2.0 * (2.0f64).sin());
    let tau: f64 = 2.0 * (3.0 - 1.0);
    let exact = 0.5 + (x1 - 0.5) * tau.cos() + v1 / 2.0 * tau.sin();
    let x = explicit.state().q(ForcedSpring::X);
    assert!((x - exact).abs() < 1e-8, "x(3) = {x}, exact {exact}");
}

/// Events are located on the dense output: the oscillator x = cos t crosses zero at
/// t = π/2 + kπ.
#[test]
fn events_are_located_on_the_dense_output() {
    let model = Oscillator { m: 1.0, k: 1.0 };
    let mut start = State::<Oscillator>::zeros();
    start.set_q(Oscillator::X, 1.0);
    let mut explicit =
        Explicit::new(&model, ExplicitOptions::tolerances(1e-10, 1e-12)).expect("valid options");
    let mut events =
        Events::new().on("x", Crossing::Either, |_, s: &State<Oscillator>, _| s.q(Oscillator::X));
    let sol = explicit
        .solve_with_events(0.0, &start, 10.0, &Sampling::Steps, &mut events, |_, _| ControlFlow::Continue(()))
        .expect("integrates");
    let times: Vec<f64> = sol.events().iter().map(|e| e.t).collect();
    assert_eq!(times.len(), 3, "{times:?}");
    for (k, t) in times.iter().enumerate() {
        let exact = std::f64::consts::FRAC_PI_2 + k as f64 * std::f64::consts::PI;
        assert!((t - exact).abs() < 1e-8, "event {k} at {t}, exact {exact}");
    }
}

/// Primitive system 2 of the paper alone: its coordinate x̄2 has neither inertia nor a
/// constraint, so its acceleration is not determined; the start says so and names it.
#[test]
fn a_motion_the_equations_do_not_determine_is_refused_by_name() {
    let model = Primitive2 { m3: 3.0, k3: 6.0 };
    let mut explicit = Explicit::new(&model, ExplicitOptions::default()).expect("valid options");
    let error = explicit.start(0.0, &State::<Primitive2>::zeros(), 1.0).expect_err("not determined");
    let message = error.to_string();
    assert!(matches!(error, SimError::NotDetermined { .. }), "{error:?}");
    assert!(message.contains("x2bar"), "{message}");
}

/// A stiff model (the chain with a spring of 10⁸ between m1 and m2, started with that spring
/// relaxed: its mode of period 4e-4 s is barely excited, so accuracy would allow large steps
/// and only stability forbids them) holds the explicit method to its stability limit. The
/// stiffness test stops the integration with `Unstable`, pointing to Radau, after a few dozen
/// steps; without it, a budget of 10⁴ steps runs out with `TooManySteps` at the time reached.
/// Never a wrong answer. (Started with the stiff spring stretched, the fast mode is motion to
/// be followed, its steps are set by accuracy, and the test rightly stays silent.)
#[test]
fn a_stiff_model_is_reported_as_stiff_or_exhausts_the_step_budget() {
    let model = MassSpringChain { m1: 1.0, m2: 1.0, m3: 1.0, k1: 1.0, k2: 1e8, k3: 1.0 };
    let start = consistent_state(
        &model,
        0.0,
        &VecQ::<MassSpringChain>::from([0.1, 0.1, 0.0]),
        &VecQ::<MassSpringChain>::zeros(),
        Consistency::default(),
    )
    .expect("consistent");
    let options = ExplicitOptions { max_steps: 10_000, ..ExplicitOptions::default() };
    let mut explicit = Explicit::new(&model, options).expect("valid options");
    let error = explicit.solve(0.0, &start, 100.0, &Sampling::Steps).expect_err("stiff");
    match &error {
        SimError::Unstable { t, detail, .. } => {
            assert!(*t < 0.01, "found stiff only at {t}");
            assert!(detail.contains("stiff") && detail.contains("Radau"), "{detail}");
        }
        other => panic!("expected Unstable, got {other:?}"),
    }
    assert!(explicit.stats().steps < 200, "{:?}", explicit.stats());

    let options = ExplicitOptions { stiffness_test: false, ..options };
    let mut explicit = Explicit::new(&model, options).expect("valid options");
    let error = explicit.solve(0.0, &start, 100.0, &Sampling::Steps).expect_err("too stiff for the budget");
    match error {
        SimError::TooManySteps { max_steps, t, t_end } => {
            assert_eq!(max_steps, 10_000);
            assert!(t > 0.0 && t < 1.0 && t_end == 100.0, "stopped at {t}");
        }
        other => panic!("expected TooManySteps, got {other:?}"),
    }
}

/// Bad options are refused by name before anything runs.
#[test]
fn bad_options_are_refused_by_name() {
    let p = unit_pendulum();
    for (options, what) in [
        (ExplicitOptions::tolerances(f64::NAN, 1e-8), "rtol"),
        (ExplicitOptions::tolerances(1e-6, -1.0), "atol"),
        (ExplicitOptions::tolerances(1e-300, 1e-8), "rtol"),
        (ExplicitOptions::fixed(0.0), "fixed_step"),
        (ExplicitOptions { initial_step: Some(f64::INFINITY), ..ExplicitOptions::default() }, "initial_step"),
        (ExplicitOptions { max_step: -1.0, ..ExplicitOptions::default() }, "max_step"),
    ] {
        let error = Explicit::new(&p, options).err().expect("refused");
        assert!(error.to_string().contains(what), "{what}: {error}");
    }
}

/// Absurd input ends in a typed error naming the cause, or in a finite result on the
/// constraints: a NaN parameter, a NaN or inconsistent start, a reversed span, a fixed step
/// far beyond the span, a sampling interval of zero.
#[test]
fn absurd_input_is_refused_or_stays_finite_and_on_the_constraints() {
    let p = unit_pendulum();
    let start = horizontal_start(&p);
    let run =
        |model: &Pendulum, options: ExplicitOptions, state: &State<Pendulum>, t_end: f64, s: &Sampling| {
            Explicit::new(model, options).and_then(|mut e| e.solve(0.0, state, t_end, s))
        };
    let at_end = Sampling::Times(vec![1.0]);
    let bad = Pendulum { g: f64::NAN, ..unit_pendulum() };
    let error = run(&bad, ExplicitOptions::default(), &start, 1.0, &at_end).expect_err("NaN parameter");
    assert!(matches!(&error, SimError::InvalidParameter { name, .. } if name == "g"), "{error:?}");
    let mut nan = start.clone();
    nan.set_v(Pendulum::X, f64::NAN);
    let error = run(&p, ExplicitOptions::default(), &nan, 1.0, &at_end).expect_err("NaN start");
    assert!(error.to_string().contains("vx"), "{error}");
    let mut off = start.clone();
    off.set_q(Pendulum::X, 2.0);
    let error = run(&p, ExplicitOptions::default(), &off, 1.0, &at_end).expect_err("off the rod");
    assert!(matches!(error, SimError::StateNotConsistent { .. }), "{error:?}");
    let error =
        run(&p, ExplicitOptions::default(), &start, -1.0, &Sampling::Steps).expect_err("reversed span");
    assert!(matches!(error, SimError::InvalidTimeSpan { .. }), "{error:?}");
    let error =
        run(&p, ExplicitOptions::default(), &start, 1.0, &Sampling::Every(0.0)).expect_err("zero interval");
    assert!(matches!(error, SimError::InvalidSampling { .. }), "{error:?}");
    // A fixed step of 1e300 is cut to the span: one step of 1 s, finite and on the rod (or a
    // typed error), never a wrong answer passed off as one that violates the constraint.
    match run(&p, ExplicitOptions::fixed(1e300), &start, 1.0, &at_end) {
        Ok(sol) => {
            let (x, y) = (sol.q(Pendulum::X)[0], sol.q(Pendulum::Y)[0]);
            assert!(x.is_finite() && y.is_finite() && (x * x + y * y - 1.0).abs() < 1e-12, "({x}, {y})");
            assert_eq!(sol.stats.steps, 1);
        }
        Err(error) => {
            assert!(matches!(error, SimError::Unstable { .. } | SimError::NonFinite { .. }), "{error:?}")
        }
    }
}

/// The macros' decision that a model's constraint rows are constant (they depend on its
/// parameters alone, and nothing is prescribed), against each model's constraints read by hand:
/// the chain's port (v2 − v̄2), the rack and pinion's `r θ̇ − ẋ` (r a parameter) and the L-C
/// loop's `i_l − i_c` are; the pendulum's `2x ẋ + 2y ẏ`, the one-form whose coefficients hold
/// `sin θ` and `cos x`, the shaken pair's prescribed `a ω cos(ω t)`, the rolling disk's
/// `cos φ` and the belt's input are not.
#[test]
fn constant_constraint_rows_are_recognised_when_the_model_compiles() {
    const {
        assert!(
            Chain::CONSTANT_CONSTRAINTS
                && RackAndPinion::CONSTANT_CONSTRAINTS
                && LcCircuit::CONSTANT_CONSTRAINTS
        );
        assert!(!Pendulum::CONSTANT_CONSTRAINTS && !CoupledByOneForm::CONSTANT_CONSTRAINTS);
        assert!(!ShakenPair::CONSTANT_CONSTRAINTS && !RollingDisk::CONSTANT_CONSTRAINTS);
        assert!(!DiskOnBelt::CONSTANT_CONSTRAINTS);
    };
}

/// A model with constant constraint rows keeps its factorisation from step to step, but not
/// across a change of the parameter in those rows: the rack and pinion solved twice by one
/// integrator, with r = 0.3 and then r = 0.8, follows the geared model's exact
/// θ(t) = θ0 cos(ω t), ω² = (kθ + k r²) / (J + m r²), each time (reference: the substitution
/// x = r θ by hand, as in `GearedByHand`).
#[test]
fn a_parameter_change_in_constant_constraint_rows_is_not_missed() {
    let (j, k_theta, m, k, theta0) = (0.2, 3.0, 1.5, 2.0, 0.4);
    let mut rack = RackAndPinion { wheel: Wheel { j, k_theta }, cart: Cart { m, k }, r: 0.3 };
    let mut explicit = Explicit::new(&mut rack, ExplicitOptions::tolerances(1e-10, 1e-12)).expect("valid");
    for r in [0.3, 0.8] {
        explicit.model_mut().expect("an exclusive model").r = r;
        let (th, cx) = (RackAndPinion::wheel(Wheel::THETA), RackAndPinion::cart(Cart::X));
        let mut start = State::<RackAndPinion>::zeros();
        start.set_q(th, theta0).set_q(cx, r * theta0);
        let start = consistent_state(explicit.model(), 0.0, &start.q, &start.v, Consistency::default())
            .expect("at rest, any gear ratio is met");
        let sol = explicit.solve(0.0, &start, 3.0, &Sampling::Times(vec![3.0])).expect("integrates");
        let end = sol.state(0).expect("a sample");
        let omega = ((k_theta + k * r * r) / (j + m * r * r)).sqrt();
        let exact = theta0 * (omega * 3.0).cos();
        assert!((end.q(th) - exact).abs() < 1e-7, "r = {r}: θ(3) = {}, exact {exact}", end.q(th));
        let gear = r * end.v(th) - end.v(cx);
        assert!(gear.abs() < 1e-12, "r = {r}: the gear's rate r θ̇ − ẋ = {gear:e}");
    }
}

/// Bad input on a model whose constraint rows are constant (the path that keeps them): a NaN
/// gear ratio and a NaN start are refused by name, a start off the gear is refused, a zero
/// ratio (the cart held still) and a huge one integrate to finite states on the gear, and a
/// NaN parameter set between two solves of one integrator is refused rather than hidden
/// behind the factorisation kept from before.
#[test]
fn bad_input_on_constant_constraint_rows_ends_in_typed_errors() {
    let rack = |r| RackAndPinion { wheel: Wheel { j: 0.2, k_theta: 3.0 }, cart: Cart { m: 1.5, k: 2.0 }, r };
    let (th, cx) = (RackAndPinion::wheel(Wheel::THETA), RackAndPinion::cart(Cart::X));
    let at_rest = |r: f64| {
        let mut s = State::<RackAndPinion>::zeros();
        s.set_q(th, 0.4).set_q(cx, r * 0.4);
        s
    };
    let options = ExplicitOptions::tolerances(1e-8, 1e-10);
    let run = |model: &RackAndPinion, start: &State<RackAndPinion>| {
        Explicit::new(model, options).expect("valid").solve(0.0, start, 2.0, &Sampling::Steps)
    };

    let error = run(&rack(f64::NAN), &at_rest(0.3)).expect_err("a NaN gear ratio");
    assert!(matches!(&error, SimError::InvalidParameter { name, .. } if name == "r"), "{error}");
    let mut nan_start = at_rest(0.3);
    nan_start.set_q(th, f64::NAN);
    assert!(matches!(run(&rack(0.3), &nan_start), Err(SimError::NonFinite { .. })));
    let mut off_the_gear = at_rest(0.3);
    off_the_gear.set_v(th, 1.0);
    let error = run(&rack(0.3), &off_the_gear).expect_err("r θ̇ − ẋ = 0.3 at the start");
    assert!(
        matches!(&error, SimError::StateNotConsistent { equation, .. } if equation.contains("gear")),
        "{error}"
    );

    for r in [0.0, 1e6] {
        let sol = run(&rack(r), &at_rest(r)).expect("integrates");
        let end = sol.state(sol.len() - 1).expect("a sample");
        assert!(end.components().all(|x| x.is_finite()), "r = {r}: {end:?}");
        let gear = r * end.v(th) - end.v(cx);
        assert!(gear.abs() <= 1e-9 * (1.0 + r * end.v(th).abs()), "r = {r}: r θ̇ − ẋ = {gear:e}");
    }

    let mut model = rack(0.3);
    let mut explicit = Explicit::new(&mut model, options).expect("valid");
    explicit.solve(0.0, &at_rest(0.3), 1.0, &Sampling::Steps).expect("integrates");
    explicit.model_mut().expect("an exclusive model").r = f64::NAN;
    let error = explicit.solve(0.0, &at_rest(0.3), 1.0, &Sampling::Steps).expect_err("r is NaN now");
    assert!(matches!(&error, SimError::InvalidParameter { name, .. } if name == "r"), "{error}");
}
