//! Analysis of a model at one instant, outside any integration: consistent initial states,
//! projection onto the constraints, linearisation about an equilibrium, Dirac structures as
//! objects, and the diagnosis that names the true cause of a failure.
//!
//! It uses the model surface and the algebra; the simulation driver and the methods use it.

/// The accelerations and multipliers at a state, solved from the saddle-point system.
pub(crate) mod accelerations;
pub mod control;
/// Finding the true cause of a failure, for the messages of typed errors.
pub mod diagnose;
/// Dirac structures as objects, with products, interconnection and membership.
pub mod dirac_structure;
/// Consistent initial states.
pub(crate) mod floors;
pub(crate) mod free;
pub mod init;
pub(crate) mod init_saddle;
/// Joint-space dynamics: mass matrix, gravity and bias torques, inverse dynamics.
pub mod joint_space;
/// Linearisation about an equilibrium, in minimal coordinates.
pub mod linear;
mod minreal;
pub(crate) mod projection;
pub(crate) mod units;
