//! Inputs held between samples: the run recorded with each input constant over
//! `[t_k, t_{k+1})` ([`Radau::record_held`]), and the gradient with respect to every sample
//! `u_k` ([`Recording::gradient_held`]), what a trajectory optimisation or a fit of an
//! unknown excitation needs.
//!
//! The integration stops at each sample and restarts with the inputs set, so no step straddles
//! a change. A held input enters the forces (`∂ṗ/∂u`): the positions, velocities and momenta go
//! on continuously across a change, and the sweep passes through it. A step's share of the
//! gradient is `Σ_j ν_p,jᵀ ∂ṗ/∂u(Y_j)` with the stage weights of the parameters' part, added to
//! the sample the step is in.

use nalgebra::DefaultAllocator;

use super::{Kept, Objective, Radau, Recording, Step};
use crate::algebra::newton::NewtonSolver;
use crate::error::SimError;
use crate::integrator::Integrator;
use crate::model::hybrid::has_laws;
use crate::model::keys::Input;
use crate::model::state::State;
use crate::model::{Hybrid, InputsOutputs, LagrangeDirac, Parameters};
use crate::shape::dims::Storage;

/// `∂ṗ/∂u` of a model's inputs at a state, `n × n_u`, column-major.
pub(super) type InputRates<M> = fn(&M, f64, &State<M>, &mut [f64]);

/// The samples of a recording that held inputs: which inputs, the first step of each sample,
/// and the inputs' values there.
pub(super) struct Segments {
    /// The held inputs' indices among the model's inputs.
    inputs: Vec<usize>,
    /// The index of the first step of each sample.
    starts: Vec<usize>,
    /// The held inputs' values, sample by sample.
    values: Vec<Vec<f64>>,
}

/// Gathers each step's `∂G/∂u` into the sample it belongs to.
pub(super) struct Accumulator<'s, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    pub rates: InputRates<M>,
    /// How many inputs the model has.
    pub count: usize,
    segments: &'s Segments,
    /// `∂G/∂u_k`, input by input.
    by_sample: Vec<Vec<f64>>,
}

impl<M: LagrangeDirac> Accumulator<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    /// Adds `step_bar`, step `k`'s share for every input of the model, to its sample, and
    /// clears it.
    pub fn add(&mut self, k: usize, step_bar: &mut [f64]) {
        let sample = self.segments.starts.partition_point(|&s| s <= k) - 1;
        for (held, &i) in self.by_sample.iter_mut().zip(&self.segments.inputs) {
            held[sample] += step_bar[i];
        }
        step_bar.fill(0.0);
    }

    /// `∂G/∂u_k`, input by input.
    pub fn finish(self) -> Vec<Vec<f64>> {
        self.by_sample
    }
}

impl<'m, M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>> Radau<'m, M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// Integrates from the consistent `state` at `t0` to `t_end` as [`record`](Self::record)
    /// does, holding each input of `held` at its `k`-th value over `[times[k], times[k+1])`
    /// (the last to `t_end`); `times` starts at `t0` and rises. The integration stops at each
    /// sample and restarts there, so that [`Recording::gradient_held`] gives the gradient with
    /// respect to every sample of every held input, besides the parameters and initial values.
    /// Needs an integrator built on `&mut model`; the model keeps the last samples' values.
    ///
    /// Refused as `record` refuses, for a model with contacts, switching surfaces or laws
    /// (not crossed with held inputs yet), for an input that enters the momenta or the
    /// constraints (the state would jump at a change: only forces are carried), and for
    /// samples that do not fit the run (`InvalidOption`, naming why).
    pub fn record_held(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        times: &[f64],
        held: &[(Input<M>, &[f64])],
    ) -> Result<Recording<M>, SimError>
    where
        M: Hybrid + Parameters + InputsOutputs,
    {
        self.check_recordable()?;
        let invalid = |reason: String| Err(SimError::InvalidOption { what: "held inputs", reason });
        let model = self.model.get();
        if !model.unilateral_names().is_empty() || model.has_switches() || has_laws(model) {
            return invalid(
                "the model has contacts, switching surfaces or laws, which a recording with held inputs \
                 does not cross yet"
                    .into(),
            );
        }
        let fits = times.first().is_some_and(|&t| t == t0)
            && times.windows(2).all(|w| w[0] < w[1])
            && times.last().is_some_and(|&t| t < t_end);
        if !fits {
            return invalid(format!(
                "the samples' times must start at t0 = {t0} and rise, each before the end {t_end}: got {times:?}"
            ));
        }
        let names = model.input_names();
        for (key, values) in held {
            let name = &names[key.index()];
            if values.len() != times.len() {
                return invalid(format!(
                    "the input `{name}` has {} values for {} sample times",
                    values.len(),
                    times.len()
                ));
            }
            if let Some(k) = values.iter().position(|u| !u.is_finite()) {
                return invalid(format!("the input `{name}`'s value at sample {k} is {}", values[k]));
            }
        }
        let set =
            |model: &mut M, k: usize| held.iter().for_each(|(key, values)| model.set_input(*key, values[k]));
        let end = |k: usize| times.get(k + 1).copied().unwrap_or(t_end);
        set(self.model.get_mut().ok_or(SimError::SharedModel { t: t0 })?, 0);
        forces_only(self.model.get(), t0, state, held)?;
        self.start(t0, state, end(0))?;
        let mut steps = Vec::new();
        let mut starts = vec![0];
        for k in 0..times.len() {
            if k > 0 {
                let t = self.t;
                set(self.model.get_mut().ok_or(SimError::SharedModel { t })?, k);
                forces_only(self.model.get(), t, &self.state.clone(), held)?;
                self.restart_until(end(k))?;
                starts.push(steps.len());
            }
            while !self.finished() {
                let (t, y) = (self.t, self.y.clone());
                let h = self.step()?;
                let z = [self.stages.z[0].clone(), self.stages.z[1].clone(), self.stages.z[2].clone()];
                steps.push(Step { t, h, y, z });
            }
        }
        let segments = Segments {
            inputs: held.iter().map(|(key, _)| key.index()).collect(),
            starts,
            values: (0..times.len()).map(|k| held.iter().map(|(_, values)| values[k]).collect()).collect(),
        };
        Ok(Recording {
            t0,
            start: state.clone(),
            t_end: self.t,
            end: self.y.clone(),
            kept: Kept::Whole(steps),
            impacts: Vec::new(),
            held: Some(segments),
        })
    }
}

/// Refuses a held input that enters the momenta (`∂(∂L/∂v)/∂u`) or the constraints
/// (`∂(A v + b)/∂u`) at `state`: a change of it would make the state jump.
fn forces_only<M: InputsOutputs>(
    model: &M,
    t: f64,
    state: &State<M>,
    held: &[(Input<M>, &[f64])],
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let sizes = model.sizes();
    let (n, m, count) = (sizes.nq, sizes.nc, model.input_names().len());
    let mut momenta = vec![0.0; n * count];
    let mut constraints = vec![0.0; m * count];
    model.l_vu(t, &state.q, &state.v, &mut momenta);
    model.av_du(t, &state.q, &state.v, &mut constraints);
    for (key, _) in held {
        let i = key.index();
        let enters = |values: &[f64], rows: usize| values[i * rows..(i + 1) * rows].iter().any(|&d| d != 0.0);
        if enters(&momenta, n) || enters(&constraints, m) {
            return Err(SimError::InvalidOption {
                what: "held inputs",
                reason: format!(
                    "the input `{}` enters the momenta or the constraints: the state would jump where it \
                     changes, and only inputs in the forces are carried",
                    model.input_names()[i]
                ),
            });
        }
    }
    Ok(())
}

impl<M: LagrangeDirac> Recording<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The gradient of `objective` over a run recorded by [`Radau::record_held`]: as
    /// [`gradient`](Self::gradient), and with respect to every sample of every held input
    /// ([`Gradient::inputs`](super::Gradient::inputs)). `model` is the model the run was
    /// recorded with; each step is swept with a copy holding that step's inputs.
    pub fn gradient_held(
        &self,
        model: &M,
        objective: &Objective<'_, M>,
    ) -> Result<super::Gradient<M>, SimError>
    where
        M: Parameters + InputsOutputs + Clone,
    {
        let Some(segments) = &self.held else {
            return Err(SimError::InvalidOption {
                what: "adjoint",
                reason: "the run held no inputs: take its gradient with `gradient`".into(),
            });
        };
        let copies: Vec<M> = segments
            .values
            .iter()
            .map(|values| {
                let mut copy = model.clone();
                for (&i, &u) in segments.inputs.iter().zip(values) {
                    copy.set_input_value(i, u);
                }
                copy
            })
            .collect();
        let model_at = |k: usize| &copies[segments.starts.partition_point(|&s| s <= k) - 1];
        let rates: InputRates<M> = |m, t, s, out| m.dpdot_du(t, &s.q, &s.v, &s.lambda, out);
        let accumulator = Accumulator {
            rates,
            count: model.input_names().len(),
            segments,
            by_sample: vec![vec![0.0; segments.values.len()]; segments.inputs.len()],
        };
        self.sweep_back(&model_at, objective, Some(accumulator))
    }
}
