//! Typed names for the components of a model's state.
//!
//! `#[derive(LagrangeDirac)]` emits one associated constant per coordinate and per constraint
//! (`Pendulum::X`, `Pendulum::ROD`), so state components are read and written by name and a
//! typo is a compile error, never an index off by one. A key of a model whose sizes are fixed
//! when it compiles always names a position its model has: `checked` is the way to make one
//! from a number. A model made of arrays hands out its keys from methods that check the
//! element index against the model itself (`ladder.cells(3, Cell::Q)`).

use core::fmt;
use core::marker::PhantomData;

use crate::model::named::Named;
use crate::shape::dims::Fixed;

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

/// What every key type has: its position, and value semantics.
macro_rules! common_key_impls {
    ($key:ident, $what:literal) => {
        impl<M: ?Sized> $key<M> {
            /// The key at this position, for generated code that has checked it against the
            /// model. Not part of the public API.
            #[doc(hidden)]
            pub const fn unchecked(index: usize) -> Self {
                Self { index, model: PhantomData }
            }

            #[doc = concat!("The position of this ", $what, " among the model's.")]
            pub const fn index(self) -> usize {
                self.index
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
    };
}

macro_rules! key_impls {
    ($key:ident, $what:literal, $names:ident, $count:ident) => {
        impl<M: Fixed + ?Sized> $key<M> {
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

        common_key_impls!($key, $what);

        impl<M: Named + Fixed> $key<M> {
            #[doc = concat!("The full dotted name of this ", $what, ", such as `left.x2` (for a")]
            /// model made of arrays, ask the model: `model.coordinate_names()[key.index()]`).
            pub fn name(self) -> String {
                M::NAMES.$names().swap_remove(self.index)
            }
        }

        impl<M: Named + Fixed> fmt::Display for $key<M> {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(&self.name())
            }
        }
    };
}

key_impls!(Coordinate, "coordinate", coordinate_names, NQ);
key_impls!(Constraint, "constraint", constraint_names, NC);

macro_rules! model_key {
    ($(#[$doc:meta])* $key:ident, $what:literal, $count:ident, $names:ident, $example:literal) => {
        $(#[$doc])*
        pub struct $key<M: ?Sized> {
            index: usize,
            model: PhantomData<fn() -> M>,
        }

        impl<M: Named + ?Sized> $key<M> {
            #[doc = concat!("The ", $what, " at this position, for generated code: it panics (at")]
            /// compile time in a `const`) if the model has no such position. Use the named
            /// constants the derive emits, or `checked`.
            #[doc(hidden)]
            pub const fn new(index: usize) -> Self {
                assert!(index < M::NAMES.$count(), concat!("the model has no such ", $what));
                Self { index, model: PhantomData }
            }

            #[doc = concat!("The ", $what, " at this position, if the model has one.")]
            pub const fn checked(index: usize) -> Option<Self> {
                if index < M::NAMES.$count() { Some(Self { index, model: PhantomData }) } else { None }
            }

            #[doc = concat!("The full dotted name of this ", $what, ", such as `", $example, "` (for a model")]
            #[doc = concat!("made of arrays, ask the model: `model.", stringify!($names), "()[key.index()]`).")]
            pub fn name(self) -> String {
                M::NAMES.$names().swap_remove(self.index)
            }
        }

        common_key_impls!($key, $what);

    };
}

model_key!(
    /// An input of model `M` (`#[dirac(input(u))]`): an `f64` field that the simulation sets
    /// while it runs. A composite's inputs are its subsystems', in field order
    /// (`Robot::arm_input(Arm::TAU)`).
    Input,
    "input",
    input_count,
    input_names,
    "motor.voltage"
);

model_key!(
    /// An output of model `M` (`#[dirac(output(name) = …)]`): a quantity computed from the
    /// state, recorded in solutions by name. A composite's outputs are its subsystems', in
    /// field order (`Robot::arm_output(Arm::TIP_X)`).
    Output,
    "output",
    output_count,
    output_names,
    "arm.tip_x"
);
