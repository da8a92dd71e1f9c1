//! The integration methods, each an [`Integrator`](crate::integrator::Integrator):
//! Radau IIA for stiff models, an explicit Runge-Kutta pair for models that are not, and a
//! variational integrator for long runs.
//!
//! The top layer: methods use everything below and nothing uses them but the crate's
//! re-exports.

pub mod explicit;
/// The Radau IIA integrator.
pub mod radau;
/// The variational integrator (discrete Hamilton-Pontryagin-d'Alembert).
pub mod variational;
