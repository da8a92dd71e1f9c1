//! Model-predictive control: at every sample, the problem is solved again from the measured
//! state over the horizon ahead, and its first input is applied until the next sample.
//!
//! Each solve is warm started from the last solution moved forward by the time elapsed (the
//! nodes interpolated, the inputs and multipliers carried with them), and runs on the
//! [`InteriorPoint`], whose KKT order and band were fixed when the controller was made: no
//! set-up per sample. Every sample's solve time, iterations and status are kept
//! ([`Mpc::samples`]). A sample whose solve fails holds the last plan's input for that time,
//! and its status says why.

use std::time::{Duration, Instant};

use nalgebra::DefaultAllocator;

use crate::model::state::State;
use crate::model::{DenseModel, InputsOutputs};
use crate::optimal::dmoc::Dmoc;
use crate::optimal::error::OptimalError;
use crate::optimal::interior::{InteriorOptions, InteriorPoint};
use crate::optimal::nlp::Nlp;
use crate::optimal::problem::Problem;
use crate::shape::dims::Storage;

/// One sample of a receding-horizon controller.
#[derive(Clone, Debug)]
pub struct MpcSample {
    /// The sample's time.
    pub t: f64,
    /// The wall time of its solve.
    pub solve: Duration,
    /// The solver's iterations.
    pub iterations: usize,
    /// The solver's status (`Solve_Succeeded`, or the failure's name).
    pub status: &'static str,
    /// The inputs applied.
    pub inputs: Vec<f64>,
}

/// A receding-horizon controller on a [`Problem`]: its horizon, grid, cost, bounds and targets
/// are kept, its start is the measured state at each sample.
pub struct Mpc<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    dmoc: Dmoc<M>,
    solver: InteriorPoint,
    options: InteriorOptions,
    samples: Vec<MpcSample>,
    /// The last solution's start time and its inputs per interval, for the next warm start and
    /// for a sample whose solve fails.
    planned: Option<f64>,
    plan: Vec<f64>,
    shifted_x: Vec<f64>,
    shifted_lambda: Vec<f64>,
    inputs: Vec<f64>,
}

impl<M> Mpc<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    /// The controller for `problem` (its start is replaced by the state at each sample), or
    /// the typed error that makes the problem unusable.
    pub fn new(problem: Problem<M>, options: InteriorOptions) -> Result<Self, OptimalError> {
        if problem.free_time.is_some() {
            let why = "a receding horizon keeps its length from sample to sample; drop `free_final_time`";
            return Err(OptimalError::FixedTimeOnly { what: "Mpc", why });
        }
        let dmoc = Dmoc::new(problem)?;
        let solver = InteriorPoint::new(&dmoc)
            .map_err(|why| OptimalError::Unsupported { model: core::any::type_name::<M>(), why })?;
        let (variables, equations) = (dmoc.variables(), dmoc.constraints());
        let nu = M::NAMES.input_count();
        Ok(Mpc {
            dmoc,
            solver,
            options,
            samples: Vec::new(),
            planned: None,
            plan: Vec::new(),
            shifted_x: vec![0.0; variables],
            shifted_lambda: vec![0.0; equations],
            inputs: vec![0.0; nu],
        })
    }

    /// Every sample so far, in time order.
    pub fn samples(&self) -> &[MpcSample] {
        &self.samples
    }

    /// The median solve time over the samples (zero before the first).
    pub fn median_solve(&self) -> Duration {
        let mut times: Vec<Duration> = self.samples.iter().map(|s| s.solve).collect();
        times.sort_unstable();
        times.get(times.len() / 2).copied().unwrap_or_default()
    }

    /// The transcription, with the last sample's start.
    pub fn dmoc(&self) -> &Dmoc<M> {
        &self.dmoc
    }

    /// Solves from the state `(q, v)` at time `t` and returns the inputs to apply now: the
    /// first interval's of the new plan, or, if the solve fails, the last plan's at `t` (zero
    /// before any plan), with the failure recorded in [`samples`](Self::samples).
    pub fn control(&mut self, t: f64, q: &[f64], v: &[f64]) -> &[f64] {
        let started = Instant::now();
        {
            let problem = &mut self.dmoc.problem;
            problem.t0 = t;
            for i in 0..M::NQ {
                problem.q0[i] = q[i];
                problem.v0[i] = v[i];
            }
        }
        let finite = q.iter().chain(v).all(|x| x.is_finite());
        let result = match (finite, self.planned) {
            (false, _) => None,
            (true, None) => Some(self.solver.solve(&mut self.dmoc, &self.options)),
            (true, Some(t_last)) => {
                self.shift(t - t_last);
                Some(self.solver.resolve(&mut self.dmoc, &self.options))
            }
        };
        let (status, iterations) = match &result {
            Some(r) => (r.status, r.iterations),
            None => ("Invalid_Number_Detected", 0),
        };
        let nu = self.inputs.len();
        let first_input = (self.dmoc.problem.intervals + 1) * M::NQ;
        match result {
            Some(r) if r.solved => {
                let z = self.solver.point();
                self.inputs.copy_from_slice(&z[first_input..first_input + nu]);
                self.plan.clear();
                self.plan.extend_from_slice(&z[first_input..]);
                self.planned = Some(t);
            }
            _ => {
                // Hold the last plan's input for this time; a later sample restarts cold.
                match self.planned {
                    Some(t_last) => {
                        let h = self.dmoc.problem.step();
                        let k = (((t - t_last) / h).floor().max(0.0) as usize)
                            .min(self.dmoc.problem.intervals - 1);
                        self.inputs.copy_from_slice(&self.plan[k * nu..(k + 1) * nu]);
                    }
                    None => self.inputs.fill(0.0),
                }
                self.planned = None;
            }
        }
        self.samples.push(MpcSample {
            t,
            solve: started.elapsed(),
            iterations,
            status,
            inputs: self.inputs.clone(),
        });
        &self.inputs
    }

    /// As [`control`](Self::control), with the inputs written into `model`: the sampled
    /// controller of a run, `.every(period, |t, state, model| mpc.apply(t, state, model))`.
    pub fn apply(&mut self, t: f64, state: &State<M>, model: &mut M) {
        let inputs = self.control(t, state.q.as_slice(), state.v.as_slice());
        for (k, &u) in inputs.iter().enumerate() {
            model.set_input_value(k, u);
        }
    }

    /// Moves the last solution forward by `dt`: each node to the last plan's position at its
    /// new time (linear between nodes, the last held), each interval's inputs and bounded
    /// velocities, and each node's multipliers likewise.
    fn shift(&mut self, dt: f64) {
        let (n, nu, intervals) = (M::NQ, self.inputs.len(), self.dmoc.problem.intervals);
        let h = self.dmoc.problem.step();
        let s = (dt / h).max(0.0);
        let nb = self.dmoc.bounded_velocities();
        let (w0, row0) = (self.dmoc.velocity_index(0, 0), self.dmoc.velocity_row(0, 0));
        let block_rows = row0 / n;
        let (x, lambda) = self.solver.point_mut();
        let at = |k: usize| -> (usize, f64) {
            let position = k as f64 + s;
            let base = position.floor();
            ((base as usize).min(intervals), position - base)
        };
        for k in 0..=intervals {
            let (j, w) = at(k);
            for i in 0..n {
                let a = x[j * n + i];
                let b = if j < intervals { x[(j + 1) * n + i] } else { a };
                self.shifted_x[k * n + i] = a + w * (b - a);
            }
        }
        for k in 0..intervals {
            let (j, _) = at(k);
            let j = j.min(intervals - 1);
            let from = (intervals + 1) * n + j * nu;
            let to = (intervals + 1) * n + k * nu;
            self.shifted_x[to..to + nu].copy_from_slice(&x[from..from + nu]);
            let (from, to) = (j * nb, k * nb);
            self.shifted_x[w0 + to..w0 + to + nb].copy_from_slice(&x[w0 + from..w0 + from + nb]);
            self.shifted_lambda[row0 + to..row0 + to + nb]
                .copy_from_slice(&lambda[row0 + from..row0 + from + nb]);
        }
        for k in 0..block_rows {
            let (j, w) = at(k);
            let j = j.min(block_rows - 1);
            for i in 0..n {
                let a = lambda[j * n + i];
                let b = if j + 1 < block_rows { lambda[(j + 1) * n + i] } else { a };
                self.shifted_lambda[k * n + i] = a + w * (b - a);
            }
        }
        x.copy_from_slice(&self.shifted_x);
        lambda.copy_from_slice(&self.shifted_lambda);
    }
}
