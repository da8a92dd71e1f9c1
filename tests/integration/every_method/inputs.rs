//! Inputs through every integrator: set between steps (by hand, by `solve_sampled`), refused
//! on a model held shared, and set within the steps by a drive, with stops where they jump
//! (every method). References: the forced spring `m ẍ = −k x + u` solved
//! piecewise in closed form for an input held constant over each interval.

use dirac::prelude::*;
use dirac::{Drive, State};

use super::{Fineness, Method};
use crate::zoo::ForcedSpring;

const M: f64 = 1.0;
const K: f64 = 4.0;

/// The spring's position and velocity after `s` from `(x, v)` under the constant force `u`.
fn held(x: f64, v: f64, u: f64, s: f64) -> (f64, f64) {
    let w = (K / M).sqrt();
    let rest = u / K;
    let (c, sn) = ((w * s).cos(), (w * s).sin());
    (rest + (x - rest) * c + v / w * sn, -(x - rest) * w * sn + v * c)
}

fn released(x0: f64) -> State<ForcedSpring> {
    let mut start = State::<ForcedSpring>::zeros();
    start.set_q(ForcedSpring::X, x0);
    start
}

/// Accuracy of each method at the suites' settings: the adaptive methods hold their
/// tolerance; the variational integrator is second order in its step.
fn tolerance(method: Method) -> f64 {
    if method == Method::Variational { 1e-4 } else { 1e-7 }
}

/// A sampled controller `u_k = −g x(t_k)`, held for a period: the solution against the
/// closed form chained over the periods.
#[test]
fn a_sampled_controller_is_held_between_samples() {
    let (x0, gain, period, t_end) = (0.5, 3.0, 0.25, 5.0);
    let (mut x, mut v) = (x0, 0.0);
    let mut t = 0.0;
    while t < t_end - 1e-12 {
        (x, v) = held(x, v, -gain * x, period);
        t += period;
    }
    let mut spring = ForcedSpring { m: M, k: K, f: 0.0 };
    each_integrator!(&mut spring, Fineness::new(1e-11, 1e-12, 1e-3), |method, integrator| {
        let solution = integrator
            .solve_sampled(0.0, &released(x0), t_end, period, &Sampling::Times(vec![t_end]), |_, s, model| {
                model.f = -gain * s.q(ForcedSpring::X);
            })
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let end = solution.last().expect("a sample at the end");
        assert!(
            (end.q(ForcedSpring::X) - x).abs() < tolerance(method),
            "{method:?}: x = {}, not {x}",
            end.q(ForcedSpring::X)
        );
        assert!(
            (end.v(ForcedSpring::X) - v).abs() < 10.0 * tolerance(method),
            "{method:?}: v = {}, not {v}",
            end.v(ForcedSpring::X)
        );
    });
}

/// An input set by hand between steps (`set_input`, which restarts the integrator), step by
/// step through the trait: the force switches on at the first step end past `t = 1`.
#[test]
fn an_input_set_between_steps_acts_from_there() {
    let (x0, force, t_end) = (0.5, 1.5, 3.0);
    let mut spring = ForcedSpring { m: M, k: K, f: 0.0 };
    each_integrator!(&mut spring, Fineness::new(1e-11, 1e-12, 1e-3), |method, integrator| {
        // The model is shared by the three runs: each starts from no force.
        integrator.model_mut().expect("held exclusively").f = 0.0;
        integrator.start(0.0, &released(x0), t_end).expect("starts");
        while integrator.t() < 1.0 {
            integrator.step().unwrap_or_else(|error| panic!("{method:?}: {error}"));
        }
        let t1 = integrator.t();
        let (x1, v1) = held(x0, 0.0, 0.0, t1);
        integrator.set_input(ForcedSpring::F, force).expect("an exclusive model");
        while !integrator.finished() {
            integrator.step().unwrap_or_else(|error| panic!("{method:?}: {error}"));
        }
        let (x, _) = held(x1, v1, force, t_end - t1);
        let reached = integrator.state().q(ForcedSpring::X);
        assert!((reached - x).abs() < tolerance(method), "{method:?}: x = {reached}, not {x}");
        assert_eq!(integrator.model().f, force, "{method:?}");
    });
}

/// An integrator built on `&model` reads the model and may not change it: a typed error, the
/// model untouched.
#[test]
fn a_shared_model_refuses_changes() {
    let spring = ForcedSpring { m: M, k: K, f: 0.0 };
    each_integrator!(&spring, Fineness::new(1e-8, 1e-10, 1e-2), |method, integrator| {
        integrator.start(0.0, &released(0.5), 1.0).expect("starts");
        let error = integrator.set_input(ForcedSpring::F, 2.0).err();
        assert!(matches!(error, Some(SimError::SharedModel { t: 0.0 })), "{method:?}: {error:?}");
        assert_eq!(integrator.model().f, 0.0, "{method:?}");
    });
}

/// An input set within the steps from time, `u = a sin(Ω t)`, in each method, against the
/// closed form of the driven spring, `x = x0 cos ωt + a/(m(ω² − Ω²)) (sin Ωt − (Ω/ω) sin ωt)`.
/// Measured at t = 4: Radau 3.7e-12, Explicit 6e-13, the variational integrator (h = 1e-3,
/// the force at each step's midpoint) 3.7e-7.
#[test]
fn inputs_within_the_steps_are_driven_in_every_method() {
    let (x0, a, big_omega, t_end) = (0.5, 0.8, 1.3, 4.0);
    let w = (K / M).sqrt();
    let exact = x0 * (w * t_end).cos()
        + a / (M * (w * w - big_omega * big_omega))
            * ((big_omega * t_end).sin() - big_omega / w * (w * t_end).sin());
    let mut source =
        |t: f64, _: &State<ForcedSpring>, model: &mut ForcedSpring| model.f = a * (big_omega * t).sin();
    let mut spring = ForcedSpring { m: M, k: K, f: 0.0 };
    each_integrator!(&mut spring, Fineness::new(1e-11, 1e-12, 1e-3), |method, integrator| {
        Drive::drive(&mut integrator, &mut source).unwrap_or_else(|e| panic!("{method:?}: {e}"));
        let solution = integrator
            .solve(0.0, &released(x0), t_end, &Sampling::Times(vec![t_end]))
            .unwrap_or_else(|e| panic!("{method:?}: {e}"));
        let x = solution.last().expect("a sample").q(ForcedSpring::X);
        let bound = if method == Method::Variational { 1e-6 } else { 1e-8 };
        assert!((x - exact).abs() < bound, "{method:?}: x = {x}, not {exact}");
    });
}

/// A drive asked of an integrator that holds its model shared: every method refuses it as it
/// refuses any change (the drive sets the model); nothing runs.
#[test]
fn a_drive_on_a_shared_model_is_refused() {
    let mut source = |_: f64, _: &State<ForcedSpring>, model: &mut ForcedSpring| model.f = 1.0;
    let spring = ForcedSpring { m: M, k: K, f: 0.0 };
    each_integrator!(&spring, Fineness::new(1e-8, 1e-10, 1e-2), |method, integrator| {
        let error = Drive::drive(&mut integrator, &mut source).err();
        assert!(matches!(error, Some(SimError::SharedModel { .. })), "{method:?}: {error:?}");
    });
    assert_eq!(spring.f, 0.0);
}

/// The stop tests' held force, 1, −2 and 0.5 from t = 0, 0.3 and 0.6, with the spring released
/// at x = 0.5: the table, the state at 0.6 and the position at 1, chained in closed form.
fn held_table() -> (dirac::sources::Table, (f64, f64), f64) {
    let table =
        dirac::sources::Table::new(vec![0.0, 0.3, 0.6], vec![1.0, -2.0, 0.5], dirac::sources::Hold::Zero)
            .expect("a valid table");
    let (x1, v1) = held(0.5, 0.0, 1.0, 0.3);
    let (x2, v2) = held(x1, v1, -2.0, 0.3);
    (table, (x2, v2), held(x2, v2, 0.5, 0.4).0)
}

/// Stops given unsorted and repeated are sorted and kept once; a stop that is not finite is
/// refused by name. A force held from a table jumps at the stops, which every method ends a
/// step at; the spring against the closed form chained over the held intervals.
#[test]
fn stops_are_sorted_and_checked() {
    let (table, _, x_end) = held_table();
    let mut source = |t: f64, _: &State<ForcedSpring>, model: &mut ForcedSpring| model.f = table.at(t);
    let mut spring = ForcedSpring { m: M, k: K, f: 0.0 };
    each_integrator!(&mut spring, Fineness::new(1e-11, 1e-12, 1e-3), |method, integrator| {
        let error = integrator.stop_at(&[0.2, f64::NAN]).expect_err("not finite");
        assert!(matches!(&error, SimError::InvalidOption { what: "stop_at", .. }), "{method:?}: {error}");
        integrator.drive(&mut source).expect("an exclusive model");
        integrator.stop_at(&[0.6, 0.3, 0.3, 0.6]).expect("finite");
        let solution = integrator.solve(0.0, &released(0.5), 1.0, &Sampling::Steps).expect("integrates");
        let times = solution.t();
        for stop in [0.3, 0.6] {
            assert_eq!(times.iter().filter(|&&t| t == stop).count(), 1, "{method:?}: {stop} in {times:?}");
        }
        let x = solution.last().expect("a sample").q(ForcedSpring::X);
        assert!((x - x_end).abs() < tolerance(method), "{method:?}: x = {x}, not {x_end}");
    });
}

/// Stops hold in the solves built on the steps: a sampled solve (its controller setting
/// nothing, so the drive alone sets the force) and a solve with an event located where the
/// spring crosses zero, after the last stop. Each against the closed form chained over the held
/// intervals, and each with a step ending at every stop.
#[test]
fn stops_hold_in_sampled_and_event_solves() {
    use dirac::{Crossing, Events};
    use std::ops::ControlFlow;
    let (table, (x2, v2), x_end) = held_table();
    let mut source = |t: f64, _: &State<ForcedSpring>, model: &mut ForcedSpring| model.f = table.at(t);
    let mut spring = ForcedSpring { m: M, k: K, f: 0.0 };
    // The spring crosses zero once, in the last interval (x(0.6) > 0 > x(1)): bisected on the
    // closed form there.
    let after = |t: f64| held(x2, v2, 0.5, t - 0.6).0;
    assert!(x2 > 0.0 && after(1.0) < 0.0);
    let (mut lo, mut hi) = (0.6, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if after(mid) > 0.0 { lo = mid } else { hi = mid }
    }
    let crossing = 0.5 * (lo + hi);
    each_integrator!(&mut spring, Fineness::new(1e-11, 1e-12, 1e-3), |method, integrator| {
        integrator.drive(&mut source).expect("an exclusive model");
        integrator.stop_at(table.times()).expect("finite");
        let sampled = integrator
            .solve_sampled(0.0, &released(0.5), 1.0, 0.25, &Sampling::Steps, |_, _, _| {})
            .unwrap_or_else(|e| panic!("{method:?}, sampled: {e}"));
        let mut events =
            Events::new().on("zero", Crossing::Falling, |_, s: &State<ForcedSpring>, _| s.q(ForcedSpring::X));
        let located = integrator
            .solve_with_events(0.0, &released(0.5), 1.0, &Sampling::Steps, &mut events, |_, _| {
                ControlFlow::Continue(())
            })
            .unwrap_or_else(|e| panic!("{method:?}, events: {e}"));
        let crossings = located.event_times("zero").expect("the event");
        assert_eq!(crossings.len(), 1, "{method:?}: {crossings:?}");
        assert!(
            (crossings[0] - crossing).abs() < tolerance(method),
            "{method:?}: {crossings:?}, not {crossing}"
        );
        for (what, solution) in [("sampled", &sampled), ("events", &located)] {
            for stop in [0.3, 0.6] {
                assert!(solution.t().contains(&stop), "{method:?}, {what}: no step ends at {stop}");
            }
            let x = solution.last().expect("a sample").q(ForcedSpring::X);
            assert!((x - x_end).abs() < tolerance(method), "{method:?}, {what}: x = {x}, not {x_end}");
        }
    });
}

/// A spring with a damper, pushed by the input force `f`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), input(f))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x, dissipation = 0.5 * c * v * v, force(x) = f)]
pub struct DampedForced {
    pub m: f64,
    pub k: f64,
    pub c: f64,
    pub f: f64,
}

/// Checks a solution's input, power and dissipated power columns sample by sample against the
/// force `force(k)` the test set: the sources' power is `f v`, the damper's `c v²`; and the same
/// values in its CSV, under the names `in(f)`, `power` and `dissipated_power`.
fn inputs_and_powers_recorded(
    what: &str,
    solution: &Solution<DampedForced, impl std::fmt::Debug>,
    c: f64,
    force: impl Fn(usize) -> f64,
) {
    let (u, v) = (solution.input(DampedForced::F), solution.v(DampedForced::X));
    assert_eq!(solution.column("in(f)"), Some(u), "{what}");
    for k in 0..solution.len() {
        assert_eq!(u[k], force(k), "{what}: the input at sample {k}, t = {}", solution.t()[k]);
        let (power, dissipated) = (solution.power()[k], solution.dissipated_power()[k]);
        assert!((power - u[k] * v[k]).abs() <= 1e-14 * (1.0 + power.abs()), "{what}: power {power} at {k}");
        let damper = c * v[k] * v[k];
        assert!(
            (dissipated - damper).abs() <= 1e-14 * (1.0 + damper),
            "{what}: {dissipated} against {damper}"
        );
    }
    let mut csv = Vec::new();
    solution.write_csv(&mut csv).expect("written");
    let csv = String::from_utf8(csv).expect("UTF-8");
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().expect("a header").split(',').collect();
    let column =
        |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("{what}: no {name}"));
    let (input, power, dissipated) = (column("in(f)"), column("power"), column("dissipated_power"));
    for (k, line) in lines.enumerate() {
        let row: Vec<f64> = line.split(',').map(|x| x.parse().expect("a number")).collect();
        assert_eq!(row[input], u[k], "{what}: CSV row {k}");
        assert_eq!(row[power], solution.power()[k], "{what}: CSV row {k}");
        assert_eq!(row[dissipated], solution.dissipated_power()[k], "{what}: CSV row {k}");
    }
}

/// The inputs a solution records are those that acted: held between steps, set by a sampled
/// controller (each sample in a period holds the value set at its start; the sample that ends
/// a period, recorded before the controller runs, the one before), or set within the steps by
/// a drive (read again at each sample's own time, not the last evaluation's), in every method.
#[test]
fn inputs_and_powers_are_recorded_by_every_driver_in_every_method() {
    let (c, gain, period, x0) = (0.4, 3.0, 0.25, 0.5);
    let mut model = DampedForced { m: M, k: K, c, f: 0.7 };
    let start = |model: &DampedForced| {
        let (q, v) = (VecQ::<DampedForced>::from([x0]), VecQ::<DampedForced>::zeros());
        consistent_state(model, 0.0, &q, &v, Consistency::default()).expect("consistent")
    };
    let begin = start(&model);
    each_integrator!(&mut model, Fineness::new(1e-10, 1e-12, 1e-3), |method, integrator| {
        let what = format!("{method:?}, held");
        // The previous method's controller left its last force in the model.
        integrator.model_mut().expect("an exclusive model").f = 0.7;
        let solution = integrator
            .solve(0.0, &begin, 1.0, &Sampling::Every(0.1))
            .unwrap_or_else(|error| panic!("{what}: {error}"));
        inputs_and_powers_recorded(&what, &solution, c, |_| 0.7);

        let what = format!("{method:?}, sampled");
        let solution = integrator
            .solve_sampled(0.0, &begin, 2.0, period, &Sampling::Every(period / 4.0), |_, s, model| {
                model.f = -gain * s.q(DampedForced::X);
            })
            .unwrap_or_else(|error| panic!("{what}: {error}"));
        let (t, x) = (solution.t(), solution.q(DampedForced::X));
        // The samples fall on the periods' starts every fourth one.
        inputs_and_powers_recorded(&what, &solution, c, |k| {
            let start = if k == 0 { 0 } else { 4 * ((k - 1) / 4) };
            assert!(
                (t[start] - period * (start / 4) as f64).abs() < 1e-12,
                "{what}: sample {start} at {}",
                t[start]
            );
            -gain * x[start]
        });
    });
    let (u0, w) = (0.6, 2.3);
    let mut source = |t: f64, _: &State<DampedForced>, model: &mut DampedForced| model.f = u0 * (w * t).sin();
    let mut source_explicit = source;
    let mut source_variational = source;
    let mut driven = model.clone();
    let fineness = Fineness::new(1e-10, 1e-12, 1e-3);
    let mut radau = Radau::new(&mut driven, fineness.radau()).expect("valid options");
    radau.drive(&mut source).expect("an exclusive model");
    let solution = radau.solve(0.0, &begin, 2.0, &Sampling::Every(0.05)).expect("integrates");
    let t = solution.t().to_vec();
    inputs_and_powers_recorded("Radau, driven", &solution, c, |k| u0 * (w * t[k]).sin());
    let mut explicit = Explicit::new(&mut driven, fineness.explicit()).expect("valid options");
    explicit.drive(&mut source_explicit).expect("an exclusive model");
    let solution = explicit.solve(0.0, &begin, 2.0, &Sampling::Every(0.05)).expect("integrates");
    let t = solution.t().to_vec();
    inputs_and_powers_recorded("Explicit, driven", &solution, c, |k| u0 * (w * t[k]).sin());
    let mut variational =
        Variational::new(&mut driven, fineness.h, fineness.variational()).expect("valid options");
    variational.drive(&mut source_variational).expect("an exclusive model");
    let solution = variational.solve(0.0, &begin, 2.0, &Sampling::Every(0.05)).expect("integrates");
    let t = solution.t().to_vec();
    inputs_and_powers_recorded("Variational, driven", &solution, c, |k| u0 * (w * t[k]).sin());

    // Through located events (the spring passing x = 0) and with sensitivities: a drive's
    // samples are read again at their own times there too, events' samples among them.
    let (mut source_events, mut source_sensitivities) = (source, source);
    let mut radau = Radau::new(&mut driven, fineness.radau()).expect("valid options");
    radau.drive(&mut source_events).expect("an exclusive model");
    let mut events =
        Events::new().on("x_zero", Crossing::Either, |_, s: &State<DampedForced>, _| s.q(DampedForced::X));
    let solution = radau
        .solve_with_events(0.0, &begin, 2.0, &Sampling::Every(0.05), &mut events, |_, _| {
            std::ops::ControlFlow::Continue(())
        })
        .expect("integrates");
    assert!(!solution.event_times("x_zero").expect("an event of that name").is_empty());
    let t = solution.t().to_vec();
    inputs_and_powers_recorded("Radau, driven, with events", &solution, c, |k| u0 * (w * t[k]).sin());
    let wrt = Sensitivities::new(&driven).parameter("k").expect("a parameter");
    let mut radau = Radau::new(&mut driven, fineness.radau())
        .and_then(|radau| radau.with_sensitivities(&wrt))
        .expect("valid options");
    radau.drive(&mut source_sensitivities).expect("an exclusive model");
    let solution =
        radau.solve_with_sensitivities(0.0, &begin, 2.0, &Sampling::Every(0.05)).expect("integrates");
    let t = solution.t().to_vec();
    inputs_and_powers_recorded("Radau, driven, with sensitivities", &solution, c, |k| u0 * (w * t[k]).sin());
}
