//! Probes of the edges: bad parameters, bad states, absurd options, degenerate models. Each
//! case ends in a typed error that names its true cause (the parameter, the equation, the
//! time), or in a correct result; none may hang, panic or abort, and each runs under a time
//! limit of its own (`within`).

use std::sync::mpsc;
use std::time::Duration;

use dirac::State;
use dirac::prelude::*;

use crate::every_method::{Fineness, Method};
use crate::zoo::*;

/// Runs `f` on its own thread and fails the test if it panics or takes longer than `seconds`.
fn within<T: Send + 'static>(seconds: u64, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = send.send(f());
    });
    match receive.recv_timeout(Duration::from_secs(seconds)) {
        Ok(value) => value,
        Err(mpsc::RecvTimeoutError::Timeout) => panic!("did not finish within {seconds} s"),
        Err(mpsc::RecvTimeoutError::Disconnected) => panic!("panicked"),
    }
}

fn pendulum(m: f64, g: f64, l: f64) -> Pendulum {
    Pendulum { m, g, l }
}

fn start_of(p: &Pendulum, x: f64, y: f64) -> Result<State<Pendulum>, SimError> {
    consistent_state(p, 0.0, &VecQ::<Pendulum>::new(x, y), &VecQ::<Pendulum>::zeros(), Consistency::default())
}

fn expect_parameter<T: std::fmt::Debug>(result: Result<T, SimError>, name: &str) {
    match result {
        Err(SimError::InvalidParameter { name: n, .. }) => assert_eq!(n, name),
        other => panic!("expected parameter `{name}` to be refused, got {other:?}"),
    }
}

/// A NaN or infinite parameter is named, wherever it is first met: in consistent_state (which
/// used to hang in its SVD on m = NaN) and in every integrator, for a primitive model and for
/// a composite (dotted name).
#[test]
fn non_finite_parameters_are_named() {
    within(20, || {
        for (p, name) in [
            (pendulum(f64::NAN, 9.81, 1.0), "m"),
            (pendulum(f64::INFINITY, 9.81, 1.0), "m"),
            (pendulum(1.0, f64::NAN, 1.0), "g"),
            (pendulum(1.0, f64::NEG_INFINITY, 1.0), "g"),
            (pendulum(1.0, 9.81, f64::NAN), "l"),
        ] {
            expect_parameter(start_of(&p, 1.0, 0.0), name);
            let good = horizontal_start(&unit_pendulum());
            each_integrator!(&p, Fineness::new(1e-6, 1e-8, 0.01), |_method, integrator| {
                expect_parameter(integrator.into_solution(&good), name)
            });
        }
        let mut chain = paper_chain();
        chain.left.m1 = f64::NAN;
        let q = VecQ::<Chain>::zeros();
        expect_parameter(consistent_state(&chain, 0.0, &q, &q, Consistency::default()), "left.m1");
        chain.left.m1 = 1.0;
        chain.right.k3 = f64::INFINITY;
        expect_parameter(consistent_state(&chain, 0.0, &q, &q, Consistency::default()), "right.k3");
    });
}

/// Solves over [0, 1] from `start` and returns the solution, for the probes.
trait IntoSolution<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    type Stats;
    fn into_solution(self, start: &State<M>) -> Result<Solution<M, Self::Stats>, SimError>;
}

impl<I: Integrator<M>, M: LagrangeDirac + Hybrid> IntoSolution<M> for I
where
    DefaultAllocator: Storage<M>,
{
    type Stats = I::Stats;
    fn into_solution(mut self, start: &State<M>) -> Result<Solution<M, I::Stats>, SimError> {
        self.solve(0.0, start, 1.0, &Sampling::Steps)
    }
}

/// Non-finite or overflowing starts and times: typed errors, never NaN multipliers as success.
#[test]
fn non_finite_starts_and_times_are_errors() {
    within(20, || {
        let p = unit_pendulum();
        let nan_time = consistent_state(
            &p,
            f64::NAN,
            &VecQ::<Pendulum>::new(1.0, 0.0),
            &VecQ::<Pendulum>::zeros(),
            Consistency::default(),
        );
        assert!(matches!(nan_time, Err(SimError::InvalidTimeSpan { .. })), "{nan_time:?}");
        let fast = consistent_state(
            &p,
            0.0,
            &VecQ::<Pendulum>::new(0.0, -1.0),
            &VecQ::<Pendulum>::new(1e200, 0.0),
            Consistency::default(),
        );
        match fast {
            Err(SimError::NonFinite { component, .. }) => assert!(!component.is_empty()),
            other => panic!("v = 1e200 overflows the tension: expected a non-finite error, got {other:?}"),
        }
        let inf_q = consistent_state(
            &p,
            0.0,
            &VecQ::<Pendulum>::new(f64::INFINITY, 0.0),
            &VecQ::<Pendulum>::zeros(),
            Consistency::default(),
        );
        assert_eq!(inf_q.err(), Some(SimError::NonFinite { t: 0.0, component: "x".into() }));
        // A spring with an infinite stiffness term met through the time: F = a sin(w t) with
        // t = inf in a start given straight to an integrator.
        let osc = DrivenOscillator { m: 1.0, k: 1.0, c: 0.0, a: 1.0, w: 1.0 };
        let start = State::<DrivenOscillator>::zeros();
        each_integrator!(&osc, Fineness::new(1e-6, 1e-8, 0.01), |method, integrator| {
            for (t0, t_end) in [(f64::INFINITY, 1.0), (0.0, f64::NAN), (1.0, 0.0), (0.0, f64::INFINITY)] {
                let err = integrator.solve(t0, &start, t_end, &Sampling::Steps);
                assert!(
                    matches!(err, Err(SimError::InvalidTimeSpan { .. })),
                    "{method:?} {t0} {t_end}: {err:?}"
                );
            }
        });
    });
}

/// A state off the constraint given straight to an integrator is refused and the equation
/// named, by every integrator, instead of integrated or silently snapped.
#[test]
fn inconsistent_starts_are_refused() {
    within(20, || {
        let fine = Fineness::new(1e-6, 1e-8, 0.01);
        let p = unit_pendulum();
        let mut off = State::<Pendulum>::zeros();
        off.set_q(Pendulum::X, 5.0);
        each_integrator!(&p, fine, |method, integrator| match integrator.into_solution(&off).err() {
            Some(SimError::StateNotConsistent { equation, residual, t }) => {
                assert_eq!(equation, "holonomic constraint `rod`");
                assert_eq!(residual, 24.0, "x² + y² − l² at x = 5");
                assert_eq!(t, 0.0);
            }
            other => panic!("{method:?}: expected the rod to be named, got {other:?}"),
        });
        // Moving across a rolling disk's no-slip constraint, and a momentum that is not m v.
        let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
        let mut slipping = State::<RollingDisk>::zeros();
        slipping.set_v(RollingDisk::Y, 1.0).set_p(RollingDisk::Y, 2.0);
        each_integrator!(&disk, fine, |method, integrator| {
            let err = integrator.into_solution(&slipping).err();
            assert!(
                matches!(&err, Some(SimError::StateNotConsistent { equation, .. }) if equation == "velocity constraint `roll_y`"),
                "{method:?}: {err:?}"
            );
        });
        let mut heavy = State::<Pendulum>::zeros();
        heavy.set_q(Pendulum::X, 1.0).set_v(Pendulum::Y, 1.0).set_p(Pendulum::Y, 3.0);
        each_integrator!(&p, fine, |method, integrator| {
            let err = integrator.into_solution(&heavy).err();
            assert!(
                matches!(&err, Some(SimError::StateNotConsistent { equation, .. }) if equation.contains("Legendre map")),
                "{method:?}: {err:?}"
            );
        });
    });
}

/// Absurd options are refused at construction, by name.
#[test]
fn absurd_options_are_refused() {
    within(20, || {
        let p = unit_pendulum();
        for options in [
            RadauOptions::tolerances(1e300, 1e300),
            RadauOptions::tolerances(1.0, 1e-8),
            RadauOptions::tolerances(1e-20, 1e-8),
            RadauOptions { max_newton_iterations: 0, ..RadauOptions::default() },
            RadauOptions { initial_step: Some(f64::NAN), ..RadauOptions::default() },
            RadauOptions { max_step: -1.0, ..RadauOptions::default() },
        ] {
            let err = Radau::new(&p, options).err();
            assert!(
                matches!(err, Some(SimError::InvalidOption { .. } | SimError::InvalidTolerance { .. })),
                "{options:?} gave {err:?}"
            );
        }
        for options in [
            VariationalOptions { max_iterations: 0, ..VariationalOptions::default() },
            VariationalOptions { tolerance: -1.0, ..VariationalOptions::default() },
            VariationalOptions { tolerance: f64::NAN, ..VariationalOptions::default() },
            VariationalOptions { max_steps: 0, ..VariationalOptions::default() },
        ] {
            let err = Variational::new(&p, 0.01, options).err();
            assert!(
                matches!(err, Some(SimError::InvalidOption { .. } | SimError::InvalidTolerance { .. })),
                "{options:?} gave {err:?}"
            );
        }
        for h in [0.0, -0.1, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                Variational::new(&p, h, VariationalOptions::default()),
                Err(SimError::InvalidOption { what: "step", .. })
            ));
        }
        for tolerance in [-1e-13, f64::NAN, 0.0] {
            let err = consistent_state(
                &p,
                0.0,
                &VecQ::<Pendulum>::new(1.0, 0.0),
                &VecQ::<Pendulum>::zeros(),
                Consistency { tolerance, max_iterations: 50 },
            );
            assert!(matches!(err, Err(SimError::InvalidTolerance { .. })), "tolerance {tolerance}: {err:?}");
        }
    });
}

/// Steps too small to advance time, step counts beyond the budget and samplings too dense to
/// hold are refused at the start, instead of looping or running out of memory.
#[test]
fn unbounded_work_is_refused_at_the_start() {
    within(20, || {
        let p = unit_pendulum();
        let start = horizontal_start(&p);
        let mut vi = Variational::new(&p, 1e-300, VariationalOptions::default()).expect("valid");
        let err = vi.solve(0.0, &start, 20.0, &Sampling::Steps).err();
        assert!(
            matches!(err, Some(SimError::StepSizeTooSmall { .. })),
            "h = 1e-300 cannot reach t = 20: {err:?}"
        );
        let mut vi = Variational::new(&p, 1e-9, VariationalOptions::default()).expect("valid");
        let err = vi.solve(0.0, &start, 20.0, &Sampling::Steps).err();
        assert!(matches!(err, Some(SimError::TooManySteps { .. })), "2e10 steps: {err:?}");
        let err = Radau::new(&p, RadauOptions::default()).expect("valid").solve(
            0.0,
            &start,
            20.0,
            &Sampling::Every(1e-8),
        );
        match err {
            Err(SimError::InvalidSampling { reason }) => assert!(reason.contains("samples"), "{reason}"),
            other => panic!("expected the sampling to be refused, got {other:?}"),
        }
        // Radau from a time so large that its first step cannot advance it: the reason is said.
        let mut radau = Radau::new(&p, RadauOptions::default()).expect("valid");
        let err = radau.solve(1e15, &start, 1e15 + 1.0, &Sampling::Steps).err();
        match err {
            Some(SimError::StepSizeTooSmall { reason, .. }) => {
                assert!(reason.contains("resolution"), "{reason}")
            }
            other => panic!("expected a step below the resolution of t, got {other:?}"),
        }
    });
}

/// A variational step beyond the stability limit (h = 2 on the chain, whose fastest period is
/// about 1.4) is an error, not an energy of 1e31 returned as success.
#[test]
fn unstable_variational_steps_are_errors() {
    within(20, || {
        let chain = paper_chain();
        let start = paper_chain_start(&chain);
        let mut vi = Variational::new(&chain, 2.0, VariationalOptions::default()).expect("valid");
        let err = vi.solve(0.0, &start, 200.0, &Sampling::Steps).err();
        match err {
            Some(SimError::Unstable { detail, .. }) => assert!(detail.contains("smaller step"), "{detail}"),
            other => panic!("expected an unstable step, got {other:?}"),
        }
        // The same chain at h = 0.05 stays stable over a long run: no false alarm.
        let mut vi = Variational::new(&chain, 0.05, VariationalOptions::default()).expect("valid");
        let sol = vi.solve(0.0, &start, 2000.0, &Sampling::Every(10.0)).expect("stable");
        let e0 = sol.energy()[0];
        assert!(sol.energy().iter().all(|e| (e - e0).abs() < 1e-2 * e0));
    });
}

/// The variational integrator ends exactly at the end time, with the number of steps that
/// span needs, even far from t = 0 (t0 = 1e15, where a step is 2 ulp) and when the span is
/// not a multiple of h; Sampling::Every records the end time when its grid misses it.
#[test]
fn end_times_are_kept() {
    within(20, || {
        let chain = MassSpringChain { m1: 1.0, m2: 2.0, m3: 3.0, k1: 4.0, k2: 5.0, k3: 6.0 };
        let q = VecQ::<MassSpringChain>::new(0.1, 0.0, 0.0);
        let start =
            consistent_state(&chain, 1e15, &q, &VecQ::<MassSpringChain>::zeros(), Consistency::default())
                .expect("consistent");
        let mut vi = Variational::new(&chain, 0.25, VariationalOptions::default()).expect("valid");
        let sol = vi.solve(1e15, &start, 1e15 + 250.0, &Sampling::Steps).expect("integrates");
        assert_eq!(sol.stats.steps, 1000);
        assert_eq!(*sol.t().last().expect("samples"), 1e15 + 250.0);
        let start =
            consistent_state(&chain, 0.0, &q, &VecQ::<MassSpringChain>::zeros(), Consistency::default())
                .expect("consistent");
        let mut vi = Variational::new(&chain, 0.3, VariationalOptions::default()).expect("valid");
        let sol = vi.solve(0.0, &start, 10.0, &Sampling::Every(1.0)).expect("integrates");
        assert_eq!(sol.stats.steps, 34, "33 steps of 0.3 and a last one of 0.1");
        assert_eq!(*sol.t().last().expect("samples"), 10.0);
        assert_eq!(sol.len(), 11, "t = 0, 1, …, 10");
        let p = unit_pendulum();
        let sol = Radau::new(&p, RadauOptions::default())
            .expect("valid")
            .solve(0.0, &horizontal_start(&p), 1.05, &Sampling::Every(0.1))
            .expect("integrates");
        assert_eq!(sol.t().len(), 12, "t = 0, 0.1, …, 1.0 and the end time 1.05");
        assert_eq!(*sol.t().last().expect("samples"), 1.05);
        // Every integrator ends exactly there, far from t = 0 too.
        let start = horizontal_start(&p);
        each_integrator!(&p, Fineness::new(1e-6, 1e-8, 0.01), |method, integrator| {
            let sol = integrator.solve(0.0, &start, 1.05, &Sampling::Every(0.1)).expect("integrates");
            assert_eq!(sol.t().len(), 12, "{method:?}: t = 0, 0.1, …, 1.0 and the end time 1.05");
            assert_eq!(*sol.t().last().expect("samples"), 1.05, "{method:?}");
            assert_eq!(integrator.t(), 1.05, "{method:?}");
        });
        // At t = 1e15, where t moves in steps of 0.125: the variational step of 0.25 ends there
        // exactly; an adaptive method whose steps fall below that says so.
        let start =
            consistent_state(&chain, 1e15, &q, &VecQ::<MassSpringChain>::zeros(), Consistency::default())
                .expect("consistent");
        each_integrator!(&chain, Fineness::new(1e-6, 1e-8, 0.25), |method, integrator| {
            match integrator.solve(1e15, &start, 1e15 + 25.0, &Sampling::Steps) {
                Ok(_) => assert_eq!(integrator.t(), 1e15 + 25.0, "{method:?}"),
                Err(SimError::StepSizeTooSmall { reason, .. }) if method != Method::Variational => {
                    assert!(reason.contains("resolution of t"), "{method:?}: {reason}")
                }
                Err(e) => panic!("{method:?}: {e}"),
            }
        });
    });
}

/// Samples between variational steps lie on the constraints (they used to be linear
/// interpolations with |A v| = 1.1e-4 at h = 0.03 on a nonholonomic model).
#[test]
fn variational_samples_lie_on_the_constraints() {
    within(20, || {
        let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
        let v = VecQ::<RollingDisk>::new(0.6, 0.0, 2.0, 1.0);
        let start = consistent_state(&disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
            .expect("consistent");
        let mut vi = Variational::new(&disk, 0.03, VariationalOptions::default()).expect("valid");
        let sol = vi.solve(0.0, &start, 5.0, &Sampling::Every(0.0137)).expect("integrates");
        let worst = sol.constraint_residual().iter().copied().fold(0.0, f64::max);
        assert!(worst < 1e-12, "|A v| at the samples: {worst:e}");
        let p = unit_pendulum();
        let mut vi = Variational::new(&p, 0.03, VariationalOptions::default()).expect("valid");
        let sol = vi.solve(0.0, &horizontal_start(&p), 5.0, &Sampling::Every(0.0137)).expect("integrates");
        let worst = sol.holonomic_residual().iter().copied().fold(0.0, f64::max);
        assert!(worst < 1e-12, "|φ| at the samples: {worst:e}");
    });
}

/// Keys are made from numbers only through `checked`, which knows the model's size.
#[test]
fn keys_out_of_range_do_not_exist() {
    assert_eq!(Coordinate::<Pendulum>::checked(1), Some(Pendulum::Y));
    assert_eq!(Coordinate::<Pendulum>::checked(5), None);
    assert_eq!(Constraint::<Pendulum>::checked(1), None);
    assert_eq!(Constraint::<Pendulum>::checked(0), Some(Pendulum::ROD));
}

/// Two constraints with the same one-form (up to a factor).
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * (vx * vx + vy * vy) - 9.81 * y)]
#[dirac(holonomic(rod) = x * x + y * y - 1.0)]
#[dirac(holonomic(again) = 2.0 * (x * x + y * y) - 2.0)]
struct TwoRods {}

/// Degenerate models and states: the message names the true cause (a vanishing one-form, a
/// massless pendulum), not another coordinate; dependent constraints run.
#[test]
fn singular_systems_name_their_cause() {
    within(20, || {
        // l = 0: the rod's one-form (2x, 2y) vanishes where the rod holds.
        let err = start_of(&pendulum(1.0, 9.81, 0.0), 0.0, 0.0).err();
        match err {
            Some(SimError::NotDetermined { cause, .. }) => {
                assert!(cause.contains("row of constraint `rod` is zero"), "{cause}")
            }
            other => panic!("expected the rod's vanishing one-form, got {other:?}"),
        }
        // Two rods that are one are redundant, not singular: the start takes the multipliers of
        // least norm, in the ratio of the rows' one-forms (1 : 2): the centripetal pull of 1 is
        // 2 λ₁ + 4 λ₂ in size, so λ = ±(0.1, 0.2).
        let start = consistent_state(
            &TwoRods {},
            0.0,
            &VecQ::<TwoRods>::new(1.0, 0.0),
            &VecQ::<TwoRods>::new(0.0, 1.0),
            Consistency::default(),
        )
        .expect("redundant rows start");
        assert!((start.lambda[1] - 2.0 * start.lambda[0]).abs() < 1e-14, "{}", start.lambda);
        assert!((start.lambda[0].abs() - 0.1).abs() < 1e-12, "{}", start.lambda);
        // A massless coordinate that nothing holds, given straight to each integrator: the
        // error names its velocity, at the start.
        // (From x3 = 0.1, where the spring pulls on x̄2 and nothing answers.)
        let mut pulled = State::<Primitive2>::zeros();
        pulled.set_q(Primitive2::X3, 0.1);
        each_integrator!(
            &Primitive2 { m3: 3.0, k3: 6.0 },
            Fineness::new(1e-6, 1e-8, 0.01),
            |method, integrator| {
                let err = integrator.into_solution(&pulled).err();
                let message = err.as_ref().map(ToString::to_string).unwrap_or_default();
                assert!(message.contains("v2bar") || message.contains("x2bar"), "{method:?}: {err:?}");
                assert!(message.contains("t = 0"), "{method:?}: {message}");
            }
        );
        // m = 0: nothing has inertia; the rod fixes one velocity, the other is free.
        let err = start_of(&pendulum(0.0, 9.81, 1.0), 1.0, 0.0).err();
        match err {
            Some(SimError::NotDetermined { cause, .. }) => {
                assert!(cause.contains("velocity of `y` is not determined"), "{cause}")
            }
            other => panic!("expected the free velocity, got {other:?}"),
        }
    });
}

/// Neighbours that are fine: a negative mass or stiffness is unusual but well posed, and runs.
#[test]
fn unusual_but_well_posed_models_run() {
    within(20, || {
        let chain = Chain {
            left: Primitive1 { m1: 1.0, m2: 2.0, k1: -4.0, k2: 5.0 },
            right: Primitive2 { m3: 3.0, k3: 6.0 },
        };
        let start = paper_chain_start(&chain);
        each_integrator!(&chain, Fineness::new(1e-6, 1e-8, 0.01), |method, integrator| {
            let sol = integrator
                .solve(0.0, &start, 1.0, &Sampling::Steps)
                .unwrap_or_else(|e| panic!("{method:?}: a negative spring is unstable but integrable: {e}"));
            assert!(sol.q(Chain::left(Primitive1::X1)).iter().all(|x| x.is_finite()), "{method:?}");
        });
    });
}

/// Messages as a new user meets them: each says what is wrong in the user's words and what to
/// do about it.
#[test]
fn messages_say_what_is_wrong_and_what_to_do() {
    // A restitution outside [0, 1] names the range, not finiteness.
    let ball = BouncingBall { m: 0.3, g: 9.81, e: 1.5 };
    let mut start = State::<BouncingBall>::zeros();
    start.set_q(BouncingBall::Y, 1.0);
    let mut events = dirac::Events::new().contacts(&ball);
    let error = Radau::new(&ball, RadauOptions::default())
        .expect("valid")
        .solve_with_events(0.0, &start, 1.0, &Sampling::Steps, &mut events, |_, _| {
            std::ops::ControlFlow::Continue(())
        })
        .expect_err("refused at the first impact")
        .to_string();
    assert!(error.contains("restitution of `floor` is 1.5: it must lie in [0, 1]"), "{error}");
    assert!(!error.contains("finite"), "{error}");

    // The step budget names the option that raises it.
    let pendulum = unit_pendulum();
    let q = VecQ::<Pendulum>::from([1f64.sin(), -1f64.cos()]);
    let start = consistent_state(&pendulum, 0.0, &q, &VecQ::<Pendulum>::zeros(), Consistency::default())
        .expect("consistent");
    let options = RadauOptions { max_steps: 5, ..RadauOptions::default() };
    let error = Radau::new(&pendulum, options)
        .expect("valid")
        .solve(0.0, &start, 10.0, &Sampling::Steps)
        .expect_err("out of steps")
        .to_string();
    assert!(error.contains("raise `max_steps`") && error.contains("RadauOptions"), "{error}");

    // A momentum that disagrees with the velocity says so, and how to make a consistent start.
    let mut wrong = start.clone();
    wrong.p[0] += 1.0;
    let error = Radau::new(&pendulum, RadauOptions::default())
        .expect("valid")
        .solve(0.0, &wrong, 1.0, &Sampling::Steps)
        .expect_err("inconsistent")
        .to_string();
    assert!(error.contains("the momentum of `x` does not match its velocity"), "{error}");
    assert!(error.contains("consistent_state"), "{error}");
}
