//! The piecewise motion of a model, over any integrator: events located within steps,
//! impacts at unilateral constraints, contacts at rest, laws (friction, diodes, ideal
//! switches) and switching surfaces, and the jumps of each with their derivatives.
//!
//! It uses the integrator's steps, analysis, the model surface and the algebra; a run drives
//! it.

pub(crate) mod contacts;
/// What a run reports of its piecewise motion: events and impacts.
pub mod event;
pub mod events;
/// An impact as a map of the state before it, with its derivative.
pub mod impact;
pub(crate) mod jumps;
pub(crate) mod law_jump;
pub(crate) mod laws;
pub(crate) mod surface;
