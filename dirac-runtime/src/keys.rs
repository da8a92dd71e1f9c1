//! Typed names for the components of a model's state.
//!
//! `#[derive(LagrangeDirac)]` emits one associated constant per coordinate and per constraint
//! (`Pendulum::X`, `Pendulum::ROD`), so state components are read and written by name and a
//! typo is a compile error, never an index off by one.

use core::fmt;
use core::marker::PhantomData;

/// A coordinate `q_i` of model `M`; it also names the velocity `v_i` and the momentum `p_i`.
pub struct Coordinate<M: ?Sized> {
    index: usize,
    name: &'static str,
    model: PhantomData<fn() -> M>,
}

/// A constraint row of model `M`; it names the row of `A(q)` and its multiplier `λ_j`.
pub struct Constraint<M: ?Sized> {
    index: usize,
    name: &'static str,
    model: PhantomData<fn() -> M>,
}

macro_rules! key_impls {
    ($key:ident, $what:literal) => {
        impl<M: ?Sized> $key<M> {
            #[doc = concat!("The ", $what, " with this position and name; used by generated code.")]
            pub const fn new(index: usize, name: &'static str) -> Self {
                Self { index, name, model: PhantomData }
            }

            #[doc = concat!("The position of this ", $what, " in its vector.")]
            pub const fn index(self) -> usize {
                self.index
            }

            #[doc = concat!("The name of this ", $what, " as declared in the model.")]
            pub const fn name(self) -> &'static str {
                self.name
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
                write!(f, "{}({} #{})", stringify!($key), self.name, self.index)
            }
        }

        impl<M: ?Sized> fmt::Display for $key<M> {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(self.name)
            }
        }
    };
}

key_impls!(Coordinate, "coordinate");
key_impls!(Constraint, "constraint");
