//! Hairer's embedded error estimate for Radau IIA, with the refinement RADAU5 applies after a
//! rejection, adapted to the algebraic rows of the Lagrange-Dirac form.

use nalgebra::DefaultAllocator;

use super::options::{ErrorNorm, norm};
use super::stages::Step;
use super::tableau::{DD1, DD2, DD3};
use crate::algebra::newton::NewtonSolver;
use crate::model::LagrangeDirac;
use crate::shape::dims::{Sizes, Storage, VecY};
use crate::shape::layout::Layout;

/// The work vectors of the estimate.
pub(crate) struct Estimator<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    f2: VecY<M>,
    e: VecY<M>,
    tmp: VecY<M>,
    sizes: Sizes,
}

/// `x ← M x` for `M = diag(I, 0, I, 0)`: zeroes the algebraic rows.
pub(crate) fn zero_algebraic<M: LagrangeDirac>(l: &Layout, x: &mut VecY<M>)
where
    DefaultAllocator: Storage<M>,
{
    let x = x.as_mut_slice();
    x[l.v..l.p].fill(0.0);
    x[l.lambda..l.len].fill(0.0);
}

impl<M: LagrangeDirac> Estimator<M>
where
    DefaultAllocator: Storage<M>,
{
    pub fn new(sizes: Sizes) -> Self {
        Estimator { f2: sizes.zeros_y::<M>(), e: sizes.zeros_y::<M>(), tmp: sizes.zeros_y::<M>(), sizes }
    }

    /// The weighted norm of `(γ/h M − J)⁻¹ (f(t, y) + M Σ e_i z_i)`, refined once with a
    /// fresh residual when `refine` (on the first step and after a rejection) and it is not
    /// below 1. `f0` is `f(t, y)` at the step's start.
    // Indexing vectors of a size known to the compiler beats nalgebra's strided iterators.
    #[allow(clippy::needless_range_loop)]
    pub fn error<S: NewtonSolver<M, M::Algebra>>(
        &mut self,
        step: Step<'_, '_, M, S>,
        z: &[VecY<M>; 3],
        f0: &VecY<M>,
        refine: bool,
    ) -> f64 {
        let h = step.h;
        let layout = Layout::new(self.sizes.typed::<M>());
        for i in 0..self.f2.len() {
            self.f2[i] = (DD1 * z[0][i] + DD2 * z[1][i] + DD3 * z[2][i]) / h;
        }
        zero_algebraic::<M>(&layout, &mut self.f2);
        // The algebraic rows of f(t_n, y_n) vanish up to the Newton tolerance of the step that
        // produced y_n: that remainder is not truncation error, and through the index-2
        // multipliers' scaling it would keep the estimate above 1 however small the step,
        // whenever a multiplier crosses zero. They are left out, as in exact arithmetic.
        self.e.copy_from(f0);
        zero_algebraic::<M>(&layout, &mut self.e);
        self.e += &self.f2;
        step.solver.solve(&mut self.e);
        // Redundant rows: the multipliers' part that exerts no force is not determined by the
        // step, so not its error.
        step.solver.least_norm(&mut self.e);
        let mut err = scaled_error::<M>(&self.e, step.weights, step.error_norm);
        if err >= 1.0 && refine {
            self.tmp.copy_from(step.y);
            self.tmp += &self.e;
            step.residual.eval(step.model, step.t, &self.tmp, &mut self.e);
            step.stats.residual_evaluations += 1;
            // As above: measure the algebraic rows from the state's own remainder.
            let Layout { v, p, lambda, len, .. } = layout;
            for i in (v..p).chain(lambda..len) {
                self.e[i] -= f0[i];
            }
            self.e += &self.f2;
            step.solver.solve(&mut self.e);
            step.solver.least_norm(&mut self.e);
            err = scaled_error::<M>(&self.e, step.weights, step.error_norm);
        }
        err
    }
}

/// The weighted norm of an error estimate `e` for the step-size control: at least 1e-10, and
/// 1e10 (reject) if it is not finite.
pub(crate) fn scaled_error<M: LagrangeDirac>(e: &VecY<M>, weights: &VecY<M>, kind: ErrorNorm) -> f64
where
    DefaultAllocator: Storage<M>,
{
    let err = norm::<M>(e, weights, kind).max(1e-10);
    if err.is_finite() { err } else { 1e10 }
}
