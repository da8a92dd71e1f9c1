//! Solving one sensitivity's stage system: directly where the stage Jacobians are the factored
//! one, by the stages' coupled system on small models, or by the simplified Newton iteration
//! in the transformed variables.

use nalgebra::DefaultAllocator;

use crate::algebra::Algebra;
use crate::algebra::newton::NewtonSolver;
use crate::methods::radau::coupled::Coupled;
use crate::methods::radau::options::norm;
use crate::methods::radau::stages::{transform, transformed_residuals};
use crate::methods::radau::tableau::{Eigen, T};
use crate::model::LagrangeDirac;
use crate::model::blocks::JacobianBlocks;
use crate::shape::dims::{Storage, VecY};
use crate::shape::layout::Layout;
use crate::simulate::sensitivity::Wrt;

use super::{Column, Iteration, Work};

/// `out = J x` for the flat Jacobian `J` given by its blocks.
pub(super) fn apply<M: LagrangeDirac>(
    l: &Layout,
    jac: &JacobianBlocks<M, M::Algebra>,
    x: &VecY<M>,
    out: &mut VecY<M>,
) where
    DefaultAllocator: Storage<M>,
{
    let (x, o) = (x.as_slice(), out.as_mut_slice());
    let (xq, xv, xp, xl) = (&x[l.q..l.v], &x[l.v..l.p], &x[l.p..l.lambda], &x[l.lambda..l.len]);
    o[l.q..l.v].copy_from_slice(xv);
    o[l.v..l.p].copy_from_slice(xp);
    o[l.p..l.len].fill(0.0);
    {
        let ov = &mut o[l.v..l.p];
        M::Algebra::qq_mul(&jac.l_vq, -1.0, xq, ov);
        M::Algebra::qq_mul(&jac.l_vv, -1.0, xv, ov);
    }
    {
        let op = &mut o[l.p..l.lambda];
        M::Algebra::qq_mul(&jac.dpdot_dq, 1.0, xq, op);
        M::Algebra::qq_mul(&jac.dpdot_dv, 1.0, xv, op);
        M::Algebra::cq_tr_mul(&jac.a, 1.0, xl, op);
    }
    let oc = &mut o[l.lambda..l.len];
    M::Algebra::cq_mul(&jac.dav_dq, 1.0, xq, oc);
    M::Algebra::cq_mul(&jac.a, 1.0, xv, oc);
}

impl<M: LagrangeDirac> Work<M>
where
    DefaultAllocator: Storage<M>,
{
    /// `f_k`: the stage right-hand sides of sensitivity `c`, `J_k (s_n + Zs_k) + g_k`.
    pub(super) fn stage_right_hand_sides(&mut self, c: &Column<M>) {
        for k in 0..3 {
            self.tmp.copy_from(&c.s);
            self.tmp += &c.z[k];
            apply::<M>(&self.layout, &self.jac[k], &self.tmp, &mut self.f[k]);
            if matches!(c.wrt, Wrt::Parameter(_)) {
                self.f[k] += &c.g[k];
            }
        }
    }

    /// The first slot of the stage right-hand sides that is not finite, if any: the cause of
    /// increments that are not.
    pub(super) fn non_finite_slot(&self) -> Option<usize> {
        self.f.iter().find_map(|f| f.iter().position(|x| !x.is_finite()))
    }

    /// Solves the stage system of `c` when the factored matrix is its exact matrix (a Jacobian
    /// the same at every stage, factored for this step's size): from zero, one solve is the
    /// solution, `M Zs = h (A ⊗ I)(J s_n + g)` in the transformed variables. One linear
    /// iteration, or why it failed, as [`Work::iterate`] says.
    pub(super) fn direct<S: NewtonSolver<M, M::Algebra>>(
        &mut self,
        solver: &mut S,
        eig: &Eigen,
        h: f64,
        c: &mut Column<M>,
    ) -> Result<usize, Option<usize>> {
        apply::<M>(&self.layout, &self.jac[0], &c.s, &mut self.tmp);
        for (fk, gk) in self.f.iter_mut().zip(&c.g) {
            fk.copy_from(&self.tmp);
            if matches!(c.wrt, Wrt::Parameter(_)) {
                *fk += gk;
            }
        }
        // `self.w` is zero (set for the step by `Forward::solve`).
        transformed_residuals::<M>(&self.layout, &eig.over(h), &self.f, &self.w, &mut self.r);
        let [r1, r2, r3] = &mut self.r;
        solver.solve(r1);
        solver.solve_complex(r2, r3);
        if self.r.iter().any(|r| r.iter().any(|x| !x.is_finite())) {
            return Err(self.non_finite_slot());
        }
        transform(&T, &self.r, &mut c.z);
        Ok(1)
    }

    /// Solves the stage system of `c` exactly, with the step's factored coupled system: one
    /// linear solve, or why it failed, as [`Work::iterate`] says.
    pub(super) fn coupled(
        &mut self,
        coupled: &mut Coupled,
        h: f64,
        c: &mut Column<M>,
    ) -> Result<usize, Option<usize>> {
        let g = matches!(c.wrt, Wrt::Parameter(_)).then_some(&c.g);
        coupled.solve(&self.layout, &self.jac, h, &c.s, g, &mut c.z);
        if c.z.iter().any(|z| z.iter().any(|x| !x.is_finite())) {
            for (k, fk) in self.f.iter_mut().enumerate() {
                apply::<M>(&self.layout, &self.jac[k], &c.s, fk);
                if let Some(g) = g {
                    *fk += &g[k];
                }
            }
            return Err(self.non_finite_slot());
        }
        Ok(1)
    }

    /// Solves the stage system of `c` by the simplified Newton iteration on the factored
    /// matrix, its increments measured in `self.weights`, to the state's Newton tolerance. The
    /// number of iterations, or why it failed: the slot whose right-hand side is not finite,
    /// or none if the iteration diverged.
    pub(super) fn iterate<S: NewtonSolver<M, M::Algebra>>(
        &mut self,
        solver: &mut S,
        eig: &Eigen,
        h: f64,
        iteration: &Iteration,
        c: &mut Column<M>,
    ) -> Result<usize, Option<usize>> {
        // Start from the last step's polynomial extrapolated, as the state's iteration does.
        if c.dense.h > 0.0 {
            c.dense.extrapolate_transformed(h, &mut c.z, &mut self.w);
        } else {
            c.z.iter_mut().chain(self.w.iter_mut()).for_each(|z| z.fill(0.0));
        }
        // The iteration is linear: it contracts about as it did in the last step (as the
        // state's did, at first), until it shows its rate in this one; relaxed to its square
        // root, more cautious than RADAU5's relaxation of the state's rate (a power 0.8).
        let last = if c.theta.is_finite() { c.theta } else { iteration.theta };
        let mut theta = last.clamp(f64::EPSILON, 0.81).sqrt();
        let mut previous = f64::INFINITY;
        for newt in 0..iteration.max_iterations {
            self.stage_right_hand_sides(c);
            transformed_residuals::<M>(&self.layout, &eig.over(h), &self.f, &self.w, &mut self.r);
            let [r1, r2, r3] = &mut self.r;
            solver.solve(r1);
            solver.solve_complex(r2, r3);
            let dyno = {
                let sum: f64 =
                    self.r.iter().map(|rk| norm::<M>(rk, &self.weights, iteration.norm).powi(2)).sum();
                (sum / 3.0).sqrt()
            };
            for (wk, rk) in self.w.iter_mut().zip(&self.r) {
                *wk += rk;
            }
            transform(&T, &self.w, &mut c.z);
            if !dyno.is_finite() {
                // A right-hand side that is not finite is the cause to name; otherwise the
                // iteration diverged.
                return Err(self.non_finite_slot());
            }
            if newt > 0 {
                theta = dyno / previous;
                if theta >= 0.99 {
                    return Err(None);
                }
                c.theta = theta;
            }
            // What remains is about θ/(1 − θ) times the last increment: iterate to the
            // state's Newton tolerance, as the state's own iteration does.
            previous = dyno.max(f64::MIN_POSITIVE);
            if dyno * theta / (1.0 - theta) <= iteration.fnewt {
                return Ok(newt + 1);
            }
        }
        Err(None)
    }
}
