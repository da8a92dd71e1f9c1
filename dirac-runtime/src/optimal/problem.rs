//! An optimal control problem on a model with inputs: the horizon and its grid, where the
//! motion starts and must end, the bounds on positions, velocities and inputs, a quadratic
//! cost, and the guess the solver starts from.

use nalgebra::DefaultAllocator;

use crate::model::keys::{Coordinate, Input};
use crate::model::{DenseModel, InputsOutputs};
use crate::optimal::error::OptimalError;
use crate::shape::dims::{Storage, VecQ};

/// `min J(q, u)` over the positions `q_0 … q_N` at the nodes of a uniform grid and the inputs
/// `u_0 … u_{N−1}` held over its intervals, subject to the model's discrete equations of
/// motion, the start, the targets and the bounds.
///
/// The cost is quadratic: over each interval `k`, of length `h`,
/// `h/2 · Σ r_i u_i² + h/2 · Σ w_i (q̄_i − q̂_i)² + h/2 · Σ c_i (v_i − v̂_i)²`, with `q̄` the
/// interval's midpoint and `v = (q_{k+1} − q_k)/h` its velocity, and at the end
/// `1/2 · Σ W_i (q_N,i − q̂_N,i)²`. Every weight defaults to zero; an input without a weight of
/// its own (`input_weight`) costs `u_i²/2` per second.
pub struct Problem<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    pub(crate) model: M,
    pub(crate) t0: f64,
    pub(crate) horizon: f64,
    pub(crate) intervals: usize,
    pub(crate) q0: VecQ<M>,
    pub(crate) v0: VecQ<M>,
    pub(crate) final_position: Vec<Option<f64>>,
    pub(crate) final_velocity: Option<VecQ<M>>,
    pub(crate) position_bounds: Vec<(f64, f64)>,
    pub(crate) velocity_bounds: Vec<(f64, f64)>,
    pub(crate) input_bounds: Vec<(f64, f64)>,
    /// The bounds of a free final time, `None` if the horizon is fixed.
    pub(crate) free_time: Option<(f64, f64)>,
    pub(crate) cost: Cost,
    pub(crate) guess: Option<Guess>,
}

impl<M> Clone for Problem<M>
where
    M: DenseModel + InputsOutputs + Clone,
    DefaultAllocator: Storage<M>,
{
    fn clone(&self) -> Self {
        Problem {
            model: self.model.clone(),
            t0: self.t0,
            horizon: self.horizon,
            intervals: self.intervals,
            q0: self.q0.clone(),
            v0: self.v0.clone(),
            final_position: self.final_position.clone(),
            final_velocity: self.final_velocity.clone(),
            position_bounds: self.position_bounds.clone(),
            velocity_bounds: self.velocity_bounds.clone(),
            input_bounds: self.input_bounds.clone(),
            free_time: self.free_time,
            cost: self.cost.clone(),
            guess: self.guess.clone(),
        }
    }
}

/// The weights and references of the quadratic cost (see [`Problem`]).
#[derive(Clone, Debug, Default)]
pub(crate) struct Cost {
    pub input: Vec<f64>,
    pub position: Vec<f64>,
    pub position_reference: Vec<f64>,
    pub velocity: Vec<f64>,
    pub velocity_reference: Vec<f64>,
    pub terminal: Vec<f64>,
    pub terminal_reference: Vec<f64>,
    /// The weight `ρ` of the final time: `ρ (t_N − t_0)`.
    pub time: f64,
}

/// Where the solver starts: positions at every node and inputs on every interval.
#[derive(Clone, Debug)]
pub(crate) struct Guess {
    pub positions: Vec<Vec<f64>>,
    pub inputs: Vec<Vec<f64>>,
}

impl<M> Problem<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    /// A problem over `horizon` seconds from `t = 0`, on `intervals` intervals, starting at rest
    /// at `q = 0`, with no target, no bounds and the cost `Σ u_i²/2` per second.
    pub fn new(model: M, horizon: f64, intervals: usize) -> Self {
        let (n, nu) = (M::NQ, M::NAMES.input_count());
        Problem {
            model,
            t0: 0.0,
            horizon,
            intervals,
            q0: VecQ::<M>::zeros(),
            v0: VecQ::<M>::zeros(),
            final_position: vec![None; n],
            final_velocity: None,
            position_bounds: vec![(f64::NEG_INFINITY, f64::INFINITY); n],
            velocity_bounds: vec![(f64::NEG_INFINITY, f64::INFINITY); n],
            input_bounds: vec![(f64::NEG_INFINITY, f64::INFINITY); nu],
            free_time: None,
            cost: Cost {
                input: vec![1.0; nu],
                position: vec![0.0; n],
                position_reference: vec![0.0; n],
                velocity: vec![0.0; n],
                velocity_reference: vec![0.0; n],
                terminal: vec![0.0; n],
                terminal_reference: vec![0.0; n],
                time: 0.0,
            },
            guess: None,
        }
    }

    /// The model, with the inputs it was given.
    pub fn model(&self) -> &M {
        &self.model
    }

    /// The time at the start (0 unless set), for models that read time.
    pub fn starting_at(mut self, t0: f64) -> Self {
        self.t0 = t0;
        self
    }

    /// Positions and velocities at the start.
    pub fn start(mut self, q: VecQ<M>, v: VecQ<M>) -> Self {
        self.q0 = q;
        self.v0 = v;
        self
    }

    /// The position coordinate `c` must reach at the end.
    pub fn final_position(mut self, c: Coordinate<M>, value: f64) -> Self {
        self.final_position[c.index()] = Some(value);
        self
    }

    /// Every position and velocity at the end: a full final state.
    pub fn final_state(mut self, q: VecQ<M>, v: VecQ<M>) -> Self {
        for (target, &value) in self.final_position.iter_mut().zip(q.iter()) {
            *target = Some(value);
        }
        self.final_velocity = Some(v);
        self
    }

    /// Bounds on coordinate `c` at every node.
    pub fn position_bounds(mut self, c: Coordinate<M>, lower: f64, upper: f64) -> Self {
        self.position_bounds[c.index()] = (lower, upper);
        self
    }

    /// Bounds on the velocity of coordinate `c`: on [`Dmoc`](super::Dmoc), each interval's
    /// velocity `(q_{k+1} − q_k)/h`; on [`Collocation`](super::Collocation), the velocity at
    /// every collocation point after the start. The start velocity (and the final velocity,
    /// if given) must lie within them.
    pub fn velocity_bounds(mut self, c: Coordinate<M>, lower: f64, upper: f64) -> Self {
        self.velocity_bounds[c.index()] = (lower, upper);
        self
    }

    /// The coordinates whose velocity is bounded, in order.
    pub(crate) fn velocity_bounded(&self) -> Vec<usize> {
        let bounded = |&(lower, upper): &(f64, f64)| lower > f64::NEG_INFINITY || upper < f64::INFINITY;
        (0..M::NQ).filter(|&i| bounded(&self.velocity_bounds[i])).collect()
    }

    /// Bounds on input `u` on every interval.
    pub fn input_bounds(mut self, u: Input<M>, lower: f64, upper: f64) -> Self {
        self.input_bounds[u.index()] = (lower, upper);
        self
    }

    /// The weight `r` of input `u` in the running cost `h/2 · r u²`.
    pub fn input_weight(mut self, u: Input<M>, r: f64) -> Self {
        self.cost.input[u.index()] = r;
        self
    }

    /// The weight `w` of coordinate `c`'s distance from `reference` in the running cost.
    pub fn position_weight(mut self, c: Coordinate<M>, w: f64, reference: f64) -> Self {
        self.cost.position[c.index()] = w;
        self.cost.position_reference[c.index()] = reference;
        self
    }

    /// The weight `w` of velocity `c`'s distance from `reference` in the running cost.
    pub fn velocity_weight(mut self, c: Coordinate<M>, w: f64, reference: f64) -> Self {
        self.cost.velocity[c.index()] = w;
        self.cost.velocity_reference[c.index()] = reference;
        self
    }

    /// The weight `W` of coordinate `c`'s distance from `reference` at the end.
    pub fn terminal_weight(mut self, c: Coordinate<M>, w: f64, reference: f64) -> Self {
        self.cost.terminal[c.index()] = w;
        self.cost.terminal_reference[c.index()] = reference;
        self
    }

    /// Lets the final time vary: the horizon becomes an unknown between `shortest` and
    /// `longest` seconds, and the intervals stay equal (`h = T/N`); the horizon given to
    /// [`Problem::new`] is where the solver starts. With [`Problem::time_weight`] the cost
    /// prices time, for time-optimal motions.
    ///
    /// The model must not read time: the derivatives with respect to the horizon are taken at
    /// fixed `(q, v, u)` through the step alone (a model whose equations change with `t` is
    /// refused when the transcription checks its guess).
    pub fn free_final_time(mut self, shortest: f64, longest: f64) -> Self {
        self.free_time = Some((shortest, longest));
        self
    }

    /// The weight `ρ` of the horizon in the cost, `ρ T`: with a free final time, what a second
    /// of motion costs against the running cost.
    pub fn time_weight(mut self, rho: f64) -> Self {
        self.cost.time = rho;
        self
    }

    /// The guess the solver starts from: positions at the `N + 1` nodes (each `n` values) and
    /// inputs on the `N` intervals (each `n_u` values). Without one, positions go linearly from
    /// the start to the targets (staying where they start where there is none) and inputs are
    /// zero, clamped into their bounds.
    pub fn guess(mut self, positions: Vec<Vec<f64>>, inputs: Vec<Vec<f64>>) -> Self {
        self.guess = Some(Guess { positions, inputs });
        self
    }

    /// The interval's length `h`.
    pub fn step(&self) -> f64 {
        self.horizon / self.intervals as f64
    }

    /// The guess at the nodes: the positions at the `N + 1` nodes and the inputs on the `N`
    /// intervals, as given or made (see [`Problem::guess`]).
    pub(crate) fn guessed_nodes(&self) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
        if let Some(guess) = &self.guess {
            return (guess.positions.clone(), guess.inputs.clone());
        }
        let intervals = self.intervals;
        let positions = (0..=intervals)
            .map(|k| {
                let s = k as f64 / intervals as f64;
                (0..M::NQ)
                    .map(|i| {
                        let end = self.final_position[i].unwrap_or(self.q0[i]);
                        let (lower, upper) = self.position_bounds[i];
                        (self.q0[i] + s * (end - self.q0[i])).clamp(lower, upper)
                    })
                    .collect()
            })
            .collect();
        let inputs = (0..intervals)
            .map(|_| self.input_bounds.iter().map(|&(lower, upper)| 0.0f64.clamp(lower, upper)).collect())
            .collect();
        (positions, inputs)
    }

    /// Every check that needs no evaluation of the model: a typed error naming the first
    /// problem found.
    pub fn check(&self) -> Result<(), OptimalError> {
        let model = core::any::type_name::<M>();
        if M::NAMES.input_count() == 0 {
            return Err(OptimalError::NoInputs { model });
        }
        if M::NAMES.unilateral_count() > 0 {
            let why = "its unilateral constraints (contacts, walls, joint limits) are not transcribed: a smooth \
                       transcription would pass through them; bound the positions instead";
            return Err(OptimalError::Unsupported { model, why });
        }
        if !crate::hybrid::laws::laws(&self.model).is_empty() {
            let why = "its laws (friction, diodes, switches) change their equations with their modes, which \
                       a smooth transcription cannot follow";
            return Err(OptimalError::Unsupported { model, why });
        }
        if M::NC > 0 {
            let why = "its constraint rows are not transcribed yet: DMOC here takes models without holonomic, \
                       nonholonomic or interconnection rows";
            return Err(OptimalError::Unsupported { model, why });
        }
        if !M::SECOND_ORDER {
            let why = "its derive generated no weighted Hessian (composites and models whose Hessian over \
                       (q, v, u) has more than 2048 entries have none)";
            return Err(OptimalError::Unsupported { model, why });
        }
        // The Jacobian's entries, `(N + 1) n (3n + 2 n_u + 6)` at most (two for the steps of a
        // free final time, four for a velocity's bound), are indexed by the solvers' 32-bit integers; a grid
        // beyond that is refused before anything is allocated.
        let (n, nu) = (M::NQ, M::NAMES.input_count());
        let entries = (self.intervals.checked_add(1))
            .and_then(|nodes| nodes.checked_mul(n))
            .and_then(|rows| rows.checked_mul(3 * n + 2 * nu + 6));
        let indexable = entries.is_some_and(|e| e <= i32::MAX as usize);
        if !(self.horizon.is_finite() && self.horizon > 0.0) || self.intervals == 0 || !indexable {
            return Err(OptimalError::InvalidGrid { horizon: self.horizon, intervals: self.intervals });
        }
        finite("the weight", "the final time", self.cost.time)?;
        if let Some((shortest, longest)) = self.free_time {
            let name = "the final time";
            bounds(name, shortest, longest)?;
            if !(shortest > 0.0 && longest.is_finite()) {
                let why = "a free final time needs a positive shortest and a finite longest horizon";
                let value = if shortest > 0.0 { longest } else { shortest };
                return Err(OptimalError::InfeasibleBounds {
                    name: name.to_string(),
                    why,
                    lower: shortest,
                    upper: longest,
                    value,
                });
            }
            let why = "the horizon the solver starts from is outside the final time's bounds";
            inside(name, why, shortest, longest, self.horizon)?;
        }
        let coordinates = self.model.coordinate_names();
        let inputs = self.model.input_names();
        for (i, name) in coordinates.iter().enumerate() {
            finite("the start position", name, self.q0[i])?;
            finite("the start velocity", name, self.v0[i])?;
            let (lower, upper) = self.position_bounds[i];
            bounds(name, lower, upper)?;
            inside(name, "the start position is outside the position bounds", lower, upper, self.q0[i])?;
            if let Some(target) = self.final_position[i] {
                finite("the final position", name, target)?;
                inside(name, "the final position is outside the position bounds", lower, upper, target)?;
            }
            let (slowest, fastest) = self.velocity_bounds[i];
            let velocity = format!("{name}'s velocity");
            bounds(&velocity, slowest, fastest)?;
            let why = "the start velocity is outside the velocity bounds";
            inside(&velocity, why, slowest, fastest, self.v0[i])?;
            if let Some(v) = &self.final_velocity {
                finite("the final velocity", name, v[i])?;
                let why = "the final velocity is outside the velocity bounds";
                inside(&velocity, why, slowest, fastest, v[i])?;
            }
            for (what, w) in [
                ("the position weight", self.cost.position[i]),
                ("the position reference", self.cost.position_reference[i]),
                ("the velocity weight", self.cost.velocity[i]),
                ("the velocity reference", self.cost.velocity_reference[i]),
                ("the terminal weight", self.cost.terminal[i]),
                ("the terminal reference", self.cost.terminal_reference[i]),
            ] {
                finite(what, name, w)?;
            }
        }
        for (k, name) in inputs.iter().enumerate() {
            let (lower, upper) = self.input_bounds[k];
            bounds(name, lower, upper)?;
            finite("the input weight", name, self.cost.input[k])?;
        }
        if let Some(guess) = &self.guess {
            let (n, nu, nodes) = (coordinates.len(), inputs.len(), self.intervals + 1);
            let shaped = guess.positions.len() == nodes
                && guess.positions.iter().all(|q| q.len() == n)
                && guess.inputs.len() == self.intervals
                && guess.inputs.iter().all(|u| u.len() == nu);
            if !shaped {
                return Err(OptimalError::NotFiniteAtGuess {
                    what: "the guess",
                    detail: format!(
                        "it must hold {nodes} positions of {n} values and {} inputs of {nu} values",
                        self.intervals
                    ),
                });
            }
        }
        Ok(())
    }
}

fn finite(what: &'static str, name: &str, value: f64) -> Result<(), OptimalError> {
    match value.is_finite() {
        true => Ok(()),
        false => Err(OptimalError::NotFinite { what, name: name.to_string(), value }),
    }
}

/// Bounds may be infinite but not NaN, and must not cross.
fn bounds(name: &str, lower: f64, upper: f64) -> Result<(), OptimalError> {
    if lower.is_nan() || upper.is_nan() || lower == f64::INFINITY || upper == f64::NEG_INFINITY {
        let value = if lower.is_nan() || lower == f64::INFINITY { lower } else { upper };
        return Err(OptimalError::NotFinite { what: "a bound", name: name.to_string(), value });
    }
    if lower > upper {
        let why = "the lower bound is above the upper bound";
        return Err(OptimalError::InfeasibleBounds {
            name: name.to_string(),
            why,
            lower,
            upper,
            value: f64::NAN,
        });
    }
    Ok(())
}

fn inside(name: &str, why: &'static str, lower: f64, upper: f64, value: f64) -> Result<(), OptimalError> {
    match (lower..=upper).contains(&value) {
        true => Ok(()),
        false => Err(OptimalError::InfeasibleBounds { name: name.to_string(), why, lower, upper, value }),
    }
}
