//! Reduction of an interconnection at compile time (DESIGN §6.1): `#[dirac(reduce)]` on a
//! composite flattens its parts into one model and eliminates the rows that only say two
//! coordinates move together.
//!
//! A derive sees only its own struct, so every model a derive makes also describes itself: a
//! `macro_rules!` named like the struct ([`description`]) that hands its derive input to a
//! callback. A reduced composite asks each of its parts' macros in turn, through the
//! function-like macro `dirac::__reduce` ([`step`]), until it holds every part's description
//! (nested composites' parts too); then [`flatten`] writes the one model, which the derive of
//! `LagrangeDirac` expands as any other, and [`rewrite`] points its parameters at the parts'
//! fields.

mod affine;
mod chain;
mod derivative;
mod flatten;
mod rewrite;

use std::cell::Cell;
use std::hash::{DefaultHasher, Hash, Hasher};

use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::DeriveInput;

pub use self::chain::{start, step};

/// Which derive a description comes from.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Kind {
    /// `#[derive(LagrangeDirac)]`.
    Primitive,
    /// `#[derive(Interconnection)]`.
    Composite,
}

impl Kind {
    fn keyword(self) -> &'static str {
        match self {
            Kind::Primitive => "primitive",
            Kind::Composite => "composite",
        }
    }
}

thread_local! {
    /// Descriptions made so far by this thread: keeps the macros' names apart when two structs
    /// of one crate are written alike.
    static MADE: Cell<usize> = const { Cell::new(0) };
}

/// The macro that describes a model to a reduced composite: `Name! { callback { state } }`
/// expands to `callback! { state { kind input } }`. It is exported with the struct's
/// visibility, under the struct's name (macros and types live in different namespaces), so
/// that a path naming the type names the macro too. A generic struct has none: it cannot be a
/// part of a reduced composite.
pub fn description(input: &DeriveInput, kind: Kind) -> TokenStream {
    if !input.generics.params.is_empty() {
        return TokenStream::new();
    }
    let ident = &input.ident;
    let mut hasher = DefaultHasher::new();
    quote!(#input).to_string().hash(&mut hasher);
    let made = MADE.with(|m| {
        let n = m.get();
        m.set(n + 1);
        n
    });
    let name = format_ident!("__dirac_model_{}_{:x}_{}", ident, hasher.finish() & 0xffff_ffff, made);
    // The description keeps what the derive reads: the `dirac` attributes and the fields.
    let mut described = input.clone();
    described.attrs.retain(|a| a.path().is_ident(crate::symbol::DIRAC));
    if let syn::Data::Struct(data) = &mut described.data {
        for field in data.fields.iter_mut() {
            field.attrs.clear();
        }
    }
    let keyword = format_ident!("{}", kind.keyword());
    let vis = &input.vis;
    let exported = matches!(vis, syn::Visibility::Public(_));
    let export = exported.then(|| quote! { #[macro_export] #[allow(non_local_definitions)] });
    quote! {
        #[doc(hidden)]
        #export
        macro_rules! #name {
            ($cb:path { $($state:tt)* }) => { $cb! { $($state)* { #keyword #described } } };
        }
        #[doc(hidden)]
        #[allow(unused_imports)]
        #vis use #name as #ident;
    }
}
