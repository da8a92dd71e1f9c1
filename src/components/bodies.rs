//! Rigid bodies in space, on `R³ × SO(3)` embedded in `R³ × R^{3×3}`.
//!
//! A body's coordinates are its centre of mass `(x, y, z)` in the space frame and the nine
//! entries `r11 … r33` of its rotation matrix `R`, whose columns are the body's axes seen in
//! space (a vector `p` in the body is `R p` in space). Six holonomic rows hold `RᵀR = I`. With
//! `J` the inertia tensor about the centre of mass in the body's axes and
//! `J_d = ½ tr(J) I − J`, the Lagrangian is
//!
//! ```text
//! L = ½ m |ẋ|² + ½ tr(Ṙ J_d Ṙᵀ) − m g z,
//! ```
//!
//! and `½ tr(Ṙ J_d Ṙᵀ) = ½ Ωᵀ J Ω` for `Ṙ = R Ω̂`, `Ω` the angular velocity in the body's
//! axes. Every expression is a polynomial in the coordinates, so the derivatives the macro
//! generates stay small; and the variational integrator on this embedding is the symplectic,
//! momentum-preserving RATTLE discretisation of the rigid body (Moser and Veselov; McLachlan
//! and Scovel), with `RᵀR = I` held to round-off by every integrator, as the holonomic rows
//! are.
//!
//! Why this representation and not unit quaternions or Euler angles: Euler angles are
//! singular where two axes align and their kinetic energy is a trigonometric expression in
//! every coordinate; quaternions carry a quartic kinetic energy (`2 q̇ᵀ E(q)ᵀ J E(q) q̇`) and a
//! sign ambiguity; the matrix's kinetic energy is a constant quadratic form in the
//! velocities, so `L_vv` is constant and is factored once, and every constraint of a joint
//! between two bodies (a point of one on a point of the other, an axis along an axis) is linear
//! or bilinear in the coordinates.
//!
//! ```
//! use dirac::components::bodies::RigidBody;
//! use dirac::prelude::*;
//!
//! # fn main() -> Result<(), SimError> {
//! // A box spinning about its axis of largest inertia keeps spinning: the angular velocity
//! // in its own axes stays (0, 0, 2) rad/s.
//! let body = RigidBody::new(2.0, [1.0, 2.0, 3.0]);
//! let (q, v) = body.state([0.0; 3], [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], [0.0; 3], [0.0, 0.0, 2.0]);
//! let start = consistent_state(&body, 0.0, &q, &v, Consistency::default())?;
//! let solution = Radau::new(&body, RadauOptions::tolerances(1e-10, 1e-10))?
//!     .solve(0.0, &start, 1.0, &Sampling::Times(vec![1.0]))?;
//! let wz = solution.output(RigidBody::WZ)[0];
//! assert!((wz - 2.0).abs() < 1e-9);
//! # Ok(())
//! # }
//! ```

use crate::LagrangeDirac;
use crate::nalgebra::Vector3;
use crate::prelude::VecQ;

/// A rigid body of mass `m` and inertia tensor `J` (about its centre of mass, in its own axes:
/// `jxx`, `jyy`, `jzz` on the diagonal and the products `jxy`, `jxz`, `jyz`) under gravity
/// `g` along `−z`, pushed by the input force `(fx, fy, fz)` at its centre of mass (in space)
/// and the input torque `(tx, ty, tz)` (in its own axes).
///
/// Outputs: its angular velocity in its own axes `wx, wy, wz`; its angular momentum about the
/// origin in space `hx, hy, hz`; its linear momentum `px, py, pz`; its energy `energy`
/// (kinetic plus gravitational).
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(x => vx, y => vy, z => vz))]
#[dirac(coordinates(r11 => dr11, r12 => dr12, r13 => dr13))]
#[dirac(coordinates(r21 => dr21, r22 => dr22, r23 => dr23))]
#[dirac(coordinates(r31 => dr31, r32 => dr32, r33 => dr33))]
#[dirac(port(x, y, z, r11, r12, r13, r21, r22, r23, r31, r32, r33))]
#[dirac(input(fx, fy, fz, tx, ty, tz), positive(m), nonnegative(g))]
// J_d = ½ tr(J) I − J, the inertia of the body's points about its centre's planes.
#[dirac(define(d11) = 0.5 * (jyy + jzz - jxx), define(d22) = 0.5 * (jxx + jzz - jyy))]
#[dirac(define(d33) = 0.5 * (jxx + jyy - jzz))]
// The products of the columns' rates, ċ_j · ċ_k.
#[dirac(define(c11) = dr11 * dr11 + dr21 * dr21 + dr31 * dr31)]
#[dirac(define(c22) = dr12 * dr12 + dr22 * dr22 + dr32 * dr32)]
#[dirac(define(c33) = dr13 * dr13 + dr23 * dr23 + dr33 * dr33)]
#[dirac(define(c12) = dr11 * dr12 + dr21 * dr22 + dr31 * dr32)]
#[dirac(define(c13) = dr11 * dr13 + dr21 * dr23 + dr31 * dr33)]
#[dirac(define(c23) = dr12 * dr13 + dr22 * dr23 + dr32 * dr33)]
#[dirac(define(rotation) = 0.5 * (d11 * c11 + d22 * c22 + d33 * c33) - jxy * c12 - jxz * c13 - jyz * c23)]
#[dirac(define(translation) = 0.5 * m * (vx * vx + vy * vy + vz * vz))]
#[dirac(lagrangian = translation + rotation - m * g * z)]
// RᵀR = I: the columns are unit vectors and orthogonal.
#[dirac(holonomic(unit1) = r11 * r11 + r21 * r21 + r31 * r31 - 1.0)]
#[dirac(holonomic(unit2) = r12 * r12 + r22 * r22 + r32 * r32 - 1.0)]
#[dirac(holonomic(unit3) = r13 * r13 + r23 * r23 + r33 * r33 - 1.0)]
#[dirac(holonomic(square12) = r11 * r12 + r21 * r22 + r31 * r32)]
#[dirac(holonomic(square13) = r11 * r13 + r21 * r23 + r31 * r33)]
#[dirac(holonomic(square23) = r12 * r13 + r22 * r23 + r32 * r33)]
// A torque τ in the body's axes does the work τ · δθ with δθ̂ = Rᵀ δR; written half on each
// of the two columns it turns, so that it is skew off the manifold too.
#[dirac(force(x) = fx, force(y) = fy, force(z) = fz)]
#[dirac(force(r11) = 0.5 * (tz * r12 - ty * r13), force(r21) = 0.5 * (tz * r22 - ty * r23))]
#[dirac(force(r31) = 0.5 * (tz * r32 - ty * r33))]
#[dirac(force(r12) = 0.5 * (tx * r13 - tz * r11), force(r22) = 0.5 * (tx * r23 - tz * r21))]
#[dirac(force(r32) = 0.5 * (tx * r33 - tz * r31))]
#[dirac(force(r13) = 0.5 * (ty * r11 - tx * r12), force(r23) = 0.5 * (ty * r21 - tx * r22))]
#[dirac(force(r33) = 0.5 * (ty * r31 - tx * r32))]
// Ω̂ = RᵀṘ: Ω₁ = c₃·ċ₂, Ω₂ = c₁·ċ₃, Ω₃ = c₂·ċ₁.
#[dirac(define(om1) = r13 * dr12 + r23 * dr22 + r33 * dr32)]
#[dirac(define(om2) = r11 * dr13 + r21 * dr23 + r31 * dr33)]
#[dirac(define(om3) = r12 * dr11 + r22 * dr21 + r32 * dr31)]
#[dirac(output(wx) = om1, output(wy) = om2, output(wz) = om3)]
// J Ω in the body's axes, then R J Ω in space, plus m x × ẋ.
#[dirac(define(pi1) = jxx * om1 + jxy * om2 + jxz * om3)]
#[dirac(define(pi2) = jxy * om1 + jyy * om2 + jyz * om3)]
#[dirac(define(pi3) = jxz * om1 + jyz * om2 + jzz * om3)]
#[dirac(output(hx) = r11 * pi1 + r12 * pi2 + r13 * pi3 + m * (y * vz - z * vy))]
#[dirac(output(hy) = r21 * pi1 + r22 * pi2 + r23 * pi3 + m * (z * vx - x * vz))]
#[dirac(output(hz) = r31 * pi1 + r32 * pi2 + r33 * pi3 + m * (x * vy - y * vx))]
#[dirac(output(px) = m * vx, output(py) = m * vy, output(pz) = m * vz)]
#[dirac(output(energy) = translation + rotation + m * g * z)]
#[dirac(unit(x, y, z) = "m", unit(vx, vy, vz) = "m/s", unit(m) = "kg", unit(g) = "m/s2")]
#[dirac(unit(r11, r12, r13, r21, r22, r23, r31, r32, r33) = "1")]
#[dirac(unit(dr11, dr12, dr13, dr21, dr22, dr23, dr31, dr32, dr33) = "1/s")]
#[dirac(unit(jxx, jyy, jzz, jxy, jxz, jyz) = "kg m2", unit(fx, fy, fz) = "N", unit(tx, ty, tz) = "N m")]
#[dirac(unit(wx, wy, wz) = "rad/s", unit(hx, hy, hz) = "N m s", unit(px, py, pz) = "N s", unit(energy) = "J")]
pub struct RigidBody {
    /// Mass.
    pub m: f64,
    /// Moment of inertia about the body's `x` axis through its centre of mass.
    pub jxx: f64,
    /// Moment of inertia about the body's `y` axis.
    pub jyy: f64,
    /// Moment of inertia about the body's `z` axis.
    pub jzz: f64,
    /// Product of inertia `J_xy` (the tensor's entry, `−∫ x y dm`).
    pub jxy: f64,
    /// Product of inertia `J_xz`.
    pub jxz: f64,
    /// Product of inertia `J_yz`.
    pub jyz: f64,
    /// Gravity's acceleration, along `−z`.
    pub g: f64,
    /// Applied force along `x` (space), at the centre of mass.
    pub fx: f64,
    /// Applied force along `y` (space).
    pub fy: f64,
    /// Applied force along `z` (space).
    pub fz: f64,
    /// Applied torque about the body's `x` axis.
    pub tx: f64,
    /// Applied torque about the body's `y` axis.
    pub ty: f64,
    /// Applied torque about the body's `z` axis.
    pub tz: f64,
}

impl RigidBody {
    /// A body of mass `m` with principal moments `[jxx, jyy, jzz]` along its own axes, no
    /// gravity, nothing applied.
    pub fn new(m: f64, moments: [f64; 3]) -> Self {
        let [jxx, jyy, jzz] = moments;
        RigidBody {
            m,
            jxx,
            jyy,
            jzz,
            jxy: 0.0,
            jxz: 0.0,
            jyz: 0.0,
            g: 0.0,
            fx: 0.0,
            fy: 0.0,
            fz: 0.0,
            tx: 0.0,
            ty: 0.0,
            tz: 0.0,
        }
    }

    /// The body with the products of inertia `[jxy, jxz, jyz]` (the tensor's off-diagonal
    /// entries).
    pub fn with_products(self, products: [f64; 3]) -> Self {
        let [jxy, jxz, jyz] = products;
        RigidBody { jxy, jxz, jyz, ..self }
    }

    /// The body under gravity `g` along `−z`.
    pub fn with_gravity(self, g: f64) -> Self {
        RigidBody { g, ..self }
    }

    /// Coordinates and velocities for the body with its centre at `centre`, its rotation
    /// `rotation` (rows of `R`: `rotation[i][j]` is `r(i+1)(j+1)`), its centre moving at
    /// `velocity` (space) and turning at `omega` (its own axes): `Ṙ = R Ω̂`. Give them to
    /// [`consistent_state`](crate::consistent_state) for a state to start from.
    pub fn state(
        &self,
        centre: [f64; 3],
        rotation: [[f64; 3]; 3],
        velocity: [f64; 3],
        omega: [f64; 3],
    ) -> (VecQ<Self>, VecQ<Self>) {
        let mut q = VecQ::<Self>::zeros();
        let mut v = VecQ::<Self>::zeros();
        let [w1, w2, w3] = omega;
        let hat = [[0.0, -w3, w2], [w3, 0.0, -w1], [-w2, w1, 0.0]];
        for i in 0..3 {
            q[i] = centre[i];
            v[i] = velocity[i];
            for j in 0..3 {
                q[3 + 3 * i + j] = rotation[i][j];
                v[3 + 3 * i + j] = (0..3).map(|k| rotation[i][k] * hat[k][j]).sum();
            }
        }
        (q, v)
    }

    /// The angular velocity `Ω` in the body's axes from the coordinates and velocities:
    /// `Ω̂ = RᵀṘ`.
    pub fn omega(q: &VecQ<Self>, v: &VecQ<Self>) -> Vector3<f64> {
        let r = |i: usize, j: usize| q[3 + 3 * i + j];
        let dr = |i: usize, j: usize| v[3 + 3 * i + j];
        let column_dot = |a: usize, b: usize| (0..3).map(|i| r(i, a) * dr(i, b)).sum::<f64>();
        Vector3::new(column_dot(2, 1), column_dot(0, 2), column_dot(1, 0))
    }
}
