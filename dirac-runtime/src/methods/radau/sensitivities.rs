//! The forward sensitivities of a Radau integration, as its users see them: asked for with
//! [`Radau::with_sensitivities`], read step by step, or recorded in a [`Solution`] by
//! [`Radau::solve_with_sensitivities`].

use nalgebra::DefaultAllocator;

use super::Radau;
use super::RadauStats;
use super::forward::{At, Failure, Forward, Iteration};
use crate::algebra::newton::NewtonSolver;
use crate::error::SimError;
use crate::model::state::State;
use crate::model::{LagrangeDirac, ParameterDerivatives, Parameters};
use crate::shape::dims::{Storage, VecY};
use crate::simulate::integrator::Integrator;
use crate::simulate::recorder::Recorder;
use crate::simulate::sensitivity::{Initial, Sensitivities};
use crate::simulate::solution::{Sampling, Solution};

impl<'m, M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>> Radau<'m, M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// This integrator, computing the forward sensitivities of its solution with respect to
    /// `wrt`'s parameters and initial values alongside it (the staggered direct method: each
    /// step's sensitivities are solved with the step's factored iteration matrix, once its
    /// state has converged). Their initial values are made consistent at the start; read them
    /// with [`Radau::sensitivity`], or record them with [`Radau::solve_with_sensitivities`].
    ///
    /// Refused with an [`InvalidOption`](SimError::InvalidOption) with projection on (the
    /// projection's derivative is not carried) or with no sensitivity asked for.
    pub fn with_sensitivities(mut self, wrt: &Sensitivities<M>) -> Result<Self, SimError>
    where
        M: Parameters,
    {
        let invalid =
            |reason: &str| Err(SimError::InvalidOption { what: "sensitivities", reason: reason.into() });
        if wrt.is_empty() {
            return invalid("no parameter or initial value to differentiate with respect to");
        }
        if self.options.projection {
            return invalid("they are not carried through the projection onto the constraints: turn it off");
        }
        let derivatives = ParameterDerivatives::of();
        self.forward =
            Some(Box::new(Forward::new(self.model.get(), derivatives, wrt.wrt(), wrt.error_control)));
        self.sensitivity_names = wrt.names().to_vec();
        Ok(self)
    }

    /// The names of the sensitivities, in order: what they are taken with respect to.
    pub fn sensitivity_names(&self) -> &[String] {
        &self.sensitivity_names
    }

    /// Writes sensitivity `j` at the time reached, `∂(q, v, p, λ)/∂θ_j`, into `out`; `false`
    /// (leaving `out` alone) if there is no sensitivity `j`.
    pub fn sensitivity(&self, j: usize, out: &mut State<M>) -> bool {
        match &self.forward {
            Some(forward) if j < forward.len() => {
                out.read_y(forward.value(j));
                true
            }
            _ => false,
        }
    }

    /// Writes sensitivity `j` at time `t` within the last step into `out` (the collocation
    /// polynomial of its stages); `false` if there is no sensitivity `j`.
    pub fn interpolate_sensitivity(&self, j: usize, t: f64, out: &mut State<M>) -> bool {
        match &self.forward {
            Some(forward) if j < forward.len() => {
                if self.dense.h > 0.0 {
                    forward.interpolate(j, self.t, t, out);
                } else {
                    out.read_y(forward.value(j));
                }
                true
            }
            _ => false,
        }
    }

    /// The consistent initial sensitivities at `t0` in `state`.
    pub(super) fn start_sensitivities(&mut self, t0: f64, state: &State<M>) -> Result<(), SimError> {
        let Some(forward) = self.forward.as_deref_mut() else {
            return Ok(());
        };
        if self.feedback.is_some() {
            return Err(SimError::InvalidOption {
                what: "sensitivities",
                reason: "a drive that feeds the state back has no exact Jacobian to differentiate: use one \
                         that reads only time"
                    .into(),
            });
        }
        let mut s = State::with_sizes(self.model.sizes());
        let mut initial = Initial::new(self.model.get(), forward.derivatives, t0, state)?;
        for j in 0..forward.len() {
            initial.solve(forward.wrt(j), &mut s);
            if let Some(slot) = s.components().position(|x| !x.is_finite()) {
                let model = self.model.get();
                let component = format!(
                    "the initial sensitivity of {} to {} (a parameter derivative that is not finite at the start)",
                    crate::analysis::diagnose::describe_slot(model, slot),
                    self.sensitivity_names[j]
                );
                return Err(SimError::NonFinite { t: t0, component });
            }
            forward.set_value(j, &s);
        }
        Ok(())
    }

    /// Integrates from `state` at `t0` to `t_end` with the sensitivities asked for
    /// ([`Radau::with_sensitivities`]), recording the state as [`Integrator::solve`] does and
    /// every sensitivity at the same samples: read them from the solution by quantity and name
    /// ([`Solution::sensitivity`]). The multipliers' sensitivities at `t0`, which the method
    /// does not carry, are extrapolated from the first step's stages.
    pub fn solve_with_sensitivities(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
    ) -> Result<Solution<M, RadauStats>, SimError> {
        if self.forward.is_none() {
            return Err(SimError::InvalidOption {
                what: "sensitivities",
                reason: "none were asked for: build the integrator with `with_sensitivities`".into(),
            });
        }
        let count = self.sensitivity_names.len();
        let layout = crate::shape::layout::Layout::new(self.model.sizes());
        let len = layout.len;
        let mut recorder = Recorder::new(self.model(), sampling, t0, t_end)?;
        // Recorded sample by sample, each sample's values side by side (contiguous writes), and
        // turned into one column per value at the end.
        let series = count * len;
        let mut rows = recorder.extra_series(series)?;
        let mut buffer = State::<M>::with_sizes(self.model.sizes());
        self.start(t0, state, t_end)?;
        recorder.record_initial(self.model(), t0, self.state());
        let push = |rows: &mut Vec<f64>, s: &State<M>| rows.extend(s.components());
        if recorder.len() > 0 {
            for j in 0..count {
                self.sensitivity(j, &mut buffer);
                push(&mut rows, &buffer);
            }
        }
        let mut first = true;
        while !self.finished() {
            let before = recorder.len();
            self.step()?;
            recorder.record_step(self.model(), self.t(), self.state(), |t, out| self.interpolate(t, out));
            let forward = self.forward.as_deref().expect("sensitivities asked for");
            if first && before > 0 {
                // The sample at t0: its multipliers' sensitivities from the first step.
                for j in 0..count {
                    buffer.read_y(forward.value(j));
                    forward.multipliers_at_start(j, &mut buffer);
                    rows[j * len + layout.lambda..(j + 1) * len].copy_from_slice(buffer.lambda.as_slice());
                }
            }
            first = false;
            for k in before..recorder.len() {
                let ts = recorder.time(k);
                for j in 0..count {
                    if ts >= self.t() {
                        self.sensitivity(j, &mut buffer);
                    } else {
                        self.interpolate_sensitivity(j, ts, &mut buffer);
                    }
                    push(&mut rows, &buffer);
                }
            }
        }
        let samples = recorder.len();
        let columns = (0..series).map(|i| (0..samples).map(|k| rows[k * series + i]).collect()).collect();
        let solution = recorder.finish(self.stats())?;
        Ok(solution.with_sensitivities(self.sensitivity_names.clone(), columns))
    }
}

impl<M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>> Radau<'_, M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// Solves the sensitivities' stage systems of the step, converged in `state_iterations`
    /// Newton iterations; their largest error
    /// estimate (zero unless error-controlled), or why they could not be solved.
    pub(super) fn solve_sensitivities(&mut self, state_iterations: usize) -> Result<f64, Failure> {
        let Radau {
            model,
            residual,
            solver,
            t,
            h,
            y,
            stages,
            eig,
            tolerances,
            options,
            forward,
            stats,
            jac,
            factored_h,
            ..
        } = self;
        let Some(forward) = forward.as_deref_mut() else {
            return Ok(0.0);
        };
        let at = At { t: *t, h: *h, y, z: &stages.z };
        forward.stages(model, residual, &at);
        let exact = *factored_h == *h && forward.stage_jacobians_equal(jac);
        stats.jacobian_evaluations += 3;
        let h = *h;
        let weights = |s: &VecY<M>, out: &mut VecY<M>| tolerances.weights(s, h, out);
        let (before, coupled_before) = (forward.iterations, forward.coupled_steps);
        let iteration = Iteration {
            fnewt: tolerances.fnewt,
            max_iterations: 4 * options.max_newton_iterations,
            norm: options.error_norm,
            theta: stages.theta,
            exact,
            state_iterations,
        };
        let result = forward.solve(solver, eig, h, &iteration, &weights);
        stats.sensitivity_iterations += forward.iterations - before;
        stats.coupled_sensitivity_steps += forward.coupled_steps - coupled_before;
        result
    }
}
