//! The parameters capability: a model's `f64` fields read and written by index, and the
//! derivatives of its residual blocks and holonomic constraints with respect to each of them,
//! which forward sensitivities (and fits) need.

use nalgebra::DefaultAllocator;

use crate::model::blocks::ResidualBlocks;
use crate::model::lagrange_dirac::LagrangeDirac;
use crate::shape::dims::{Storage, VecC, VecH, VecQ};

/// A model whose parameters can be read, set and differentiated with respect to.
/// `#[derive(LagrangeDirac)]` and `#[derive(Interconnection)]` implement it for every model
/// they make (a model made of arrays of subsystems has no parameters and keeps the defaults);
/// sensitivities and the FMI export ask for it in their bounds.
pub trait Parameters: LagrangeDirac
where
    DefaultAllocator: Storage<Self>,
{
    /// How many parameters the model has: those its names list
    /// ([`parameter_names`](crate::model::Named::parameter_names)). Known from the type, except
    /// for a composite with arrays, whose arrays' lengths count.
    fn parameter_count(&self) -> usize {
        Self::NAMES.parameter_count()
    }

    /// The value of parameter `k` (an index into
    /// [`parameter_names`](crate::model::Named::parameter_names)). The derive implements it; it
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
    /// [`residual_blocks_dtheta`](Parameters::residual_blocks_dtheta) for each `k`, but a
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
        let count = self.parameter_count();
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

    /// The transposed parameter blocks: for every parameter `k`, into `out[k]`,
    ///
    /// `w.momentum_rateᵀ ∂ṗ/∂θ_k + w.dl_dvᵀ ∂(∂L/∂v)/∂θ_k + w.constraint_velocityᵀ ∂(A v + b)/∂θ_k`
    ///
    /// at fixed `(t, q, v, λ)`: what an adjoint sweep needs, the gradient of a weighted sum of
    /// the residual blocks with respect to all parameters. A primitive model's derive emits it
    /// by reverse accumulation on the expression graph, so it costs a small multiple of one
    /// evaluation of the blocks whatever the number of parameters, and never forms
    /// `∂/∂θ_k`; composites, arrays and networks sum their parts'. The default computes each
    /// parameter's blocks and weighs them. `out` must hold one value per parameter.
    fn residual_blocks_vjp_dtheta(
        &self,
        t: f64,
        q: &VecQ<Self>,
        v: &VecQ<Self>,
        lambda: &VecC<Self>,
        w: &ResidualBlocks<Self>,
        out: &mut [f64],
    ) {
        let count = self.parameter_count();
        assert_eq!(out.len(), count, "residual_blocks_vjp_dtheta: the slice must hold {count} values");
        let mut each = ResidualBlocks::<Self>::with_sizes(&self.sizes());
        for (k, out) in out.iter_mut().enumerate() {
            self.residual_blocks_dtheta(k, t, q, v, lambda, &mut each);
            *out = w.dot(&each);
        }
    }

    /// `w_φᵀ ∂φ/∂θ_k` for every parameter `k`, into `out[k]`: the transposed derivative of the
    /// holonomic constraint values at fixed `(t, q)`, generated like
    /// [`residual_blocks_vjp_dtheta`](Parameters::residual_blocks_vjp_dtheta). `out` must hold
    /// one value per parameter.
    fn holonomic_vjp_dtheta(&self, t: f64, q: &VecQ<Self>, w: &VecH<Self>, out: &mut [f64]) {
        let count = self.parameter_count();
        assert_eq!(out.len(), count, "holonomic_vjp_dtheta: the slice must hold {count} values");
        let mut each = self.sizes().zeros_h::<Self>();
        for (k, out) in out.iter_mut().enumerate() {
            self.holonomic_dtheta(k, t, q, &mut each);
            *out = w.dot(&each);
        }
    }
}

/// [`Parameters::residual_blocks_dtheta`] of models of type `M`.
type BlocksDtheta<M> = fn(&M, usize, f64, &VecQ<M>, &VecQ<M>, &VecC<M>, &mut ResidualBlocks<M>);
/// [`Parameters::residual_blocks_dtheta_all`] of models of type `M`.
type BlocksDthetaAll<M> = fn(&M, f64, &VecQ<M>, &VecQ<M>, &VecC<M>, &mut [ResidualBlocks<M>]);

/// [`Parameters::residual_blocks_vjp_dtheta`] of models of type `M`.
type BlocksVjp<M> = fn(&M, f64, &VecQ<M>, &VecQ<M>, &VecC<M>, &ResidualBlocks<M>, &mut [f64]);

/// A model's parameter derivatives as function pointers: what code that holds a model of any
/// kind keeps when it was built under a [`Parameters`] bound (an integrator asked for
/// sensitivities), so that its steps differentiate with respect to parameters without
/// every method of it asking for the capability.
pub(crate) struct ParameterDerivatives<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// [`Parameters::residual_blocks_dtheta`].
    pub blocks: BlocksDtheta<M>,
    /// [`Parameters::residual_blocks_dtheta_all`].
    pub all: BlocksDthetaAll<M>,
    /// [`Parameters::holonomic_dtheta`].
    pub holonomic: fn(&M, usize, f64, &VecQ<M>, &mut VecH<M>),
    /// [`Parameters::residual_blocks_vjp_dtheta`].
    pub transposed: BlocksVjp<M>,
    /// [`Parameters::holonomic_vjp_dtheta`].
    pub holonomic_transposed: fn(&M, f64, &VecQ<M>, &VecH<M>, &mut [f64]),
}

impl<M: Parameters> ParameterDerivatives<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The parameter derivatives of models of type `M`.
    pub fn of() -> Self {
        ParameterDerivatives {
            blocks: M::residual_blocks_dtheta,
            all: M::residual_blocks_dtheta_all,
            holonomic: M::holonomic_dtheta,
            transposed: M::residual_blocks_vjp_dtheta,
            holonomic_transposed: M::holonomic_vjp_dtheta,
        }
    }
}

impl<M: LagrangeDirac> Clone for ParameterDerivatives<M>
where
    DefaultAllocator: Storage<M>,
{
    fn clone(&self) -> Self {
        *self
    }
}

impl<M: LagrangeDirac> Copy for ParameterDerivatives<M> where DefaultAllocator: Storage<M> {}
