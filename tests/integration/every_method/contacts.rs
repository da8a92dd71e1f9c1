//! Contacts declared on the model (`unilateral(floor, restitution = e) = y`) through every
//! integrator: the impact law applied at each touchdown, the touchdowns on the geometric
//! series of free fall, and each impulse the momentum the law reverses, `m (1 + e) |v⁻|`.

use std::ops::ControlFlow;
use std::time::Duration;

use dirac::State;
use dirac::prelude::*;
use dirac::{Events, Impact, Solution};

use super::{Fineness, Method};
use crate::zoo::BouncingBall;

const G: f64 = 9.81;

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Touchdown `n` at `T_n = t1 (1 + 2 (e + … + eⁿ))`, `t1 = √(2 h0 / g)`, with the impulse
/// `m (1 + e) eⁿ √(2 g h0)`; each method integrates the parabolas between them exactly.
#[test]
fn a_ball_bounces_on_its_declared_floor_under_every_method() {
    let (h0, e, m) = (1.0, 0.8, 0.3);
    let ball = BouncingBall { m, g: G, e };
    let mut start = State::<BouncingBall>::zeros();
    start.set_q(BouncingBall::Y, h0);
    let t1 = (2.0 * h0 / G).sqrt();
    let zeno = t1 * (1.0 + 2.0 * e / (1.0 - e));
    each_integrator!(&ball, Fineness::new(1e-12, 1e-12, 0.01), |method, integrator| {
        let mut events = Events::new().contacts(&ball);
        let solution = integrator
            .solve_with_events(0.0, &start, 0.95 * zeno, &Sampling::Every(0.01), &mut events, |_, _| {
                ControlFlow::Continue(())
            })
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let impacts = solution.impacts_at("floor").expect("a contact of that name");
        assert!(impacts.len() >= 10, "{method:?}: {} impacts", impacts.len());
        for (n, &Impact { t, impulse, .. }) in impacts.iter().enumerate() {
            let exact_t = t1 * (1.0 + 2.0 * (1..=n as i32).map(|k| e.powi(k)).sum::<f64>());
            let exact_impulse = m * (1.0 + e) * e.powi(n as i32) * (2.0 * G * h0).sqrt();
            assert!(relative(t, exact_t) < 1e-8, "{method:?}: impact {n} at {t}, not {exact_t}");
            assert!(
                relative(impulse, exact_impulse) < 1e-7,
                "{method:?}: impulse {n} {impulse}, not {exact_impulse}"
            );
        }
        // Between impacts the ball stays above its floor, at every sample.
        let lowest = solution.q(BouncingBall::Y).iter().copied().fold(f64::INFINITY, f64::min);
        assert!(lowest > -1e-9, "{method:?}: the ball went {lowest} below the floor");
        // Every sample, between steps too, on the closed-form flight it belongs to: from
        // touchdown n, `y = eⁿ v1 s − g s²/2`, `s = t − T_n`, `v1 = √(2 g h0)`. The adaptive
        // methods' dense outputs are exact on parabolas; the variational integrator's samples
        // between its grid points are interpolated and put back on the constraints, within
        // `g h²/8` of the flight.
        let v1 = (2.0 * G * h0).sqrt();
        let tolerance = if method == Method::Variational { G * 0.01 * 0.01 / 8.0 } else { 1e-8 };
        for (&t, &y) in solution.t().iter().zip(solution.q(BouncingBall::Y)) {
            let exact = match impacts.iter().rposition(|i| i.t <= t) {
                None => h0 - 0.5 * G * t * t,
                Some(n) => {
                    let s = t - impacts[n].t;
                    e.powi(n as i32 + 1) * v1 * s - 0.5 * G * s * s
                }
            };
            // At an impact's time the solution holds the state before and after it: both at y = 0.
            assert!((y - exact).abs() <= tolerance, "{method:?}: y({t}) = {y}, not {exact}");
        }
    });
}

/// A declared floor is never passed unannounced: every run watches it (a plain solve, a
/// sampled-controller solve, an observed one, one with progress, one with events that watch
/// nothing else), and the ball bounces off it once in the first second, at the touchdown of free
/// fall, `√(2 h0/g)`; with `Events::free_motion()` the ball falls through it, as asked.
#[test]
fn no_solve_passes_through_a_declared_floor_unannounced() {
    let mut ball = BouncingBall { m: 0.3, g: G, e: 0.8 };
    let mut start = State::<BouncingBall>::zeros();
    start.set_q(BouncingBall::Y, 1.0);
    fn bounced<S>(method: Method, how: &str, solution: Result<Solution<BouncingBall, S>, SimError>) {
        let solution = solution.unwrap_or_else(|error| panic!("{method:?}, {how}: {error}"));
        // The touchdown at √(2 h0/g) = 0.4515 s; the next, 2 · 0.8 · 0.4515 s later, is past 1 s.
        let impacts = solution.impacts_at("floor").expect("the floor");
        assert_eq!(impacts.len(), 1, "{method:?}, {how}: {impacts:?}");
        assert!((impacts[0].t - (2.0 / G).sqrt()).abs() < 1e-7, "{method:?}, {how}: {impacts:?}");
        let lowest = solution.q(BouncingBall::Y).iter().copied().fold(f64::INFINITY, f64::min);
        assert!(lowest > -1e-9, "{method:?}, {how}: {lowest}");
    }
    each_integrator!(&mut ball, Fineness::new(1e-8, 1e-8, 0.01), |method, integrator| {
        let plain = integrator.solve(0.0, &start, 1.0, &Sampling::Every(0.01));
        bounced(method, "solve", plain);
        let mut steps = 0;
        let observed = integrator.solve_observed(0.0, &start, 1.0, &Sampling::Steps, |_, _| {
            steps += 1;
            ControlFlow::Continue(())
        });
        bounced(method, "solve_observed", observed);
        assert!(steps > 2, "{method:?}: the observer saw {steps} steps");
        let mut samples = 0;
        let sampled =
            integrator.solve_sampled(0.0, &start, 1.0, 0.1, &Sampling::Steps, |_, _, _| samples += 1);
        bounced(method, "solve_sampled", sampled);
        assert_eq!(samples, 10, "{method:?}: samples at 0, 0.1, …, 0.9");
        let mut reports = 0;
        let progress =
            integrator
                .solve_with_progress(0.0, &start, 1.0, &Sampling::Steps, Duration::ZERO, |_| reports += 1);
        bounced(method, "solve_with_progress", progress);
        assert!(reports > 2, "{method:?}: {reports} reports");
        let mut events = Events::new();
        let watched_nothing =
            integrator.solve_with_events(0.0, &start, 1.0, &Sampling::Steps, &mut events, |_, _| {
                ControlFlow::Continue(())
            });
        bounced(method, "solve_with_events", watched_nothing);
        // The opt-out: free fall through the floor, y = 1 − g t²/2 = −3.905 at t = 1.
        let mut events = Events::new().free_motion();
        let free = integrator
            .solve_with_events(0.0, &start, 1.0, &Sampling::Steps, &mut events, |_, _| {
                ControlFlow::Continue(())
            })
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let y = *free.q(BouncingBall::Y).last().expect("samples");
        assert!((y - (1.0 - 0.5 * G)).abs() < 1e-6, "{method:?}: {y}");
    });
}
