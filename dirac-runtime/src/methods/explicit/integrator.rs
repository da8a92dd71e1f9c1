//! Explicit as an [`Integrator`]: start, change and restart, step, and the state between
//! steps.

use nalgebra::DefaultAllocator;

use super::tableau::weights_at;
use super::{ERROR_OLD_START, Explicit, ExplicitStats};
use crate::error::SimError;
use crate::integrator::{Drive, Integrator};
use crate::model::state::State;
use crate::model::{LagrangeDirac, configuration};
use crate::shape::dims::Storage;

impl<M: LagrangeDirac> Integrator<M> for Explicit<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    type Stats = ExplicitStats;

    const NAME: &'static str = "Explicit";

    fn model(&self) -> &M {
        self.model.get()
    }

    fn start(&mut self, t0: f64, state: &State<M>, t_end: f64) -> Result<(), SimError> {
        // A drive sets the inputs at the start before the state is checked against them.
        let stretch = self.driver.stops.stretch(t0, t_end);
        self.driver.apply_state(&mut self.model, (t0, stretch), state);
        self.restarts.start(self.model.get(), (t0, t_end), state, self.options.rtol.max(1e-8))?;
        self.state.clone_from(state);
        self.previous.clone_from(state);
        (self.t, self.t_previous, self.h_last) = (t0, t0, 0.0);
        self.t_end = self.driver.stops.stretch(t0, t_end);
        // A tenth of the span: near t = 0, the resolution the run's own times have.
        self.time_scale = 0.1 * (t_end - t0);
        self.peaks = [0.0; 2];
        self.stats = ExplicitStats::default();
        self.accelerations.factorizations = 0;
        self.forget();
        self.find_free_velocities(t0)?;
        // The interpolation's own system, factored once here: a sparse factorisation finds
        // its pivots (and allocates) the first time only.
        let (probe, acceleration) = self.probe.get_mut();
        if !probe.is_dense() {
            let s = &self.state;
            probe.evaluate(self.model.get(), t0, (&s.q, &s.v), acceleration, &mut self.lambda_stage);
        }
        (self.error_old, self.rejected_last) = (ERROR_OLD_START, false);
        (self.stiff_steps, self.nonstiff_steps) = (0, 0);
        self.h = self.initial_step();
        Ok(())
    }

    fn model_mut(&mut self) -> Option<&mut M> {
        self.restarts.model_mut(&mut self.model, self.t, &self.state)
    }

    fn restart_until(&mut self, t_end: f64) -> Result<(), SimError> {
        if self.t >= t_end {
            return Ok(());
        }
        self.restarts.resume(
            self.model.get(),
            self.t,
            &self.state,
            (self.options.rtol.max(1e-8), |_, _| 0.0),
        )?;
        self.resume(t_end)
    }

    fn set_inputs_at(&mut self, t: f64, state: &State<M>) {
        self.driver.apply_state(&mut self.model, (t, self.t_end), state);
    }

    fn driven(&self) -> bool {
        self.driver.driven()
    }

    fn restart_at(&mut self, t: f64, state: &State<M>) -> Result<(), SimError> {
        self.restarts.jump(
            self.model.get(),
            t,
            (self.t_previous, self.t),
            state,
            self.options.rtol.max(1e-8),
        )?;
        self.state.clone_from(state);
        self.previous.clone_from(state);
        // The state may have jumped (an impact): start again with a short step, which grows by
        // up to ten times a step, so that the steps after the event see an event function
        // leave zero (a ball leaving the floor) before one of them could span its return, as
        // Radau does. A step that spanned the ball's whole flight saw its height negative at
        // both ends and let it fall through the floor.
        if self.h_last > 0.0 && self.options.fixed_step.is_none() {
            self.h = 1e-3 * self.h_last;
        }
        (self.t, self.t_previous, self.h_last) = (t, t, 0.0);
        self.forget();
        if self.restarts.rows_switch {
            self.find_free_velocities(t)?;
        } else {
            self.evaluate_start()?;
        }
        (self.error_old, self.rejected_last) = (ERROR_OLD_START, false);
        (self.stiff_steps, self.nonstiff_steps) = (0, 0);
        Ok(())
    }

    fn end(&self) -> f64 {
        self.driver.stops.goal()
    }

    fn next_step_end(&self) -> f64 {
        (self.t + self.h).min(self.driver.stops.goal())
    }

    fn end_step_at(&mut self, t: Option<f64>) -> bool {
        if self.options.fixed_step.is_some() {
            return false;
        }
        self.driver.stops.set_timed(t);
        self.t_end = self.driver.stops.stretch(self.t, self.driver.stops.goal());
        true
    }

    fn step(&mut self) -> Result<f64, SimError> {
        if self.driver.stops.due(self.t, self.t_end) {
            // A stop: the inputs jump or bend here; the first stage is evaluated afresh. An
            // input that prescribes a velocity (a voltage source's) makes it jump: the
            // velocities are put back on the constraints by the least change the inertia
            // allows, a constraint impulse, and the start evaluated there.
            self.resume(self.driver.stops.goal())?;
            let (t, s) = (self.t, &mut self.state);
            if self.accelerations.project(self.model.get(), t, &mut s.q, &mut s.v).moved {
                self.evaluate_start()?;
            }
        }
        let h = self.attempt()?;
        self.observe_peaks();
        self.t_previous = self.t;
        self.h_last = h;
        self.previous.clone_from(&self.state);
        self.t = if self.t_end - self.t == h { self.t_end } else { self.t + h };
        self.stats.steps += 1;
        let s = &mut self.state;
        s.q.copy_from(&self.q_new);
        s.v.copy_from(&self.v_new);
        // The seventh stage was evaluated at the new solution: its factorisation projects it,
        // and its accelerations and multipliers are the next step's first stage (first same as
        // last). The projection moves the solution by about the local error, O(h⁶), so the
        // first stage is then taken that far from the state: a perturbation of O(h⁷) in the
        // next step, below its local error, which keeps the order.
        let projection = self.accelerations.project(self.model.get(), self.t, &mut s.q, &mut s.v);
        if !projection.reached {
            return Err(SimError::Unstable {
                t: self.t,
                h,
                detail: "the step left the constraints too far for the projection to bring the state \
                         back to them: take a smaller step (a fixed step), or adaptive steps"
                    .to_owned(),
            });
        }
        let moved = projection.moved;
        self.start_acceleration.copy_from(&self.kv[6]);
        s.lambda.copy_from(&self.lambda_stage);
        if moved {
            self.model.get().dl_dv(self.t, &s.q, &s.v, &mut s.p);
        } else {
            s.p.copy_from(self.accelerations.momenta());
        }
        self.check_finite()?;
        Ok(h)
    }

    fn finished(&self) -> bool {
        self.t >= self.driver.stops.goal()
    }

    fn t(&self) -> f64 {
        self.t
    }

    fn state(&self) -> &State<M> {
        &self.state
    }

    /// The state within the last step: positions and velocities from the method's continuous
    /// extension (order 4), put back on the constraints as the steps are; momenta from the
    /// Legendre map and multipliers from the accelerations' system there.
    fn interpolate(&self, t: f64, out: &mut State<M>) {
        if self.h_last == 0.0 {
            out.clone_from(&self.state);
            return;
        }
        let theta = self.motion_at(t, out);
        let model = self.model.get();
        let mut probe = self.probe.borrow_mut();
        let (accelerations, acceleration) = &mut *probe;
        // With a drive, the inputs at `t` are not set here (the model is only read): the
        // multipliers are interpolated between the step's ends, as where the motion is not
        // determined, and the momenta follow from the velocities.
        let mut determined = !self.driver.driven()
            && accelerations.settle(model, t, &out.q, &mut out.v)
            && accelerations.evaluate(model, t, (&out.q, &out.v), acceleration, &mut out.lambda);
        if determined && self.sizes.nc > 0 {
            accelerations.project(model, t, &mut out.q, &mut out.v);
            determined = accelerations.evaluate(model, t, (&out.q, &out.v), acceleration, &mut out.lambda);
        }
        if determined {
            out.p.copy_from(accelerations.momenta());
        } else {
            out.lambda.copy_from(&self.previous.lambda);
            out.lambda.axpy(theta, &self.state.lambda, 1.0 - theta);
            model.dl_dv(t, &out.q, &out.v, &mut out.p);
        }
    }

    /// The positions and velocities of the dense output, without the accelerations that the
    /// momenta and multipliers take (unless velocities that only forces fix must be settled).
    fn interpolate_motion(&self, t: f64, out: &mut State<M>) {
        if self.h_last == 0.0 || self.probe.borrow().0.has_free() {
            self.interpolate(t, out);
        } else {
            self.motion_at(t, out);
        }
    }

    fn stats(&self) -> ExplicitStats {
        self.stats
    }
}

impl<M: LagrangeDirac> Explicit<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    /// Starts again from the state reached towards `goal`, its accelerations evaluated afresh
    /// and the step-size history dropped: after a change of the model, or at a stop.
    fn resume(&mut self, goal: f64) -> Result<(), SimError> {
        self.t_end = self.driver.stops.stretch(self.t, goal);
        self.forget();
        self.evaluate_start()?;
        (self.error_old, self.rejected_last) = (ERROR_OLD_START, false);
        (self.stiff_steps, self.nonstiff_steps) = (0, 0);
        Ok(())
    }

    /// The dense output's positions and velocities at `t` within the last step, into `out`;
    /// returns `t`'s fraction of the step.
    fn motion_at(&self, t: f64, out: &mut State<M>) -> f64 {
        let theta = ((t - self.t_previous) / self.h_last).clamp(0.0, 1.0);
        let weights = weights_at(theta);
        let h = self.h_last;
        // The positions' tangent `Σ w_k k_k` is built in `out.q`, then the positions move
        // along it from the step's start.
        for i in 0..self.sizes.nq {
            let (mut dq, mut dv) = (0.0, 0.0);
            for (k, w) in weights.iter().enumerate() {
                dq += w * self.kq[k][i];
                dv += w * self.kv[k][i];
            }
            out.q[i] = dq;
            out.v[i] = self.previous.v[i] + h * dv;
        }
        configuration::advance_onto::<M>(&self.previous.q, h, &mut out.q);
        theta
    }
}

/// Inputs set before every stage's evaluation; between steps, the multipliers of the dense
/// output are interpolated (the model is not evaluated there).
impl<'m, M: LagrangeDirac> Drive<'m, M> for Explicit<'m, M>
where
    DefaultAllocator: Storage<M>,
{
    fn drive(&mut self, drive: &'m mut dyn FnMut(f64, &State<M>, &mut M)) -> Result<(), SimError> {
        self.driver.set(&mut self.model, drive, self.t)
    }

    fn stop_at(&mut self, times: &[f64]) -> Result<(), SimError> {
        self.driver.stops.set(times)
    }
}
