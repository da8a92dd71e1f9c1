//! Derive macros of dirac. Use them through the `dirac` crate, which re-exports them with the
//! runtime they generate code for.

mod sym;
