//! Events through every integrator: crossings located against closed forms, declared event
//! functions, and actions that reset the state, change the model or stop. References: free
//! fall and its geometric series of bounces, the pendulum's quarter period by the complete
//! elliptic integral (the design notes' `T = 2.367841947576237449` for `l = 1`, `g = 9.81`
//! from the horizontal), and the forced oscillator's piecewise closed form.

use std::f64::consts::PI;
use std::ops::ControlFlow;

use dirac::State;
use dirac::prelude::*;
use dirac::{Crossing, Events};

use super::{Fineness, Method};
use crate::zoo::{Ball, ForcedSpring, Pendulum, PortedBall, horizontal_start, unit_pendulum};

const G: f64 = 9.81;

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// A ball dropped from `h0` whose velocity an action reverses and scales by `e` at each
/// touchdown: touchdown `n` at `t1 (1 + 2 (e + … + eⁿ))`, apex `n` at that plus `eⁿ t1`,
/// `t1 = √(2 h0 / g)`. Every method integrates a parabola exactly (Radau's collocation and
/// Explicit's pair and continuous extension are exact on quadratics, and the variational step
/// is exact under a constant force), so the located times agree to round-off.
#[test]
fn bounces_and_apexes_follow_the_geometric_series() {
    let (h0, e): (f64, f64) = (1.0, 0.8);
    let ball = Ball { m: 0.3, g: G };
    let mut start = State::<Ball>::zeros();
    start.set_q(Ball::Y, h0);
    let t1 = (2.0 * h0 / G).sqrt();
    let touchdown_at = |n: i32| t1 * (1.0 + 2.0 * (1..=n).map(|k| e.powi(k)).sum::<f64>());
    each_integrator!(&ball, Fineness::new(1e-12, 1e-12, 0.01), |method, integrator| {
        let mut events = Events::new()
            .on("touchdown", Crossing::Falling, |_, s: &State<Ball>, _| s.q(Ball::Y))
            .on("apex", Crossing::Falling, |_, s: &State<Ball>, _| s.v(Ball::Y));
        let touchdown = events.index("touchdown").expect("an event of that name");
        let solution = integrator
            .solve_with_events(0.0, &start, 3.5, &Sampling::Every(0.01), &mut events, |event, at| {
                if event.index == touchdown {
                    let v = at.state().v(Ball::Y);
                    at.state_mut().set_v(Ball::Y, -e * v);
                }
                ControlFlow::Continue(())
            })
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let touchdowns = solution.event_times("touchdown").expect("an event function of that name");
        let apexes = solution.event_times("apex").expect("an event function of that name");
        assert!(touchdowns.len() >= 8, "{method:?}: {} touchdowns", touchdowns.len());
        for (n, &t) in touchdowns.iter().enumerate() {
            let exact = touchdown_at(n as i32);
            assert!(relative(t, exact) < 1e-9, "{method:?}: touchdown {n} at {t}, not {exact}");
        }
        for (n, &t) in apexes.iter().enumerate() {
            let n = n as i32 + 1;
            let exact = touchdown_at(n - 1) + e.powi(n) * t1;
            assert!(relative(t, exact) < 1e-9, "{method:?}: apex {n} at {t}, not {exact}");
        }
        assert!(solution.events().windows(2).all(|w| w[0].t < w[1].t), "{method:?}: events in time order");
    });
}

/// The pendulum released from the horizontal passes below its pivot (x falls through zero)
/// after a quarter period, `T/4 = 0.591960486894059`; the action stops the integration there.
/// Radau and Explicit hold their tolerance; the variational integrator is second order in its
/// step, `h² = 1e-6`.
#[test]
fn the_pendulum_passes_below_its_pivot_after_a_quarter_period() {
    let quarter = 2.367_841_947_576_237 / 4.0;
    let p = unit_pendulum();
    let start = horizontal_start(&p);
    each_integrator!(&p, Fineness::new(1e-10, 1e-12, 1e-3), |method, integrator| {
        let mut events =
            Events::new().on("below", Crossing::Falling, |_, s: &State<Pendulum>, _| s.q(Pendulum::X));
        let solution = integrator
            .solve_with_events(0.0, &start, 2.0, &Sampling::Steps, &mut events, |_, _| ControlFlow::Break(()))
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let t = solution.event_times("below").expect("the event")[0];
        let tolerance = if method == Method::Variational { 1e-5 } else { 1e-8 };
        assert!(relative(t, quarter) < tolerance, "{method:?}: {t} against {quarter}");
        assert_eq!(*solution.t().last().expect("samples"), t, "{method:?}: stopped at the event");
        assert_eq!(solution.events().len(), 1, "{method:?}");
    });
}

/// Events the model declares (`#[dirac(event(apex, falling) = v)]` on the ported ball): thrown
/// up at `v0` from `y0`, the ball's apex is at `v0/g`, at the height `y0 + v0²/(2g)`; its
/// floor, watched, is not reached.
#[test]
fn declared_events_are_located_by_every_method() {
    let (y0, v0) = (1.0, 2.0);
    let ball = PortedBall { m: 0.5, g: G, e: 0.5 };
    let mut start = State::<PortedBall>::zeros();
    start.set_q(PortedBall::Y, y0).set_v(PortedBall::Y, v0).set_p(PortedBall::Y, 0.5 * v0);
    each_integrator!(&ball, Fineness::new(1e-12, 1e-12, 0.01), |method, integrator| {
        let mut events = Events::new().declared().contacts(&ball);
        let solution = integrator
            .solve_with_events(0.0, &start, 0.5, &Sampling::Steps, &mut events, |_, _| {
                ControlFlow::Continue(())
            })
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let apex = solution.event_times("apex").expect("the declared event");
        assert_eq!(apex.len(), 1, "{method:?}: {apex:?}");
        assert!(relative(apex[0], v0 / G) < 1e-9, "{method:?}: {} against {}", apex[0], v0 / G);
        let k = solution.t().iter().position(|&t| t == apex[0]).expect("a sample at the event");
        let height = solution.q(PortedBall::Y)[k];
        assert!(relative(height, y0 + v0 * v0 / (2.0 * G)) < 1e-9, "{method:?}: apex height {height}");
    });
}

/// An action that changes the model: the spring `m ẍ = −k x + f` released from `x0` at rest
/// with `f = 0` gets the force `F` when it first passes zero, at `t1 = π/(2ω)`; after that
/// `x = F/k − (F/k) cos(ω s) − x0 sin(ω s)`, `s = t − t1`.
#[test]
fn an_action_that_changes_the_model_restarts_on_the_new_one() {
    let (m, k, x0, force): (f64, f64, f64, f64) = (1.0, 4.0, 0.5, 1.5);
    let omega = (k / m).sqrt();
    let t1 = PI / (2.0 * omega);
    let t_end = 3.0;
    let s = t_end - t1;
    let exact = force / k - force / k * (omega * s).cos() - x0 * (omega * s).sin();
    let mut start = State::<ForcedSpring>::zeros();
    start.set_q(ForcedSpring::X, x0);
    let mut spring = ForcedSpring { m, k, f: 0.0 };
    each_integrator!(&mut spring, Fineness::new(1e-10, 1e-12, 1e-3), |method, integrator| {
        integrator.model_mut().expect("held exclusively").f = 0.0;
        let mut events =
            Events::new().on("zero", Crossing::Falling, |_, s: &State<ForcedSpring>, _| s.q(ForcedSpring::X));
        let solution = integrator
            .solve_with_events(0.0, &start, t_end, &Sampling::Times(vec![t_end]), &mut events, |_, at| {
                at.model_mut().expect("held exclusively").f = force;
                ControlFlow::Continue(())
            })
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let x = *solution.q(ForcedSpring::X).last().expect("a sample at the end");
        let tolerance = if method == Method::Variational { 1e-5 } else { 1e-8 };
        assert!((x - exact).abs() < tolerance, "{method:?}: x(3) = {x}, not {exact}");
        let zero = solution.event_times("zero").expect("the event");
        assert!(relative(zero[0], t1) < tolerance, "{method:?}: {} against {t1}", zero[0]);
    });
}
