//! The runtime of dirac: the trait that generated models implement, their state with named
//! access, and the numerics that simulate them on stack-allocated nalgebra matrices.
//!
//! Most users reach this crate through the `dirac` facade and its prelude.

/// Type-level sizes of a model and the allocator bound that goes with them.
pub mod dims;
/// Typed names of coordinates and constraints.
pub mod keys;
/// The model trait and its block structs.
pub mod model;
/// The state `(q, v, p, λ)` with named access.
pub mod state;

pub use dims::{Dimensions, MatCQ, MatKK, MatQQ, MatYY, Storage, VecC, VecH, VecK, VecQ, VecY};
pub use keys::{Constraint, Coordinate};
pub use model::{Equations, JacobianBlocks, LagrangeDirac, OperationCounts, ResidualBlocks};
pub use state::State;

/// Items generated code refers to by absolute path. Not part of the public API.
#[doc(hidden)]
pub mod __private {
    pub use crate::dims::{Dimensions, MatCQ, MatQQ, MatYY, VecC, VecH, VecQ, VecY};
    pub use crate::keys::{Constraint, Coordinate};
    pub use crate::model::{Equations, JacobianBlocks, LagrangeDirac, OperationCounts, ResidualBlocks};
    pub use nalgebra::Const;
    pub use std::borrow::Cow;
}
