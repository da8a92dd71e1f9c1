//! The forward sensitivities of a Radau integration, as its users see them: asked for with
//! [`Radau::with_sensitivities`] (or [`Sensitive::carry_sensitivities`]), read step by step,
//! or recorded in a [`Solution`](crate::output::solution::Solution) by [`Sensitive::solve_with_sensitivities`].

use nalgebra::DefaultAllocator;

use super::Radau;
use super::forward::{At, Failure, Forward, Iteration};
use crate::algebra::newton::NewtonSolver;
use crate::error::{Capability, SimError};
use crate::model::state::State;
use crate::model::{LagrangeDirac, ParameterDerivatives, Parameters};
use crate::shape::dims::{Storage, VecY};
use crate::simulate::sensitive::Sensitive;
use crate::simulate::sensitivity::{Initial, Sensitivities};

impl<'m, M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>> Radau<'m, M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// This integrator, computing the forward sensitivities of its solution with respect to
    /// `wrt`'s parameters and initial values alongside it (the staggered direct method: each
    /// step's sensitivities are solved with the step's factored iteration matrix, once its
    /// state has converged). Their initial values are made consistent at the start; read them
    /// with [`Sensitive::sensitivity`], or record them with
    /// [`Sensitive::solve_with_sensitivities`]. The same as
    /// [`Sensitive::carry_sensitivities`], as a builder.
    ///
    /// Refused with an [`InvalidOption`](SimError::InvalidOption) with projection on (the
    /// projection's derivative is not carried) or with no sensitivity asked for.
    pub fn with_sensitivities(mut self, wrt: &Sensitivities<M>) -> Result<Self, SimError>
    where
        M: Parameters,
    {
        self.carry_sensitivities(wrt)?;
        Ok(self)
    }

    /// [`Sensitive::carry_sensitivities`].
    pub(super) fn carry(&mut self, wrt: &Sensitivities<M>) -> Result<(), SimError>
    where
        M: Parameters,
    {
        let invalid =
            |reason: &str| Err(SimError::InvalidOption { what: "sensitivities", reason: reason.into() });
        if wrt.is_empty() {
            return invalid("no parameter or initial value to differentiate with respect to");
        }
        if M::NON_ASSOCIATED {
            return Err(SimError::Unsupported {
                method: "Radau's sensitivities",
                capability: Capability::ContactFriction,
            });
        }
        if self.options.projection {
            return invalid("they are not carried through the projection onto the constraints: turn it off");
        }
        let derivatives = ParameterDerivatives::of();
        self.forward =
            Some(Box::new(Forward::new(self.model.get(), derivatives, wrt.wrt(), wrt.error_control)));
        self.sensitivity_names = wrt.names().to_vec();
        Ok(())
    }

    /// [`Sensitive::sensitivity`].
    pub(super) fn sensitivity_now(&self, j: usize, out: &mut State<M>) -> bool {
        match &self.forward {
            Some(forward) if j < forward.len() => {
                out.read_y(forward.value(j));
                true
            }
            _ => false,
        }
    }

    /// [`Sensitive::interpolate_sensitivity`]: the collocation polynomial of the stages.
    pub(super) fn sensitivity_within(&self, j: usize, t: f64, out: &mut State<M>) -> bool {
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

    /// [`Sensitive::complete_initial_sensitivity`]: the multipliers' sensitivities at the
    /// start, extrapolated from the first step's stages.
    pub(super) fn initial_multipliers(&self, j: usize, out: &mut State<M>) {
        if let Some(forward) = self.forward.as_deref()
            && j < forward.len()
        {
            forward.multipliers_at_start(j, out);
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
        let weights = |s: &VecY<M>, out: &mut VecY<M>| tolerances.sensitivity_weights(s, h, out);
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
