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
//! Each stage is a Newton iteration on a system of size `n + m`, the size of the condensed
//! systems of the design notes, factored on the stack (`general`); separable models take a
//! shortcut through `m × m` systems (`separable`). A step allocates nothing.

mod general;
mod separable;
mod work;

use nalgebra::DefaultAllocator;

use self::general::general_step;
use self::separable::{Mass, separable_step};
use self::work::{Step, Work};
pub use self::work::{VariationalOptions, VariationalStats};
use crate::dims::{MatQQ, Storage};
use crate::error::SimError;
use crate::integrator::Integrator;
use crate::model::LagrangeDirac;
use crate::state::State;

/// The variational integrator for a model `M`, with fixed step `h`.
pub struct Variational<'m, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    model: &'m M,
    h: f64,
    options: VariationalOptions,
    t0: f64,
    t: f64,
    t_end: f64,
    /// The state reached: `v` is the stage-2 velocity `w`, and `λ = 2 Γ / h` the multiplier
    /// that the last stage-2 impulse `A(q)ᵀ Γ` stands for over half a step.
    state: State<M>,
    /// The state at the start of the last step, for interpolation.
    previous: State<M>,
    work: Work<M>,
    /// The factored constant mass matrix of a separable model, when the shortcut is on.
    mass: Option<Mass<M>>,
    stats: VariationalStats,
}

impl<'m, M: LagrangeDirac> Variational<'m, M>
where
    DefaultAllocator: Storage<M>,
{
    /// An integrator for `model` with step `h`.
    pub fn new(model: &'m M, h: f64, options: VariationalOptions) -> Result<Self, SimError> {
        if h.is_nan() || h <= 0.0 || h.is_infinite() {
            return Err(SimError::InvalidOption {
                what: "step",
                reason: format!("{h} is not positive and finite"),
            });
        }
        if options.tolerance.is_nan() || options.tolerance <= 0.0 {
            return Err(SimError::InvalidTolerance { what: "tolerance", value: options.tolerance });
        }
        Ok(Variational {
            model,
            h,
            options,
            t0: 0.0,
            t: 0.0,
            t_end: 0.0,
            state: State::zeros(),
            previous: State::zeros(),
            work: Work::new(),
            mass: None,
            stats: VariationalStats::default(),
        })
    }
}

impl<M: LagrangeDirac> Integrator<M> for Variational<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    type Stats = VariationalStats;

    fn model(&self) -> &M {
        self.model
    }

    fn start(&mut self, t0: f64, state: &State<M>, t_end: f64) -> Result<(), SimError> {
        if !t0.is_finite() || !t_end.is_finite() || t_end <= t0 {
            return Err(SimError::InvalidTimeSpan {
                reason: format!("from {t0} to {t_end}: need finite t0 < t_end"),
            });
        }
        self.t = t0;
        self.t0 = t0;
        self.t_end = t_end;
        self.state.clone_from(state);
        self.previous.clone_from(state);
        self.work.big_lambda.fill(0.0);
        self.work.gamma.fill(0.0);
        self.stats = VariationalStats::default();
        self.mass = None;
        if M::SEPARABLE && self.options.use_structure {
            let mut matrix = MatQQ::<M>::zeros();
            self.model.l_vv(t0, &self.state.q, &self.state.v, &mut matrix);
            self.mass = Mass::new(&matrix);
            self.model.dl_dq(t0, &self.state.q, &self.state.v, &mut self.work.dl_dq);
        }
        Ok(())
    }

    /// Takes one step of size `h` and returns `h`.
    fn step(&mut self) -> Result<f64, SimError> {
        let h = self.h;
        self.previous.clone_from(&self.state);
        self.work.a0.fill(0.0);
        self.model.constraint_matrix(&self.state.q, &mut self.work.a0);
        self.work.v.copy_from(&self.state.v);
        self.work.big_lambda.copy_from(&self.work.gamma);
        let mut step = Step {
            model: self.model,
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
        self.state.q += &self.work.v * h;
        self.stats.steps += 1;
        self.t = self.t0 + self.stats.steps as f64 * h;
        self.state.lambda.copy_from(&(&self.work.gamma * (2.0 / h)));
        let s = &self.state;
        if let Some(i) = s.q.iter().chain(s.p.iter()).position(|x| !x.is_finite()) {
            let names = M::coordinate_names();
            return Err(SimError::NonFinite { t: self.t, component: names[i % M::NQ].clone() });
        }
        Ok(h)
    }

    /// Whether the end time has been reached: the last step ends at the first multiple of `h`
    /// (from the start) at or after the end time.
    fn finished(&self) -> bool {
        self.t >= self.t_end - 1e-9 * self.h
    }

    fn t(&self) -> f64 {
        self.t
    }

    fn state(&self) -> &State<M> {
        &self.state
    }

    /// Linear interpolation between step points: second order, like the method.
    fn interpolate(&self, t: f64, out: &mut State<M>) {
        let s = (t - (self.t - self.h)) / self.h;
        let parts = out.components_mut().zip(self.previous.components().zip(self.state.components()));
        for (x, (a, b)) in parts {
            *x = a * (1.0 - s) + b * s;
        }
    }

    fn stats(&self) -> VariationalStats {
        self.stats
    }
}
