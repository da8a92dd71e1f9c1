//! What the derive derived, for people: a model's equations as text and LaTeX, and the
//! arithmetic cost of its generated kernels.

use std::borrow::Cow;

/// The derived equations of a model, for people: plain text and LaTeX.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Equations {
    /// One equation a line, in Rust-like notation.
    pub text: Cow<'static, str>,
    /// An `aligned` LaTeX environment, one equation a row.
    pub latex: Cow<'static, str>,
}

/// How many arithmetic operations (`+ − × ÷`, an elementary function counting as one) the
/// generated kernels of a model perform per call, after common subexpressions are shared.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OperationCounts {
    /// [`LagrangeDirac::residual`](crate::LagrangeDirac::residual).
    pub residual: usize,
    /// [`LagrangeDirac::jacobian`](crate::LagrangeDirac::jacobian).
    pub jacobian: usize,
    /// Residual and Jacobian together, sharing subexpressions between them.
    pub residual_and_jacobian: usize,
    /// [`LagrangeDirac::residual_blocks`](crate::LagrangeDirac::residual_blocks).
    pub residual_blocks: usize,
    /// [`LagrangeDirac::jacobian_blocks`](crate::LagrangeDirac::jacobian_blocks).
    pub jacobian_blocks: usize,
}

impl OperationCounts {
    /// All counts zero.
    pub const ZERO: OperationCounts = OperationCounts {
        residual: 0,
        jacobian: 0,
        residual_and_jacobian: 0,
        residual_blocks: 0,
        jacobian_blocks: 0,
    };

    /// The counts of two kernels run one after the other.
    pub const fn plus(self, other: OperationCounts) -> OperationCounts {
        OperationCounts {
            residual: self.residual + other.residual,
            jacobian: self.jacobian + other.jacobian,
            residual_and_jacobian: self.residual_and_jacobian + other.residual_and_jacobian,
            residual_blocks: self.residual_blocks + other.residual_blocks,
            jacobian_blocks: self.jacobian_blocks + other.jacobian_blocks,
        }
    }
}

/// The equations a derive derived for a model, and what its kernels cost. The derives
/// implement it for every model they make.
pub trait Derivation {
    /// The arithmetic cost of the generated kernels.
    const OPERATION_COUNTS: OperationCounts;

    /// The derived equations, for people.
    fn equations() -> Equations;
}
