//! The seam between transcriptions and solvers: a nonlinear program with exact sparse first
//! and second derivatives, whose sparsity is fixed before the first evaluation.

/// `min f(x)` subject to `g_l ≤ g(x) ≤ g_u` and `x_l ≤ x ≤ x_u`.
///
/// Patterns are lists of `(row, column)`; values are written in the same order. The Hessian is
/// that of the program's Lagrangian `σ f(x) + Σ μ_j g_j(x)`, lower triangle only
/// (`row ≥ column`). Evaluations take `&mut self` so a transcription keeps its work space.
pub trait Nlp {
    /// The number of variables.
    fn variables(&self) -> usize;
    /// The number of constraints.
    fn constraints(&self) -> usize;
    /// The bounds on the variables (infinite where there is none).
    fn variable_bounds(&self, lower: &mut [f64], upper: &mut [f64]);
    /// The bounds on the constraints (equal for equations).
    fn constraint_bounds(&self, lower: &mut [f64], upper: &mut [f64]);
    /// The point the solver starts from.
    fn starting_point(&self, x: &mut [f64]);
    /// `f(x)`.
    fn objective(&mut self, x: &[f64]) -> f64;
    /// `∇f(x)`.
    fn gradient(&mut self, x: &[f64], out: &mut [f64]);
    /// `g(x)`.
    fn constraint_values(&mut self, x: &[f64], out: &mut [f64]);
    /// The structurally nonzero entries of `∂g/∂x`.
    fn jacobian_pattern(&self) -> &[(usize, usize)];
    /// Their values at `x`.
    fn jacobian_values(&mut self, x: &[f64], out: &mut [f64]);
    /// The structurally nonzero entries of the lower triangle of the Lagrangian's Hessian.
    fn hessian_pattern(&self) -> &[(usize, usize)];
    /// Their values at `x`, for the objective's factor `sigma` and the constraints'
    /// multipliers.
    fn hessian_values(&mut self, x: &[f64], sigma: f64, multipliers: &[f64], out: &mut [f64]);
}
