//! What a run reports of its piecewise motion: the events located and the impacts applied.

/// Which sign changes of an event function count as the event.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Crossing {
    /// From negative to positive.
    Rising,
    /// From positive to negative.
    Falling,
    /// Either way.
    Either,
}

impl Crossing {
    /// Whether a crossing in the direction `rising` counts.
    pub(crate) fn counts(self, rising: bool) -> bool {
        match self {
            Crossing::Rising => rising,
            Crossing::Falling => !rising,
            Crossing::Either => true,
        }
    }
}

/// An event located in an integration: which function crossed zero, when, and which way.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Event {
    /// The event function's index in its [`Events`](crate::hybrid::events::Events), in the order they were added.
    pub index: usize,
    /// The time of the crossing, to round-off: the first time at which the function's value is
    /// zero or has its new sign.
    pub t: f64,
    /// [`Crossing::Rising`] or [`Crossing::Falling`]: the way it crossed.
    pub crossing: Crossing,
}

/// An impact at a unilateral constraint `φ(q, t) ≥ 0`: which one (its index among the model's
/// [`unilateral_names`](crate::model::Named::unilateral_names)), when, and the impulse
/// `Λ ≥ 0` its one-form took, `p⁺ = p⁻ + Λ ∂φ/∂q`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Impact {
    /// The unilateral constraint.
    pub contact: usize,
    /// The time of the impact.
    pub t: f64,
    /// The impulse along the constraint's one-form (a momentum: N·s for a force on a length).
    pub impulse: f64,
}
