//! The trait every Lagrange-Dirac model implements, primitive or interconnected.
//!
//! A model is exposed block-wise (∂L/∂q, ∂L/∂v, L_vv, A(q), …) so that integrators can exploit
//! the structure of the implicit Lagrange-d'Alembert equations and interconnections can assemble
//! a composite from its parts without re-deriving anything. The flat semi-explicit DAE
//! `M ẏ = f(t, y)` with `y = (q, v, p, λ)` is available too.
//!
//! # Sparse writes
//!
//! Methods that fill a matrix write only its structurally nonzero entries. Give them a buffer
//! that was zeroed once (for example with [`nalgebra::Matrix::zeros`]) and that only the same
//! method writes to: the structural zeros then stay zero without being rewritten on every call.
//! The allocating conveniences (`*_matrix`, [`LagrangeDirac::residual_vector`], …) do this for you.

use nalgebra::DefaultAllocator;

use crate::algebra::Algebra;
use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
use crate::model::keys::{Constraint, Coordinate};
use crate::model::named::Named;
use crate::model::state::State;
use crate::model::structure::Structure;
use crate::shape::dims::{Dimensions, MatYY, Sizes, Storage, VecC, VecH, VecQ, VecY};

/// An `n × n` block of a model (second derivatives of L, force Jacobians): a dense matrix
/// for models of fixed size, sparse for models made of arrays.
pub type MatQQ<M> = <<M as LagrangeDirac>::Algebra as Algebra<M>>::Qq;
/// An `m × n` block of a model (the constraint rows `A(q)`, `∂(A v)/∂q`).
pub type MatCQ<M> = <<M as LagrangeDirac>::Algebra as Algebra<M>>::Cq;
/// The condensed Newton solver of model `M`'s algebra: the one integrators use by default.
pub type Condensed<M> = <<M as LagrangeDirac>::Algebra as Algebra<M>>::Condensed;

/// A typed error if a parameter of `model` is NaN or infinite, or breaks a requirement of its
/// model (`positive(r)`, `nonnegative(d)`).
pub fn check_parameters<M: LagrangeDirac>(model: &M) -> Result<(), crate::error::SimError>
where
    DefaultAllocator: Storage<M>,
{
    match model.invalid_parameter() {
        Some((name, value, requirement)) => {
            Err(crate::error::SimError::InvalidParameter { name, value, requirement })
        }
        None => Ok(()),
    }
}

/// A Lagrange-Dirac system (implicit Lagrangian system) with constraints and external forces.
///
/// With `n` coordinates `q`, velocities `v`, momenta `p` and `m` multipliers `λ`, its
/// equations (the implicit Lagrange-d'Alembert equations, paper eq. 3) are
///
/// ```text
/// q̇ = v
/// ṗ = ∂L/∂q + F(q, v, t) + A(q, t)ᵀ λ
/// 0 = p − ∂L/∂v
/// 0 = A(q, t) v + b(q, t)
/// ```
///
/// Implement it with `#[derive(LagrangeDirac)]`; every method is generated code specialised
/// to the model. Holonomic constraints `φ(q, t) = 0` contribute the first [`Fixed::NH`](crate::shape::dims::Fixed::NH) (for a model of fixed size)
/// rows, `A = ∂φ/∂q` and `b = ∂φ/∂t`. `b` is zero unless a constraint prescribes a motion.
///
/// This trait holds what every integration method needs: the blocks, the flat residual and
/// Jacobian, the outputs every solution records. What only some methods need is a trait of
/// its own, which the derives implement beside this one and methods ask for in their bounds:
/// [`InputsOutputs`](crate::model::InputsOutputs) (setting inputs, linearisation),
/// [`Parameters`](crate::model::Parameters) (parameter values and derivatives),
/// [`Hybrid`](crate::model::Hybrid) (events and contacts),
/// [`SparseJacobian`](crate::SparseJacobian) (the flat Jacobian in compressed columns),
/// [`Derivation`](crate::model::Derivation) (the equations, for people) and
/// [`EnergyBalance`](crate::model::EnergyBalance) (energy and powers, from the blocks). A new
/// capability adds a trait there, not methods here.
pub trait LagrangeDirac: Dimensions + Named + Sized + 'static
where
    DefaultAllocator: Storage<Self>,
{
    /// How the model's blocks are stored and its linear systems solved:
    /// [`Dense`](crate::algebra::Dense) for models whose sizes are fixed when they compile,
    /// [`Sparse`](crate::algebra::Sparse) for models made of arrays of subsystems.
    type Algebra: Algebra<Self>;

    /// Whether `L = ½ vᵀ M v − V(q, t)` with a constant mass matrix `M` and no external forces
    /// (decided from the model's structure when it compiles). Integrators may take shortcuts
    /// for such models; the variational integrator's step then costs what RATTLE's does.
    const SEPARABLE: bool;
    /// Whether some constraint prescribes a motion, `b(q, t) ≠ 0` in `A(q, t) v + b(q, t) = 0`
    /// (decided from the model's structure when it compiles). Integrators skip the rates of
    /// constraints, and the work they do, for models without.
    const PRESCRIBED: bool;
    /// Whether the constraint rows `A` depend on nothing but the model's parameters (not on
    /// `q`, `t` or a coordinate of another subsystem) and no constraint prescribes a motion
    /// (decided from the model's structure when it compiles; `false` unless known). Between
    /// changes to the model, `A` is then constant and `∂(A v + b)/∂(q, t)` zero: integrators
    /// keep what they derived from it.
    const CONSTANT_CONSTRAINTS: bool = false;
    /// The coordinates whose velocity neither inertia nor a constraint fixes, only the forces,
    /// when the derive solved each one's momentum balance for it in closed form (a node
    /// between a resistor and an inductor): [`LagrangeDirac::solved_velocities`] gives them.
    /// Empty otherwise; integrators then solve that balance by Newton's method.
    const SOLVED_VELOCITIES: &'static [usize] = &[];
    /// Whether some force grows with a constraint force (Coulomb friction `μ λ_n` on the
    /// multiplier `λ_n` of a contact row, while it slips): the momentum balance then reads
    /// `Bᵀλ` with `B = A +` [`LagrangeDirac::slip_rows`], not `Aᵀλ`. Decided when
    /// the model compiles; `false` unless the derive emits `slip_rows`.
    const NON_ASSOCIATED: bool = false;
    /// Whether [`LagrangeDirac::slip_rows`] depend on the velocities (a friction cone on a
    /// contact force pushes against the slip's direction): integrators that hold `B` fixed
    /// over a step then evaluate it at the step's velocity, with
    /// [`LagrangeDirac::slip_dv`] in their matrix. `false` unless the derive emits `slip_dv`.
    const SLIP_TURNS: bool = false;
    /// The sparsity pattern of the condensed Newton system and what to say about each unknown;
    /// interconnections combine their subsystems' to check themselves when they compile.
    const STRUCTURE: Structure;

    /// The model's sizes: `n` coordinates, `m` constraint rows, the holonomic ones first.
    fn sizes(&self) -> Sizes;

    /// What the model's [`Algebra`] needs to build its blocks and solvers: the sizes of a
    /// dense model, the sparsity pattern of a sparse one. Built once by each integrator.
    fn shape(&self) -> <Self::Algebra as Algebra<Self>>::Shape;

    /// The Lagrangian `L(q, v, t)`.
    fn lagrangian(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>) -> f64;
    /// `∂L/∂q`.
    fn dl_dq(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut VecQ<Self>);
    /// `∂L/∂v`.
    fn dl_dv(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut VecQ<Self>);
    /// `L_qq = ∂²L/∂q²` (sparse write).
    fn l_qq(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut MatQQ<Self>);
    /// `L_vq = ∂(∂L/∂v)/∂q`, entry `(i, j) = ∂²L/∂v_i∂q_j` (sparse write).
    fn l_vq(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut MatQQ<Self>);
    /// `L_vv = ∂²L/∂v²` (sparse write).
    fn l_vv(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut MatQQ<Self>);
    /// The external force `F(q, v, t)`, a covector.
    fn force(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut VecQ<Self>);
    /// `∂F/∂q` (sparse write).
    fn force_dq(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut MatQQ<Self>);
    /// `∂F/∂v` (sparse write).
    fn force_dv(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut MatQQ<Self>);
    /// The constraint rows `A(q, t)`; row `j` is the one-form of constraint `j` (sparse write).
    fn constraint_matrix(&self, t: f64, q: &VecQ<Self>, out: &mut MatCQ<Self>);
    /// `∂(A(q, t) v + b(q, t))/∂q` (sparse write).
    fn dav_dq(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut MatCQ<Self>);
    /// `∂(A(q, t)ᵀ λ)/∂q` (sparse write).
    fn datl_dq(&self, t: f64, q: &VecQ<Self>, lambda: &VecC<Self>, out: &mut MatQQ<Self>);
    /// `B − A` at `(t, q, v)`: row `j` holds what the forces driven by multiplier `j` add to the
    /// one-form of row `j` (for friction slipping on the contact force of row `j`, `−μ s ∂g/∂v`),
    /// so that the constraint forces of the momentum balance are `Bᵀλ`. Zero (nothing written)
    /// unless [`LagrangeDirac::NON_ASSOCIATED`] (sparse write).
    fn slip_rows(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut MatCQ<Self>) {
        let _ = (t, q, v, out);
    }
    /// `∂((B − A)ᵀ λ)/∂v` at `(t, q, v)`: how the forces that grow with the multipliers turn
    /// with the velocities (a friction cone's push on a contact force follows the slip). Zero
    /// (nothing written) unless [`LagrangeDirac::SLIP_TURNS`] (sparse write).
    fn slip_dv(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>, out: &mut MatQQ<Self>) {
        let _ = (t, q, v, lambda, out);
    }
    /// The holonomic constraint values `φ(q, t)`, zero on the constraint manifold.
    fn holonomic(&self, t: f64, q: &VecQ<Self>, out: &mut VecH<Self>);
    /// The rates `b(q, t)` of the constraints `A(q, t) v + b(q, t) = 0`: `∂φ/∂t` for a
    /// holonomic row, the part without velocities for a velocity row. Zero unless a constraint
    /// prescribes a motion (a rheonomic constraint); then it does work, and
    /// [`constraint_power`](crate::model::EnergyBalance::constraint_power) is its power.
    fn constraint_rate(&self, t: f64, q: &VecQ<Self>, out: &mut VecC<Self>);
    /// `∂(A(q, t) v + b(q, t))/∂t`.
    fn dav_dt(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut VecC<Self>);

    /// The residual blocks in one pass, sharing every common subexpression.
    fn residual_blocks(
        &self,
        t: f64,
        q: &VecQ<Self>,
        v: &VecQ<Self>,
        lambda: &VecC<Self>,
        out: &mut ResidualBlocks<Self>,
    );
    /// The Jacobian blocks in one pass (sparse write into each block).
    fn jacobian_blocks(
        &self,
        t: f64,
        q: &VecQ<Self>,
        v: &VecQ<Self>,
        lambda: &VecC<Self>,
        out: &mut JacobianBlocks<Self, Self::Algebra>,
    );

    /// The first parameter (its dotted name, `left.m1` in a composite) whose value is NaN or
    /// infinite, or breaks its model's requirement (`positive(r)`, `nonnegative(d)`), with that
    /// value and what it must be (`"finite"`, `"positive"`, `"non-negative"`). Integrators and
    /// [`consistent_state`](crate::consistent_state) refuse such a model before they evaluate
    /// it. The derive implements it.
    fn invalid_parameter(&self) -> Option<(String, f64, &'static str)> {
        None
    }

    /// `∂(∂L/∂v)/∂t`: how the momenta of a time-dependent Lagrangian change at fixed `(q, v)`.
    fn l_vt(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut VecQ<Self>);
    /// `∂L/∂t`: with the power of the forces, the rate of change of the energy on solutions,
    /// `dE/dt = ⟨F, v⟩ − ∂L/∂t`.
    fn dl_dt(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>) -> f64;

    /// Writes the velocity of each coordinate of [`LagrangeDirac::SOLVED_VELOCITIES`] that its
    /// momentum balance gives at `(t, q)` and the other velocities of `v`, at its index of
    /// `out`; the other entries of `out` are left alone.
    fn solved_velocities(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut VecQ<Self>) {
        let _ = (t, q, v, out);
    }

    /// For a robot whose joints form a tree fixed in the world (a URDF model whose
    /// [`JointSpace`](crate::model::JointSpace) is recursive): writes the momentum balance
    /// without its accelerations and constraint forces, `∂L/∂q + F − L_vt − L_vq v = F − b(q, v)`
    /// with `b` the bias torques of the recursive Newton-Euler algorithm, into `rate`, and
    /// `L_vv = M(q)` of the composite rigid bodies into `l_vv`, and returns `true`; every other
    /// model writes nothing and returns `false` (the default). The accelerations that
    /// `Explicit` steps on and that consistent starts are checked with read these in place of
    /// the blocks `∂L/∂q`, `L_vq` and `L_vv`.
    fn tree_dynamics(
        &self,
        t: f64,
        q: &VecQ<Self>,
        v: &VecQ<Self>,
        rate: &mut VecQ<Self>,
        l_vv: &mut MatQQ<Self>,
    ) -> bool {
        let _ = (t, q, v, rate, l_vv);
        false
    }

    /// The interconnection forces `Ωᵀμ` of the model and, scattered, of its subsystems: the
    /// efforts at the ports (zero for a primitive model).
    fn interconnection_forces(&self, t: f64, q: &VecQ<Self>, lambda: &VecC<Self>, out: &mut VecQ<Self>) {
        let _ = (t, q, lambda);
        out.fill(0.0);
    }

    /// The flat right-hand side `f(t, y)` of `M ẏ = f(t, y)`, `M = diag(I, 0, I, 0)`, in the
    /// slots of `y = (q, v, p, λ)`: `(v, p − ∂L/∂v, ∂L/∂q + F + Aᵀλ, A v)`.
    ///
    /// The default assembles it from [`LagrangeDirac::residual_blocks`]; the derive for a
    /// primitive model emits a specialised version.
    fn residual(&self, t: f64, y: &VecY<Self>, out: &mut VecY<Self>) {
        let sizes = self.sizes().typed::<Self>();
        let state = State::<Self>::from_y(sizes, y);
        let mut blocks = ResidualBlocks::<Self>::with_sizes(&sizes);
        self.residual_blocks(t, &state.q, &state.v, &state.lambda, &mut blocks);
        crate::model::flat::residual(&state, &blocks, out);
    }

    /// The flat Jacobian `∂f/∂y`. Entries outside the blocks of the design notes' Jacobian are
    /// never written; the derive for a primitive model writes structural nonzeros only.
    ///
    /// The default assembles it from [`LagrangeDirac::jacobian_blocks`].
    fn jacobian(&self, t: f64, y: &VecY<Self>, out: &mut MatYY<Self>) {
        let sizes = self.sizes();
        let state = State::<Self>::from_y(sizes, y);
        let mut blocks = JacobianBlocks::<Self, Self::Algebra>::with_shape(&self.shape());
        self.jacobian_blocks(t, &state.q, &state.v, &state.lambda, &mut blocks);
        crate::model::flat::jacobian::<Self, Self::Algebra>(&sizes, &blocks, out);
    }

    /// The coordinates through which the model may be interconnected, at any depth.
    fn ports(&self) -> Vec<Coordinate<Self>> {
        Self::NAMES.port_indices().into_iter().map(Coordinate::unchecked).collect()
    }

    /// The model's outputs at `(t, q, v, λ)`, into `out` (one value per output, in the order
    /// of their keys). The derive implements it for models with outputs; for a model without,
    /// there is nothing to write.
    fn outputs(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>, out: &mut [f64]) {
        let _ = (t, q, v, lambda);
        assert!(out.is_empty(), "outputs: the model has none, so the output slice must be empty");
    }

    /// Whether [`LagrangeDirac::recovered`] reads the accelerations (a multiplier recovered
    /// from the momentum balance of a coordinate with inertia).
    const RECOVERED_READS_ACCELERATIONS: bool = false;

    /// The series a reduced composite (`#[dirac(reduce)]`) took out of its state and recovers
    /// at each sample, in the names the composite has unreduced: each eliminated coordinate
    /// and its velocity (`rotor.phi`, `rotor.w`), each eliminated connection's or row's
    /// multiplier (`lambda(connect6)`), and the interconnection force at each port
    /// (`f(gear.a)`). A solution records them under these names. None for other models.
    fn recovered_names(&self) -> &'static [&'static str] {
        &[]
    }

    /// The series of [`LagrangeDirac::recovered_names`] at `(t, q, v)` with accelerations `a`
    /// and multipliers `λ`, into `out` (one value per name).
    fn recovered(
        &self,
        t: f64,
        q: &VecQ<Self>,
        v: &VecQ<Self>,
        a: &VecQ<Self>,
        lambda: &VecC<Self>,
        out: &mut [f64],
    ) {
        let _ = (t, q, v, a, lambda);
        assert!(out.is_empty(), "recovered: the model recovers nothing, so the slice must be empty");
    }

    /// The values of the model's inputs now, into `out` (one per input, in the order of their
    /// keys): what a solution records as `in(name)`. The derives implement it for models with
    /// inputs; a hand-written model with inputs implements it too (the default writes NaN: not
    /// known).
    fn input_values(&self, out: &mut [f64]) {
        out.fill(f64::NAN);
    }

    /// The coordinate with this (dotted) name, if the model has one.
    fn coordinate(&self, name: &str) -> Option<Coordinate<Self>> {
        self.coordinate_names().iter().position(|c| c == name).map(Coordinate::unchecked)
    }

    /// The constraint with this (dotted) name, if the model has one.
    fn constraint(&self, name: &str) -> Option<Constraint<Self>> {
        self.constraint_names().iter().position(|c| c == name).map(Constraint::unchecked)
    }

    /// [`LagrangeDirac::residual`] into a new vector.
    fn residual_vector(&self, t: f64, y: &VecY<Self>) -> VecY<Self> {
        let mut out = self.sizes().zeros_y::<Self>();
        self.residual(t, y, &mut out);
        out
    }

    /// [`LagrangeDirac::jacobian`] into a new, correctly zeroed matrix.
    fn jacobian_matrix(&self, t: f64, y: &VecY<Self>) -> MatYY<Self> {
        let mut out = self.sizes().zeros_yy::<Self>();
        self.jacobian(t, y, &mut out);
        out
    }
}

/// A model of fixed size with dense storage on the stack: every model `#[derive(LagrangeDirac)]`
/// makes and every composite of named subsystems. Generic code over such models may use
/// nalgebra's dense matrices on its blocks (`MatQQ::<M>::zeros()`, `a.transpose() * λ`), and
/// run it ([`Solve::solve`](crate::Solve::solve) watches a model's contacts and laws,
/// which the [`Hybrid`](crate::model::Hybrid) capability every such model has declares).
pub trait DenseModel:
    LagrangeDirac<Algebra = crate::algebra::Dense>
    + crate::shape::dims::Fixed
    + crate::model::Hybrid
    + crate::model::JointSpace
where
    DefaultAllocator: Storage<Self>,
{
}

impl<M> DenseModel for M
where
    M: LagrangeDirac<Algebra = crate::algebra::Dense>
        + crate::shape::dims::Fixed
        + crate::model::Hybrid
        + crate::model::JointSpace,
    DefaultAllocator: Storage<M>,
{
}
