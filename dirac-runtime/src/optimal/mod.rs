//! Optimal control from the same model: a [`Problem`](crate::optimal::Problem) (horizon, grid,
//! start, targets, bounds, quadratic cost) transcribed into a nonlinear program
//! ([`Nlp`](crate::optimal::Nlp)) whose constraint Jacobian and Lagrangian Hessian come from
//! the model's generated blocks, and solved by dirac's own
//! [`InteriorPoint`](crate::optimal::interior::InteriorPoint) (banded, for small models and
//! receding horizons: [`Mpc`](crate::optimal::Mpc)) or by IPOPT (feature `ipopt`, for larger
//! ones).
//!
//! Two transcriptions ([`Transcription`](crate::optimal::Transcription)):
//!
//! - [`Dmoc`](crate::optimal::Dmoc), the variational integrator's own discrete Lagrangian and
//!   forces: an optimal trajectory is one [`Variational`](crate::Variational) reproduces with
//!   the same step and the inputs held over each interval, and it keeps every discrete
//!   momentum map of the problem's symmetries to round-off;
//! - [`Collocation`](crate::optimal::Collocation), Radau IIA's stage equations (order 5) on
//!   positions, velocities and the momenta as their functions, for models whose velocities are
//!   better kept as unknowns (stiff forces, degenerate Lagrangians).
//!
//! The second derivatives the solvers need are generated when the model compiles
//! ([`InputsOutputs::weighted_hessian`](crate::InputsOutputs::weighted_hessian)).

mod band;
mod collocation;
mod dmoc;
mod error;
pub mod interior;
mod interval;
#[cfg(feature = "ipopt")]
pub mod ipopt;
mod mpc;
mod nlp;
mod problem;

pub use self::collocation::Collocation;
pub use self::dmoc::Dmoc;
pub use self::error::OptimalError;
pub use self::mpc::{Mpc, MpcSample};
pub use self::nlp::Nlp;
pub use self::problem::Problem;

use nalgebra::DefaultAllocator;

use crate::model::{DenseModel, InputsOutputs};
use crate::shape::dims::Storage;

/// An optimal trajectory: positions and momenta at the nodes, inputs on the intervals, and
/// what the solve cost.
#[derive(Clone, Debug)]
pub struct Optimum {
    /// The node times `t_0 … t_N`.
    pub times: Vec<f64>,
    /// The positions at the nodes, one vector of `n` per node.
    pub positions: Vec<Vec<f64>>,
    /// The discrete momenta at the nodes (the variational integrator's `p_k`).
    pub momenta: Vec<Vec<f64>>,
    /// The inputs held over each interval, one vector of `n_u` per interval.
    pub inputs: Vec<Vec<f64>>,
    /// The optimal cost.
    pub cost: f64,
    /// The largest violation of the discrete equations at the optimum.
    pub violation: f64,
    /// The solver's iterations.
    pub iterations: usize,
    /// The solver's status, by its own name.
    pub status: &'static str,
    /// Wall time of the solve.
    pub wall: std::time::Duration,
    /// The part of it spent evaluating the equations and their derivatives.
    pub evaluation: std::time::Duration,
}

/// The refusal of a free final time on a model whose equations read `t`: the derivatives
/// with respect to the step hold `t` fixed. The program's equations are evaluated at `z` with
/// the problem starting at its own start (`start` gives access to it) and a horizon later; a
/// model that does not read `t` gives the same values, bit for bit. The start is restored.
pub(crate) fn refuse_time_dependence<M, N: Nlp>(
    nlp: &mut N,
    start: fn(&mut N) -> &mut f64,
    horizon: f64,
    z: &[f64],
) -> Result<(), OptimalError> {
    let t0 = *start(nlp);
    let equations = |nlp: &mut N, t: f64| {
        *start(nlp) = t;
        let mut g = vec![0.0; nlp.constraints()];
        nlp.constraint_values(z, &mut g);
        g
    };
    let same = equations(nlp, t0) == equations(nlp, t0 + horizon);
    *start(nlp) = t0;
    if same {
        return Ok(());
    }
    let why = "its equations change with time, and a free final time moves every node's time: only models \
               that do not read `t` take a free final time";
    Err(OptimalError::Unsupported { model: core::any::type_name::<M>(), why })
}

/// A transcription of a [`Problem`] into a nonlinear program: [`Dmoc`] or [`Collocation`].
/// Both solve the same way, through [`Transcription::solve_interior`] and (feature `ipopt`)
/// [`Transcription::solve`].
pub trait Transcription: Nlp {
    /// The model transcribed.
    type Model;
    /// The guess as a point of the program.
    fn guess(&self) -> Vec<f64>;
    /// A typed error if the cost or the equations are not finite at `z`.
    fn check_guess(&mut self, z: &[f64]) -> Result<(), OptimalError>;
    /// The trajectory at the point `z`, with the solve's figures.
    fn optimum(
        &mut self,
        z: &[f64],
        iterations: usize,
        status: &'static str,
        wall: std::time::Duration,
    ) -> Optimum;
    /// Starts counting the time spent in evaluations afresh.
    fn reset_evaluation(&mut self);

    /// Solves the problem with the pure-Rust [`InteriorPoint`](interior::InteriorPoint): the
    /// optimum, or a typed error naming the solver's status.
    fn solve_interior(&mut self, options: &interior::InteriorOptions) -> Result<Optimum, OptimalError>
    where
        Self: Sized,
    {
        let started = std::time::Instant::now();
        let guess = self.guess();
        self.check_guess(&guess)?;
        let mut solver = interior::InteriorPoint::new(self)
            .map_err(|why| OptimalError::Unsupported { model: core::any::type_name::<Self::Model>(), why })?;
        self.reset_evaluation();
        let result = solver.solve(self, options);
        if !result.solved {
            return Err(OptimalError::Solver {
                status: result.status,
                iterations: result.iterations,
                cost: result.objective,
                violation: result.violation,
            });
        }
        // The wall time counts the solver's set-up (its KKT order and band), as IPOPT's
        // counts its symbolic analysis.
        let z = solver.point().to_vec();
        Ok(self.optimum(&z, result.iterations, result.status, started.elapsed()))
    }

    /// Solves the problem with IPOPT: the optimum, or a typed error naming IPOPT's status.
    #[cfg(feature = "ipopt")]
    fn solve(&mut self, options: &ipopt::IpoptOptions) -> Result<Optimum, OptimalError>
    where
        Self: Sized,
    {
        let guess = self.guess();
        self.check_guess(&guess)?;
        self.reset_evaluation();
        let result = ipopt::solve(self, options).map_err(|why| OptimalError::SolverMissing { why })?;
        if !result.solved {
            return Err(OptimalError::Solver {
                status: result.status,
                iterations: result.iterations,
                cost: result.objective,
                violation: result.violation,
            });
        }
        Ok(self.optimum(&result.x, result.iterations, result.status, result.wall))
    }
}

impl<M> Dmoc<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    /// The trajectory at the point `z` of the program, with the solve's figures.
    pub fn optimum(
        &mut self,
        z: &[f64],
        iterations: usize,
        status: &'static str,
        wall: std::time::Duration,
    ) -> Optimum {
        let nodes = self.problem.intervals + 1;
        let mut g = vec![0.0; self.constraints()];
        self.constraint_values(z, &mut g);
        Optimum {
            times: (0..nodes).map(|k| self.time(z, k)).collect(),
            positions: (0..nodes).map(|k| self.node(z, k)).collect(),
            momenta: self.momenta(z),
            inputs: (0..self.problem.intervals).map(|k| self.inputs(z, k)).collect(),
            cost: self.objective(z),
            violation: g.iter().fold(0.0, |m: f64, x| m.max(x.abs())),
            iterations,
            status,
            wall,
            evaluation: self.evaluation,
        }
    }

    /// Solves the problem with the pure-Rust [`InteriorPoint`](interior::InteriorPoint): the
    /// optimum, or a typed error naming the solver's status.
    pub fn solve_interior(&mut self, options: &interior::InteriorOptions) -> Result<Optimum, OptimalError> {
        Transcription::solve_interior(self, options)
    }

    /// Solves the problem with IPOPT: the optimum, or a typed error naming IPOPT's status.
    #[cfg(feature = "ipopt")]
    pub fn solve(&mut self, options: &ipopt::IpoptOptions) -> Result<Optimum, OptimalError> {
        Transcription::solve(self, options)
    }
}

impl<M> Transcription for Dmoc<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    type Model = M;

    fn guess(&self) -> Vec<f64> {
        Dmoc::guess(self)
    }

    fn check_guess(&mut self, z: &[f64]) -> Result<(), OptimalError> {
        Dmoc::check_guess(self, z)
    }

    fn optimum(
        &mut self,
        z: &[f64],
        iterations: usize,
        status: &'static str,
        wall: std::time::Duration,
    ) -> Optimum {
        Dmoc::optimum(self, z, iterations, status, wall)
    }

    fn reset_evaluation(&mut self) {
        self.evaluation = std::time::Duration::ZERO;
    }
}

impl<M> Collocation<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    /// Solves the problem with the pure-Rust [`InteriorPoint`](interior::InteriorPoint).
    pub fn solve_interior(&mut self, options: &interior::InteriorOptions) -> Result<Optimum, OptimalError> {
        Transcription::solve_interior(self, options)
    }

    /// Solves the problem with IPOPT: the optimum, or a typed error naming IPOPT's status.
    #[cfg(feature = "ipopt")]
    pub fn solve(&mut self, options: &ipopt::IpoptOptions) -> Result<Optimum, OptimalError> {
        Transcription::solve(self, options)
    }
}
