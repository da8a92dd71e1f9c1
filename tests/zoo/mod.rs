//! The shared zoo of test models: the paper's primitive systems and chain, a pendulum, a
//! rolling disk, forced and degenerate models, an 8-link pendulum, and one model that uses
//! every supported function. Integration tests, examples and benchmarks all use these.

#![allow(dead_code)]

use dirac::State;
use dirac::prelude::*;

pub mod bodies;
pub mod robots;

/// Primitive system 1 of the paper (Fig. 2): wall —k1— m1 —k2— m2, port at x2.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x1 => v1, x2 => v2), port(x2))]
#[dirac(lagrangian = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2
                   - 0.5 * k1 * x1 * x1 - 0.5 * k2 * (x2 - x1).powi(2))]
pub struct Primitive1 {
    pub m1: f64,
    pub m2: f64,
    pub k1: f64,
    pub k2: f64,
}

/// Primitive system 2 of the paper: x̄2 —k3— m3, port at x̄2. Degenerate: no kinetic term in v̄2.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x2bar => v2bar, x3 => v3), port(x2bar))]
#[dirac(lagrangian = 0.5 * m3 * v3 * v3 - 0.5 * k3 * (x3 - x2bar).powi(2))]
pub struct Primitive2 {
    pub m3: f64,
    pub k3: f64,
}

/// The paper's Fig. 1 as one model: wall —k1— m1 —k2— m2 —k3— m3.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x1 => v1, x2 => v2, x3 => v3))]
#[dirac(lagrangian = 0.5 * (m1 * v1 * v1 + m2 * v2 * v2 + m3 * v3 * v3)
                   - 0.5 * (k1 * x1 * x1 + k2 * (x2 - x1).powi(2) + k3 * (x3 - x2).powi(2)))]
pub struct MassSpringChain {
    pub m1: f64,
    pub m2: f64,
    pub m3: f64,
    pub k1: f64,
    pub k2: f64,
    pub k3: f64,
}

/// A planar pendulum in Cartesian coordinates with the holonomic constraint x² + y² = l².
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(rod) = x * x + y * y - l * l)]
pub struct Pendulum {
    pub m: f64,
    pub g: f64,
    pub l: f64,
}

/// A pendulum whose pivot is shaken along x as `a sin(ω t)`: a rheonomic holonomic
/// constraint.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(define(pivot) = a * sin(w * t))]
#[dirac(holonomic(rod) = 0.5 * ((x - pivot) * (x - pivot) + y * y - l * l))]
pub struct ShakenPendulum {
    pub m: f64,
    pub g: f64,
    pub l: f64,
    pub a: f64,
    pub w: f64,
}

/// A mass on a spring whose far end `e` is dragged at speed `c`: the end has no inertia, and
/// its motion is prescribed by `e − c t = 0`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, e => ve))]
#[dirac(lagrangian = 0.5 * m * vx * vx - 0.5 * k * (e - x) * (e - x))]
#[dirac(holonomic(drag) = e - c * t)]
pub struct DraggedMass {
    pub m: f64,
    pub k: f64,
    pub c: f64,
}

/// A bead sliding without friction on a straight rod turned about the origin at rate `w`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy))]
#[dirac(holonomic(rod) = x * sin(w * t) - y * cos(w * t))]
pub struct BeadOnRod {
    pub m: f64,
    pub w: f64,
}

/// The Kepler problem, `μ = 1`: an ODE with a closed form ([`kepler_exact`]) whose steps vary
/// tenfold along an eccentric orbit.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * (vx * vx + vy * vy) + 1.0 / (x * x + y * y).sqrt())]
pub struct Kepler {}

/// `[x, y, vx, vy]` at time `t` on the Kepler orbit of eccentricity `e` and semi-major axis 1
/// that starts at perihelion on the x axis: Kepler's equation `E − e sin E = t` solved by
/// Newton's method to round-off.
pub fn kepler_exact(e: f64, t: f64) -> [f64; 4] {
    let mut anomaly = t;
    for _ in 0..50 {
        let step = (anomaly - e * anomaly.sin() - t) / (1.0 - e * anomaly.cos());
        anomaly -= step;
        if step.abs() < 1e-16 {
            break;
        }
    }
    let (s, c) = anomaly.sin_cos();
    let b = (1.0 - e * e).sqrt();
    let rate = 1.0 / (1.0 - e * c);
    [c - e, b * s, -s * rate, b * c * rate]
}

/// `[x, y, vx, vy]` at time `t` of the bead on the rod turned at rate `w`, released at
/// `r0` on the x axis at rest along the rod: `r = r0 cosh ωt`.
pub fn bead_exact(w: f64, r0: f64, t: f64) -> [f64; 4] {
    let (r, dr) = (r0 * (w * t).cosh(), r0 * w * (w * t).sinh());
    let (s, c) = (w * t).sin_cos();
    [r * c, r * s, dr * c - r * w * s, dr * s + r * w * c]
}

/// A free mass on a line.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), lagrangian = 0.5 * m * v * v)]
pub struct FreeMass {
    pub m: f64,
}

/// Two free masses whose relative velocity is prescribed, `v_r − v_l = a ω cos(ω t)`: an
/// affine interconnection one-form.
#[derive(Interconnection, Clone, Debug)]
#[dirac(constraint(shake) = right.v - left.v - a * w * cos(w * t))]
pub struct ShakenPair {
    pub left: FreeMass,
    pub right: FreeMass,
    pub a: f64,
    pub w: f64,
}

/// A row of free masses, each shaken against the one before as in [`ShakenPair`].
#[derive(Interconnection, Clone, Debug)]
#[dirac(constraint(shake) = cells[i + 1].v - cells[i].v - a * w * cos(w * t))]
pub struct ShakenRow {
    pub cells: Vec<FreeMass>,
    pub a: f64,
    pub w: f64,
}

/// A vertical disk rolling without slipping on a belt that moves along x at the speed of the
/// input `belt`: affine nonholonomic constraints, `ẋ − r cos φ θ̇ − belt = 0`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v_x, y => v_y, theta => v_theta, phi => v_phi), input(belt))]
#[dirac(lagrangian = 0.5 * m * (v_x * v_x + v_y * v_y) + 0.5 * i_roll * v_theta * v_theta
                   + 0.5 * i_turn * v_phi * v_phi)]
#[dirac(constraint(roll_x) = v_x - r * phi.cos() * v_theta - belt)]
#[dirac(constraint(roll_y) = v_y - r * sin(phi) * v_theta)]
pub struct DiskOnBelt {
    pub m: f64,
    pub r: f64,
    pub i_roll: f64,
    pub i_turn: f64,
    pub belt: f64,
}

/// [`DiskOnBelt`] on a belt that accelerates, written with `t`: `belt = u0 + c t`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v_x, y => v_y, theta => v_theta, phi => v_phi))]
#[dirac(lagrangian = 0.5 * m * (v_x * v_x + v_y * v_y) + 0.5 * i_roll * v_theta * v_theta
                   + 0.5 * i_turn * v_phi * v_phi)]
#[dirac(constraint(roll_x) = v_x - r * phi.cos() * v_theta - (u0 + c * t))]
#[dirac(constraint(roll_y) = v_y - r * sin(phi) * v_theta)]
pub struct DiskOnAcceleratingBelt {
    pub m: f64,
    pub r: f64,
    pub i_roll: f64,
    pub i_turn: f64,
    pub u0: f64,
    pub c: f64,
}

/// A slider crank with its crank turned at constant speed, `θ − ω t = 0`: crank (uniform,
/// length `r`, mass `m1`) about the origin, connecting rod (uniform, length `l`, mass `m2`)
/// at angle β, slider (mass `m3`) on the x axis with a damper `c`, under gravity.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(theta => v_theta, beta => v_beta, x => v_x))]
#[dirac(define(rod_vx) = -r * sin(theta) * v_theta - 0.5 * l * sin(beta) * v_beta)]
#[dirac(define(rod_vy) = r * cos(theta) * v_theta - 0.5 * l * cos(beta) * v_beta)]
#[dirac(define(rod_y) = r * sin(theta) - 0.5 * l * sin(beta))]
#[dirac(lagrangian = 0.5 * m1 * r * r / 3.0 * v_theta * v_theta
                   + 0.5 * m2 * (rod_vx * rod_vx + rod_vy * rod_vy)
                   + 0.5 * m2 * l * l / 12.0 * v_beta * v_beta
                   + 0.5 * m3 * v_x * v_x
                   - m1 * g * 0.5 * r * sin(theta) - m2 * g * rod_y)]
#[dirac(force(x) = -c * v_x)]
#[dirac(holonomic(loop_x) = r * cos(theta) + l * cos(beta) - x)]
#[dirac(holonomic(loop_y) = r * sin(theta) - l * sin(beta))]
#[dirac(holonomic(drive) = theta - w * t)]
pub struct SliderCrank {
    pub m1: f64,
    pub m2: f64,
    pub m3: f64,
    pub r: f64,
    pub l: f64,
    pub g: f64,
    pub c: f64,
    pub w: f64,
}

/// A vertical disk rolling without slipping: ẋ = r cos φ θ̇, ẏ = r sin φ θ̇ (nonholonomic).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v_x, y => v_y, theta => v_theta, phi => v_phi))]
#[dirac(lagrangian = 0.5 * m * (v_x * v_x + v_y * v_y) + 0.5 * i_roll * v_theta * v_theta
                   + 0.5 * i_turn * v_phi * v_phi)]
#[dirac(constraint(roll_x) = v_x - r * phi.cos() * v_theta)]
#[dirac(constraint(roll_y) = v_y - r * sin(phi) * v_theta)]
pub struct RollingDisk {
    pub m: f64,
    pub r: f64,
    pub i_roll: f64,
    pub i_turn: f64,
}

/// A damped oscillator driven by a time-dependent force.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(force(x) = -c * v + a * (w * t).sin())]
pub struct DrivenOscillator {
    pub m: f64,
    pub k: f64,
    pub c: f64,
    pub a: f64,
    pub w: f64,
}

/// A mass on a spring driven by the input force `f`: `m ẍ = −k x + f`. Its output `energy`
/// is the energy written out by hand, and `stretch` is `k x`, the spring's force.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), port(x), input(f))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x, force(x) = f)]
#[dirac(output(energy) = 0.5 * m * v * v + 0.5 * k * x * x, output(stretch) = k * x)]
pub struct ForcedSpring {
    pub m: f64,
    pub k: f64,
    pub f: f64,
}

/// A spring whose mass has an adjustable part `dm`, an input in the mass matrix: changing it
/// while the mass moves changes the momentum.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), input(dm))]
#[dirac(lagrangian = 0.5 * (m + dm) * v * v - 0.5 * k * x * x)]
pub struct AdjustableMass {
    pub m: f64,
    pub dm: f64,
    pub k: f64,
}

/// Two forced springs whose ends are joined: the composite's inputs are `left.f` and `right.f`.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(left.x, right.x))]
pub struct ForcedPair {
    pub left: ForcedSpring,
    pub right: ForcedSpring,
}

/// An L-C loop with charges as coordinates: a degenerate Lagrangian (the capacitor's charge has
/// no inductance) closed by Kirchhoff's current law `i_l − i_c = 0` as a velocity constraint.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(q_l => i_l, q_c => i_c))]
#[dirac(lagrangian = 0.5 * ind * i_l * i_l - 0.5 * q_c * q_c / cap)]
#[dirac(constraint(kcl) = i_l - i_c)]
pub struct LcCircuit {
    pub ind: f64,
    pub cap: f64,
}

/// An 8-link planar pendulum in absolute angle coordinates (θ from the downward vertical),
/// equal masses m at the joints and equal lengths l:
/// `L = ½ Σ_ij (8 − max(i, j)) m l² ω_i ω_j cos(θ_i − θ_j) + g Σ_i (8 − i) m l cos θ_i`
/// (0-based i, j), written out term by term.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(th1 => w1, th2 => w2, th3 => w3, th4 => w4, th5 => w5, th6 => w6, th7 => w7, th8 => w8))]
#[dirac(lagrangian = 0.5 * 8.0 * m * l * l * w1 * w1
        + 0.5 * 7.0 * m * l * l * w2 * w2
        + 0.5 * 6.0 * m * l * l * w3 * w3
        + 0.5 * 5.0 * m * l * l * w4 * w4
        + 0.5 * 4.0 * m * l * l * w5 * w5
        + 0.5 * 3.0 * m * l * l * w6 * w6
        + 0.5 * 2.0 * m * l * l * w7 * w7
        + 0.5 * 1.0 * m * l * l * w8 * w8
        + 7.0 * m * l * l * w1 * w2 * (th1 - th2).cos()
        + 6.0 * m * l * l * w1 * w3 * (th1 - th3).cos()
        + 5.0 * m * l * l * w1 * w4 * (th1 - th4).cos()
        + 4.0 * m * l * l * w1 * w5 * (th1 - th5).cos()
        + 3.0 * m * l * l * w1 * w6 * (th1 - th6).cos()
        + 2.0 * m * l * l * w1 * w7 * (th1 - th7).cos()
        + 1.0 * m * l * l * w1 * w8 * (th1 - th8).cos()
        + 6.0 * m * l * l * w2 * w3 * (th2 - th3).cos()
        + 5.0 * m * l * l * w2 * w4 * (th2 - th4).cos()
        + 4.0 * m * l * l * w2 * w5 * (th2 - th5).cos()
        + 3.0 * m * l * l * w2 * w6 * (th2 - th6).cos()
        + 2.0 * m * l * l * w2 * w7 * (th2 - th7).cos()
        + 1.0 * m * l * l * w2 * w8 * (th2 - th8).cos()
        + 5.0 * m * l * l * w3 * w4 * (th3 - th4).cos()
        + 4.0 * m * l * l * w3 * w5 * (th3 - th5).cos()
        + 3.0 * m * l * l * w3 * w6 * (th3 - th6).cos()
        + 2.0 * m * l * l * w3 * w7 * (th3 - th7).cos()
        + 1.0 * m * l * l * w3 * w8 * (th3 - th8).cos()
        + 4.0 * m * l * l * w4 * w5 * (th4 - th5).cos()
        + 3.0 * m * l * l * w4 * w6 * (th4 - th6).cos()
        + 2.0 * m * l * l * w4 * w7 * (th4 - th7).cos()
        + 1.0 * m * l * l * w4 * w8 * (th4 - th8).cos()
        + 3.0 * m * l * l * w5 * w6 * (th5 - th6).cos()
        + 2.0 * m * l * l * w5 * w7 * (th5 - th7).cos()
        + 1.0 * m * l * l * w5 * w8 * (th5 - th8).cos()
        + 2.0 * m * l * l * w6 * w7 * (th6 - th7).cos()
        + 1.0 * m * l * l * w6 * w8 * (th6 - th8).cos()
        + 1.0 * m * l * l * w7 * w8 * (th7 - th8).cos()
        + 8.0 * m * g * l * th1.cos()
        + 7.0 * m * g * l * th2.cos()
        + 6.0 * m * g * l * th3.cos()
        + 5.0 * m * g * l * th4.cos()
        + 4.0 * m * g * l * th5.cos()
        + 3.0 * m * g * l * th6.cos()
        + 2.0 * m * g * l * th7.cos()
        + 1.0 * m * g * l * th8.cos())]
pub struct Pendulum8 {
    pub m: f64,
    pub l: f64,
    pub g: f64,
}

/// The 8-link pendulum of [`Pendulum8`] with a torque at each joint: `u_1` between the ground
/// and the first link, `u_i` between links `i - 1` and `i`, so that in absolute angles link
/// `i` feels `u_i - u_(i+1)`. For the optimal control benchmarks.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(th1 => w1, th2 => w2, th3 => w3, th4 => w4, th5 => w5, th6 => w6, th7 => w7, th8 => w8))]
#[dirac(input(u1, u2, u3, u4, u5, u6, u7, u8))]
#[dirac(force(th1) = u1 - u2, force(th2) = u2 - u3, force(th3) = u3 - u4, force(th4) = u4 - u5, force(th5) = u5 - u6, force(th6) = u6 - u7, force(th7) = u7 - u8, force(th8) = u8)]
#[dirac(lagrangian = 0.5 * 8.0 * m * l * l * w1 * w1
        + 0.5 * 7.0 * m * l * l * w2 * w2
        + 0.5 * 6.0 * m * l * l * w3 * w3
        + 0.5 * 5.0 * m * l * l * w4 * w4
        + 0.5 * 4.0 * m * l * l * w5 * w5
        + 0.5 * 3.0 * m * l * l * w6 * w6
        + 0.5 * 2.0 * m * l * l * w7 * w7
        + 0.5 * 1.0 * m * l * l * w8 * w8
        + 7.0 * m * l * l * w1 * w2 * (th1 - th2).cos()
        + 6.0 * m * l * l * w1 * w3 * (th1 - th3).cos()
        + 5.0 * m * l * l * w1 * w4 * (th1 - th4).cos()
        + 4.0 * m * l * l * w1 * w5 * (th1 - th5).cos()
        + 3.0 * m * l * l * w1 * w6 * (th1 - th6).cos()
        + 2.0 * m * l * l * w1 * w7 * (th1 - th7).cos()
        + 1.0 * m * l * l * w1 * w8 * (th1 - th8).cos()
        + 6.0 * m * l * l * w2 * w3 * (th2 - th3).cos()
        + 5.0 * m * l * l * w2 * w4 * (th2 - th4).cos()
        + 4.0 * m * l * l * w2 * w5 * (th2 - th5).cos()
        + 3.0 * m * l * l * w2 * w6 * (th2 - th6).cos()
        + 2.0 * m * l * l * w2 * w7 * (th2 - th7).cos()
        + 1.0 * m * l * l * w2 * w8 * (th2 - th8).cos()
        + 5.0 * m * l * l * w3 * w4 * (th3 - th4).cos()
        + 4.0 * m * l * l * w3 * w5 * (th3 - th5).cos()
        + 3.0 * m * l * l * w3 * w6 * (th3 - th6).cos()
        + 2.0 * m * l * l * w3 * w7 * (th3 - th7).cos()
        + 1.0 * m * l * l * w3 * w8 * (th3 - th8).cos()
        + 4.0 * m * l * l * w4 * w5 * (th4 - th5).cos()
        + 3.0 * m * l * l * w4 * w6 * (th4 - th6).cos()
        + 2.0 * m * l * l * w4 * w7 * (th4 - th7).cos()
        + 1.0 * m * l * l * w4 * w8 * (th4 - th8).cos()
        + 3.0 * m * l * l * w5 * w6 * (th5 - th6).cos()
        + 2.0 * m * l * l * w5 * w7 * (th5 - th7).cos()
        + 1.0 * m * l * l * w5 * w8 * (th5 - th8).cos()
        + 2.0 * m * l * l * w6 * w7 * (th6 - th7).cos()
        + 1.0 * m * l * l * w6 * w8 * (th6 - th8).cos()
        + 1.0 * m * l * l * w7 * w8 * (th7 - th8).cos()
        + 8.0 * m * g * l * th1.cos()
        + 7.0 * m * g * l * th2.cos()
        + 6.0 * m * g * l * th3.cos()
        + 5.0 * m * g * l * th4.cos()
        + 4.0 * m * g * l * th5.cos()
        + 3.0 * m * g * l * th6.cos()
        + 2.0 * m * g * l * th7.cos()
        + 1.0 * m * g * l * th8.cos())]
pub struct Chain8 {
    pub m: f64,
    pub l: f64,
    pub g: f64,
    pub u1: f64,
    pub u2: f64,
    pub u3: f64,
    pub u4: f64,
    pub u5: f64,
    pub u6: f64,
    pub u7: f64,
    pub u8: f64,
}

/// A model that uses every supported function and spelling, with arguments kept in their
/// domains for any state, so its generated derivatives can be checked everywhere.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(a => va, b => vb, c => vc))]
#[dirac(lagrangian = 0.5 * m * (1.0 + 0.25 * a.sin().powi(2)) * va * va
                   + 0.5 * m * vb * vb / (1.0 + c * c) + 0.5 * (2.0 + vc.tanh()) * vc * vc
                   - k * (a.cos() + sqrt(1.0 + b * b) + (1.0 + a * a).ln() + b.exp() * 0.1)
                   + k * atan2(a, 2.0 + b * b) + k * (0.5 * c).tan() + k * c.atan()
                   + k * (a * b).sinh() * 0.1 + k * f64::cosh(0.5 * c) + (1.0 + b * b).powf(0.75)
                   + (2.0 + a * a).powf(0.1 * b) + std::f64::consts::PI * k * (1.0 + c * c).powi(-2))]
#[dirac(holonomic(link) = a * a + b - c.sin())]
#[dirac(constraint(slide) = vb * a.cos() - vc * (1.0 + a * a))]
#[dirac(force(a) = -k * va * (t * 0.5).cos())]
#[dirac(force(c) = -k * vc.powi(3) + b / (1.0 + t * t))]
pub struct AllFunctions {
    pub m: f64,
    pub k: f64,
}

/// The paper's example torn and interconnected: primitive systems 1 and 2 joined at the ports
/// x2 and x̄2 (v2 = v̄2, f2 + f̄2 = 0).
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(left.x2, right.x2bar))]
pub struct Chain {
    pub left: Primitive1,
    pub right: Primitive2,
}

/// The paper's chain extended by one mass: wall —k1— m1 —k2— m2 —k3— m3 —k4— m4 —k5— m5,
/// as one model; the reference for the three-level hierarchy below.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x1 => v1, x2 => v2, x3 => v3, x4 => v4, x5 => v5))]
#[dirac(lagrangian = 0.5 * (m1 * v1 * v1 + m2 * v2 * v2 + m3 * v3 * v3 + m4 * v4 * v4 + m5 * v5 * v5)
                   - 0.5 * (k1 * x1 * x1 + k2 * (x2 - x1).powi(2) + k3 * (x3 - x2).powi(2)
                            + k4 * (x4 - x3).powi(2) + k5 * (x5 - x4).powi(2)))]
pub struct MassSpringChain5 {
    pub m1: f64,
    pub m2: f64,
    pub m3: f64,
    pub m4: f64,
    pub m5: f64,
    pub k1: f64,
    pub k2: f64,
    pub k3: f64,
    pub k4: f64,
    pub k5: f64,
}

/// A spring and a mass hanging off a port: x̄ —k— m. Degenerate like primitive system 2.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(xbar => vbar, x => v), port(xbar, x))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * (x - xbar).powi(2))]
pub struct Tail {
    pub m: f64,
    pub k: f64,
}

/// Level 1 of a hierarchy: the paper's chain built from primitive system 1 and a tail, whose
/// free end stays a port.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(left.x2, right.xbar))]
pub struct Chain3 {
    pub left: Primitive1,
    pub right: Tail,
}

/// Level 2: a tail attached to the level-1 chain's last mass.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(head.right.x, tail.xbar))]
pub struct Chain4 {
    pub head: Chain3,
    pub tail: Tail,
}

/// Level 3: another tail attached to the level-2 composite's last mass.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(body.tail.x, end.xbar))]
pub struct Chain5 {
    pub body: Chain4,
    pub end: Tail,
}

/// A wheel on a torsion spring.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(theta => v_theta))]
#[dirac(lagrangian = 0.5 * j * v_theta * v_theta - 0.5 * k_theta * theta * theta)]
pub struct Wheel {
    pub j: f64,
    pub k_theta: f64,
}

/// A cart on a spring.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v_x))]
#[dirac(lagrangian = 0.5 * m * v_x * v_x - 0.5 * k * x * x)]
pub struct Cart {
    pub m: f64,
    pub k: f64,
}

/// A rack and pinion: the cart moves r per radian of the wheel, `r θ̇ − ẋ = 0`.
#[derive(Interconnection, Clone, Debug)]
#[dirac(constraint(gear) = r * wheel.v_theta - cart.v_x)]
pub struct RackAndPinion {
    pub wheel: Wheel,
    pub cart: Cart,
    pub r: f64,
}

/// The rack and pinion by hand, in the wheel angle alone (x = r θ substituted).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(theta => v_theta))]
#[dirac(lagrangian = 0.5 * (j + m * r * r) * v_theta * v_theta - 0.5 * (k_theta + k * r * r) * theta * theta)]
pub struct GearedByHand {
    pub j: f64,
    pub k_theta: f64,
    pub m: f64,
    pub k: f64,
    pub r: f64,
}

/// A wheel and a cart joined by a one-form whose coefficients depend on both subsystems'
/// coordinates and on a parameter: it exercises every interconnection block (A, ∂(Av)/∂q,
/// ∂(Aᵀμ)/∂q across subsystems).
#[derive(Interconnection, Clone, Debug)]
#[dirac(constraint(tie) = (1.0 + 0.1 * wheel.theta.sin()) * wheel.v_theta - c * cart.x.cos() * cart.v_x)]
pub struct CoupledByOneForm {
    pub wheel: Wheel,
    pub cart: Cart,
    pub c: f64,
}

/// Two masses joined by a spring, free in space: invariant under translation, so the total
/// momentum p1 + p2 is a momentum map.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x1 => v1, x2 => v2))]
#[dirac(lagrangian = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2 - 0.5 * k * (x2 - x1 - d).powi(2))]
pub struct FreeSpring {
    pub m1: f64,
    pub m2: f64,
    pub k: f64,
    pub d: f64,
}

/// A spherical pendulum in Cartesian coordinates: invariant under rotation about the vertical,
/// so the angular momentum x p_y − y p_x is a momentum map.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy, z => vz))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy + vz * vz) - m * g * z)]
#[dirac(holonomic(rod) = x * x + y * y + z * z - l * l)]
pub struct SphericalPendulum {
    pub m: f64,
    pub g: f64,
    pub l: f64,
}

/// The paper's torn chain with m = (1, 2, 3), k = (4, 5, 6).
pub fn paper_chain() -> Chain {
    Chain { left: Primitive1 { m1: 1.0, m2: 2.0, k1: 4.0, k2: 5.0 }, right: Primitive2 { m3: 3.0, k3: 6.0 } }
}

/// The paper's initial state: x1 = 0.1, everything else at rest, made consistent.
pub fn paper_chain_start(chain: &Chain) -> State<Chain> {
    let mut q = VecQ::<Chain>::zeros();
    q[Chain::left(Primitive1::X1).index()] = 0.1;
    consistent_state(chain, 0.0, &q, &VecQ::<Chain>::zeros(), Consistency::default())
        .expect("a consistent start")
}

/// The pendulum of DESIGN.md §3: l = 1, g = 9.81, m = 1.
pub fn unit_pendulum() -> Pendulum {
    Pendulum { m: 1.0, g: 9.81, l: 1.0 }
}

/// Released from rest at the horizontal, x = 1, y = 0.
pub fn horizontal_start(p: &Pendulum) -> State<Pendulum> {
    consistent_state(
        p,
        0.0,
        &VecQ::<Pendulum>::new(1.0, 0.0),
        &VecQ::<Pendulum>::zeros(),
        Consistency::default(),
    )
    .expect("a consistent start")
}

/// A double pendulum in Cartesian coordinates with two rods (holonomic constraints).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x1 => vx1, y1 => vy1, x2 => vx2, y2 => vy2))]
#[dirac(lagrangian = 0.5 * m1 * (vx1 * vx1 + vy1 * vy1) + 0.5 * m2 * (vx2 * vx2 + vy2 * vy2)
                   - g * (m1 * y1 + m2 * y2))]
#[dirac(holonomic(rod1) = x1 * x1 + y1 * y1 - l1 * l1)]
#[dirac(holonomic(rod2) = (x2 - x1).powi(2) + (y2 - y1).powi(2) - l2 * l2)]
pub struct DoublePendulum {
    pub m1: f64,
    pub m2: f64,
    pub l1: f64,
    pub l2: f64,
    pub g: f64,
}

/// A mass on a spring seen from a frame that moves at the velocity `u0 cos(w t)`: the
/// Lagrangian depends on time through the velocity, so `∂(∂L/∂v)/∂t` is not zero.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), port(x))]
#[dirac(lagrangian = 0.5 * m * (v + u0 * (w * t).cos()).powi(2) - 0.5 * k * x * x)]
pub struct MovingFrame {
    pub m: f64,
    pub k: f64,
    pub u0: f64,
    pub w: f64,
}

/// Two masses in moving frames joined at their ports.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(first.x, second.x))]
pub struct FramedPair {
    pub first: MovingFrame,
    pub second: MovingFrame,
}

/// A four-bar linkage in the angles of its links (crank θ1 on a pivot at the origin, coupler
/// θ2, rocker θ3 on a pivot at (d, 0)), each a uniform rod with mass, under gravity. The
/// coupler's kinetic energy has a `cos(θ1 − θ2)` cross term, so the mass matrix depends on the
/// configuration; the loop closes through two holonomic constraints: a closed-loop mechanism.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(th1 => w1, th2 => w2, th3 => w3))]
#[dirac(lagrangian = 0.5 * (m1 * l1 * l1 / 3.0) * w1 * w1
        + 0.5 * m2 * (l1 * l1 * w1 * w1 + 0.25 * l2 * l2 * w2 * w2 + l1 * l2 * w1 * w2 * (th1 - th2).cos())
        + 0.5 * (m2 * l2 * l2 / 12.0) * w2 * w2
        + 0.5 * (m3 * l3 * l3 / 3.0) * w3 * w3
        - g * (0.5 * m1 * l1 * th1.sin() + m2 * (l1 * th1.sin() + 0.5 * l2 * th2.sin()) + 0.5 * m3 * l3 * th3.sin()))]
#[dirac(holonomic(loop_x) = l1 * th1.cos() + l2 * th2.cos() - l3 * th3.cos() - d)]
#[dirac(holonomic(loop_y) = l1 * th1.sin() + l2 * th2.sin() - l3 * th3.sin())]
pub struct FourBar {
    pub m1: f64,
    pub m2: f64,
    pub m3: f64,
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub d: f64,
    pub g: f64,
}

/// A four-bar with a crank-rocker geometry (Grashof: the crank turns fully).
pub fn four_bar() -> FourBar {
    FourBar { m1: 0.5, m2: 1.0, m3: 0.8, l1: 0.2, l2: 0.6, l3: 0.5, d: 0.5, g: 9.81 }
}

/// The crank at 60° turning at 2 rad/s; coupler and rocker angles and rates made consistent.
pub fn four_bar_start(model: &FourBar) -> State<FourBar> {
    let q = VecQ::<FourBar>::new(std::f64::consts::FRAC_PI_3, 0.4, 1.7);
    let v = VecQ::<FourBar>::new(2.0, 0.0, 0.0);
    consistent_state(model, 0.0, &q, &v, Consistency::default()).expect("a consistent start")
}

/// One section of the ladder: a series inductor from the previous node (`a`) to this node
/// (`b`), and a capacitor from this node to ground. Coordinates are node fluxes, so their
/// velocities are node voltages.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(a => va, b => vb), port(a, b))]
#[dirac(lagrangian = 0.5 * c * vb * vb - (b - a) * (b - a) / (2.0 * l))]
pub struct Cell {
    pub l: f64,
    pub c: f64,
}

/// The ground node: its flux held at zero.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(g => vg), port(g))]
#[dirac(lagrangian = 0.0 * vg)]
#[dirac(holonomic(grounded) = g)]
pub struct Ground {}

/// `cells.len()` sections between ground and an open end.
#[derive(Interconnection, Clone)]
#[dirac(connect(ground.g, cells[0].a), connect(cells[i].b, cells[i + 1].a))]
pub struct Ladder {
    pub ground: Ground,
    pub cells: Vec<Cell>,
}

/// A ladder of `n` unit cells.
pub fn unit_ladder(n: usize) -> Ladder {
    Ladder { ground: Ground {}, cells: vec![Cell { l: 1.0, c: 1.0 }; n] }
}

/// The same ladder assembled while the program runs: a ground `gnd` and cells `c0`, `c1`, …
/// added and connected in the derived ladder's order, so that its coordinates and rows are
/// the derived ladder's, one for one.
pub fn network_ladder(n: usize) -> dirac::network::Network {
    let mut b = dirac::network::Network::builder();
    b.add("gnd", Ground {}).expect("a new name");
    for j in 0..n {
        b.add(&format!("c{j}"), Cell { l: 1.0, c: 1.0 }).expect("a new name");
    }
    if n > 0 {
        b.connect("gnd.g", "c0.a").expect("existing ports");
    }
    for j in 1..n {
        b.connect(&format!("c{}.b", j - 1), &format!("c{j}.a")).expect("existing ports");
    }
    b.finish().expect("a network")
}

/// The ladder's consistent state with node fluxes `x` (cell by cell) at rest.
pub fn ladder_at_rest(ladder: &Ladder, x: &[f64]) -> State<Ladder> {
    let sizes = ladder.sizes();
    let mut q = sizes.zeros_q::<Ladder>();
    for (j, &xj) in x.iter().enumerate() {
        q[ladder.cells(j, Cell::B).index()] = xj;
        if j + 1 < x.len() {
            q[ladder.cells(j + 1, Cell::A).index()] = xj;
        }
    }
    let v = sizes.zeros_q::<Ladder>();
    consistent_state(ladder, 0.0, &q, &v, Consistency::default()).expect("a consistent start")
}

/// The ladder's node fluxes `x_1 … x_N` (`x_0 = 0` is ground) obey `C ẍ = −(1/L) T x` with
/// `T` tridiagonal (2 on the diagonal, 1 in the last row for the open end, −1 beside it).
/// `T` has the eigenpairs `λ_k = 4 sin²(θ_k / 2)`, `u_k(j) = sin(j θ_k)` with
/// `θ_k = (2k − 1)π / (2N + 1)`; each is checked here against `T` itself before it is used.
/// Returns `x(t)` for `x(0) = x0`, `ẋ(0) = 0`.
pub fn modal_solution(x0: &[f64], l: f64, c: f64, t: f64) -> Vec<f64> {
    let n = x0.len();
    let mut x = vec![0.0; n];
    let mut u = vec![0.0; n];
    for k in 1..=n {
        let theta = (2 * k - 1) as f64 * std::f64::consts::PI / (2 * n + 1) as f64;
        let lambda = 4.0 * (theta / 2.0).sin().powi(2);
        for (j, uj) in u.iter_mut().enumerate() {
            *uj = ((j + 1) as f64 * theta).sin();
        }
        for j in 0..n {
            let left = if j == 0 { 0.0 } else { u[j - 1] };
            let (diagonal, right) = if j + 1 == n { (1.0, 0.0) } else { (2.0, u[j + 1]) };
            let tu = diagonal * u[j] - left - right;
            // sin(j θ) is evaluated to about j θ ε.
            assert!(
                (tu - lambda * u[j]).abs() < 1e-14 * n as f64 + 1e-12,
                "mode {k} is not an eigenvector of T"
            );
        }
        let norm: f64 = u.iter().map(|v| v * v).sum();
        let coefficient = u.iter().zip(x0).map(|(a, b)| a * b).sum::<f64>() / norm;
        let omega = (lambda / (l * c)).sqrt();
        let factor = coefficient * (omega * t).cos();
        for (xj, uj) in x.iter_mut().zip(&u) {
            *xj += factor * uj;
        }
    }
    x
}

/// A smooth pulse of node fluxes, five nodes wide, centred a third of the way down a ladder
/// of `n` nodes: it splits into two waves that travel one node per unit time.
pub fn pulse(n: usize) -> Vec<f64> {
    let (centre, width) = (n as f64 / 3.0, 5.0);
    (1..=n).map(|j| (-((j as f64 - centre) / width).powi(2)).exp()).collect()
}

/// A ball moving vertically under gravity `g`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(y => v))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * y)]
pub struct Ball {
    pub m: f64,
    pub g: f64,
}

/// An undamped oscillator, `x = x0 cos(√(k/m) t)`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
pub struct Oscillator {
    pub m: f64,
    pub k: f64,
}

/// A particle in an anharmonic well, `V = ½ k (x² + y²) + c x² y²`, whose coupling makes
/// its motion irregular: the particle of a billiard with a potential.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - 0.5 * k * (x * x + y * y) - c * x * x * y * y)]
pub struct Well {
    pub m: f64,
    pub k: f64,
    pub c: f64,
}

/// A ball above a floor it bounces on with restitution `e`: the contact `y ≥ 0`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(y => v))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * y)]
#[dirac(unilateral(floor, restitution = e) = y)]
pub struct BouncingBall {
    pub m: f64,
    pub g: f64,
    pub e: f64,
}

/// A pendulum on a rod of length `l` that strikes the wall `x = w` (from `x > w`) with
/// restitution `e`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(rod) = x * x + y * y - l * l)]
#[dirac(unilateral(wall, restitution = e) = x - w)]
pub struct PendulumAndWall {
    pub m: f64,
    pub g: f64,
    pub l: f64,
    pub e: f64,
    pub w: f64,
}

/// A bar of length `l` moving in a vertical plane above a floor, which each of its ends
/// strikes with restitution `e`: its centre `(x, y)`, its angle `th` from the horizontal.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy, th => w))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) + 0.5 * j * w * w - m * g * y)]
#[dirac(unilateral(left, restitution = e) = y - 0.5 * l * th.sin())]
#[dirac(unilateral(right, restitution = e) = y + 0.5 * l * th.sin())]
pub struct Bar {
    pub m: f64,
    pub j: f64,
    pub g: f64,
    pub l: f64,
    pub e: f64,
}

/// A pendulum on a string, whirled: the string goes slack when its tension, the rod's
/// multiplier (`λ < 0` pulls), vanishes; both events are declared on the model.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(rod) = x * x + y * y - l * l)]
#[dirac(event(slack, rising) = rod)]
#[dirac(event(level) = y)]
pub struct Sling {
    pub m: f64,
    pub g: f64,
    pub l: f64,
}

/// A ball with a port at its height, a floor and an apex event.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(y => v), port(y))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * y)]
#[dirac(unilateral(floor, restitution = e) = y)]
#[dirac(event(apex, falling) = v)]
pub struct PortedBall {
    pub m: f64,
    pub g: f64,
    pub e: f64,
}

/// A free mass with a port.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(z => w), port(z))]
#[dirac(lagrangian = 0.5 * m * w * w)]
pub struct Load {
    pub m: f64,
}

/// A ball carrying a load: the two move as one body of mass `m_ball + m_load` pulled down by
/// the ball's weight alone, on the ball's floor.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(ball.y, load.z))]
pub struct LoadedBall {
    pub ball: PortedBall,
    pub load: Load,
}

/// A ball on a floor, its contact a holonomic row that a parameter switches: the row
/// `a y + (1 − a) s` holds the ball on the floor when `a = 1` (its multiplier is then the
/// contact force) and, when `a = 0`, holds only the slack coordinate `s`, of unit mass, which
/// stays at rest, so that the multiplier vanishes and the ball moves freely. Switching `a` at
/// an event is a change of the model. A force `f0 sin(ω t)` pulls the ball up.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(y => v, s => w))]
#[dirac(lagrangian = 0.5 * m * v * v + 0.5 * w * w - m * g * y)]
#[dirac(holonomic(floor) = a * y + (1.0 - a) * s)]
#[dirac(force(y) = f0 * (om * t).sin())]
pub struct SwitchedFloor {
    pub m: f64,
    pub g: f64,
    pub a: f64,
    pub f0: f64,
    pub om: f64,
}

/// A ball on a floor it bounces on with restitution `e`, pulled up by `f0 sin(ω t)`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(y => v))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * y)]
#[dirac(force(y) = f0 * (om * t).sin())]
#[dirac(unilateral(floor, restitution = e) = y)]
pub struct LiftedBall {
    pub m: f64,
    pub g: f64,
    pub e: f64,
    pub f0: f64,
    pub om: f64,
}

/// A DC motor without armature inductance under an alternating voltage: its current `i` has
/// no inertia and the armature's resistance fixes it (`k w = u − r i`); `j ẇ = k i − b w`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(q => i, th => w))]
#[dirac(lagrangian = 0.5 * j * w * w + k * i * th)]
#[dirac(dissipation = 0.5 * r * i * i + 0.5 * b * w * w)]
#[dirac(force(q) = u0 * (om * t).sin())]
pub struct AcMotor {
    pub r: f64,
    pub k: f64,
    pub j: f64,
    pub b: f64,
    pub u0: f64,
    pub om: f64,
}

/// Every non-smooth function and conditional: a spring with a dead zone and an `abs` spring
/// (switching on positions, in the Lagrangian), saturated damping, a sign-dependent friction
/// with `min` and `max` in its coefficient, and conditionals in the forces and dissipation.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v, y => w))]
#[dirac(lagrangian = 0.5 * m * (v * v + w * w)
    - (if x > gap { 0.5 * k * (x - gap).powi(2) } else if x < -gap { 0.5 * k * (x + gap).powi(2) } else { 0.0 })
    - k * y.abs().powi(3))]
#[dirac(force(x) = (-c * v).clamp(-fmax, fmax) - mu * v.signum() * (1.0 + x.max(y).min(2.0)))]
#[dirac(force(y) = if w >= 0.0 { -c * w * w } else { c * w * w } + max(x - y, 0.0))]
#[dirac(dissipation = 0.5 * c * (if w - v <= 0.0 { 2.0 * (w - v).powi(2) } else { (w - v).powi(2) }))]
pub struct NonSmooth {
    pub m: f64,
    pub k: f64,
    pub gap: f64,
    pub c: f64,
    pub fmax: f64,
    pub mu: f64,
}

/// A mass driven to `r` by a PD controller whose force saturates at `±fmax`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v)]
#[dirac(force(x) = (kp * (r - x) - kd * v).clamp(-fmax, fmax))]
pub struct SaturatedServo {
    pub m: f64,
    pub kp: f64,
    pub kd: f64,
    pub r: f64,
    pub fmax: f64,
}

/// A mass on a spring with Coulomb friction `mu` (a force that jumps where the velocity
/// changes sign, a switching surface on a velocity) and a brake `f` past `x = a` (one on a
/// position).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(force(x) = -mu * v.signum() + if x > a { -f } else { 0.0 })]
pub struct CoulombSpring {
    pub m: f64,
    pub k: f64,
    pub mu: f64,
    pub a: f64,
    pub f: f64,
}

/// A pendulum on a rod of length `l` whose damper `c` engages past `x = w`: its force jumps
/// from zero to `−c vx` there.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(rod) = x * x + y * y - l * l)]
#[dirac(force(x) = if x > w { -c * vx } else { 0.0 })]
pub struct DampedPastW {
    pub m: f64,
    pub g: f64,
    pub l: f64,
    pub w: f64,
    pub c: f64,
}

/// Two Coulomb springs whose speeds differ by `c`: their friction and brake surfaces, in an
/// interconnection, each part's parameters at its offset among the composite's.
#[derive(Interconnection, Clone, Debug)]
#[dirac(constraint(link) = right.v - left.v - c)]
pub struct CoulombPair {
    pub left: CoulombSpring,
    pub right: CoulombSpring,
    pub c: f64,
}

/// A mass on a spring whose other end is driven at a speed that steps from zero to `u` at
/// `t = t1`: a switching surface in a constraint, across which the velocities jump.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v, y => w))]
#[dirac(lagrangian = 0.5 * m * v * v + 0.5 * w * w - 0.5 * k * (x - y) * (x - y))]
#[dirac(constraint(drive) = w - if t > t1 { u } else { 0.0 })]
pub struct SteppedDrive {
    pub m: f64,
    pub k: f64,
    pub u: f64,
    pub t1: f64,
}

/// A mass on a belt moving at `vb`, held by a spring to the wall, with Coulomb friction and
/// stiction as the law `grip`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(friction(grip, kinetic = mu_k * n, stiction = mu_s * n) = v - vb)]
pub struct FrictionBelt {
    pub m: f64,
    pub k: f64,
    pub vb: f64,
    pub n: f64,
    pub mu_s: f64,
    pub mu_k: f64,
}

/// A block of mass `m` on a slope of angle `slope`, `x` down the slope and `y` off it: the row
/// `floor` holds it on the slope (its multiplier the contact force) and Coulomb friction on
/// that force, `μ λ_floor`, resists its slip. A force `push t` along the slope grows with time.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) + m * g * (x * sin(slope) - y * cos(slope)))]
#[dirac(force(x) = push * t)]
#[dirac(holonomic(floor) = y)]
#[dirac(friction(slide, kinetic = mu * floor) = vx)]
pub struct SlopeBlock {
    pub m: f64,
    pub g: f64,
    pub slope: f64,
    pub mu: f64,
    pub push: f64,
}

/// A ball of mass `m` and radius `r` (moment of inertia `2/5 m r²`) on a slope of angle
/// `slope`, `x` down the slope, `y` off it, `phi` its turn: the row `floor` holds it on the
/// slope and Coulomb friction on the contact force, `μ λ_floor`, acts where it touches, whose
/// velocity is `vx − r w`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy, phi => w))]
#[dirac(
    lagrangian = 0.5 * m * (vx * vx + vy * vy) + 0.2 * m * r * r * w * w
        + m * g * (x * sin(slope) - y * cos(slope))
)]
#[dirac(holonomic(floor) = y)]
#[dirac(friction(touch, kinetic = mu * floor) = vx - r * w)]
pub struct SlopeBall {
    pub m: f64,
    pub g: f64,
    pub r: f64,
    pub slope: f64,
    pub mu: f64,
}

/// A puck of mass `m` on the floor `z = 0` under Coulomb's isotropic friction cone on the
/// contact force, `μ λ_floor` against the slip `(vx, vy)`; pushed with `push t` along the
/// direction `angle` and with the constant `side` at right angles to it.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy, z => vz))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy + vz * vz) - m * g * z)]
#[dirac(holonomic(floor) = z)]
#[dirac(force(x) = push * t * cos(angle) - side * sin(angle))]
#[dirac(force(y) = push * t * sin(angle) + side * cos(angle))]
#[dirac(friction(slip, kinetic = mu * floor) = (vx, vy))]
#[dirac(nonnegative(mu))]
pub struct Puck {
    pub m: f64,
    pub g: f64,
    pub mu: f64,
    pub push: f64,
    pub angle: f64,
    pub side: f64,
}

/// [`Puck`] with a kinetic force that names no row, `μ m g`: Coulomb's cone as a force of the
/// state (its push is in `force`, not in the slip rows).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy))]
#[dirac(force(y) = side)]
#[dirac(friction(slip, kinetic = mu * m * g) = (vx, vy))]
pub struct FlatPuck {
    pub m: f64,
    pub g: f64,
    pub mu: f64,
    pub side: f64,
}

/// A puck that tows a load along x, so its inertia is `mx` along x and `my` along y, pushed by
/// the constant force `(fx, fy)` under Coulomb's cone of the fixed bound `bound`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * (mx * vx * vx + my * vy * vy))]
#[dirac(force(x) = fx)]
#[dirac(force(y) = fy)]
#[dirac(friction(slip, kinetic = bound) = (vx, vy))]
pub struct TowingPuck {
    pub mx: f64,
    pub my: f64,
    pub fx: f64,
    pub fy: f64,
    pub bound: f64,
}

/// A symmetric top on the floor, its point tip held on it (the row `floor`) under Coulomb's
/// cone on the contact force: centre of mass `(x, y, z)`, ZXZ Euler angles (`psi` precession,
/// `theta` tilt, `phi` spin), the tip at `l` below the centre along the axis; mass `m`,
/// moments `a` across the axis and `c` about it, both at the centre. The tip's velocity on the
/// floor is the centre's less `l` times the axis' rate.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy, z => vz, psi => wpsi, theta => wtheta, phi => wphi))]
#[dirac(
    lagrangian = 0.5 * m * (vx * vx + vy * vy + vz * vz)
        + 0.5 * a * (wtheta * wtheta + wpsi * wpsi * sin(theta) * sin(theta))
        + 0.5 * c * (wphi + wpsi * cos(theta)) * (wphi + wpsi * cos(theta))
        - m * g * z
)]
#[dirac(holonomic(floor) = z - l * cos(theta))]
#[dirac(friction(tip, kinetic = mu * floor) = (
    vx - l * (cos(theta) * wtheta * sin(psi) + sin(theta) * cos(psi) * wpsi),
    vy + l * (cos(theta) * wtheta * cos(psi) - sin(theta) * sin(psi) * wpsi)
))]
#[dirac(nonnegative(mu))]
pub struct GroundTop {
    pub m: f64,
    pub g: f64,
    pub l: f64,
    pub a: f64,
    pub c: f64,
    pub mu: f64,
}

/// A cart of mass `mc` pushed by `f`, with a pole of mass `mp` at distance `l` hinged on it;
/// `theta` is measured from hanging straight down.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, theta => w), input(f))]
#[dirac(lagrangian = 0.5 * (mc + mp) * vx * vx + mp * l * vx * w * cos(theta) + 0.5 * mp * l * l * w * w
    + mp * g * l * cos(theta))]
#[dirac(force(x) = f)]
pub struct CartPole {
    pub mc: f64,
    pub mp: f64,
    pub l: f64,
    pub g: f64,
    pub f: f64,
}

/// The cart-pole of the optimal control tests and benchmarks: a 1 kg cart, a 0.3 kg pole
/// 0.5 m from the hinge.
pub fn cart_pole() -> CartPole {
    CartPole { mc: 1.0, mp: 0.3, l: 0.5, g: 9.81, f: 0.0 }
}

/// The receding-horizon problem of the MPC test and benchmark: keep the cart-pole upright and
/// centred over a 1 s horizon on `intervals` intervals (midpoint and terminal weights on the
/// positions, light ones on the velocities and the push), the push within ±20 N and the cart
/// within ±1.5 m.
pub fn cart_pole_balance(intervals: usize) -> dirac::optimal::Problem<CartPole> {
    let upright = std::f64::consts::PI;
    dirac::optimal::Problem::new(cart_pole(), 1.0, intervals)
        .position_weight(CartPole::X, 1.0, 0.0)
        .position_weight(CartPole::THETA, 20.0, upright)
        .velocity_weight(CartPole::X, 0.1, 0.0)
        .velocity_weight(CartPole::THETA, 0.1, 0.0)
        .terminal_weight(CartPole::X, 10.0, 0.0)
        .terminal_weight(CartPole::THETA, 100.0, upright)
        .input_weight(CartPole::F, 0.01)
        .position_bounds(CartPole::X, -1.5, 1.5)
        .input_bounds(CartPole::F, -20.0, 20.0)
}

/// The acrobot: two equal point-mass links on a fixed pivot, with a torque `tau` only at the
/// elbow; `th1` and `th2` are the links' absolute angles from hanging straight down.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(th1 => w1, th2 => w2), input(tau))]
#[dirac(lagrangian = m * l * l * w1 * w1 + 0.5 * m * l * l * w2 * w2 + m * l * l * w1 * w2 * cos(th1 - th2)
    + 2.0 * m * g * l * cos(th1) + m * g * l * cos(th2))]
#[dirac(force(th1) = -tau, force(th2) = tau)]
pub struct Acrobot {
    pub m: f64,
    pub l: f64,
    pub g: f64,
    pub tau: f64,
}

/// The acrobot of the optimal control benchmark: 1 kg links 1 m long.
pub fn acrobot() -> Acrobot {
    Acrobot { m: 1.0, l: 1.0, g: 9.81, tau: 0.0 }
}
