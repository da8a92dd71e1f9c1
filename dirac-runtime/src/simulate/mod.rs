//! The simulation driver and its results: the [`Integrator`](integrator::Integrator) trait
//! every method implements, with `solve` written once on top of its steps; how an integrator
//! holds its model; events, impacts and sensitivities over any method; the recorder and the
//! solution it fills; input sources and ensembles.
//!
//! It uses analysis, the model surface and the algebra; the methods implement its traits.

pub(crate) mod arrow;
pub(crate) mod contacts;
pub(crate) mod drive;
/// Many simulations of one model on all cores, and sweeps split into jobs.
#[cfg(feature = "ensemble")]
pub mod ensemble;
pub mod events;
/// How an integrator holds its model: shared, or exclusive to change it while it runs.
pub mod held;
/// An impact as a map of the state before it, with its derivative.
pub mod impact;
/// The driver every integrator shares, with `solve` written once.
pub mod integrator;
pub(crate) mod law_jump;
pub(crate) mod laws;
pub(crate) mod parquet;
pub mod progress;
pub(crate) mod recorder;
pub(crate) mod restart;
/// One run: samples, events, a controller, an observer and a progress report together.
pub mod run;
pub mod sensitive;
pub mod sensitivity;
/// Simulation results with named series.
pub mod solution;
/// Input sources read by time: tables held or interpolated.
pub mod sources;
pub(crate) mod surface;
