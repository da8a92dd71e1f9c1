//! Where each quantity sits in the flat state `y = (q, v, p, λ)` of the semi-explicit DAE
//! `M ẏ = f(t, y)`, `M = diag(I, 0, I, 0)`, and what each slot is called: the one place that
//! knows the slot arithmetic. Integrators, linear solvers, results and error messages ask it
//! instead of computing offsets.

use core::marker::PhantomData;

use crate::dims::Dimensions;
use crate::names::Named;

/// The slots of the flat state of a model `M`.
pub struct Layout<M: ?Sized>(PhantomData<fn() -> M>);

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

impl<M: Dimensions> Layout<M> {
    /// Where the positions start.
    pub const Q: usize = 0;
    /// Where the velocities start.
    pub const V: usize = M::NQ;
    /// Where the momenta start.
    pub const P: usize = 2 * M::NQ;
    /// Where the multipliers start.
    pub const LAMBDA: usize = 3 * M::NQ;
    /// The number of slots, `3n + m`.
    pub const LEN: usize = 3 * M::NQ + M::NC;

    /// What slot `i` holds.
    ///
    /// # Panics
    ///
    /// If `i` is not below [`Layout::LEN`].
    pub fn slot(i: usize) -> Slot {
        assert!(i < Self::LEN, "slot {i} of a state with {} slots", Self::LEN);
        match i {
            _ if i >= Self::LAMBDA => Slot::Multiplier(i - Self::LAMBDA),
            _ if i >= Self::P => Slot::Momentum(i - Self::P),
            _ if i >= Self::V => Slot::Velocity(i - Self::V),
            _ => Slot::Position(i),
        }
    }

    /// Whether row `i` of `M ẏ = f` is a differential equation (`q̇ = v`, `ṗ = …`); the
    /// velocity and multiplier rows (`0 = p − ∂L/∂v`, `0 = A v`) are algebraic.
    pub fn is_differential(i: usize) -> bool {
        matches!(Self::slot(i), Slot::Position(_) | Slot::Momentum(_))
    }
}

impl<M: Dimensions + Named> Layout<M> {
    /// The name of every slot, in order: `x`, `vx`, `p(x)`, `lambda(rod)`; dotted in a
    /// composite (`left.x2`). These are also the column names of a solution.
    pub fn names() -> Vec<String> {
        let names = M::NAMES;
        let coordinates = names.coordinate_names();
        let mut out = coordinates.clone();
        out.extend(names.velocity_names());
        out.extend(coordinates.iter().map(|c| format!("p({c})")));
        out.extend(names.constraint_names().iter().map(|c| format!("lambda({c})")));
        out
    }

    /// Slot `i` in words, for messages: "coordinate `x`", "momentum of `x`".
    pub fn describe(i: usize) -> String {
        let names = M::NAMES;
        match Self::slot(i) {
            Slot::Position(k) => format!("coordinate `{}`", names.coordinate_names()[k]),
            Slot::Velocity(k) => format!("velocity `{}`", names.velocity_names()[k]),
            Slot::Momentum(k) => format!("momentum of `{}`", names.coordinate_names()[k]),
            Slot::Multiplier(k) => format!("multiplier `{}`", names.constraint_names()[k]),
        }
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::Const;

    use super::*;

    struct Sizes;

    impl Dimensions for Sizes {
        type Nq = Const<2>;
        type Nc = Const<1>;
        type Nh = Const<0>;
        type Nk = Const<3>;
        type Ny = Const<7>;
    }

    #[test]
    fn slots_follow_q_v_p_lambda() {
        type L = Layout<Sizes>;
        let slots: Vec<Slot> = (0..L::LEN).map(L::slot).collect();
        use Slot::*;
        assert_eq!(
            slots,
            [Position(0), Position(1), Velocity(0), Velocity(1), Momentum(0), Momentum(1), Multiplier(0)]
        );
        let differential: Vec<bool> = (0..L::LEN).map(L::is_differential).collect();
        assert_eq!(differential, [true, true, false, false, true, true, false]);
    }
}
