//! The symbolic engine: a hash-consed expression graph with canonicalising constructors,
//! memoised differentiation, evaluation, s-expressions, and emission as straight-line Rust.

mod diff;
pub mod emit;
mod eval;
pub mod graph;
pub mod pretty;
#[cfg(test)]
mod proptests;
mod reverse;
#[cfg(test)]
mod sexpr;

#[cfg(test)]
mod tests;

pub use graph::{Func, Graph, Id, Node};
