//! The runtime of dirac: the traits that generated models implement, their state with named
//! access, and the numerics that simulate them on stack-allocated nalgebra matrices (heap and
//! sparse for models made of arrays).
//!
//! Most users reach this crate through the `dirac` facade and its prelude.
//!
//! # Layers
//!
//! The crate is built in six layers, each a folder whose modules import only from the layers
//! below it (and from [`error`], the typed errors, which every layer may use).
//!
//! [`shape`] holds sizes and layout: a model's dimensions as types the derive fixes, where each
//! quantity sits in the flat state `y = (q, v, p, λ)` and in the `(v, λ)` unknowns of a
//! saddle-point system, and how much stack an integrator takes. It knows nothing of models
//! beyond their sizes.
//!
//! [`algebra`] stores blocks and solves linear systems: dense blocks on the stack, sparse ones
//! for models made of arrays, LU factorisations, the saddle-point solvers and the Newton seam
//! every implicit step solves through. It knows blocks, not the models that fill them.
//!
//! [`model`] is what a model is to the rest: the core trait [`LagrangeDirac`] with the blocks
//! every method needs, one trait per optional capability ([`InputsOutputs`], [`Parameters`],
//! [`Hybrid`], [`Derivation`], [`EnergyBalance`], [`SparseJacobian`]), which is where a new
//! capability adds its blocks, the typed names and keys, the [`State`], the flat DAE, the
//! pieces of composites, and [`model::configuration`], the one seam through which methods
//! move positions (`q ⊕ h v`).
//!
//! [`analysis`] looks at a model at one instant: consistent initialisation, projection onto
//! the constraints, linearisation about an equilibrium, Dirac structures as objects, and the
//! diagnosis that names the true cause of every failure.
//!
//! [`simulate`] is the driver: the [`Integrator`] trait with `solve`, sampled control and
//! sensitivities written once on top of its steps, the restart checks every method shares,
//! events and impacts, the recorder and the [`Solution`], input sources and ensembles.
//!
//! [`methods`] holds [`Radau`], [`Explicit`] and [`Variational`], each an [`Integrator`];
//! nothing but the re-exports below uses them.
//!
//! # Features
//!
//! `sparse` adds sparse storage and its LU (`algebra::Sparse`), for composites made of arrays
//! of subsystems and for run-time networks (`network`), and brings faer; `ensemble` adds
//! `ensemble`, many runs on all cores, and brings rayon. Neither is on by default: the facade
//! `dirac` turns them on with its features of the same names.

pub mod algebra;
pub mod analysis;
/// The typed errors of a simulation.
pub mod error;
pub mod hybrid;
pub mod integrator;
pub mod methods;
pub mod model;
#[cfg(feature = "sparse")]
pub mod network;
/// Optimal control problems on models with inputs, transcribed by DMOC and solved by IPOPT.
pub mod optimal;
pub mod output;
pub mod shape;
pub mod simulate;

pub use algebra::{Algebra, Dense};
pub use analysis::dirac_structure::{DiracStructure, Membership};
pub use analysis::init::Consistency;
pub use analysis::linear::{Basis, Linearization, linearize};
pub use error::{Capability, SimError};
pub use hybrid::event::{Crossing, Event, Impact};
pub use hybrid::events::{EventContext, Events};
pub use hybrid::laws::consistent_state;
pub use integrator::held::Held;
pub use integrator::{Drive, Integrator};
pub use methods::explicit::{Explicit, ExplicitOptions, ExplicitStats};
pub use methods::radau::{DenseOutput, ErrorNorm, Radau, RadauOptions, RadauStats};
pub use methods::variational::{Variational, VariationalOptions, VariationalStats};
pub use model::Named;
pub use model::blocks::{JacobianBlocks, ResidualBlocks};
pub use model::keys::{Constraint, Coordinate, Input, Output};
pub use model::names::{Names, ResolveError, Resolved, Subsystem};
pub use model::sparse::SparseJacobian;
pub use model::state::State;
pub use model::structure::Structure;
pub use model::{
    DenseModel, Derivation, EnergyBalance, Equations, Hybrid, InputsOutputs, LagrangeDirac, MatCQ, MatQQ,
    OperationCounts, Parameters,
};
#[cfg(feature = "sparse")]
pub use network::{Network, NetworkBuilder, NetworkError};
pub use output::progress::Progress;
pub use output::solution::{Sampling, Solution};
pub use shape::dims::{Dimensions, Fixed, MatKK, MatYY, Sizes, Storage, VecC, VecH, VecK, VecQ, VecY};
pub use shape::layout::{Layout, Slot};
pub use simulate::run::{Run, Solve, feedback};
pub use simulate::sensitive::Sensitive;
pub use simulate::sensitivity::{Sensitivities, Wrt};

/// Gradients of one objective with respect to every parameter and initial value at once: the
/// discrete adjoint of a Radau integration, recorded with [`Radau::record`] and swept back
/// with [`Recording::gradient`](adjoint::Recording::gradient).
pub mod adjoint {
    pub use crate::methods::radau::{Gradient, Objective, Recording, SampleFunction, StateFunction};
}

/// The linear systems of implicit steps: the seam every method solves through, the condensed
/// solver a model's algebra provides, and a full reference solver.
pub mod newton {
    pub use crate::algebra::newton::{Full, NewtonSolver};
    pub use crate::model::Condensed;
}

/// The linear-algebra crate the runtime is built on, for generic code over models (the
/// [`DefaultAllocator`](nalgebra::DefaultAllocator) of the [`Storage`] bound) and for users
/// who want its types without a second, possibly different, version of it.
pub use nalgebra;

/// Items generated code refers to by absolute path. Not part of the public API.
#[doc(hidden)]
pub mod __private {
    pub use crate::algebra::{Algebra, Dense};
    #[cfg(feature = "sparse")]
    pub use crate::algebra::{Pattern, Sparse, SparseShape};
    pub use crate::analysis::init::Consistency;
    pub use crate::error::SimError;
    pub use crate::hybrid::events::Events;
    pub use crate::hybrid::laws::{consistent_with_laws, law_names};
    pub use crate::integrator::Integrator;
    pub use crate::model::Named;
    #[cfg(feature = "sparse")]
    pub use crate::model::arrays::{Field, Pattern as RowPattern, Placement, instances, put};
    pub use crate::model::assemble::{
        EventRows, Offsets, gather_blocks, gather_c, gather_h, gather_q, place_block,
        place_event_derivatives, scatter_c, scatter_cq, scatter_h, scatter_q, scatter_qq,
    };
    pub use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
    pub use crate::model::flat::{jacobian_csc_from_blocks, l_qq_from_blocks};
    pub use crate::model::geometry;
    pub use crate::model::hybrid::has_laws;
    pub use crate::model::keys::{Constraint, Coordinate, Input, Output};
    pub use crate::model::names::{Message, Names, ResolveError, Resolved, Subsystem};
    pub use crate::model::sparse::SparseJacobian;
    pub use crate::model::state::State;
    pub use crate::model::structure::{
        Structure, all, composite_unknown, prefix_sum, undetermined_unknown, unpaired_unknown,
    };
    pub use crate::model::{
        DenseModel, Derivation, Equations, Hybrid, InputsOutputs, JointSpace, LagrangeDirac, MatCQ, MatQQ,
        OperationCounts, Parameters, Shapes,
    };
    pub use crate::output::solution::{Sampling, Solution};
    pub use crate::shape::dims::{Dimensions, Fixed, MatYY, Sizes, Storage, VecC, VecH, VecQ, VecY};
    pub use crate::shape::stack::{STACK_LIMIT, stack_bytes};
    pub use crate::simulate::run::Solve;
    pub use nalgebra::{Const, DefaultAllocator, Dyn};
    pub use std::borrow::Cow;

    /// What a subsystem of an interconnection must be: a model of fixed size with every
    /// capability the derives implement, as one bound (one error where a field is not a model).
    pub trait Member: DenseModel + InputsOutputs + Parameters + Hybrid + Derivation
    where
        DefaultAllocator: Storage<Self>,
    {
    }

    impl<M> Member for M
    where
        M: DenseModel + InputsOutputs + Parameters + Hybrid + Derivation,
        DefaultAllocator: Storage<M>,
    {
    }

    /// A composite reduced when it compiles keeps its parts as fields and reads only their
    /// parameters: the derive reads every field here, so that a part without parameters (a
    /// ground) is not reported as a field never read.
    pub trait ReducedParts {
        /// Reads every field of the composite.
        fn read_parts(&self);
    }

    /// A constant of the user's code, where generated code reads it: its type must be `f64`.
    #[inline(always)]
    pub const fn constant(value: f64) -> f64 {
        value
    }
}
