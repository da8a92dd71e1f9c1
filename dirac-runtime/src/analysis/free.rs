//! Velocities that neither inertia nor constraints fix, found from the forces: the directions
//! `N` of `ker L_vv ∩ ker A` (a capacitor's current, a motor's current without armature
//! inductance, a massless node between a damper and a spring). Along them the Legendre map is
//! algebraic and the momentum balance projected on `N`, with `Nᵀ L_vv = 0` and `Nᵀ Aᵀ = 0`,
//!
//! ```text
//! g(q, v, t) = Nᵀ (∂L/∂q + F(q, v, t) − L_vq v − ∂²L/∂v∂t) = 0,
//! ```
//!
//! is an equation in `v` without `v̇` (index 1). It fixes them where
//! `Nᵀ (L_qv − L_vq + F_v) N` is nonsingular: dissipation (`−R_vv`, part of `F_v`),
//! velocity-dependent forces and gyroscopic coupling all count (design notes §5.1).
//!
//! The explicit integrator solves `g = 0` at every stage and the variational integrator at
//! every step's end, by Newton's method with that matrix (the terms with third derivatives
//! of `L` left out: they change the rate, not the solution). `N` is found once per start, from
//! the blocks there (set-up: it allocates); a solve allocates nothing. Where the derive solved
//! the balance in closed form for every free velocity ([`LagrangeDirac::SOLVED_VELOCITIES`],
//! each one's balance affine in it alone), that closed form replaces Newton's method: one
//! evaluation of a small kernel per solve. Dense models only: a
//! sparse model with such velocities is integrated by Radau, whose Newton matrix holds
//! `F_v` already.

use nalgebra::{DMatrix, DefaultAllocator, Dyn};

use crate::algebra::lu::Lu;
use crate::algebra::{Algebra, dense_cq, dense_qq};
use crate::analysis::init::{free_directions, free_matrix, undetermined_velocities};
use crate::error::SimError;
use crate::model::blocks::ResidualBlocks;
use crate::model::{LagrangeDirac, MatQQ};
use crate::shape::dims::{Storage, VecC, VecQ};

/// The free directions of a model at its start, with the storage of their Newton iteration.
pub(crate) struct FreeVelocities<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// `N`, `n × k`, orthonormal columns (in the model's coordinates).
    basis: DMatrix<f64>,
    /// `N Nᵀ` in the model's storage, which completes `L_vv` into a regular matrix.
    pub projector: MatQQ<M>,
    blocks: ResidualBlocks<M>,
    zero_lambda: VecC<M>,
    lvt: VecQ<M>,
    lvq: MatQQ<M>,
    fv: MatQQ<M>,
    /// `L_vq` and `∂F/∂v` where the matrix was last factored: the factorisation holds while
    /// they stay the same (linear forces, such as resistors').
    factored_lvq: MatQQ<M>,
    factored_fv: MatQQ<M>,
    factored: bool,
    g: Vec<f64>,
    residual: Vec<f64>,
    lu: Lu<f64, Dyn>,
    /// Whether `N` spans exactly the coordinates the model solves in closed form, and the
    /// storage of their solution.
    closed_form: bool,
    solution: VecQ<M>,
}

impl<M: LagrangeDirac> FreeVelocities<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The free directions at `(t, q, v)`, `None` if there are none. An error if the model is
    /// sparse (then only Radau integrates it) or the forces leave some of them undetermined.
    pub fn find(
        model: &M,
        t: f64,
        (q, v): (&VecQ<M>, &VecQ<M>),
        method: &str,
    ) -> Result<Option<Self>, SimError> {
        let (sizes, shape) = (model.sizes(), model.shape());
        let (n, m) = (sizes.nq, sizes.nc);
        let (mut lvv, mut a) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_cq(&shape));
        model.l_vv(t, q, v, &mut lvv);
        model.constraint_matrix(t, q, &mut a);
        let Some(directions) =
            free_directions(&dense_qq::<M, M::Algebra>(&lvv, n), &dense_cq::<M, M::Algebra>(&a, m, n))
        else {
            return Err(SimError::NonFinite {
                t,
                component: "the mass matrix or the constraint rows".into(),
            });
        };
        let k = directions.ncols();
        if k == 0 {
            return Ok(None);
        }
        // The same directions, orthonormal in the model's coordinates.
        let basis = directions.qr().q();
        let mut projector = M::Algebra::zeros_qq(&shape);
        if M::Algebra::dense_qq(&projector).is_none() {
            return Err(SimError::NotDetermined {
                t,
                cause: format!(
                    "this model has velocities that no inertia or constraint fixes, only the forces; {method} \
                     integrates them in models of fixed size only: integrate this one with Radau"
                ),
            });
        }
        let product = &basis * basis.transpose();
        M::Algebra::qq_values_mut(&mut projector).copy_from_slice(product.as_slice());
        // `N` holds each solved coordinate's axis where `N Nᵀ` has 1 on its diagonal there;
        // as many axes as directions, it is spanned by them.
        let solved = M::SOLVED_VELOCITIES;
        let closed_form = solved.len() == k && solved.iter().all(|&i| (product[(i, i)] - 1.0).abs() <= 1e-12);
        let mut free = FreeVelocities {
            basis,
            projector,
            blocks: ResidualBlocks::with_sizes(&sizes),
            zero_lambda: sizes.zeros_c::<M>(),
            lvt: sizes.zeros_q::<M>(),
            lvq: M::Algebra::zeros_qq(&shape),
            fv: M::Algebra::zeros_qq(&shape),
            factored_lvq: M::Algebra::zeros_qq(&shape),
            factored_fv: M::Algebra::zeros_qq(&shape),
            factored: false,
            g: vec![0.0; n],
            residual: vec![0.0; k],
            lu: Lu::new(k),
            closed_form,
            solution: sizes.zeros_q::<M>(),
        };
        if free.factor(model, t, (q, v)).is_err() {
            let svd = free_matrix(model, t, (q, v), &free.basis).svd(true, true);
            let v_t = svd.v_t.as_ref().expect("V computed");
            let direction = &free.basis * v_t.row(svd.singular_values.imin()).transpose();
            return Err(SimError::NotDetermined { t, cause: undetermined_velocities(model, &direction) });
        }
        Ok(Some(free))
    }

    /// Removes the components along `N` from `x` (a residual over the coordinates).
    pub fn remove(&self, x: &mut [f64]) {
        let n = x.len();
        for column in self.basis.column_iter() {
            let dot: f64 = (0..n).map(|i| column[i] * x[i]).sum();
            for i in 0..n {
                x[i] -= dot * column[i];
            }
        }
    }

    /// Adds the components of `d` along `N` to `x` (vectors over the coordinates).
    pub fn add_along(&self, x: &mut [f64], d: &[f64]) {
        let n = x.len();
        for column in self.basis.column_iter() {
            let dot: f64 = (0..n).map(|i| column[i] * d[i]).sum();
            for i in 0..n {
                x[i] += dot * column[i];
            }
        }
    }

    /// Forms and factors `Nᵀ (L_qv − L_vq + F_v) N` at `(t, q, v)`.
    fn factor(&mut self, model: &M, t: f64, (q, v): (&VecQ<M>, &VecQ<M>)) -> Result<(), ()> {
        model.l_vq(t, q, v, &mut self.lvq);
        model.force_dv(t, q, v, &mut self.fv);
        let (lvq, fv) = (M::Algebra::qq_values(&self.lvq), M::Algebra::qq_values(&self.fv));
        if self.factored
            && lvq == M::Algebra::qq_values(&self.factored_lvq)
            && fv == M::Algebra::qq_values(&self.factored_fv)
        {
            return Ok(());
        }
        let n = self.g.len();
        let k = self.basis.ncols();
        let basis = self.basis.as_slice();
        let matrix = self.lu.matrix_mut();
        for a in 0..k {
            for b in 0..k {
                let mut sum = 0.0;
                for j in 0..n {
                    let nb = basis[j + b * n];
                    if nb == 0.0 {
                        continue;
                    }
                    for i in 0..n {
                        // Column-major `n × n` blocks: entry (i, j) at i + j n.
                        let d = lvq[j + i * n] - lvq[i + j * n] + fv[i + j * n];
                        sum += basis[i + a * n] * d * nb;
                    }
                }
                matrix[(a, b)] = sum;
            }
        }
        self.factored = self.lu.factor().is_ok();
        M::Algebra::qq_values_mut(&mut self.factored_lvq).copy_from_slice(lvq);
        M::Algebra::qq_values_mut(&mut self.factored_fv).copy_from_slice(fv);
        if self.factored { Ok(()) } else { Err(()) }
    }

    /// Solves `Nᵀ (∂L/∂q + F − L_vq v − ∂²L/∂v∂t) = 0` for the velocities along `N` at
    /// `(t, q)`, starting from `v`, in closed form where the model gives it; false if the closed
    /// form is not finite (a resistance of zero), or Newton's method does not converge in eight
    /// iterations or the matrix is singular there.
    pub fn settle(&mut self, model: &M, t: f64, q: &VecQ<M>, v: &mut VecQ<M>) -> bool {
        if self.closed_form {
            model.solved_velocities(t, q, v, &mut self.solution);
            for &i in M::SOLVED_VELOCITIES {
                let solved = self.solution[i];
                if !solved.is_finite() {
                    return false;
                }
                v[i] = solved;
            }
            return true;
        }
        let n = self.g.len();
        let k = self.basis.ncols();
        for _ in 0..8 {
            model.residual_blocks(t, q, v, &self.zero_lambda, &mut self.blocks);
            self.g.copy_from_slice(self.blocks.momentum_rate.as_slice());
            if !M::SEPARABLE {
                model.l_vt(t, q, v, &mut self.lvt);
                for (g, l) in self.g.iter_mut().zip(self.lvt.iter()) {
                    *g -= l;
                }
                model.l_vq(t, q, v, &mut self.lvq);
                M::Algebra::qq_mul(&self.lvq, -1.0, v.as_slice(), &mut self.g);
            }
            for a in 0..k {
                let column = &self.basis.as_slice()[a * n..(a + 1) * n];
                self.residual[a] = column.iter().zip(&self.g).map(|(b, g)| b * g).sum();
            }
            if self.factor(model, t, (q, v)).is_err() {
                return false;
            }
            self.lu.solve_slice(&mut self.residual);
            let basis = self.basis.as_slice();
            let mut largest = 0.0f64;
            for i in 0..n {
                let step: f64 = (0..k).map(|a| basis[i + a * n] * self.residual[a]).sum();
                v[i] -= step;
                largest = largest.max(step.abs());
            }
            if !largest.is_finite() {
                return false;
            }
            if largest <= 1e-14 * (1.0 + v.amax()) {
                return true;
            }
        }
        false
    }
}
