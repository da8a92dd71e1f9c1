//! Optimal control from the same model: a [`Problem`](crate::optimal::Problem) (horizon, grid,
//! start, targets, bounds, quadratic cost) transcribed by [`Dmoc`](crate::optimal::Dmoc) into a
//! nonlinear program ([`Nlp`](crate::optimal::Nlp)) whose
//! constraint Jacobian and Lagrangian Hessian come from the model's generated blocks, and
//! solved by dirac's own [`InteriorPoint`](crate::optimal::interior::InteriorPoint) (banded,
//! for small models and receding horizons: [`Mpc`](crate::optimal::Mpc)) or by IPOPT (feature
//! `ipopt`, for larger ones).
//!
//! The transcription is the variational integrator's own discrete Lagrangian and forces, so
//! an optimal trajectory is one [`Variational`](crate::Variational) reproduces with the same
//! step and the inputs held over each interval, and the second derivatives the solver needs
//! are generated when the model compiles ([`InputsOutputs::weighted_hessian`](crate::InputsOutputs::weighted_hessian)).

mod band;
mod dmoc;
mod error;
pub mod interior;
mod interval;
#[cfg(feature = "ipopt")]
pub mod ipopt;
mod mpc;
mod nlp;
mod problem;

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

impl<M> Dmoc<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    /// The trajectory at the point `z` of the program, with the solve's figures.
    #[allow(clippy::too_many_arguments)]
    pub fn optimum(
        &mut self,
        z: &[f64],
        iterations: usize,
        status: &'static str,
        wall: std::time::Duration,
    ) -> Optimum {
        let nodes = self.problem.intervals + 1;
        let h = self.problem.step();
        let mut g = vec![0.0; self.constraints()];
        self.constraint_values(z, &mut g);
        Optimum {
            times: (0..nodes).map(|k| self.problem.t0 + k as f64 * h).collect(),
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
        let started = std::time::Instant::now();
        let guess = self.guess();
        self.check_guess(&guess)?;
        let mut solver = interior::InteriorPoint::new(self)
            .map_err(|why| OptimalError::Unsupported { model: core::any::type_name::<M>(), why })?;
        self.evaluation = std::time::Duration::ZERO;
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
    pub fn solve(&mut self, options: &ipopt::IpoptOptions) -> Result<Optimum, OptimalError> {
        let guess = self.guess();
        self.check_guess(&guess)?;
        self.evaluation = std::time::Duration::ZERO;
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
