//! Typed names for the components of a model's state.
//!
//! `#[derive(LagrangeDirac)]` emits one associated constant per coordinate and per constraint
//! (`Pendulum::X`, `Pendulum::ROD`), so state components are read and written by name and a
//! typo is a compile error, never an index off by one.

use core::fmt;
use core::marker::PhantomData;

use crate::names::Named;

/// A coordinate `q_i` of model `M`; it also names the velocity `v_i` and the momentum `p_i`.
pub struct Coordinate<M: ?Sized> {
    index: usize,
    model: PhantomData<fn() -> M>,
}

/// A constraint row of model `M`; it names the row of `A(q)` and its multiplier `λ_j`.
pub struct Constraint<M: ?Sized> {
    index: usize,
    model: PhantomData<fn() -> M>,
}

macro_rules! key_impls {
    ($key:ident, $what:literal, $names:ident) => {
        impl<M: ?Sized> $key<M> {
            #[doc = concat!("The ", $what, " at this position; used by generated code.")]
            pub const fn new(index: usize) -> Self {
                Self { index, model: PhantomData }
            }

            #[doc = concat!("The position of this ", $what, " in its vector.")]
            pub const fn index(self) -> usize {
                self.index
            }
        }

        impl<M: Named> $key<M> {
            #[doc = concat!("The full dotted name of this ", $what, ", such as `left.x2`.")]
            pub fn name(self) -> String {
                M::NAMES.$names().swap_remove(self.index)
            }
        }

        impl<M: ?Sized> Clone for $key<M> {
            fn clone(&self) -> Self {
                *self
            }
        }

        impl<M: ?Sized> Copy for $key<M> {}

        impl<M: ?Sized> PartialEq for $key<M> {
            fn eq(&self, other: &Self) -> bool {
                self.index == other.index
            }
        }

        impl<M: ?Sized> Eq for $key<M> {}

        impl<M: ?Sized> fmt::Debug for $key<M> {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, "{}(#{})", stringify!($key), self.index)
            }
        }

        impl<M: Named> fmt::Display for $key<M> {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(&self.name())
            }
        }
    };
}

key_impls!(Coordinate, "coordinate", coordinate_names);
key_impls!(Constraint, "constraint", constraint_names);
