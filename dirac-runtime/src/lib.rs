//! The runtime of dirac: the trait that generated models implement, their state with named
//! access, and the numerics that simulate them on stack-allocated nalgebra matrices.
//!
//! Most users reach this crate through the `dirac` facade and its prelude.

/// Moving subsystem parts in and out of composites, for generated code.
#[doc(hidden)]
pub mod assemble;
/// Type-level sizes of a model and the allocator bound that goes with them.
pub mod dims;
/// Dirac structures as objects, with products, interconnection and membership.
pub mod dirac_structure;
/// The typed errors of a simulation.
pub mod error;
/// The flat DAE assembled from a model's blocks.
pub mod flat;
/// Consistent initial states.
pub mod init;
/// Typed names of coordinates and constraints.
pub mod keys;
/// LU factorisation on the stack, real or complex.
pub mod lu;
/// The model trait and its block structs.
pub mod model;
/// Names of a model as a tree that `const` code can search.
pub mod names;
/// The linear systems of implicit steps: condensed and full solvers.
pub mod newton;
/// The Radau IIA integrator.
pub mod radau;
/// Simulation results with named series.
pub mod solution;
/// The state `(q, v, p, λ)` with named access.
pub mod state;
/// Structural nonsingularity of the condensed system, checked at compile time.
pub mod structure;
/// The variational integrator (discrete Hamilton-Pontryagin-d'Alembert).
pub mod variational;

pub use dims::{Dimensions, MatCQ, MatKK, MatQQ, MatYY, Storage, VecC, VecH, VecK, VecQ, VecY};
pub use dirac_structure::{DiracStructure, Membership};
pub use error::SimError;
pub use flat::SparseJacobian;
pub use init::{Consistency, consistent_state};
pub use keys::{Constraint, Coordinate};
pub use model::{Equations, JacobianBlocks, LagrangeDirac, OperationCounts, ResidualBlocks};
pub use names::{Names, ResolveError, Resolved, Subsystem};
pub use radau::{Options, Radau, Stats};
pub use solution::{Sampling, Solution};
pub use state::State;
pub use structure::Structure;
pub use variational::{Variational, VariationalOptions, VariationalStats};

/// Items generated code refers to by absolute path. Not part of the public API.
#[doc(hidden)]
pub mod __private {
    pub use crate::assemble::{
        Slot, gather_c, gather_q, scatter_c, scatter_cq, scatter_h, scatter_q, scatter_qq,
    };
    pub use crate::dims::Storage;
    pub use crate::dims::{Dimensions, MatCQ, MatQQ, MatYY, VecC, VecH, VecQ, VecY};
    pub use crate::flat::SparseJacobian;
    pub use crate::keys::{Constraint, Coordinate};
    pub use crate::model::{Equations, JacobianBlocks, LagrangeDirac, OperationCounts, ResidualBlocks};
    pub use crate::names::{Names, ResolveError, Resolved, Subsystem};
    pub use crate::structure::{Structure, composite_unknown, unpaired_unknown};
    pub use nalgebra::{Const, DefaultAllocator};
    pub use std::borrow::Cow;
}
