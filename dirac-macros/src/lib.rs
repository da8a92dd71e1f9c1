//! Derive macros of dirac. Use them through the `dirac` crate, which re-exports them with the
//! runtime they generate code for.
//!
//! The derive parses a model, checks it, lowers its expressions into a symbolic graph over
//! typed symbols, differentiates them once into a table of blocks, analyses the blocks and
//! emits straight-line Rust from them: attributes → model AST (with spans) → checks →
//! symbolic graph → block table → structure → CSE schedule → Rust tokens. That work is the
//! library `dirac-expand`; this crate is its entry points.

use proc_macro::TokenStream;
use syn::{DeriveInput, parse_macro_input};

/// Derives `dirac::LagrangeDirac` (and `dirac::Dimensions`) for a struct whose `f64` fields are
/// the model's parameters, from `#[dirac(...)]` attributes:
///
/// - `coordinates(x1 => v1, x2 => v2)`: coordinates and their velocity names (default `v_x`);
/// - `lagrangian = expr`: the Lagrangian `L(q, v, t)`, possibly degenerate;
/// - `holonomic(name) = expr`: a position constraint `φ(q, t) = 0`, name optional;
/// - `constraint(name) = expr`: a velocity constraint affine in the velocities,
///   `A(q, t) v + b(q, t) = 0`;
/// - `force(x) = expr`: the external force on coordinate `x`, a function of `q`, `v`, `t`;
/// - `port(x, ...)`: coordinates through which the model may be interconnected.
///
/// See the `dirac` crate documentation for examples.
#[proc_macro_derive(LagrangeDirac, attributes(dirac))]
pub fn derive_lagrange_dirac(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    dirac_expand::lagrange_dirac(&input).into()
}

/// Derives `dirac::LagrangeDirac` for a struct whose fields are Lagrange-Dirac systems (its
/// subsystems) and `f64` parameters, interconnected through `#[dirac(...)]` attributes:
///
/// - `connect(a.x, b.y)`: ports `a.x` and `b.y` move together, `v_a.x = v_b.y`, and their
///   efforts balance, `f_a.x + f_b.y = 0` (paper eq. 8);
/// - `constraint(name) = expr`: a general interconnection one-form, linear in the subsystems'
///   velocities (`r * wheel.v_theta - cart.v_x`), with coefficients that may depend on their
///   coordinates and on the struct's `f64` fields.
///
/// - `reduce`: flatten the parts into one model when the program compiles, solving the rows
///   that only relate coordinates linearly with constant coefficients (connections, grounds,
///   fixed flanges, gears); the names keep their dotted paths.
///
/// The result is again a Lagrange-Dirac system, so interconnections nest.
#[proc_macro_derive(Interconnection, attributes(dirac))]
pub fn derive_interconnection(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    dirac_expand::interconnection(&input).into()
}

/// One step of a reduced composite's gathering of its parts (`#[dirac(reduce)]`): called by
/// the code the derives emit, never by hand.
#[doc(hidden)]
#[proc_macro]
pub fn __reduce(input: TokenStream) -> TokenStream {
    dirac_expand::reduce_step(input.into()).into()
}
