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
//! systems of the design notes, factored on the stack: a step allocates nothing.

use std::ops::ControlFlow;

use nalgebra::{DefaultAllocator, OVector};

use crate::dims::{Dimensions, MatCQ, MatQQ, Storage, VecC, VecH, VecQ, VecY};
use crate::error::SimError;
use crate::lu::Lu;
use crate::model::LagrangeDirac;
use crate::radau::Stats;
use crate::solution::{Integrator, Sampling, Solution, Stepper, integrate};
use crate::state::State;

/// Newton tolerances of the two stages.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VariationalOptions {
    /// Converged when the Newton update is below `tolerance · (1 + |x|)` in every component
    /// (default `1e-12`), or when it has stalled at round-off below `1e3 · tolerance`.
    pub tolerance: f64,
    /// Newton iterations allowed per stage.
    pub max_iterations: usize,
    /// Whether to use the shortcut for separable models ([`LagrangeDirac::SEPARABLE`] with a
    /// nonsingular mass matrix): the same discrete equations, solved through `m × m` systems
    /// in the multipliers as RATTLE does. On by default.
    pub use_structure: bool,
}

impl Default for VariationalOptions {
    fn default() -> Self {
        VariationalOptions { tolerance: 1e-12, max_iterations: 20, use_structure: true }
    }
}

/// Counters of the work a variational integration did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct VariationalStats {
    /// Steps taken.
    pub steps: usize,
    /// Newton iterations, both stages.
    pub newton_iterations: usize,
}

/// The variational integrator for a model `M`, with fixed step `h`.
pub struct Variational<'m, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    model: &'m M,
    h: f64,
    options: VariationalOptions,
    t: f64,
    t_end: f64,
    q: VecQ<M>,
    p: VecQ<M>,
    w: VecQ<M>,
    lambda: VecC<M>,
    t0: f64,
    previous: VecY<M>,
    current: VecY<M>,
    // Work space of one step.
    v: VecQ<M>,
    big_lambda: VecC<M>,
    gamma: VecC<M>,
    a0: MatCQ<M>,
    lu: Lu<f64, M::Nk>,
    last_update: f64,
    /// The factored constant mass matrix of a separable model, when the shortcut is on.
    mass: Option<Mass<M>>,
    small: Lu<f64, M::Nc>,
    /// `∂L/∂q` at the current point (separable models: independent of `v`).
    dl_dq: VecQ<M>,
    stats: VariationalStats,
}

/// The `(n + m)`-sized unknowns and residuals of a stage.
type VecK<M> = OVector<f64, <M as Dimensions>::Nk>;

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
            t: 0.0,
            t_end: 0.0,
            q: VecQ::<M>::zeros(),
            p: VecQ::<M>::zeros(),
            w: VecQ::<M>::zeros(),
            lambda: VecC::<M>::zeros(),
            t0: 0.0,
            previous: VecY::<M>::zeros(),
            current: VecY::<M>::zeros(),
            v: VecQ::<M>::zeros(),
            big_lambda: VecC::<M>::zeros(),
            gamma: VecC::<M>::zeros(),
            a0: MatCQ::<M>::zeros(),
            lu: Lu::new(),
            last_update: f64::INFINITY,
            mass: None,
            small: Lu::new(),
            dl_dq: VecQ::<M>::zeros(),
            stats: VariationalStats::default(),
        })
    }

    /// The current time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// The current state `(q, v, p, λ)`; λ is the multiplier that the last stage-2 impulse
    /// `A(q)ᵀ Γ` stands for over half a step, `λ = 2 Γ / h`.
    pub fn state(&self) -> State<M> {
        State { q: self.q.clone(), v: self.w.clone(), p: self.p.clone(), lambda: self.lambda.clone() }
    }

    /// The work done so far.
    pub fn stats(&self) -> VariationalStats {
        self.stats
    }

    /// Whether the end time has been reached: the last step ends at the first multiple of `h`
    /// (from the start) at or after the end time.
    pub fn finished(&self) -> bool {
        self.t >= self.t_end - 1e-9 * self.h
    }

    /// Prepares to integrate from a consistent `state` at `t0` until `t_end`.
    pub fn start(&mut self, t0: f64, state: &State<M>, t_end: f64) -> Result<(), SimError> {
        if !t0.is_finite() || !t_end.is_finite() || t_end <= t0 {
            return Err(SimError::InvalidTimeSpan {
                reason: format!("from {t0} to {t_end}: need finite t0 < t_end"),
            });
        }
        self.t = t0;
        self.t0 = t0;
        self.t_end = t_end;
        self.q.copy_from(&state.q);
        self.p.copy_from(&state.p);
        self.w.copy_from(&state.v);
        self.lambda.copy_from(&state.lambda);
        self.big_lambda.fill(0.0);
        self.gamma.fill(0.0);
        self.stats = VariationalStats::default();
        self.write_current();
        self.previous.copy_from(&self.current);
        self.mass = None;
        if M::SEPARABLE && self.options.use_structure {
            let mut matrix = MatQQ::<M>::zeros();
            self.model.l_vv(t0, &self.q, &self.w, &mut matrix);
            self.mass = Mass::new(&matrix);
            self.model.dl_dq(t0, &self.q, &self.w, &mut self.dl_dq);
        }
        Ok(())
    }

    fn write_current(&mut self) {
        let n = M::NQ;
        self.current.rows_mut(0, n).copy_from(&self.q);
        self.current.rows_mut(n, n).copy_from(&self.w);
        self.current.rows_mut(2 * n, n).copy_from(&self.p);
        self.current.rows_mut(3 * n, M::NC).copy_from(&self.lambda);
    }

    /// Takes one step of size `h`.
    pub fn step(&mut self) -> Result<(), SimError> {
        self.previous.copy_from(&self.current);
        self.a0.fill(0.0);
        self.model.constraint_matrix(&self.q, &mut self.a0);
        self.v.copy_from(&self.w);
        self.big_lambda.copy_from(&self.gamma);
        if self.mass.is_some() {
            self.separable_step()?;
        } else {
            self.last_update = f64::INFINITY;
            self.stage_one()?;
            self.last_update = f64::INFINITY;
            self.stage_two()?;
        }
        self.q += &self.v * self.h;
        self.stats.steps += 1;
        self.t = self.t0 + self.stats.steps as f64 * self.h;
        self.lambda.copy_from(&(&self.gamma * (2.0 / self.h)));
        self.write_current();
        if let Some(i) = self.q.iter().chain(self.p.iter()).position(|x| !x.is_finite()) {
            let names = M::coordinate_names();
            return Err(SimError::NonFinite { t: self.t, component: names[i % M::NQ].clone() });
        }
        Ok(())
    }

    /// Both stages for a separable model, `M v = p_k + (h/2) ∂L/∂q(q_k) + A(q_k)ᵀ Λ`: with `M`
    /// factored once, stage 1 is Newton on `Λ` alone (SHAKE) and stage 2 a linear system in
    /// `Γ` (RATTLE's velocity projection), both `m × m`.
    fn separable_step(&mut self) -> Result<(), SimError> {
        let (m, h) = (M::NC, self.h);
        let mass = self.mass.as_ref().expect("separable step with a factored mass matrix");
        let t1 = self.t + h;
        let mut v_free = &self.p + &self.dl_dq * (0.5 * h);
        mass.solve(&mut v_free);
        if m == 0 {
            self.v.copy_from(&v_free);
        } else {
            // B = M⁻¹ A(q_k)ᵀ, so v = v_free + B Λ.
            let mut b = self.a0.transpose();
            for j in 0..m {
                let mut column = b.column(j).into_owned();
                mass.solve(&mut column);
                b.set_column(j, &column);
            }
            let mut converged = false;
            self.last_update = f64::INFINITY;
            for _ in 0..self.options.max_iterations {
                self.v.copy_from(&(&v_free + &b * &self.big_lambda));
                let q1 = &self.q + &self.v * h;
                let qm = &self.q + &self.v * (0.5 * h);
                let mut r = self.stage_one_constraints(&q1, &qm);
                let c = Self::stage_one_constraint_jacobian(self.model, &q1, &qm, &self.v, h);
                self.small.matrix_mut().copy_from(&(c * &b));
                self.factor_small()?;
                self.small.solve(&mut r);
                self.big_lambda -= &r;
                self.stats.newton_iterations += 1;
                let size = r.amax();
                let scale = 1.0 + self.big_lambda.amax();
                let stalled = size >= 0.5 * self.last_update && size <= 1e3 * self.options.tolerance * scale;
                self.last_update = size;
                if size <= self.options.tolerance * scale || stalled {
                    converged = true;
                    break;
                }
            }
            if !converged {
                return Err(SimError::NewtonDiverged {
                    t: self.t,
                    h,
                    iterations: self.options.max_iterations,
                });
            }
            self.v.copy_from(&(&v_free + &b * &self.big_lambda));
        }
        let q1 = &self.q + &self.v * h;
        let mut dl_dq1 = VecQ::<M>::zeros();
        self.model.dl_dq(t1, &q1, &self.v, &mut dl_dq1);
        // M v = p_k + (h/2) g_k + A_kᵀ Λ, so P(v) + (h/2) g_{k+1} needs no product with M.
        let target = &self.p + (&self.dl_dq + &dl_dq1) * (0.5 * h) + self.a0.transpose() * &self.big_lambda;
        let mass = self.mass.as_ref().expect("separable step with a factored mass matrix");
        let mut w = target.clone();
        mass.solve(&mut w);
        if m == 0 {
            self.w.copy_from(&w);
            self.p.copy_from(&target);
        } else {
            let mut a1 = MatCQ::<M>::zeros();
            self.model.constraint_matrix(&q1, &mut a1);
            let mut d = a1.transpose();
            for j in 0..m {
                let mut column = d.column(j).into_owned();
                mass.solve(&mut column);
                d.set_column(j, &column);
            }
            self.small.matrix_mut().copy_from(&(&a1 * &d));
            self.factor_small()?;
            let mut gamma = -(&a1 * &w);
            self.small.solve(&mut gamma);
            self.gamma.copy_from(&gamma);
            self.w.copy_from(&(w + d * &gamma));
            self.p.copy_from(&(target + a1.transpose() * &gamma));
        }
        self.dl_dq.copy_from(&dl_dq1);
        Ok(())
    }

    fn factor_small(&mut self) -> Result<(), SimError> {
        self.small.factor().map_err(|s| SimError::SingularMatrix {
            t: self.t,
            h: self.h,
            detail: format!(
                "the constraint `{}` is dependent on the others",
                M::constraint_names()[s.column]
            ),
        })
    }

    /// Stage 1: the new positions, through `(v, Λ)`.
    fn stage_one(&mut self) -> Result<(), SimError> {
        let (n, m, h) = (M::NQ, M::NC, self.h);
        let (t0, t1, tm) = (self.t, self.t + h, self.t + 0.5 * h);
        let mut r = VecK::<M>::zeros();
        for _ in 0..self.options.max_iterations {
            let q1 = &self.q + &self.v * h;
            let qm = &self.q + &self.v * (0.5 * h);
            let (mut lv0, mut lv1, mut lq0, mut f) =
                (VecQ::<M>::zeros(), VecQ::<M>::zeros(), VecQ::<M>::zeros(), VecQ::<M>::zeros());
            self.model.dl_dv(t0, &self.q, &self.v, &mut lv0);
            self.model.dl_dv(t1, &q1, &self.v, &mut lv1);
            self.model.dl_dq(t0, &self.q, &self.v, &mut lq0);
            self.model.force(tm, &qm, &self.v, &mut f);
            let momentum =
                (lv0 + lv1) * 0.5 - (lq0 + f) * (0.5 * h) - self.a0.transpose() * &self.big_lambda - &self.p;
            r.rows_mut(0, n).copy_from(&momentum);
            let constraint = self.stage_one_constraints(&q1, &qm);
            r.rows_mut(n, m).copy_from(&constraint);

            let jac = self.lu.matrix_mut();
            jac.fill(0.0);
            let (mut lvv0, mut lvv1, mut lvq0, mut lvq1) =
                (MatQQ::<M>::zeros(), MatQQ::<M>::zeros(), MatQQ::<M>::zeros(), MatQQ::<M>::zeros());
            let (mut fq, mut fv) = (MatQQ::<M>::zeros(), MatQQ::<M>::zeros());
            self.model.l_vv(t0, &self.q, &self.v, &mut lvv0);
            self.model.l_vv(t1, &q1, &self.v, &mut lvv1);
            self.model.l_vq(t0, &self.q, &self.v, &mut lvq0);
            self.model.l_vq(t1, &q1, &self.v, &mut lvq1);
            self.model.force_dq(tm, &qm, &self.v, &mut fq);
            self.model.force_dv(tm, &qm, &self.v, &mut fv);
            let top = (lvv0 + lvv1 + lvq1 * h) * 0.5 - (lvq0.transpose() + fv + fq * (0.5 * h)) * (0.5 * h);
            jac.view_mut((0, 0), (n, n)).copy_from(&top);
            jac.view_mut((0, n), (n, m)).copy_from(&(-self.a0.transpose()));
            let bottom = Self::stage_one_constraint_jacobian(self.model, &q1, &qm, &self.v, h);
            jac.view_mut((n, 0), (m, n)).copy_from(&bottom);
            if self.newton_update(&mut r, Stage::One)? {
                return Ok(());
            }
        }
        Err(SimError::NewtonDiverged { t: self.t, h, iterations: self.options.max_iterations })
    }

    /// `φ(q_{k+1})/h` for holonomic rows, `A(q_{k+½}) v` for the others.
    fn stage_one_constraints(&self, q1: &VecQ<M>, qm: &VecQ<M>) -> VecC<M> {
        let (m, nh) = (M::NC, M::NH);
        let mut out = VecC::<M>::zeros();
        if m == 0 {
            return out;
        }
        let mut phi = VecH::<M>::zeros();
        self.model.holonomic(q1, &mut phi);
        let mut am = MatCQ::<M>::zeros();
        self.model.constraint_matrix(qm, &mut am);
        let av = am * &self.v;
        for j in 0..m {
            out[j] = if j < nh { phi[j] / self.h } else { av[j] };
        }
        out
    }

    fn stage_one_constraint_jacobian(model: &M, q1: &VecQ<M>, qm: &VecQ<M>, v: &VecQ<M>, h: f64) -> MatCQ<M> {
        let (m, nh) = (M::NC, M::NH);
        let mut out = MatCQ::<M>::zeros();
        if m == 0 {
            return out;
        }
        let (mut a1, mut am, mut gm) = (MatCQ::<M>::zeros(), MatCQ::<M>::zeros(), MatCQ::<M>::zeros());
        model.constraint_matrix(q1, &mut a1);
        model.constraint_matrix(qm, &mut am);
        model.dav_dq(qm, v, &mut gm);
        for j in 0..m {
            for i in 0..M::NQ {
                out[(j, i)] = if j < nh { a1[(j, i)] } else { am[(j, i)] + 0.5 * h * gm[(j, i)] };
            }
        }
        out
    }

    /// Stage 2: the new momenta and velocities, through `(w, Γ)`.
    fn stage_two(&mut self) -> Result<(), SimError> {
        let (n, m, h) = (M::NQ, M::NC, self.h);
        let (t0, t1, tm) = (self.t, self.t + h, self.t + 0.5 * h);
        let q1 = &self.q + &self.v * h;
        let qm = &self.q + &self.v * (0.5 * h);
        let (mut lv0, mut lv1, mut lq1, mut f) =
            (VecQ::<M>::zeros(), VecQ::<M>::zeros(), VecQ::<M>::zeros(), VecQ::<M>::zeros());
        self.model.dl_dv(t0, &self.q, &self.v, &mut lv0);
        self.model.dl_dv(t1, &q1, &self.v, &mut lv1);
        self.model.dl_dq(t1, &q1, &self.v, &mut lq1);
        self.model.force(tm, &qm, &self.v, &mut f);
        let target = (lv0 + lv1) * 0.5 + (lq1 + f) * (0.5 * h);
        let mut a1 = MatCQ::<M>::zeros();
        self.model.constraint_matrix(&q1, &mut a1);
        self.w.copy_from(&self.v);
        let mut r = VecK::<M>::zeros();
        for _ in 0..self.options.max_iterations {
            let mut lv = VecQ::<M>::zeros();
            self.model.dl_dv(t1, &q1, &self.w, &mut lv);
            let momentum = &lv - a1.transpose() * &self.gamma - &target;
            r.rows_mut(0, n).copy_from(&momentum);
            r.rows_mut(n, m).copy_from(&(&a1 * &self.w));
            let mut lvv = MatQQ::<M>::zeros();
            self.model.l_vv(t1, &q1, &self.w, &mut lvv);
            let jac = self.lu.matrix_mut();
            jac.fill(0.0);
            jac.view_mut((0, 0), (n, n)).copy_from(&lvv);
            jac.view_mut((0, n), (n, m)).copy_from(&(-a1.transpose()));
            jac.view_mut((n, 0), (m, n)).copy_from(&a1);
            if self.newton_update(&mut r, Stage::Two)? {
                self.model.dl_dv(t1, &q1, &self.w, &mut self.p);
                return Ok(());
            }
        }
        Err(SimError::NewtonDiverged { t: self.t, h, iterations: self.options.max_iterations })
    }

    /// Factors the Jacobian in `self.lu`, applies the Newton update to the stage's unknowns and
    /// says whether the iteration has converged.
    fn newton_update(&mut self, r: &mut VecK<M>, stage: Stage) -> Result<bool, SimError> {
        let n = M::NQ;
        if let Err(singular) = self.lu.factor() {
            let detail = if singular.column < n {
                format!("no pivot for the velocity `{}`", M::velocity_names()[singular.column])
            } else {
                format!("no pivot for the multiplier `{}`", M::constraint_names()[singular.column - n])
            };
            return Err(SimError::SingularMatrix { t: self.t, h: self.h, detail });
        }
        self.lu.solve(r);
        self.stats.newton_iterations += 1;
        let (x, mult) = match stage {
            Stage::One => (&mut self.v, &mut self.big_lambda),
            Stage::Two => (&mut self.w, &mut self.gamma),
        };
        let mut converged = true;
        for i in 0..n {
            x[i] -= r[i];
            converged &= r[i].abs() <= self.options.tolerance * (1.0 + x[i].abs());
        }
        for j in 0..M::NC {
            mult[j] -= r[n + j];
            converged &= r[n + j].abs() <= self.options.tolerance * (1.0 + mult[j].abs());
        }
        if !r.iter().all(|x| x.is_finite()) {
            return Err(SimError::NonFinite {
                t: self.t,
                component: "a Newton update of the variational step".into(),
            });
        }
        Ok(converged)
    }

    /// Integrates from `state` at `t0` to `t_end` in steps of `h`, recording samples.
    pub fn solve(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
    ) -> Result<Solution<M>, SimError> {
        self.solve_observed(t0, state, t_end, sampling, |_, _| ControlFlow::Continue(()))
    }

    /// [`Variational::solve`] with an observer called after every step with the time and the
    /// state `y = (q, v, p, λ)`; returning `ControlFlow::Break(())` stops early.
    pub fn solve_observed(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
        observer: impl FnMut(f64, &VecY<M>) -> ControlFlow<()>,
    ) -> Result<Solution<M>, SimError> {
        integrate(self, t0, state, t_end, sampling, observer)
    }
}

impl<M: LagrangeDirac> Integrator<M> for Variational<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    fn model(&self) -> &M {
        self.model
    }

    fn begin(&mut self, t0: f64, state: &State<M>, t_end: f64) -> Result<(), SimError> {
        self.start(t0, state, t_end)
    }

    fn advance(&mut self) -> Result<(), SimError> {
        self.step()
    }

    fn done(&self) -> bool {
        self.finished()
    }

    fn statistics(&self) -> Stats {
        Stats { steps: self.stats.steps, newton_iterations: self.stats.newton_iterations, ..Stats::default() }
    }
}

/// A constant, nonsingular mass matrix, ready to solve with: its inverse diagonal when it is
/// diagonal (point masses), its LU factors otherwise.
enum Mass<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    Diagonal(VecQ<M>),
    Dense(Lu<f64, M::Nq>),
}

impl<M: Dimensions> Mass<M>
where
    DefaultAllocator: Storage<M>,
{
    fn new(matrix: &MatQQ<M>) -> Option<Self> {
        let n = M::NQ;
        let diagonal = (0..n).all(|i| (0..n).all(|j| i == j || matrix[(i, j)] == 0.0));
        if diagonal {
            let d = matrix.diagonal();
            return d.iter().all(|x| *x != 0.0 && x.is_finite()).then(|| Mass::Diagonal(d.map(|x| 1.0 / x)));
        }
        let mut lu = Lu::<f64, M::Nq>::new();
        lu.matrix_mut().copy_from(matrix);
        lu.factor().ok().map(|()| Mass::Dense(lu))
    }

    /// `x ← M⁻¹ x`.
    fn solve(&self, x: &mut VecQ<M>) {
        match self {
            Mass::Diagonal(inverse) => x.component_mul_assign(inverse),
            Mass::Dense(lu) => lu.solve(x),
        }
    }
}

#[derive(Clone, Copy)]
enum Stage {
    One,
    Two,
}

impl<M: LagrangeDirac> Stepper<M> for Variational<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    fn t(&self) -> f64 {
        self.t
    }

    fn t_previous(&self) -> f64 {
        self.t - self.h
    }

    fn y(&self) -> &VecY<M> {
        &self.current
    }

    /// Linear interpolation between step points: second order, like the method.
    fn interpolate(&self, t: f64, out: &mut VecY<M>) {
        let s = (t - (self.t - self.h)) / self.h;
        out.copy_from(&(&self.previous * (1.0 - s) + &self.current * s));
    }
}
