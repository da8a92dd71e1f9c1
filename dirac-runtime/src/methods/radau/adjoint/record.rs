//! Recording a run for the adjoint: [`Run::record`] keeps every step and every jump,
//! [`Run::record_within`] checkpoints within a memory budget; both through the run's one loop,
//! as a [`Tangent`] it carries.

use nalgebra::DefaultAllocator;

use super::checkpoints::Checkpoints;
use super::{Cut, Kept, Radau, Recording, Step};
use crate::algebra::newton::NewtonSolver;
use crate::error::{Capability, SimError};
use crate::hybrid::event::Event;
use crate::hybrid::events::Events;
use crate::hybrid::jumps::{Crossed, Jump};
use crate::integrator::restart::restart_at_nearest;
use crate::model::hybrid::has_laws;
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac, Parameters};
use crate::output::recorder::Recorder;
use crate::output::solution::Sampling;
use crate::shape::dims::{Storage, VecY};
use crate::simulate::run::feedback::Open;
use crate::simulate::run::tangent::Tangent;
use crate::simulate::run::{Run, Solve};

impl<'m, M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>> Radau<'m, M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// Integrates from the consistent `state` at `t0` to `t_end`, as
    /// [`Solve::solve`] does, and keeps every accepted step
    /// for [`Recording::gradient`]: a shorthand of `run(t0, state, t_end).record()`
    /// ([`Run::record`]), which says what is crossed and what refused.
    pub fn record(&mut self, t0: f64, state: &State<M>, t_end: f64) -> Result<Recording<M>, SimError>
    where
        M: Hybrid + Parameters,
    {
        self.run(t0, state, t_end).record()
    }

    /// Integrates as [`record`](Self::record) does, but keeps, of the steps, only their sizes
    /// and as many of their starts as half of `budget` bytes holds: a shorthand of
    /// `run(t0, state, t_end).record_within(budget)` ([`Run::record_within`]).
    pub fn record_within(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        budget: usize,
    ) -> Result<Recording<M>, SimError>
    where
        M: Hybrid + Parameters,
    {
        self.run(t0, state, t_end).record_within(budget)
    }

    /// What a recording refuses, by name.
    pub(super) fn check_recordable(&self) -> Result<(), SimError> {
        let invalid = |reason: &str| Err(SimError::InvalidOption { what: "adjoint", reason: reason.into() });
        if M::NON_ASSOCIATED {
            return Err(SimError::Unsupported {
                method: "Radau's adjoint",
                capability: Capability::ContactFriction,
            });
        }
        if self.options.projection {
            return invalid("the projection onto the constraints has no derivative carried: turn it off");
        }
        if self.residual.driven() || self.feedback.is_some() {
            return invalid("a drive's inputs have no derivative to transpose: hold the inputs instead");
        }
        Ok(())
    }
}

impl<'m, M: Hybrid + Parameters, S: NewtonSolver<M, M::Algebra>> Run<'_, M, Radau<'m, M, S>, Open>
where
    DefaultAllocator: Storage<M>,
{
    /// Runs the integration as [`Run::solve`] does and keeps every accepted step for
    /// [`Recording::gradient`], instead of samples. The run's observer, progress report and
    /// events of its own compose with it; a controller, an event action or a drive, whose
    /// derivatives are not carried, do not compile with it.
    ///
    /// A model with unilateral constraints has its contacts watched, and one with switching
    /// surfaces (`abs`, `signum`, conditionals) has them located, as `solve` does: the
    /// recording keeps each impact's or crossing's jump and the sweep carries the adjoint back
    /// across it by the transposed saltation matrix. A model with laws (friction, diodes, ideal
    /// switches) has them switched as `solve` does, and each switch kept as a crossing is. A
    /// contact that comes to rest ends the recording in [`SimError::ContactCloses`].
    ///
    /// Refused with an [`InvalidOption`](SimError::InvalidOption) with projection on (the
    /// projection's derivative is not carried) or a drive set on the integrator before the run
    /// (its inputs' derivative is not known).
    pub fn record(self) -> Result<Recording<M>, SimError> {
        self.integrator.check_recordable()?;
        self.keep(Kept::Whole(Vec::new()))
    }

    /// Runs the integration as [`record`](Self::record) does, but keeps, of the steps, only
    /// their sizes and as many of their starts as half of `budget` bytes holds, thinned to
    /// every second one whenever it is full. The sweep solves the steps between two starts
    /// again and keeps them within the other half, recursively when they do not fit: the
    /// memory is bounded by `budget` plus eight bytes a step (the sizes), at the cost of
    /// solving the run again once for every level of checkpoints (one when `N` steps satisfy
    /// `N ≤ budget² / (32 s²)` for states of `s` bytes).
    ///
    /// Turns on [`RadauOptions::exact_stages`](crate::methods::radau::RadauOptions::exact_stages)
    /// for the run: each step's stages are solved to round-off, so that the sweep solves it
    /// again with the same result and the gradient is exact for the discrete solution.
    /// Refused as `record` refuses, for a budget below sixteen states, and for a model with
    /// contacts, switching surfaces or laws, whose jumps a recording within a budget does not
    /// cross yet.
    pub fn record_within(self, budget: usize) -> Result<Recording<M>, SimError> {
        let radau = &mut *self.integrator;
        radau.check_recordable()?;
        let model = radau.model.get();
        if let Some(contact) = model.unilateral_names().first() {
            return Err(SimError::InvalidOption {
                what: "adjoint",
                reason: format!(
                    "the contact `{contact}`: a recording within a budget does not cross impacts yet; \
                     record every step with `record`"
                ),
            });
        }
        if model.has_switches() || has_laws(model) {
            return Err(SimError::InvalidOption {
                what: "adjoint",
                reason: "the model has switching surfaces or laws (friction, diodes, switches): a recording \
                         within a budget does not cross them yet; record every step with `record`"
                    .into(),
            });
        }
        let checkpoints = Checkpoints::new(radau.model.sizes(), radau.options, budget)?;
        self.keep(Kept::Checkpointed(checkpoints))
    }

    /// Runs the loop with a tape that keeps the steps as `kept` holds them, and the jumps.
    fn keep(self, kept: Kept<M>) -> Result<Recording<M>, SimError> {
        let t0 = self.t0;
        let mut tape = Tape { kept, impacts: Vec::new(), from: None, start: None, exact: false };
        let (_, radau) = self.sampling(Sampling::Times(Vec::new())).go(Some(&mut tape))?;
        if radau.solver.deflating() {
            // Its steps' transposed systems are singular in the same multipliers, and not
            // deflated: refused rather than solved on a pivot of round-off.
            return Err(SimError::InvalidOption {
                what: "adjoint",
                reason: "the model's constraint rows are redundant (their multipliers are fixed at their least \
                         norm, which the adjoint sweep does not carry): drop the rows that repeat others, or use \
                         forward sensitivities"
                    .into(),
            });
        }
        let start = tape.start.expect("a run that started keeps its start");
        Ok(Recording {
            t0,
            start,
            t_end: radau.t,
            end: radau.y.clone(),
            kept: tape.kept,
            impacts: tape.impacts,
            held: None,
        })
    }
}

/// What [`Run::record`] keeps of a run, as a [`Tangent`] its loop carries: the steps (whole or
/// checkpointed) and every jump.
struct Tape<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    kept: Kept<M>,
    impacts: Vec<Cut<M>>,
    /// The start of the step being taken.
    from: Option<(f64, VecY<M>)>,
    /// The state the run started from.
    start: Option<State<M>>,
    /// Whether the integrator solved its stages to round-off before the run.
    exact: bool,
}

impl<M: Hybrid + Parameters, S: NewtonSolver<M, M::Algebra>> Tangent<M, Radau<'_, M, S>> for Tape<M>
where
    DefaultAllocator: Storage<M>,
{
    fn cross(
        &mut self,
        model: &M,
        events: &mut Events<'_, M>,
        event: &Event,
    ) -> Result<Crossed<M>, SimError> {
        events.cross(model, event, "adjoint")
    }

    fn prepare(&mut self, radau: &mut Radau<'_, M, S>) {
        self.exact = radau.options.exact_stages;
        if let Kept::Checkpointed(_) = self.kept {
            radau.options.exact_stages = true;
        }
    }

    fn restore(&mut self, radau: &mut Radau<'_, M, S>) {
        radau.options.exact_stages = self.exact;
    }

    fn started(&mut self, _: &Radau<'_, M, S>, _: &Recorder<M>, from: &State<M>) -> Result<(), SimError> {
        self.start = Some(from.clone());
        Ok(())
    }

    fn before_step(&mut self, radau: &Radau<'_, M, S>) {
        match &mut self.kept {
            Kept::Whole(_) => self.from = Some((radau.t, radau.y.clone())),
            Kept::Checkpointed(checkpoints) => checkpoints.mark(radau.t, &radau.y),
        }
    }

    fn after_step(&mut self, radau: &Radau<'_, M, S>, h: f64) {
        match &mut self.kept {
            Kept::Whole(steps) => {
                let (t, y) = self.from.take().expect("a step has a start");
                let z = [radau.stages.z[0].clone(), radau.stages.z[1].clone(), radau.stages.z[2].clone()];
                steps.push(Step { t, h, y, z });
            }
            Kept::Checkpointed(checkpoints) => checkpoints.push(h),
        }
    }

    fn sampled(&mut self, _: &Radau<'_, M, S>, _: &Recorder<M>, _: usize) {}

    fn jump(&mut self, radau: &mut Radau<'_, M, S>, t: f64, mut jump: Jump<M>) -> Result<State<M>, SimError> {
        let Kept::Whole(steps) = &self.kept else {
            unreachable!("a recording within a budget refuses models whose events jump")
        };
        let step = steps.len() - 1;
        restart_at_nearest(radau, t, &mut jump.after)?;
        let after = jump.after.clone();
        self.impacts.push(Cut { step, t, jump });
        Ok(after)
    }

    fn restarted(&mut self, _: &Recorder<M>, _: usize) {}
}
