//! Non-smooth laws through every integrator. Non-smooth functions: their switching surfaces
//! are located as events and the integration restarts there (reference: the same closed loop
//! integrated by a classical Runge-Kutta method written here, with 2·10⁵ steps per time unit,
//! its error below 1e-9 here, and the switch time found by bisection on its steps).
//! Set-valued laws (Coulomb friction with stiction, an ideal diode): modes held in the model's
//! fields, in each of which the motion is smooth, switched by the events' action (references:
//! closed forms).

use std::f64::consts::PI;
use std::ops::ControlFlow;

use dirac::EventContext;
use dirac::State;
use dirac::prelude::*;

use super::{Fineness, Method};
use crate::zoo::SaturatedServo;

/// The servo's acceleration: `clamp(kp (r − x) − kd v, −fmax, fmax) / m`.
fn acceleration(s: &SaturatedServo, x: f64, v: f64) -> f64 {
    (s.kp * (s.r - x) - s.kd * v).clamp(-s.fmax, s.fmax) / s.m
}

/// RK4 with step `h` from `(x, v)` over `span`, and the first time the controller leaves
/// saturation (its unclamped force falls below `fmax`).
fn reference(s: &SaturatedServo, span: f64, h: f64) -> ((f64, f64), f64) {
    let (mut x, mut v, mut t) = (0.0, 0.0, 0.0);
    let mut released = f64::NAN;
    let steps = (span / h).round() as usize;
    for _ in 0..steps {
        let f = |x: f64, v: f64| (v, acceleration(s, x, v));
        let (k1x, k1v) = f(x, v);
        let (k2x, k2v) = f(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
        let (k3x, k3v) = f(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
        let (k4x, k4v) = f(x + h * k3x, v + h * k3v);
        let (x1, v1) = (
            x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x),
            v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v),
        );
        let unclamped = |x: f64, v: f64| s.kp * (s.r - x) - s.kd * v - s.fmax;
        if released.is_nan() && unclamped(x1, v1) < 0.0 {
            // Linear between the steps' ends: O(h²), far below the tolerance here.
            let (a, b) = (unclamped(x, v), unclamped(x1, v1));
            released = t + h * a / (a - b);
        }
        (x, v, t) = (x1, v1, t + h);
    }
    ((x, v), released)
}

/// Saturated at `+fmax` from rest, the servo accelerates uniformly until its PD force falls
/// below the limit, then settles as a damped oscillator: positions against the reference, and
/// the switch located as the event `switch…` within the tolerance of the reference's time.
#[test]
fn a_saturated_controller_against_a_hand_integrated_reference() {
    let servo = SaturatedServo { m: 1.0, kp: 4.0, kd: 1.5, r: 1.0, fmax: 1.0 };
    let ((x_end, v_end), released) = reference(&servo, 4.0, 5e-6);
    assert!(released > 0.1 && released < 2.0, "the reference leaves saturation at {released}");
    let start = State::<SaturatedServo>::zeros();
    let fineness = Fineness::new(1e-10, 1e-12, 1e-4);
    each_integrator!(&servo, fineness, |method, integrator| {
        let solution = integrator.solve(0.0, &start, 4.0, &Sampling::Times(vec![4.0])).expect("integrates");
        let tolerance = if method == Method::Variational { 1e-6 } else { 1e-8 };
        let end = solution.last().expect("a sample");
        let (ex, ev) = ((end.q(SaturatedServo::X) - x_end).abs(), (end.v(SaturatedServo::X) - v_end).abs());
        assert!(ex < tolerance && ev < tolerance, "{method:?}: x off by {ex:e}, v by {ev:e}");
        let switches: Vec<f64> = solution.events().iter().map(|e| e.t).collect();
        assert!(!switches.is_empty(), "{method:?}: the switch is located");
        let first = switches[0];
        assert!((first - released).abs() < 1e-6, "{method:?}: switch at {first}, reference {released}");
        assert!(solution.event_name(&solution.events()[0]).starts_with("switch"));
    });
}

/// A mass on a belt moving at `vb`, held by a spring to the wall, with static and kinetic
/// Coulomb friction (`μs N`, `μk N`), its modes held in fields and switched by the events'
/// action. Slipping (`stuck = 0`), the friction is `−μk N side`, where `side` is the sign of
/// `v − vb`, held over the slip: each mode is smooth, so every integrator steps it at its
/// order, and the slip ends at the event `sticks`, where the relative velocity reaches zero.
/// Stuck (`stuck = 1`), the row `stick` holds `v = vb` and its multiplier is the friction
/// force, within `±μs N`; the slack coordinate `s` carries the row while it slips. The event
/// `release` is where the stick force reaches its bound.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v, s => vs))]
#[dirac(lagrangian = 0.5 * m * v * v + 0.5 * vs * vs - 0.5 * k * x * x)]
#[dirac(constraint(stick) = stuck * (v - vb) + (1.0 - stuck) * vs)]
#[dirac(force(x) = -(1.0 - stuck) * mu_k * n * side)]
#[dirac(event(sticks, falling) = (1.0 - stuck) * side * (v - vb) + stuck)]
#[dirac(event(release, falling) = stuck * (mu_s * n - stick.abs()) + (1.0 - stuck))]
pub struct BeltOscillator {
    pub m: f64,
    pub k: f64,
    pub vb: f64,
    pub n: f64,
    pub mu_s: f64,
    pub mu_k: f64,
    pub stuck: f64,
    pub side: f64,
}

/// What the stick-slip run saw: the times the mass was released and stuck again.
#[derive(Default, Debug)]
struct Phases {
    released: Vec<f64>,
    stuck: Vec<f64>,
}

/// The friction law as the events' action: a release frees the mass on the side the stick
/// force pushed it; where the relative velocity reaches zero, the mass sticks if the force
/// that holds it on the belt (the spring's pull, `k x`) is within `μs N`, and slips on the
/// other side if not.
fn friction_law<I: Integrator<BeltOscillator>>(
    phases: &mut Phases,
    event: &Event,
    at: &mut EventContext<'_, BeltOscillator, I>,
) -> ControlFlow<()> {
    let state = at.state();
    let (pull, force) = (at.model().k * state.q(BeltOscillator::X), state.lambda(BeltOscillator::STICK));
    let model = at.model_mut().expect("held exclusively");
    let bound = model.mu_s * model.n;
    if model.stuck == 1.0 && event.index == 1 {
        // Stuck, the row's force on `x` is the friction; slipping, it keeps pushing that way.
        model.stuck = 0.0;
        model.side = -force.signum();
        phases.released.push(event.t);
    } else if model.stuck == 0.0 && event.index == 0 {
        // Strictly within the bound: at a release it is at the bound, and slips on.
        if pull.abs() < bound * (1.0 - 1e-6) {
            model.stuck = 1.0;
            phases.stuck.push(event.t);
            // The row now holds `v = vb`, which the located state meets to the tolerance: the
            // restart projects it there.
            at.state_mut();
        } else {
            model.side = -model.side;
        }
    }
    ControlFlow::Continue(())
}

/// Stick-slip from `x = 0` stuck on the belt, with each integrator. Closed form (the slip phase
/// is a harmonic oscillation about `x_e = μk N/k` from `x_e + d`, `d = (μs − μk) N/k`, at speed
/// `vb`): the first stick lasts `μs N/(k vb)`; each slip `(π + 2φ)/ω` with `ω = √(k/m)`,
/// `φ = atan(vb/(ω d))`, and ends at `v = vb`, `x = x_e − d`, where the mass sticks again
/// (`|k x| ≤ μs N`) for `2d/vb`. Checked on the phase times, on the friction force during
/// stick, and on the steps, which stay few while stuck whatever the tolerance.
#[test]
fn stick_slip_on_a_belt_against_its_closed_form() {
    let (m, k, vb, n, mu_s, mu_k): (f64, f64, f64, f64, f64, f64) = (1.0, 4.0, 0.5, 9.81, 0.4, 0.25);
    let omega = (k / m).sqrt();
    let d = (mu_s - mu_k) * n / k;
    let phi = (vb / (omega * d)).atan();
    let (first_stick, slip, stick) = (mu_s * n / (k * vb), (PI + 2.0 * phi) / omega, 2.0 * d / vb);
    // Release times: first_stick, then every slip + stick.
    let releases: Vec<f64> = (0..3).map(|j| first_stick + f64::from(j) * (slip + stick)).collect();
    let sticks: Vec<f64> = releases.iter().map(|r| r + slip).collect();
    let t_end = releases[2] + 0.5 * slip;
    let mut belt = BeltOscillator { m, k, vb, n, mu_s, mu_k, stuck: 1.0, side: 1.0 };
    for (tolerance, h) in [(1e-6, 2e-3), (1e-10, 2e-4)] {
        let mut steps = Vec::new();
        each_integrator!(&mut belt, Fineness::new(tolerance, 1e-2 * tolerance, h), |method, integrator| {
            *integrator.model_mut().expect("held exclusively") =
                BeltOscillator { m, k, vb, n, mu_s, mu_k, stuck: 1.0, side: 1.0 };
            let mut v0 = VecQ::<BeltOscillator>::zeros();
            v0[0] = vb;
            let zero = VecQ::<BeltOscillator>::zeros();
            let start = consistent_state(integrator.model(), 0.0, &zero, &v0, Consistency::default())
                .expect("stuck on the belt");
            let mut events = Events::new().declared();
            let mut phases = Phases::default();
            let solution = integrator
                .solve_with_events(0.0, &start, t_end, &Sampling::Steps, &mut events, |event, at| {
                    friction_law(&mut phases, event, at)
                })
                .expect("integrates");
            let Phases { released, stuck } = &phases;
            assert_eq!(released.len(), 3, "{method:?}: releases at {released:?}, closed form {releases:?}");
            assert_eq!(stuck.len(), 2, "{method:?}: sticks at {stuck:?}, closed form {sticks:?}");
            // Within the tolerance (the adaptive methods), within the step's second-order error
            // (the variational one: ω²h²/24 relative on the slip's phase, and the event
            // located on a dense output of its order).
            let bound = match method {
                Method::Variational => 0.2 * h * h * omega * omega * slip,
                _ => 30.0 * tolerance,
            };
            for (got, want) in released.iter().zip(&releases).chain(stuck.iter().zip(&sticks)) {
                assert!(
                    (got - want).abs() < bound,
                    "{method:?}: {released:?} {stuck:?} against {releases:?} {sticks:?}"
                );
            }
            // While stuck, the friction force (the multiplier of `stick`) is within ±μs N and
            // the mass moves with the belt.
            let lambda = solution.lambda(BeltOscillator::STICK);
            let mut stick_steps = 0;
            for (i, &t) in solution.t().iter().enumerate() {
                let stuck_now = t < releases[0] - 1e-3
                    || sticks.iter().zip(&releases[1..]).any(|(s, r)| t > s + 1e-3 && t < r - 1e-3);
                if stuck_now {
                    stick_steps += 1;
                    assert!(lambda[i].abs() <= mu_s * n * (1.0 + 1e-9), "{method:?} at {t}: {}", lambda[i]);
                    assert!(
                        (solution.v(BeltOscillator::X)[i] - vb).abs() < 1e-8,
                        "{method:?}: sticks at {t}"
                    );
                }
            }
            steps.push((method, solution.len(), stick_steps));
        });
        // No chattering: stuck, the motion is the belt's, a few steps whatever the tolerance
        // (the variational method's are its fixed steps); the adaptive methods' steps of the
        // whole run grow with the tolerance as a smooth motion's do, not without bound.
        for &(method, all, stuck) in &steps {
            match method {
                Method::Variational => assert!(all < (2.0 * t_end / h) as usize, "{steps:?}"),
                _ => assert!(stuck < 40 && all < 3000, "{steps:?}"),
            }
        }
    }
}

/// A friction coefficient of NaN is refused before anything is evaluated, by name, by the
/// consistent initialisation and by every integrator's start.
#[test]
fn a_nan_friction_coefficient_is_a_typed_error() {
    let belt =
        BeltOscillator { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: f64::NAN, stuck: 0.0, side: 1.0 };
    let zero = VecQ::<BeltOscillator>::zeros();
    let named = |error: SimError| {
        let text = error.to_string();
        assert!(text.contains("mu_k"), "{text}");
    };
    named(consistent_state(&belt, 0.0, &zero, &zero, Consistency::default()).expect_err("NaN"));
    let start = State::<BeltOscillator>::zeros();
    each_integrator!(&belt, Fineness::new(1e-8, 1e-10, 1e-3), |method, integrator| {
        let result = integrator.solve(0.0, &start, 1.0, &Sampling::Steps);
        match result {
            Err(error) => named(error),
            Ok(_) => panic!("{method:?}: a NaN coefficient integrated"),
        }
    });
}

/// A half-wave rectifier in node-flux coordinates (each node's velocity is its voltage): a
/// source `u = U sin ωt` drives node `a` (the row `source`), an ideal diode from `a` to the
/// output node `o`, and there a capacitor `C` (its energy `½ C vo²` is kinetic in these
/// coordinates) in parallel with a resistor `r` (the Rayleigh function `½ vo²/r`).
///
/// The ideal diode is the complementarity `g = vo − va ≥ 0` (reverse voltage), `i ≥ 0`
/// (forward current), `g i = 0`, with its mode held in `on` and switched by the events'
/// action: conducting, the row `diode` holds `g = 0` and its multiplier is the current `i`;
/// blocking, it holds the slack `s` and the diode carries no current. It blocks where the
/// current falls to zero (`blocks`), and conducts again where the reverse voltage does
/// (`conducts`).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(a => va, o => vo, s => vs))]
#[dirac(lagrangian = 0.5 * c * vo * vo + 0.5 * vs * vs)]
#[dirac(dissipation = 0.5 * vo * vo / r)]
#[dirac(constraint(source) = va - u * (w * t).sin())]
#[dirac(constraint(diode) = on * (vo - va) + (1.0 - on) * vs)]
#[dirac(event(blocks, falling) = on * diode + (1.0 - on))]
#[dirac(event(conducts, falling) = (1.0 - on) * (vo - va) + on)]
pub struct Rectifier {
    pub u: f64,
    pub w: f64,
    pub c: f64,
    pub r: f64,
    pub on: f64,
}

/// The rectifier's conduction intervals in closed form. Conducting from `t = 0` (where the
/// source starts to rise), the output follows the source, `vo = U sin ωt`, and the diode's
/// current `i = C U ω cos ωt + U sin ωt / r` falls to zero at `ωt_off = π − atan(ωrC)`.
/// Blocking, the capacitor discharges, `vo = U sin(ωt_off) e^{−(t − t_off)/rC}`, until the
/// rising source meets it again at `t_on` (bisection on the closed-form difference within
/// the first quarter of the next period). From there the diode conducts until
/// `t_off + 2π/ω`: every period repeats the first's `[t_on, t_off]`.
fn rectifier_intervals(rectifier: &Rectifier, periods: usize) -> Vec<(f64, f64)> {
    let Rectifier { u, w, c, r, .. } = *rectifier;
    let period = 2.0 * PI / w;
    let t_off = (PI - (w * r * c).atan()) / w;
    let held = u * (w * t_off).sin();
    let gap = |t: f64| u * (w * t).sin() - held * (-(t - t_off) / (r * c)).exp();
    let (mut lo, mut hi) = (period, period + 0.25 * period);
    assert!(gap(lo) < 0.0 && gap(hi) > 0.0, "the source meets the output in the first quarter");
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if gap(mid) < 0.0 { lo = mid } else { hi = mid }
    }
    let t_on = 0.5 * (lo + hi) - period;
    (0..periods)
        .map(|j| {
            let shift = period * j as f64;
            (if j == 0 { 0.0 } else { t_on + shift }, t_off + shift)
        })
        .collect()
}

/// Three periods of the rectifier with each integrator, from rest with the diode conducting:
/// the conduction intervals against the closed form, the current never negative while it
/// conducts, the reverse voltage never negative while it blocks, and the output voltage
/// against the closed form at the end.
#[test]
fn a_half_wave_rectifier_against_its_closed_form() {
    let model = Rectifier { u: 1.0, w: 1.0, c: 2.0, r: 1.0, on: 1.0 };
    let intervals = rectifier_intervals(&model, 3);
    let t_end = intervals[2].1 + 1.0;
    let mut rectifier = model.clone();
    for (tolerance, h) in [(1e-6, 2e-3), (1e-10, 2e-4)] {
        each_integrator!(
            &mut rectifier,
            Fineness::new(tolerance, 1e-2 * tolerance, h),
            |method, integrator| {
                *integrator.model_mut().expect("held exclusively") = model.clone();
                let zero = VecQ::<Rectifier>::zeros();
                let start = consistent_state(integrator.model(), 0.0, &zero, &zero, Consistency::default())
                    .expect("at rest, conducting");
                let mut events = Events::new().declared();
                let (mut on, mut off) = (vec![0.0], Vec::new());
                let solution = integrator
                    .solve_with_events(0.0, &start, t_end, &Sampling::Steps, &mut events, |event, at| {
                        let model = at.model_mut().expect("held exclusively");
                        match (model.on == 1.0, event.index) {
                            (true, 0) => {
                                model.on = 0.0;
                                off.push(event.t);
                                // The row now holds the slack at rest, which the located state
                                // meets to the tolerance: the restart projects it there.
                                at.state_mut();
                            }
                            (false, 1) => {
                                model.on = 1.0;
                                on.push(event.t);
                                // The row now holds `vo = va`, which the located state meets to the
                                // tolerance: the restart projects it there.
                                at.state_mut();
                            }
                            _ => {}
                        }
                        ControlFlow::Continue(())
                    })
                    .unwrap_or_else(|e| panic!("{method:?}: {e}"));
                assert_eq!(on.len(), 3, "{method:?}: conducts from {on:?}, closed form {intervals:?}");
                assert_eq!(off.len(), 3, "{method:?}: blocks at {off:?}, closed form {intervals:?}");
                // The adaptive methods within the tolerance; the variational one within its
                // second-order error (measured 0.02 h² and 0.017 h² at both steps). Blocking is a
                // zero of the diode's current, a multiplier: Radau's multipliers of a velocity row
                // are algebraic variables of index two, whose dense output is of the stage order,
                // not the step's (measured 6.8e-6 at rtol 1e-6, 2.0e-8 at 1e-10).
                let (bound_on, bound_off) = match method {
                    Method::Variational => (0.1 * h * h, 0.1 * h * h),
                    Method::Radau => (100.0 * tolerance, 0.1 * tolerance.powf(0.6)),
                    Method::Explicit => (100.0 * tolerance, 100.0 * tolerance),
                };
                for (j, &(t_on, t_off)) in intervals.iter().enumerate() {
                    assert!(
                        (on[j] - t_on).abs() < bound_on && (off[j] - t_off).abs() < bound_off,
                        "{method:?}: [{on:?}, {off:?}] against {intervals:?}"
                    );
                }
                // Complementarity along the run: the current while it conducts and the reverse
                // voltage while it blocks are never negative.
                let (current, g) = (solution.lambda(Rectifier::DIODE), solution.v(Rectifier::O));
                for (i, &t) in solution.t().iter().enumerate() {
                    let conducting = intervals.iter().any(|&(a, b)| t > a + 1e-3 && t < b - 1e-3);
                    let blocking = intervals.windows(2).any(|p| t > p[0].1 + 1e-3 && t < p[1].0 - 1e-3);
                    let source = model.u * (model.w * t).sin();
                    if conducting {
                        assert!(current[i] > -1e-8, "{method:?} at {t}: current {}", current[i]);
                        assert!((g[i] - source).abs() < 1e-8, "{method:?} at {t}: vo {} u {source}", g[i]);
                    }
                    if blocking {
                        assert!(
                            g[i] - source > -1e-8,
                            "{method:?} at {t}: reverse voltage {}",
                            g[i] - source
                        );
                    }
                }
                // The end, one time unit into the third blocking interval: the capacitor's
                // discharge from the source's value at `t_off`.
                let (t_off, tau) = (intervals[2].1, model.r * model.c);
                let expected = model.u * (model.w * t_off).sin() * (-(t_end - t_off) / tau).exp();
                let end = solution.last().expect("a sample").v(Rectifier::O);
                assert!((end - expected).abs() < bound_off, "{method:?}: vo = {end}, closed form {expected}");
            }
        );
    }
}

/// An oscillator that grazes a stiff soft stop: the stop's force `−kw max(x − a, 0)` acts
/// beyond `x = a`, and the oscillation's amplitude reaches just past it, so that each
/// excursion into the stop is short against a step.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * v * v - 0.5 * x * x)]
#[dirac(force(x) = -kw * (x - a).max(0.0))]
pub struct GrazingStop {
    pub kw: f64,
    pub a: f64,
}

/// The grazing oscillator's period in closed form, started at `x = 0` with speed `A`: free,
/// `x = A sin t` reaches the stop at `t₁ = asin(a/A)` with speed `v₁ = √(A² − a²)`; in the
/// stop, `u = x − a kw/(1 + kw)` oscillates at `ω = √(1 + kw)` from `u₀ = a/(1 + kw)` and
/// leaves after `(π − 2ψ)/ω`, `tan ψ = ω u₀/v₁`; the free motion takes the rest of its
/// period but the `π − 2t₁` it would have spent beyond `a`.
fn grazing_period(stop: &GrazingStop, amplitude: f64) -> (f64, f64) {
    let GrazingStop { kw, a } = *stop;
    let t1 = (a / amplitude).asin();
    let v1 = (amplitude * amplitude - a * a).sqrt();
    let omega = (1.0 + kw).sqrt();
    let psi = (omega * a / (1.0 + kw) / v1).atan();
    let inside = (PI - 2.0 * psi) / omega;
    (2.0 * PI - (PI - 2.0 * t1) + inside, inside)
}

/// A switching surface crossed and crossed back within one step: each integrator, at a
/// tolerance whose steps (up to 0.25 here) are several times the excursion into the stop
/// (0.063), finds both crossings of every period (without sampling within the steps, Radau
/// found 16 of 20 with `kw = 10` and 10 with `kw = 1`, Explicit 18 and 4), and ends where the
/// closed form says: the motion is periodic, so after whole periods it is back at `x = 0`
/// with speed `A` (within the accumulated error of the tolerance, or the variational step's
/// phase error `h²/24` per unit time).
#[test]
fn a_surface_crossed_twice_within_a_step_is_found() {
    for kw in [10.0, 1.0] {
        let stop = GrazingStop { kw, a: 0.9995 };
        let amplitude = 1.0;
        let (period, inside) = grazing_period(&stop, amplitude);
        let periods = 10;
        let t_end = period * f64::from(periods);
        let mut start = State::<GrazingStop>::zeros();
        start.v[0] = amplitude;
        start.p[0] = amplitude;
        each_integrator!(&stop, Fineness::new(1e-6, 1e-8, 0.02), |method, integrator| {
            let solution = integrator
                .solve(0.0, &start, t_end, &Sampling::Steps)
                .unwrap_or_else(|e| panic!("{method:?}: {e}"));
            let longest = solution.t().windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
            if method != Method::Variational {
                assert!(longest > 2.0 * inside, "{method:?}: the steps ({longest}) straddle the excursion");
            }
            let crossings = solution.events().len();
            assert_eq!(crossings, 2 * periods as usize, "{method:?}, kw = {kw}");
            let end = solution.last().expect("a sample");
            let (x, v) = (end.q(GrazingStop::X), end.v(GrazingStop::X));
            // Measured: 1.8e-6 with Radau and Explicit (4.2e-4 and 2.3e-4 without sampling within
            // the steps), 1.19e-3 with the variational step, whose phase error over t_end is
            // t_end h²/24 = 1.05e-3.
            let bound = if method == Method::Variational { 1.5 * t_end * 0.02 * 0.02 / 24.0 } else { 1e-5 };
            assert!(x.abs() < bound && (v - amplitude).abs() < bound, "{method:?}: x = {x}, v = {v}");
        });
    }
}

/// Coulomb friction written as a plain non-smooth force, with no modes: `μ N sign(vb − v)`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(force(x) = mu * n * (vb - v).signum())]
pub struct PlainBelt {
    pub m: f64,
    pub k: f64,
    pub vb: f64,
    pub n: f64,
    pub mu: f64,
}

/// A sliding mode entered at `t = 0`: the mass starts on the belt's speed with the spring's
/// pull within the friction's bound, so that both sides of the sign push the motion back onto
/// `v = vb`. Written with a plain `signum`, no integrator can hold that motion (its steps
/// collapse, or its Newton iteration has no solution): each ends at once in
/// [`SimError::Sliding`] naming the surface and the time, not in a hang or a step-size error
/// that hides why. Started beyond the bound (`k x > μ N`), the mass leaves the surface and
/// every integrator goes on: the same start, crossed rather than slid along.
#[test]
fn a_sliding_mode_is_named_where_it_begins() {
    let belt = PlainBelt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu: 0.4 };
    for (x0, slides) in [(0.0, true), (0.5, true), (1.5, false)] {
        let mut start = State::<PlainBelt>::zeros();
        start.q[0] = x0;
        start.v[0] = belt.vb;
        start.p[0] = belt.m * belt.vb;
        each_integrator!(&belt, Fineness::new(1e-6, 1e-8, 1e-3).steps(100_000), |method, integrator| {
            let result = integrator.solve(0.0, &start, 1.0, &Sampling::Steps);
            match (slides, result) {
                (true, Err(SimError::Sliding { surface, condition, t, cause })) => {
                    assert_eq!((surface.as_str(), condition.as_str()), ("switch0", "vb - v"), "{method:?}");
                    assert!(t < 1e-3, "{method:?}: named at t = {t} ({cause})");
                }
                (false, Ok(solution)) => {
                    // Pulled back harder than friction holds: the mass leaves the belt's speed.
                    let end = solution.last().expect("a sample");
                    assert!(end.v(PlainBelt::X) < belt.vb - 0.1, "{method:?}: {}", end.v(PlainBelt::X));
                }
                (_, result) => panic!("{method:?} from x = {x0}: {:?}", result.map(|s| s.len())),
            }
        });
    }
    // Entered later: from rest, the belt drags the mass (`x = x_e (1 − cos ωt)` about
    // `x_e = μ N/k`) until it reaches the belt's speed, `x_e ω sin ωt = vb`, with the spring's
    // pull far within the bound: it would stick there, and each integrator names the surface
    // at that time.
    let (omega, xe) = ((belt.k / belt.m).sqrt(), belt.mu * belt.n / belt.k);
    let sticks = (belt.vb / (xe * omega)).asin() / omega;
    each_integrator!(&belt, Fineness::new(1e-8, 1e-10, 1e-4).steps(100_000), |method, integrator| {
        match integrator.solve(0.0, &State::<PlainBelt>::zeros(), 1.0, &Sampling::Steps) {
            Err(SimError::Sliding { surface, t, .. }) => {
                assert_eq!(surface, "switch0", "{method:?}");
                assert!((t - sticks).abs() < 1e-3, "{method:?}: named at t = {t}, sticks at {sticks}");
            }
            result => panic!("{method:?}: {:?}", result.map(|s| s.len())),
        }
    });
}

/// The belt oscillator of [`BeltOscillator`] with its friction written as the law it is:
/// `friction(grip, kinetic = μk N, stiction = μs N) = v − vb`. The derive gives it the mode
/// coordinate `grip_mode`, the row `grip` (its multiplier the friction force while stuck) and
/// the events `grip_stops` and `grip_slips`, and a plain `solve` switches it.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(friction(grip, kinetic = mu_k * n, stiction = mu_s * n) = v - vb)]
pub struct Belt {
    pub m: f64,
    pub k: f64,
    pub vb: f64,
    pub n: f64,
    pub mu_s: f64,
    pub mu_k: f64,
}

/// A model with a law counts the law's mode among its coordinates: `vec_q` takes the ones
/// written in the model, and the start chooses the mode (a mass at rest under a moving belt
/// slips backwards relative to it: mode −1).
#[test]
fn a_law_models_vectors_take_the_coordinates_written_in_it() {
    let belt = Belt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 };
    let q = Belt::vec_q([0.3]);
    assert_eq!(q.as_slice(), [0.3, 0.0]);
    let start =
        consistent_state(&belt, 0.0, &q, &Belt::vec_q([0.0]), Consistency::default()).expect("consistent");
    assert_eq!((start.q[Belt::X.index()], start.q[Belt::GRIP_MODE.index()]), (0.3, -1.0));
}

/// Stick-slip with the friction law, by a plain `solve` with each integrator, from rest (the
/// belt moves, the mass does not: it starts slipping, and its mode is chosen so). Closed form:
/// slipping from rest, `x = x_e (1 − cos ωt)` about `x_e = μk N/k`, until `v = vb` at
/// `t₁ = asin(vb/(ω x_e))/ω`, where the spring's pull `k x` is within `μs N`, so it sticks,
/// and rides the belt until `k x = μs N`; from there the periodic stick-slip of
/// [`stick_slip_on_a_belt_against_its_closed_form`]. Checked as there: the event times, the
/// friction force within its bound while stuck, the mass on the belt's speed, the mode
/// coordinate, and the steps while stuck.
#[test]
fn the_friction_law_sticks_and_slips_by_itself() {
    let belt = Belt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 };
    let Belt { m, k, vb, n, mu_s, mu_k } = belt;
    let omega = (k / m).sqrt();
    let xe = mu_k * n / k;
    let t1 = (vb / (omega * xe)).asin() / omega;
    let x1 = xe * (1.0 - (omega * t1).cos());
    let first_release = t1 + (mu_s * n / k - x1) / vb;
    let d = (mu_s - mu_k) * n / k;
    let phi = (vb / (omega * d)).atan();
    let (slip, stick) = ((PI + 2.0 * phi) / omega, 2.0 * d / vb);
    let slips: Vec<f64> = (0..2).map(|j| first_release + f64::from(j) * (slip + stick)).collect();
    let stops = vec![t1, slips[0] + slip];
    let t_end = slips[1] + 0.5 * slip;
    let stuck =
        |t: f64| (t > t1 + 1e-3 && t < slips[0] - 1e-3) || (t > stops[1] + 1e-3 && t < slips[1] - 1e-3);
    let mut steps = Vec::new();
    for (tolerance, h) in [(1e-6, 2e-3), (1e-10, 2e-4)] {
        each_integrator!(&belt, Fineness::new(tolerance, 1e-2 * tolerance, h), |method, integrator| {
            let solution = integrator
                .solve(0.0, &State::<Belt>::zeros(), t_end, &Sampling::Steps)
                .unwrap_or_else(|e| panic!("{method:?}: {e}"));
            let times = |name: &str| -> Vec<f64> {
                solution.events().iter().filter(|e| solution.event_name(e) == name).map(|e| e.t).collect()
            };
            let (got_stops, got_slips) = (times("grip_stops"), times("grip_slips"));
            assert_eq!((got_stops.len(), got_slips.len()), (2, 2), "{method:?}: {got_stops:?} {got_slips:?}");
            // Measured at rtol 1e-10 (h = 2e-4): 1.6e-10 (Radau), 5e-12 (Explicit), 6.6e-9
            // (Variational, against its bound 1.2e-7).
            let bound = match method {
                Method::Variational => 0.2 * h * h * omega * omega * slip,
                _ => 30.0 * tolerance,
            };
            for (got, want) in got_stops.iter().zip(&stops).chain(got_slips.iter().zip(&slips)) {
                assert!(
                    (got - want).abs() < bound,
                    "{method:?}: {got_stops:?} {got_slips:?} against {stops:?} {slips:?}"
                );
            }
            let (lambda, v, mode) =
                (solution.lambda(Belt::GRIP), solution.v(Belt::X), solution.q(Belt::GRIP_MODE));
            let mut stuck_steps = 0;
            for (i, &t) in solution.t().iter().enumerate() {
                if stuck(t) {
                    stuck_steps += 1;
                    assert!(lambda[i].abs() <= mu_s * n * (1.0 + 1e-9), "{method:?} at {t}: {}", lambda[i]);
                    // The mode is 0 stuck; engaged, the slack's velocity is free and the mode
                    // drifts by the integration's error (1.1e-10 measured with Radau at 1e-10).
                    assert!(
                        (v[i] - vb).abs() < 1e-8 && mode[i].abs() < 1e-6,
                        "{method:?} at {t}: v = {}, mode {}",
                        v[i],
                        mode[i]
                    );
                } else if t < t1 - 1e-3 {
                    // Slower than the belt: slipping backwards relative to it.
                    assert!((mode[i] + 1.0).abs() < 1e-6, "{method:?} at {t}: mode {}", mode[i]);
                }
            }
            steps.push((method, solution.len(), stuck_steps));
        });
    }
    for &(method, all, stuck) in &steps {
        match method {
            Method::Variational => assert!(all < (2.0 * t_end / 2e-4) as usize, "{steps:?}"),
            _ => assert!(stuck < 40 && all < 3000, "{steps:?}"),
        }
    }
}

/// The rectifier of [`Rectifier`] with its diode written as the law it is, `diode(d) = vo − va`:
/// no slack, no mode field, no events of its own.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(a => va, o => vo))]
#[dirac(lagrangian = 0.5 * c * vo * vo)]
#[dirac(dissipation = 0.5 * vo * vo / r)]
#[dirac(constraint(source) = va - u * (w * t).sin())]
#[dirac(diode(d) = vo - va)]
pub struct HalfWave {
    pub u: f64,
    pub w: f64,
    pub c: f64,
    pub r: f64,
}

/// The ideal diode by a plain `solve` with each integrator, from rest: it starts conducting
/// (its reverse voltage is zero and the current the source drives into the capacitor,
/// `C U ω`, positive), and its conduction intervals, the complementarity along the run and the
/// output at the end are checked against the closed form of [`rectifier_intervals`], within
/// the bounds of [`a_half_wave_rectifier_against_its_closed_form`].
#[test]
fn the_diode_law_conducts_and_blocks_by_itself() {
    let model = HalfWave { u: 1.0, w: 1.0, c: 2.0, r: 1.0 };
    let intervals = rectifier_intervals(&Rectifier { u: 1.0, w: 1.0, c: 2.0, r: 1.0, on: 1.0 }, 3);
    let t_end = intervals[2].1 + 1.0;
    for (tolerance, h) in [(1e-6, 2e-3), (1e-10, 2e-4)] {
        each_integrator!(&model, Fineness::new(tolerance, 1e-2 * tolerance, h), |method, integrator| {
            let solution = integrator
                .solve(0.0, &State::<HalfWave>::zeros(), t_end, &Sampling::Steps)
                .unwrap_or_else(|e| panic!("{method:?}: {e}"));
            let times = |name: &str| -> Vec<f64> {
                solution.events().iter().filter(|e| solution.event_name(e) == name).map(|e| e.t).collect()
            };
            let (on, off) = (times("d_conducts"), times("d_blocks"));
            assert_eq!((on.len(), off.len()), (2, 3), "{method:?}: {on:?} {off:?} against {intervals:?}");
            let (bound_on, bound_off) = match method {
                Method::Variational => (0.1 * h * h, 0.1 * h * h),
                Method::Radau => (100.0 * tolerance, 0.1 * tolerance.powf(0.6)),
                Method::Explicit => (100.0 * tolerance, 100.0 * tolerance),
            };
            for (j, &(t_on, t_off)) in intervals.iter().enumerate() {
                assert!((off[j] - t_off).abs() < bound_off, "{method:?}: {off:?} against {intervals:?}");
                if j > 0 {
                    assert!((on[j - 1] - t_on).abs() < bound_on, "{method:?}: {on:?} against {intervals:?}");
                }
            }
            let (current, vo, mode) =
                (solution.lambda(HalfWave::D), solution.v(HalfWave::O), solution.q(HalfWave::D_MODE));
            for (i, &t) in solution.t().iter().enumerate() {
                let conducting = intervals.iter().any(|&(a, b)| t > a + 1e-3 && t < b - 1e-3);
                let blocking = intervals.windows(2).any(|p| t > p[0].1 + 1e-3 && t < p[1].0 - 1e-3);
                let source = model.u * (model.w * t).sin();
                if conducting {
                    assert!(
                        current[i] > -1e-8 && mode[i].abs() < 1e-6,
                        "{method:?} at {t}: current {}",
                        current[i]
                    );
                    assert!((vo[i] - source).abs() < 1e-8, "{method:?} at {t}: vo {} u {source}", vo[i]);
                }
                if blocking {
                    assert!(
                        vo[i] - source > -1e-8 && (mode[i] - 1.0).abs() < 1e-6,
                        "{method:?} at {t}: reverse {}",
                        vo[i] - source
                    );
                }
            }
            let (t_off, tau) = (intervals[2].1, model.r * model.c);
            let expected = model.u * (model.w * t_off).sin() * (-(t_end - t_off) / tau).exp();
            let end = solution.last().expect("a sample").v(HalfWave::O);
            assert!((end - expected).abs() < bound_off, "{method:?}: vo = {end}, closed form {expected}");
        });
    }
}

/// A capacitor `C` charged from a source `U` through an ideal switch and a resistor `r`, in
/// node-flux coordinates: the source holds node `a`, the switch joins `a` to `b` while
/// `cos ωt > 0`, the resistor joins `b` to the output `o`. Node `b` has no inertia: its voltage
/// is fixed by the resistor (equal to `vo` while the switch is open, no current flowing).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(a => va, b => vb, o => vo))]
#[dirac(lagrangian = 0.5 * c * vo * vo)]
#[dirac(dissipation = 0.5 * (vb - vo) * (vb - vo) / r)]
#[dirac(constraint(source) = va - u)]
#[dirac(switch(s, closed = (w * t).cos()) = va - vb)]
pub struct SwitchedCharge {
    pub u: f64,
    pub w: f64,
    pub c: f64,
    pub r: f64,
}

/// The ideal switch by a plain `solve` with each integrator, from an empty capacitor. Closed
/// form: closed on `[0, π/2ω)` and `(3π/2ω, 5π/2ω)`, the capacitor charges as
/// `U − (U − vo) e^{−τ/rC}`; open, it holds its voltage and the switch carries no current.
/// The switch's events at the control's zeros, the output at the end and the current while
/// open against it.
#[test]
fn the_switch_law_follows_its_control() {
    let model = SwitchedCharge { u: 1.0, w: 1.0, c: 1.0, r: 1.0 };
    let tau = model.r * model.c;
    let quarter = PI / 2.0 / model.w;
    let t_end = 6.0 * quarter;
    let expected = model.u * (1.0 - (-3.0 * quarter / tau).exp());
    for (tolerance, h) in [(1e-6, 2e-3), (1e-10, 2e-4)] {
        each_integrator!(&model, Fineness::new(tolerance, 1e-2 * tolerance, h), |method, integrator| {
            let zero = VecQ::<SwitchedCharge>::zeros();
            let start = consistent_state(integrator.model(), 0.0, &zero, &zero, Consistency::default())
                .expect("the source's voltage on the closed switch's far side");
            let solution = integrator
                .solve(0.0, &start, t_end, &Sampling::Steps)
                .unwrap_or_else(|e| panic!("{method:?}: {e}"));
            let times = |name: &str| -> Vec<f64> {
                solution.events().iter().filter(|e| solution.event_name(e) == name).map(|e| e.t).collect()
            };
            let (opens, closes) = (times("s_opens"), times("s_closes"));
            assert_eq!((opens.len(), closes.len()), (2, 1), "{method:?}: {opens:?} {closes:?}");
            let bound = if method == Method::Variational { 0.1 * h * h } else { 100.0 * tolerance };
            for (got, want) in opens.iter().chain(&closes).zip([quarter, 5.0 * quarter, 3.0 * quarter]) {
                assert!((got - want).abs() < bound, "{method:?}: {opens:?} {closes:?}");
            }
            let current = solution.lambda(SwitchedCharge::S);
            for (i, &t) in solution.t().iter().enumerate() {
                if (t > quarter + 1e-3 && t < 3.0 * quarter - 1e-3) || t > 5.0 * quarter + 1e-3 {
                    assert!(current[i].abs() < 1e-8, "{method:?} at {t}: {}", current[i]);
                }
            }
            let end = solution.last().expect("a sample").v(SwitchedCharge::O);
            let error = (end - expected).abs();
            assert!(error < 1e3 * bound, "{method:?}: vo = {end}, closed form {expected} (off by {error:e})");
        });
    }
}

/// The block of [`Belt`] alone, its position a port.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), port(x))]
#[dirac(lagrangian = 0.5 * m * v * v)]
#[dirac(friction(grip, kinetic = mu_k * n, stiction = mu_s * n) = v - vb)]
pub struct Block {
    pub m: f64,
    pub vb: f64,
    pub n: f64,
    pub mu_s: f64,
    pub mu_k: f64,
}

/// A spring to the wall, massless, its end a port.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(y => w), port(y))]
#[dirac(lagrangian = -0.5 * k * y * y)]
pub struct WallSpring {
    pub k: f64,
}

/// [`Belt`] as an interconnection of the block and the spring.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(block.x, spring.y))]
pub struct BlockOnSpring {
    pub block: Block,
    pub spring: WallSpring,
}

/// A law inside an interconnection is the composite's, by its dotted name: the block's
/// friction switches as [`Belt`]'s does (the same closed form for the first stick and the
/// first slip), with each integrator.
#[test]
fn a_law_inside_an_interconnection_switches_by_its_dotted_name() {
    let (m, k, vb, n, mu_s, mu_k): (f64, f64, f64, f64, f64, f64) = (1.0, 4.0, 0.5, 9.81, 0.4, 0.25);
    let composite = BlockOnSpring { block: Block { m, vb, n, mu_s, mu_k }, spring: WallSpring { k } };
    let omega = (k / m).sqrt();
    let xe = mu_k * n / k;
    let t1 = (vb / (omega * xe)).asin() / omega;
    let x1 = xe * (1.0 - (omega * t1).cos());
    let first_release = t1 + (mu_s * n / k - x1) / vb;
    let (tolerance, h) = (1e-10, 2e-4);
    each_integrator!(&composite, Fineness::new(tolerance, 1e-2 * tolerance, h), |method, integrator| {
        let zero = VecQ::<BlockOnSpring>::zeros();
        let start = consistent_state(integrator.model(), 0.0, &zero, &zero, Consistency::default())
            .expect("slipping from rest");
        let solution = integrator
            .solve(0.0, &start, first_release + 0.5, &Sampling::Steps)
            .unwrap_or_else(|e| panic!("{method:?}: {e}"));
        let named: Vec<(&str, f64)> =
            solution.events().iter().map(|e| (solution.event_name(e), e.t)).collect();
        assert_eq!(named.len(), 2, "{method:?}: {named:?}");
        let bound = if method == Method::Variational { 1e-6 } else { 30.0 * tolerance };
        assert!(named[0].0 == "block.grip_stops" && (named[0].1 - t1).abs() < bound, "{method:?}: {named:?}");
        assert!(
            named[1].0 == "block.grip_slips" && (named[1].1 - first_release).abs() < bound,
            "{method:?}: {named:?} against {t1}, {first_release}"
        );
    });
}

/// `consistent_state` chooses each law's mode from the state, whatever `grip_mode` holds: on
/// the belt's speed with the spring's pull within `μs N` (x = 0.5: `k x` = 2 against 3.92) the
/// mass sticks, and the row's multiplier is the force that holds it (`k x`, by the momentum
/// balance `0 = −k x + λ`); beyond it (x = 1.5: 6 N) it slips, backwards relative to the belt,
/// the way the spring pulls it; off the belt's speed it slips to the side of `v − vb`.
#[test]
fn the_start_chooses_each_laws_mode() {
    let belt = Belt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 };
    for (x, v, mode) in [(0.5, 0.5, 0.0), (1.5, 0.5, -1.0), (0.0, 0.7, 1.0), (0.0, 0.2, -1.0)] {
        for held in [0.0, 1.0, -1.0] {
            let mut q = VecQ::<Belt>::zeros();
            q[0] = x;
            q[1] = held;
            let mut velocities = VecQ::<Belt>::zeros();
            velocities[0] = v;
            let state =
                consistent_state(&belt, 0.0, &q, &velocities, Consistency::default()).expect("consistent");
            assert_eq!(state.q(Belt::GRIP_MODE), mode, "x = {x}, v = {v}, held {held}");
            assert_eq!(state.v(Belt::X), v, "the velocity is kept: x = {x}, v = {v}");
            if mode == 0.0 {
                assert!(
                    (state.lambda(Belt::GRIP) - belt.k * x).abs() < 1e-12,
                    "{}",
                    state.lambda(Belt::GRIP)
                );
            } else {
                assert_eq!(state.lambda(Belt::GRIP), 0.0, "slipping, the row holds the slack");
            }
        }
    }
}

/// A friction law with a NaN coefficient is refused by name before anything is evaluated, by
/// `consistent_state` and by every integrator's plain `solve`.
#[test]
fn a_friction_law_with_a_nan_coefficient_is_refused() {
    let belt = Belt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: f64::NAN, mu_k: 0.25 };
    let zero = VecQ::<Belt>::zeros();
    let error = consistent_state(&belt, 0.0, &zero, &zero, Consistency::default()).expect_err("NaN");
    assert!(error.to_string().contains("mu_s"), "{error}");
    each_integrator!(&belt, Fineness::new(1e-8, 1e-10, 1e-3), |method, integrator| {
        match integrator.solve(0.0, &State::<Belt>::zeros(), 1.0, &Sampling::Steps) {
            Err(error) => assert!(error.to_string().contains("mu_s"), "{method:?}: {error}"),
            Ok(_) => panic!("{method:?}: a NaN coefficient integrated"),
        }
    });
}

/// An RC low-pass driven by a pulse train whose first edge is at the start, `t = 0`.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(source.p, r.p), connect(r.n, c.p), connect(c.n, ground.p), connect(source.n, ground.p))]
struct PulsedRc {
    source: dirac::components::electrical::PulseVoltage,
    r: dirac::components::electrical::Resistor,
    c: dirac::components::electrical::Capacitor,
    ground: dirac::components::electrical::Ground,
}

/// The capacitor's voltage under 1 V pulses of width `w` and period 1 from `t = 0`, time
/// constant `tau`, from 0 V: in closed form, `1 − (1 − a) e^{−s/τ}` over each pulse from its
/// value `a` at the rising edge, and `b e^{−(s − w)/τ}` after the falling edge from its value
/// `b` there.
fn pulsed_rc_exact(t: f64, w: f64, tau: f64) -> f64 {
    let mut a = 0.0;
    for _ in 0..t.floor() as usize {
        let b = 1.0 - (1.0 - a) * (-w / tau).exp();
        a = b * (-(1.0 - w) / tau).exp();
    }
    let s = t - t.floor();
    let b = 1.0 - (1.0 - a) * (-s.min(w) / tau).exp();
    if s <= w { b } else { b * (-(s - w) / tau).exp() }
}

/// The pulse's first edge at the start (where its switching function is zero, and the source
/// reads low at `t = 0` itself and high just after): the run starts on the pulse, in every
/// integrator, where before it failed at once as "sliding" (the first step straddled the edge).
/// Against the closed form over three periods.
#[test]
fn a_pulse_train_that_rises_at_the_start_is_followed_from_its_first_edge() {
    use dirac::components::electrical::{Capacitor, Ground, PulseVoltage, Resistor};
    let (w, tau) = (0.5, 0.2);
    let source = PulseVoltage { offset: 0.0, amplitude: 1.0, width: w, period: 1.0, start: 0.0 };
    let rc = PulsedRc { source, r: Resistor { r: 1.0 }, c: Capacitor { c: tau }, ground: Ground {} };
    let zero = VecQ::<PulsedRc>::zeros();
    let start = consistent_state(&rc, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
    let times: Vec<f64> = (1..=60).map(|k| 0.05 * k as f64).collect();
    each_integrator!(&rc, Fineness::new(1e-9, 1e-9, 1e-4), |method, integrator| {
        let run = integrator.solve(0.0, &start, 3.0, &Sampling::Times(times.clone())).expect("integrates");
        let output = run.column("out(c.v)").expect("the capacitor's voltage");
        let worst = run
            .t()
            .iter()
            .zip(output)
            .fold(0.0_f64, |m, (&t, &v)| m.max((v - pulsed_rc_exact(t, w, tau)).abs()));
        // The variational integrator: second order at h = 1e-4, its edges located within a step.
        let bound = if method == Method::Variational { 1e-4 } else { 1e-6 };
        eprintln!("{}: pulsed RC from its first edge, worst {worst:.1e}", method.name());
        assert!(worst < bound, "{}: {worst:e}", method.name());
    });
}
