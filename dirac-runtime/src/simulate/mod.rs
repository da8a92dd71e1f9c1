//! The simulation driver: one run of any integrator ([`Solve::run`](run::Solve::run)), with
//! samples, events, a sampled-data controller, an observer, a progress report, forward
//! sensitivities or an adjoint's recording, in one loop; what sensitivities are taken with
//! respect to; input sources and ensembles.
//!
//! It uses the integrator's steps, the piecewise motion (`hybrid`), the output, analysis and the
//! model surface; the methods implement its traits.

/// Many simulations of one model on all cores, and sweeps split into jobs.
#[cfg(feature = "ensemble")]
pub mod ensemble;
/// One run: samples, events, a controller, an observer and a progress report together.
pub mod run;
pub mod sensitive;
pub mod sensitivity;
