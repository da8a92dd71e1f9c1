//! Sizes and layout: how many coordinates and constraints a model has, as type-level
//! dimensions the derive fixes, where each quantity sits in the flat state `y = (q, v, p, λ)`,
//! and how much stack its integrators take.
//!
//! The lowest layer: it knows nothing of models beyond their sizes, so every other layer may
//! use it.

/// Type-level sizes of a model and the allocator bound that goes with them.
pub mod dims;
/// Where each quantity sits in the flat state `y = (q, v, p, λ)`.
pub mod layout;
/// How much stack a model's integrators take (decided alike by the derive).
pub use dirac_structure::stack;
