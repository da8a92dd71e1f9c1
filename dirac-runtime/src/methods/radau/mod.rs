//! Radau IIA of order 5 with three stages for the implicit Lagrange-d'Alembert equations
//! `M ẏ = f(t, y)`, `M = diag(I, 0, I, 0)`: simplified Newton on the real and complex
//! transformed stage systems (`stages`), condensed linear algebra, Jacobian reuse across
//! steps, an error estimate scaled for the index-2 multipliers (`estimate`), predictive
//! step-size control (`controller`) and dense output (`dense`).
//!
//! The algorithm follows Hairer & Wanner's RADAU5 (*Solving Ordinary Differential Equations
//! II*, §IV.8), including its transformation of tolerances (`rtol → 0.1 rtol^(2/3)`) so that
//! the achieved error follows the requested one. A step allocates nothing: every vector and
//! matrix lives in the integrator, on the stack sizes the model fixes.

mod adjoint;
mod controller;
mod coupled;
mod dense;
mod drive;
mod estimate;
mod forward;
mod integrator;
mod options;
mod residual;
mod sensitivities;
mod stages;
pub(crate) mod tableau;

use std::cell::RefCell;

use nalgebra::{Complex, DefaultAllocator};

pub use self::adjoint::{Gradient, Objective, Recording, SampleFunction, StateFunction};
use self::controller::Controller;
use self::dense::{Dense, Legendre, Start};
use self::drive::Feedback;
use self::estimate::Estimator;
use self::forward::{Failure, Forward};
use self::options::Tolerances;
pub use self::options::{DenseOutput, ErrorNorm, RadauOptions, RadauStats};
use self::residual::Residual;
use self::stages::{Outcome, Stages, Step};
use self::tableau::{Eigen, eigen};
use crate::algebra::Algebra;
use crate::algebra::lu::Singular;
use crate::algebra::newton::NewtonSolver;
use crate::analysis::accelerations::Accelerations;
use crate::analysis::diagnose::{describe_slot, pivot_name, singular_cause};
use crate::analysis::projection::Projector;
use crate::error::SimError;
use crate::integrator::held::Held;
use crate::integrator::restart::Restarts;
use crate::model::Condensed;
use crate::model::LagrangeDirac;
use crate::model::blocks::JacobianBlocks;
use crate::model::state::State;
use crate::shape::dims::{Storage, VecC, VecQ, VecY};

/// Below this contraction rate of the last Newton iteration the Jacobian is kept.
const THET: f64 = 0.001;
/// The most Newton iterations past convergence with [`RadauOptions::exact_stages`].
const POLISH_ITERATIONS: usize = 20;
/// The most Newton iterations to convergence of a replayed step, from a fresh Jacobian.
const REPLAY_ITERATIONS: usize = 20;
/// One over the order of the error estimate the step size controls (`h⁴`), for the first
/// step's choice.
const FIRST_STEP_EXPONENT: f64 = 0.25;

/// The equations of motion at acceleration level and their accelerations and multipliers:
/// exact multipliers between steps.
type ExactMultipliers<M> = (Accelerations<M>, VecQ<M>, VecC<M>);

/// The Radau IIA integrator for a model `M`, with the Newton solver `S`.
pub struct Radau<'m, M: LagrangeDirac, S: NewtonSolver<M, M::Algebra> = Condensed<M>>
where
    DefaultAllocator: Storage<M>,
{
    model: Held<'m, M>,
    solver: S,
    options: RadauOptions,
    eig: Eigen,
    tolerances: Tolerances<M>,
    t: f64,
    t_end: f64,
    h: f64,
    /// The state reached, as the flat vector the stages work on ...
    y: VecY<M>,
    /// ... and by name.
    state: State<M>,
    /// `f(t, y)`.
    f0: VecY<M>,
    weights: VecY<M>,
    /// Evaluates the flat residual without allocating, the inputs set first when driven.
    residual: Residual<'m, M>,
    /// With a drive that feeds the state back: the residual blocks at the current inputs and
    /// at perturbed ones, and the perturbed state, for the inputs' part of the Jacobian.
    feedback: Option<Box<Feedback<'m, M>>>,
    /// Forward sensitivities, when asked for ([`Radau::with_sensitivities`]).
    forward: Option<Box<Forward<M>>>,
    /// What the sensitivities are taken with respect to, by name.
    sensitivity_names: Vec<String>,
    stages: Stages<M>,
    estimator: Estimator<M>,
    dense: Dense<M>,
    /// The last step's start, for sampling between steps.
    start: Start<M>,
    /// Velocities between steps from the Legendre map.
    legendre: Legendre<M>,
    controller: Controller,
    jac: JacobianBlocks<M, M::Algebra>,
    /// Puts accepted steps back on the constraints, when the options ask for it.
    /// Behind a cell: samples between steps are projected too, through `&self`.
    projector: Option<RefCell<Projector<M>>>,
    /// Whether `jac` was evaluated at the current state.
    jac_current: bool,
    need_jac: bool,
    need_factor: bool,
    factored_h: f64,
    /// The step size the control proposed before the last step was cut to end at the end
    /// time: where a restart picks up.
    unclipped: f64,
    /// The run's span, its own time scale: where steps end as too small near `t = 0`.
    time_scale: f64,
    /// The equations of motion at acceleration level, for the multipliers between steps where
    /// a release is located on them (a model with laws or contacts): the collocation
    /// polynomial's are of the stage order only. Behind a cell: read through `&self`.
    multipliers: Option<RefCell<ExactMultipliers<M>>>,
    stats: RadauStats,
    /// What a restart checks after the model was handed out for a change.
    restarts: Restarts<M>,
}

impl<'m, M: LagrangeDirac> Radau<'m, M>
where
    DefaultAllocator: Storage<M>,
{
    /// An integrator for `model` with the condensed Newton solver of its algebra.
    ///
    /// Built on `&model`, the integrator reads the model; built on `&mut model`, it may also
    /// change it between steps ([`Integrator::update`](crate::integrator::Integrator::update), [`Integrator::set_input`](crate::integrator::Integrator::set_input)).
    pub fn new(model: impl Into<Held<'m, M>>, options: RadauOptions) -> Result<Self, SimError> {
        options.validate()?;
        let model = model.into();
        let shape = model.shape();
        Self::build(model, options, M::Algebra::condensed(&shape), &shape)
    }
}

impl<'m, M: LagrangeDirac, S: NewtonSolver<M, M::Algebra>> Radau<'m, M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// An integrator for `model` that solves its linear systems with `solver`.
    pub fn with_solver(
        model: impl Into<Held<'m, M>>,
        options: RadauOptions,
        solver: S,
    ) -> Result<Self, SimError> {
        options.validate()?;
        let model = model.into();
        let shape = model.shape();
        Self::build(model, options, solver, &shape)
    }

    fn build(
        model: Held<'m, M>,
        options: RadauOptions,
        solver: S,
        shape: &<M::Algebra as Algebra<M>>::Shape,
    ) -> Result<Self, SimError> {
        let sizes = model.sizes();
        let projector =
            (options.projection && sizes.nc > 0).then(|| RefCell::new(Projector::new(model.get())));
        let legendre = Legendre::new(model.get());
        let restarts = Restarts::new(model.get());
        // Releases are located on exact multipliers where the dense system that gives them is
        // small; a large network keeps the collocation polynomial's (a dense solve there
        // would cost more than the run).
        let releases =
            crate::model::hybrid::has_laws(model.get()) || !model.get().unilateral_names().is_empty();
        let small = sizes.nq + sizes.nc <= crate::analysis::diagnose::SPARSE_ANALYSIS;
        let multipliers = (releases && small).then(|| {
            RefCell::new((Accelerations::new(model.get()), sizes.zeros_q::<M>(), sizes.zeros_c::<M>()))
        });
        Ok(Radau {
            model,
            solver,
            options,
            eig: eigen(),
            tolerances: Tolerances::new(&options, sizes),
            t: 0.0,
            t_end: 0.0,
            h: 0.0,
            y: sizes.zeros_y::<M>(),
            state: State::with_sizes(sizes),
            f0: sizes.zeros_y::<M>(),
            weights: sizes.zeros_y::<M>(),
            residual: Residual::new(&sizes),
            feedback: None,
            forward: None,
            sensitivity_names: Vec::new(),
            stages: Stages::new(sizes),
            estimator: Estimator::new(sizes),
            dense: Dense::new(sizes),
            start: Start::new(sizes),
            legendre,
            controller: Controller::new(),
            jac: JacobianBlocks { non_associated: M::NON_ASSOCIATED, ..JacobianBlocks::with_shape(shape) },
            projector,
            jac_current: false,
            need_jac: true,
            need_factor: true,
            factored_h: 0.0,
            unclipped: 0.0,
            time_scale: 1.0,
            multipliers,
            stats: RadauStats::default(),
            restarts,
        })
    }

    /// Sets one absolute tolerance per component of the state, replacing
    /// [`RadauOptions::atol`] (for example, a looser one for multipliers of large magnitude):
    /// `atol.lambda(Model::ROD)` is the absolute tolerance of that multiplier.
    pub fn set_absolute_tolerances(&mut self, atol: &State<M>) -> Result<(), SimError> {
        self.tolerances.set_absolute(&self.options, atol)
    }

    /// The smallest step allowed at time `t`: sixteen round-offs of `t`, or of the run's span
    /// near `t = 0` (relative to the run's own time scale, so that a run of nanoseconds steps
    /// as finely as a run of seconds).
    fn min_step(&self, t: f64) -> f64 {
        16.0 * f64::EPSILON * t.abs().max(self.time_scale)
    }

    /// One attempt after another until a step is accepted or the integration must give up.
    fn attempt(&mut self) -> Result<f64, SimError> {
        let mut singular = 0;
        let mut reason = "it would not advance t: steps this small are below the resolution of t";
        loop {
            if self.stats.steps + self.stats.rejected >= self.options.max_steps {
                return Err(SimError::TooManySteps {
                    max_steps: self.options.max_steps,
                    t: self.t,
                    t_end: self.residual.stops.goal(),
                });
            }
            if self.t + self.h >= self.t_end - 1e-12 * self.h {
                self.unclipped = self.unclipped.max(self.h);
                self.h = self.t_end - self.t;
            } else {
                self.unclipped = 0.0;
            }
            if self.h <= self.min_step(self.t) {
                return Err(SimError::StepSizeTooSmall { t: self.t, h: self.h, reason: reason.to_owned() });
            }
            self.tolerances.weights(&self.y, self.h, &mut self.weights);
            let fresh = self.need_jac;
            if self.need_jac {
                self.evaluate_jacobian()?;
            }
            // A step size within round-off of the factored one (a step cut to end at a sample
            // time) keeps the factorisation: the simplified Newton matrix is approximate anyway.
            if (self.need_factor || (self.h - self.factored_h).abs() > 1e-10 * self.h)
                && let Err(Singular { column }) = self.factor()
            {
                singular += 1;
                if singular >= 6 {
                    let s = &self.state;
                    let cause = singular_cause(self.model.get(), self.t, &s.q, &s.v);
                    let mut detail = format!("{}; {cause}", pivot_name(self.model.get(), column));
                    if self.solver.deflating() && self.projector.is_none() {
                        detail.push_str(
                            "; the model's rows are redundant, and without `RadauOptions::projection` the \
                             positions drift off the constraints to where the rows contradict each other: \
                             turn it on",
                        );
                    }
                    return Err(SimError::SingularMatrix { t: self.t, h: self.h, detail });
                }
                reason = "singular iteration matrix";
                self.reject(0.5);
                continue;
            }
            if fresh && self.solver.deflating() {
                // Redundant rows: the multipliers' part that exerts no force is no unknown of
                // the steps, and drifts as the rows turn; with rows evaluated at this state, it
                // is set back to zero (the force `Aᵀ λ`, so the residual, is unchanged).
                self.solver.least_norm(&mut self.y);
                self.state.read_y(&self.y);
            }
            match self.newton() {
                Outcome::Shrink(factor, why) => {
                    reason = why;
                    if self.h * factor <= self.min_step(self.t) {
                        return Err(self.newton_failure(why));
                    }
                    self.reject(factor);
                    if !self.jac_current {
                        self.need_jac = true;
                    }
                }
                Outcome::Converged(iterations) => {
                    self.tolerances.weights_judging((&self.y, &self.stages.z[2]), self.h, &mut self.weights);
                    let mut err = self.estimate();
                    if err < 1.0 && self.forward.is_some() {
                        match self.solve_sensitivities(iterations) {
                            Ok(err_s) => err = err.max(err_s),
                            Err(Failure::NonFinite { column, slot }) => {
                                let component = format!(
                                    "the sensitivity of {} to {}",
                                    describe_slot(self.model.get(), slot),
                                    self.sensitivity_names[column]
                                );
                                return Err(SimError::NonFinite { t: self.t, component });
                            }
                            Err(Failure::NotConverged) => {
                                reason = "the sensitivities' linear iteration did not converge";
                                if self.h * 0.5 <= self.min_step(self.t) {
                                    let (t, h) = (self.t, self.h);
                                    return Err(SimError::StepSizeTooSmall {
                                        t,
                                        h,
                                        reason: reason.to_owned(),
                                    });
                                }
                                self.reject(0.5);
                                if !self.jac_current {
                                    self.need_jac = true;
                                }
                                continue;
                            }
                        }
                    }
                    let quot = Controller::quotient(err, iterations, self.options.max_newton_iterations);
                    if err < 1.0 {
                        return self.accept(err, quot);
                    }
                    reason = "error estimate too large";
                    let factor = self.controller.reject_for_error(quot);
                    self.shrink(factor);
                }
            }
        }
    }

    /// A rejected attempt: the step shrinks by `factor` and the matrix is factored anew.
    fn reject(&mut self, factor: f64) {
        self.controller.rejected();
        self.shrink(factor);
    }

    fn shrink(&mut self, factor: f64) {
        self.h *= factor;
        self.stats.rejected += 1;
        self.need_factor = true;
    }

    fn evaluate_jacobian(&mut self) -> Result<(), SimError> {
        self.residual.apply(&mut self.model, self.t, &self.y);
        if self.feedback.is_some() {
            Feedback::clear_columns(&mut self.jac);
        }
        let s = &self.state;
        self.model.jacobian_blocks(self.t, &s.q, &s.v, &s.lambda, &mut self.jac);
        if M::NON_ASSOCIATED {
            self.model.slip_rows(self.t, &s.q, &s.v, &mut self.jac.slip);
        }
        if let Some(feedback) = &mut self.feedback {
            feedback.add_columns(&mut self.model, &mut self.residual, self.t, &self.y, &mut self.jac)?;
        }
        self.stats.jacobian_evaluations += 1;
        self.need_jac = false;
        self.jac_current = true;
        self.need_factor = true;
        Ok(())
    }

    /// The first step when the options give none: DOPRI5's `HINIT` on the motion's ODE
    /// `q̇ = v`, `v̇ = a(t, q, v)` at the start, with the tolerances the error estimate uses and
    /// the exponent of its order, so that the first step is near what the error allows (RADAU5
    /// starts at `1e-6` of the span, and climbed from there by at most 8 a step: on the pendulum
    /// at rtol 1e-4, 6 of its 22 steps). `1e-6` of the span if the start's accelerations are not
    /// determined. Allocates (the accelerations' solver): called once, by `start`.
    fn first_step(&mut self, t0: f64, state: &State<M>, span: f64) -> f64 {
        let fallback = (1e-6 * span).min(self.options.max_step);
        self.residual.apply_state(&mut self.model, t0, state);
        let model = self.model.get();
        let sizes = model.sizes();
        let mut accelerations = Accelerations::new(model);
        let (mut a0, mut lambda) = (sizes.zeros_q::<M>(), sizes.zeros_c::<M>());
        self.stats.residual_evaluations += 2;
        if !accelerations.evaluate(model, t0, (&state.q, &state.v), &mut a0, &mut lambda)
            || !a0.iter().all(|a| a.is_finite())
        {
            return fallback;
        }
        let (mut q1, mut v1, mut a1) = (sizes.zeros_q::<M>(), sizes.zeros_q::<M>(), sizes.zeros_q::<M>());
        let tolerances = &self.tolerances;
        let h = accelerations.initial_step(
            model,
            (t0, &state.q, &state.v, &a0),
            |i, y| tolerances.motion_scale(i, y),
            (FIRST_STEP_EXPONENT, self.options.max_step.min(span)),
            (&mut q1, &mut v1, &mut a1, &mut lambda),
        );
        if h.is_finite() && h > 0.0 { h } else { fallback }
    }

    /// Starts stepping from `self.y` at `t0` with the step size in `self.h`, capped by the
    /// span and the options, without step-size history or extrapolated stages. A `fresh`
    /// start evaluates and factors a new Jacobian; a restart keeps the last one as the
    /// simplified Newton iteration's matrix (marked out of date, so that a slow iteration
    /// replaces it) and refactors only if the step size changed.
    fn begin(&mut self, t0: f64, t_end: f64, fresh: bool) -> Result<(), SimError> {
        self.t = t0;
        self.t_end = self.residual.stops.stretch(t0, t_end);
        self.residual.stretch_end = self.t_end;
        let t_end = self.t_end;
        self.h = self.h.min(t_end - t0).min(self.options.max_step);
        self.unclipped = 0.0;
        self.controller.restart();
        self.stages.restart();
        self.start.forget();
        if fresh {
            self.need_jac = true;
            self.need_factor = true;
        } else {
            self.jac_current = false;
        }
        self.residual.eval(&mut self.model, t0, &self.y, &mut self.f0);
        self.stats.residual_evaluations += 1;
        if let Some(forward) = self.forward.as_deref_mut() {
            forward.begin(&mut self.model, &mut self.residual, t0, &self.y);
        }
        self.check_finite(t0)
    }

    fn factor(&mut self) -> Result<(), Singular> {
        let e = &self.eig;
        let sigma = e.gamma / self.h;
        let sigma_c = Complex::new(e.alpha, e.beta) / self.h;
        let result = self.solver.factor(&self.jac, sigma, sigma_c);
        self.stats.factorizations += 1;
        self.factored_h = self.h;
        self.need_factor = result.is_err();
        result
    }

    fn newton(&mut self) -> Outcome {
        let dense = if self.controller.first() { None } else { Some(&self.dense) };
        self.stages.initial_guess(dense, self.h);
        let Radau {
            model, residual, solver, t, h, y, weights, stats, stages, eig, tolerances, options, ..
        } = self;
        let step =
            Step { model, residual, solver, t: *t, h: *h, y, weights, error_norm: options.error_norm, stats };
        let outcome = stages.iterate(step, eig, tolerances.fnewt, options.max_newton_iterations);
        if !(options.exact_stages && matches!(outcome, Outcome::Converged(_))) {
            return outcome;
        }
        let step =
            Step { model, residual, solver, t: *t, h: *h, y, weights, error_norm: options.error_norm, stats };
        match stages.polish(step, eig, tolerances.round_off(), POLISH_ITERATIONS) {
            Ok(()) => outcome,
            Err(why) => Outcome::Shrink(0.5, why),
        }
    }

    /// Solves one step of size `h` from `y` at `t` again, its stages to round-off, into
    /// `self.stages.z`: with a Jacobian at `y`, from the last replayed step's polynomial when
    /// this one `continues` it, else from zero. Allocates nothing.
    pub(crate) fn replay(&mut self, t: f64, y: &VecY<M>, h: f64, continues: bool) -> Result<(), SimError> {
        self.t = t;
        self.h = h;
        self.y.copy_from(y);
        self.state.read_y(y);
        self.tolerances.weights(&self.y, h, &mut self.weights);
        self.evaluate_jacobian()?;
        if let Err(Singular { column }) = self.factor() {
            let detail = format!("replaying a recorded step: {}", pivot_name(self.model.get(), column));
            return Err(SimError::SingularMatrix { t, h, detail });
        }
        if !continues {
            self.stages.restart();
        }
        self.stages.initial_guess(continues.then_some(&self.dense), h);
        let Radau { model, residual, solver, y, weights, stats, stages, eig, tolerances, options, .. } = self;
        let step = Step { model, residual, solver, t, h, y, weights, error_norm: options.error_norm, stats };
        let iterations = REPLAY_ITERATIONS;
        let failed = |why: &str| {
            if why.starts_with("non-finite") {
                SimError::NonFinite { t, component: "a stage of a replayed step".into() }
            } else {
                SimError::NewtonDiverged { t, h, iterations }
            }
        };
        if let Outcome::Shrink(_, why) = stages.iterate(step, eig, tolerances.fnewt, iterations) {
            return Err(failed(why));
        }
        let step = Step { model, residual, solver, t, h, y, weights, error_norm: options.error_norm, stats };
        stages.polish(step, eig, tolerances.round_off(), POLISH_ITERATIONS).map_err(failed)?;
        self.dense.update(&self.stages.z, h);
        Ok(())
    }

    fn estimate(&mut self) -> f64 {
        let refine = self.controller.cautious();
        let Radau {
            model, residual, solver, t, h, y, weights, stats, stages, estimator, f0, options, ..
        } = self;
        let step =
            Step { model, residual, solver, t: *t, h: *h, y, weights, error_norm: options.error_norm, stats };
        estimator.error(step, &stages.z, f0, refine)
    }

    fn accept(&mut self, err: f64, quot: f64) -> Result<f64, SimError> {
        let h = self.h;
        let quot = self.controller.accepted_quotient(h, err, quot, self.stats.steps > 0);
        self.start.push(&self.y, &self.f0);
        self.legendre.forget();
        self.dense.update(&self.stages.z, h);
        if let Some(forward) = self.forward.as_deref_mut() {
            forward.accept(h);
        }
        self.y += &self.stages.z[2];
        self.state.read_y(&self.y);
        if let Some(projector) = &mut self.projector {
            let s = &mut self.state;
            projector.get_mut().project(self.model.get(), self.t + h, &mut s.q, &mut s.v);
            self.model.dl_dv(self.t + h, &s.q, &s.v, &mut s.p);
            s.write_y(&mut self.y);
        }
        self.tolerances.observe(&self.y);
        self.t += h;
        self.stats.steps += 1;
        self.residual.eval(&mut self.model, self.t, &self.y, &mut self.f0);
        self.stats.residual_evaluations += 1;
        self.check_finite(self.t)?;
        let h_new = self.controller.next_step(h, quot, self.options.max_step);
        self.jac_current = false;
        self.need_jac = self.stages.theta > THET;
        let ratio = h_new / h;
        // A new step size is factored when the next attempt finds it differs from the
        // factored one; a restart that cuts it back to a segment's length may find it equal.
        if self.need_jac || !(1.0..=1.2).contains(&ratio) {
            self.h = h_new;
        }
        Ok(h)
    }

    /// A typed error if the state or its residual `f0` holds a non-finite value.
    fn check_finite(&self, t: f64) -> Result<(), SimError> {
        if let Some(i) = self.y.iter().position(|v| !v.is_finite()) {
            return Err(SimError::NonFinite { t, component: describe_slot(self.model.get(), i) });
        }
        if let Some(i) = self.f0.iter().position(|v| !v.is_finite()) {
            let component = format!("the equation of {}", describe_slot(self.model.get(), i));
            return Err(SimError::NonFinite { t, component });
        }
        Ok(())
    }

    /// The error when Newton's iteration fails at the smallest step, for reason `why`.
    fn newton_failure(&self, why: &str) -> SimError {
        if why.starts_with("non-finite") {
            let i = self.stages.non_finite_slot().unwrap_or(0);
            let component = format!("the equation of {}", describe_slot(self.model.get(), i));
            return SimError::NonFinite { t: self.t, component };
        }
        SimError::NewtonDiverged { t: self.t, h: self.h, iterations: self.options.max_newton_iterations }
    }
}
