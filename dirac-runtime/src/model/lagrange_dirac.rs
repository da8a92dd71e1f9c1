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

use std::borrow::Cow;

use nalgebra::DefaultAllocator;

use crate::algebra::Algebra;
use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
use crate::model::keys::{Constraint, Coordinate, Input};
use crate::model::names::Named;
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

/// A typed error if a parameter of `model` is NaN or infinite.
pub fn check_parameters<M: LagrangeDirac>(model: &M) -> Result<(), crate::error::SimError>
where
    DefaultAllocator: Storage<M>,
{
    match model.non_finite_parameter() {
        Some((name, value)) => Err(crate::error::SimError::InvalidParameter { name, value }),
        None => Ok(()),
    }
}

/// The derived equations of a model, for people: plain text and LaTeX.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Equations {
    /// One equation a line, in Rust-like notation.
    pub text: Cow<'static, str>,
    /// An `aligned` LaTeX environment, one equation a row.
    pub latex: Cow<'static, str>,
}

/// How many arithmetic operations (`+ − × ÷`, an elementary function counting as one) the
/// generated kernels of a model perform per call, after common subexpressions are shared.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OperationCounts {
    /// [`LagrangeDirac::residual`].
    pub residual: usize,
    /// [`LagrangeDirac::jacobian`].
    pub jacobian: usize,
    /// Residual and Jacobian together, sharing subexpressions between them.
    pub residual_and_jacobian: usize,
    /// [`LagrangeDirac::residual_blocks`].
    pub residual_blocks: usize,
    /// [`LagrangeDirac::jacobian_blocks`].
    pub jacobian_blocks: usize,
}

impl OperationCounts {
    /// All counts zero.
    pub const ZERO: OperationCounts = OperationCounts {
        residual: 0,
        jacobian: 0,
        residual_and_jacobian: 0,
        residual_blocks: 0,
        jacobian_blocks: 0,
    };

    /// The counts of two kernels run one after the other.
    pub const fn plus(self, other: OperationCounts) -> OperationCounts {
        OperationCounts {
            residual: self.residual + other.residual,
            jacobian: self.jacobian + other.jacobian,
            residual_and_jacobian: self.residual_and_jacobian + other.residual_and_jacobian,
            residual_blocks: self.residual_blocks + other.residual_blocks,
            jacobian_blocks: self.jacobian_blocks + other.jacobian_blocks,
        }
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
/// to the model. Holonomic constraints `φ(q, t) = 0` contribute the first [`Dimensions::NH`]
/// rows, `A = ∂φ/∂q` and `b = ∂φ/∂t`. `b` is zero unless a constraint prescribes a motion.
pub trait LagrangeDirac: Dimensions + Named + Sized + 'static
where
    DefaultAllocator: Storage<Self>,
{
    /// How the model's blocks are stored and its linear systems solved:
    /// [`Dense`](crate::algebra::Dense) for models whose sizes are fixed when they compile,
    /// [`Sparse`](crate::algebra::Sparse) for models made of arrays of subsystems.
    type Algebra: Algebra<Self>;

    /// The arithmetic cost of the generated kernels.
    const OPERATION_COUNTS: OperationCounts;
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
    /// The sparsity pattern of the condensed Newton system and what to say about each unknown;
    /// interconnections combine their subsystems' to check themselves when they compile.
    const STRUCTURE: Structure;

    /// The derived equations, for people.
    fn equations() -> Equations;

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
    /// The holonomic constraint values `φ(q, t)`, zero on the constraint manifold.
    fn holonomic(&self, t: f64, q: &VecQ<Self>, out: &mut VecH<Self>);
    /// The rates `b(q, t)` of the constraints `A(q, t) v + b(q, t) = 0`: `∂φ/∂t` for a
    /// holonomic row, the part without velocities for a velocity row. Zero unless a constraint
    /// prescribes a motion (a rheonomic constraint); then it does work, and
    /// [`constraint_power`](LagrangeDirac::constraint_power) is its power.
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
    /// infinite, with that value. Integrators and [`consistent_state`](crate::consistent_state)
    /// refuse such a model before they evaluate it. The derive implements it.
    fn non_finite_parameter(&self) -> Option<(String, f64)> {
        None
    }

    /// `∂(∂L/∂v)/∂t`: how the momenta of a time-dependent Lagrangian change at fixed `(q, v)`.
    fn l_vt(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut VecQ<Self>);
    /// `∂L/∂t`: with the power of the forces, the rate of change of the energy on solutions,
    /// `dE/dt = ⟨F, v⟩ − ∂L/∂t`.
    fn dl_dt(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>) -> f64;

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

    /// The full dotted name of every coordinate, in the order of `q` (`left.x2` in a
    /// composite, `cells[3].x` in an array).
    fn coordinate_names(&self) -> Vec<String> {
        Self::NAMES.coordinate_names()
    }

    /// The full dotted name of every velocity, in the order of `v`.
    fn velocity_names(&self) -> Vec<String> {
        Self::NAMES.velocity_names()
    }

    /// The full dotted name of every constraint, in the order of the rows of `A(q)` and of `λ`.
    fn constraint_names(&self) -> Vec<String> {
        Self::NAMES.constraint_names()
    }

    /// The coordinates through which the model may be interconnected, at any depth.
    fn ports(&self) -> Vec<Coordinate<Self>> {
        Self::NAMES.port_indices().into_iter().map(Coordinate::unchecked).collect()
    }

    /// The full dotted name of every input (`motor.voltage` in a composite), in the order of
    /// the model's [`Input`] keys.
    fn input_names(&self) -> Vec<String> {
        Self::NAMES.input_names()
    }

    /// The full dotted name of every output (`arm.tip_x` in a composite), in the order of the
    /// model's [`Output`](crate::model::keys::Output) keys.
    fn output_names(&self) -> Vec<String> {
        Self::NAMES.output_names()
    }

    /// The model's outputs at `(t, q, v, λ)`, into `out` (one value per output, in the order
    /// of their keys). The derive implements it for models with outputs; for a model without,
    /// there is nothing to write.
    fn outputs(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>, out: &mut [f64]) {
        let _ = (t, q, v, lambda);
        assert!(out.is_empty(), "outputs: the model has none, so the output slice must be empty");
    }

    /// `∂ṗ/∂u`, `n × n_u`, dense and column-major, into `out`; the input matrix `B` of a
    /// linearisation. Generated for models with inputs.
    fn dpdot_du(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>, out: &mut [f64]) {
        let _ = (t, q, v, lambda);
        assert!(out.is_empty(), "dpdot_du: the model has no inputs, so the slice must be empty");
    }

    /// `∂(∂L/∂v)/∂u`, `n × n_u`, dense and column-major: nonzero when an input enters the
    /// momenta. Generated for models with inputs.
    fn l_vu(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q, v);
        assert!(out.is_empty(), "l_vu: the model has no inputs, so the slice must be empty");
    }

    /// `∂y/∂q` of the outputs, `n_y × n`, dense and column-major. Generated for models with
    /// outputs.
    fn output_dq(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q, v);
        assert!(out.is_empty(), "output_dq: the model has no outputs, so the slice must be empty");
    }

    /// `∂y/∂v` of the outputs, `n_y × n`, dense and column-major.
    fn output_dv(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q, v);
        assert!(out.is_empty(), "output_dv: the model has no outputs, so the slice must be empty");
    }

    /// `∂y/∂u` of the outputs, `n_y × n_u`, dense and column-major.
    fn output_du(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q, v);
        assert!(
            out.is_empty(),
            "output_du: the model has no outputs or no inputs, so the slice must be empty"
        );
    }

    /// The names of the model's unilateral constraints `φ_u(q, t) ≥ 0`
    /// (`#[dirac(unilateral(name) = φ)]`: contacts, stops, walls), in the order declared.
    /// An interconnection has its subsystems', by dotted name (`ball.floor`).
    fn unilateral_names(&self) -> Vec<String> {
        Self::NAMES.unilateral_names()
    }

    /// The values `φ_u(q, t)` of the unilateral constraints, into `out` (one per constraint):
    /// positive while open, zero at contact.
    fn unilateral(&self, t: f64, q: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q);
        assert!(
            out.is_empty(),
            "unilateral: the model has no unilateral constraints, so the slice must be empty"
        );
    }

    /// `∂φ_u/∂q`, one row per unilateral constraint (its one-form, along which an impact's
    /// impulse acts), dense and column-major.
    fn unilateral_dq(&self, t: f64, q: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q);
        assert!(
            out.is_empty(),
            "unilateral_dq: the model has no unilateral constraints, so the slice must be empty"
        );
    }

    /// The coefficient of restitution of each unilateral constraint: the share of the normal
    /// velocity an impact reverses (1 elastic, 0 plastic).
    fn restitution(&self, t: f64, q: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q);
        assert!(
            out.is_empty(),
            "restitution: the model has no unilateral constraints, so the slice must be empty"
        );
    }

    /// Whether unilateral constraint `j` is closed, held as a holonomic constraint: in the
    /// companion the derive makes of a model with unilateral constraints
    /// (`model.with_contacts()`, of type `<Model>WithContacts`); never in other models.
    fn contact_closed(&self, j: usize) -> bool {
        let _ = j;
        false
    }

    /// Closes or opens unilateral constraint `j` of a companion with contacts that can rest;
    /// whether the model has such a switch (false for other models, which it leaves alone).
    fn set_contact_closed(&mut self, j: usize, closed: bool) -> bool {
        let _ = (j, closed);
        false
    }

    /// The constraint row that holds unilateral constraint `j` while it is closed, in a
    /// companion with contacts that can rest: its multiplier is the contact force.
    fn contact_row(&self, j: usize) -> Option<usize> {
        let _ = j;
        None
    }

    /// The model's event functions `g(t, q, v, λ)` (`#[dirac(event(name, direction) = g)]`),
    /// into `out`, one per event in the order declared (`Events::new().declared()` watches
    /// them).
    fn events(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>, out: &mut [f64]) {
        let _ = (t, q, v, lambda);
        assert!(out.is_empty(), "events: the model declares none, so the slice must be empty");
    }

    /// The value of input `k`, the position of an [`Input`] key. The derive implements it for
    /// models with inputs; it panics if the model has no input `k`.
    fn input_value(&self, k: usize) -> f64 {
        panic!("the model has no input {k}: it has {}", Self::NAMES.input_count())
    }

    /// Sets input `k`, the position of an [`Input`] key. The derive implements it for models
    /// with inputs; it panics if the model has no input `k`.
    fn set_input_value(&mut self, k: usize, value: f64) {
        let _ = value;
        panic!("the model has no input {k}: it has {}", Self::NAMES.input_count())
    }

    /// The full dotted name of every parameter, the model's `f64` fields (`left.k` in a
    /// composite: its subsystems' in field order, then its own), in the order of their indices:
    /// the parameters that [`parameter_value`](LagrangeDirac::parameter_value), sensitivities
    /// and fits name. A model made of arrays of subsystems has none.
    fn parameter_names(&self) -> Vec<String> {
        Self::NAMES.parameter_names()
    }

    /// The index of the parameter with this dotted name, if the model has one.
    fn parameter_index(&self, name: &str) -> Option<usize> {
        self.parameter_names().iter().position(|p| p == name)
    }

    /// The value of parameter `k` (an index into
    /// [`parameter_names`](LagrangeDirac::parameter_names)). The derive implements it; it
    /// panics if the model has no parameter `k`.
    fn parameter_value(&self, k: usize) -> f64 {
        panic!("the model has no parameter {k}: it has {}", Self::NAMES.parameter_count())
    }

    /// Sets parameter `k`. The derive implements it; it panics if the model has no parameter
    /// `k`. Between the steps of an integration, change parameters through the integrator
    /// ([`Integrator::update`](crate::Integrator::update)), which restarts it.
    fn set_parameter_value(&mut self, k: usize, value: f64) {
        let _ = value;
        panic!("the model has no parameter {k}: it has {}", Self::NAMES.parameter_count())
    }

    /// The derivatives of the residual blocks with respect to parameter `k` at fixed
    /// `(t, q, v, λ)`: `∂ṗ/∂θ_k`, `∂(∂L/∂v)/∂θ_k` and `∂(A v + b)/∂θ_k`, each vector written
    /// whole. Generated symbolically, with shared subexpressions, for every parameter of a
    /// primitive model and of a composite of named subsystems; it panics if the model has no
    /// parameter `k`.
    fn residual_blocks_dtheta(
        &self,
        k: usize,
        t: f64,
        q: &VecQ<Self>,
        v: &VecQ<Self>,
        lambda: &VecC<Self>,
        out: &mut ResidualBlocks<Self>,
    ) {
        let _ = (t, q, v, lambda, out);
        panic!("the model has no parameter {k}: it has {}", Self::NAMES.parameter_count())
    }

    /// The derivatives of the residual blocks with respect to every parameter at once, into
    /// `out[k]` for parameter `k`; it panics if `out` holds fewer blocks than the model has
    /// parameters. The same values as
    /// [`residual_blocks_dtheta`](LagrangeDirac::residual_blocks_dtheta) for each `k`, but a
    /// primitive model's derive evaluates what the parameters' derivatives share (its
    /// trigonometry, its mass matrix) once for all of them; elsewhere it calls
    /// `residual_blocks_dtheta` for each parameter.
    fn residual_blocks_dtheta_all(
        &self,
        t: f64,
        q: &VecQ<Self>,
        v: &VecQ<Self>,
        lambda: &VecC<Self>,
        out: &mut [ResidualBlocks<Self>],
    ) {
        let count = Self::NAMES.parameter_count();
        for (k, out) in out[..count].iter_mut().enumerate() {
            self.residual_blocks_dtheta(k, t, q, v, lambda, out);
        }
    }

    /// `∂φ/∂θ_k`: the derivative of the holonomic constraint values with respect to parameter
    /// `k` at fixed `(t, q)`, written whole.
    fn holonomic_dtheta(&self, k: usize, t: f64, q: &VecQ<Self>, out: &mut VecH<Self>) {
        let _ = (t, q, out);
        panic!("the model has no parameter {k}: it has {}", Self::NAMES.parameter_count())
    }

    /// The value of an input.
    fn input(&self, key: Input<Self>) -> f64 {
        self.input_value(key.index())
    }

    /// Sets an input. Between the steps of an integration, set inputs through the integrator
    /// ([`Integrator::set_input`](crate::Integrator::set_input)), which restarts it.
    fn set_input(&mut self, key: Input<Self>, value: f64) {
        self.set_input_value(key.index(), value);
    }

    /// The coordinate with this (dotted) name, if the model has one.
    fn coordinate(&self, name: &str) -> Option<Coordinate<Self>> {
        self.coordinate_names().iter().position(|c| c == name).map(Coordinate::unchecked)
    }

    /// The constraint with this (dotted) name, if the model has one.
    fn constraint(&self, name: &str) -> Option<Constraint<Self>> {
        self.constraint_names().iter().position(|c| c == name).map(Constraint::unchecked)
    }

    /// The power `⟨Ωᵀμ, v⟩` of the interconnection forces; zero wherever the interconnection
    /// constraints hold, since an interconnection is lossless (Tellegen's theorem), unless it
    /// prescribes a relative motion (`Ω v + b = 0`): then it is `−⟨μ, b⟩`.
    fn interconnection_power(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>) -> f64 {
        let mut f = self.sizes().zeros_q::<Self>();
        self.interconnection_forces(t, q, lambda, &mut f);
        f.dot(v)
    }

    /// The generalised energy `E(q, v, p) = ⟨p, v⟩ − L(q, v, t)`.
    fn energy(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, p: &VecQ<Self>) -> f64 {
        p.dot(v) - self.lagrangian(t, q, v)
    }

    /// The power `⟨Aᵀλ, v⟩ = −⟨λ, b(q, t)⟩` that the constraints put into the model where
    /// they hold: zero unless a constraint prescribes a motion. On solutions
    /// `dE/dt = ⟨F, v⟩ − ∂L/∂t + constraint_power`.
    fn constraint_power(&self, t: f64, q: &VecQ<Self>, lambda: &VecC<Self>) -> f64 {
        let mut b = self.sizes().zeros_c::<Self>();
        self.constraint_rate(t, q, &mut b);
        -b.dot(lambda)
    }

    /// The power of the external forces `⟨F(q, v, t), v⟩`; on solutions `dE/dt` equals it.
    fn power(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>) -> f64 {
        let mut f = self.sizes().zeros_q::<Self>();
        self.force(t, q, v, &mut f);
        f.dot(v)
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
/// nalgebra's dense matrices on its blocks (`MatQQ::<M>::zeros()`, `a.transpose() * λ`).
pub trait DenseModel: LagrangeDirac<Algebra = crate::algebra::Dense> + crate::shape::dims::Fixed
where
    DefaultAllocator: Storage<Self>,
{
}

impl<M> DenseModel for M
where
    M: LagrangeDirac<Algebra = crate::algebra::Dense> + crate::shape::dims::Fixed,
    DefaultAllocator: Storage<M>,
{
}
