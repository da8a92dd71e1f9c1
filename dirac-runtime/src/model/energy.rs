//! The energy balance of a model, computed from its core blocks: the generalised energy
//! `E = ⟨p, v⟩ − L` and the powers that change it on solutions,
//! `dE/dt = ⟨F, v⟩ − ∂L/∂t − ⟨λ, b⟩` (the forces, an explicit time dependence of `L`, and
//! constraints that prescribe a motion), with the interconnection's power, zero when lossless.

use nalgebra::DefaultAllocator;

use crate::model::lagrange_dirac::LagrangeDirac;
use crate::shape::dims::{Storage, VecC, VecQ};

/// The energy and powers of any model, from its blocks: implemented for every
/// [`LagrangeDirac`] model.
pub trait EnergyBalance: LagrangeDirac
where
    DefaultAllocator: Storage<Self>,
{
    /// The generalised energy `E(q, v, p) = ⟨p, v⟩ − L(q, v, t)`.
    fn energy(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, p: &VecQ<Self>) -> f64 {
        p.dot(v) - self.lagrangian(t, q, v)
    }

    /// The power of the external forces `⟨F(q, v, t), v⟩`, the dissipation's `−∂R/∂v`
    /// included; on solutions `dE/dt` equals it (plus `−∂L/∂t` and the constraints' power).
    fn power(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>) -> f64 {
        let mut f = self.sizes().zeros_q::<Self>();
        self.force(t, q, v, &mut f);
        f.dot(v)
    }

    /// The power `⟨Aᵀλ, v⟩ = −⟨λ, b(q, t)⟩` that the constraints put into the model where
    /// they hold: zero unless a constraint prescribes a motion. On solutions
    /// `dE/dt = ⟨F, v⟩ − ∂L/∂t + constraint_power`. Where friction pushes with a contact
    /// force ([`LagrangeDirac::NON_ASSOCIATED`]), its power `⟨(B − A)ᵀλ, v⟩` adds to this:
    /// a solution's constraint-power series holds both.
    fn constraint_power(&self, t: f64, q: &VecQ<Self>, lambda: &VecC<Self>) -> f64 {
        let mut b = self.sizes().zeros_c::<Self>();
        self.constraint_rate(t, q, &mut b);
        -b.dot(lambda)
    }

    /// The power `⟨Ωᵀμ, v⟩` of the interconnection forces; zero wherever the interconnection
    /// constraints hold, since an interconnection is lossless (Tellegen's theorem), unless it
    /// prescribes a relative motion (`Ω v + b = 0`): then it is `−⟨μ, b⟩`.
    fn interconnection_power(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>) -> f64 {
        let mut f = self.sizes().zeros_q::<Self>();
        self.interconnection_forces(t, q, lambda, &mut f);
        f.dot(v)
    }
}

impl<M: LagrangeDirac> EnergyBalance for M where DefaultAllocator: Storage<M> {}
