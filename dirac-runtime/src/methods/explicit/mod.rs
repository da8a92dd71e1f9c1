//! An explicit integrator for non-stiff models: Tsitouras' 5(4) Runge-Kutta pair with PI
//! step-size control and dense output (as Hairer, Nørsett & Wanner's DOPRI5 drives the
//! Dormand-Prince pair), applied to the positions and velocities, with the multipliers from
//! one saddle-point solve per stage and every accepted step projected back onto the
//! constraints.
//!
//! Each stage is explicit in the differential part, `q̇ = v`, and takes the accelerations and
//! the multipliers from the equations of motion with the constraints differentiated once
//! more (`accelerations`):
//!
//! ```text
//! [ L_vv  −Aᵀ ] [ v̇ ]   [ ∂L/∂q + F − L_vt − L_vq v ]
//! [ A      0  ] [ λ ] = [ −∂(A v + b)/∂q v − ∂(A v + b)/∂t ]
//! ```
//!
//! the same saddle-point structure as Radau's condensed Newton systems, without a Newton
//! iteration, a Jacobian or a complex factorisation. The stages satisfy the constraints at
//! acceleration level only, so after every accepted step the positions are put back onto
//! `φ(q, t) = 0` and the velocities onto `A(q, t) v + b(q, t) = 0` by the smallest
//! corrections (a projection method, Hairer, Lubich & Wanner, *Geometric Numerical
//! Integration*, §IV.4; Hairer & Wanner, *Solving ODEs II*, §VII.2): the constraint residuals
//! stay at round-off instead of drifting, and the order of the method is kept. The momenta
//! follow from the Legendre map and the multipliers from the system above at the projected
//! state.
//!
//! The system is regular when `L_vv` is positive definite on the constraint distribution. A
//! degenerate Lagrangian whose massless coordinates are held by constraints (the paper's torn
//! chain, `p̄2 = 0`) is therefore integrated as it is: its algebraic velocities are eliminated
//! by the solve. A model whose motion the system does not determine is refused at the start
//! with [`SimError::NotDetermined`], naming the free unknown.
//!
//! The method is explicit: on a stiff model (a stiff spring, a fast electrical mode) its step
//! is held to the stability limit by the error control. Hairer's stiffness test notices (the
//! last two stages estimate `h |λ|`) and the integration stops with [`SimError::Unstable`]
//! saying the model is stiff, where it would otherwise crawl on to
//! [`SimError::TooManySteps`]. Use [`Radau`](crate::methods::radau::Radau) there; the facade's guide has a
//! table of which integrator suits which model. A step allocates nothing.

mod integrator;
mod options;
mod tableau;

use std::cell::RefCell;

use nalgebra::DefaultAllocator;

pub use self::options::{ExplicitOptions, ExplicitStats};
use self::tableau::{A, C, E};
use crate::analysis::accelerations::Accelerations;
use crate::analysis::diagnose::singular_cause;
use crate::error::SimError;
use crate::integrator::drive::Driver;
use crate::integrator::held::Held;
use crate::integrator::restart::Restarts;
use crate::integrator::rough_power;
use crate::model::LagrangeDirac;
use crate::model::configuration;
use crate::model::state::State;
use crate::shape::dims::{Sizes, Storage, VecC, VecQ};

/// The step-size controller's constants, as in DOPRI5: the safety factor and the bounds on
/// the ratio of new to old step. Its PI control takes the new step as
/// `h · SAFETY / (error^0.17 / error_old^β)` with `β = 0.04` (and `0.17 = 1/5 − 0.75 β`).
const SAFETY: f64 = 0.9;
const MAX_GROWTH: f64 = 10.0;
const MAX_SHRINK: f64 = 0.2;
/// Where the stiffness test counts a step as held by stability: `h |λ|` near the boundary of
/// the method's stability region on the negative real axis (about −3.5 for Tsitouras' pair;
/// Hairer's DOPRI5 takes 3.25 for a boundary of −3.3).
const STIFF_H_LAMBDA: f64 = 3.25;
/// The PI controller's memory at a start, `(10⁻⁴)^β`, as DOPRI5 has it.
const ERROR_OLD_START: f64 = 0.691_830_970_918_936_5;

/// Why the last attempt was rejected, for the error when steps become too small.
#[derive(Clone, Copy)]
enum Rejection {
    /// None yet: the first attempt's step was already too small for `t` to move.
    Resolution,
    Error,
    NonFinite,
    Singular,
}

impl Rejection {
    fn reason(self) -> &'static str {
        match self {
            Rejection::Resolution => "it would not advance t: steps this small are below the resolution of t",
            Rejection::Error => "the local error stayed above the tolerance",
            Rejection::NonFinite => "the stages held values that are not finite",
            Rejection::Singular => "the accelerations were not determined at a stage",
        }
    }
}

/// The explicit integrator for a model `M`: see the [module](self) documentation.
pub struct Explicit<'m, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    model: Held<'m, M>,
    options: ExplicitOptions,
    sizes: Sizes,
    accelerations: Accelerations<M>,
    t: f64,
    t_end: f64,
    /// The run's span, its own time scale: where steps end as too small near `t = 0`.
    time_scale: f64,
    /// The largest magnitude of the positions and of the velocities reached in the run (above
    /// `rtol · atol`): the caps of their absolute tolerance, as Radau's (see its options).
    peaks: [f64; 2],
    /// The start of the last step, and its size (zero before the first step and after a
    /// restart: no step to interpolate in).
    t_previous: f64,
    h_last: f64,
    /// The size of the next step.
    h: f64,
    /// The state reached ...
    state: State<M>,
    /// ... and at the start of the last step.
    previous: State<M>,
    /// The accelerations at the state reached: the first stage of the next step.
    start_acceleration: VecQ<M>,
    /// The stages' velocities and accelerations, `k_i = (V_i, v̇_i)`, of the last attempt.
    kq: [VecQ<M>; 7],
    kv: [VecQ<M>; 7],
    /// A stage's positions and multipliers.
    q_stage: VecQ<M>,
    lambda_stage: VecC<M>,
    /// The fifth-order solution at the end of the last step, before the projection.
    q_new: VecQ<M>,
    v_new: VecQ<M>,
    /// The PI controller's memory: the last accepted error to the power `β`, and whether the
    /// last attempt was rejected.
    error_old: f64,
    rejected_last: bool,
    /// The stiffness test's counts of accepted steps in a row at and below the stability limit.
    stiff_steps: usize,
    nonstiff_steps: usize,
    /// The multipliers and accelerations of interpolated states, apart from the integration's.
    probe: RefCell<(Accelerations<M>, VecQ<M>)>,
    stats: ExplicitStats,
    /// What a restart checks after the model was handed out for a change.
    restarts: Restarts<M>,
    /// The drive of the inputs within the steps, and the stops where they jump or bend.
    driver: Driver<'m, M>,
}

impl<'m, M: LagrangeDirac> Explicit<'m, M>
where
    DefaultAllocator: Storage<M>,
{
    /// An integrator for `model`.
    ///
    /// Built on `&model`, the integrator reads the model; built on `&mut model`, it may also
    /// change it between steps ([`Integrator::update`](crate::integrator::Integrator::update), [`Integrator::set_input`](crate::integrator::Integrator::set_input)).
    pub fn new(model: impl Into<Held<'m, M>>, options: ExplicitOptions) -> Result<Self, SimError> {
        options.validate()?;
        let model = model.into();
        let sizes = model.sizes();
        let zeros = || sizes.zeros_q::<M>();
        let restarts = Restarts::new(model.get());
        Ok(Explicit {
            accelerations: Accelerations::new(model.get()),
            probe: RefCell::new((Accelerations::new(model.get()), zeros())),
            model,
            options,
            sizes,
            t: 0.0,
            t_end: 0.0,
            time_scale: 1.0,
            peaks: [0.0; 2],
            t_previous: 0.0,
            h_last: 0.0,
            h: 0.0,
            state: State::with_sizes(sizes),
            previous: State::with_sizes(sizes),
            start_acceleration: zeros(),
            kq: std::array::from_fn(|_| zeros()),
            kv: std::array::from_fn(|_| zeros()),
            q_stage: zeros(),
            lambda_stage: sizes.zeros_c::<M>(),
            q_new: zeros(),
            v_new: zeros(),
            error_old: ERROR_OLD_START,
            rejected_last: false,
            stiff_steps: 0,
            nonstiff_steps: 0,
            stats: ExplicitStats::default(),
            restarts,
            driver: Driver::default(),
        })
    }

    /// Forgets the factorisations and the mass matrix: the model may have changed.
    fn forget(&mut self) {
        self.accelerations.forget();
        self.probe.get_mut().0.forget();
    }

    /// The smallest step allowed at time `t`: sixteen round-offs of `t`, or of the run's span
    /// near `t = 0` (relative to the run's own time scale, so that a run of nanoseconds steps
    /// as finely as a run of seconds).
    fn min_step(&self, t: f64) -> f64 {
        16.0 * f64::EPSILON * t.abs().max(self.time_scale)
    }

    /// Evaluates the start (or restart) at `t` with the velocities that only the forces fix
    /// looked for afresh where its system is singular ([`Self::evaluate_start`]): which
    /// coordinates lack inertia and constraints can change at a restart (a law's row that
    /// switched, a diode that blocks).
    fn find_free_velocities(&mut self, t: f64) -> Result<(), SimError> {
        self.accelerations.unprepare();
        self.probe.get_mut().0.unprepare();
        self.evaluate_start()?;
        if self.accelerations.has_free() {
            let s = &self.state;
            self.probe.get_mut().0.prepare(self.model.get(), t, (&s.q, &s.v))?;
        }
        Ok(())
    }

    /// Evaluates the accelerations, multipliers and momenta at the state reached (a start, a
    /// restart, an accepted step that was projected), with the cause named if the motion is
    /// not determined there.
    fn evaluate_start(&mut self) -> Result<(), SimError> {
        let s = &mut self.state;
        if self.driver.driven() {
            self.driver.apply(&mut self.model, (self.t, self.t_end), &s.q, &s.v);
            let rate = &mut self.accelerations.input_rate;
            self.driver.input_rate(&mut self.model, (self.t, self.t_end), (&s.q, &s.v), rate);
        }
        let model = self.model.get();
        self.stats.evaluations += 1;
        let mut determined = false;
        for attempt in 0..2 {
            determined = self.accelerations.settle(model, self.t, &s.q, &mut s.v)
                && self.accelerations.evaluate(
                    model,
                    self.t,
                    (&s.q, &s.v),
                    &mut self.start_acceleration,
                    &mut s.lambda,
                );
            if determined || attempt == 1 || self.accelerations.has_free() {
                break;
            }
            // Singular: velocities that only the forces fix, if that is why (set-up: allocates).
            self.accelerations.prepare(model, self.t, (&s.q, &s.v))?;
            if !self.accelerations.has_free() {
                break;
            }
        }
        self.stats.factorizations = self.accelerations.factorizations;
        if !determined {
            return Err(SimError::NotDetermined {
                t: self.t,
                cause: singular_cause(model, self.t, &s.q, &s.v),
            });
        }
        s.p.copy_from(self.accelerations.momenta());
        self.check_finite()
    }

    /// A typed error naming the first component of the state reached that is not finite.
    fn check_finite(&self) -> Result<(), SimError> {
        let s = &self.state;
        // x · 0 is zero for every finite x and NaN otherwise: one pass without branches tells
        // whether all are finite, and only then is the culprit searched for.
        let zeros = |x: &[f64]| x.iter().fold(0.0, |sum, x| sum + x * 0.0);
        let all = [s.q.as_slice(), s.v.as_slice(), s.p.as_slice(), s.lambda.as_slice()];
        if all.iter().map(|x| zeros(x)).sum::<f64>() + zeros(self.start_acceleration.as_slice()) == 0.0 {
            return Ok(());
        }
        let n = self.sizes.nq;
        if let Some(i) = (0..n).find(|&i| !(s.q[i].is_finite() && s.v[i].is_finite() && s.p[i].is_finite())) {
            let names = self.model.get().coordinate_names();
            return Err(SimError::NonFinite { t: self.t, component: names[i].clone() });
        }
        if let Some(j) = s.lambda.iter().position(|x| !x.is_finite()) {
            let names = self.model.get().constraint_names();
            return Err(SimError::NonFinite { t: self.t, component: format!("multiplier `{}`", names[j]) });
        }
        if let Some(i) = self.start_acceleration.iter().position(|x| !x.is_finite()) {
            let names = self.model.get().velocity_names();
            return Err(SimError::NonFinite {
                t: self.t,
                component: format!("the acceleration of {}", names[i]),
            });
        }
        Ok(())
    }

    /// The first step size, from the size of the state and its derivatives, as DOPRI5's
    /// `HINIT` chooses it: an explicit Euler step's error of about 1% of the tolerance.
    fn initial_step(&mut self) -> f64 {
        let span = self.t_end - self.t;
        let max = self.options.max_step.min(span);
        if let Some(h) = self.options.initial_step {
            return h.min(max);
        }
        let (rtol, atol) = (self.options.rtol, self.options.atol);
        self.stats.evaluations += 1;
        let s = &self.state;
        self.accelerations.initial_step(
            self.model.get(),
            (self.t, &s.q, &s.v, &self.start_acceleration),
            |_, y| atol + rtol * y.abs(),
            (0.2, max),
            (&mut self.q_stage, &mut self.kq[1], &mut self.kv[1], &mut self.lambda_stage),
        )
    }

    /// The stages of a step of size `h` from the state reached, the fifth-order solution in
    /// `q_new`, `v_new`, and the scaled local error (`None` with the reason where a stage is
    /// not determined). `DRIVEN`: whether a drive sets the inputs at each stage (a constant, so
    /// that the undriven loop keeps what it loads from `self` in registers across stages).
    fn stages<const DRIVEN: bool>(&mut self, h: f64) -> Result<f64, Rejection> {
        let n = self.sizes.nq;
        let s = &self.state;
        self.kq[0].copy_from(&s.v);
        self.kv[0].copy_from(&self.start_acceleration);
        for i in 1..7 {
            // The stage's positions move along the stages' velocities; its velocities are
            // built in `v_new`, which after the seventh stage holds the new solution's.
            let (k, stage) = ((&self.kq[..i], &self.kv[..i]), (&mut self.q_stage, &mut self.v_new));
            configuration::advance_by::<M>((&s.q, &s.v), h, &A[i][..i], k, stage);
            self.stats.evaluations += 1;
            // At a stretch's end the model is read from the left, as its inputs are.
            let t = self.driver.stops.read_at(self.t + C[i] * h, self.t_end);
            if DRIVEN {
                self.driver.apply(&mut self.model, (t, self.t_end), &self.q_stage, &self.v_new);
                let (stage, rate) = ((&self.q_stage, &self.v_new), &mut self.accelerations.input_rate);
                self.driver.input_rate(&mut self.model, (t, self.t_end), stage, rate);
            }
            let model = self.model.get();
            if !self.accelerations.settle(model, t, &self.q_stage, &mut self.v_new) {
                return Err(Rejection::Singular);
            }
            let stage = (&self.q_stage, &self.v_new);
            if !self.accelerations.evaluate(model, t, stage, &mut self.kv[i], &mut self.lambda_stage) {
                return Err(Rejection::Singular);
            }
            self.kq[i].copy_from(&self.v_new);
        }
        self.q_new.copy_from(&self.q_stage);
        let (rtol, atol) = (self.options.rtol, self.options.atol);
        // The absolute tolerance never exceeds the relative one times the largest magnitude the
        // positions (velocities) reach, this step's end included: invariant under units.
        let [aq, av] =
            self.candidate_peaks().map(|peak| if peak > 0.0 { atol.min(rtol * peak) } else { atol });
        let mut sum = 0.0;
        for i in 0..n {
            let (mut eq, mut ev) = (0.0, 0.0);
            for (j, &e) in E.iter().enumerate() {
                eq += e * self.kq[j][i];
                ev += e * self.kv[j][i];
            }
            let wq = aq + rtol * s.q[i].abs().max(self.q_new[i].abs());
            let wv = av + rtol * s.v[i].abs().max(self.v_new[i].abs());
            sum += (h * eq / wq).powi(2) + (h * ev / wv).powi(2);
        }
        let error = (sum / (2 * n).max(1) as f64).sqrt();
        if error.is_finite() { Ok(error) } else { Err(Rejection::NonFinite) }
    }

    /// The peaks of the positions and velocities with those of the state reached and of the
    /// candidate end `q_new`, `v_new` (magnitudes below `rtol · atol` left out: round-off of a
    /// quantity at rest sets no scale).
    fn candidate_peaks(&self) -> [f64; 2] {
        let negligible = self.options.rtol * self.options.atol;
        // The size as a constant where the model fixes it, and one indexed pass: an iterator
        // over both vectors cost the chain 4% more instructions a solve.
        let n = <M::Nq as nalgebra::Dim>::try_to_usize().unwrap_or(self.sizes.nq);
        let (q, q_new) = (&self.state.q.as_slice()[..n], &self.q_new.as_slice()[..n]);
        let (v, v_new) = (&self.state.v.as_slice()[..n], &self.v_new.as_slice()[..n]);
        let [mut peak_q, mut peak_v] = self.peaks;
        for i in 0..n {
            let (a, b) = (q[i].abs().max(q_new[i].abs()), v[i].abs().max(v_new[i].abs()));
            if a > negligible && a > peak_q {
                peak_q = a;
            }
            if b > negligible && b > peak_v {
                peak_v = b;
            }
        }
        [peak_q, peak_v]
    }

    /// Takes in the state reached after an accepted step.
    pub(crate) fn observe_peaks(&mut self) {
        self.peaks = self.candidate_peaks();
    }

    /// Hairer's stiffness test (DOPRI5): the sixth and seventh stages both sit at the step's
    /// end, so `h ‖k₇ − k₆‖ / ‖y₇ − y₆‖` estimates `h |λ|` for the dominant eigenvalue along
    /// their difference. Held above the stability boundary's neighbourhood on fifteen accepted
    /// steps in a row (six below it reset the count), the step is limited by stability, not by
    /// accuracy: the model is stiff, and an implicit method would take far larger steps.
    fn test_stiffness(&mut self, h: f64) -> Result<(), SimError> {
        let (mut numerator, mut denominator) = (0.0, 0.0);
        for i in 0..self.sizes.nq {
            let (mut dq, mut dv) = (0.0, 0.0);
            // y₇ − y₆ = h Σ_j (b_j − a_6j) k_j; row 6 of the table ends in a zero.
            for (j, (b, a)) in A[6].iter().zip(&A[5]).enumerate() {
                let w = b - a;
                dq += w * self.kq[j][i];
                dv += w * self.kv[j][i];
            }
            denominator += (h * dq).powi(2) + (h * dv).powi(2);
            numerator += (self.kq[6][i] - self.kq[5][i]).powi(2) + (self.kv[6][i] - self.kv[5][i]).powi(2);
        }
        if denominator <= 0.0 {
            return Ok(());
        }
        let h_lambda = h * (numerator / denominator).sqrt();
        if h_lambda > STIFF_H_LAMBDA {
            self.stiff_steps += 1;
            self.nonstiff_steps = 0;
        } else {
            self.nonstiff_steps += 1;
            if self.nonstiff_steps == 6 {
                self.stiff_steps = 0;
            }
        }
        if self.stiff_steps < 15 {
            return Ok(());
        }
        Err(SimError::Unstable {
            t: self.t + h,
            h,
            detail: format!(
                "the model is stiff here: 15 steps in a row were held at the explicit method's stability \
                 limit (h·|λ| ≈ {h_lambda:.1}), so it would crawl; integrate it with Radau (or set \
                 ExplicitOptions::stiffness_test to false to go on)"
            ),
        })
    }

    /// Attempts until a step is accepted; returns its size.
    fn attempt(&mut self) -> Result<f64, SimError> {
        let mut reason = Rejection::Resolution;
        loop {
            if self.stats.steps + self.stats.rejected >= self.options.max_steps {
                return Err(SimError::TooManySteps {
                    max_steps: self.options.max_steps,
                    t: self.t,
                    t_end: self.driver.stops.goal(),
                });
            }
            let fixed = self.options.fixed_step;
            let mut h = fixed.unwrap_or(self.h).min(self.options.max_step);
            // The last step ends at the end time, taken whole if within 1% of it.
            if self.t + 1.01 * h >= self.t_end || fixed.is_some() && self.t + 1.000_001 * h >= self.t_end {
                h = self.t_end - self.t;
            }
            if h < self.min_step(self.t) {
                return Err(SimError::StepSizeTooSmall { t: self.t, h, reason: reason.reason().to_owned() });
            }
            let outcome = if self.driver.driven() { self.stages::<true>(h) } else { self.stages::<false>(h) };
            self.stats.factorizations = self.accelerations.factorizations;
            match (outcome, fixed) {
                (Ok(error), None) => {
                    // error^0.17 and error^β = error^0.04 from one power, error^0.01.
                    let u = rough_power(error, 0.01);
                    let u4 = (u * u) * (u * u);
                    let grow = (u4 * u4) * (u4 * u4) * u;
                    if error <= 1.0 {
                        let ratio =
                            (grow / self.error_old / SAFETY).clamp(1.0 / MAX_GROWTH, 1.0 / MAX_SHRINK);
                        let mut next = h / ratio;
                        if self.rejected_last {
                            next = next.min(h);
                        }
                        self.error_old = if error >= 1e-4 { u4 } else { ERROR_OLD_START };
                        self.rejected_last = false;
                        self.h = next.min(self.options.max_step);
                        // Every tenth step, and every step once one looked stiff, as DOPRI5
                        // tests (there every thousandth): a test costs a tenth of a small
                        // model's step.
                        let due = self.stats.steps.is_multiple_of(10) || self.stiff_steps > 0;
                        if self.options.stiffness_test && due {
                            self.test_stiffness(h)?;
                        }
                        return Ok(h);
                    }
                    reason = Rejection::Error;
                    self.h = h / (grow / SAFETY).min(1.0 / MAX_SHRINK);
                }
                (Ok(_), Some(_)) => return Ok(h),
                (Err(why), None) => {
                    reason = why;
                    self.h = 0.1 * h;
                }
                (Err(why), Some(_)) => {
                    return Err(match why {
                        Rejection::Singular => {
                            let model = self.model.get();
                            SimError::NotDetermined {
                                t: self.t,
                                cause: singular_cause(model, self.t, &self.state.q, &self.state.v),
                            }
                        }
                        _ => SimError::Unstable {
                            t: self.t,
                            h,
                            detail: format!(
                                "{}: the fixed step is beyond the stability limit of the method for this \
                                 model; take a smaller step or adaptive steps",
                                why.reason()
                            ),
                        },
                    });
                }
            }
            self.stats.rejected += 1;
            self.rejected_last = true;
        }
    }
}
