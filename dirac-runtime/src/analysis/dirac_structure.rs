//! Dirac structures as objects: the induced Dirac structure `D_ΔQ` of a constraint
//! distribution (paper eq. 1), products (eq. 4) and interconnection `⋈` (eqs. 5–6), with a
//! membership test for a pair `(w, α)`.
//!
//! In coordinates, with `Δ_Q(q) = ker A(q)`, a pair of a tangent vector `w = (q̇, ṗ)` and a
//! covector `α = (β, u)` on `T*Q` belongs to `D_ΔQ(q, p)` when
//!
//! ```text
//! q̇ ∈ Δ_Q(q)    (A q̇ = 0),    u = q̇,    β + ṗ ∈ Δ_Q°(q) = range(Aᵀ)
//! ```
//!
//! A Lagrange-Dirac system's solution satisfies `(X, dE|TP + F̃) ∈ D_ΔQ` (eq. 2) with
//! `X = (v, ṗ)` and `dE|TP + F̃ = (−∂L/∂q − F, v)`. These objects are for checking and
//! explaining; integrators use the model's blocks directly.

use nalgebra::{DMatrix, DVector, DefaultAllocator};

use crate::algebra::{Algebra, dense_cq};
use crate::model::LagrangeDirac;
use crate::shape::dims::{Storage, VecQ};

/// The induced Dirac structure of `Δ_Q = ker A` at one configuration: the rows of `A` are the
/// one-forms that annihilate the distribution.
#[derive(Clone, Debug, PartialEq)]
pub struct DiracStructure {
    a: DMatrix<f64>,
}

/// How far a pair `(w, α)` is from a Dirac structure, condition by condition.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Membership {
    /// `‖A q̇‖`: how far `q̇` is from the distribution.
    pub distribution: f64,
    /// `‖u − q̇‖`.
    pub velocity: f64,
    /// The distance of `β + ṗ` from the annihilator `range(Aᵀ)`.
    pub annihilator: f64,
}

impl Membership {
    /// The largest of the three residuals.
    pub fn max(&self) -> f64 {
        self.distribution.max(self.velocity).max(self.annihilator)
    }
}

impl DiracStructure {
    /// The structure induced by the one-forms in the rows of `a` (`n` columns).
    pub fn from_one_forms(a: DMatrix<f64>) -> DiracStructure {
        DiracStructure { a }
    }

    /// The structure a model induces at time `t` and configuration `q`: its constraint rows
    /// `A(q, t)` (of a rheonomic constraint `A v + b = 0`, the linear part).
    pub fn of_model<M: LagrangeDirac>(model: &M, t: f64, q: &VecQ<M>) -> DiracStructure
    where
        DefaultAllocator: Storage<M>,
    {
        let sizes = model.sizes();
        let mut a = M::Algebra::zeros_cq(&model.shape());
        model.constraint_matrix(t, q, &mut a);
        DiracStructure { a: dense_cq::<M, M::Algebra>(&a, sizes.nc, sizes.nq) }
    }

    /// The one-forms, one per row.
    pub fn one_forms(&self) -> &DMatrix<f64> {
        &self.a
    }

    /// The dimension of the configuration space.
    pub fn dim(&self) -> usize {
        self.a.ncols()
    }

    /// The product structure `D1 × D2` on `Q1 × Q2` (eq. 4): block-diagonal one-forms.
    pub fn product(&self, other: &DiracStructure) -> DiracStructure {
        let (m1, n1) = self.a.shape();
        let (m2, n2) = other.a.shape();
        let mut a = DMatrix::zeros(m1 + m2, n1 + n2);
        a.view_mut((0, 0), (m1, n1)).copy_from(&self.a);
        a.view_mut((m1, n1), (m2, n2)).copy_from(&other.a);
        DiracStructure { a }
    }

    /// The interconnection `D ⋈ D_int` (eqs. 5–6) with the interconnection one-forms `Ω` (rows):
    /// the induced structure of `Δ_C = Δ ∩ Δ_int`, whose annihilator is spanned by both.
    ///
    /// # Panics
    ///
    /// If `omega` has a different number of columns than the structure's dimension.
    pub fn interconnect(&self, omega: &DMatrix<f64>) -> DiracStructure {
        assert_eq!(
            omega.ncols(),
            self.dim(),
            "interconnection one-forms live on the same configuration space"
        );
        let (m, n) = self.a.shape();
        let mut a = DMatrix::zeros(m + omega.nrows(), n);
        a.view_mut((0, 0), (m, n)).copy_from(&self.a);
        a.view_mut((m, 0), (omega.nrows(), n)).copy_from(omega);
        DiracStructure { a }
    }

    /// How far `((q̇, ṗ), (β, u))` is from this structure.
    pub fn membership(&self, qdot: &[f64], pdot: &[f64], beta: &[f64], u: &[f64]) -> Membership {
        let n = self.dim();
        let (qdot, pdot) = (DVector::from_column_slice(qdot), DVector::from_column_slice(pdot));
        let (beta, u) = (DVector::from_column_slice(beta), DVector::from_column_slice(u));
        assert!(
            qdot.len() == n && pdot.len() == n && beta.len() == n && u.len() == n,
            "vectors of dimension n"
        );
        let distribution = (&self.a * &qdot).norm();
        let velocity = (&u - &qdot).norm();
        let w = beta + pdot;
        let annihilator = if self.a.nrows() == 0 {
            w.norm()
        } else {
            // The residual of the least-squares fit of w by combinations Aᵀ c of the one-forms.
            let at = self.a.transpose();
            let c = at.clone().svd(true, true).solve(&w, 1e-12).expect("SVD with both factors computed");
            (w - at * c).norm()
        };
        Membership { distribution, velocity, annihilator }
    }
}
