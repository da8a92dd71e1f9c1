//! Inputs: `f64` fields declared with `input(...)`, set between steps through the integrator,
//! which restarts there. References are closed forms of the forced spring `m ẍ = −k x + f`
//! with `f` held constant over each interval (the motion is harmonic about `f/k`), chained
//! interval by interval here, independently of dirac.

use dirac::prelude::*;
use dirac::{Input, State};

use crate::zoo::{AdjustableMass, ForcedPair, ForcedSpring};

/// `(x, v)` after `dt` from `(x, v)` under `m ẍ = −k x + f`, `f` constant.
fn propagate((x, v): (f64, f64), f: f64, (m, k): (f64, f64), dt: f64) -> (f64, f64) {
    let w = (k / m).sqrt();
    let xe = f / k;
    let (s, c) = (w * dt).sin_cos();
    (xe + (x - xe) * c + v / w * s, -(x - xe) * w * s + v * c)
}

fn at_rest_at(model: &ForcedSpring, x: f64) -> State<ForcedSpring> {
    let (q, v) = (VecQ::<ForcedSpring>::from([x]), VecQ::<ForcedSpring>::zeros());
    consistent_state(model, 0.0, &q, &v, Consistency::default()).expect("consistent")
}

#[test]
fn inputs_have_keys_names_and_values() {
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.5 };
    assert_eq!(ForcedSpring::F.index(), 0);
    assert_eq!(ForcedSpring::F.name(), "f");
    assert_eq!(spring.input_names(), ["f"]);
    assert_eq!(spring.input(ForcedSpring::F), 0.5);
    spring.set_input(ForcedSpring::F, -2.0);
    assert_eq!(spring.f, -2.0);
    assert_eq!(Input::<ForcedSpring>::checked(1), None);
    // A model without inputs has none.
    assert!(crate::zoo::unit_pendulum().input_names().is_empty());
}

#[test]
fn a_composite_exposes_its_members_inputs() {
    let left = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let mut pair = ForcedPair { left: left.clone(), right: ForcedSpring { m: 2.0, k: 5.0, f: 0.0 } };
    assert_eq!(pair.input_names(), ["left.f", "right.f"]);
    let right_f = ForcedPair::right_input(ForcedSpring::F);
    assert_eq!(right_f.index(), 1);
    assert_eq!(right_f.name(), "right.f");
    pair.set_input(right_f, 3.0);
    pair.set_input(ForcedPair::left_input(ForcedSpring::F), -1.0);
    assert_eq!((pair.left.f, pair.right.f), (-1.0, 3.0));
    assert_eq!(pair.input(right_f), 3.0);
}

#[test]
fn a_held_step_input_gives_the_exact_forced_response() {
    // f = 0 on [0, 1), f = 2 on [1, 3]: two harmonic arcs about 0 and about f/k.
    let (m, k, tol) = (1.0, 4.0, 1e-11);
    let mut spring = ForcedSpring { m, k, f: 0.0 };
    let start = at_rest_at(&spring, 1.0);
    let mut radau = Radau::new(&mut spring, RadauOptions::tolerances(tol, tol)).expect("valid");
    radau.start(0.0, &start, 1.0).expect("starts");
    while !radau.finished() {
        radau.step().expect("steps");
    }
    radau.set_input(ForcedSpring::F, 2.0).expect("an exclusive model");
    radau.restart_until(3.0).expect("restarts");
    while !radau.finished() {
        radau.step().expect("steps");
    }
    let expected = propagate(propagate((1.0, 0.0), 0.0, (m, k), 1.0), 2.0, (m, k), 2.0);
    let s = radau.state();
    assert_eq!(radau.t(), 3.0);
    assert!((s.q[0] - expected.0).abs() < 1e-8, "x = {} against {}", s.q[0], expected.0);
    assert!((s.v[0] - expected.1).abs() < 1e-8, "v = {} against {}", s.v[0], expected.1);
    assert!((s.p[0] - m * expected.1).abs() < 1e-8);
}

/// The variational integrator's error at t = 3 under the same held step, with step `h`.
fn variational_step_error(h: f64) -> f64 {
    let (m, k) = (1.0, 4.0);
    let mut spring = ForcedSpring { m, k, f: 0.0 };
    let start = at_rest_at(&spring, 1.0);
    let mut vi = Variational::new(&mut spring, h, VariationalOptions::default()).expect("valid");
    let solution = vi
        .solve_sampled(0.0, &start, 3.0, 1.0, &Sampling::Times(vec![3.0]), |t, _, model| {
            model.f = if t < 1.0 { 0.0 } else { 2.0 };
        })
        .expect("integrates");
    let expected = propagate(propagate((1.0, 0.0), 0.0, (m, k), 1.0), 2.0, (m, k), 2.0);
    (solution.last().expect("a sample").q[0] - expected.0).abs()
}

#[test]
fn the_variational_integrator_follows_held_inputs_to_second_order() {
    let (coarse, fine) = (variational_step_error(2e-3), variational_step_error(1e-3));
    assert!(fine < 1e-5, "error {fine:e} at h = 1e-3");
    let order = (coarse / fine).log2();
    assert!((order - 2.0).abs() < 0.1, "observed order {order} (errors {coarse:e}, {fine:e})");
}

#[test]
fn a_sampled_controller_closes_the_loop_exactly() {
    // f_k = −K x(t_k) − D v(t_k) every T, held: the closed loop of a sampled-data controller,
    // chained here interval by interval from the closed form.
    let (m, k, gain, damping, period, t_end) = (1.0, 4.0, 3.0, 0.5, 0.1, 5.0);
    let law = |x: f64, v: f64| -gain * x - damping * v;
    let mut reference = vec![(0.0, (1.0, 0.0))];
    let mut xv = (1.0, 0.0);
    for step in 1..=50 {
        xv = propagate(xv, law(xv.0, xv.1), (m, k), period);
        reference.push((step as f64 * period, xv));
    }
    let mut spring = ForcedSpring { m, k, f: 0.0 };
    let start = at_rest_at(&spring, 1.0);
    let tol = 1e-11;
    let mut radau = Radau::new(&mut spring, RadauOptions::tolerances(tol, tol)).expect("valid");
    let times: Vec<f64> = reference.iter().map(|(t, _)| *t).collect();
    let solution = radau
        .solve_sampled(0.0, &start, t_end, period, &Sampling::Times(times), |_, s, model| {
            model.set_input(ForcedSpring::F, law(s.q[0], s.v[0]));
        })
        .expect("integrates");
    assert_eq!(solution.len(), reference.len());
    let (xs, vs) = (solution.q(ForcedSpring::X), solution.v(ForcedSpring::X));
    for (i, (t, (x, v))) in reference.iter().enumerate() {
        assert!((solution.t()[i] - t).abs() < 1e-12);
        assert!((xs[i] - x).abs() < 1e-8, "x({t}) = {} against {x}", xs[i]);
        assert!((vs[i] - v).abs() < 1e-8, "v({t}) = {} against {v}", vs[i]);
    }
    // The controller acted: without it the amplitude stays 1; the damping term alone would
    // leave an envelope of about e^(−D t / 2m) = e^(−1.25) ≈ 0.29 at t = 5.
    let (_, (x_end, _)) = reference.last().copied().expect("samples");
    assert!(x_end.abs() < 0.4, "closed loop at t = 5: {x_end}");
}

#[test]
fn a_composite_is_driven_through_its_members_inputs() {
    // Joined ends: (m1 + m2) ẍ = −(k1 + k2) x + f1 + f2.
    let (left, right) = (ForcedSpring { m: 1.0, k: 4.0, f: 0.0 }, ForcedSpring { m: 2.0, k: 5.0, f: 0.0 });
    let mut pair = ForcedPair { left, right };
    let q = VecQ::<ForcedPair>::from([0.5, 0.5]);
    let start = consistent_state(&pair, 0.0, &q, &VecQ::<ForcedPair>::zeros(), Consistency::default())
        .expect("consistent");
    let tol = 1e-11;
    let mut radau = Radau::new(&mut pair, RadauOptions::tolerances(tol, tol)).expect("valid");
    let right_f = ForcedPair::right_input(ForcedSpring::F);
    let solution = radau
        .solve_sampled(0.0, &start, 2.0, 0.5, &Sampling::Times(vec![2.0]), |t, _, model| {
            model.set_input(right_f, if t < 1.0 { 0.0 } else { 3.0 });
        })
        .expect("integrates");
    let (mass, stiffness) = (3.0, 9.0);
    let expected = propagate(propagate((0.5, 0.0), 0.0, (mass, stiffness), 1.0), 3.0, (mass, stiffness), 1.0);
    let end = solution.last().expect("a sample");
    assert!((end.q[0] - expected.0).abs() < 1e-8, "x = {} against {}", end.q[0], expected.0);
    assert!((end.q[1] - expected.0).abs() < 1e-8);
}

#[test]
fn changing_a_shared_model_is_refused() {
    let spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let start = at_rest_at(&spring, 1.0);
    let mut radau = Radau::new(&spring, RadauOptions::default()).expect("valid");
    radau.start(0.0, &start, 1.0).expect("starts");
    radau.step().expect("steps");
    let error = radau.set_input(ForcedSpring::F, 1.0).expect_err("a shared model");
    assert!(matches!(error, SimError::SharedModel { .. }), "{error}");
    assert!(error.to_string().contains("&mut model"), "{error}");
    let sampled = Radau::new(&spring, RadauOptions::default()).expect("valid").solve_sampled(
        0.0,
        &start,
        1.0,
        0.1,
        &Sampling::Steps,
        |_, _, _| {},
    );
    assert!(matches!(sampled, Err(SimError::SharedModel { t: 0.0 })));
}

#[test]
fn an_input_in_the_mass_matrix_cannot_change_while_the_mass_moves() {
    let mut model = AdjustableMass { m: 1.0, dm: 0.0, k: 4.0 };
    let (q, v) = (VecQ::<AdjustableMass>::from([0.0]), VecQ::<AdjustableMass>::from([1.0]));
    let start = consistent_state(&model, 0.0, &q, &v, Consistency::default()).expect("consistent");
    let mut radau = Radau::new(&mut model, RadauOptions::default()).expect("valid");
    radau.start(0.0, &start, 1.0).expect("starts");
    radau.step().expect("steps");
    let t = radau.t();
    let error = radau.update(|m| m.dm = 0.5).expect_err("the momentum no longer matches");
    match &error {
        SimError::MomentumChanged { t: at, equation, .. } => {
            assert_eq!(*at, t);
            assert!(equation.contains("`x`"), "{equation}");
        }
        other => panic!("expected MomentumChanged, got {other}"),
    }
    // At rest p = (m + dm) v = 0 whatever dm is: the same change is allowed there.
    let mut resting = AdjustableMass { m: 1.0, dm: 0.0, k: 4.0 };
    let start = consistent_state(&resting, 0.0, &q, &VecQ::<AdjustableMass>::zeros(), Consistency::default())
        .expect("consistent");
    let mut radau = Radau::new(&mut resting, RadauOptions::default()).expect("valid");
    radau.start(0.0, &start, 1.0).expect("starts");
    radau.update(|m| m.dm = 0.5).expect("p = 0 still matches");
}

/// A pendulum whose inertia depends on its angle: its momentum `p = ∂L/∂v` is nonlinear in the
/// angle, so the stages' Newton iteration solves it to the integrator's accuracy, not exactly.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(q => v), input(u), force(q) = u)]
#[dirac(lagrangian = 0.5 * (1.0 + 0.5 * q.sin() * q.sin()) * v * v + q.cos())]
struct WobblySwing {
    u: f64,
}

/// A damping controller sampled at 1 kHz on it: an input in a force keeps `p = ∂L/∂v`, and
/// every restart accepts the momenta as Radau's Newton iteration left them (within its error
/// weights). Before, the check held them to 1e-8 of their own size and failed where the
/// momentum passes through zero (at t = 1.374: "the momentum of `q` does not match its
/// velocity … by 1.0e-8"), as it did in the Panda example.
#[test]
fn a_sampled_controller_on_an_angle_dependent_inertia_runs_to_its_end() {
    let mut swing = WobblySwing { u: 0.0 };
    let q = VecQ::<WobblySwing>::from([1.0]);
    let start = consistent_state(&swing, 0.0, &q, &VecQ::<WobblySwing>::zeros(), Consistency::default())
        .expect("consistent");
    let mut radau = Radau::new(&mut swing, RadauOptions::tolerances(1e-8, 1e-8)).expect("valid");
    let run = radau
        .solve_sampled(0.0, &start, 10.0, 1e-3, &Sampling::Steps, |_, s, m| m.u = -0.1 * s.v[0])
        .expect("runs to its end");
    // Damped: the energy falls.
    let energy = run.energy();
    assert!(energy[energy.len() - 1] < energy[0], "{} from {}", energy[energy.len() - 1], energy[0]);
}

#[test]
fn a_sampled_run_rejects_a_bad_period() {
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let start = at_rest_at(&spring, 1.0);
    let mut radau = Radau::new(&mut spring, RadauOptions::default()).expect("valid");
    for period in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let result = radau.solve_sampled(0.0, &start, 1.0, period, &Sampling::Steps, |_, _, _| {});
        assert!(matches!(result, Err(SimError::InvalidOption { what: "period", .. })), "{period}");
    }
}

#[test]
fn a_sinusoidal_source_gives_the_closed_form_forced_response() {
    // m ẍ + k x = u0 sin(ω t), x(0) = x0, ẋ(0) = 0, ω ≠ ω0:
    // x = x0 cos ω0 t + (u0/m)/(ω0² − ω²) (sin ω t − (ω/ω0) sin ω0 t).
    let (m, k, u0, w, x0): (f64, f64, f64, f64, f64) = (1.0, 4.0, 0.7, 1.3, 0.5);
    let w0 = (k / m).sqrt();
    let exact = |t: f64| {
        x0 * (w0 * t).cos() + (u0 / m) / (w0 * w0 - w * w) * ((w * t).sin() - w / w0 * (w0 * t).sin())
    };
    let mut spring = ForcedSpring { m, k, f: 0.0 };
    let start = at_rest_at(&spring, x0);
    let mut source = |t: f64, _: &State<ForcedSpring>, model: &mut ForcedSpring| model.f = u0 * (w * t).sin();
    let tol = 1e-11;
    let mut radau = Radau::new(&mut spring, RadauOptions::tolerances(tol, tol)).expect("valid");
    radau.drive(&mut source).expect("an exclusive model");
    let times: Vec<f64> = (1..=10).map(|i| i as f64).collect();
    let solution = radau.solve(0.0, &start, 10.0, &Sampling::Times(times.clone())).expect("integrates");
    let xs = solution.q(ForcedSpring::X);
    assert_eq!(xs.len(), times.len());
    for (x, t) in xs.iter().zip(&times) {
        assert!((x - exact(*t)).abs() < 1e-8, "x({t}) = {x} against {}", exact(*t));
    }
}

#[test]
fn a_linearly_interpolated_table_gives_the_ramp_response() {
    // u = a t on [0, 4] from a two-sample table: x = (a/k) t + x0 cos ω0 t − a/(k ω0) sin ω0 t.
    let (m, k, a, x0): (f64, f64, f64, f64) = (1.0, 4.0, 0.3, 0.2);
    let w0 = (k / m).sqrt();
    let exact = |t: f64| a / k * t + x0 * (w0 * t).cos() - a / (k * w0) * (w0 * t).sin();
    let table = dirac::sources::Table::new(vec![0.0, 4.0], vec![0.0, 4.0 * a], dirac::sources::Hold::Linear)
        .expect("a valid table");
    let mut spring = ForcedSpring { m, k, f: 0.0 };
    let start = at_rest_at(&spring, x0);
    let mut source = |t: f64, _: &State<ForcedSpring>, model: &mut ForcedSpring| model.f = table.at(t);
    let tol = 1e-11;
    let mut radau = Radau::new(&mut spring, RadauOptions::tolerances(tol, tol)).expect("valid");
    radau.drive(&mut source).expect("an exclusive model");
    let solution = radau.solve(0.0, &start, 4.0, &Sampling::Times(vec![4.0])).expect("integrates");
    let x = solution.last().expect("a sample").q[0];
    assert!((x - exact(4.0)).abs() < 1e-8, "x(4) = {x} against {}", exact(4.0));
}

/// How the feedback's part of the Newton matrix is formed.
#[derive(Clone, Copy)]
enum FeedbackJacobian {
    None,
    Differences,
    Given,
}

/// A feedback law on the forced spring, and its `∂u/∂(q, v)`.
type Law<'m> = &'m mut dyn FnMut(f64, &State<ForcedSpring>, &mut ForcedSpring);
type LawJacobian<'m> = &'m mut dyn FnMut(f64, &State<ForcedSpring>, &mut [f64]);

/// Attaches the feedback `law` to `radau` with the Jacobian treatment `jacobian`
/// (`law_jacobian` its `∂u/∂(q, v)` for `Given`).
fn attach<'m>(
    radau: &mut Radau<'m, ForcedSpring>,
    jacobian: FeedbackJacobian,
    law: Law<'m>,
    law_jacobian: LawJacobian<'m>,
) {
    match jacobian {
        FeedbackJacobian::None => radau.drive(law).expect("an exclusive model"),
        FeedbackJacobian::Differences => radau.drive_feedback(law).expect("a dense model"),
        FeedbackJacobian::Given => radau.drive_feedback_with(law, law_jacobian).expect("a dense model"),
    }
}

/// Radau on the forced spring under the continuous feedback `f = −K x − D v`, with the given
/// Jacobian treatment; the largest error against the closed loop's closed form and the Newton
/// iterations.
fn feedback_run(jacobian: FeedbackJacobian) -> (f64, usize) {
    // m ẍ + D ẋ + (k + K) x = 0, x(0) = x0, ẋ(0) = 0: an underdamped oscillator.
    let (m, k, gain, damping, x0): (f64, f64, f64, f64, f64) = (1.0, 4.0, 5.0, 0.8, 1.0);
    let (sigma, wd) = (damping / (2.0 * m), ((k + gain) / m - (damping / (2.0 * m)).powi(2)).sqrt());
    let exact = |t: f64| x0 * (-sigma * t).exp() * ((wd * t).cos() + sigma / wd * (wd * t).sin());
    let mut spring = ForcedSpring { m, k, f: 0.0 };
    let start = at_rest_at(&spring, x0);
    let mut law = |_: f64, s: &State<ForcedSpring>, model: &mut ForcedSpring| {
        model.f = -gain * s.q[0] - damping * s.v[0];
    };
    // ∂f/∂(x, v), one input, two columns.
    let mut law_jacobian =
        |_: f64, _: &State<ForcedSpring>, out: &mut [f64]| out.copy_from_slice(&[-gain, -damping]);
    let tol = 1e-10;
    let mut radau = Radau::new(&mut spring, RadauOptions::tolerances(tol, tol)).expect("valid");
    attach(&mut radau, jacobian, &mut law, &mut law_jacobian);
    let times: Vec<f64> = (1..=20).map(|i| 0.25 * i as f64).collect();
    let solution = radau.solve(0.0, &start, 5.0, &Sampling::Times(times.clone())).expect("integrates");
    let xs = solution.q(ForcedSpring::X);
    assert_eq!(xs.len(), times.len());
    let error = xs.iter().zip(&times).map(|(x, t)| (x - exact(*t)).abs()).fold(0.0, f64::max);
    (error, solution.stats.newton_iterations)
}

#[test]
fn continuous_feedback_closes_the_loop_with_its_jacobian() {
    let (error, iterations) = feedback_run(FeedbackJacobian::Differences);
    assert!(error < 1e-8, "closed-loop error {error:e}");
    let (error_given, iterations_given) = feedback_run(FeedbackJacobian::Given);
    assert!(error_given < 1e-8, "closed-loop error with the given Jacobian {error_given:e}");
    // Differences and the exact product build the same Newton matrix up to round-off.
    assert!(
        iterations_given.abs_diff(iterations) <= iterations / 20,
        "{iterations_given} against {iterations}"
    );
    // Without the inputs' part of the Newton matrix the iteration still converges on this
    // mild loop, to the same solution, but it needs more iterations.
    let (error_without, iterations_without) = feedback_run(FeedbackJacobian::None);
    assert!(error_without < 1e-8, "closed-loop error without the feedback Jacobian {error_without:e}");
    assert!(
        iterations < iterations_without,
        "{iterations} Newton iterations with the feedback Jacobian, {iterations_without} without"
    );
}

/// Radau on the forced spring under the nonlinear feedback `f = −K x³ − D v` from x(0) = 1 at
/// rest: x at t = 5, the Newton iterations and the Jacobian evaluations.
fn cubic_feedback_run(jacobian: FeedbackJacobian, tol: f64) -> (f64, usize, usize) {
    let (gain, damping) = (20.0, 0.3);
    let mut spring = ForcedSpring { m: 1.0, k: 1.0, f: 0.0 };
    let start = at_rest_at(&spring, 1.0);
    let mut law = |_: f64, s: &State<ForcedSpring>, model: &mut ForcedSpring| {
        model.f = -gain * s.q[0].powi(3) - damping * s.v[0];
    };
    let mut law_jacobian = |_: f64, s: &State<ForcedSpring>, out: &mut [f64]| {
        out.copy_from_slice(&[-3.0 * gain * s.q[0] * s.q[0], -damping]);
    };
    let mut radau = Radau::new(&mut spring, RadauOptions::tolerances(tol, tol)).expect("valid");
    attach(&mut radau, jacobian, &mut law, &mut law_jacobian);
    let solution = radau.solve(0.0, &start, 5.0, &Sampling::Times(vec![5.0])).expect("integrates");
    let x = solution.q(ForcedSpring::X)[0];
    (x, solution.stats.newton_iterations, solution.stats.jacobian_evaluations)
}

#[test]
fn a_nonlinear_feedback_keeps_its_jacobian_through_reevaluations() {
    // The law's Jacobian changes along the motion, so the Newton matrix is evaluated again and
    // again; each evaluation must carry the feedback's part once, not once more every time.
    let (reference, ..) = cubic_feedback_run(FeedbackJacobian::None, 1e-12);
    let (x_without, iterations_without, _) = cubic_feedback_run(FeedbackJacobian::None, 1e-8);
    let (x_given, iterations_given, evaluations) = cubic_feedback_run(FeedbackJacobian::Given, 1e-8);
    let (x_differences, iterations_differences, _) = cubic_feedback_run(FeedbackJacobian::Differences, 1e-8);
    assert!(evaluations > 10, "{evaluations} Jacobian evaluations");
    for x in [x_without, x_given, x_differences] {
        assert!((x - reference).abs() < 1e-6, "x(5) = {x} against {reference} (rtol 1e-12)");
    }
    assert!(
        iterations_given.abs_diff(iterations_differences) <= iterations_given / 20,
        "{iterations_given} against {iterations_differences}"
    );
    assert!(
        iterations_given < iterations_without,
        "{iterations_given} Newton iterations with the feedback Jacobian, {iterations_without} without"
    );
}

#[test]
fn tables_refuse_bad_samples() {
    use dirac::sources::{Hold, Table};
    for (times, values) in [
        (vec![], vec![]),
        (vec![0.0, 1.0], vec![1.0]),
        (vec![0.0, 0.0], vec![1.0, 2.0]),
        (vec![1.0, 0.0], vec![1.0, 2.0]),
        (vec![0.0, f64::NAN], vec![1.0, 2.0]),
        (vec![0.0, 1.0], vec![1.0, f64::INFINITY]),
    ] {
        let result = Table::new(times.clone(), values, Hold::Zero);
        assert!(matches!(result, Err(SimError::InvalidOption { what: "table", .. })), "{times:?}");
    }
    let held = Table::new(vec![0.0, 1.0, 2.0], vec![1.0, 2.0, 3.0], Hold::Zero).expect("valid");
    assert_eq!([held.at(-1.0), held.at(0.5), held.at(1.0), held.at(7.0)], [1.0, 1.0, 2.0, 3.0]);
    let line = Table::new(vec![0.0, 1.0, 2.0], vec![1.0, 2.0, 0.0], Hold::Linear).expect("valid");
    assert_eq!([line.at(-1.0), line.at(0.5), line.at(1.5), line.at(7.0)], [1.0, 1.5, 1.0, 0.0]);
}

#[test]
fn a_drive_needs_an_exclusive_model() {
    let spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let mut radau = Radau::new(&spring, RadauOptions::default()).expect("valid");
    let mut source = |_: f64, _: &State<ForcedSpring>, m: &mut ForcedSpring| m.f = 1.0;
    assert!(matches!(radau.drive(&mut source), Err(SimError::SharedModel { .. })));
}

#[test]
fn outputs_are_recorded_by_name() {
    // The output `energy` is written by hand in the model; the solution's `energy` column is
    // computed by the runtime as ⟨p, v⟩ − L. Unforced, both are the same constant.
    let spring = ForcedSpring { m: 1.5, k: 4.0, f: 0.0 };
    assert_eq!(spring.output_names(), ["energy", "stretch"]);
    assert_eq!(ForcedSpring::STRETCH.name(), "stretch");
    let start = at_rest_at(&spring, 0.8);
    let mut radau = Radau::new(&spring, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let solution = radau.solve(0.0, &start, 3.0, &Sampling::Every(0.5)).expect("integrates");
    let (output, energy) = (solution.output(ForcedSpring::ENERGY), solution.energy());
    assert_eq!(output.len(), solution.len());
    for (a, b) in output.iter().zip(energy) {
        assert!((a - b).abs() < 1e-12, "output {a} against energy {b}");
        assert!((a - 0.5 * 4.0 * 0.8 * 0.8).abs() < 1e-7, "energy {a} is kept to the tolerance");
    }
    let stretch = solution.column("out(stretch)").expect("a column named out(stretch)");
    for (s, x) in stretch.iter().zip(solution.q(ForcedSpring::X)) {
        assert!((s - 4.0 * x).abs() < 1e-12);
    }
}

#[test]
fn a_composite_records_its_members_outputs() {
    // The composite's energy is the sum of its members' (the interconnection is lossless and
    // adds no energy of its own).
    let (left, right) = (ForcedSpring { m: 1.0, k: 4.0, f: 0.0 }, ForcedSpring { m: 2.0, k: 5.0, f: 0.0 });
    let pair = ForcedPair { left, right };
    assert_eq!(pair.output_names(), ["left.energy", "left.stretch", "right.energy", "right.stretch"]);
    let right_energy = ForcedPair::right_output(ForcedSpring::ENERGY);
    assert_eq!((right_energy.index(), right_energy.name()), (2, "right.energy".to_owned()));
    let q = VecQ::<ForcedPair>::from([0.5, 0.5]);
    let start = consistent_state(&pair, 0.0, &q, &VecQ::<ForcedPair>::zeros(), Consistency::default())
        .expect("consistent");
    let mut radau = Radau::new(&pair, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let solution = radau.solve(0.0, &start, 2.0, &Sampling::Every(0.25)).expect("integrates");
    let left_energy = solution.output(ForcedPair::left_output(ForcedSpring::ENERGY));
    let right_energy = solution.output(right_energy);
    for ((l, r), e) in left_energy.iter().zip(right_energy).zip(solution.energy()) {
        assert!((l + r - e).abs() < 1e-12, "{l} + {r} against {e}");
    }
    // Read directly from the model, as a controller would.
    let last = solution.last().expect("a sample");
    let mut values = [0.0; 4];
    pair.outputs(2.0, &last.q, &last.v, &last.lambda, &mut values);
    assert_eq!(values[1], 4.0 * last.q[0]);
    assert_eq!(values[3], 5.0 * last.q[1]);
}

/// The zoo's Cartesian pendulum with the rod's tension as an output: the force `Aᵀλ = 2λ q`
/// has magnitude `2 |λ| l` along the rod.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(rod) = x * x + y * y - l * l)]
#[dirac(output(tension) = -2.0 * l * rod)]
struct TautPendulum {
    m: f64,
    g: f64,
    l: f64,
}

#[test]
fn an_output_reads_a_multiplier_by_its_constraint_name() {
    // Released at rest from the horizontal, the bob passes the bottom after a quarter period,
    // T/4 = √(l/g) K(1/2) (DESIGN.md §3), at speed v² = 2 g l: the rod pulls m g + m v²/l = 3 m g.
    let (m, g, l) = (1.0, 9.81, 1.0);
    let model = TautPendulum { m, g, l };
    let q = VecQ::<TautPendulum>::from([l, 0.0]);
    let start = consistent_state(&model, 0.0, &q, &VecQ::<TautPendulum>::zeros(), Consistency::default())
        .expect("consistent");
    let quarter = 2.367_841_947_576_237_4 / 4.0;
    let mut radau = Radau::new(&model, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let solution = radau.solve(0.0, &start, quarter, &Sampling::Times(vec![quarter])).expect("integrates");
    let tension = solution.output(TautPendulum::TENSION)[0];
    assert!((tension - 3.0 * m * g).abs() < 1e-5 * m * g, "tension {tension} against 3 m g");
    // Hanging at rest it carries the weight, m g cos θ + m l θ̇²: stationary to first order in
    // (θ, θ̇), so its row of the linear model is zero.
    let hanging = consistent_state(
        &model,
        0.0,
        &VecQ::<TautPendulum>::from([0.0, -l]),
        &VecQ::<TautPendulum>::zeros(),
        Consistency::default(),
    )
    .expect("consistent");
    let mut values = [0.0];
    model.outputs(0.0, &hanging.q, &hanging.v, &hanging.lambda, &mut values);
    assert!((values[0] - m * g).abs() < 1e-12, "tension at rest {}", values[0]);
    let linear = linearize(&model, 0.0, &hanging).expect("an output of a multiplier");
    assert!(linear.c.amax() < 1e-12, "the tension's row {}", linear.c);
}

/// Springs whose ends are all joined: an array whose elements have inputs and outputs.
#[derive(Interconnection, Clone)]
#[dirac(connect(springs[i].x, springs[i + 1].x))]
struct Bundle {
    springs: Vec<ForcedSpring>,
}

#[test]
fn an_array_exposes_its_elements_inputs_and_outputs() {
    // Joined ends: (Σ m) ẍ = −(Σ k) x + Σ f; element j's `stretch` is k_j x.
    let springs: Vec<ForcedSpring> =
        (0..4).map(|j| ForcedSpring { m: 1.0 + j as f64, k: 2.0 + j as f64, f: 0.0 }).collect();
    let (mass, stiffness) =
        (springs.iter().map(|s| s.m).sum::<f64>(), springs.iter().map(|s| s.k).sum::<f64>());
    let mut bundle = Bundle { springs };
    assert_eq!(bundle.input_names(), ["springs[0].f", "springs[1].f", "springs[2].f", "springs[3].f"]);
    assert_eq!(bundle.output_names().len(), 8);
    assert_eq!(bundle.output_names()[3], "springs[1].stretch");
    let third = bundle.springs_input(2, ForcedSpring::F);
    assert_eq!(third.index(), 2);
    bundle.set_input(third, 1.5);
    assert_eq!((bundle.springs[2].f, bundle.input(third)), (1.5, 1.5));
    bundle.set_input(third, 0.0);
    let stretch = bundle.springs_output(1, ForcedSpring::STRETCH);
    assert_eq!(stretch.index(), 3);

    let sizes = bundle.sizes();
    let q = VecQ::<Bundle>::from_element_generic(
        dirac::nalgebra::Dyn(sizes.nq),
        dirac::nalgebra::Const::<1>,
        0.4,
    );
    let v = VecQ::<Bundle>::zeros_generic(dirac::nalgebra::Dyn(sizes.nq), dirac::nalgebra::Const::<1>);
    let start = consistent_state(&bundle, 0.0, &q, &v, Consistency::default()).expect("consistent");
    let tol = 1e-11;
    let mut radau = Radau::new(&mut bundle, RadauOptions::tolerances(tol, tol)).expect("valid");
    let solution = radau
        .solve_sampled(0.0, &start, 2.0, 0.5, &Sampling::Times(vec![2.0]), |t, _, model| {
            model.set_input(third, if t < 1.0 { 0.0 } else { 2.0 });
        })
        .expect("integrates");
    let expected = propagate(propagate((0.4, 0.0), 0.0, (mass, stiffness), 1.0), 2.0, (mass, stiffness), 1.0);
    let end = solution.last().expect("a sample");
    assert!((end.q[0] - expected.0).abs() < 1e-8, "x = {} against {}", end.q[0], expected.0);
    let recorded = solution.output(stretch)[0];
    assert!((recorded - 3.0 * expected.0).abs() < 1e-8, "springs[1].stretch = {recorded}");
    assert_eq!(solution.column("out(springs[1].stretch)").map(|c| c[0]), Some(recorded));
}

#[test]
#[should_panic(expected = "`springs` has 2 elements; there is no element 5")]
fn a_key_past_the_end_of_an_array_of_inputs_panics() {
    let bundle = Bundle { springs: vec![ForcedSpring { m: 1.0, k: 1.0, f: 0.0 }; 2] };
    let _ = bundle.springs_input(5, ForcedSpring::F);
}

/// Bad input to the open-model API ends in typed errors that name the cause.
#[test]
fn open_models_refuse_bad_input_with_typed_errors() {
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let start = at_rest_at(&spring, 1.0);

    // A NaN input is refused at the restart, by name.
    let mut radau = Radau::new(&mut spring, RadauOptions::default()).expect("valid");
    radau.start(0.0, &start, 1.0).expect("starts");
    radau.step().expect("steps");
    let error = radau.set_input(ForcedSpring::F, f64::NAN).expect_err("a NaN input");
    assert!(matches!(&error, SimError::InvalidParameter { name, .. } if name == "f"), "{error}");

    // Sampling periods that are below the resolution of t, or make absurdly many samples,
    // and spans that are not spans.
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let mut radau = Radau::new(&mut spring, RadauOptions::default()).expect("valid");
    for (t_end, period) in [(1.0, 1e-20), (1e3, 1e-8)] {
        let result = radau.solve_sampled(0.0, &start, t_end, period, &Sampling::Steps, |_, _, _| {});
        assert!(matches!(result, Err(SimError::InvalidOption { what: "period", .. })), "{period:e}");
    }
    for t_end in [f64::NAN, 0.0, -1.0, f64::INFINITY] {
        let result = radau.solve_sampled(0.0, &start, t_end, 0.1, &Sampling::Steps, |_, _, _| {});
        assert!(matches!(result, Err(SimError::InvalidTimeSpan { .. })), "{t_end}");
    }

    // A drive that turns an input to NaN mid-run: an error, not a NaN solution.
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let mut source =
        |t: f64, _: &State<ForcedSpring>, m: &mut ForcedSpring| m.f = if t < 0.5 { 0.0 } else { f64::NAN };
    let mut radau = Radau::new(&mut spring, RadauOptions::default()).expect("valid");
    radau.drive(&mut source).expect("exclusive");
    let error = radau.solve(0.0, &start, 1.0, &Sampling::Steps).expect_err("a NaN input");
    assert!(matches!(error, SimError::NonFinite { .. } | SimError::StepSizeTooSmall { .. }), "{error}");
    assert!(error.to_string().contains("0.5") || error.to_string().contains("non-finite"), "{error}");

    // A user feedback Jacobian with NaN in it is named.
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let mut law = |_: f64, s: &State<ForcedSpring>, m: &mut ForcedSpring| m.f = -s.q[0];
    let mut bad_jacobian =
        |_: f64, _: &State<ForcedSpring>, out: &mut [f64]| out.copy_from_slice(&[-1.0, f64::NAN]);
    let mut radau = Radau::new(&mut spring, RadauOptions::default()).expect("valid");
    radau.drive_feedback_with(&mut law, &mut bad_jacobian).expect("a dense model");
    let error = radau.solve(0.0, &start, 1.0, &Sampling::Steps).expect_err("a NaN Jacobian");
    assert!(error.to_string().contains("drive_feedback_with"), "{error}");

    // Linearising a model with a NaN parameter.
    let broken = ForcedSpring { m: 1.0, k: f64::NAN, f: 0.0 };
    let state = State::<ForcedSpring>::zeros();
    let error = dirac::linearize(&broken, 0.0, &state).expect_err("a NaN parameter");
    assert!(matches!(&error, SimError::InvalidParameter { name, .. } if name == "k"), "{error}");
}

/// A model whose output is not finite somewhere along the run.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(x => v), output(root) = x.sqrt())]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
struct Rooted {
    m: f64,
    k: f64,
}

#[test]
fn a_non_finite_output_is_an_error_not_a_result() {
    // x = cos 2t turns negative at t = π/4, where √x is NaN.
    let model = Rooted { m: 1.0, k: 4.0 };
    let q = VecQ::<Rooted>::from([1.0]);
    let start = consistent_state(&model, 0.0, &q, &VecQ::<Rooted>::zeros(), Consistency::default())
        .expect("consistent");
    let mut radau = Radau::new(&model, RadauOptions::default()).expect("valid");
    let error = radau.solve(0.0, &start, 2.0, &Sampling::Every(0.1)).expect_err("√x of a negative x");
    match &error {
        SimError::NonFinite { t, component } => {
            assert!(component.contains("output `root`"), "{component}");
            assert!(*t > std::f64::consts::FRAC_PI_4 && *t < 1.0, "first at {t}");
        }
        other => panic!("expected NonFinite, got {other}"),
    }
}
