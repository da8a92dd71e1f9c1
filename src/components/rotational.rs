//! Rotational parts: flanges whose coordinates are angles about one axis (rad), so that their
//! velocities are angular speeds and the interconnection force at a flange is the torque on the
//! part there.
//!
//! A part between flanges `a` and `b` is twisted by `b − a`; its torque `tau` is the one with
//! which it turns `a` towards `b` (the torque on `a` is `tau`, on `b` it is `−tau`).

use crate::LagrangeDirac;

/// A rotor of inertia `j` at angle `phi`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(phi => w), port(phi), positive(j))]
#[dirac(lagrangian = 0.5 * j * w * w)]
#[dirac(output(momentum) = j * w, output(energy) = 0.5 * j * w * w)]
#[dirac(unit(phi) = "rad", unit(w) = "rad/s", unit(j) = "kg m2", unit(momentum) = "N m s", unit(energy) = "J")]
pub struct Inertia {
    /// Moment of inertia about the axis.
    pub j: f64,
}

/// A torsion spring of stiffness `k` and unstretched angle `angle`: the energy
/// `½ k (b − a − angle)²`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(a => wa, b => wb), port(a, b))]
#[dirac(lagrangian = -0.5 * k * (b - a - angle) * (b - a - angle))]
#[dirac(output(tau) = k * (b - a - angle), output(energy) = 0.5 * k * (b - a - angle) * (b - a - angle))]
#[dirac(unit(a, b, angle) = "rad", unit(wa, wb) = "rad/s", unit(k) = "N m/rad", unit(tau) = "N m")]
#[dirac(unit(energy) = "J")]
pub struct Spring {
    /// Torsional stiffness.
    pub k: f64,
    /// Unstretched angle.
    pub angle: f64,
}

/// A linear rotational damper `tau = d (wb − wa)`: the Rayleigh function `½ d (wb − wa)²`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(a => wa, b => wb), port(a, b), nonnegative(d))]
#[dirac(lagrangian = 0.0)]
#[dirac(dissipation = 0.5 * d * (wb - wa) * (wb - wa))]
#[dirac(output(tau) = d * (wb - wa), output(power) = d * (wb - wa) * (wb - wa))]
#[dirac(unit(a, b) = "rad", unit(wa, wb) = "rad/s", unit(d) = "N m s/rad", unit(tau) = "N m", unit(power) = "W")]
pub struct Damper {
    /// Damping coefficient.
    pub d: f64,
}

/// A torsion spring and a damper in parallel: a flexible shaft.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(a => wa, b => wb), port(a, b), nonnegative(d))]
#[dirac(lagrangian = -0.5 * k * (b - a - angle) * (b - a - angle))]
#[dirac(dissipation = 0.5 * d * (wb - wa) * (wb - wa))]
#[dirac(output(tau) = k * (b - a - angle) + d * (wb - wa), output(power) = d * (wb - wa) * (wb - wa))]
#[dirac(output(energy) = 0.5 * k * (b - a - angle) * (b - a - angle))]
#[dirac(unit(a, b, angle) = "rad", unit(wa, wb) = "rad/s", unit(k) = "N m/rad", unit(d) = "N m s/rad")]
#[dirac(unit(tau) = "N m", unit(power) = "W", unit(energy) = "J")]
pub struct SpringDamper {
    /// Torsional stiffness.
    pub k: f64,
    /// Damping coefficient.
    pub d: f64,
    /// Unstretched angle.
    pub angle: f64,
}

/// An ideal gear of ratio `ratio = wa / wb`, lossless: the torques on it at `a` and `b` are
/// related by `tau_b = −ratio tau_a`, and the torque on it at `a` is minus its row `gear`'s
/// multiplier.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(a => wa, b => wb), port(a, b), nonzero(ratio))]
#[dirac(lagrangian = 0.0)]
#[dirac(constraint(gear) = wa - ratio * wb)]
#[dirac(unit(a, b) = "rad", unit(wa, wb) = "rad/s", unit(ratio) = "1")]
pub struct IdealGear {
    /// Transmission ratio, the speed of `a` over that of `b`.
    pub ratio: f64,
}

/// A flange fixed at `phi0`; its row `fixed` carries the torque that holds it.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(phi => w), port(phi))]
#[dirac(lagrangian = 0.0)]
#[dirac(holonomic(fixed) = phi - phi0)]
#[dirac(unit(phi, phi0) = "rad", unit(w) = "rad/s")]
pub struct Fixed {
    /// Where the flange is held.
    pub phi0: f64,
}

/// A torque source turning flange `phi` with the input `tau` (its reaction is taken by the
/// ground).
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(phi => w), port(phi), input(tau))]
#[dirac(lagrangian = 0.0)]
#[dirac(force(phi) = tau)]
#[dirac(output(supplied) = tau * w)]
#[dirac(unit(phi) = "rad", unit(w) = "rad/s", unit(tau) = "N m", unit(supplied) = "W")]
pub struct Torque {
    /// The torque on the flange.
    pub tau: f64,
}

/// A torque step on flange `phi`: `offset` until `start`, `offset + height` from then on.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(phi => w), port(phi))]
#[dirac(lagrangian = 0.0)]
#[dirac(define(tau) = if t < start { offset } else { offset + height })]
#[dirac(force(phi) = tau)]
#[dirac(output(torque) = tau, output(supplied) = tau * w)]
#[dirac(unit(phi) = "rad", unit(w) = "rad/s", unit(offset, height, torque) = "N m", unit(start) = "s")]
#[dirac(unit(supplied) = "W")]
pub struct StepTorque {
    /// The torque before the step.
    pub offset: f64,
    /// The step's height.
    pub height: f64,
    /// The step's instant.
    pub start: f64,
}

/// A prescribed speed: flange `phi` turns at the input `w_ref`; the row `speed` carries the
/// torque that drives it.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(phi => w), port(phi), input(w_ref))]
#[dirac(lagrangian = 0.0)]
#[dirac(constraint(speed) = w - w_ref)]
#[dirac(output(supplied) = speed * w)]
#[dirac(unit(phi) = "rad", unit(w, w_ref) = "rad/s", unit(supplied) = "W")]
pub struct Speed {
    /// The flange's speed.
    pub w_ref: f64,
}

/// A friction clutch between flanges `a` and `b`: Coulomb friction with stiction whose
/// torques, `kinetic` while slipping and up to `stiction` while stuck, are scaled by the input
/// `engaged` (0 open, 1 fully pressed). Its output `tau` is the torque it puts on what is at `a`:
/// minus the law `clutch`'s multiplier while stuck, the kinetic torque against the slip while
/// slipping.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(a => wa, b => wb), port(a, b), input(engaged), nonnegative(kinetic, stiction))]
#[dirac(lagrangian = 0.0)]
#[dirac(friction(clutch, kinetic = kinetic * engaged, stiction = stiction * engaged) = wb - wa)]
#[dirac(output(tau) = -(1.0 - clutch_mode * clutch_mode) * clutch + kinetic * engaged * clutch_mode)]
#[dirac(unit(a, b) = "rad", unit(wa, wb) = "rad/s", unit(kinetic, stiction, tau) = "N m", unit(engaged) = "1")]
pub struct Clutch {
    /// The torque while slipping, fully engaged.
    pub kinetic: f64,
    /// The largest torque while stuck, fully engaged.
    pub stiction: f64,
    /// How far the clutch is pressed, in [0, 1].
    pub engaged: f64,
}

/// A brake (or bearing friction) on flange `phi` against the ground: Coulomb friction with
/// stiction whose torques are scaled by the input `engaged`. Its output `tau` is the torque it
/// puts on the shaft: the law `brake`'s multiplier while stuck, the kinetic torque against the
/// motion while slipping.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(phi => w), port(phi), input(engaged), nonnegative(kinetic, stiction))]
#[dirac(lagrangian = 0.0)]
#[dirac(friction(brake, kinetic = kinetic * engaged, stiction = stiction * engaged) = w)]
#[dirac(output(tau) = (1.0 - brake_mode * brake_mode) * brake - kinetic * engaged * brake_mode)]
#[dirac(unit(phi) = "rad", unit(w) = "rad/s", unit(kinetic, stiction, tau) = "N m", unit(engaged) = "1")]
pub struct Brake {
    /// The torque while slipping, fully engaged.
    pub kinetic: f64,
    /// The largest torque while stuck, fully engaged.
    pub stiction: f64,
    /// How far the brake is pressed, in [0, 1].
    pub engaged: f64,
}

/// A wheel (or a rack and pinion) of radius `radius`, rolling without slip: the rotational
/// flange `phi` and the translational flange `s` move as `v = radius w`. The force on it at `s`
/// is minus its row `roll`'s multiplier.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(phi => w, s => v), port(phi, s), nonzero(radius))]
#[dirac(lagrangian = 0.0)]
#[dirac(constraint(roll) = v - radius * w)]
#[dirac(unit(phi) = "rad", unit(w) = "rad/s", unit(s, radius) = "m", unit(v) = "m/s")]
pub struct Wheel {
    /// The radius.
    pub radius: f64,
}

/// An angle sensor on flange `phi`: outputs `angle`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq, Default)]
#[dirac(coordinates(phi => w), port(phi))]
#[dirac(lagrangian = 0.0)]
#[dirac(output(angle) = phi)]
#[dirac(unit(phi, angle) = "rad", unit(w) = "rad/s")]
pub struct AngleSensor {}

/// A speed sensor on flange `phi`: outputs `speed`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq, Default)]
#[dirac(coordinates(phi => w), port(phi))]
#[dirac(lagrangian = 0.0)]
#[dirac(output(speed) = w)]
#[dirac(unit(phi) = "rad", unit(w, speed) = "rad/s")]
pub struct SpeedSensor {}

/// A torque sensor joining flanges `a` and `b` rigidly (its row `rigid`): outputs the torque
/// `tau` passed from `a` to `b`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq, Default)]
#[dirac(coordinates(a => wa, b => wb), port(a, b))]
#[dirac(lagrangian = 0.0)]
#[dirac(constraint(rigid) = wb - wa)]
#[dirac(output(tau) = rigid)]
#[dirac(unit(a, b) = "rad", unit(wa, wb) = "rad/s", unit(tau) = "N m")]
pub struct TorqueSensor {}
