//! Radau IIA of order 5 with three stages for the implicit Lagrange-d'Alembert equations
//! `M ẏ = f(t, y)`, `M = diag(I, 0, I, 0)`: simplified Newton on the real and complex
//! transformed stage systems, condensed linear algebra, Jacobian reuse across steps, an error
//! estimate scaled for the index-2 multipliers, predictive step-size control and dense output.
//!
//! The algorithm follows Hairer & Wanner's RADAU5 (*Solving Ordinary Differential Equations
//! II*, §IV.8), including its transformation of tolerances (`rtol → 0.1 rtol^(2/3)`) so that
//! the achieved error follows the requested one. A step allocates nothing: every vector and
//! matrix lives in the integrator, on the stack sizes the model fixes.

mod tableau;

use std::ops::ControlFlow;

use nalgebra::{Complex, DefaultAllocator};

use self::tableau::{C1, C2, C3, DD1, DD2, DD3, Eigen, T, TI, eigen};
use crate::dims::{Storage, VecC, VecQ, VecY};
use crate::error::SimError;
use crate::lu::Singular;
use crate::model::{JacobianBlocks, LagrangeDirac};
use crate::newton::{Condensed, NewtonSolver};
use crate::solution::{Integrator, Sampling, Solution, integrate};
use crate::state::State;

/// Tolerances and limits of a Radau integration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Relative tolerance (default `1e-6`).
    pub rtol: f64,
    /// Absolute tolerance (default `1e-8`).
    pub atol: f64,
    /// The first step size; by default `1e-6` of the time span.
    pub initial_step: Option<f64>,
    /// The largest step size (default: unbounded).
    pub max_step: f64,
    /// The most steps, accepted and rejected, before giving up (default `1_000_000`).
    pub max_steps: usize,
    /// Newton iterations per step attempt (default 7).
    pub max_newton_iterations: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            rtol: 1e-6,
            atol: 1e-8,
            initial_step: None,
            max_step: f64::INFINITY,
            max_steps: 1_000_000,
            max_newton_iterations: 7,
        }
    }
}

impl Options {
    /// The default options with relative and absolute tolerances `rtol` and `atol`.
    pub fn tolerances(rtol: f64, atol: f64) -> Options {
        Options { rtol, atol, ..Options::default() }
    }

    fn validate(&self) -> Result<(), SimError> {
        for (what, value) in [("rtol", self.rtol), ("atol", self.atol)] {
            if value.is_nan() || value <= 0.0 || value.is_infinite() {
                return Err(SimError::InvalidTolerance { what, value });
            }
        }
        if self.max_step.is_nan() || self.max_step <= 0.0 {
            return Err(SimError::InvalidOption {
                what: "max_step",
                reason: format!("{} is not positive", self.max_step),
            });
        }
        if let Some(h) = self.initial_step
            && (h.is_nan() || h <= 0.0 || h.is_infinite())
        {
            return Err(SimError::InvalidOption {
                what: "initial_step",
                reason: format!("{h} is not positive"),
            });
        }
        if self.max_newton_iterations < 2 {
            return Err(SimError::InvalidOption {
                what: "max_newton_iterations",
                reason: "at least 2".into(),
            });
        }
        Ok(())
    }
}

/// Counters of the work an integration did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected step attempts (error too large, Newton failure, singular matrix).
    pub rejected: usize,
    /// Evaluations of the residual `f(t, y)`.
    pub residual_evaluations: usize,
    /// Evaluations of the Jacobian blocks.
    pub jacobian_evaluations: usize,
    /// LU factorisations (each a real and a complex one).
    pub factorizations: usize,
    /// Newton iterations.
    pub newton_iterations: usize,
}

/// How a Newton iteration ended.
enum Newton {
    Converged(usize),
    /// Retry with the step multiplied by this factor, for this reason.
    Shrink(f64, &'static str),
}

/// The Radau IIA integrator for a model `M`, with the Newton solver `S`.
pub struct Radau<'m, M: LagrangeDirac, S: NewtonSolver<M> = Condensed<M>>
where
    DefaultAllocator: Storage<M>,
{
    model: &'m M,
    solver: S,
    options: Options,
    eig: Eigen,
    rtol: f64,
    atol: VecY<M>,
    fnewt: f64,
    t: f64,
    t_end: f64,
    h: f64,
    h_old: f64,
    y: VecY<M>,
    f0: VecY<M>,
    scal: VecY<M>,
    z: [VecY<M>; 3],
    w: [VecY<M>; 3],
    f: [VecY<M>; 3],
    tmp: VecY<M>,
    cont: [VecY<M>; 3],
    jac: JacobianBlocks<M>,
    jac_current: bool,
    need_jac: bool,
    need_factor: bool,
    factored_h: f64,
    first: bool,
    last_rejected: bool,
    faccon: f64,
    theta: f64,
    h_acc: f64,
    err_acc: f64,
    stats: Stats,
}

const SAFE: f64 = 0.9;
const FACL: f64 = 5.0;
const FACR: f64 = 0.125;
const THET: f64 = 0.001;

impl<'m, M: LagrangeDirac> Radau<'m, M>
where
    DefaultAllocator: Storage<M>,
{
    /// An integrator for `model` with the condensed Newton solver.
    pub fn new(model: &'m M, options: Options) -> Result<Self, SimError> {
        Self::with_solver(model, options, Condensed::default())
    }
}

impl<'m, M: LagrangeDirac, S: NewtonSolver<M>> Radau<'m, M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// An integrator for `model` that solves its linear systems with `solver`.
    pub fn with_solver(model: &'m M, options: Options, solver: S) -> Result<Self, SimError> {
        options.validate()?;
        // Hairer's transformation: an rtol of 1e-6 asks the estimator for 1e-5 locally.
        let rtol = 0.1 * options.rtol.powf(2.0 / 3.0);
        let atol = rtol * options.atol / options.rtol;
        let fnewt = (10.0 * f64::EPSILON / rtol).max(0.03f64.min(rtol.sqrt()));
        let zero = VecY::<M>::zeros;
        Ok(Radau {
            model,
            solver,
            options,
            eig: eigen(),
            rtol,
            atol: VecY::<M>::repeat(atol),
            fnewt,
            t: 0.0,
            t_end: 0.0,
            h: 0.0,
            h_old: 0.0,
            y: zero(),
            f0: zero(),
            scal: zero(),
            z: [zero(), zero(), zero()],
            w: [zero(), zero(), zero()],
            f: [zero(), zero(), zero()],
            tmp: zero(),
            cont: [zero(), zero(), zero()],
            jac: JacobianBlocks::zeros(),
            jac_current: false,
            need_jac: true,
            need_factor: true,
            factored_h: 0.0,
            first: true,
            last_rejected: false,
            faccon: 1.0,
            theta: 1.0,
            h_acc: 0.0,
            err_acc: 0.0,
            stats: Stats::default(),
        })
    }

    /// Sets one absolute tolerance per component of `y = (q, v, p, λ)`, replacing
    /// [`Options::atol`] (for example, a looser one for multipliers of large magnitude).
    pub fn set_absolute_tolerances(&mut self, atol: &VecY<M>) -> Result<(), SimError> {
        if let Some(&value) = atol.iter().find(|a| a.is_nan() || **a <= 0.0 || a.is_infinite()) {
            return Err(SimError::InvalidTolerance { what: "atol", value });
        }
        let factor = 0.1 * self.options.rtol.powf(2.0 / 3.0) / self.options.rtol;
        self.atol = atol * factor;
        Ok(())
    }

    /// The current time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// The current state as a flat vector `y = (q, v, p, λ)`.
    pub fn y(&self) -> &VecY<M> {
        &self.y
    }

    /// The work done so far.
    pub fn stats(&self) -> Stats {
        Stats { factorizations: self.solver.factorizations(), ..self.stats }
    }

    /// Whether the end time has been reached.
    pub fn finished(&self) -> bool {
        self.t >= self.t_end
    }

    /// Prepares to integrate from `state` at `t0` to `t_end`. The state should be consistent
    /// (see [`crate::init::consistent_state`]).
    pub fn start(&mut self, t0: f64, state: &State<M>, t_end: f64) -> Result<(), SimError> {
        if !t0.is_finite() || !t_end.is_finite() || t_end <= t0 {
            return Err(SimError::InvalidTimeSpan {
                reason: format!("from {t0} to {t_end}: need finite t0 < t_end"),
            });
        }
        state.write_y(&mut self.y);
        self.t = t0;
        self.t_end = t_end;
        let span = t_end - t0;
        self.h = self.options.initial_step.unwrap_or(1e-6 * span).min(span).min(self.options.max_step);
        self.first = true;
        self.last_rejected = false;
        self.need_jac = true;
        self.need_factor = true;
        self.faccon = 1.0;
        self.theta = 1.0;
        self.stats = Stats::default();
        self.model.residual(t0, &self.y, &mut self.f0);
        self.stats.residual_evaluations += 1;
        self.check_finite(t0, Which::F0)?;
        Ok(())
    }

    /// Takes one accepted step (retrying with smaller steps as needed) and returns its size.
    pub fn step(&mut self) -> Result<f64, SimError> {
        let mut singular = 0;
        let mut reason = "";
        loop {
            if self.stats.steps + self.stats.rejected >= self.options.max_steps {
                return Err(SimError::TooManySteps {
                    max_steps: self.options.max_steps,
                    t: self.t,
                    t_end: self.t_end,
                });
            }
            if self.t + self.h >= self.t_end - 1e-12 * self.h {
                self.h = self.t_end - self.t;
            }
            if self.h <= 16.0 * f64::EPSILON * self.t.abs().max(1.0) {
                return Err(SimError::StepSizeTooSmall { t: self.t, h: self.h, reason: reason.to_owned() });
            }
            self.prepare_scale();
            if self.need_jac {
                self.evaluate_jacobian();
            }
            if (self.need_factor || self.h != self.factored_h)
                && let Err(Singular { column }) = self.factor()
            {
                singular += 1;
                if singular >= 6 {
                    return Err(SimError::SingularMatrix {
                        t: self.t,
                        h: self.h,
                        detail: self.unknown_name(column),
                    });
                }
                self.reject(0.5, "singular iteration matrix");
                reason = "singular iteration matrix";
                continue;
            }
            match self.newton() {
                Newton::Shrink(factor, why) => {
                    reason = why;
                    if self.h * factor <= 16.0 * f64::EPSILON * self.t.abs().max(1.0) {
                        if why.starts_with("non-finite") {
                            return Err(self.non_finite_error());
                        }
                        return Err(SimError::NewtonDiverged {
                            t: self.t,
                            h: self.h,
                            iterations: self.options.max_newton_iterations,
                        });
                    }
                    self.reject(factor, why);
                    if !self.jac_current {
                        self.need_jac = true;
                    }
                }
                Newton::Converged(iterations) => {
                    let err = self.error_estimate();
                    let fac = SAFE.min(
                        (1.0 + 2.0 * self.options.max_newton_iterations as f64) * SAFE
                            / (iterations as f64 + 2.0 * self.options.max_newton_iterations as f64),
                    );
                    let quot = FACR.max(FACL.min(err.powf(0.25) / fac));
                    if err < 1.0 {
                        return self.accept(err, quot);
                    }
                    reason = "error estimate too large";
                    let factor = if self.first { 0.1 } else { 1.0 / quot };
                    self.reject(factor, reason);
                }
            }
        }
    }

    fn reject(&mut self, factor: f64, _why: &str) {
        self.h *= factor;
        self.stats.rejected += 1;
        self.last_rejected = true;
        self.need_factor = true;
    }

    fn prepare_scale(&mut self) {
        let n = M::NQ;
        for (i, s) in self.scal.iter_mut().enumerate() {
            *s = self.atol[i] + self.rtol * self.y[i].abs();
            // Multipliers are index-2 variables: their error estimate is one order worse.
            if i >= 3 * n {
                *s /= self.h;
            }
        }
    }

    fn evaluate_jacobian(&mut self) {
        let n = M::NQ;
        let mut q = VecQ::<M>::zeros();
        let mut v = VecQ::<M>::zeros();
        let mut lambda = VecC::<M>::zeros();
        q.copy_from(&self.y.rows(0, n));
        v.copy_from(&self.y.rows(n, n));
        lambda.copy_from(&self.y.rows(3 * n, M::NC));
        self.model.jacobian_blocks(self.t, &q, &v, &lambda, &mut self.jac);
        self.stats.jacobian_evaluations += 1;
        self.need_jac = false;
        self.jac_current = true;
        self.need_factor = true;
    }

    fn factor(&mut self) -> Result<(), Singular> {
        let e = &self.eig;
        let sigma = e.gamma / self.h;
        let sigma_c = Complex::new(e.alpha, e.beta) / self.h;
        let result = self.solver.factor(&self.jac, sigma, sigma_c);
        self.factored_h = self.h;
        self.need_factor = result.is_err();
        result
    }

    /// `out ← M x` for `M = diag(I, 0, I, 0)`.
    fn zero_algebraic(x: &mut VecY<M>) {
        let n = M::NQ;
        for i in n..2 * n {
            x[i] = 0.0;
        }
        for i in 3 * n..x.len() {
            x[i] = 0.0;
        }
    }

    fn norm(&self, x: &VecY<M>) -> f64 {
        let sum: f64 = x.iter().zip(self.scal.iter()).map(|(a, s)| (a / s) * (a / s)).sum();
        (sum / x.len() as f64).sqrt()
    }

    fn newton(&mut self) -> Newton {
        let h = self.h;
        let c = [C1, C2, C3];
        if self.first {
            for k in 0..3 {
                self.z[k].fill(0.0);
                self.w[k].fill(0.0);
            }
        } else {
            // Extrapolate the previous step's collocation polynomial to the new nodes.
            let (s1, s2) = (C1 - 1.0, C2 - 1.0);
            for (zk, &ck) in self.z.iter_mut().zip(&c) {
                let s = ck * h / self.h_old;
                let d = &self.cont;
                for i in 0..zk.len() {
                    zk[i] = s * (d[0][i] + (s - s2) * (d[1][i] + (s - s1) * d[2][i]));
                }
            }
            self.transform_to_w();
        }
        let mut faccon = self.faccon.max(f64::EPSILON).powf(0.8);
        let mut theta = self.theta.abs();
        let (mut dyno_old, mut thq_old) = (1.0, 1.0);
        let max_newton = self.options.max_newton_iterations;
        let (gamma, alpha, beta) = (self.eig.gamma / h, self.eig.alpha / h, self.eig.beta / h);
        for newt in 0..max_newton {
            for ((zk, fk), ck) in self.z.iter().zip(self.f.iter_mut()).zip(c) {
                self.tmp.copy_from(&self.y);
                self.tmp += zk;
                self.model.residual(self.t + ck * h, &self.tmp, fk);
                self.stats.residual_evaluations += 1;
                if !fk.iter().all(|x| x.is_finite()) {
                    return Newton::Shrink(0.5, "non-finite residual");
                }
            }
            // Transformed residuals r_k = (T⁻¹ f)_k − (Λ/h ⊗ M) w, solved in place.
            let mut r = [VecY::<M>::zeros(), VecY::<M>::zeros(), VecY::<M>::zeros()];
            for (k, rk) in r.iter_mut().enumerate() {
                for i in 0..rk.len() {
                    rk[i] = TI[k][0] * self.f[0][i] + TI[k][1] * self.f[1][i] + TI[k][2] * self.f[2][i];
                }
            }
            let n = M::NQ;
            for i in (0..n).chain(2 * n..3 * n) {
                let (w1, w2, w3) = (self.w[0][i], self.w[1][i], self.w[2][i]);
                r[0][i] -= gamma * w1;
                r[1][i] -= alpha * w2 - beta * w3;
                r[2][i] -= beta * w2 + alpha * w3;
            }
            let [r1, r2, r3] = &mut r;
            self.solver.solve(r1);
            self.solver.solve_complex(r2, r3);
            self.stats.newton_iterations += 1;
            let dyno = {
                let sum: f64 = r.iter().map(|rk| self.norm(rk).powi(2)).sum();
                (sum / 3.0).sqrt()
            };
            if newt >= 1 {
                let thq = dyno / dyno_old;
                theta = if newt == 1 { thq } else { (thq * thq_old).sqrt() };
                thq_old = thq;
                if theta < 0.99 {
                    faccon = theta / (1.0 - theta);
                    let remaining = (max_newton - 1 - newt) as i32;
                    let dyth = faccon * dyno * theta.powi(remaining) / self.fnewt;
                    if dyth >= 1.0 {
                        let qnewt = dyth.clamp(1e-4, 20.0);
                        return Newton::Shrink(
                            0.8 * qnewt.powf(-1.0 / (4.0 + remaining as f64)),
                            "Newton converging too slowly",
                        );
                    }
                } else {
                    return Newton::Shrink(0.5, "Newton iteration diverging");
                }
            }
            dyno_old = dyno.max(f64::EPSILON);
            for (wk, rk) in self.w.iter_mut().zip(&r) {
                *wk += rk;
            }
            self.transform_to_z();
            if faccon * dyno <= self.fnewt {
                self.faccon = faccon;
                self.theta = theta;
                return Newton::Converged(newt + 1);
            }
        }
        Newton::Shrink(0.5, "Newton iteration did not converge")
    }

    fn transform_to_z(&mut self) {
        for i in 0..self.y.len() {
            let (w1, w2, w3) = (self.w[0][i], self.w[1][i], self.w[2][i]);
            for (zk, tk) in self.z.iter_mut().zip(&T) {
                zk[i] = tk[0] * w1 + tk[1] * w2 + tk[2] * w3;
            }
        }
    }

    fn transform_to_w(&mut self) {
        for i in 0..self.y.len() {
            let (z1, z2, z3) = (self.z[0][i], self.z[1][i], self.z[2][i]);
            for (wk, tk) in self.w.iter_mut().zip(&TI) {
                wk[i] = tk[0] * z1 + tk[1] * z2 + tk[2] * z3;
            }
        }
    }

    /// Hairer's embedded estimate `(γ/h M − J)⁻¹ (f(t, y) + M Σ e_i Z_i)`, refined once with a
    /// fresh residual after a rejection.
    fn error_estimate(&mut self) -> f64 {
        let h = self.h;
        let mut f2 = VecY::<M>::zeros();
        for i in 0..f2.len() {
            f2[i] = (DD1 * self.z[0][i] + DD2 * self.z[1][i] + DD3 * self.z[2][i]) / h;
        }
        Self::zero_algebraic(&mut f2);
        // The algebraic rows of f(t_n, y_n) vanish up to the Newton tolerance of the step that
        // produced y_n: that remainder is not truncation error, and through the index-2
        // multipliers' scaling it would keep the estimate above 1 however small the step,
        // whenever a multiplier crosses zero. They are left out, as in exact arithmetic.
        let mut e = self.f0.clone();
        Self::zero_algebraic(&mut e);
        e += &f2;
        self.solver.solve(&mut e);
        let mut err = self.norm(&e).max(1e-10);
        if err >= 1.0 && (self.first || self.last_rejected) {
            self.tmp.copy_from(&self.y);
            self.tmp += &e;
            self.model.residual(self.t, &self.tmp, &mut e);
            self.stats.residual_evaluations += 1;
            // As above: measure the algebraic rows from the state's own remainder.
            let n = M::NQ;
            for i in (n..2 * n).chain(3 * n..e.len()) {
                e[i] -= self.f0[i];
            }
            e += &f2;
            self.solver.solve(&mut e);
            err = self.norm(&e).max(1e-10);
        }
        if err.is_finite() { err } else { 1e10 }
    }

    fn accept(&mut self, err: f64, mut quot: f64) -> Result<f64, SimError> {
        let h = self.h;
        if self.stats.steps > 0 {
            let facgus = ((self.h_acc / h) * (err * err / self.err_acc).powf(0.25) / SAFE).clamp(FACR, FACL);
            quot = quot.max(facgus);
        }
        self.h_acc = h;
        self.err_acc = err.max(1e-2);
        // Dense output: Newton divided differences of the collocation polynomial at s = c − 1.
        let (c1m1, c2m1, c1mc2) = (C1 - 1.0, C2 - 1.0, C1 - C2);
        for i in 0..self.y.len() {
            let (z1, z2, z3) = (self.z[0][i], self.z[1][i], self.z[2][i]);
            let d1 = (z2 - z3) / c2m1;
            let ak = (z1 - z2) / c1mc2;
            let acont3 = (ak - z1 / C1) / C2;
            let d2 = (ak - d1) / c1m1;
            self.cont[0][i] = d1;
            self.cont[1][i] = d2;
            self.cont[2][i] = d2 - acont3;
        }
        self.y += &self.z[2];
        self.t += h;
        self.h_old = h;
        self.stats.steps += 1;
        self.model.residual(self.t, &self.y, &mut self.f0);
        self.stats.residual_evaluations += 1;
        self.check_finite(self.t, Which::Y)?;
        self.check_finite(self.t, Which::F0)?;
        let mut h_new = (h / quot).min(self.options.max_step);
        if self.last_rejected {
            h_new = h_new.min(h);
        }
        self.first = false;
        self.last_rejected = false;
        self.jac_current = false;
        self.need_jac = self.theta > THET;
        let ratio = h_new / h;
        if self.need_jac || !(1.0..=1.2).contains(&ratio) {
            self.h = h_new;
            self.need_factor = true;
        }
        Ok(h)
    }

    /// Evaluates the last step's collocation polynomial at `t` (between the step's ends).
    pub fn interpolate(&self, t: f64, out: &mut VecY<M>) {
        let s = (t - self.t) / self.h_old;
        let (s1, s2) = (C1 - 1.0, C2 - 1.0);
        let d = &self.cont;
        for i in 0..out.len() {
            out[i] = self.y[i] + s * (d[0][i] + (s - s2) * (d[1][i] + (s - s1) * d[2][i]));
        }
    }

    fn check_finite(&self, t: f64, which: Which) -> Result<(), SimError> {
        let x = match which {
            Which::Y => &self.y,
            Which::F0 => &self.f0,
        };
        match x.iter().position(|v| !v.is_finite()) {
            None => Ok(()),
            Some(i) => {
                let what = match which {
                    Which::Y => self.unknown_slot(i),
                    Which::F0 => format!("the equation of {}", self.unknown_slot(i)),
                };
                Err(SimError::NonFinite { t, component: what })
            }
        }
    }

    fn non_finite_error(&self) -> SimError {
        let i = self.f.iter().find_map(|f| f.iter().position(|v| !v.is_finite())).unwrap_or(0);
        SimError::NonFinite { t: self.t, component: format!("the equation of {}", self.unknown_slot(i)) }
    }

    /// The name of slot `i` of `y = (q, v, p, λ)`.
    fn unknown_slot(&self, i: usize) -> String {
        let n = M::NQ;
        match i / n.max(1) {
            _ if i >= 3 * n => format!("multiplier `{}`", M::constraint_names()[i - 3 * n]),
            0 => format!("coordinate `{}`", M::coordinate_names()[i]),
            1 => format!("velocity `{}`", M::velocity_names()[i - n]),
            _ => format!("momentum of `{}`", M::coordinate_names()[i - 2 * n]),
        }
    }

    /// The unknown of the condensed system `(Δv, Δλ)` at `column`.
    fn unknown_name(&self, column: usize) -> String {
        let n = M::NQ;
        if column < n {
            format!("no pivot for the velocity `{}`", M::velocity_names()[column])
        } else {
            format!("no pivot for the multiplier `{}`", M::constraint_names()[column - n])
        }
    }

    /// Integrates from `state` at `t0` to `t_end`, recording samples as `sampling` says.
    pub fn solve(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
    ) -> Result<Solution<M>, SimError> {
        self.solve_observed(t0, state, t_end, sampling, |_, _| ControlFlow::Continue(()))
    }

    /// [`Radau::solve`] with an observer called after every accepted step with the time and
    /// the state; returning `ControlFlow::Break(())` stops the integration early.
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

impl<M: LagrangeDirac, S: NewtonSolver<M>> Integrator<M> for Radau<'_, M, S>
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
        self.step().map(|_| ())
    }

    fn done(&self) -> bool {
        self.finished()
    }

    fn statistics(&self) -> Stats {
        self.stats()
    }
}

#[derive(Clone, Copy)]
enum Which {
    Y,
    F0,
}

impl<M: LagrangeDirac, S: NewtonSolver<M>> crate::solution::Stepper<M> for Radau<'_, M, S>
where
    DefaultAllocator: Storage<M>,
{
    fn t(&self) -> f64 {
        self.t
    }

    fn t_previous(&self) -> f64 {
        self.t - self.h_old
    }

    fn y(&self) -> &VecY<M> {
        &self.y
    }

    fn interpolate(&self, t: f64, out: &mut VecY<M>) {
        Radau::interpolate(self, t, out);
    }
}
