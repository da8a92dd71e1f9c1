//! Non-smooth functions through every integrator: their switching surfaces are located as
//! events and the integration restarts there. Reference: the same closed loop integrated by
//! a classical Runge-Kutta method written here, with 2·10⁵ steps per time unit (its error is
//! below 1e-9 here) and the switch time found by bisection on its steps.

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
