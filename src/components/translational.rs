//! Translational parts: flanges whose coordinates are positions along one axis (m), so that
//! their velocities are speeds and the interconnection force at a flange is the force on the
//! part there, positive along the axis.
//!
//! A part between flanges `a` and `b` is stretched by `b − a`; its force `f` is the tension
//! with which it pulls `a` towards `b` (the force on `a` is `f`, on `b` it is `−f`).

use crate::LagrangeDirac;

/// A point mass `m` at position `s`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(s => v), port(s), positive(m))]
#[dirac(lagrangian = 0.5 * m * v * v)]
#[dirac(output(momentum) = m * v, output(energy) = 0.5 * m * v * v)]
#[dirac(unit(s) = "m", unit(v) = "m/s", unit(m) = "kg", unit(momentum) = "N s", unit(energy) = "J")]
pub struct Mass {
    /// Mass.
    pub m: f64,
}

/// A linear spring of stiffness `k` and unstretched length `length`: the energy
/// `½ k (b − a − length)²`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(a => va, b => vb), port(a, b))]
#[dirac(lagrangian = -0.5 * k * (b - a - length) * (b - a - length))]
#[dirac(output(f) = k * (b - a - length), output(energy) = 0.5 * k * (b - a - length) * (b - a - length))]
#[dirac(unit(a, b, length) = "m", unit(va, vb) = "m/s", unit(k) = "N/m", unit(f) = "N", unit(energy) = "J")]
pub struct Spring {
    /// Stiffness.
    pub k: f64,
    /// Unstretched length.
    pub length: f64,
}

/// A linear damper `f = d (vb − va)`: the Rayleigh function `½ d (vb − va)²`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(a => va, b => vb), port(a, b), nonnegative(d))]
#[dirac(lagrangian = 0.0)]
#[dirac(dissipation = 0.5 * d * (vb - va) * (vb - va))]
#[dirac(output(f) = d * (vb - va), output(power) = d * (vb - va) * (vb - va))]
#[dirac(unit(a, b) = "m", unit(va, vb) = "m/s", unit(d) = "N s/m", unit(f) = "N", unit(power) = "W")]
pub struct Damper {
    /// Damping coefficient.
    pub d: f64,
}

/// A spring and a damper in parallel.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(a => va, b => vb), port(a, b), nonnegative(d))]
#[dirac(lagrangian = -0.5 * k * (b - a - length) * (b - a - length))]
#[dirac(dissipation = 0.5 * d * (vb - va) * (vb - va))]
#[dirac(output(f) = k * (b - a - length) + d * (vb - va), output(power) = d * (vb - va) * (vb - va))]
#[dirac(output(energy) = 0.5 * k * (b - a - length) * (b - a - length))]
#[dirac(unit(a, b, length) = "m", unit(va, vb) = "m/s", unit(k) = "N/m", unit(d) = "N s/m")]
#[dirac(unit(f) = "N", unit(power) = "W", unit(energy) = "J")]
pub struct SpringDamper {
    /// Stiffness.
    pub k: f64,
    /// Damping coefficient.
    pub d: f64,
    /// Unstretched length.
    pub length: f64,
}

/// A flange fixed at `s0`; its row `fixed` carries the force that holds it.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(s => v), port(s))]
#[dirac(lagrangian = 0.0)]
#[dirac(holonomic(fixed) = s - s0)]
#[dirac(unit(s, s0) = "m", unit(v) = "m/s")]
pub struct Fixed {
    /// Where the flange is held.
    pub s0: f64,
}

/// A force source pushing flange `s` along the axis with the input `f` (its reaction is taken
/// by the ground).
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(s => v), port(s), input(f))]
#[dirac(lagrangian = 0.0)]
#[dirac(force(s) = f)]
#[dirac(output(supplied) = f * v)]
#[dirac(unit(s) = "m", unit(v) = "m/s", unit(f) = "N", unit(supplied) = "W")]
pub struct Force {
    /// The force on the flange.
    pub f: f64,
}

/// A force step on flange `s`: `offset` until `start`, `offset + height` from then on.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(s => v), port(s))]
#[dirac(lagrangian = 0.0)]
#[dirac(define(f) = if t < start { offset } else { offset + height })]
#[dirac(force(s) = f)]
#[dirac(output(force) = f, output(supplied) = f * v)]
#[dirac(unit(s) = "m", unit(v) = "m/s", unit(offset, height, force) = "N", unit(start) = "s")]
#[dirac(unit(supplied) = "W")]
pub struct StepForce {
    /// The force before the step.
    pub offset: f64,
    /// The step's height.
    pub height: f64,
    /// The step's instant.
    pub start: f64,
}

/// A prescribed speed: flange `s` moves at the input `v_ref`; the row `speed` carries the force
/// that drives it.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(s => v), port(s), input(v_ref))]
#[dirac(lagrangian = 0.0)]
#[dirac(constraint(speed) = v - v_ref)]
#[dirac(output(supplied) = speed * v)]
#[dirac(unit(s) = "m", unit(v, v_ref) = "m/s", unit(supplied) = "W")]
pub struct Speed {
    /// The flange's speed.
    pub v_ref: f64,
}

/// A prescribed oscillation: flange `s` at `offset + amplitude sin(2π f t + phase)`; the row
/// `motion` carries the force that moves it.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(s => v), port(s))]
#[dirac(lagrangian = 0.0)]
#[dirac(holonomic(motion) = s - offset - amplitude * (TAU * f * t + phase).sin())]
#[dirac(output(supplied) = motion * v)]
#[dirac(unit(s, offset, amplitude) = "m", unit(v) = "m/s", unit(f) = "Hz", unit(phase) = "rad")]
#[dirac(unit(supplied) = "W")]
pub struct SinePosition {
    /// The mean position.
    pub offset: f64,
    /// The amplitude.
    pub amplitude: f64,
    /// The frequency.
    pub f: f64,
    /// The phase at `t = 0`.
    pub phase: f64,
}

/// Coulomb friction with stiction between flanges `a` and `b`: while they slip, the force
/// `kinetic` against the relative motion; while they stick, up to `stiction` (the law
/// `friction`, whose mode coordinate `friction_mode` is 0 stuck and ±1 slipping; see the guide's
/// "Dissipation, friction and switches"). Its output `f` is the tension: minus the law's
/// multiplier while stuck, `kinetic` against the slip while slipping. Ground one flange with [`Fixed`] for friction against
/// the ground.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(a => va, b => vb), port(a, b), nonnegative(kinetic, stiction))]
#[dirac(lagrangian = 0.0)]
#[dirac(friction(friction, kinetic = kinetic, stiction = stiction) = vb - va)]
#[dirac(output(f) = -(1.0 - friction_mode * friction_mode) * friction + kinetic * friction_mode)]
#[dirac(unit(a, b) = "m", unit(va, vb) = "m/s", unit(kinetic, stiction, f) = "N")]
pub struct Friction {
    /// The force while slipping.
    pub kinetic: f64,
    /// The largest force while sticking (at least `kinetic`).
    pub stiction: f64,
}

/// A hard stop: flange `b` stays at least `gap` beyond flange `a` (`b − a ≥ gap`), hitting it
/// with Newton's restitution `restitution` (0 plastic, 1 elastic).
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(a => va, b => vb), port(a, b), nonnegative(restitution))]
#[dirac(lagrangian = 0.0)]
#[dirac(unilateral(stop, restitution = restitution) = b - a - gap)]
#[dirac(unit(a, b, gap) = "m", unit(va, vb) = "m/s", unit(restitution) = "1")]
pub struct Stop {
    /// The closest `b − a` may come.
    pub gap: f64,
    /// Newton's coefficient of restitution, in [0, 1].
    pub restitution: f64,
}

/// A position sensor on flange `s`: outputs `position`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq, Default)]
#[dirac(coordinates(s => v), port(s))]
#[dirac(lagrangian = 0.0)]
#[dirac(output(position) = s)]
#[dirac(unit(s, position) = "m", unit(v) = "m/s")]
pub struct PositionSensor {}

/// A speed sensor on flange `s`: outputs `speed`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq, Default)]
#[dirac(coordinates(s => v), port(s))]
#[dirac(lagrangian = 0.0)]
#[dirac(output(speed) = v)]
#[dirac(unit(s) = "m", unit(v, speed) = "m/s")]
pub struct SpeedSensor {}

/// A force sensor joining flanges `a` and `b` rigidly (its row `rigid`): outputs the force `f`
/// passed from `a` to `b` (the force on `b`'s side, `−f` on `a`'s).
#[derive(LagrangeDirac, Clone, Debug, PartialEq, Default)]
#[dirac(coordinates(a => va, b => vb), port(a, b))]
#[dirac(lagrangian = 0.0)]
#[dirac(constraint(rigid) = vb - va)]
#[dirac(output(f) = rigid)]
#[dirac(unit(a, b) = "m", unit(va, vb) = "m/s", unit(f) = "N")]
pub struct ForceSensor {}
