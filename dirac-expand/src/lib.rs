//! The implementation of dirac's derive macros, as a library of `proc_macro2` code: what
//! `#[derive(LagrangeDirac)]` and `#[derive(Interconnection)]` do, callable outside a
//! compiler plugin so that its unit tests, snapshot tests and expansion benchmarks run it as
//! it is. Not for direct use: `dirac-macros` calls it, and the `dirac` crate re-exports the
//! derives.
//!
//! A model is parsed, checked, lowered into a symbolic graph over typed symbols, differentiated
//! once into a table of blocks, analysed and emitted as straight-line Rust: attributes → model
//! AST (with spans) → checks → symbolic graph → block table → structure → CSE schedule → Rust
//! tokens.

mod ast;
mod blocks;
mod check;
mod codegen;
mod contacts;
mod ctxt;
mod desugar;
mod equations;
mod expand;
mod interconnect;
mod law_decl;
mod laws;
mod lower;
mod model;
mod reduce;
mod structure;
mod suggest;
mod sym;
mod symbol;
mod symbols;
mod urdf;

#[cfg(test)]
mod snapshots;

use proc_macro2::TokenStream;
use syn::DeriveInput;

/// The expansion of `#[derive(LagrangeDirac)]` on `input`: the trait impls, or the errors
/// (every one found, with its span) beside stub impls.
pub fn lagrange_dirac(input: &DeriveInput) -> TokenStream {
    let expanded = expand::derive(input);
    let description = reduce::description(input, reduce::Kind::Primitive);
    quote::quote! { #expanded #description }
}

/// The expansion of `#[derive(Interconnection)]` on `input`.
pub fn interconnection(input: &DeriveInput) -> TokenStream {
    let expanded = interconnect::derive(input, reduce::start);
    // A reduced composite describes itself as the one model it becomes, when it has become it.
    if interconnect::asks_reduce(input) {
        return expanded;
    }
    let description = reduce::description(input, reduce::Kind::Composite);
    quote::quote! { #expanded #description }
}

/// One step of a reduced composite's gathering of its parts' descriptions: the expansion of
/// the hidden macro `dirac::__reduce`, which the derives call.
pub fn reduce_step(tokens: TokenStream) -> TokenStream {
    reduce::step(tokens)
}
