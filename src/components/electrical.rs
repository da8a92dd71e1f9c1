//! Electrical parts: pins `p` and `n` whose coordinates are node fluxes (V s), so that their
//! velocities `vp` and `vn` are the nodes' voltages and the interconnection force at a pin is
//! the current into the part there.
//!
//! A two-pin part's voltage is `v = vp − vn` and its current `i` flows into `p`, through the
//! part, out of `n` (the passive sign convention: `v i` is the power the part takes in).

use crate::LagrangeDirac;

/// A resistor `v = r i`: the Rayleigh function `½ (vp − vn)²/r` dissipates `v²/r`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), positive(r))]
#[dirac(lagrangian = 0.0)]
#[dirac(dissipation = 0.5 * (vp - vn) * (vp - vn) / r)]
#[dirac(output(v) = vp - vn, output(i) = (vp - vn) / r, output(power) = (vp - vn) * (vp - vn) / r)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v) = "V", unit(r) = "Ohm", unit(i) = "A", unit(power) = "W")]
pub struct Resistor {
    /// Resistance.
    pub r: f64,
}

/// A conductor `i = g v`: a resistor given by its conductance, which may be zero (an open
/// branch).
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), nonnegative(g))]
#[dirac(lagrangian = 0.0)]
#[dirac(dissipation = 0.5 * g * (vp - vn) * (vp - vn))]
#[dirac(output(v) = vp - vn, output(i) = g * (vp - vn), output(power) = g * (vp - vn) * (vp - vn))]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v) = "V", unit(g) = "S", unit(i) = "A", unit(power) = "W")]
pub struct Conductor {
    /// Conductance.
    pub g: f64,
}

/// A Shockley diode from anode `p` to cathode `n`: the forward current
/// `i = is (exp(v / n_vt) − 1)` at the voltage `v = vp − vn`, smooth (no switching surface),
/// with the saturation current `is` and the emission coefficient times the thermal voltage,
/// `n_vt` (25.85 mV for an ideal junction at 27 °C, SPICE's default temperature).
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), positive(is, n_vt))]
#[dirac(lagrangian = 0.0)]
#[dirac(define(i) = is * (((vp - vn) / n_vt).exp() - 1.0))]
#[dirac(force(p) = -i, force(n) = i)]
#[dirac(output(v) = vp - vn, output(current) = i, output(power) = (vp - vn) * i)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v, n_vt) = "V", unit(is, current) = "A", unit(power) = "W")]
pub struct ShockleyDiode {
    /// The saturation current.
    pub is: f64,
    /// The emission coefficient times the thermal voltage `k T / q`.
    pub n_vt: f64,
}

/// Chua's diode: the piecewise-linear resistor `i = ga v` for `|v| ≤ ve` and
/// `i = gb v ± (ga − gb) ve` beyond, continuous at `±ve` (Kennedy 1993). With negative slopes it
/// supplies power (its output `power`, the power it takes in, is then negative). Its corners
/// are switching surfaces every integrator locates.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), positive(ve))]
#[dirac(lagrangian = 0.0)]
#[dirac(define(i) = if vp - vn < -ve { gb * (vp - vn + ve) - ga * ve } else if vp - vn > ve { gb * (vp - vn - ve) + ga * ve } else { ga * (vp - vn) })]
#[dirac(force(p) = -i, force(n) = i)]
#[dirac(output(v) = vp - vn, output(current) = i, output(power) = (vp - vn) * i)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v, ve) = "V", unit(ga, gb) = "S", unit(current) = "A", unit(power) = "W")]
pub struct ChuaDiode {
    /// The slope within `±ve`.
    pub ga: f64,
    /// The slope beyond.
    pub gb: f64,
    /// Where the slope changes.
    pub ve: f64,
}

/// A capacitor `i = c dv/dt`: its electric energy `½ c (vp − vn)²` is kinetic in node-flux
/// coordinates, and its charge `c v` is the momentum at `p`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), positive(c))]
#[dirac(lagrangian = 0.5 * c * (vp - vn) * (vp - vn))]
#[dirac(output(v) = vp - vn, output(charge) = c * (vp - vn), output(energy) = 0.5 * c * (vp - vn) * (vp - vn))]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v) = "V", unit(c) = "F", unit(charge) = "C", unit(energy) = "J")]
pub struct Capacitor {
    /// Capacitance.
    pub c: f64,
}

/// An inductor `v = l di/dt`: its magnetic energy `(p − n)²/2l` is potential in node-flux
/// coordinates, and its current is `(p − n)/l`. Give it an initial current through its pins'
/// fluxes: `p − n = l i₀`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), positive(l))]
#[dirac(lagrangian = -(p - n) * (p - n) / (2.0 * l))]
#[dirac(output(v) = vp - vn, output(i) = (p - n) / l, output(energy) = (p - n) * (p - n) / (2.0 * l))]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v) = "V", unit(l) = "H", unit(i) = "A", unit(energy) = "J")]
pub struct Inductor {
    /// Inductance.
    pub l: f64,
}

/// An inductor `vp − vn = l di/dt` whose current `i` (into `p`, through the part, out of `n`)
/// is the rate of its coordinate `s`: the inductor branch of modified nodal analysis. Its
/// magnetic energy `½ l i²` is kinetic in `s`, and the pins exchange the current through
/// lossless forces. The inductance may be zero, a short circuit whose current the rest of the
/// circuit fixes: one assembly serves both, and at `l = 0` it has one state less. Give it an
/// initial current through the velocity of `s`. [`Inductor`] carries the flux `p − n` instead,
/// one coordinate less, and needs `l > 0`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn, s => i), port(p, n), nonnegative(l))]
#[dirac(lagrangian = 0.5 * l * i * i)]
#[dirac(force(s) = vp - vn, force(p) = -i, force(n) = i)]
#[dirac(output(v) = vp - vn, output(energy) = 0.5 * l * i * i)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v) = "V", unit(s) = "C", unit(i) = "A", unit(l) = "H", unit(energy) = "J")]
pub struct BranchInductor {
    /// Inductance, zero or more.
    pub l: f64,
}

/// Two magnetically coupled inductors (a transformer with leakage): the magnetic energy
/// `½ ψᵀ L⁻¹ ψ` of the winding fluxes `ψ₁ = p1 − n1`, `ψ₂ = p2 − n2` with the inductance
/// matrix `L = [l1 m; m l2]`, which must be positive definite (`m² < l1 l2`).
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p1 => vp1, n1 => vn1, p2 => vp2, n2 => vn2), port(p1, n1, p2, n2), positive(l1, l2))]
#[dirac(define(det) = l1 * l2 - m * m)]
#[dirac(define(i1) = (l2 * (p1 - n1) - m * (p2 - n2)) / det)]
#[dirac(define(i2) = (l1 * (p2 - n2) - m * (p1 - n1)) / det)]
#[dirac(lagrangian = -0.5 * ((p1 - n1) * i1 + (p2 - n2) * i2))]
#[dirac(output(v1) = vp1 - vn1, output(v2) = vp2 - vn2, output(current1) = i1, output(current2) = i2)]
#[dirac(output(energy) = 0.5 * ((p1 - n1) * i1 + (p2 - n2) * i2))]
#[dirac(unit(p1, n1, p2, n2) = "Wb", unit(vp1, vn1, vp2, vn2, v1, v2) = "V", unit(l1, l2, m) = "H")]
#[dirac(unit(current1, current2) = "A", unit(energy) = "J")]
pub struct CoupledInductors {
    /// Self-inductance of winding 1.
    pub l1: f64,
    /// Self-inductance of winding 2.
    pub l2: f64,
    /// Mutual inductance.
    pub m: f64,
}

/// An ideal transformer of turns ratio `n`: `v1 = n v2` and `i2 = −n i1`, lossless. Its row
/// `transform` carries `−i1`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p1 => vp1, n1 => vn1, p2 => vp2, n2 => vn2), port(p1, n1, p2, n2), nonzero(n))]
#[dirac(lagrangian = 0.0)]
#[dirac(constraint(transform) = (vp1 - vn1) - n * (vp2 - vn2))]
#[dirac(output(v1) = vp1 - vn1, output(v2) = vp2 - vn2, output(current1) = -transform)]
#[dirac(output(current2) = n * transform)]
#[dirac(unit(p1, n1, p2, n2) = "Wb", unit(vp1, vn1, vp2, vn2, v1, v2) = "V", unit(n) = "1")]
#[dirac(unit(current1, current2) = "A")]
pub struct IdealTransformer {
    /// Turns ratio `v1 / v2`.
    pub n: f64,
}

/// A gyrator `i1 = g v2`, `i2 = −g v1`, lossless: the gyroscopic term `−g (p1 − n1)(vp2 − vn2)`
/// of the Lagrangian.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p1 => vp1, n1 => vn1, p2 => vp2, n2 => vn2), port(p1, n1, p2, n2))]
#[dirac(lagrangian = -g * (p1 - n1) * (vp2 - vn2))]
#[dirac(output(v1) = vp1 - vn1, output(v2) = vp2 - vn2)]
#[dirac(output(current1) = g * (vp2 - vn2), output(current2) = -g * (vp1 - vn1))]
#[dirac(unit(p1, n1, p2, n2) = "Wb", unit(vp1, vn1, vp2, vn2, v1, v2) = "V", unit(g) = "S")]
#[dirac(unit(current1, current2) = "A")]
pub struct Gyrator {
    /// Gyration conductance.
    pub g: f64,
}

/// The reference node: its flux, and so its voltage, held at zero. The current into the ground
/// is minus its row `ground`'s multiplier.
#[derive(LagrangeDirac, Clone, Debug, PartialEq, Default)]
#[dirac(coordinates(p => vp), port(p))]
#[dirac(lagrangian = 0.0)]
#[dirac(holonomic(ground) = p)]
#[dirac(unit(p) = "Wb", unit(vp) = "V")]
pub struct Ground {}

/// A voltage-controlled current source of transconductance `gm`: the current
/// `i = gm (vp1 − vn1)` flows into `p2`, through the part, out of `n2` (as through a
/// conductance `gm` if the control were its own voltage), and the control pins draw no current.
/// It supplies power: with a large `gm` and a resistor across its output it is an amplifier.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p1 => vp1, n1 => vn1, p2 => vp2, n2 => vn2), port(p1, n1, p2, n2))]
#[dirac(lagrangian = 0.0)]
#[dirac(force(p2) = -gm * (vp1 - vn1), force(n2) = gm * (vp1 - vn1))]
#[dirac(output(i) = gm * (vp1 - vn1))]
#[dirac(unit(p1, n1, p2, n2) = "Wb", unit(vp1, vn1, vp2, vn2) = "V", unit(gm) = "S", unit(i) = "A")]
pub struct VoltageControlledCurrent {
    /// Transconductance.
    pub gm: f64,
}

/// A voltage-controlled voltage source of gain `gain`: `vp2 − vn2 = gain (vp1 − vn1)`, and the
/// control pins draw no current. Its output current `i` (into `p2`, through the part, out of
/// `n2`) is the rate of its coordinate `s`, whose balance is the voltage law: the branch of
/// modified nodal analysis, so that the control's side carries no reaction.
///
/// `i` is an unknown without inertia, fixed by what the output drives: a loop of this output
/// with capacitors and voltage sources alone would leave it undetermined by the velocities,
/// which no integrator here resolves (the SPICE reader refuses such a loop).
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p1 => vp1, n1 => vn1, p2 => vp2, n2 => vn2, s => i), port(p1, n1, p2, n2))]
#[dirac(lagrangian = 0.0)]
#[dirac(force(s) = vp2 - vn2 - gain * (vp1 - vn1), force(p2) = -i, force(n2) = i)]
#[dirac(output(v) = vp2 - vn2, output(supplied) = -(vp2 - vn2) * i)]
#[dirac(unit(p1, n1, p2, n2) = "Wb", unit(vp1, vn1, vp2, vn2, v) = "V", unit(gain) = "1")]
#[dirac(unit(s) = "C", unit(i) = "A", unit(supplied) = "W")]
pub struct VoltageControlledVoltage {
    /// The voltage gain.
    pub gain: f64,
}

/// A voltage source `vp − vn = u` whose current `i` (into `p`, through the source, out of `n`)
/// is the rate of its coordinate `s`, a port: the branch of modified nodal analysis, which a
/// current-controlled source joins to read the current (SPICE's `F` and `H` name such a source).
/// [`VoltageSource`] carries its current as a multiplier instead, which no other part can read.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn, s => i), port(p, n, s), input(u))]
#[dirac(lagrangian = 0.0)]
#[dirac(force(s) = vp - vn - u, force(p) = -i, force(n) = i)]
#[dirac(output(supplied) = -u * i)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, u) = "V", unit(s) = "C", unit(i) = "A", unit(supplied) = "W")]
pub struct SensedVoltageSource {
    /// The source's voltage `vp − vn`.
    pub u: f64,
}

/// A current-controlled current source of gain `gain`: the current `gain · ic` flows into `p`,
/// through the part, out of `n`, where `ic` is the rate of the control coordinate `c`, joined to
/// a [`SensedVoltageSource`]'s `s` (or any coordinate whose rate is a current).
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(c => ic, p => vp, n => vn), port(c, p, n))]
#[dirac(lagrangian = 0.0)]
#[dirac(force(p) = -gain * ic, force(n) = gain * ic)]
#[dirac(output(i) = gain * ic, output(supplied) = -(vp - vn) * gain * ic)]
#[dirac(unit(c) = "C", unit(ic, i) = "A", unit(p, n) = "Wb", unit(vp, vn) = "V", unit(gain) = "1")]
#[dirac(unit(supplied) = "W")]
pub struct CurrentControlledCurrent {
    /// The current gain.
    pub gain: f64,
}

/// A current-controlled voltage source of transresistance `r`: `vp − vn = r · ic`, where `ic`
/// is the rate of the control coordinate `c` (joined as for [`CurrentControlledCurrent`]). Its
/// own current `i`, into `p`, is the rate of its coordinate `s`, as for
/// [`VoltageControlledVoltage`].
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(c => ic, p => vp, n => vn, s => i), port(c, p, n))]
#[dirac(lagrangian = 0.0)]
#[dirac(force(s) = vp - vn - r * ic, force(p) = -i, force(n) = i)]
#[dirac(output(v) = vp - vn, output(supplied) = -(vp - vn) * i)]
#[dirac(unit(c, s) = "C", unit(ic, i) = "A", unit(p, n) = "Wb", unit(vp, vn, v) = "V", unit(r) = "Ohm")]
#[dirac(unit(supplied) = "W")]
pub struct CurrentControlledVoltage {
    /// The transresistance.
    pub r: f64,
}

/// An ideal diode from anode `p` to cathode `n`: the complementarity `vn − vp ≥ 0`, `i ≥ 0`,
/// `(vn − vp) i = 0` (the law `diode`, whose multiplier is the forward current `i`). It
/// conducts or blocks by itself; see the guide's "Dissipation, friction and switches".
#[derive(LagrangeDirac, Clone, Debug, PartialEq, Default)]
#[dirac(coordinates(p => vp, n => vn), port(p, n))]
#[dirac(lagrangian = 0.0)]
#[dirac(diode(diode) = vn - vp)]
#[dirac(output(v) = vp - vn, output(i) = diode)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v) = "V", unit(i) = "A")]
pub struct IdealDiode {}

/// An ideal switch between `p` and `n`, closed (`v = 0`) while its input `control` is
/// positive and open (`i = 0`) otherwise: the law `switch`, whose multiplier is the current.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), input(control))]
#[dirac(lagrangian = 0.0)]
#[dirac(switch(switch, closed = control) = vp - vn)]
#[dirac(output(v) = vp - vn, output(i) = -switch)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v) = "V", unit(i) = "A")]
pub struct IdealSwitch {
    /// Closed while positive.
    pub control: f64,
}

/// A voltage source `v = u` whose voltage is an input: constant unless a controller, a table
/// or a drive sets it while the simulation runs. Its row `source` carries `−i`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), input(u))]
#[dirac(lagrangian = 0.0)]
#[dirac(constraint(source) = vp - vn - u)]
#[dirac(output(i) = -source, output(supplied) = u * source)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, u) = "V", unit(i) = "A", unit(supplied) = "W")]
pub struct VoltageSource {
    /// The source's voltage `vp − vn`.
    pub u: f64,
}

/// A voltage step: `offset` until `start`, `offset + height` from then on. The step's instant is
/// a switching surface every integrator locates.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n))]
#[dirac(lagrangian = 0.0)]
#[dirac(define(u) = if t < start { offset } else { offset + height })]
#[dirac(constraint(source) = vp - vn - u)]
#[dirac(output(v) = u, output(i) = -source, output(supplied) = u * source)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, offset, height, v) = "V", unit(start) = "s", unit(i) = "A", unit(supplied) = "W")]
pub struct StepVoltage {
    /// The voltage before the step.
    pub offset: f64,
    /// The step's height.
    pub height: f64,
    /// The step's instant.
    pub start: f64,
}

/// A voltage ramp: `offset` until `start`, rising linearly by `height` over `duration`, then
/// held. Its corners are switching surfaces every integrator locates.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), positive(duration))]
#[dirac(lagrangian = 0.0)]
#[dirac(define(u) = offset + height * ((t - start) / duration).clamp(0.0, 1.0))]
#[dirac(constraint(source) = vp - vn - u)]
#[dirac(output(v) = u, output(i) = -source, output(supplied) = u * source)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, offset, height, v) = "V", unit(start, duration) = "s")]
#[dirac(unit(i) = "A", unit(supplied) = "W")]
pub struct RampVoltage {
    /// The voltage before the ramp.
    pub offset: f64,
    /// The rise over the ramp.
    pub height: f64,
    /// The ramp's start.
    pub start: f64,
    /// The ramp's duration.
    pub duration: f64,
}

/// A sine voltage: `offset` until `start`, then `offset + amplitude sin(2π f (t − start) + phase)`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n))]
#[dirac(lagrangian = 0.0)]
#[dirac(define(u) = if t < start { offset } else { offset + amplitude * (TAU * f * (t - start) + phase).sin() })]
#[dirac(constraint(source) = vp - vn - u)]
#[dirac(output(v) = u, output(i) = -source, output(supplied) = u * source)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, offset, amplitude, v) = "V", unit(f) = "Hz", unit(phase) = "rad")]
#[dirac(unit(start) = "s", unit(i) = "A", unit(supplied) = "W")]
pub struct SineVoltage {
    /// The voltage before the start, and the sine's mean.
    pub offset: f64,
    /// The sine's amplitude.
    pub amplitude: f64,
    /// The frequency.
    pub f: f64,
    /// The phase at `start`.
    pub phase: f64,
    /// When the sine starts.
    pub start: f64,
}

/// A damped sine voltage from `t = 0`: `offset + amplitude e^(−damping t) sin(2π f t + phase)`,
/// smooth (no switching surface): SPICE's `SIN` source without a delay.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), nonnegative(damping))]
#[dirac(lagrangian = 0.0)]
#[dirac(define(u) = offset + amplitude * (-damping * t).exp() * (TAU * f * t + phase).sin())]
#[dirac(constraint(source) = vp - vn - u)]
#[dirac(output(v) = u, output(i) = -source, output(supplied) = u * source)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, offset, amplitude, v) = "V", unit(f, damping) = "Hz")]
#[dirac(unit(phase) = "rad", unit(i) = "A", unit(supplied) = "W")]
pub struct DampedSineVoltage {
    /// The sine's mean.
    pub offset: f64,
    /// The amplitude at `t = 0`.
    pub amplitude: f64,
    /// The frequency.
    pub f: f64,
    /// The decay rate of the amplitude.
    pub damping: f64,
    /// The phase at `t = 0`.
    pub phase: f64,
}

/// A train of rectangular pulses (pulse-width modulation): `offset` until `start`, then in each
/// `period` the value `offset + amplitude` for the fraction `width` of it (0 < width < 1) and
/// `offset` for the rest. Every edge is a switching surface every integrator locates.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), positive(period, width))]
#[dirac(lagrangian = 0.0)]
#[dirac(define(u) = if t < start { offset } else if (TAU * ((t - start) / period - 0.5 * width)).cos() > (PI * width).cos() { offset + amplitude } else { offset })]
#[dirac(constraint(source) = vp - vn - u)]
#[dirac(output(v) = u, output(i) = -source, output(supplied) = u * source)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, offset, amplitude, v) = "V", unit(period, start) = "s")]
#[dirac(unit(width) = "1", unit(i) = "A", unit(supplied) = "W")]
pub struct PulseVoltage {
    /// The low level.
    pub offset: f64,
    /// The pulses' height above `offset`.
    pub amplitude: f64,
    /// The fraction of each period the pulse is high, in (0, 1).
    pub width: f64,
    /// The period.
    pub period: f64,
    /// When the first pulse rises.
    pub start: f64,
}

/// A current source whose current `i`, into `p`, through the source and out of `n`, is an
/// input: constant unless a controller, a table or a drive sets it.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n), input(i))]
#[dirac(lagrangian = 0.0)]
#[dirac(force(p) = -i, force(n) = i)]
#[dirac(output(v) = vp - vn, output(supplied) = -(vp - vn) * i)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v) = "V", unit(i) = "A", unit(supplied) = "W")]
pub struct CurrentSource {
    /// The source's current, into `p`.
    pub i: f64,
}

/// A current step: `offset` until `start`, `offset + height` from then on, into `p`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n))]
#[dirac(lagrangian = 0.0)]
#[dirac(define(i) = if t < start { offset } else { offset + height })]
#[dirac(force(p) = -i, force(n) = i)]
#[dirac(output(current) = i, output(v) = vp - vn, output(supplied) = -(vp - vn) * i)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v) = "V", unit(offset, height, current) = "A", unit(start) = "s")]
#[dirac(unit(supplied) = "W")]
pub struct StepCurrent {
    /// The current before the step.
    pub offset: f64,
    /// The step's height.
    pub height: f64,
    /// The step's instant.
    pub start: f64,
}

/// A sine current: `offset` until `start`, then `offset + amplitude sin(2π f (t − start) + phase)`,
/// into `p`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn), port(p, n))]
#[dirac(lagrangian = 0.0)]
#[dirac(define(i) = if t < start { offset } else { offset + amplitude * (TAU * f * (t - start) + phase).sin() })]
#[dirac(force(p) = -i, force(n) = i)]
#[dirac(output(current) = i, output(v) = vp - vn, output(supplied) = -(vp - vn) * i)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v) = "V", unit(offset, amplitude, current) = "A")]
#[dirac(unit(f) = "Hz", unit(phase) = "rad", unit(start) = "s", unit(supplied) = "W")]
pub struct SineCurrent {
    /// The current before the start, and the sine's mean.
    pub offset: f64,
    /// The sine's amplitude.
    pub amplitude: f64,
    /// The frequency.
    pub f: f64,
    /// The phase at `start`.
    pub phase: f64,
    /// When the sine starts.
    pub start: f64,
}

/// A voltmeter between `p` and `n`: draws no current; its output `v` is `vp − vn`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq, Default)]
#[dirac(coordinates(p => vp, n => vn), port(p, n))]
#[dirac(lagrangian = 0.0)]
#[dirac(output(v) = vp - vn)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn, v) = "V")]
pub struct VoltageSensor {}

/// An ammeter in series: joins `p` to `n` (its row `short`) and outputs the current `i` into
/// `p`, through it, out of `n`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq, Default)]
#[dirac(coordinates(p => vp, n => vn), port(p, n))]
#[dirac(lagrangian = 0.0)]
#[dirac(constraint(short) = vp - vn)]
#[dirac(output(i) = -short)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn) = "V", unit(i) = "A")]
pub struct CurrentSensor {}

/// A wattmeter: its current path from `pc` to `nc` (a short, as an ammeter) and its voltage
/// pins `pv` and `nv` (drawing no current, as a voltmeter); its output `power` is
/// `(vpv − vnv) i`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq, Default)]
#[dirac(coordinates(pc => vpc, nc => vnc, pv => vpv, nv => vnv), port(pc, nc, pv, nv))]
#[dirac(lagrangian = 0.0)]
#[dirac(constraint(short) = vpc - vnc)]
#[dirac(output(i) = -short, output(v) = vpv - vnv, output(power) = -(vpv - vnv) * short)]
#[dirac(unit(pc, nc, pv, nv) = "Wb", unit(vpc, vnc, vpv, vnv, v) = "V", unit(i) = "A", unit(power) = "W")]
pub struct PowerSensor {}
