//! Where each quantity sits in the flat state `y = (q, v, p, λ)` of the semi-explicit DAE
//! `M ẏ = f(t, y)`, `M = diag(I, 0, I, 0)`, and what each slot is called: the one place that
//! knows the slot arithmetic. Integrators, linear solvers, results and error messages ask it
//! instead of computing offsets; [`Unknowns`](crate::shape::layout::Unknowns) answers the same questions for the saddle-point
//! systems in `(v, λ)` that condensed Newton steps, projections and accelerations solve.

use crate::shape::dims::Sizes;

/// The slots of the flat state of a model of some [`Sizes`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// Where the positions start.
    pub q: usize,
    /// Where the velocities start.
    pub v: usize,
    /// Where the momenta start.
    pub p: usize,
    /// Where the multipliers start.
    pub lambda: usize,
    /// The number of slots, `3n + m`.
    pub len: usize,
}

/// What one slot of `y` holds: a part of the state and the index within that part.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Slot {
    /// The position of coordinate `i`.
    Position(usize),
    /// The velocity of coordinate `i`.
    Velocity(usize),
    /// The momentum conjugate to coordinate `i`.
    Momentum(usize),
    /// The multiplier of constraint `j`.
    Multiplier(usize),
}

impl Layout {
    /// The layout of a model of these sizes.
    pub const fn new(sizes: Sizes) -> Layout {
        let n = sizes.nq;
        Layout { q: 0, v: n, p: 2 * n, lambda: 3 * n, len: 3 * n + sizes.nc }
    }

    /// What slot `i` holds.
    ///
    /// # Panics
    ///
    /// If `i` is not below [`Layout::len`](Layout#structfield.len).
    pub fn slot(&self, i: usize) -> Slot {
        assert!(i < self.len, "slot {i} of a state with {} slots", self.len);
        match i {
            _ if i >= self.lambda => Slot::Multiplier(i - self.lambda),
            _ if i >= self.p => Slot::Momentum(i - self.p),
            _ if i >= self.v => Slot::Velocity(i - self.v),
            _ => Slot::Position(i),
        }
    }

    /// Whether row `i` of `M ẏ = f` is a differential equation (`q̇ = v`, `ṗ = …`); the
    /// velocity and multiplier rows (`0 = p − ∂L/∂v`, `0 = A v`) are algebraic.
    pub fn is_differential(&self, i: usize) -> bool {
        matches!(self.slot(i), Slot::Position(_) | Slot::Momentum(_))
    }
}

/// The unknowns of a saddle-point system of a model (a condensed Newton step, a variational
/// stage, a projection, the accelerations): `n` velocity-like unknowns, then `m` multipliers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Unknowns {
    /// The number of velocity-like unknowns, one per coordinate.
    pub n: usize,
    /// The number of multipliers, one per constraint row.
    pub m: usize,
}

/// What one unknown of a saddle-point system is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unknown {
    /// The velocity-like unknown of coordinate `i`.
    Velocity(usize),
    /// The multiplier of constraint `j`.
    Multiplier(usize),
}

impl Unknowns {
    /// The unknowns of a model of these sizes.
    pub const fn new(sizes: Sizes) -> Unknowns {
        Unknowns { n: sizes.nq, m: sizes.nc }
    }

    /// What unknown `column` is.
    pub fn unknown(&self, column: usize) -> Unknown {
        if column < self.n { Unknown::Velocity(column) } else { Unknown::Multiplier(column - self.n) }
    }

    /// A vector of the unknowns split into its velocities and its multipliers.
    pub fn split<'a, T>(&self, x: &'a [T]) -> (&'a [T], &'a [T]) {
        x.split_at(self.n)
    }

    /// [`Unknowns::split`], mutably.
    pub fn split_mut<'a, T>(&self, x: &'a mut [T]) -> (&'a mut [T], &'a mut [T]) {
        x.split_at_mut(self.n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slots_follow_q_v_p_lambda() {
        let layout = Layout::new(Sizes { nq: 2, nc: 1, nh: 0 });
        let slots: Vec<Slot> = (0..layout.len).map(|i| layout.slot(i)).collect();
        use Slot::*;
        assert_eq!(
            slots,
            [Position(0), Position(1), Velocity(0), Velocity(1), Momentum(0), Momentum(1), Multiplier(0)]
        );
        let differential: Vec<bool> = (0..layout.len).map(|i| layout.is_differential(i)).collect();
        assert_eq!(differential, [true, true, false, false, true, true, false]);
    }

    #[test]
    fn saddle_unknowns_are_velocities_then_multipliers() {
        let unknowns = Unknowns::new(Sizes { nq: 2, nc: 1, nh: 0 });
        let kinds: Vec<Unknown> = (0..3).map(|c| unknowns.unknown(c)).collect();
        assert_eq!(kinds, [Unknown::Velocity(0), Unknown::Velocity(1), Unknown::Multiplier(0)]);
        let x = [1.0, 2.0, 3.0];
        assert_eq!(unknowns.split(&x), (&x[..2], &x[2..]));
    }
}
