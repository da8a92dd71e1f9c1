//! Discrete mechanics and optimal control (DMOC, Ober-Blöbaum, Junge and Marsden 2011): the
//! problem's equations of motion are the discrete forced Euler-Lagrange equations of the
//! variational integrator, so an optimal trajectory is a trajectory of
//! [`Variational`](crate::Variational) with the inputs held over each interval, and keeps
//! every discrete momentum map of the problem's symmetries exactly.
//!
//! Variables: `z = (q_0, …, q_N, u_0, …, u_{N−1})`. Equations, `n` rows each (`D₁`, `D₂` of
//! each interval as in [`interval`](super::interval)):
//!
//! ```text
//! c_0 = p_0 + D₁(interval 0)                         p_0 = ∂L/∂v at the start
//! c_k = D₂(interval k − 1) + D₁(interval k)          k = 1 … N − 1
//! c_N = D₂(interval N − 1) − p_N                     only if the final velocity is given
//! ```
//!
//! With a free final time, the step of each interval is a variable too, `h_0 … h_{N−1}` after
//! the inputs, held equal by the rows `h_k − h_{k+1} = 0`: the horizon is `Σ h_k`, and each
//! equation reads only the steps of its own two intervals, so the KKT matrix stays banded.
//!
//! A bounded velocity is a variable of each interval, `w_k` after the steps, with the row
//! `q_{k+1} − q_k − h_k w_k = 0` (linear, or bilinear with a free final time): the bound is
//! then a bound on a variable, which every solver here takes, and the rows stay within their
//! interval.
//!
//! The Jacobian is stored in dense `n × n` and `n × n_u` blocks; the Hessian's pattern is the
//! model's generated pattern pulled back onto each interval, so it is known before the first
//! evaluation and holds no entry that is zero for every model of the type.

use std::collections::BTreeMap;

use nalgebra::{DMatrix, DefaultAllocator};

use crate::model::{DenseModel, InputsOutputs};
use crate::optimal::error::OptimalError;
use crate::optimal::interval::{END, Interval, MIDDLE, Map, START, add_pulled};
use crate::optimal::nlp::Nlp;
use crate::optimal::problem::Problem;
use crate::shape::dims::Storage;

/// A variable block: positions at node `k`, inputs on interval `k` or its step (free final
/// time).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Block {
    Q(usize),
    U(usize),
    H(usize),
}

/// The DMOC transcription of a [`Problem`] into a nonlinear program.
pub struct Dmoc<M>
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
    /// Whether the final velocity is given (the equations `c_N`).
    final_rows: bool,
    /// The coordinates whose velocity is bounded: each has a variable and a row per interval.
    bounded: Vec<usize>,
    /// Where the values of the steps' rows and of the velocities' rows start among the
    /// Jacobian's entries.
    step_entries: usize,
    velocity_entries: usize,
    /// For each interval and bounded velocity, the Hessian entry `(w_k, h_k)` (free final
    /// time).
    velocity_hessian: Vec<usize>,
    /// For each block row of equations, its variable blocks with their width and the offset of
    /// their values (row-major within the block row).
    rows: Vec<Vec<(Block, usize, usize)>>,
    jacobian_pattern: Vec<(usize, usize)>,
    /// The interval's Hessian pattern, `(a, b)` with `a ≥ b` in `z = (q_k, q_{k+1}, u_k)`.
    local: Vec<(usize, usize)>,
    /// For each interval, the global index of each entry of `local`.
    scatter: Vec<Vec<usize>>,
    hessian_pattern: Vec<(usize, usize)>,
    work: Interval<M>,
    d1: Vec<f64>,
    d2: Vec<f64>,
    /// Time spent in the model's generated functions and their assembly, for the statistics.
    pub(crate) evaluation: std::time::Duration,
}

impl<M> Dmoc<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    /// The transcription of `problem`, refused with a typed error if the problem is
    /// malformed.
    pub fn new(problem: Problem<M>) -> Result<Self, OptimalError> {
        problem.check()?;
        let (n, nu, intervals) = (M::NQ, M::NAMES.input_count(), problem.intervals);
        let h = problem.step();
        let free = problem.free_time.is_some();
        let final_rows = problem.final_velocity.is_some();
        let block_rows = intervals + usize::from(final_rows);
        let mut rows = Vec::with_capacity(block_rows);
        let mut jacobian_pattern = Vec::new();
        for j in 0..block_rows {
            let mut blocks = Vec::new();
            if j >= 1 {
                blocks.push(Block::Q(j - 1));
            }
            blocks.push(Block::Q(j));
            if j < intervals {
                blocks.push(Block::Q(j + 1));
            }
            if j >= 1 {
                blocks.push(Block::U(j - 1));
            }
            if j < intervals {
                blocks.push(Block::U(j));
            }
            if free && j >= 1 {
                blocks.push(Block::H(j - 1));
            }
            if free && j < intervals {
                blocks.push(Block::H(j));
            }
            let start = |block: Block| match block {
                Block::Q(k) => k * n,
                Block::U(k) => (intervals + 1) * n + k * nu,
                Block::H(k) => (intervals + 1) * n + intervals * nu + k,
            };
            let widths: Vec<usize> = blocks
                .iter()
                .map(|b| match b {
                    Block::Q(_) => n,
                    Block::U(_) => nu,
                    Block::H(_) => 1,
                })
                .collect();
            // Row-major over the block row: each equation's entries block by block, so block
            // `b` of equation `i` starts at `row_start + i * width + offset_b`.
            let row_start = jacobian_pattern.len();
            for i in 0..n {
                for (&block, &w) in blocks.iter().zip(&widths) {
                    jacobian_pattern.extend((0..w).map(|c| (j * n + i, start(block) + c)));
                }
            }
            let mut within = 0;
            let placed: Vec<(Block, usize, usize)> = blocks
                .iter()
                .zip(&widths)
                .map(|(&block, &w)| {
                    within += w;
                    (block, row_start + within - w, w)
                })
                .collect();
            rows.push(placed);
        }
        debug_assert!(rows.iter().all(|r| !r.is_empty()));
        let h0 = (intervals + 1) * n + intervals * nu;
        let step_entries = jacobian_pattern.len();
        if free {
            // h_k − h_{k+1} = 0.
            let row0 = block_rows * n;
            for k in 0..intervals - 1 {
                jacobian_pattern.extend([(row0 + k, h0 + k), (row0 + k, h0 + k + 1)]);
            }
        }
        // q_{k+1} − q_k − h_k w_k = 0 for each bounded velocity.
        let bounded = problem.velocity_bounded();
        let nb = bounded.len();
        let (row0, w0) = (block_rows * n + step_rows(free, intervals), h0 + step_variables(free, intervals));
        let velocity_entries = jacobian_pattern.len();
        let mut products = Vec::new();
        for k in 0..intervals {
            for (j, &i) in bounded.iter().enumerate() {
                let (row, w) = (row0 + k * nb + j, w0 + k * nb + j);
                jacobian_pattern.extend([(row, k * n + i), (row, (k + 1) * n + i), (row, w)]);
                if free {
                    jacobian_pattern.push((row, h0 + k));
                    products.push((w, h0 + k));
                }
            }
        }
        let local = local_pattern(&problem, n, nu, h, free);
        let Scattered { intervals: scatter, extra: velocity_hessian, pattern: hessian_pattern } =
            scatter(&local, &products, n, nu, intervals);
        let work = Interval::new(&problem.model);
        Ok(Dmoc {
            problem,
            n,
            nu,
            intervals,
            h,
            free,
            final_rows,
            bounded,
            step_entries,
            velocity_entries,
            velocity_hessian,
            rows,
            jacobian_pattern,
            local,
            scatter,
            hessian_pattern,
            work,
            d1: vec![0.0; n],
            d2: vec![0.0; n],
            evaluation: std::time::Duration::ZERO,
        })
    }

    /// The problem transcribed.
    pub fn problem(&self) -> &Problem<M> {
        &self.problem
    }

    /// The slice of `z` holding the positions at node `k`.
    pub fn node(&self, z: &[f64], k: usize) -> Vec<f64> {
        z[k * self.n..(k + 1) * self.n].to_vec()
    }

    /// The inputs on interval `k`.
    pub fn inputs(&self, z: &[f64], k: usize) -> Vec<f64> {
        let start = (self.intervals + 1) * self.n + k * self.nu;
        z[start..start + self.nu].to_vec()
    }

    fn set_inputs(&mut self, z: &[f64], k: usize) {
        let start = (self.intervals + 1) * self.n + k * self.nu;
        for i in 0..self.nu {
            self.problem.model.set_input_value(i, z[start + i]);
        }
    }

    /// Where the step of interval `k` is in `z` (free final time).
    fn step_index(&self, k: usize) -> usize {
        (self.intervals + 1) * self.n + self.intervals * self.nu + k
    }

    /// Where the velocity `j` of the bounded ones is in `z` on interval `k`.
    pub(crate) fn velocity_index(&self, k: usize, j: usize) -> usize {
        let h0 = (self.intervals + 1) * self.n + self.intervals * self.nu;
        h0 + step_variables(self.free, self.intervals) + k * self.bounded.len() + j
    }

    /// The row of interval `k`'s bounded velocity `j`.
    pub(crate) fn velocity_row(&self, k: usize, j: usize) -> usize {
        self.rows.len() * self.n + step_rows(self.free, self.intervals) + k * self.bounded.len() + j
    }

    /// The number of bounded velocities (each a variable and a row on every interval).
    pub(crate) fn bounded_velocities(&self) -> usize {
        self.bounded.len()
    }

    /// The step of interval `k`: the problem's, or the variable's with a free final time.
    pub(crate) fn step(&self, z: &[f64], k: usize) -> f64 {
        if self.free { z[self.step_index(k)] } else { self.h }
    }

    /// The time at node `k`.
    pub(crate) fn time(&self, z: &[f64], k: usize) -> f64 {
        match self.free {
            true => self.problem.t0 + (0..k).map(|j| z[self.step_index(j)]).sum::<f64>(),
            false => self.problem.t0 + k as f64 * self.h,
        }
    }

    /// The discrete momenta `p_k` at every node: `p_k = −D₁(interval k)` and
    /// `p_N = D₂(interval N − 1)`, the momenta of the variational integrator's steps.
    pub fn momenta(&mut self, z: &[f64]) -> Vec<Vec<f64>> {
        let n = self.n;
        let mut out = Vec::with_capacity(self.intervals + 1);
        for k in 0..self.intervals {
            self.set_inputs(z, k);
            let (a, b) = (&z[k * n..(k + 1) * n], &z[(k + 1) * n..(k + 2) * n]);
            let (t, h) = (self.time(z, k), self.step(z, k));
            self.work.residual(&self.problem.model, t, a, b, h, &mut self.d1, &mut self.d2);
            out.push(self.d1.iter().map(|x| -x).collect());
            if k + 1 == self.intervals {
                out.push(self.d2.clone());
            }
        }
        out
    }

    /// The momenta `∂L/∂v` at the given state `(q, v)` at time `t`, with the inputs set.
    fn given_momenta(&mut self, t: f64, q: &[f64], v: &[f64]) {
        for i in 0..self.n {
            self.work.q[i] = q[i];
            self.work.v[i] = v[i];
        }
        self.problem.model.dl_dv(t, &self.work.q, &self.work.v, &mut self.work.out);
    }

    /// The guess as a point of `z`.
    pub fn guess(&self) -> Vec<f64> {
        let (n, nu, intervals) = (self.n, self.nu, self.intervals);
        let mut z = vec![0.0; self.variables()];
        let (positions, inputs) = self.problem.guessed_nodes();
        for (k, q) in positions.iter().enumerate() {
            z[k * n..(k + 1) * n].copy_from_slice(q);
        }
        for (k, u) in inputs.iter().enumerate() {
            let start = (intervals + 1) * n + k * nu;
            z[start..start + nu].copy_from_slice(u);
        }
        if self.free {
            for k in 0..intervals {
                z[self.step_index(k)] = self.h;
            }
        }
        for k in 0..intervals {
            for (j, &i) in self.bounded.iter().enumerate() {
                let (lower, upper) = self.problem.velocity_bounds[i];
                let v = (positions[k + 1][i] - positions[k][i]) / self.h;
                z[self.velocity_index(k, j)] = v.clamp(lower, upper);
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
        // The steps' and velocities' rows are linear in a finite guess: only the equations can
        // fail.
        if let Some(row) = g[..self.rows.len() * self.n].iter().position(|x| !x.is_finite()) {
            let (block, i) = (row / self.n, row % self.n);
            let name = &self.problem.model.coordinate_names()[i];
            return Err(OptimalError::NotFiniteAtGuess {
                what: "the discrete equations",
                detail: format!("the balance of `{name}` at node {block} is {}", g[row]),
            });
        }
        if self.free {
            let horizon = self.problem.horizon;
            super::refuse_time_dependence::<M, _>(self, |t| &mut t.problem.t0, horizon, z)?;
        }
        Ok(())
    }

    /// Adds the running cost's Hessian on the interval from `a` to `b` with inputs `u` and
    /// step `h` (scaled by `sigma`) to the work's.
    #[allow(clippy::too_many_arguments)]
    fn add_cost_hessian(&mut self, sigma: f64, last: bool, a: &[f64], b: &[f64], u: &[f64], h: f64) {
        let (n, nu) = (self.n, self.nu);
        let c = &self.problem.cost;
        let hessian = &mut self.work.hessian;
        for i in 0..n {
            add_pulled(hessian, MIDDLE, n, h, i, i, sigma * h * c.position[i]);
            add_pulled(hessian, MIDDLE, n, h, n + i, n + i, sigma * h * c.velocity[i]);
            if last {
                hessian[(n + i, n + i)] += sigma * c.terminal[i];
            }
        }
        for i in 0..nu {
            hessian[(2 * n + i, 2 * n + i)] += sigma * h * c.input[i];
        }
        if self.free {
            // `∂/∂h` of `h/2 [w (q̄ − q̂)² + c (v − v̂)² + r u²]` is
            // `w/2 (q̄ − q̂)² + c/2 (v̂² − v²) + r/2 u²`, with `v = (b − a)/h`.
            let step = 2 * n + nu;
            let mut along_h = 0.0;
            let mut add = |x: usize, value: f64| {
                hessian[(x, step)] += sigma * value;
                hessian[(step, x)] += sigma * value;
            };
            for i in 0..n {
                let mid = c.position[i] * (0.5 * (a[i] + b[i]) - c.position_reference[i]);
                let v = (b[i] - a[i]) / h;
                add(i, 0.5 * mid + c.velocity[i] * v / h);
                add(n + i, 0.5 * mid - c.velocity[i] * v / h);
                along_h += c.velocity[i] * v * v / h;
            }
            for (i, (r, u)) in c.input.iter().zip(u).enumerate() {
                add(2 * n + i, r * u);
            }
            hessian[(step, step)] += sigma * along_h;
        }
    }
}

/// The steps' variables: one per interval with a free final time.
fn step_variables(free: bool, intervals: usize) -> usize {
    if free { intervals } else { 0 }
}

/// The steps' rows `h_k − h_{k+1} = 0`.
fn step_rows(free: bool, intervals: usize) -> usize {
    if free { intervals - 1 } else { 0 }
}

/// The lower triangle of an interval's Hessian that any point of the model may fill: the
/// model's pattern pulled back through the three points, and the cost's diagonal.
fn local_pattern<M>(problem: &Problem<M>, n: usize, nu: usize, h: f64, free: bool) -> Vec<(usize, usize)>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    let d = 2 * n + nu + usize::from(free);
    let mut mark = DMatrix::from_element(d, d, false);
    for map in [START, END, MIDDLE] {
        for &(r, c) in problem.model.weighted_hessian_pattern() {
            mark_pulled(&mut mark, map, n, h, r, c);
        }
    }
    let cost = &problem.cost;
    for i in 0..n {
        let ones = [(cost.position[i], i), (cost.velocity[i], n + i)];
        for (w, r) in ones {
            if w != 0.0 {
                mark_pulled(&mut mark, MIDDLE, n, h, r, r);
            }
        }
        if cost.terminal[i] != 0.0 {
            mark[(n + i, n + i)] = true;
        }
    }
    for i in 0..nu {
        if cost.input[i] != 0.0 {
            mark[(2 * n + i, 2 * n + i)] = true;
        }
    }
    if free {
        // The step moves every point's velocity and scales the rest: its row is full.
        mark.row_mut(d - 1).fill(true);
    }
    let mut local = Vec::new();
    for a in 0..d {
        for b in 0..=a {
            if mark[(a, b)] || mark[(b, a)] {
                local.push((a, b));
            }
        }
    }
    local
}

/// Marks the entries of `z` that entry `(r, c)` of an `x`-space Hessian reaches through `map`
/// (whatever the values: pulled entries that cancel for some model are still structural).
fn mark_pulled(mark: &mut DMatrix<bool>, map: Map, n: usize, h: f64, r: usize, c: usize) {
    for (a, pa) in map.column(r, n, h) {
        for (b, pb) in map.column(c, n, h) {
            if pa != 0.0 && pb != 0.0 {
                mark[(a, b)] = true;
                mark[(b, a)] = true;
            }
        }
    }
}

/// Where the Hessian's entries go among the global pattern's.
struct Scattered {
    /// For each interval, the global index of each of its local entries.
    intervals: Vec<Vec<usize>>,
    /// The global index of each extra entry.
    extra: Vec<usize>,
    /// The global pattern, deduplicated and ordered by row then column.
    pattern: Vec<(usize, usize)>,
}

/// The global index of each interval's local entries and of the `extra` entries (each
/// `row ≥ column`), and the global pattern.
fn scatter(
    local: &[(usize, usize)],
    extra: &[(usize, usize)],
    n: usize,
    nu: usize,
    intervals: usize,
) -> Scattered {
    let global = |k: usize, a: usize| match a {
        a if a < 2 * n => k * n + a,
        a if a < 2 * n + nu => (intervals + 1) * n + k * nu + (a - 2 * n),
        _ => (intervals + 1) * n + intervals * nu + k,
    };
    let mut index = BTreeMap::new();
    for k in 0..intervals {
        for &(a, b) in local {
            index.entry((global(k, a), global(k, b))).or_insert(0usize);
        }
    }
    for &entry in extra {
        index.entry(entry).or_insert(0);
    }
    for (i, value) in index.values_mut().enumerate() {
        *value = i;
    }
    Scattered {
        intervals: (0..intervals)
            .map(|k| local.iter().map(|&(a, b)| index[&(global(k, a), global(k, b))]).collect())
            .collect(),
        extra: extra.iter().map(|entry| index[entry]).collect(),
        pattern: index.into_keys().collect(),
    }
}

impl<M> Nlp for Dmoc<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    fn variables(&self) -> usize {
        self.velocity_index(self.intervals, 0)
    }

    fn constraints(&self) -> usize {
        self.velocity_row(self.intervals, 0)
    }

    fn variable_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
        let (n, nu, p) = (self.n, self.nu, &self.problem);
        for k in 0..=self.intervals {
            for i in 0..n {
                let (l, u) = p.position_bounds[i];
                let fixed = match k {
                    0 => Some(p.q0[i]),
                    k if k == self.intervals => p.final_position[i],
                    _ => None,
                };
                (lower[k * n + i], upper[k * n + i]) = fixed.map_or((l, u), |x| (x, x));
            }
        }
        for k in 0..self.intervals {
            for i in 0..nu {
                let at = (self.intervals + 1) * n + k * nu + i;
                (lower[at], upper[at]) = p.input_bounds[i];
            }
        }
        if let Some((shortest, longest)) = p.free_time {
            let per = self.intervals as f64;
            for k in 0..self.intervals {
                let at = self.step_index(k);
                (lower[at], upper[at]) = (shortest / per, longest / per);
            }
        }
        for k in 0..self.intervals {
            for (j, &i) in self.bounded.iter().enumerate() {
                let at = self.velocity_index(k, j);
                (lower[at], upper[at]) = p.velocity_bounds[i];
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
            let (a, b) = (&z[k * n..(k + 1) * n], &z[(k + 1) * n..(k + 2) * n]);
            for i in 0..n {
                let mid = 0.5 * (a[i] + b[i]) - c.position_reference[i];
                let v = (b[i] - a[i]) / h - c.velocity_reference[i];
                total += 0.5 * h * (c.position[i] * mid * mid + c.velocity[i] * v * v);
            }
            let u = &z[(self.intervals + 1) * n + k * nu..][..nu];
            total += 0.5 * h * u.iter().zip(&c.input).map(|(u, r)| r * u * u).sum::<f64>();
        }
        let end = &z[self.intervals * n..(self.intervals + 1) * n];
        for ((x, reference), w) in end.iter().zip(&c.terminal_reference).zip(&c.terminal) {
            total += 0.5 * w * (x - reference) * (x - reference);
        }
        total
    }

    fn gradient(&mut self, z: &[f64], out: &mut [f64]) {
        let (n, nu, c) = (self.n, self.nu, &self.problem.cost);
        out.fill(0.0);
        for k in 0..self.intervals {
            let h = self.step(z, k);
            // `∂/∂h` of the interval's running cost and of `ρ h` (free final time).
            let mut along_h = c.time;
            for i in 0..n {
                let (a, b) = (z[k * n + i], z[(k + 1) * n + i]);
                let offset = 0.5 * (a + b) - c.position_reference[i];
                let mid = c.position[i] * offset * 0.5 * h;
                let v = (b - a) / h;
                let dv = c.velocity[i] * (v - c.velocity_reference[i]);
                out[k * n + i] += mid - dv;
                out[(k + 1) * n + i] += mid + dv;
                let reference = c.velocity_reference[i];
                along_h += 0.5 * c.position[i] * offset * offset
                    + 0.5 * c.velocity[i] * (reference * reference - v * v);
            }
            let start = (self.intervals + 1) * n + k * nu;
            for i in 0..nu {
                out[start + i] = h * c.input[i] * z[start + i];
                along_h += 0.5 * c.input[i] * z[start + i] * z[start + i];
            }
            if self.free {
                out[self.step_index(k)] = along_h;
            }
        }
        let end = self.intervals * n;
        for i in 0..n {
            out[end + i] += c.terminal[i] * (z[end + i] - c.terminal_reference[i]);
        }
    }

    fn constraint_values(&mut self, z: &[f64], out: &mut [f64]) {
        let started = std::time::Instant::now();
        let n = self.n;
        out.fill(0.0);
        for k in 0..self.intervals {
            self.set_inputs(z, k);
            let (t, h) = (self.time(z, k), self.step(z, k));
            if k == 0 {
                let (q0, v0) = (self.problem.q0.clone(), self.problem.v0.clone());
                self.given_momenta(t, q0.as_slice(), v0.as_slice());
                for (g, p) in out.iter_mut().zip(self.work.out.iter()) {
                    *g += p;
                }
            }
            let (a, b) = (&z[k * n..(k + 1) * n], &z[(k + 1) * n..(k + 2) * n]);
            self.work.residual(&self.problem.model, t, a, b, h, &mut self.d1, &mut self.d2);
            for i in 0..n {
                out[k * n + i] += self.d1[i];
                if k + 1 < self.intervals || self.final_rows {
                    out[(k + 1) * n + i] += self.d2[i];
                }
            }
        }
        if let Some(v_end) = self.problem.final_velocity.clone() {
            let last = self.intervals;
            self.given_momenta(self.time(z, last), &z[last * n..(last + 1) * n], v_end.as_slice());
            for i in 0..n {
                out[last * n + i] -= self.work.out[i];
            }
        }
        if self.free {
            let row0 = self.rows.len() * n;
            for k in 0..self.intervals - 1 {
                out[row0 + k] = z[self.step_index(k)] - z[self.step_index(k + 1)];
            }
        }
        for k in 0..self.intervals {
            let h = self.step(z, k);
            for (j, &i) in self.bounded.iter().enumerate() {
                let w = z[self.velocity_index(k, j)];
                out[self.velocity_row(k, j)] = z[(k + 1) * n + i] - z[k * n + i] - h * w;
            }
        }
        self.evaluation += started.elapsed();
    }

    fn jacobian_pattern(&self) -> &[(usize, usize)] {
        &self.jacobian_pattern
    }

    fn jacobian_values(&mut self, z: &[f64], out: &mut [f64]) {
        let started = std::time::Instant::now();
        let n = self.n;
        const GIVEN_START: Map = Map { alpha: 0.0, beta: 0.0, gamma: 0.0 };
        const GIVEN_END: Map = Map { alpha: 0.0, beta: 1.0, gamma: 0.0 };
        out.fill(0.0);
        for k in 0..self.intervals {
            self.set_inputs(z, k);
            let (t, h) = (self.time(z, k), self.step(z, k));
            let (a, b) = (&z[k * n..(k + 1) * n], &z[(k + 1) * n..(k + 2) * n]);
            self.work.jacobian(&self.problem.model, t, a, b, h, self.free);
            // D₁ into the equations of node k, D₂ into those of node k + 1.
            self.add_rows(out, k, 0, k);
            self.add_rows(out, k + 1, n, k);
            if k == 0 {
                // p_0 = ∂L/∂v(q_0, v_0, u_0) reads u_0 where an input enters the momenta.
                let (q0, v0) = (self.problem.q0.clone(), self.problem.v0.clone());
                self.given_momenta(t, q0.as_slice(), v0.as_slice());
                self.work.jacobian.fill(0.0);
                self.work.momentum_jacobian(&self.problem.model, t);
                self.work.pull_lv(GIVEN_START, 0, 1.0, h);
                self.add_rows(out, 0, 0, 0);
            }
        }
        if let Some(v_end) = self.problem.final_velocity.clone() {
            let (last, h) = (self.intervals, self.step(z, self.intervals - 1));
            self.set_inputs(z, last - 1);
            let t = self.time(z, last);
            self.given_momenta(t, &z[last * n..(last + 1) * n], v_end.as_slice());
            self.work.jacobian.fill(0.0);
            self.work.momentum_jacobian(&self.problem.model, t);
            self.work.pull_lv(GIVEN_END, 0, -1.0, h);
            self.add_rows(out, last, 0, last - 1);
        }
        let steps = &mut out[self.step_entries..self.velocity_entries];
        for pair in steps.chunks_exact_mut(2) {
            pair.copy_from_slice(&[1.0, -1.0]);
        }
        let mut at = self.velocity_entries;
        for k in 0..self.intervals {
            let h = self.step(z, k);
            for j in 0..self.bounded.len() {
                out[at..at + 3].copy_from_slice(&[-1.0, 1.0, -h]);
                at += 3;
                if self.free {
                    out[at] = -z[self.velocity_index(k, j)];
                    at += 1;
                }
            }
        }
        debug_assert_eq!(at, out.len());
        self.evaluation += started.elapsed();
    }

    fn hessian_pattern(&self) -> &[(usize, usize)] {
        &self.hessian_pattern
    }

    fn hessian_values(&mut self, z: &[f64], sigma: f64, mu: &[f64], out: &mut [f64]) {
        let started = std::time::Instant::now();
        let n = self.n;
        out.fill(0.0);
        for k in 0..self.intervals {
            self.set_inputs(z, k);
            let (t, h) = (self.time(z, k), self.step(z, k));
            let (a, b) = (&z[k * n..(k + 1) * n], &z[(k + 1) * n..(k + 2) * n]);
            self.work.hessian.fill(0.0);
            let after = k + 1 < self.rows.len();
            for i in 0..n {
                let before = mu[k * n + i];
                let next = if after { mu[(k + 1) * n + i] } else { 0.0 };
                self.work.wq[i] = 0.5 * h * before;
                self.work.wv[i] = 0.5 * (next - before);
                self.work.wf[i] = 0.0;
            }
            self.work.place(START, a, b, h);
            self.work.add_point_hessian(&self.problem.model, t, START, h);
            if self.free {
                self.work.add_step_hessian(&self.problem.model, t, START, h);
            }
            for i in 0..n {
                let next = if after { mu[(k + 1) * n + i] } else { 0.0 };
                self.work.wq[i] = 0.5 * h * next;
            }
            self.work.place(END, a, b, h);
            self.work.add_point_hessian(&self.problem.model, t + h, END, h);
            if self.free {
                self.work.add_step_hessian(&self.problem.model, t + h, END, h);
            }
            for i in 0..n {
                let next = if after { mu[(k + 1) * n + i] } else { 0.0 };
                self.work.wf[i] = 0.5 * h * (mu[k * n + i] + next);
                self.work.wq[i] = 0.0;
                self.work.wv[i] = 0.0;
            }
            self.work.place(MIDDLE, a, b, h);
            self.work.add_point_hessian(&self.problem.model, t + 0.5 * h, MIDDLE, h);
            if self.free {
                self.work.add_step_hessian(&self.problem.model, t + 0.5 * h, MIDDLE, h);
            }
            self.work.wf.fill(0.0);
            if k == 0 {
                // p_0's dependence on u_0.
                let (q0, v0) = (self.problem.q0.clone(), self.problem.v0.clone());
                self.work.q.copy_from(&q0);
                self.work.v.copy_from(&v0);
                self.work.wv.copy_from_slice(&mu[..n]);
                self.work.add_point_hessian(
                    &self.problem.model,
                    t,
                    Map { alpha: 0.0, beta: 0.0, gamma: 0.0 },
                    h,
                );
            }
            if k + 1 == self.intervals && self.final_rows {
                let v_end = self.problem.final_velocity.clone().expect("final rows have a final velocity");
                for i in 0..n {
                    self.work.q[i] = b[i];
                    self.work.wv[i] = -mu[(k + 1) * n + i];
                }
                self.work.v.copy_from(&v_end);
                self.work.add_point_hessian(
                    &self.problem.model,
                    t + h,
                    Map { alpha: 0.0, beta: 1.0, gamma: 0.0 },
                    h,
                );
            }
            let u = &z[(self.intervals + 1) * n + k * self.nu..][..self.nu];
            self.add_cost_hessian(sigma, k + 1 == self.intervals, a, b, u, h);
            for (&(a, b), &at) in self.local.iter().zip(&self.scatter[k]) {
                out[at] += self.work.hessian[(a, b)];
            }
        }
        // `−μ h_k w_k` of each bounded velocity's row (free final time).
        let nb = self.bounded.len();
        for (e, &at) in self.velocity_hessian.iter().enumerate() {
            out[at] -= mu[self.velocity_row(e / nb, e % nb)];
        }
        self.evaluation += started.elapsed();
    }
}

impl<M> Dmoc<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    /// Adds rows `row0..row0 + n` of the work's interval Jacobian (columns
    /// `(q_k, q_{k+1}, u_k)` of interval `k`) to the equations of node `node`, if the problem
    /// has them.
    fn add_rows(&self, out: &mut [f64], node: usize, row0: usize, k: usize) {
        let Some(blocks) = self.rows.get(node) else { return };
        let n = self.n;
        let width: usize = blocks.iter().map(|b| b.2).sum();
        for &(block, offset, w) in blocks {
            let column0 = match block {
                Block::Q(j) if j == k => 0,
                Block::Q(j) if j == k + 1 => n,
                Block::U(j) if j == k => 2 * n,
                Block::H(j) if j == k => 2 * n + self.nu,
                _ => continue,
            };
            for i in 0..n {
                for c in 0..w {
                    out[offset + i * width + c] += self.work.jacobian[(row0 + i, column0 + c)];
                }
            }
        }
    }
}
