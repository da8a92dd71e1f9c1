//! The inputs and outputs capability: a model whose forces or Lagrangian read inputs `u` set
//! while it runs (a torque, a voltage, a controller's output), with the derivatives that an
//! exact linearisation `(A, B, C, D)` needs.
//!
//! The outputs themselves are part of [`LagrangeDirac`], since every integration records them;
//! this trait carries what controllers and linearisation add: setting inputs, and the blocks
//! `∂ṗ/∂u`, `∂(∂L/∂v)/∂u`, `∂y/∂q`, `∂y/∂v` and `∂y/∂u`.

use nalgebra::DefaultAllocator;

use crate::model::keys::Input;
use crate::model::lagrange_dirac::LagrangeDirac;
use crate::shape::dims::{Storage, VecC, VecQ};

/// A model with inputs and outputs. `#[derive(LagrangeDirac)]` and
/// `#[derive(Interconnection)]` implement it for every model they make, with the inputs and
/// outputs it declares (a model without any keeps the defaults, which have nothing to do);
/// methods that set inputs or linearise ask for it in their bounds.
pub trait InputsOutputs: LagrangeDirac
where
    DefaultAllocator: Storage<Self>,
{
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

    /// The value of an input.
    fn input(&self, key: Input<Self>) -> f64 {
        self.input_value(key.index())
    }

    /// Sets an input. Between the steps of an integration, set inputs through the integrator
    /// ([`Integrator::set_input`](crate::Integrator::set_input)), which restarts it.
    fn set_input(&mut self, key: Input<Self>, value: f64) {
        self.set_input_value(key.index(), value);
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

    /// `∂(A v + b)/∂u`, `m × n_u`, dense and column-major: nonzero when an input prescribes a
    /// motion through a constraint (a voltage source's voltage). Generated for models with
    /// inputs and constraints.
    fn av_du(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q, v);
        assert!(
            out.is_empty(),
            "av_du: the model has no inputs or no constraints, so the slice must be empty"
        );
    }

    /// `∂y/∂q` of the outputs, `n_y × n`, dense and column-major. Generated for models with
    /// outputs.
    fn output_dq(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>, out: &mut [f64]) {
        let _ = (t, q, v, lambda);
        assert!(out.is_empty(), "output_dq: the model has no outputs, so the slice must be empty");
    }

    /// `∂y/∂v` of the outputs, `n_y × n`, dense and column-major.
    fn output_dv(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>, out: &mut [f64]) {
        let _ = (t, q, v, lambda);
        assert!(out.is_empty(), "output_dv: the model has no outputs, so the slice must be empty");
    }

    /// `∂y/∂λ` of the outputs, `n_y × m`, dense and column-major: nonzero for outputs that read
    /// a multiplier (a source's current, a support's force).
    fn output_dlambda(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>, out: &mut [f64]) {
        let _ = (t, q, v, lambda);
        assert!(
            out.is_empty(),
            "output_dlambda: the model has no outputs or no constraints, so the slice must be empty"
        );
    }

    /// `∂y/∂u` of the outputs, `n_y × n_u`, dense and column-major.
    fn output_du(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>, out: &mut [f64]) {
        let _ = (t, q, v, lambda);
        assert!(
            out.is_empty(),
            "output_du: the model has no outputs or no inputs, so the slice must be empty"
        );
    }

    /// Whether the derive generated [`InputsOutputs::force_du`] and the weighted Hessian
    /// ([`InputsOutputs::weighted_hessian`]) that transcriptions of optimal control problems
    /// need: for primitive models with inputs whose Hessian's lower triangle over `(q, v, u)`
    /// has at most 2048 entries. `false` for every other model.
    const SECOND_ORDER: bool = false;

    /// `∂F/∂u` of the forces alone, `n × n_u`, dense and column-major (`∂ṗ/∂u` holds
    /// `∂²L/∂q∂u` too). Generated where [`InputsOutputs::SECOND_ORDER`].
    fn force_du(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q, v);
        assert!(out.is_empty(), "force_du: the model has no second-order blocks, so the slice must be empty");
    }

    /// The structurally nonzero entries `(row, column)`, `row ≥ column`, of the weighted
    /// Hessian's lower triangle over `x = (q, v, u)` (indices `0..n` for `q`, `n..2n` for `v`,
    /// `2n..2n + n_u` for `u`), in the order [`InputsOutputs::weighted_hessian`] writes them.
    /// Known when the model compiles; empty where not [`InputsOutputs::SECOND_ORDER`].
    fn weighted_hessian_pattern(&self) -> &'static [(usize, usize)] {
        &[]
    }

    /// The lower triangle of `∂²/∂x² (wqᵀ ∂L/∂q + wvᵀ ∂L/∂v + wfᵀ F)` at `(t, q, v)` and the
    /// model's inputs, over `x = (q, v, u)`, one value per entry of
    /// [`InputsOutputs::weighted_hessian_pattern`]: the second derivatives of the residual
    /// blocks contracted with multipliers, generated symbolically (forward over reverse).
    #[allow(clippy::too_many_arguments)]
    fn weighted_hessian(
        &self,
        t: f64,
        q: &VecQ<Self>,
        v: &VecQ<Self>,
        wq: &VecQ<Self>,
        wv: &VecQ<Self>,
        wf: &VecQ<Self>,
        out: &mut [f64],
    ) {
        let _ = (t, q, v, wq, wv, wf);
        assert!(
            out.is_empty(),
            "weighted_hessian: the model has no second-order blocks, so the slice must be empty"
        );
    }
}
