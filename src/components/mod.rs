//! A library of parts that connect: electrical, translational, rotational and
//! electromechanical, each an ordinary `#[derive(LagrangeDirac)]` model with ports, units and
//! outputs, joined by `#[derive(Interconnection)]` like any model of yours.
//!
//! The library is the cargo feature `components`, on by default; it adds about 17 s to the
//! release build of `dirac` itself (BENCHMARKS.md, "Components"), which a crate that writes all
//! of its models saves with `default-features = false`.
//!
//! # The connector convention
//!
//! A port's coordinate is the integral of the *across* quantity: a pin's node flux (V s) for
//! electrical parts, so its velocity is the node's voltage; a flange's position (m) for
//! translational parts; a flange's angle (rad) for rotational ones. The interconnection force
//! at a port is the *through* quantity flowing into the part there: the current, the force,
//! the torque. `connect(a.x, b.y)` is the paper's `v = v̄, f + f̄ = 0`: the two ports move
//! together and what flows out of one flows into the other, so Kirchhoff's current law at a
//! node, and Newton's third law at a joint, are the momentum balance of the parts that meet
//! there, with no equation written for them.
//!
//! Two-pin parts follow the passive sign convention: the voltage `v = vp − vn`, the current
//! `i` into `p`, and `v i` is the power the part takes in. Sources report the power they
//! supply as `supplied`.
//!
//! ```
//! use dirac::components::electrical::{Capacitor, Ground, Resistor, StepVoltage};
//! use dirac::prelude::*;
//!
//! /// An RC circuit switched onto 1 V at t = 0.
//! #[derive(Interconnection)]
//! #[dirac(connect(source.p, r.p), connect(r.n, c.p), connect(c.n, ground.p), connect(source.n, ground.p))]
//! struct Rc {
//!     source: StepVoltage,
//!     r: Resistor,
//!     c: Capacitor,
//!     ground: Ground,
//! }
//!
//! # fn main() -> Result<(), SimError> {
//! let circuit = Rc {
//!     source: StepVoltage { offset: 0.0, height: 1.0, start: 0.0 },
//!     r: Resistor { r: 1e3 },
//!     c: Capacitor { c: 1e-6 },
//!     ground: Ground {},
//! };
//! let zero = VecQ::<Rc>::zeros();
//! let start = consistent_state(&circuit, 0.0, &zero, &zero, Consistency::default())?;
//! let solution = Radau::new(&circuit, RadauOptions::tolerances(1e-10, 1e-10))?
//!     .solve(0.0, &start, 1e-3, &Sampling::Times(vec![1e-3]))?;
//! // The capacitor charges as 1 − e^(−t/RC), RC = 1 ms.
//! let v = solution.output(Rc::c_output(Capacitor::V))[0];
//! assert!((v - (1.0 - (-1.0f64).exp())).abs() < 1e-8);
//! # Ok(())
//! # }
//! ```

pub mod bodies;
pub mod electrical;
pub mod electromechanical;
pub mod rotational;
pub mod translational;

#[cfg(test)]
mod tests;
