//! What dirac decides about a model's structure twice, from one source so that both decide
//! alike: once in the derive, while a model expands (with spans for its errors), and once in
//! the runtime's `const` items, where an interconnection checks itself from its subsystems'
//! constants when it compiles.
//!
//! - [`matching`]: a maximum matching of the condensed Newton system's pattern, which finds an
//!   unknown no equation determines (a structurally singular model);
//! - [`stack`]: how much stack one integrator of a model holds, and how much a model may take
//!   without asking.
//!
//! Both are `const fn`s that depend on nothing. Not for direct use: the `dirac` crate uses it.

pub mod matching;
pub mod stack;
