//! Radau IIA collocation (three stages, order 5): the stage equations of the implicit
//! Lagrangian system, written on positions and velocities with the momenta `p = ∂L/∂v` as
//! functions of them, as the constraints of a nonlinear program.
//!
//! Variables: the points `X_P = (q_P, v_P)`, `P = 0 … 3N` (point `3k` is node `k`, points
//! `3k + 1`, `3k + 2` and `3k + 3` are interval `k`'s stages, the last one node `k + 1`),
//! then the inputs `u_0 … u_{N−1}` held over each interval. For interval `k`, with `B = 3k`,
//! `X_j = X_{B+j}` and stage `i = 1, 2, 3`:
//!
//! ```text
//! q_i − q_0 − h Σ_j a_ij v_j = 0
//! p(X_i) − p(X_0) − h Σ_j a_ij [∂L/∂q + F](X_j, u_k) = 0
//! ```
//!
//! Collocating the momenta keeps every momentum that is one of their components (a cyclic
//! coordinate's) exactly, as any Runge-Kutta method keeps linear invariants; a momentum map
//! that is not linear in them (angular momentum in Cartesian coordinates) drifts at the
//! method's order, where [`Dmoc`](super::Dmoc) keeps it to round-off.
//!
//! A velocity's bounds hold at every point after the start, where they are bounds on the
//! variables `v_P`.
//!
//! The cost is that of the [`Problem`], with the running part integrated by the method's own
//! quadrature, `h Σ_j b_j ℓ(X_j, u_k)`.
//!
//! With a free final time, each interval's step `h_k` is a variable after the inputs, held
//! equal to the next by a row `h_k − h_{k+1} = 0`. The stage equations are linear in it, so
//! its second derivatives are the first derivatives of what it multiplies.

use std::collections::BTreeMap;

use nalgebra::DefaultAllocator;

use crate::methods::radau::tableau::{A, C1, C2};
use crate::model::{DenseModel, InputsOutputs, MatQQ};
use crate::optimal::error::OptimalError;
use crate::optimal::nlp::Nlp;
use crate::optimal::problem::Problem;
use crate::optimal::{Optimum, Transcription};
use crate::shape::dims::{Storage, VecC, VecQ};

/// The stages' times within an interval, as fractions of `h`, point 0 being the start.
const C: [f64; 4] = [0.0, C1, C2, 1.0];

/// The Radau IIA collocation of a [`Problem`] into a nonlinear program.
pub struct Collocation<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    pub(crate) problem: Problem<M>,
    n: usize,
    nu: usize,
    intervals: usize,
    h: f64,
    /// Whether the steps are variables (a free final time).
    free: bool,
    jacobian_pattern: Vec<(usize, usize)>,
    hessian_pattern: Vec<(usize, usize)>,
    /// For each interval and each of its four points, the global index of each entry of the
    /// model's weighted Hessian pattern.
    scatter: Vec<usize>,
    /// The cost's diagonal: `(entry, coefficient, interval)`, the coefficient before `σ` and
    /// before the step of its interval, if it has one.
    cost_diagonal: Vec<(usize, f64, Option<usize>)>,
    /// For each interval, the global index of its step's row of the Hessian against the
    /// `(q, v)` of its three stages and its inputs (free final time).
    step_scatter: Vec<usize>,
    work: Work<M>,
    /// Time spent in the model's generated functions and their assembly, for the statistics.
    pub(crate) evaluation: std::time::Duration,
}

/// The model's blocks at the four points of an interval.
struct Work<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    q: VecQ<M>,
    v: VecQ<M>,
    lambda: VecC<M>,
    out: VecQ<M>,
    wq: VecQ<M>,
    wv: VecQ<M>,
    wf: VecQ<M>,
    /// `p(X_j)` and `[∂L/∂q + F](X_j)`, `n` values per point.
    momenta: Vec<f64>,
    rates: Vec<f64>,
    /// `∂p/∂q`, `∂p/∂v` at each point; `∂(L_q + F)/∂q`, `∂(L_q + F)/∂v` at each point.
    p_q: Vec<MatQQ<M>>,
    p_v: Vec<MatQQ<M>>,
    g_q: Vec<MatQQ<M>>,
    g_v: Vec<MatQQ<M>>,
    /// `∂p/∂u` and `∂(L_q + F)/∂u` at each point, `n × n_u` column-major.
    p_u: Vec<Vec<f64>>,
    g_u: Vec<Vec<f64>>,
    l_qq: MatQQ<M>,
    f_q: MatQQ<M>,
    f_v: MatQQ<M>,
    point_hessian: Vec<f64>,
}

impl<M> Collocation<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    /// The collocation of `problem`, refused with a typed error if the problem is malformed.
    pub fn new(problem: Problem<M>) -> Result<Self, OptimalError> {
        problem.check()?;
        let (n, nu, intervals) = (M::NQ, M::NAMES.input_count(), problem.intervals);
        // Three stages of `5n + n (8n + n_u)` entries per interval (and a step's column),
        // indexed by 32-bit integers.
        let entries = intervals.checked_mul(3 * n * (8 * n + nu + 7));
        if entries.is_none_or(|e| e > i32::MAX as usize) {
            return Err(OptimalError::InvalidGrid { horizon: problem.horizon, intervals });
        }
        let h = problem.step();
        let free = problem.free_time.is_some();
        let points = 3 * intervals + 1;
        let inputs0 = points * 2 * n;
        let point = |p: usize| p * 2 * n;
        let step = |k: usize| inputs0 + intervals * nu + k;

        let mut jacobian_pattern = Vec::new();
        for k in 0..intervals {
            let base = 3 * k;
            for i in 0..3 {
                let row0 = (base + i) * 2 * n;
                for c in 0..n {
                    jacobian_pattern.push((row0 + c, point(base + i + 1) + c));
                    jacobian_pattern.push((row0 + c, point(base) + c));
                    for j in 1..4 {
                        jacobian_pattern.push((row0 + c, point(base + j) + n + c));
                    }
                    if free {
                        jacobian_pattern.push((row0 + c, step(k)));
                    }
                }
                for c in 0..n {
                    for j in 0..4 {
                        jacobian_pattern.extend((0..2 * n).map(|x| (row0 + n + c, point(base + j) + x)));
                    }
                    jacobian_pattern.extend((0..nu).map(|x| (row0 + n + c, inputs0 + k * nu + x)));
                    if free {
                        jacobian_pattern.push((row0 + n + c, step(k)));
                    }
                }
            }
        }
        if free {
            // h_k − h_{k+1} = 0.
            let row0 = 3 * intervals * 2 * n;
            for k in 0..intervals - 1 {
                jacobian_pattern.extend([(row0 + k, step(k)), (row0 + k, step(k + 1))]);
            }
        }

        // The Hessian: the model's pattern at every point of every interval (with that
        // interval's inputs), and the cost's diagonal.
        let model_pattern = problem.model.weighted_hessian_pattern();
        let global = |k: usize, j: usize, r: usize| match r {
            r if r < 2 * n => point(3 * k + j) + r,
            r => inputs0 + k * nu + (r - 2 * n),
        };
        let mut index = BTreeMap::new();
        for k in 0..intervals {
            for j in 0..4 {
                for &(r, c) in model_pattern {
                    index.entry((global(k, j, r), global(k, j, c))).or_insert(0usize);
                }
            }
        }
        let cost = &problem.cost;
        let mut diagonal = Vec::new();
        for k in 0..intervals {
            for j in 1..4 {
                for i in 0..n {
                    let b = A[2][j - 1];
                    diagonal.push((point(3 * k + j) + i, b * cost.position[i], Some(k)));
                    diagonal.push((point(3 * k + j) + n + i, b * cost.velocity[i], Some(k)));
                }
            }
            diagonal.extend((0..nu).map(|i| (inputs0 + k * nu + i, cost.input[i], Some(k))));
        }
        diagonal.extend((0..n).map(|i| (point(3 * intervals) + i, cost.terminal[i], None)));
        diagonal.retain(|&(_, w, _)| w != 0.0);
        for &(at, _, _) in &diagonal {
            index.entry((at, at)).or_insert(0);
        }
        // The step's row: against every stage's `(q, v)` and the inputs of its interval.
        let step_columns = |k: usize| {
            let stages = (1..4).flat_map(move |j| (0..2 * n).map(move |x| point(3 * k + j) + x));
            stages.chain((0..nu).map(move |x| inputs0 + k * nu + x))
        };
        if free {
            for k in 0..intervals {
                for column in step_columns(k) {
                    index.entry((step(k), column)).or_insert(0);
                }
            }
        }
        for (i, value) in index.values_mut().enumerate() {
            *value = i;
        }
        let step_scatter = match free {
            true => (0..intervals)
                .flat_map(|k| step_columns(k).map(move |c| (step(k), c)))
                .map(|e| index[&e])
                .collect(),
            false => Vec::new(),
        };
        let mut scatter = Vec::with_capacity(intervals * 4 * model_pattern.len());
        for k in 0..intervals {
            for j in 0..4 {
                scatter
                    .extend(model_pattern.iter().map(|&(r, c)| index[&(global(k, j, r), global(k, j, c))]));
            }
        }
        let cost_diagonal = diagonal.iter().map(|&(at, w, k)| (index[&(at, at)], w, k)).collect();
        let hessian_pattern = index.into_keys().collect();

        let zm = MatQQ::<M>::zeros;
        let work = Work {
            q: VecQ::<M>::zeros(),
            v: VecQ::<M>::zeros(),
            lambda: VecC::<M>::zeros(),
            out: VecQ::<M>::zeros(),
            wq: VecQ::<M>::zeros(),
            wv: VecQ::<M>::zeros(),
            wf: VecQ::<M>::zeros(),
            momenta: vec![0.0; 4 * n],
            rates: vec![0.0; 4 * n],
            p_q: (0..4).map(|_| zm()).collect(),
            p_v: (0..4).map(|_| zm()).collect(),
            g_q: (0..4).map(|_| zm()).collect(),
            g_v: (0..4).map(|_| zm()).collect(),
            p_u: vec![vec![0.0; n * nu]; 4],
            g_u: vec![vec![0.0; n * nu]; 4],
            l_qq: zm(),
            f_q: zm(),
            f_v: zm(),
            point_hessian: vec![0.0; model_pattern.len()],
        };
        Ok(Collocation {
            problem,
            n,
            nu,
            intervals,
            h,
            free,
            jacobian_pattern,
            hessian_pattern,
            scatter,
            cost_diagonal,
            step_scatter,
            work,
            evaluation: std::time::Duration::ZERO,
        })
    }

    /// The problem transcribed.
    pub fn problem(&self) -> &Problem<M> {
        &self.problem
    }

    fn point(&self, p: usize) -> usize {
        p * 2 * self.n
    }

    fn input_start(&self, k: usize) -> usize {
        (3 * self.intervals + 1) * 2 * self.n + k * self.nu
    }

    fn set_inputs(&mut self, z: &[f64], k: usize) {
        let start = self.input_start(k);
        for i in 0..self.nu {
            self.problem.model.set_input_value(i, z[start + i]);
        }
    }

    /// Where the step of interval `k` is in `z` (free final time).
    fn step_index(&self, k: usize) -> usize {
        self.input_start(self.intervals) + k
    }

    /// The step of interval `k`: the problem's, or the variable's with a free final time.
    fn step(&self, z: &[f64], k: usize) -> f64 {
        if self.free { z[self.step_index(k)] } else { self.h }
    }

    /// The time of point `j` of interval `k`.
    fn time(&self, z: &[f64], k: usize, j: usize) -> f64 {
        match self.free {
            true => {
                let before: f64 = (0..k).map(|i| z[self.step_index(i)]).sum();
                self.problem.t0 + before + C[j] * self.step(z, k)
            }
            false => self.problem.t0 + (k as f64 + C[j]) * self.h,
        }
    }

    /// Places point `p` of `z` in the work's `(q, v)`.
    fn place(&mut self, z: &[f64], p: usize) {
        let (n, at) = (self.n, self.point(p));
        for i in 0..n {
            self.work.q[i] = z[at + i];
            self.work.v[i] = z[at + n + i];
        }
    }

    /// `p(X_j)` at the four points of interval `k`, and `[L_q + F](X_j)` at its stages, into
    /// the work, with the inputs already set to `u_k`.
    fn values(&mut self, z: &[f64], k: usize) {
        let n = self.n;
        for j in 0..4 {
            self.place(z, 3 * k + j);
            let t = self.time(z, k, j);
            let model = &self.problem.model;
            let w = &mut self.work;
            model.dl_dv(t, &w.q, &w.v, &mut w.out);
            w.momenta[j * n..(j + 1) * n].copy_from_slice(w.out.as_slice());
            if j > 0 {
                model.dl_dq(t, &w.q, &w.v, &mut w.out);
                w.rates[j * n..(j + 1) * n].copy_from_slice(w.out.as_slice());
                model.force(t, &w.q, &w.v, &mut w.out);
                for i in 0..n {
                    w.rates[j * n + i] += w.out[i];
                }
            }
        }
    }

    /// The blocks' derivatives at the four points of interval `k`, into the work.
    fn derivatives(&mut self, z: &[f64], k: usize) {
        let n = self.n;
        for j in 0..4 {
            self.place(z, 3 * k + j);
            let t = self.time(z, k, j);
            let model = &self.problem.model;
            let w = &mut self.work;
            model.l_vq(t, &w.q, &w.v, &mut w.p_q[j]);
            model.l_vv(t, &w.q, &w.v, &mut w.p_v[j]);
            model.l_vu(t, &w.q, &w.v, &mut w.p_u[j]);
            if j > 0 {
                model.l_qq(t, &w.q, &w.v, &mut w.l_qq);
                model.force_dq(t, &w.q, &w.v, &mut w.f_q);
                model.force_dv(t, &w.q, &w.v, &mut w.f_v);
                model.dpdot_du(t, &w.q, &w.v, &w.lambda, &mut w.g_u[j]);
                for r in 0..n {
                    for c in 0..n {
                        w.g_q[j][(r, c)] = w.l_qq[(r, c)] + w.f_q[(r, c)];
                        w.g_v[j][(r, c)] = w.p_q[j][(c, r)] + w.f_v[(r, c)];
                    }
                }
            }
        }
    }

    /// The trajectory at the point `z` of the program, with the solve's figures: positions
    /// and momenta `∂L/∂v` at the nodes.
    pub fn optimum(
        &mut self,
        z: &[f64],
        iterations: usize,
        status: &'static str,
        wall: std::time::Duration,
    ) -> Optimum {
        let (n, intervals) = (self.n, self.intervals);
        let mut g = vec![0.0; self.constraints()];
        self.constraint_values(z, &mut g);
        let mut momenta = Vec::with_capacity(intervals + 1);
        for k in 0..intervals {
            self.set_inputs(z, k);
            self.values(z, k);
            momenta.push(self.work.momenta[..n].to_vec());
            if k + 1 == intervals {
                momenta.push(self.work.momenta[3 * n..].to_vec());
            }
        }
        Optimum {
            times: (0..=intervals)
                .map(|k| if k < intervals { self.time(z, k, 0) } else { self.time(z, k - 1, 3) })
                .collect(),
            positions: (0..=intervals).map(|k| z[self.point(3 * k)..][..n].to_vec()).collect(),
            momenta,
            inputs: (0..intervals).map(|k| z[self.input_start(k)..][..self.nu].to_vec()).collect(),
            cost: self.objective(z),
            violation: g.iter().fold(0.0, |m: f64, x| m.max(x.abs())),
            iterations,
            status,
            wall,
            evaluation: self.evaluation,
        }
    }

    /// The guess as a point of `z`: the problem's positions at the nodes, straight lines
    /// between them through the stages, and each interval's mean velocity at its points.
    #[allow(clippy::needless_range_loop)]
    pub fn guess(&self) -> Vec<f64> {
        let (n, h, p) = (self.n, self.h, &self.problem);
        let mut z = vec![0.0; self.variables()];
        let (positions, inputs) = p.guessed_nodes();
        for k in 0..self.intervals {
            let (a, b) = (&positions[k], &positions[k + 1]);
            for j in 0..4 {
                let at = self.point(3 * k + j);
                for i in 0..n {
                    z[at + i] = a[i] + C[j] * (b[i] - a[i]);
                    let (lower, upper) = p.velocity_bounds[i];
                    z[at + n + i] = ((b[i] - a[i]) / h).clamp(lower, upper);
                }
            }
            z[self.input_start(k)..][..self.nu].copy_from_slice(&inputs[k]);
            if self.free {
                z[self.step_index(k)] = h;
            }
        }
        for i in 0..n {
            z[n + i] = p.v0[i];
            if let Some(v) = &p.final_velocity {
                z[self.point(3 * self.intervals) + n + i] = v[i];
            }
        }
        z
    }

    /// A typed error if the cost or the equations are not finite at the guess.
    pub fn check_guess(&mut self, z: &[f64]) -> Result<(), OptimalError> {
        let cost = self.objective(z);
        if !cost.is_finite() {
            return Err(OptimalError::NotFiniteAtGuess { what: "the cost", detail: format!("it is {cost}") });
        }
        let mut g = vec![0.0; self.constraints()];
        self.constraint_values(z, &mut g);
        if let Some(row) = g.iter().position(|x| !x.is_finite()) {
            let n = self.n;
            let (block, within) = (row / (2 * n), row % (2 * n));
            let name = &self.problem.model.coordinate_names()[within % n];
            let what = if within < n { "velocity" } else { "momentum balance" };
            return Err(OptimalError::NotFiniteAtGuess {
                what: "the collocation equations",
                detail: format!(
                    "the {what} of `{name}` at stage {} of interval {} is {}",
                    block % 3 + 1,
                    block / 3,
                    g[row]
                ),
            });
        }
        if self.free {
            let horizon = self.problem.horizon;
            super::refuse_time_dependence::<M, _>(self, |t| &mut t.problem.t0, horizon, z)?;
        }
        Ok(())
    }
}

impl<M> Nlp for Collocation<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    fn variables(&self) -> usize {
        (3 * self.intervals + 1) * 2 * self.n + self.intervals * (self.nu + usize::from(self.free))
    }

    fn constraints(&self) -> usize {
        3 * self.intervals * 2 * self.n + if self.free { self.intervals - 1 } else { 0 }
    }

    fn variable_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
        let (n, p) = (self.n, &self.problem);
        lower.fill(f64::NEG_INFINITY);
        upper.fill(f64::INFINITY);
        let last = 3 * self.intervals;
        for point in 0..=last {
            let at = self.point(point);
            for i in 0..n {
                let (l, u) = p.position_bounds[i];
                let fixed = match point {
                    0 => Some(p.q0[i]),
                    k if k == last => p.final_position[i],
                    _ => None,
                };
                (lower[at + i], upper[at + i]) = fixed.map_or((l, u), |x| (x, x));
                (lower[at + n + i], upper[at + n + i]) = p.velocity_bounds[i];
            }
        }
        for i in 0..n {
            (lower[n + i], upper[n + i]) = (p.v0[i], p.v0[i]);
            if let Some(v) = &p.final_velocity {
                let at = self.point(last) + n + i;
                (lower[at], upper[at]) = (v[i], v[i]);
            }
        }
        for k in 0..self.intervals {
            for (i, &(l, u)) in p.input_bounds.iter().enumerate() {
                let at = self.input_start(k) + i;
                (lower[at], upper[at]) = (l, u);
            }
        }
        if let Some((shortest, longest)) = p.free_time {
            let per = self.intervals as f64;
            for k in 0..self.intervals {
                let at = self.step_index(k);
                (lower[at], upper[at]) = (shortest / per, longest / per);
            }
        }
    }

    fn constraint_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
        lower.fill(0.0);
        upper.fill(0.0);
    }

    fn starting_point(&self, x: &mut [f64]) {
        x.copy_from_slice(&self.guess());
    }

    fn objective(&mut self, z: &[f64]) -> f64 {
        let (n, nu, c) = (self.n, self.nu, &self.problem.cost);
        let mut total = 0.0;
        for k in 0..self.intervals {
            let h = self.step(z, k);
            total += c.time * h;
            for j in 1..4 {
                let at = self.point(3 * k + j);
                let mut running = 0.0;
                for i in 0..n {
                    let dq = z[at + i] - c.position_reference[i];
                    let dv = z[at + n + i] - c.velocity_reference[i];
                    running += c.position[i] * dq * dq + c.velocity[i] * dv * dv;
                }
                total += 0.5 * h * A[2][j - 1] * running;
            }
            let u = &z[self.input_start(k)..][..nu];
            total += 0.5 * h * u.iter().zip(&c.input).map(|(u, r)| r * u * u).sum::<f64>();
        }
        let end = self.point(3 * self.intervals);
        for i in 0..n {
            let d = z[end + i] - c.terminal_reference[i];
            total += 0.5 * c.terminal[i] * d * d;
        }
        total
    }

    fn gradient(&mut self, z: &[f64], out: &mut [f64]) {
        let (n, nu, c) = (self.n, self.nu, &self.problem.cost);
        out.fill(0.0);
        for k in 0..self.intervals {
            let h = self.step(z, k);
            // The interval's running cost over `h`, and `ρ`: its derivative in the step.
            let mut along_h = c.time;
            for j in 1..4 {
                let (at, b) = (self.point(3 * k + j), A[2][j - 1]);
                for i in 0..n {
                    let dq = z[at + i] - c.position_reference[i];
                    let dv = z[at + n + i] - c.velocity_reference[i];
                    out[at + i] = h * b * c.position[i] * dq;
                    out[at + n + i] = h * b * c.velocity[i] * dv;
                    along_h += 0.5 * b * (c.position[i] * dq * dq + c.velocity[i] * dv * dv);
                }
            }
            let start = self.input_start(k);
            for i in 0..nu {
                out[start + i] = h * c.input[i] * z[start + i];
                along_h += 0.5 * c.input[i] * z[start + i] * z[start + i];
            }
            if self.free {
                out[self.step_index(k)] = along_h;
            }
        }
        let end = self.point(3 * self.intervals);
        for i in 0..n {
            out[end + i] += c.terminal[i] * (z[end + i] - c.terminal_reference[i]);
        }
    }

    #[allow(clippy::needless_range_loop)]
    fn constraint_values(&mut self, z: &[f64], out: &mut [f64]) {
        let started = std::time::Instant::now();
        let n = self.n;
        for k in 0..self.intervals {
            let h = self.step(z, k);
            self.set_inputs(z, k);
            self.values(z, k);
            let base = 3 * k;
            for i in 0..3 {
                let row0 = (base + i) * 2 * n;
                let (start, stage) = (self.point(base), self.point(base + i + 1));
                for c in 0..n {
                    let mut velocity = z[stage + c] - z[start + c];
                    let mut momentum = self.work.momenta[(i + 1) * n + c] - self.work.momenta[c];
                    for j in 1..4 {
                        velocity -= h * A[i][j - 1] * z[self.point(base + j) + n + c];
                        momentum -= h * A[i][j - 1] * self.work.rates[j * n + c];
                    }
                    out[row0 + c] = velocity;
                    out[row0 + n + c] = momentum;
                }
            }
        }
        if self.free {
            let row0 = 3 * self.intervals * 2 * n;
            for k in 0..self.intervals - 1 {
                out[row0 + k] = z[self.step_index(k)] - z[self.step_index(k + 1)];
            }
        }
        self.evaluation += started.elapsed();
    }

    fn jacobian_pattern(&self) -> &[(usize, usize)] {
        &self.jacobian_pattern
    }

    #[allow(clippy::needless_range_loop)]
    fn jacobian_values(&mut self, z: &[f64], out: &mut [f64]) {
        let started = std::time::Instant::now();
        let (n, nu, free) = (self.n, self.nu, usize::from(self.free));
        let stage_entries = (5 + free) * n + n * (8 * n + nu + free);
        for k in 0..self.intervals {
            let h = self.step(z, k);
            self.set_inputs(z, k);
            if self.free {
                // The step multiplies the stages' velocities and rates.
                self.values(z, k);
            }
            self.derivatives(z, k);
            let w = &self.work;
            for i in 0..3 {
                let mut at = (3 * k + i) * stage_entries;
                for c in 0..n {
                    out[at] = 1.0;
                    out[at + 1] = -1.0;
                    for j in 1..4 {
                        out[at + 1 + j] = -h * A[i][j - 1];
                    }
                    if self.free {
                        let velocities = (1..4).map(|j| A[i][j - 1] * z[self.point(3 * k + j) + n + c]);
                        out[at + 5] = -velocities.sum::<f64>();
                    }
                    at += 5 + free;
                }
                for r in 0..n {
                    // X_0: −∂p/∂x.
                    for c in 0..n {
                        out[at + c] = -w.p_q[0][(r, c)];
                        out[at + n + c] = -w.p_v[0][(r, c)];
                    }
                    at += 2 * n;
                    // X_j: ∂p/∂x at the stage's own point, less h a_ij ∂(L_q + F)/∂x.
                    for j in 1..4 {
                        let s = h * A[i][j - 1];
                        let own = if j == i + 1 { 1.0 } else { 0.0 };
                        for c in 0..n {
                            out[at + c] = own * w.p_q[j][(r, c)] - s * w.g_q[j][(r, c)];
                            out[at + n + c] = own * w.p_v[j][(r, c)] - s * w.g_v[j][(r, c)];
                        }
                        at += 2 * n;
                    }
                    for x in 0..nu {
                        let mut value = w.p_u[i + 1][x * n + r] - w.p_u[0][x * n + r];
                        for j in 1..4 {
                            value -= h * A[i][j - 1] * w.g_u[j][x * n + r];
                        }
                        out[at + x] = value;
                    }
                    at += nu;
                    if self.free {
                        out[at] = -(1..4).map(|j| A[i][j - 1] * w.rates[j * n + r]).sum::<f64>();
                        at += 1;
                    }
                }
            }
        }
        if self.free {
            let at = out.len() - 2 * (self.intervals - 1);
            for pair in out[at..].chunks_exact_mut(2) {
                pair.copy_from_slice(&[1.0, -1.0]);
            }
        }
        self.evaluation += started.elapsed();
    }

    fn hessian_pattern(&self) -> &[(usize, usize)] {
        &self.hessian_pattern
    }

    fn hessian_values(&mut self, z: &[f64], sigma: f64, mu: &[f64], out: &mut [f64]) {
        let started = std::time::Instant::now();
        let n = self.n;
        let entries = self.work.point_hessian.len();
        out.fill(0.0);
        for k in 0..self.intervals {
            let h = self.step(z, k);
            self.set_inputs(z, k);
            if self.free {
                self.add_step_hessian(z, k, sigma, mu, out);
            }
            // The momentum rows' multipliers of stage i are `mu[(3k + i) 2n + n ..][..n]`.
            let stage = |i: usize, c: usize| mu[(3 * k + i) * 2 * n + n + c];
            for j in 0..4 {
                for c in 0..n {
                    let (wv, wq) = match j {
                        0 => (-(0..3).map(|i| stage(i, c)).sum::<f64>(), 0.0),
                        j => (stage(j - 1, c), -h * (0..3).map(|i| A[i][j - 1] * stage(i, c)).sum::<f64>()),
                    };
                    self.work.wv[c] = wv;
                    self.work.wq[c] = wq;
                    self.work.wf[c] = wq;
                }
                self.place(z, 3 * k + j);
                let t = self.time(z, k, j);
                let Work { q, v, wq, wv, wf, point_hessian, .. } = &mut self.work;
                self.problem.model.weighted_hessian(t, q, v, wq, wv, wf, point_hessian);
                let scatter = &self.scatter[(4 * k + j) * entries..][..entries];
                for (&at, &value) in scatter.iter().zip(point_hessian.iter()) {
                    out[at] += value;
                }
            }
        }
        for &(at, w, k) in &self.cost_diagonal {
            out[at] += sigma * w * k.map_or(1.0, |k| self.step(z, k));
        }
        self.evaluation += started.elapsed();
    }
}

impl<M> Collocation<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    /// Adds the step's row of the Hessian on interval `k` to `out` (free final time). The
    /// equations are linear in `h_k`: `∂²/∂h∂x` is what multiplies `h_k`, differentiated once,
    /// `−Σ_i a_ij (μ_vel,i on v_j + μ_mom,iᵀ ∂(L_q + F)/∂x_j)`, and the running cost's
    /// gradient over `h_k`; `∂²/∂h²` is zero.
    #[allow(clippy::needless_range_loop)]
    fn add_step_hessian(&mut self, z: &[f64], k: usize, sigma: f64, mu: &[f64], out: &mut [f64]) {
        let (n, nu) = (self.n, self.nu);
        self.derivatives(z, k);
        let velocity = |i: usize, c: usize| mu[(3 * k + i) * 2 * n + c];
        let momentum = |i: usize, c: usize| mu[(3 * k + i) * 2 * n + n + c];
        let c = &self.problem.cost;
        let w = &self.work;
        let row = &self.step_scatter[k * (6 * n + nu)..][..6 * n + nu];
        let mut at = 0;
        for j in 1..4 {
            let b = A[2][j - 1];
            let point = self.point(3 * k + j);
            // The momentum rows' weights on this point's rates.
            let weight = |r: usize| -(0..3).map(|i| A[i][j - 1] * momentum(i, r)).sum::<f64>();
            for x in 0..n {
                let mut value = sigma * b * c.position[x] * (z[point + x] - c.position_reference[x]);
                for r in 0..n {
                    value += weight(r) * w.g_q[j][(r, x)];
                }
                out[row[at + x]] += value;
            }
            at += n;
            for x in 0..n {
                let mut value = sigma * b * c.velocity[x] * (z[point + n + x] - c.velocity_reference[x]);
                value -= (0..3).map(|i| A[i][j - 1] * velocity(i, x)).sum::<f64>();
                for r in 0..n {
                    value += weight(r) * w.g_v[j][(r, x)];
                }
                out[row[at + x]] += value;
            }
            at += n;
        }
        let start = self.input_start(k);
        for x in 0..nu {
            let mut value = sigma * c.input[x] * z[start + x];
            for j in 1..4 {
                for r in 0..n {
                    let weight = -(0..3).map(|i| A[i][j - 1] * momentum(i, r)).sum::<f64>();
                    value += weight * w.g_u[j][x * n + r];
                }
            }
            out[row[at + x]] += value;
        }
    }
}

impl<M> Transcription for Collocation<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    type Model = M;

    fn guess(&self) -> Vec<f64> {
        Collocation::guess(self)
    }

    fn check_guess(&mut self, z: &[f64]) -> Result<(), OptimalError> {
        Collocation::check_guess(self, z)
    }

    fn optimum(
        &mut self,
        z: &[f64],
        iterations: usize,
        status: &'static str,
        wall: std::time::Duration,
    ) -> Optimum {
        Collocation::optimum(self, z, iterations, status, wall)
    }

    fn reset_evaluation(&mut self) {
        self.evaluation = std::time::Duration::ZERO;
    }
}
