//! Radau as an [`Integrator`]: start, change and restart, step, and the state between
//! steps.

use nalgebra::DefaultAllocator;

use super::{DenseOutput, Radau, RadauStats};
use crate::algebra::newton::NewtonSolver;
use crate::error::SimError;
use crate::integrator::Integrator;
use crate::model::state::State;
use crate::model::{LagrangeDirac, Parameters};
use crate::shape::dims::Storage;
use crate::simulate::sensitive::Sensitive;
use crate::simulate::sensitivity::Sensitivities;

impl<M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>> Integrator<M> for Radau<'_, M, S>
where
    DefaultAllocator: Storage<M>,
{
    type Stats = RadauStats;

    const NAME: &'static str = "Radau";

    fn model(&self) -> &M {
        self.model.get()
    }

    fn start(&mut self, t0: f64, state: &State<M>, t_end: f64) -> Result<(), SimError> {
        // A drive sets the inputs at the start before the state is checked against them.
        self.residual.stretch_end = self.residual.stops.stretch(t0, t_end);
        self.residual.apply_state(&mut self.model, t0, state);
        self.restarts.start(self.model.get(), (t0, t_end), state, self.options.rtol.max(1e-8))?;
        state.write_y(&mut self.y);
        self.tolerances.begin_run(0.1 * (t_end - t0));
        if let Some(cell) = &self.multipliers {
            // The velocities only the forces fix, looked for where the model can say (a dense
            // one); elsewhere the multipliers between steps stay the collocation polynomial's.
            let accelerations = &mut cell.borrow_mut().0;
            accelerations.forget();
            if accelerations.prepare(self.model.get(), t0, (&state.q, &state.v)).is_err() {
                accelerations.unprepare();
            }
        }
        // The peaks start empty: a group at zero but for round-off (a multiplier that starts at
        // 2e-16) would cap its tolerance at round-off. Accepted steps set them, and a step is
        // judged by the peaks it would reach.
        self.state.clone_from(state);
        let span = t_end - t0;
        // A tenth of the span: near t = 0, the resolution the run's own times have.
        self.time_scale = 0.1 * span;
        self.stats = RadauStats::default();
        self.h = match self.options.initial_step {
            Some(h) => h,
            None => self.first_step(t0, state, span),
        };
        self.start_sensitivities(t0, state)?;
        self.begin(t0, t_end, true)
    }

    fn model_mut(&mut self) -> Option<&mut M> {
        self.restarts.model_mut(&mut self.model, self.t, &self.state)
    }

    fn restart_until(&mut self, t_end: f64) -> Result<(), SimError> {
        if self.t >= t_end {
            return Ok(());
        }
        // The momenta are as exact as the stages' Newton iteration left them: within their
        // error weights.
        let tolerances = &self.tolerances;
        let slack = |i, p| tolerances.momentum_weight(i, p);
        self.restarts.resume(self.model.get(), self.t, &self.state, (self.options.rtol.max(1e-8), slack))?;
        self.h = self.h.max(self.unclipped);
        self.begin(self.t, t_end, false)
    }

    fn set_inputs_at(&mut self, t: f64, state: &State<M>) {
        self.residual.apply_state(&mut self.model, t, state);
    }

    fn driven(&self) -> bool {
        self.residual.driven()
    }

    fn restart_at(&mut self, t: f64, state: &State<M>) -> Result<(), SimError> {
        if self.forward.is_some() {
            return Err(SimError::InvalidOption {
                what: "sensitivities",
                reason: format!(
                    "a restart at t = {t} (an event's reset, a change of the model or a contact coming to \
                     rest) would need the sensitivities' jump conditions, which are carried only across \
                     impacts (by `solve_with_sensitivities`): integrate with sensitivities between such events"
                ),
            });
        }
        self.restart_state(t, state)
    }

    fn end(&self) -> f64 {
        self.residual.stops.goal()
    }

    fn exact_multipliers(&self, t: f64, state: &mut State<M>) {
        if let Some(cell) = &self.multipliers {
            let (accelerations, acceleration, lambda) = &mut *cell.borrow_mut();
            if accelerations.evaluate(self.model.get(), t, (&state.q, &state.v), acceleration, lambda)
                && lambda.iter().all(|x| x.is_finite())
            {
                state.lambda.copy_from(lambda);
            }
        }
    }

    fn next_step_end(&self) -> f64 {
        (self.t + self.h.max(self.unclipped)).min(self.residual.stops.goal())
    }

    fn end_step_at(&mut self, t: Option<f64>) -> bool {
        self.residual.stops.set_timed(t);
        self.t_end = self.residual.stops.stretch(self.t, self.residual.stops.goal());
        self.residual.stretch_end = self.t_end;
        true
    }

    fn step(&mut self) -> Result<f64, SimError> {
        if self.residual.stops.due(self.t, self.t_end) {
            // A stop: the inputs jump or bend here, so the stages extrapolated from the last
            // step are dropped and the rates evaluated afresh with the inputs after it.
            self.h = self.h.max(self.unclipped);
            self.begin(self.t, self.residual.stops.goal(), false)?;
        }
        self.attempt()
    }

    fn finished(&self) -> bool {
        self.t >= self.residual.stops.goal()
    }

    fn t(&self) -> f64 {
        self.t
    }

    fn state(&self) -> &State<M> {
        &self.state
    }

    fn interpolate(&self, t: f64, out: &mut State<M>) {
        self.dense.interpolate(&self.y, self.t, t, out);
        // The correction needs velocities from the Legendre map and the constraints, with the
        // model's inputs those of the step's end: a drive that sets them along the step would
        // need the model mutably, so driven models keep the collocation polynomial, and so do
        // models whose velocities that map does not determine.
        let model = self.model.get();
        if self.options.dense_output == DenseOutput::Corrected
            && !self.residual.driven()
            && self.legendre.ready(model, &self.jac.l_vv, (self.t, &self.state.q))
            && self.start.refine(&self.dense, (&self.y, &self.f0), (self.t, self.dense.h), t, out)
        {
            self.legendre.correct(model, t, out);
        }
        if let Some(projector) = &self.projector {
            projector.borrow_mut().project(model, t, &mut out.q, &mut out.v);
            model.dl_dv(t, &out.q, &out.v, &mut out.p);
        }
    }

    /// The collocation polynomial, without the correction that [`Integrator::interpolate`]
    /// makes to it: enough to see which side of a surface the motion is on.
    fn interpolate_motion(&self, t: f64, out: &mut State<M>) {
        self.dense.interpolate(&self.y, self.t, t, out);
    }

    fn stats(&self) -> RadauStats {
        self.stats
    }
}

impl<M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>> Radau<'_, M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// Restarts at `t` from `state`, the sensitivities (if carried) set by the caller.
    fn restart_state(&mut self, t: f64, state: &State<M>) -> Result<(), SimError> {
        self.restarts.jump(
            self.model.get(),
            t,
            (self.t - self.dense.h, self.t),
            state,
            self.options.rtol.max(1e-8),
        )?;
        state.write_y(&mut self.y);
        self.state.clone_from(state);
        // The rows may have changed (a contact closed or opened): redundant now, or no longer.
        self.solver.remeasure();
        if let Some(cell) = &self.multipliers {
            cell.borrow_mut().0.remeasure();
        }
        // The state may have jumped (an impact): start again with a short step, which grows by
        // up to 8× a step, so that the steps after the event see an event function leave zero
        // (a ball leaving the floor) before one of them could span its return.
        if self.dense.h > 0.0 {
            self.h = 1e-3 * self.dense.h;
        }
        self.dense.h = 0.0;
        // A fresh Jacobian: the jump may have switched a law's mode, which changes the rows,
        // and a simplified Newton iteration on the old mode's matrix can stop early with a
        // wrong state that the error estimate does not see.
        self.begin(t, self.residual.stops.goal(), true)
    }
}

impl<M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>> Sensitive<M> for Radau<'_, M, S>
where
    DefaultAllocator: Storage<M>,
{
    fn carry_sensitivities(&mut self, wrt: &Sensitivities<M>) -> Result<(), SimError>
    where
        M: Parameters,
    {
        self.carry(wrt)
    }

    fn sensitivity_names(&self) -> &[String] {
        &self.sensitivity_names
    }

    fn sensitivity(&self, j: usize, out: &mut State<M>) -> bool {
        self.sensitivity_now(j, out)
    }

    fn interpolate_sensitivity(&self, j: usize, t: f64, out: &mut State<M>) -> bool {
        self.sensitivity_within(j, t, out)
    }

    fn sensitivity_parameter(&self, j: usize) -> Option<usize> {
        match self.forward.as_deref().filter(|forward| j < forward.len()).map(|forward| forward.wrt(j)) {
            Some(crate::simulate::sensitivity::Wrt::Parameter(k)) => Some(k),
            _ => None,
        }
    }

    fn restart_with_sensitivities(
        &mut self,
        t: f64,
        state: &State<M>,
        sensitivities: &[State<M>],
    ) -> Result<(), SimError> {
        let Some(forward) = self.forward.as_deref_mut() else {
            return self.restart_at(t, state);
        };
        if sensitivities.len() != forward.len() {
            return Err(SimError::InvalidOption {
                what: "sensitivities",
                reason: format!("{} given at the restart, {} carried", sensitivities.len(), forward.len()),
            });
        }
        for (j, s) in sensitivities.iter().enumerate() {
            forward.set_value(j, s);
        }
        self.restart_state(t, state)
    }

    fn complete_initial_sensitivity(&self, j: usize, out: &mut State<M>) {
        self.initial_multipliers(j, out);
    }
}
