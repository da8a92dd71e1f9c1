//! Typed names for the components of a model's state.
//!
//! `#[derive(LagrangeDirac)]` emits one associated constant per coordinate and per constraint
//! (`Pendulum::X`, `Pendulum::ROD`), so state components are read and written by name and a
//! typo is a compile error, never an index off by one. A key always names a position its model
//! has: `checked` is the way to make one from a number.

use core::fmt;
use core::marker::PhantomData;

use crate::dims::Dimensions;
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
    ($key:ident, $what:literal, $names:ident, $count:ident) => {
        impl<M: Dimensions + ?Sized> $key<M> {
            #[doc = concat!("The ", $what, " at this position, for generated code: it panics (at")]
            /// compile time in a `const`) if the model has no such position. Use the named
            /// constants the derive emits, or `checked`.
            #[doc(hidden)]
            pub const fn new(index: usize) -> Self {
                assert!(index < M::$count, "the model has no such position");
                Self { index, model: PhantomData }
            }

            #[doc = concat!("The ", $what, " at this position, if the model has one.")]
            pub const fn checked(index: usize) -> Option<Self> {
                if index < M::$count { Some(Self { index, model: PhantomData }) } else { None }
            }
        }

        impl<M: ?Sized> $key<M> {
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

key_impls!(Coordinate, "coordinate", coordinate_names, NQ);
key_impls!(Constraint, "constraint", constraint_names, NC);
