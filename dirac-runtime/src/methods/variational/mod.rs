//! A variational integrator from the discrete Hamilton-Pontryagin-d'Alembert principle:
//! second order, fixed step, symplectic for unconstrained and holonomic systems, with
//! constraints of every kind (holonomic, nonholonomic, interconnection) enforced at every step.
//!
//! The discrete Lagrangian is the trapezoidal `L_d = (h/2) [L(q_k, v, t_k) + L(q_{k+1}, v, t_{k+1})]`
//! with `v = (q_{k+1} − q_k)/h`, forces enter by the discrete Lagrange-d'Alembert principle at
//! the midpoint (`F_d± = (h/2) F(q_{k+½}, v, t_{k+½})`), and constraint impulses act at both
//! ends, as in RATTLE (Marsden & West 2001, §3.4). With `P(v) = ½ [L_v(q_k, v) + L_v(q_{k+1}, v)]`
//! one step from `(q_k, p_k)` solves
//!
//! ```text
//! stage 1, for (v, Λ):  p_k = P(v) − (h/2)(L_q(q_k, v) + F) − A(q_k)ᵀ Λ
//!                       φ(q_k + h v) = 0                      (holonomic rows)
//!                       A(q_k + h v/2) v = 0                  (other rows: nonholonomic and
//!                                                              interconnection one-forms)
//! stage 2, for (w, Γ):  L_v(q_{k+1}, w) − A(q_{k+1})ᵀ Γ = P(v) + (h/2)(L_q(q_{k+1}, v) + F)
//!                       A(q_{k+1}) w = 0
//! ```
//!
//! and sets `p_{k+1} = L_v(q_{k+1}, w)`: the new state lies on the constraint manifold and in
//! the image of the Legendre map of the constraint distribution, so a degenerate Lagrangian
//! (whose momenta are constrained, `p̄2 = 0`) is handled like any other. For a regular
//! Lagrangian `½ vᵀ M v − V(q)` without constraints the step is velocity Verlet; with
//! holonomic constraints it is RATTLE.
//!
//! Events are located on the discrete flow: the state at a time within a step is a step of
//! the method to that time ([`Integrator::state_at`](crate::integrator::Integrator::state_at)), so an impact time is solved within the
//! step, on the trajectory the method takes. A restart there (an impact's reset) keeps the
//! grid: the step after it ends where the interrupted one would have, so the map across an
//! impact (a step `αh` to it, the rest `(1 − α)h` after it) is as symmetric in time as the
//! method, and the energy error stays bounded over many elastic impacts (a collision
//! integrator in the sense of Fetecau, Marsden, Ortiz and West 2003, with the impact law left
//! to the event's action).
//!
//! Each stage is a Newton iteration on a system of size `n + m`, the size of the condensed
//! systems of the design notes, factored on the stack (`general`); separable models take a
//! shortcut through `m × m` systems (`separable`). A step allocates nothing.

mod general;
pub(crate) mod separable;
mod work;

use crate::analysis::free::FreeVelocities;
use nalgebra::DefaultAllocator;

use std::cell::RefCell;

use self::general::general_step;
use self::separable::separable_step;
use self::work::{Step, Work};
pub use self::work::{VariationalOptions, VariationalStats};
use crate::algebra::mass::Mass;
use crate::algebra::{Algebra, Saddle};
use crate::analysis::projection::Projector;
use crate::error::SimError;
use crate::integrator::drive::Driver;
use crate::integrator::held::Held;
use crate::integrator::restart::{Restarts, constraint_violation};
use crate::integrator::{Drive, Integrator};
use crate::model::configuration;
use crate::model::state::State;
use crate::model::{EnergyBalance, LagrangeDirac};
use crate::shape::dims::{Sizes, Storage, VecC};

/// The variational integrator for a model `M`, with fixed step `h`.
pub struct Variational<'m, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    model: Held<'m, M>,
    h: f64,
    options: VariationalOptions,
    t0: f64,
    t: f64,
    /// The start of the last step (the start, or the restart, before the first).
    t_previous: f64,
    t_end: f64,
    /// Steps taken since the start, and the number that reaches the end time.
    taken: usize,
    total: usize,
    /// The energy at the start, and the size of the energy's parts `|⟨p, v⟩| + |L|` there,
    /// for the stability check.
    energy0: f64,
    /// The largest size of the energy's parts since the start (restarts included): errors far
    /// below it are round-off, even where the energy's parts vanish (a body come to rest).
    energy_scale: f64,
    /// The size of the energy's parts at the (re)start: an energy error a hundred times the
    /// size of the energy there and of the work done since is growth, not error.
    size0: f64,
    /// The largest momentum at the last stability check that passed: a step that multiplies it
    /// by 8 is checked at once.
    p_checked: f64,
    /// The largest `|⟨p, v⟩|` (twice the kinetic energy of a quadratic Lagrangian) reached at a
    /// step since the (re)start: the energy the motion exchanges between its parts, the scale of
    /// a stable run's energy error even where the energy's parts vanish together (a pendulum
    /// released from the horizontal, at the top of its swing).
    exchanged: f64,
    /// The state reached: `v` is the stage-2 velocity `w`, and `λ` the multipliers
    /// extrapolated from the steps' impulses to second order (see `update_multipliers`).
    state: State<M>,
    /// The state at the start of the last step, for interpolation.
    previous: State<M>,
    /// The multipliers at the last midpoint before a step taken as sub-steps.
    saved_midpoint: VecC<M>,
    work: Work<M>,
    /// The factored constant mass matrix of a separable dense model, when the shortcut is on.
    mass: Option<Mass<M>>,
    /// Puts interpolated samples back on the constraints.
    projector: RefCell<Projector<M>>,
    /// The state and work space of steps to times within the last step
    /// ([`Integrator::state_at`]), apart from the integration's own.
    probe: RefCell<(State<M>, Work<M>, VariationalStats)>,
    sizes: Sizes,
    stats: VariationalStats,
    /// What a restart checks after the model was handed out for a change.
    restarts: Restarts<M>,
    /// The drive of the inputs within the steps, and the stops where they jump or bend.
    driver: Driver<'m, M>,
}

impl<'m, M: LagrangeDirac> Variational<'m, M>
where
    DefaultAllocator: Storage<M>,
{
    /// An integrator for `model` with step `h`.
    ///
    /// Built on `&model`, the integrator reads the model; built on `&mut model`, it may also
    /// change it between steps ([`Integrator::update`], [`Integrator::set_input`]).
    pub fn new(model: impl Into<Held<'m, M>>, h: f64, options: VariationalOptions) -> Result<Self, SimError> {
        let model = model.into();
        if h.is_nan() || h <= 0.0 || h.is_infinite() {
            return Err(SimError::InvalidOption {
                what: "step",
                reason: format!("{h} is not positive and finite"),
            });
        }
        options.validate()?;
        let sizes = model.sizes();
        let (work, projector) = (Work::new(model.get()), RefCell::new(Projector::new(model.get())));
        let probe =
            RefCell::new((State::with_sizes(sizes), Work::new(model.get()), VariationalStats::default()));
        let restarts = Restarts::new(model.get());
        Ok(Variational {
            model,
            h,
            options,
            t0: 0.0,
            t: 0.0,
            t_previous: 0.0,
            t_end: 0.0,
            taken: 0,
            total: 0,
            energy0: 0.0,
            size0: 0.0,
            p_checked: 0.0,
            exchanged: 0.0,
            energy_scale: 0.0,
            state: State::with_sizes(sizes),
            previous: State::with_sizes(sizes),
            saved_midpoint: sizes.zeros_c::<M>(),
            work,
            mass: None,
            projector,
            probe,
            sizes,
            stats: VariationalStats::default(),
            restarts,
            driver: Driver::default(),
        })
    }
}

impl<M: LagrangeDirac> Variational<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    /// Finds the velocities only the forces fix at `(t, state)`, where they may be: not in a
    /// separable model, nor where `[L_vv Aᵀ; A 0]` is regular. At every start and restart:
    /// which coordinates lack inertia and constraints can change at a restart (a law's row that
    /// switched, a diode that blocks).
    fn find_free_velocities(&mut self, t: f64, state: &State<M>) -> Result<(), SimError> {
        self.work.free = None;
        self.probe.get_mut().1.free = None;
        if !M::SEPARABLE && !self.work.saddle_regular(self.model.get(), t, state) {
            let free = |model: &M| FreeVelocities::find(model, t, (&state.q, &state.v), "Variational");
            self.work.free = free(self.model.get())?;
            self.probe.get_mut().1.free = free(self.model.get())?;
        }
        Ok(())
    }

    /// Steps from `self.state` at `t0` towards `t_end` on a new grid: the energy reference
    /// and the work of the forces start again, and a separable model's mass matrix is
    /// factored again (a change of the model may have changed it).
    fn begin(&mut self, t0: f64, goal: f64) -> Result<(), SimError> {
        let t_end = self.driver.stops.stretch(t0, goal);
        self.total = self.steps_to(t0, t_end)?;
        self.taken = 0;
        self.t0 = t0;
        self.t_end = t_end;
        self.rebase(t0);
        Ok(())
    }

    /// Carries on from `self.state` at `t` on the present grid: the energy reference and the
    /// work of the forces start again, and a separable model's mass matrix is factored again
    /// (a change of the model may have changed it).
    fn rebase(&mut self, t0: f64) {
        self.t = t0;
        self.t_previous = t0;
        self.work.work = 0.0;
        self.work.midpoint.1 = 0.0;
        let model = self.model.get();
        let s = &self.state;
        self.energy0 = model.energy(t0, &s.q, &s.v, &s.p);
        self.size0 = s.p.dot(&s.v).abs() + model.lagrangian(t0, &s.q, &s.v).abs();
        self.p_checked = s.p.amax();
        self.exchanged = s.p.dot(&s.v).abs();
        self.previous.clone_from(s);
        self.work.grow_scales(model, t0, s);
        self.mass = None;
        if M::SEPARABLE && !M::NON_ASSOCIATED && self.options.use_structure {
            let lvv = &mut self.work.blocks.lvv0;
            model.l_vv(t0, &s.q, &s.v, lvv);
            self.mass = M::Algebra::dense_qq(lvv).and_then(|matrix| Mass::new(&self.sizes, matrix));
            model.dl_dq(t0, &s.q, &s.v, &mut self.work.dl_dq);
        }
    }

    /// The size of the next step and how many grid intervals it closes: one, to the next
    /// grid point (the end time after the last); after a restart between grid points, the
    /// rest of the interval, joined to the next one when it is shorter than a millionth of
    /// a step.
    fn next_step(&self) -> (f64, usize) {
        let k = self.taken;
        if self.t == self.time_after(k) {
            return (if k + 1 == self.total { self.t_end - self.t } else { self.h }, 1);
        }
        let short = k + 2 <= self.total && self.time_after(k + 1) - self.t < 1e-6 * self.h;
        let intervals = if short { 2 } else { 1 };
        (self.time_after(k + intervals) - self.t, intervals)
    }

    /// The multipliers at the end of a step of size `h`. Each of the impulses `Λ` and `Γ` alone
    /// gives them to first order only; their sum over the step, `μ = (Λ + Γ)/h`, gives them at
    /// the step's midpoint to second order. They are extrapolated from this midpoint and the
    /// one before (from the multipliers at the start, after a start or restart) to the end of
    /// the step, to second order.
    fn update_multipliers(&mut self, h: f64) {
        let w = &mut self.work;
        let (previous, h_previous) = &mut w.midpoint;
        let start = *h_previous == 0.0;
        // The step's end lies h/2 beyond its midpoint, which lies (h_previous + h)/2 beyond
        // the midpoint before (h/2 beyond the start after a start or restart).
        let beyond = if start { 1.0 } else { h / (*h_previous + h) };
        let inverse_h = 1.0 / h;
        for j in 0..self.sizes.typed::<M>().nc {
            let mu = (w.big_lambda[j] + w.gamma[j]) * inverse_h;
            let before = if start { self.state.lambda[j] } else { previous[j] };
            self.state.lambda[j] = mu + (mu - before) * beyond;
            previous[j] = mu;
        }
        *h_previous = h;
    }

    /// The work of the step's constraint impulses, `−⟨Λ, b(q_k, t_k)⟩ − ⟨Γ, b(q_{k+1}, t_{k+1})⟩`
    /// (each impulse times the velocity its constraint prescribes), into the work the energy
    /// check allows for: zero unless a constraint prescribes a motion.
    fn add_constraint_work(&mut self, h: f64) {
        let model = self.model.get();
        let w = &mut self.work;
        model.constraint_rate(self.t, &self.state.q, &mut w.vectors.rate);
        w.work -= w.vectors.rate.dot(&w.big_lambda);
        configuration::advance::<M>(&self.state.q, h, &w.v, &mut w.vectors.q1);
        model.constraint_rate(self.t + h, &w.vectors.q1, &mut w.vectors.rate);
        w.work -= w.vectors.rate.dot(&w.gamma);
    }

    /// The number of steps from `t0` to `t_end`, the last one possibly shorter; an error if
    /// the step cannot advance time at that magnitude or the budget does not allow them.
    fn steps_to(&self, t0: f64, t_end: f64) -> Result<usize, SimError> {
        let h = self.h;
        if h <= f64::EPSILON * t0.abs().max(t_end.abs()) {
            return Err(SimError::StepSizeTooSmall {
                t: t0,
                h,
                reason: format!(
                    "the step does not advance time at t = {t0}: its size is below the resolution of t"
                ),
            });
        }
        // A last step shorter than a millionth of h is folded into the one before it.
        let steps = ((t_end - t0) / h - 1e-6).ceil().max(1.0);
        if steps > self.options.max_steps as f64 {
            return Err(SimError::TooManySteps { max_steps: self.options.max_steps, t: t0, t_end });
        }
        Ok(steps as usize)
    }

    /// The time after `k` steps: `t0 + k h`, except the end time after the last.
    fn time_after(&self, k: usize) -> f64 {
        if k >= self.total { self.t_end } else { self.t0 + k as f64 * self.h }
    }

    /// One step of the method of size `h` from `self.t` and `self.state`, with its work and
    /// multipliers; `self.t` is left at the step's start. Inlined into `step`, as the whole
    /// step was before sub-steps called it too (a call cost the separable pendulum 10% of its
    /// instructions).
    #[inline(always)]
    fn advance(&mut self, h: f64) -> Result<(), SimError> {
        // The forces act at the step's midpoint: a drive sets the inputs for that time (from
        // the state at the step's start), second order as the method is.
        if self.driver.driven() {
            let s = &self.state;
            self.driver.apply(&mut self.model, (self.t + 0.5 * h, self.t_end), &s.q, &s.v);
        }
        self.model.get().constraint_matrix(self.t, &self.state.q, &mut self.work.a0);
        if M::NON_ASSOCIATED {
            self.model.get().slip_rows(self.t, &self.state.q, &self.state.v, &mut self.work.slip0);
        }
        self.work.v.copy_from(&self.state.v);
        self.work.big_lambda.copy_from(&self.work.gamma);
        let mut step = Step {
            model: self.model.get(),
            h,
            t: self.t,
            options: &self.options,
            state: &mut self.state,
            work: &mut self.work,
            stats: &mut self.stats,
        };
        match &self.mass {
            Some(mass) => separable_step(&mut step, mass)?,
            None => general_step(&mut step)?,
        }
        let qm = &mut self.work.vectors.qm;
        configuration::advance::<M>(&self.state.q, 0.5 * h, &self.work.v, qm);
        self.work.work -= h * self.model.get().dl_dt(self.t + 0.5 * h, qm, &self.work.v);
        if M::PRESCRIBED {
            self.add_constraint_work(h);
        }
        configuration::advance_in_place::<M>(&mut self.state.q, h, self.work.v.as_slice());
        self.update_multipliers(h);
        Ok(())
    }

    /// The step of size `h` from `self.previous` at `self.t`, whose iteration failed with
    /// `error`, as ever more equal sub-steps, until every sub-step converges; `error` if 64 do
    /// not, or at once if it is not a Newton iteration's divergence.
    #[cold]
    #[inline(never)]
    fn substeps(&mut self, h: f64, error: SimError) -> Result<(), SimError> {
        if !matches!(error, SimError::NewtonDiverged { .. }) {
            return Err(error);
        }
        let t0 = self.t;
        let work0 = self.work.work;
        let (midpoint, h_midpoint) = &self.work.midpoint;
        self.saved_midpoint.copy_from(midpoint);
        let h_midpoint = *h_midpoint;
        let mut parts = 2;
        loop {
            self.state.clone_from(&self.previous);
            self.work.work = work0;
            self.work.midpoint.0.copy_from(&self.saved_midpoint);
            self.work.midpoint.1 = h_midpoint;
            self.work.gamma.fill(0.0);
            if self.mass.is_some() {
                let s = &self.state;
                self.model.get().dl_dq(t0, &s.q, &s.v, &mut self.work.dl_dq);
            }
            let hs = h / parts as f64;
            let mut converged = true;
            for j in 0..parts {
                self.t = t0 + j as f64 * hs;
                match self.advance(hs) {
                    Ok(()) => self.stats.substeps += 1,
                    Err(SimError::NewtonDiverged { .. }) => {
                        converged = false;
                        break;
                    }
                    Err(other) => {
                        self.t = t0;
                        return Err(other);
                    }
                }
            }
            self.t = t0;
            // Sub-steps whose iterations stopped short of the constraints (a singular direction
            // the step size does not cure) are no better than the step that diverged.
            if converged {
                let end = t0 + h;
                return match constraint_violation(self.model.get(), end, &self.state) <= 1e-10 {
                    true => Ok(()),
                    false => Err(error),
                };
            }
            if parts >= 64 {
                return Err(error);
            }
            parts *= 2;
        }
    }

    /// A fixed step beyond the method's stability limit makes the discrete solution grow
    /// geometrically: the energy error (corrected by the work of the forces and of the
    /// Lagrangian's time dependence) then becomes as large as the energy's own parts and as half
    /// the largest kinetic energy the motion reached, which in a stable run it never approaches
    /// (the second matters where the parts vanish together: a pendulum released from the
    /// horizontal has energy 0 and, at the top of each swing, parts near 0), and far larger than the energy at the start and the
    /// work done since (the energy's parts grow with the solution, so the first test alone
    /// would let a run grow without bound when they grow alike). Checked every 16 steps, and
    /// at once after a step that multiplies the largest momentum by 8 (`pmax`).
    #[inline(never)]
    fn check_stability(&mut self, pmax: f64) -> Result<(), SimError> {
        let s = &self.state;
        let lagrangian = self.model.get().lagrangian(self.t, &s.q, &s.v);
        let kinetic = s.p.dot(&s.v);
        let energy = kinetic - lagrangian;
        let error = (energy - self.energy0 - self.work.work).abs();
        let size = kinetic.abs() + lagrangian.abs() + self.energy0.abs();
        // Growth: far beyond the energy at the start, the work done since and the largest
        // energy's parts of a check whose error was small (those of a growing solution are not).
        let reference = self.size0 + self.work.work.abs() + self.energy_scale;
        let grown = reference > 0.0 && error > 100.0 * reference && error > 1e-3 * size;
        // Small: against the energy's parts now, or against half the largest kinetic energy the
        // motion reached (`exchanged` is twice it). A growing solution's error outgrows both.
        let small = error <= 0.5 * size.max(1e-9 * self.energy_scale) || error <= 0.25 * self.exchanged;
        if !grown && (error.is_finite() && small || size == 0.0) {
            if error <= 0.1 * size {
                self.energy_scale = self.energy_scale.max(size);
            }
            self.p_checked = self.p_checked.max(pmax);
            return Ok(());
        }
        Err(SimError::Unstable {
            t: self.t,
            h: self.h,
            detail: format!(
                "the energy went from {:e} to {energy:e} (the forces did {:e} of work; the largest \
                 kinetic energy reached was {:e}): the step {:e} is beyond or near the stability limit \
                 of the method for this motion; take a smaller step (the limit of a linear oscillation \
                 of frequency ω is h < 2/ω) or Radau, whose steps follow the motion",
                self.energy0,
                self.work.work,
                0.5 * self.exchanged,
                self.h
            ),
        })
    }
}

impl<M: LagrangeDirac> Integrator<M> for Variational<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    type Stats = VariationalStats;

    const NAME: &'static str = "Variational";

    fn model(&self) -> &M {
        self.model.get()
    }

    fn start(&mut self, t0: f64, state: &State<M>, t_end: f64) -> Result<(), SimError> {
        // A drive sets the inputs at the start before the state is checked against them.
        let stretch = self.driver.stops.stretch(t0, t_end);
        self.driver.apply_state(&mut self.model, (t0, stretch), state);
        self.restarts.start(self.model.get(), (t0, t_end), state, 1e-8)?;
        self.state.clone_from(state);
        self.work.scale.fill(0.0);
        self.work.big_lambda.fill(0.0);
        self.work.gamma.fill(0.0);
        self.stats = VariationalStats::default();
        self.energy_scale = 0.0;
        self.find_free_velocities(t0, state)?;
        self.begin(t0, t_end)
    }

    fn model_mut(&mut self) -> Option<&mut M> {
        self.restarts.model_mut(&mut self.model, self.t, &self.state)
    }

    fn restart_until(&mut self, t_end: f64) -> Result<(), SimError> {
        if self.t >= t_end {
            return Ok(());
        }
        self.restarts.resume(self.model.get(), self.t, &self.state, (1e-8, |_, _| 0.0))?;
        self.begin(self.t, t_end)
    }

    fn restart_at(&mut self, t: f64, state: &State<M>) -> Result<(), SimError> {
        self.restarts.jump(self.model.get(), t, (self.t_previous, self.t), state, 1e-8)?;
        if self.restarts.rows_switch {
            self.find_free_velocities(t, state)?;
        }
        self.state.clone_from(state);
        // The rows may have changed (a contact closed or opened): redundant now, or no longer.
        self.work.saddle.remeasure();
        self.work.small_deflation.remeasure();
        self.work.big_lambda.fill(0.0);
        self.work.gamma.fill(0.0);
        if t >= self.t_end {
            // At the end time: nothing is left to step.
            (self.t, self.t_previous, self.t0, self.taken, self.total) = (t, t, t, 0, 0);
            return Ok(());
        }
        // The grid stays: the next step ends where the last one did. Across an impact the map
        // is then a step αh to it and the rest, (1 − α)h, after it, which is as symmetric in
        // time as the method itself; restarting the grid at the impact instead makes the
        // energy drift over many impacts.
        if t < self.t {
            self.taken -= 1;
        }
        self.rebase(t);
        Ok(())
    }

    fn end(&self) -> f64 {
        self.driver.stops.goal()
    }

    fn set_inputs_at(&mut self, t: f64, state: &State<M>) {
        self.driver.apply_state(&mut self.model, (t, self.t_end), state);
    }

    fn driven(&self) -> bool {
        self.driver.driven()
    }

    /// Takes one step of size `h` (the last one shorter, so that it ends at the end time) and
    /// returns its size. Where Newton's iteration does not converge (the step's equations may
    /// have no solution near the motion: RATTLE's projection of a pendulum swinging through
    /// more than its length in a step misses the circle), the step is taken as 2, 4, …, 64
    /// equal sub-steps of the method; the result is then a composition of variational steps,
    /// as symplectic and of the same order, counted in [`VariationalStats::substeps`].
    #[inline]
    fn step(&mut self) -> Result<f64, SimError> {
        if self.taken >= self.total && self.driver.stops.due(self.t, self.t_end) {
            // A stop: a new grid from here to the next one (or the end).
            self.begin(self.t, self.driver.stops.goal())?;
        }
        let (h, intervals) = self.next_step();
        self.t_previous = self.t;
        self.previous.clone_from(&self.state);
        if let Err(error) = self.advance(h) {
            self.substeps(h, error)?;
        }
        self.stats.steps += 1;
        self.taken += intervals;
        self.t = self.time_after(self.taken);
        let s = &self.state;
        // An index loop: the chained iterators of nalgebra cost more than the step itself.
        if let Some(i) =
            (0..self.sizes.typed::<M>().nq).find(|&i| !(s.q[i].is_finite() && s.p[i].is_finite()))
        {
            let names = self.model.get().coordinate_names();
            return Err(SimError::NonFinite { t: self.t, component: names[i].clone() });
        }
        self.exchanged = self.exchanged.max(s.p.dot(&s.v).abs());
        let limit = 8.0 * self.p_checked;
        let grew = (0..self.sizes.typed::<M>().nq).any(|i| s.p[i].abs() > limit);
        if grew || self.taken.is_multiple_of(16) || self.finished() {
            self.check_stability(s.p.amax())?;
        }
        Ok(h)
    }

    /// Whether the end time has been reached.
    fn finished(&self) -> bool {
        self.taken >= self.total && self.t_end >= self.driver.stops.goal()
    }

    fn t(&self) -> f64 {
        self.t
    }

    fn state(&self) -> &State<M> {
        &self.state
    }

    /// The state between step points: positions and velocities interpolated linearly (second
    /// order, like the method) and put back on the constraints (positions onto `φ(q, t) = 0`,
    /// velocities onto `A(q, t) v + b(q, t) = 0`, each by the smallest correction), momenta from the
    /// Legendre map, multipliers interpolated.
    fn interpolate(&self, t: f64, out: &mut State<M>) {
        let t_previous = self.t_previous;
        let s = (t - t_previous) / (self.t - t_previous);
        configuration::between::<M>(&self.previous.q, &self.state.q, s, &mut out.q);
        // Velocities and multipliers by the same weights; momenta from the Legendre map below.
        let (a, b) = (&self.previous, &self.state);
        out.v.zip_zip_apply(&a.v, &b.v, |x, a, b| *x = a * (1.0 - s) + b * s);
        out.lambda.zip_zip_apply(&a.lambda, &b.lambda, |x, a, b| *x = a * (1.0 - s) + b * s);
        if self.sizes.nc > 0 {
            self.projector.borrow_mut().project(self.model.get(), t, &mut out.q, &mut out.v);
        }
        self.model.get().dl_dv(t, &out.q, &out.v, &mut out.p);
    }

    /// A step of the method from the last step's start to `t`: the discrete flow, on which
    /// events are located, so that an impact lies on the trajectory the integrator would
    /// have taken (the impact time solved within the step) and a restart there carries on
    /// the method's energy behaviour instead of an interpolation's error.
    fn state_at(&self, t: f64, out: &mut State<M>) -> Result<(), SimError> {
        let t_previous = self.t_previous;
        let (h, h_last) = (t - t_previous, self.t - t_previous);
        if h <= 0.0 || h >= h_last {
            out.clone_from(if h <= 0.0 { &self.previous } else { &self.state });
            return Ok(());
        }
        let model = self.model.get();
        let mut probe = self.probe.borrow_mut();
        let (state, work, stats) = &mut *probe;
        state.clone_from(&self.previous);
        model.constraint_matrix(t_previous, &state.q, &mut work.a0);
        if M::NON_ASSOCIATED {
            model.slip_rows(t_previous, &state.q, &state.v, &mut work.slip0);
        }
        work.v.copy_from(&state.v);
        // The last step's impulses, scaled to the shorter step, start Newton.
        let share = h / h_last;
        work.big_lambda.copy_from(&self.work.big_lambda);
        work.big_lambda *= share;
        work.gamma.copy_from(&self.work.gamma);
        work.gamma *= share;
        work.scale.copy_from(&self.work.scale);
        let mut step = Step { model, h, t: t_previous, options: &self.options, state, work, stats };
        match &self.mass {
            Some(mass) => {
                model.dl_dq(t_previous, &step.state.q, &step.state.v, &mut step.work.dl_dq);
                separable_step(&mut step, mass)?;
            }
            None => general_step(&mut step)?,
        }
        configuration::advance_in_place::<M>(&mut state.q, h, work.v.as_slice());
        out.q.copy_from(&state.q);
        out.v.copy_from(&state.v);
        out.p.copy_from(&state.p);
        // The multipliers as the interpolation has them.
        out.lambda.copy_from(&self.previous.lambda);
        out.lambda.axpy(share, &self.state.lambda, 1.0 - share);
        Ok(())
    }

    fn stats(&self) -> VariationalStats {
        self.stats
    }
}

/// Inputs set once a step, at its midpoint, where the discrete forces act; a step to a time
/// within the last one ([`Integrator::state_at`]) reads the inputs as they were last set.
impl<'m, M: LagrangeDirac> Drive<'m, M> for Variational<'m, M>
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
