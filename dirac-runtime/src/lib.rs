//! The runtime of dirac: the trait that generated models implement, their state with named
//! access, and the numerics that simulate them on stack-allocated nalgebra matrices.
//!
//! Most users reach this crate through the `dirac` facade and its prelude.

/// How models store their matrices and solve their linear systems: dense or sparse.
pub mod algebra;
/// Where the parts of composites made of arrays sit, for generated code.
#[doc(hidden)]
pub mod arrays;
/// Moving subsystem parts in and out of composites, for generated code.
#[doc(hidden)]
pub mod assemble;
/// The block outputs of a model: residual blocks and Jacobian blocks.
pub mod blocks;
mod contacts;
/// Finding the true cause of a failure, for the messages of typed errors.
pub mod diagnose;
/// Type-level sizes of a model and the allocator bound that goes with them.
pub mod dims;
/// Dirac structures as objects, with products, interconnection and membership.
pub mod dirac_structure;
/// Many simulations of one model on all cores, and sweeps split into jobs.
pub mod ensemble;
/// The typed errors of a simulation.
pub mod error;
pub mod events;
pub mod explicit;
/// The flat DAE assembled from a model's blocks.
pub mod flat;
/// How an integrator holds its model: shared, or exclusive to change it while it runs.
pub mod held;
/// Consistent initial states.
pub mod init;
mod init_saddle;
/// The driver every integrator shares, with `solve` written once.
pub mod integrator;
/// Typed names of coordinates and constraints.
pub mod keys;
/// Where each quantity sits in the flat state `y = (q, v, p, λ)`.
pub mod layout;
/// Linearisation about an equilibrium, in minimal coordinates.
pub mod linear;
/// LU factorisation on the stack, real or complex.
pub mod lu;
mod matching;
/// The model trait.
pub mod model;
/// Names of a model as a tree that `const` code can search.
pub mod names;
/// The linear systems of implicit steps: condensed and full solvers.
pub mod newton;
mod projection;
/// The Radau IIA integrator.
pub mod radau;
mod recorder;
pub mod sensitivity;
/// Simulation results with named series.
pub mod solution;
/// Input sources read by time: tables held or interpolated.
pub mod sources;
/// The flat Jacobian in compressed sparse columns.
pub mod sparse;
/// How much stack a model's integrators take.
pub mod stack;
/// The state `(q, v, p, λ)` with named access.
pub mod state;
/// Structural nonsingularity of the condensed system, checked at compile time.
pub mod structure;
#[cfg(test)]
mod testing;
/// The variational integrator (discrete Hamilton-Pontryagin-d'Alembert).
pub mod variational;

pub use algebra::{Algebra, Dense};
pub use blocks::{JacobianBlocks, ResidualBlocks};
pub use dims::{Dimensions, Fixed, MatKK, MatYY, Sizes, Storage, VecC, VecH, VecK, VecQ, VecY};
pub use dirac_structure::{DiracStructure, Membership};
pub use error::SimError;
pub use events::{EventContext, Events, SolveWithEvents};
pub use explicit::{Explicit, ExplicitOptions, ExplicitStats};
pub use held::Held;
pub use init::{Consistency, consistent_state};
pub use integrator::Integrator;
pub use keys::{Constraint, Coordinate, Input, Output};
pub use layout::{Layout, Slot};
pub use linear::{Linearization, linearize};
pub use model::{DenseModel, Equations, LagrangeDirac, MatCQ, MatQQ, OperationCounts};
pub use names::{Named, Names, ResolveError, Resolved, Subsystem};
pub use radau::{ErrorNorm, Radau, RadauOptions, RadauStats};
pub use sensitivity::{Sensitivities, Wrt};
pub use solution::{Crossing, Event, Impact, Sampling, Solution};
pub use sparse::SparseJacobian;
pub use state::State;
pub use structure::Structure;
pub use variational::{Variational, VariationalOptions, VariationalStats};

/// The linear-algebra crate the runtime is built on, for generic code over models (the
/// [`DefaultAllocator`](nalgebra::DefaultAllocator) of the [`Storage`] bound) and for users
/// who want its types without a second, possibly different, version of it.
pub use nalgebra;

/// Items generated code refers to by absolute path. Not part of the public API.
#[doc(hidden)]
pub mod __private {
    pub use crate::algebra::{Algebra, Dense, Pattern, Sparse, SparseShape};
    pub use crate::arrays::{Field, Pattern as RowPattern, Placement, instances, put};
    pub use crate::assemble::{
        Slot, gather_c, gather_q, place_block, scatter_c, scatter_cq, scatter_h, scatter_q, scatter_qq,
    };
    pub use crate::blocks::{JacobianBlocks, ResidualBlocks};
    pub use crate::dims::Storage;
    pub use crate::dims::{Dimensions, Fixed, MatYY, Sizes, VecC, VecH, VecQ, VecY};
    pub use crate::keys::{Constraint, Coordinate, Input, Output};
    pub use crate::model::{DenseModel, Equations, LagrangeDirac, MatCQ, MatQQ, OperationCounts};
    pub use crate::names::{Named, Names, ResolveError, Resolved, Subsystem};
    pub use crate::sparse::SparseJacobian;
    pub use crate::stack::{STACK_LIMIT, stack_bytes};
    pub use crate::structure::{Structure, all, composite_unknown, prefix_sum, unpaired_unknown};
    pub use nalgebra::{Const, DefaultAllocator, Dyn};
    pub use std::borrow::Cow;

    /// A constant of the user's code, where generated code reads it: its type must be `f64`.
    #[inline(always)]
    pub const fn constant(value: f64) -> f64 {
        value
    }
}
