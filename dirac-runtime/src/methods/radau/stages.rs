//! The simplified Newton iteration on Radau's stage system, in the variables `w = (T⁻¹ ⊗ I) z`
//! that split it into one real and one complex linear system (Hairer & Wanner, §IV.8), with
//! the convergence-rate tests of RADAU5.

use nalgebra::DefaultAllocator;

use super::dense::Dense;
use super::options::{ErrorNorm, RadauStats, norm};
use super::residual::Residual;
use super::tableau::{C1, C2, C3, Eigen, T, TI};
use crate::algebra::newton::NewtonSolver;
use crate::integrator::held::Held;
use crate::integrator::rough_power;
use crate::model::LagrangeDirac;
use crate::shape::dims::{Sizes, Storage, VecY};
use crate::shape::layout::Layout;

/// How a Newton iteration ended.
pub(crate) enum Outcome {
    /// Converged after this many iterations.
    Converged(usize),
    /// Retry with the step multiplied by this factor, for this reason.
    Shrink(f64, &'static str),
}

/// What the iteration needs from the step it solves.
pub(crate) struct Step<'a, 'm, M: LagrangeDirac, S>
where
    DefaultAllocator: Storage<M>,
{
    pub model: &'a mut Held<'m, M>,
    pub residual: &'a mut Residual<'m, M>,
    pub solver: &'a mut S,
    pub t: f64,
    pub h: f64,
    pub y: &'a VecY<M>,
    pub weights: &'a VecY<M>,
    pub error_norm: ErrorNorm,
    pub stats: &'a mut RadauStats,
}

/// The stage increments `z_k = Y_k − y`, their transforms `w`, the stage residuals, and the
/// convergence history that carries over from step to step.
pub(crate) struct Stages<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// The stage increments; `z[2]` is the step's increment.
    pub z: [VecY<M>; 3],
    w: [VecY<M>; 3],
    f: [VecY<M>; 3],
    r: [VecY<M>; 3],
    tmp: VecY<M>,
    inverse_weights: VecY<M>,
    sizes: Sizes,
    faccon: f64,
    /// The last observed contraction rate; a fresh Jacobian is needed when it is not small.
    pub theta: f64,
}

/// Three zero vectors over the flat state: one per stage.
pub(crate) fn three<M: LagrangeDirac>(sizes: Sizes) -> [VecY<M>; 3]
where
    DefaultAllocator: Storage<M>,
{
    [sizes.zeros_y::<M>(), sizes.zeros_y::<M>(), sizes.zeros_y::<M>()]
}

impl<M: LagrangeDirac> Stages<M>
where
    DefaultAllocator: Storage<M>,
{
    pub fn new(sizes: Sizes) -> Self {
        Stages {
            z: three(sizes),
            w: three(sizes),
            f: three(sizes),
            r: three(sizes),
            tmp: sizes.zeros_y::<M>(),
            inverse_weights: sizes.zeros_y::<M>(),
            sizes,
            faccon: 1.0,
            theta: 1.0,
        }
    }

    /// Forgets the convergence history, for a new integration.
    pub fn restart(&mut self) {
        self.faccon = 1.0;
        self.theta = 1.0;
    }

    /// Starting values: zero on the first step, else the last step's polynomial extrapolated.
    pub fn initial_guess(&mut self, dense: Option<&Dense<M>>, h: f64) {
        match dense {
            None => {
                for k in 0..3 {
                    self.z[k].fill(0.0);
                    self.w[k].fill(0.0);
                }
            }
            Some(dense) => {
                dense.extrapolate_transformed(h, &mut self.z, &mut self.w);
            }
        }
    }

    /// Iterates to convergence, or says by how much to shrink the step.
    pub fn iterate<S: NewtonSolver<M, M::Algebra>>(
        &mut self,
        mut step: Step<'_, '_, M, S>,
        eig: &Eigen,
        fnewt: f64,
        max_iterations: usize,
    ) -> Outcome {
        let h = step.h;
        for (inverse, w) in self.inverse_weights.iter_mut().zip(step.weights.iter()) {
            *inverse = 1.0 / w;
        }
        let mut faccon = rough_power(self.faccon.max(f64::EPSILON), 0.8);
        let mut theta = self.theta.abs();
        let (mut dyno_old, mut thq_old) = (1.0, 1.0);
        let shifts = eig.over(h);
        for newt in 0..max_iterations {
            self.residuals(&mut step);
            self.transformed_residuals(&shifts);
            let [r1, r2, r3] = &mut self.r;
            step.solver.solve(r1);
            step.solver.solve_complex(r2, r3);
            // The iterates advance before the tests: an attempt that ends in a shrink starts
            // the next one from fresh starting values.
            let dyno = self.advance(step.weights, step.error_norm);
            // A non-finite residual makes the increments, and so their norm, non-finite: the
            // residuals are searched only then, not on every iteration.
            if !dyno.is_finite() && self.non_finite_slot().is_some() {
                return Outcome::Shrink(0.5, "non-finite residual");
            }
            step.stats.newton_iterations += 1;
            if newt >= 1 {
                let thq = dyno / dyno_old;
                theta = if newt == 1 { thq } else { (thq * thq_old).sqrt() };
                thq_old = thq;
                if theta < 0.99 {
                    faccon = theta / (1.0 - theta);
                    let remaining = (max_iterations - 1 - newt) as i32;
                    let dyth = faccon * dyno * theta.powi(remaining) / fnewt;
                    if dyth >= 1.0 {
                        let qnewt = dyth.clamp(1e-4, 20.0);
                        return Outcome::Shrink(
                            0.8 * qnewt.powf(-1.0 / (4.0 + remaining as f64)),
                            "Newton converging too slowly",
                        );
                    }
                } else {
                    return Outcome::Shrink(0.5, "Newton iteration diverging");
                }
            }
            dyno_old = dyno.max(f64::EPSILON);
            if faccon * dyno <= fnewt {
                self.faccon = faccon;
                self.theta = theta;
                return Outcome::Converged(newt + 1);
            }
        }
        Outcome::Shrink(0.5, "Newton iteration did not converge")
    }

    /// Goes on iterating after [`iterate`](Self::iterate) converged, until an increment's
    /// weighted norm is below `floor` (round-off) or stops contracting: the stages are then the
    /// root of the stage system to round-off, whatever the starting values and the Jacobian
    /// the iteration used. At most `max_iterations`; `Err` if the iterates become non-finite.
    pub fn polish<S: NewtonSolver<M, M::Algebra>>(
        &mut self,
        mut step: Step<'_, '_, M, S>,
        eig: &Eigen,
        floor: f64,
        max_iterations: usize,
    ) -> Result<(), &'static str> {
        let shifts = eig.over(step.h);
        let mut previous = f64::INFINITY;
        for _ in 0..max_iterations {
            self.residuals(&mut step);
            self.transformed_residuals(&shifts);
            let [r1, r2, r3] = &mut self.r;
            step.solver.solve(r1);
            step.solver.solve_complex(r2, r3);
            let dyno = self.advance(step.weights, step.error_norm);
            step.stats.newton_iterations += 1;
            if !dyno.is_finite() {
                return Err("non-finite residual");
            }
            if dyno <= floor || dyno > 0.5 * previous {
                break;
            }
            previous = dyno;
        }
        Ok(())
    }

    /// `w += r` and `z = T w`, in one pass over the components, and the size of the Newton
    /// increments `r`: the root mean square of the three stages' norms. The root-mean-square
    /// norm multiplies by the reciprocal weights, formed once an attempt: three divisions a
    /// component in every iteration were a tenth of a small model's iteration.
    // Indexing vectors of a size known to the compiler beats nalgebra's strided iterators.
    #[allow(clippy::needless_range_loop)]
    fn advance(&mut self, weights: &VecY<M>, kind: ErrorNorm) -> f64 {
        let dyno = match kind {
            ErrorNorm::Rms => None,
            ErrorNorm::Max => {
                let sum: f64 = self.r.iter().map(|rk| norm::<M>(rk, weights, kind).powi(2)).sum();
                Some((sum / 3.0).sqrt())
            }
        };
        let [w1, w2, w3] = &mut self.w;
        let [r1, r2, r3] = &self.r;
        let mut sum = 0.0;
        for i in 0..w1.len() {
            let (d1, d2, d3) = (r1[i], r2[i], r3[i]);
            let iw = self.inverse_weights[i];
            let (e1, e2, e3) = (d1 * iw, d2 * iw, d3 * iw);
            sum += e1 * e1 + e2 * e2 + e3 * e3;
            let (x1, x2, x3) = (w1[i] + d1, w2[i] + d2, w3[i] + d3);
            (w1[i], w2[i], w3[i]) = (x1, x2, x3);
            for (zk, tk) in self.z.iter_mut().zip(&T) {
                zk[i] = tk[0] * x1 + tk[1] * x2 + tk[2] * x3;
            }
        }
        dyno.unwrap_or_else(|| (sum / (3 * weights.len()) as f64).sqrt())
    }

    /// The stage residuals `f(t + c_k h, y + z_k)`.
    // Indexing vectors of a size known to the compiler beats nalgebra's strided iterators.
    #[allow(clippy::needless_range_loop)]
    fn residuals<S>(&mut self, step: &mut Step<'_, '_, M, S>)
    where
        DefaultAllocator: Storage<M>,
    {
        for ((zk, fk), ck) in self.z.iter().zip(self.f.iter_mut()).zip([C1, C2, C3]) {
            for i in 0..zk.len() {
                self.tmp[i] = step.y[i] + zk[i];
            }
            step.residual.eval(step.model, step.t + ck * step.h, &self.tmp, fk);
            step.stats.residual_evaluations += 1;
        }
    }

    /// The slot of the first non-finite value among the stage residuals, if there is one.
    pub fn non_finite_slot(&self) -> Option<usize> {
        self.f.iter().find_map(|f| f.iter().position(|v| !v.is_finite()))
    }

    /// `r_k = (T⁻¹ f)_k − (Λ/h ⊗ M) w`, with `M` the identity on the differential rows and
    /// `shifts` the eigenvalues `Λ/h`.
    fn transformed_residuals(&mut self, shifts: &Eigen) {
        transformed_residuals::<M>(
            &Layout::new(self.sizes.typed::<M>()),
            shifts,
            &self.f,
            &self.w,
            &mut self.r,
        );
    }
}

/// `r_k = (T⁻¹ f)_k − (Λ/h ⊗ M) w_k`: the residuals of the stage system in the transformed
/// variables `w`, for stage right-hand sides `f` (Hairer & Wanner, §IV.8), with `M` the
/// identity on the differential rows of the state's layout `l`.
// Indexing vectors of a size known to the compiler beats nalgebra's strided iterators.
#[allow(clippy::needless_range_loop)]
pub(crate) fn transformed_residuals<M: LagrangeDirac>(
    l: &Layout,
    shifts: &Eigen,
    f: &[VecY<M>; 3],
    w: &[VecY<M>; 3],
    r: &mut [VecY<M>; 3],
) where
    DefaultAllocator: Storage<M>,
{
    let Eigen { gamma, alpha, beta } = *shifts;
    let [r1, r2, r3] = r;
    for i in 0..r1.len() {
        let (f1, f2, f3) = (f[0][i], f[1][i], f[2][i]);
        r1[i] = TI[0][0] * f1 + TI[0][1] * f2 + TI[0][2] * f3;
        r2[i] = TI[1][0] * f1 + TI[1][1] * f2 + TI[1][2] * f3;
        r3[i] = TI[2][0] * f1 + TI[2][1] * f2 + TI[2][2] * f3;
    }
    // The differential rows, positions and momenta, as two plain ranges: a chained iterator
    // costs more than the arithmetic of a small model.
    for rows in [l.q..l.v, l.p..l.lambda] {
        for i in rows {
            let (w1, w2, w3) = (w[0][i], w[1][i], w[2][i]);
            r1[i] -= gamma * w1;
            r2[i] -= alpha * w2 - beta * w3;
            r3[i] -= beta * w2 + alpha * w3;
        }
    }
}

/// `to_k = Σ_j matrix[k][j] from_j` component by component: `z = T w` or `w = T⁻¹ z`.
pub(crate) fn transform<M: LagrangeDirac>(matrix: &[[f64; 3]; 3], from: &[VecY<M>; 3], to: &mut [VecY<M>; 3])
where
    DefaultAllocator: Storage<M>,
{
    for i in 0..from[0].len() {
        let (x1, x2, x3) = (from[0][i], from[1][i], from[2][i]);
        for (tk, mk) in to.iter_mut().zip(matrix) {
            tk[i] = mk[0] * x1 + mk[1] * x2 + mk[2] * x3;
        }
    }
}
