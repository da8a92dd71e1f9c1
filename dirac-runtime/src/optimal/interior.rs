//! A primal-dual interior point in pure Rust for the programs of this module: equations
//! `g(x) = g_l` and bounds `x_l ≤ x ≤ x_u`, the algorithm of IPOPT (Wächter and Biegler
//! 2006) in its essentials, on a banded factorisation of the KKT matrix.
//!
//! - The barrier `μ` falls monotonically (Fiacco-McCormick): once the barrier problem is
//!   solved to `κ_ε μ`, `μ ← max(ε/10, min(κ_μ μ, μ^θ_μ))`.
//! - Steps solve `[W + Σ + δ_w I, Jᵀ; J, −δ_c I] (Δx, Δλ) = −(∇φ + Jᵀλ, g)`, with `δ_w`
//!   raised until the inertia is `(n, m, 0)`: the step is then a descent direction of the
//!   barrier problem on the equations' null space.
//! - A filter line search (with one second-order correction against the Maratos effect)
//!   accepts a step that reduces the infeasibility or the barrier function, with the
//!   fraction-to-the-boundary rule keeping the bounds strictly satisfied.
//! - Fixed variables (`x_l = x_u`) are parameters: their rows are the identity.
//! - The KKT matrix is ordered once, when the solver is made (reverse Cuthill-McKee on the
//!   variables, each equation right after the last of its variables), into a band whose width
//!   does not grow with the number of intervals, and factored as `L D Lᵀ` without pivoting;
//!   the inertia is read from `D`.
//!
//! What it leaves out: IPOPT's feasibility restoration phase (a line search that cannot find a
//! step ends with the status `Line_Search_Failed`), inequality constraints `g_l < g_u`, and the
//! problem's automatic scaling. Its advantage is no set-up per solve (the KKT's order and
//! band are fixed when the solver is made), a factorisation whose cost grows linearly with the
//! number of intervals, warm starts from the last solution, and no allocation while solving.

use std::time::{Duration, Instant};

use crate::optimal::band::{Banded, Inertia};
use crate::optimal::nlp::Nlp;

/// The interior point's settings.
#[derive(Clone, Debug)]
pub struct InteriorOptions {
    /// The tolerance on the scaled optimality error (IPOPT's `tol`), `1e-8` by default.
    pub tolerance: f64,
    /// The most iterations before `Maximum_Iterations_Exceeded`, 500 by default.
    pub max_iterations: usize,
    /// The barrier parameter a cold start begins with (IPOPT's `mu_init`), `0.1` by default.
    pub barrier: f64,
    /// The barrier parameter a warm start begins with, `1e-6` by default: small, since the
    /// last solution's bound multipliers are already nearly complementary.
    pub warm_barrier: f64,
}

impl Default for InteriorOptions {
    fn default() -> Self {
        InteriorOptions { tolerance: 1e-8, max_iterations: 500, barrier: 0.1, warm_barrier: 1e-6 }
    }
}

/// What a solve returned.
#[derive(Clone, Debug)]
pub struct InteriorResult {
    /// `Solve_Succeeded`, `Maximum_Iterations_Exceeded`, `Line_Search_Failed`,
    /// `Error_In_Step_Computation` (no regularisation made the step's matrix usable),
    /// `Invalid_Number_Detected` (the program is not finite at the start) or `Invalid_Option`
    /// (a tolerance or barrier that is not a finite positive number; nothing is evaluated).
    pub status: &'static str,
    /// Whether the status is a solution.
    pub solved: bool,
    /// The objective at the last point.
    pub objective: f64,
    /// The largest violation of the equations there.
    pub violation: f64,
    /// The steps taken.
    pub iterations: usize,
    /// Wall time of the solve.
    pub wall: Duration,
}

// IPOPT's constants (Wächter and Biegler 2006, table 1, and IPOPT's defaults).
const KAPPA_EPSILON: f64 = 10.0;
const KAPPA_MU: f64 = 0.2;
const THETA_MU: f64 = 1.5;
const TAU_MIN: f64 = 0.99;
const KAPPA_SIGMA: f64 = 1e10;
const GAMMA_THETA: f64 = 1e-5;
const GAMMA_PHI: f64 = 1e-8;
const DELTA: f64 = 1.0;
const S_THETA: f64 = 1.1;
const S_PHI: f64 = 2.3;
const ETA_PHI: f64 = 1e-4;
const S_MAX: f64 = 100.0;
const BOUND_PUSH: f64 = 1e-2;
const DELTA_W_FIRST: f64 = 1e-4;
const DELTA_W_MIN: f64 = 1e-20;
const DELTA_W_MAX: f64 = 1e40;

/// The solver and its work space, sized for one program's patterns: made once, solving that
/// program (or one with the same patterns, as a receding horizon's) as often as asked.
pub struct InteriorPoint {
    n: usize,
    m: usize,
    band: Banded,
    hessian_slots: Vec<usize>,
    jacobian_slots: Vec<usize>,
    diagonal_slots: Vec<usize>,
    hessian_pattern: Vec<(usize, usize)>,
    jacobian_pattern: Vec<(usize, usize)>,
    lower: Vec<f64>,
    upper: Vec<f64>,
    target: Vec<f64>,
    fixed: Vec<bool>,
    x: Vec<f64>,
    lambda: Vec<f64>,
    zl: Vec<f64>,
    zu: Vec<f64>,
    trial: Vec<f64>,
    gradient: Vec<f64>,
    g: Vec<f64>,
    g_trial: Vec<f64>,
    jacobian: Vec<f64>,
    hessian: Vec<f64>,
    rhs: Vec<f64>,
    step: Vec<f64>,
    residual: Vec<f64>,
    dzl: Vec<f64>,
    dzu: Vec<f64>,
    filter: Vec<(f64, f64)>,
    last_delta_w: f64,
    started: bool,
}

/// The barrier problem's measures at a point.
#[derive(Clone, Copy)]
struct Measures {
    theta: f64,
    phi: f64,
}

impl InteriorPoint {
    /// The solver for `nlp`'s patterns, or why it cannot solve it (inequality constraints).
    pub fn new(nlp: &dyn Nlp) -> Result<Self, &'static str> {
        let (n, m) = (nlp.variables(), nlp.constraints());
        let (mut gl, mut gu) = (vec![0.0; m], vec![0.0; m]);
        nlp.constraint_bounds(&mut gl, &mut gu);
        if gl.iter().zip(&gu).any(|(l, u)| l != u) {
            return Err("the interior point takes equations only (equal constraint bounds)");
        }
        let hessian_pattern = nlp.hessian_pattern().to_vec();
        let jacobian_pattern = nlp.jacobian_pattern().to_vec();
        let band = Banded::new(n, m, &hessian_pattern, &jacobian_pattern);
        let hessian_slots = hessian_pattern.iter().map(|&(r, c)| band.slot(r, c)).collect();
        let jacobian_slots = jacobian_pattern.iter().map(|&(r, c)| band.slot(n + r, c)).collect();
        let diagonal_slots = (0..n + m).map(|k| band.slot(k, k)).collect();
        Ok(InteriorPoint {
            n,
            m,
            band,
            hessian_slots,
            jacobian_slots,
            diagonal_slots,
            lower: vec![0.0; n],
            upper: vec![0.0; n],
            target: gl,
            fixed: vec![false; n],
            x: vec![0.0; n],
            lambda: vec![0.0; m],
            zl: vec![0.0; n],
            zu: vec![0.0; n],
            trial: vec![0.0; n],
            gradient: vec![0.0; n],
            g: vec![0.0; m],
            g_trial: vec![0.0; m],
            jacobian: vec![0.0; jacobian_pattern.len()],
            hessian: vec![0.0; hessian_pattern.len()],
            rhs: vec![0.0; n + m],
            step: vec![0.0; n + m],
            residual: vec![0.0; n + m],
            dzl: vec![0.0; n],
            dzu: vec![0.0; n],
            filter: Vec::with_capacity(1024),
            hessian_pattern,
            jacobian_pattern,
            last_delta_w: 0.0,
            started: false,
        })
    }

    /// The half bandwidth of the KKT matrix in its elimination order.
    pub fn bandwidth(&self) -> usize {
        self.band.width
    }

    /// The last point (the solution after a successful solve).
    pub fn point(&self) -> &[f64] {
        &self.x
    }

    /// The equations' multipliers at the last point.
    pub fn multipliers(&self) -> &[f64] {
        &self.lambda
    }

    /// The last point and multipliers, to be moved before a warm start (a receding horizon
    /// shifts them by one interval).
    pub fn point_mut(&mut self) -> (&mut [f64], &mut [f64]) {
        (&mut self.x, &mut self.lambda)
    }

    /// Solves from `nlp`'s starting point.
    pub fn solve(&mut self, nlp: &mut dyn Nlp, options: &InteriorOptions) -> InteriorResult {
        nlp.starting_point(&mut self.x);
        self.lambda.fill(0.0);
        self.zl.fill(1.0);
        self.zu.fill(1.0);
        self.last_delta_w = 0.0;
        self.run(nlp, options, options.barrier, true)
    }

    /// Solves from the last point and multipliers (bound multipliers included), as
    /// [`point_mut`](Self::point_mut) left them; a cold [`solve`](Self::solve) if there was none.
    pub fn resolve(&mut self, nlp: &mut dyn Nlp, options: &InteriorOptions) -> InteriorResult {
        if !self.started {
            return self.solve(nlp, options);
        }
        self.run(nlp, options, options.warm_barrier.max(options.tolerance / 10.0), false)
    }

    fn run(
        &mut self,
        nlp: &mut dyn Nlp,
        options: &InteriorOptions,
        barrier: f64,
        cold: bool,
    ) -> InteriorResult {
        let started = Instant::now();
        let positive = |x: f64| x.is_finite() && x > 0.0;
        if !(positive(options.tolerance) && positive(barrier)) {
            return self.finish("Invalid_Option", false, f64::NAN, 0, started);
        }
        self.started = true;
        nlp.variable_bounds(&mut self.lower, &mut self.upper);
        let mut gu = std::mem::take(&mut self.g_trial);
        nlp.constraint_bounds(&mut self.target, &mut gu);
        self.g_trial = gu;
        self.place_inside();
        let mut mu = barrier;
        let tolerance = options.tolerance;
        self.filter.clear();
        let mut iterations = 0;
        let mut objective = self.evaluate(nlp);
        let theta0 = self.theta(&self.g);
        if !objective.is_finite() || !theta0.is_finite() {
            return self.finish("Invalid_Number_Detected", false, objective, iterations, started);
        }
        if cold {
            self.least_squares_multipliers();
        }
        let theta_min = 1e-4 * theta0.max(1.0);
        let theta_max = 1e4 * theta0.max(1.0);
        loop {
            if self.error(0.0) <= tolerance {
                return self.finish("Solve_Succeeded", true, objective, iterations, started);
            }
            while self.error(mu) <= KAPPA_EPSILON * mu && mu > tolerance / 10.0 {
                mu = (tolerance / 10.0).max((KAPPA_MU * mu).min(mu.powf(THETA_MU)));
                self.filter.clear();
            }
            if iterations >= options.max_iterations {
                return self.finish("Maximum_Iterations_Exceeded", false, objective, iterations, started);
            }
            nlp.hessian_values(&self.x, 1.0, &self.lambda, &mut self.hessian);
            if !self.factor(mu) {
                return self.finish("Error_In_Step_Computation", false, objective, iterations, started);
            }
            self.barrier_rhs(mu);
            for r in 0..self.m {
                self.rhs[self.n + r] = -self.g[r];
            }
            self.solve_step();
            let tau = TAU_MIN.max(1.0 - mu);
            let alpha_max = self.boundary_step(&self.step[..self.n], tau);
            let here = Measures { theta: self.theta(&self.g), phi: self.phi(objective, &self.x, mu) };
            let slope = self.barrier_slope(mu);
            let tiny =
                (0..self.n).all(|i| self.step[i].abs() <= 10.0 * f64::EPSILON * (1.0 + self.x[i].abs()));
            let mut alpha = alpha_max;
            let mut accepted = None;
            let mut corrected = false;
            while alpha > 1e-14 {
                self.take(alpha);
                let f = nlp.objective(&self.trial);
                nlp.constraint_values(&self.trial, &mut self.g_trial);
                for (g, t) in self.g_trial.iter_mut().zip(&self.target) {
                    *g -= t;
                }
                let trial = Measures { theta: self.theta(&self.g_trial), phi: self.phi(f, &self.trial, mu) };
                if tiny {
                    accepted = Some((f, false));
                    break;
                }
                if let Some(kind) = self.acceptable(here, trial, alpha, slope, theta_min, theta_max) {
                    accepted = Some((f, kind));
                    break;
                }
                if !corrected && alpha == alpha_max && trial.theta >= here.theta && trial.theta.is_finite() {
                    corrected = true;
                    // The second-order correction: the same matrix, the equations' right-hand
                    // side corrected by their value at the trial point.
                    for r in 0..self.m {
                        self.rhs[self.n + r] = -(alpha * self.g[r] + self.g_trial[r]);
                    }
                    self.barrier_rhs(mu);
                    let saved: f64 = alpha;
                    self.solve_step();
                    let alpha_soc = self.boundary_step(&self.step[..self.n], tau);
                    self.take(alpha_soc);
                    let f = nlp.objective(&self.trial);
                    nlp.constraint_values(&self.trial, &mut self.g_trial);
                    for (g, t) in self.g_trial.iter_mut().zip(&self.target) {
                        *g -= t;
                    }
                    let soc =
                        Measures { theta: self.theta(&self.g_trial), phi: self.phi(f, &self.trial, mu) };
                    if let Some(kind) = self.acceptable(here, soc, saved, slope, theta_min, theta_max) {
                        alpha = alpha_soc;
                        accepted = Some((f, kind));
                        break;
                    }
                    // Back to the uncorrected direction.
                    self.barrier_rhs(mu);
                    for r in 0..self.m {
                        self.rhs[self.n + r] = -self.g[r];
                    }
                    self.solve_step();
                    alpha = saved;
                }
                alpha *= 0.5;
            }
            let Some((_, armijo)) = accepted else {
                return self.finish("Line_Search_Failed", false, objective, iterations, started);
            };
            if !armijo {
                self.filter.push(((1.0 - GAMMA_THETA) * here.theta, here.phi - GAMMA_PHI * here.theta));
            }
            self.bound_steps(mu);
            let alpha_z = self.dual_boundary_step(tau);
            self.x.copy_from_slice(&self.trial);
            for r in 0..self.m {
                self.lambda[r] += alpha * self.step[self.n + r];
            }
            for i in 0..self.n {
                self.zl[i] += alpha_z * self.dzl[i];
                self.zu[i] += alpha_z * self.dzu[i];
            }
            self.safeguard(mu);
            iterations += 1;
            objective = self.evaluate(nlp);
            if !objective.is_finite() || self.g.iter().any(|g| !g.is_finite()) {
                return self.finish("Invalid_Number_Detected", false, objective, iterations, started);
            }
        }
    }

    fn finish(
        &self,
        status: &'static str,
        solved: bool,
        objective: f64,
        iterations: usize,
        started: Instant,
    ) -> InteriorResult {
        let violation = self.g.iter().fold(0.0f64, |m, g| m.max(g.abs()));
        InteriorResult { status, solved, objective, violation, iterations, wall: started.elapsed() }
    }

    /// Fixed variables at their value; the others at least `κ₁ max(1, |bound|)` inside their
    /// bounds (IPOPT's `bound_push`, `bound_frac`).
    fn place_inside(&mut self) {
        for i in 0..self.n {
            let (l, u) = (self.lower[i], self.upper[i]);
            self.fixed[i] = l == u;
            if self.fixed[i] {
                self.x[i] = l;
                continue;
            }
            let span = u - l;
            if l.is_finite() {
                let push = (BOUND_PUSH * l.abs().max(1.0)).min(if span.is_finite() {
                    BOUND_PUSH * span
                } else {
                    f64::INFINITY
                });
                self.x[i] = self.x[i].max(l + push);
            }
            if u.is_finite() {
                let push = (BOUND_PUSH * u.abs().max(1.0)).min(if span.is_finite() {
                    BOUND_PUSH * span
                } else {
                    f64::INFINITY
                });
                self.x[i] = self.x[i].min(u - push);
            }
            if !l.is_finite() {
                self.zl[i] = 0.0;
            } else if self.zl[i] <= 0.0 {
                self.zl[i] = 1.0;
            }
            if !u.is_finite() {
                self.zu[i] = 0.0;
            } else if self.zu[i] <= 0.0 {
                self.zu[i] = 1.0;
            }
        }
    }

    /// Evaluates the objective, its gradient, the equations (less their targets) and their
    /// Jacobian at `x`; returns the objective.
    fn evaluate(&mut self, nlp: &mut dyn Nlp) -> f64 {
        let f = nlp.objective(&self.x);
        nlp.gradient(&self.x, &mut self.gradient);
        nlp.constraint_values(&self.x, &mut self.g);
        for (g, t) in self.g.iter_mut().zip(&self.target) {
            *g -= t;
        }
        nlp.jacobian_values(&self.x, &mut self.jacobian);
        f
    }

    fn theta(&self, g: &[f64]) -> f64 {
        g.iter().map(|g| g.abs()).sum()
    }

    /// The barrier function `f − μ Σ ln(slacks)`.
    #[allow(clippy::needless_range_loop)]
    fn phi(&self, f: f64, x: &[f64], mu: f64) -> f64 {
        let mut phi = f;
        for i in 0..self.n {
            if self.fixed[i] {
                continue;
            }
            if self.lower[i].is_finite() {
                phi -= mu * (x[i] - self.lower[i]).ln();
            }
            if self.upper[i].is_finite() {
                phi -= mu * (self.upper[i] - x[i]).ln();
            }
        }
        phi
    }

    /// The scaled optimality error of the barrier problem for `mu` (of the program for 0).
    fn error(&mut self, mu: f64) -> f64 {
        // The dual residual ∇f + Jᵀλ − z_l + z_u in `residual[..n]`.
        let (n, m) = (self.n, self.m);
        self.residual[..n].copy_from_slice(&self.gradient);
        for (&(r, c), &a) in self.jacobian_pattern.iter().zip(&self.jacobian) {
            self.residual[c] += a * self.lambda[r];
        }
        let (mut dual, mut complementarity, mut z_sum, mut bounded) = (0.0f64, 0.0f64, 0.0, 0usize);
        for i in 0..n {
            if self.fixed[i] {
                continue;
            }
            let d = self.residual[i] - self.zl[i] + self.zu[i];
            dual = dual.max(d.abs());
            if self.lower[i].is_finite() {
                complementarity = complementarity.max(((self.x[i] - self.lower[i]) * self.zl[i] - mu).abs());
                z_sum += self.zl[i].abs();
                bounded += 1;
            }
            if self.upper[i].is_finite() {
                complementarity = complementarity.max(((self.upper[i] - self.x[i]) * self.zu[i] - mu).abs());
                z_sum += self.zu[i].abs();
                bounded += 1;
            }
        }
        let primal = self.g.iter().fold(0.0f64, |a, g| a.max(g.abs()));
        let lambda_sum: f64 = self.lambda.iter().map(|l| l.abs()).sum();
        let s_d = S_MAX.max((lambda_sum + z_sum) / (m + n) as f64) / S_MAX;
        let s_c = S_MAX.max(z_sum / bounded.max(1) as f64) / S_MAX;
        (dual / s_d).max(primal).max(complementarity / s_c)
    }

    /// The equations' multipliers that best satisfy the dual equations at the start,
    /// `min ‖∇f − z_l + z_u + Jᵀλ‖`, from `[I, Jᵀ; J, 0] (w, λ) = (−(∇f − z_l + z_u), 0)`;
    /// zero if they are not smaller than 1000 (IPOPT's `constr_mult_init_max`) or the system is
    /// singular.
    fn least_squares_multipliers(&mut self) {
        self.lambda.fill(0.0);
        if self.m == 0 {
            return;
        }
        self.band.clear();
        for (k, &(_, c)) in self.jacobian_pattern.iter().enumerate() {
            if !self.fixed[c] {
                self.band.add(self.jacobian_slots[k], self.jacobian[k]);
            }
        }
        for i in 0..self.n {
            self.band.add(self.diagonal_slots[i], 1.0);
            self.rhs[i] = if self.fixed[i] { 0.0 } else { -(self.gradient[i] - self.zl[i] + self.zu[i]) };
        }
        self.rhs[self.n..].fill(0.0);
        if !matches!(self.band.factor(), Inertia::Counted(p, q) if p == self.n && q == self.m) {
            return;
        }
        self.solve_step();
        let multipliers = &self.step[self.n..];
        if multipliers.iter().all(|l| l.abs() <= 1e3) {
            self.lambda.copy_from_slice(multipliers);
        }
    }

    /// Assembles and factors the step's matrix, raising `δ_w` until its inertia is right.
    fn factor(&mut self, mu: f64) -> bool {
        let mut delta_w = 0.0;
        let mut delta_c = 0.0;
        loop {
            self.assemble(delta_w, delta_c);
            match self.band.factor() {
                Inertia::Counted(p, q) if p == self.n && q == self.m => {
                    // The band factors in a fixed order without pivoting, so a pivot can vanish
                    // where the matrix does not (a variable without curvature eliminated before
                    // its equations): a factorisation that pivots, as IPOPT's does, needs no
                    // `δ_w` there. The `δ_w` that got past such a pivot is therefore not what
                    // the next iteration's first trial starts from; only one that corrected the
                    // inertia is.
                    if delta_w > 0.0 && delta_c == 0.0 {
                        self.last_delta_w = delta_w;
                    }
                    return true;
                }
                Inertia::Singular if delta_c == 0.0 => {
                    delta_c = 1e-8 * mu.powf(0.25);
                    continue;
                }
                _ => {}
            }
            delta_w = match (delta_w == 0.0, self.last_delta_w == 0.0) {
                (true, true) => DELTA_W_FIRST,
                (true, false) => DELTA_W_MIN.max(self.last_delta_w / 3.0),
                (false, true) => 100.0 * delta_w,
                (false, false) => 8.0 * delta_w,
            };
            if delta_w > DELTA_W_MAX {
                return false;
            }
        }
    }

    fn assemble(&mut self, delta_w: f64, delta_c: f64) {
        self.band.clear();
        for (k, &(r, c)) in self.hessian_pattern.iter().enumerate() {
            if !self.fixed[r] && !self.fixed[c] {
                self.band.add(self.hessian_slots[k], self.hessian[k]);
            }
        }
        for (k, &(_, c)) in self.jacobian_pattern.iter().enumerate() {
            if !self.fixed[c] {
                self.band.add(self.jacobian_slots[k], self.jacobian[k]);
            }
        }
        for i in 0..self.n {
            let diagonal = match self.fixed[i] {
                true => 1.0,
                false => {
                    let mut sigma = delta_w;
                    if self.lower[i].is_finite() {
                        sigma += self.zl[i] / (self.x[i] - self.lower[i]);
                    }
                    if self.upper[i].is_finite() {
                        sigma += self.zu[i] / (self.upper[i] - self.x[i]);
                    }
                    sigma
                }
            };
            self.band.add(self.diagonal_slots[i], diagonal);
        }
        for r in 0..self.m {
            self.band.add(self.diagonal_slots[self.n + r], -delta_c);
        }
    }

    /// The variables' right-hand side `−(∇f + Jᵀλ − μ/(x − x_l) + μ/(x_u − x))`, zero for fixed
    /// variables.
    fn barrier_rhs(&mut self, mu: f64) {
        let n = self.n;
        self.rhs[..n].copy_from_slice(&self.gradient);
        for (&(r, c), &a) in self.jacobian_pattern.iter().zip(&self.jacobian) {
            self.rhs[c] += a * self.lambda[r];
        }
        for i in 0..n {
            if self.fixed[i] {
                self.rhs[i] = 0.0;
                continue;
            }
            if self.lower[i].is_finite() {
                self.rhs[i] -= mu / (self.x[i] - self.lower[i]);
            }
            if self.upper[i].is_finite() {
                self.rhs[i] += mu / (self.upper[i] - self.x[i]);
            }
            self.rhs[i] = -self.rhs[i];
        }
    }

    fn solve_step(&mut self) {
        self.step.copy_from_slice(&self.rhs);
        self.residual.copy_from_slice(&self.rhs);
        self.band.solve(&mut self.step, &mut self.residual);
    }

    /// `∇φᵀ Δx`.
    fn barrier_slope(&self, mu: f64) -> f64 {
        let mut slope = 0.0;
        for i in 0..self.n {
            if self.fixed[i] {
                continue;
            }
            let mut g = self.gradient[i];
            if self.lower[i].is_finite() {
                g -= mu / (self.x[i] - self.lower[i]);
            }
            if self.upper[i].is_finite() {
                g += mu / (self.upper[i] - self.x[i]);
            }
            slope += g * self.step[i];
        }
        slope
    }

    /// The largest step in `(0, 1]` that keeps every slack at least `1 − τ` of its value.
    #[allow(clippy::needless_range_loop)]
    fn boundary_step(&self, dx: &[f64], tau: f64) -> f64 {
        let mut alpha: f64 = 1.0;
        for i in 0..self.n {
            if self.fixed[i] {
                continue;
            }
            if dx[i] < 0.0 && self.lower[i].is_finite() {
                alpha = alpha.min(-tau * (self.x[i] - self.lower[i]) / dx[i]);
            }
            if dx[i] > 0.0 && self.upper[i].is_finite() {
                alpha = alpha.min(tau * (self.upper[i] - self.x[i]) / dx[i]);
            }
        }
        alpha
    }

    fn take(&mut self, alpha: f64) {
        for i in 0..self.n {
            self.trial[i] = if self.fixed[i] { self.x[i] } else { self.x[i] + alpha * self.step[i] };
        }
    }

    /// Whether the filter accepts the trial point, and if so whether by the Armijo condition
    /// on the barrier function (`true`, the filter is not augmented) or by the filter
    /// (`false`).
    fn acceptable(
        &self,
        here: Measures,
        trial: Measures,
        alpha: f64,
        slope: f64,
        theta_min: f64,
        theta_max: f64,
    ) -> Option<bool> {
        if !(trial.theta.is_finite() && trial.phi.is_finite()) || trial.theta > theta_max {
            return None;
        }
        if self.filter.iter().any(|&(theta, phi)| trial.theta >= theta && trial.phi >= phi) {
            return None;
        }
        let switching = slope < 0.0 && alpha * (-slope).powf(S_PHI) > DELTA * here.theta.powf(S_THETA);
        if here.theta <= theta_min && switching {
            return (trial.phi <= here.phi + ETA_PHI * alpha * slope).then_some(true);
        }
        let better =
            trial.theta <= (1.0 - GAMMA_THETA) * here.theta || trial.phi <= here.phi - GAMMA_PHI * here.theta;
        better.then_some(false)
    }

    /// The bound multipliers' steps for the accepted direction (`step`, corrected or not).
    fn bound_steps(&mut self, mu: f64) {
        for i in 0..self.n {
            (self.dzl[i], self.dzu[i]) = (0.0, 0.0);
            if self.fixed[i] {
                continue;
            }
            let dx = self.step[i];
            if self.lower[i].is_finite() {
                let s = self.x[i] - self.lower[i];
                self.dzl[i] = mu / s - self.zl[i] - self.zl[i] / s * dx;
            }
            if self.upper[i].is_finite() {
                let s = self.upper[i] - self.x[i];
                self.dzu[i] = mu / s - self.zu[i] + self.zu[i] / s * dx;
            }
        }
    }

    fn dual_boundary_step(&self, tau: f64) -> f64 {
        let mut alpha: f64 = 1.0;
        for i in 0..self.n {
            if self.dzl[i] < 0.0 {
                alpha = alpha.min(-tau * self.zl[i] / self.dzl[i]);
            }
            if self.dzu[i] < 0.0 {
                alpha = alpha.min(-tau * self.zu[i] / self.dzu[i]);
            }
        }
        alpha
    }

    /// Keeps each bound multiplier within `κ_Σ` of `μ / slack` (IPOPT's safeguard).
    fn safeguard(&mut self, mu: f64) {
        for i in 0..self.n {
            if self.fixed[i] {
                continue;
            }
            if self.lower[i].is_finite() {
                let s = self.x[i] - self.lower[i];
                self.zl[i] = self.zl[i].clamp(mu / (KAPPA_SIGMA * s), KAPPA_SIGMA * mu / s);
            }
            if self.upper[i].is_finite() {
                let s = self.upper[i] - self.x[i];
                self.zu[i] = self.zu[i].clamp(mu / (KAPPA_SIGMA * s), KAPPA_SIGMA * mu / s);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `min (x₀ − 2)² + (x₁ − 1)² + x₂²` subject to `x₀ + x₁ = 1`, `x₀ ≤ 0.2` and `x₂ = 3`
    /// (fixed by its bounds). By hand: on the line, the bound is active, so `x = (0.2, 0.8, 3)`
    /// with `λ = −2 (x₁ − 1) = 0.4`.
    struct Bounded;

    impl Nlp for Bounded {
        fn variables(&self) -> usize {
            3
        }
        fn constraints(&self) -> usize {
            1
        }
        fn variable_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
            lower.copy_from_slice(&[f64::NEG_INFINITY, f64::NEG_INFINITY, 3.0]);
            upper.copy_from_slice(&[0.2, f64::INFINITY, 3.0]);
        }
        fn constraint_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
            lower[0] = 1.0;
            upper[0] = 1.0;
        }
        fn starting_point(&self, x: &mut [f64]) {
            x.copy_from_slice(&[0.0, 0.0, 0.0]);
        }
        fn objective(&mut self, x: &[f64]) -> f64 {
            (x[0] - 2.0).powi(2) + (x[1] - 1.0).powi(2) + x[2] * x[2]
        }
        fn gradient(&mut self, x: &[f64], out: &mut [f64]) {
            out.copy_from_slice(&[2.0 * (x[0] - 2.0), 2.0 * (x[1] - 1.0), 2.0 * x[2]]);
        }
        fn constraint_values(&mut self, x: &[f64], out: &mut [f64]) {
            out[0] = x[0] + x[1];
        }
        fn jacobian_pattern(&self) -> &[(usize, usize)] {
            &[(0, 0), (0, 1)]
        }
        fn jacobian_values(&mut self, _: &[f64], out: &mut [f64]) {
            out.copy_from_slice(&[1.0, 1.0]);
        }
        fn hessian_pattern(&self) -> &[(usize, usize)] {
            &[(0, 0), (1, 1), (2, 2)]
        }
        fn hessian_values(&mut self, _: &[f64], sigma: f64, _: &[f64], out: &mut [f64]) {
            out.fill(2.0 * sigma);
        }
    }

    /// `min x₀ + x₁` on the circle `x₀² + x₁² = 2`, from `(1, 0.5)`. By hand (Lagrange):
    /// `1 + 2λ x_i = 0`, so `x = (−1, −1)` and `λ = 1/2`. The Lagrangian's Hessian is `2λ I`,
    /// indefinite along the way: the steps need its inertia corrected.
    struct Circle;

    impl Nlp for Circle {
        fn variables(&self) -> usize {
            2
        }
        fn constraints(&self) -> usize {
            1
        }
        fn variable_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
            lower.fill(f64::NEG_INFINITY);
            upper.fill(f64::INFINITY);
        }
        fn constraint_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
            lower[0] = 2.0;
            upper[0] = 2.0;
        }
        fn starting_point(&self, x: &mut [f64]) {
            x.copy_from_slice(&[1.0, 0.5]);
        }
        fn objective(&mut self, x: &[f64]) -> f64 {
            x[0] + x[1]
        }
        fn gradient(&mut self, _: &[f64], out: &mut [f64]) {
            out.fill(1.0);
        }
        fn constraint_values(&mut self, x: &[f64], out: &mut [f64]) {
            out[0] = x[0] * x[0] + x[1] * x[1];
        }
        fn jacobian_pattern(&self) -> &[(usize, usize)] {
            &[(0, 0), (0, 1)]
        }
        fn jacobian_values(&mut self, x: &[f64], out: &mut [f64]) {
            out.copy_from_slice(&[2.0 * x[0], 2.0 * x[1]]);
        }
        fn hessian_pattern(&self) -> &[(usize, usize)] {
            &[(0, 0), (1, 1)]
        }
        fn hessian_values(&mut self, _: &[f64], _: f64, multipliers: &[f64], out: &mut [f64]) {
            out.fill(2.0 * multipliers[0]);
        }
    }

    #[test]
    fn an_active_bound_and_a_fixed_variable_land_where_the_hand_solution_does() {
        let mut solver = InteriorPoint::new(&Bounded).expect("equations only");
        let result = solver.solve(&mut Bounded, &InteriorOptions::default());
        assert!(result.solved, "{result:?}");
        let x = solver.point();
        assert!((x[0] - 0.2).abs() < 1e-7 && (x[1] - 0.8).abs() < 1e-7 && x[2] == 3.0, "{x:?}");
        assert!(x[0] < 0.2, "the bound is kept strictly: {}", x[0]);
        assert!((solver.multipliers()[0] - 0.4).abs() < 1e-6, "{:?}", solver.multipliers());
    }

    #[test]
    fn a_nonconvex_equation_is_solved_through_the_inertia_correction() {
        let mut solver = InteriorPoint::new(&Circle).expect("equations only");
        let result = solver.solve(&mut Circle, &InteriorOptions::default());
        assert!(result.solved, "{result:?}");
        let x = solver.point();
        assert!((x[0] + 1.0).abs() < 1e-8 && (x[1] + 1.0).abs() < 1e-8, "{x:?}");
        assert!((solver.multipliers()[0] - 0.5).abs() < 1e-8, "{:?}", solver.multipliers());
        assert!((result.objective + 2.0).abs() < 1e-8);
        // Stopped early, the status says so by name and the result is not a solution.
        let options = InteriorOptions { max_iterations: 1, ..InteriorOptions::default() };
        let result = InteriorPoint::new(&Circle).expect("equations only").solve(&mut Circle, &options);
        assert_eq!(
            (result.status, result.solved, result.iterations),
            ("Maximum_Iterations_Exceeded", false, 1)
        );
        // Absurd options are refused by name before anything is evaluated.
        for options in [
            InteriorOptions { tolerance: f64::NAN, ..InteriorOptions::default() },
            InteriorOptions { tolerance: 0.0, ..InteriorOptions::default() },
            InteriorOptions { barrier: -1.0, ..InteriorOptions::default() },
        ] {
            let result = InteriorPoint::new(&Circle).expect("equations only").solve(&mut Circle, &options);
            assert_eq!((result.status, result.solved, result.iterations), ("Invalid_Option", false, 0));
        }
    }

    #[test]
    fn inequalities_are_refused_by_name() {
        struct Inequality;
        impl Nlp for Inequality {
            fn variables(&self) -> usize {
                1
            }
            fn constraints(&self) -> usize {
                1
            }
            fn variable_bounds(&self, _: &mut [f64], _: &mut [f64]) {}
            fn constraint_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
                (lower[0], upper[0]) = (0.0, 1.0);
            }
            fn starting_point(&self, _: &mut [f64]) {}
            fn objective(&mut self, _: &[f64]) -> f64 {
                0.0
            }
            fn gradient(&mut self, _: &[f64], _: &mut [f64]) {}
            fn constraint_values(&mut self, _: &[f64], _: &mut [f64]) {}
            fn jacobian_pattern(&self) -> &[(usize, usize)] {
                &[]
            }
            fn jacobian_values(&mut self, _: &[f64], _: &mut [f64]) {}
            fn hessian_pattern(&self) -> &[(usize, usize)] {
                &[]
            }
            fn hessian_values(&mut self, _: &[f64], _: f64, _: &[f64], _: &mut [f64]) {}
        }
        let why = InteriorPoint::new(&Inequality).err().expect("refused");
        assert!(why.contains("equations only"), "{why}");
    }
}
