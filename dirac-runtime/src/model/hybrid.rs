//! The hybrid capability: what makes a model's motion piecewise, its event functions
//! `g(t, q, v, λ)` and its unilateral constraints `φ_u(q, t) ≥ 0` (contacts, stops, walls)
//! with their one-forms, restitutions and, in the companion that lets contacts rest, the switch
//! that holds a closed contact as a constraint row.

use nalgebra::DefaultAllocator;

use crate::model::lagrange_dirac::LagrangeDirac;
use crate::model::names::{CLOSES, CONDUCTS, STOPS};
use crate::shape::dims::{Storage, VecC, VecQ};

/// A model with event functions and unilateral constraints. The derives implement it for
/// every model they make (one without keeps the defaults: no events, no contacts);
/// [`Events::declared`](crate::Events::declared) and [`Events::contacts`](crate::Events::contacts)
/// ask for it in their bounds.
pub trait Hybrid: LagrangeDirac
where
    DefaultAllocator: Storage<Self>,
{
    /// The model's event functions `g(t, q, v, λ)` (`#[dirac(event(name, direction) = g)]`),
    /// into `out`, one per event in the order declared (`Events::new().declared()` watches
    /// them).
    fn events(&self, t: f64, q: &VecQ<Self>, v: &VecQ<Self>, lambda: &VecC<Self>, out: &mut [f64]) {
        let _ = (t, q, v, lambda);
        assert!(out.is_empty(), "events: the model declares none, so the slice must be empty");
    }

    /// How many values [`Hybrid::event_derivatives`] writes: zero where it is not generated (a
    /// network, a model whose events are too many for dense rows, an interconnection with such
    /// a part); a derived model with events has it.
    fn event_derivatives_len(&self) -> usize {
        0
    }

    /// The gradient of each event function (`Hybrid::events`), into `out`, event after event:
    /// `∂g/∂q` (`n`), `∂g/∂v` (`n`), `∂g/∂λ` (`m`), `∂g/∂t` and `∂g/∂θ` (the model's `P`
    /// parameters in order), `2n + m + 1 + P` values an event
    /// ([`Hybrid::event_derivatives_len`] in all). Generated symbolically where that is not
    /// zero; otherwise it writes nothing. What carries a sensitivity across a switching surface.
    fn event_derivatives(
        &self,
        t: f64,
        q: &VecQ<Self>,
        v: &VecQ<Self>,
        lambda: &VecC<Self>,
        out: &mut [f64],
    ) {
        let _ = (t, q, v, lambda);
        assert!(
            out.is_empty(),
            "event_derivatives: not generated for this model, so the slice must be empty"
        );
    }

    /// The values `φ_u(q, t)` of the unilateral constraints, into `out` (one per constraint):
    /// positive while open, zero at contact.
    fn unilateral(&self, t: f64, q: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q);
        assert!(
            out.is_empty(),
            "unilateral: the model has no unilateral constraints, so the slice must be empty"
        );
    }

    /// `∂φ_u/∂q`, one row per unilateral constraint (its one-form, along which an impact's
    /// impulse acts), dense and column-major.
    fn unilateral_dq(&self, t: f64, q: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q);
        assert!(
            out.is_empty(),
            "unilateral_dq: the model has no unilateral constraints, so the slice must be empty"
        );
    }

    /// The coefficient of restitution of each unilateral constraint: the share of the normal
    /// velocity an impact reverses (1 elastic, 0 plastic).
    fn restitution(&self, t: f64, q: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q);
        assert!(
            out.is_empty(),
            "restitution: the model has no unilateral constraints, so the slice must be empty"
        );
    }

    /// How many values [`Hybrid::unilateral_derivatives`] writes: zero where the derive does
    /// not emit it (an interconnection does not yet; a primitive model with unilateral
    /// constraints does).
    fn unilateral_derivatives_len(&self) -> usize {
        0
    }

    /// What the derivative of an impact needs of the unilateral constraints, into `out`, for
    /// `k` constraints, `n` coordinates and the model's `P` parameters in order:
    ///
    /// 1. each constraint's Hessian `∂²φ_j/∂q²`, `n × n` column-major, `k` of them (`k n²`);
    /// 2. `∂e/∂q` of the restitutions, `k × n` column-major (`k n`);
    /// 3. for `x = t, θ_0, …, θ_{P−1}` in turn: `∂φ/∂x` (`k`), `∂a/∂x` (`k × n` column-major,
    ///    `a = ∂φ/∂q` the one-forms) and `∂e/∂x` (`k`);
    /// 4. for the same `x` in turn, `∂²φ/∂t∂x` (`k`): how a moving contact's own speed changes.
    ///
    /// `k n² + k n + (P + 1)(3k + k n)` values in all
    /// ([`Hybrid::unilateral_derivatives_len`]). Generated symbolically where that is not zero;
    /// otherwise it writes nothing.
    fn unilateral_derivatives(&self, t: f64, q: &VecQ<Self>, out: &mut [f64]) {
        let _ = (t, q);
        assert!(
            out.is_empty(),
            "unilateral_derivatives: not generated for this model, so the slice must be empty"
        );
    }

    /// Whether unilateral constraint `j` is closed, held as a holonomic constraint: in the
    /// companion the derive makes of a model with unilateral constraints
    /// (`model.with_contacts()`, of type `<Model>WithContacts`); never in other models.
    fn contact_closed(&self, j: usize) -> bool {
        let _ = j;
        false
    }

    /// Closes or opens unilateral constraint `j` of a companion with contacts that can rest;
    /// whether the model has such a switch (false for other models, which it leaves alone).
    fn set_contact_closed(&mut self, j: usize, closed: bool) -> bool {
        let _ = (j, closed);
        false
    }

    /// The constraint row that holds unilateral constraint `j` while it is closed, in a
    /// companion with contacts that can rest: its multiplier is the contact force.
    fn contact_row(&self, j: usize) -> Option<usize> {
        let _ = j;
        None
    }
}

/// Whether `model` declares a friction law, an ideal diode or an ideal switch.
pub fn has_laws<M: LagrangeDirac>(model: &M) -> bool
where
    DefaultAllocator: Storage<M>,
{
    model.any_event(&|code| matches!(code, STOPS | CONDUCTS | CLOSES))
}
