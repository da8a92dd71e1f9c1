//! The typed errors of an optimal control problem: what is wrong with it, found before any
//! solve, and how a solver ended when it did not converge.

/// Why an optimal control problem was refused or its solve failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum OptimalError {
    /// The model has no inputs: there is nothing to choose.
    #[error(
        "the model `{model}` has no inputs: an optimal control problem chooses inputs, so declare at least one (`#[dirac(inputs(...))]`)"
    )]
    NoInputs {
        /// The model's type name.
        model: &'static str,
    },
    /// The transcription needs a capability the model's derive did not generate.
    #[error("the model `{model}` cannot be transcribed: {why}")]
    Unsupported {
        /// The model's type name.
        model: &'static str,
        /// What is missing.
        why: &'static str,
    },
    /// The horizon or the number of intervals cannot make a grid, or the grid makes a program
    /// too large to index (more than `i32::MAX` derivative entries, the solvers' index type).
    #[error(
        "the horizon must be finite and positive with at least one interval and a program that fits a 32-bit \
         index, not {horizon} s over {intervals} intervals"
    )]
    InvalidGrid {
        /// The horizon asked for.
        horizon: f64,
        /// The intervals asked for.
        intervals: usize,
    },
    /// A bound, start or target is not a finite number (bounds may be infinite, not NaN).
    #[error("{what} of `{name}` is {value}, which is not a number the problem can use")]
    NotFinite {
        /// What the value is (`"the start position"`, `"the lower bound"`, …).
        what: &'static str,
        /// The coordinate or input it belongs to.
        name: String,
        /// The value.
        value: f64,
    },
    /// A bound's lower end is above its upper end, or a start or target lies outside its
    /// bounds: no trajectory is feasible.
    #[error("the bounds of `{name}` admit nothing: {why} (lower {lower}, upper {upper}, value {value})")]
    InfeasibleBounds {
        /// The coordinate or input.
        name: String,
        /// Which bounds and what breaks them.
        why: &'static str,
        /// The lower bound.
        lower: f64,
        /// The upper bound.
        upper: f64,
        /// The start or target outside them (NaN where the bounds cross).
        value: f64,
    },
    /// The problem's final time is free, and what was asked of it keeps a fixed horizon.
    #[error("{what} takes a fixed final time only: {why}")]
    FixedTimeOnly {
        /// What keeps its horizon (`"Mpc"`).
        what: &'static str,
        /// Why, and what to use instead.
        why: &'static str,
    },
    /// The cost or a constraint is not finite at the initial guess, where the solver starts.
    #[error(
        "{what} is not finite at the initial guess ({detail}); start from a guess where the model can be evaluated"
    )]
    NotFiniteAtGuess {
        /// `"the cost"` or `"the discrete equations"`.
        what: &'static str,
        /// Where: the interval, or the value.
        detail: String,
    },
    /// IPOPT's library could not be loaded.
    #[error(
        "IPOPT's library could not be loaded ({why}); install Debian's coinor-libipopt-dev, or name a build of libipopt in DIRAC_IPOPT"
    )]
    SolverMissing {
        /// Each file tried and why it failed.
        why: String,
    },
    /// The solver stopped without a solution; `status` is its own name for why.
    #[error(
        "the solver ended with `{status}` after {iterations} iterations (cost {cost}, constraint violation {violation:.3e})"
    )]
    Solver {
        /// The solver's status, by its own name (`Infeasible_Problem_Detected`, …).
        status: &'static str,
        /// Its iterations.
        iterations: usize,
        /// The cost at the last iterate.
        cost: f64,
        /// The largest constraint violation at the last iterate.
        violation: f64,
    },
}
