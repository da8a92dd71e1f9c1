//! `#[derive(Interconnection)]`: a composite of Lagrange-Dirac systems joined by a Dirac
//! structure, itself a Lagrange-Dirac system (paper §IV–V): `L = Σ Lᵢ`, `F = ⊕ Fᵢ`, constraint
//! rows `[blockdiag(Aᵢ); Ω]` with multipliers `(λᵢ, μ)`.
//!
//! Parse ([`ast`]), lower the interconnection rows ([`model`]), check their linearity, derive
//! their block table ([`blocks`]), then emit: the `const` items that resolve and check the
//! composite when the program compiles ([`consts`]), the methods from the signature table
//! ([`methods`], with the rows' own parts from [`emit`]) and the named items ([`items`]).

mod ast;
mod blocks;
mod consts;
mod emit;
mod items;
mod methods;
mod model;

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote, quote_spanned};
use syn::DeriveInput;
use syn::spanned::Spanned;

use self::ast::Composite;
use self::blocks::CompositeBlocks;
use self::emit::Own;
use self::items::{Targets, equations, inherent_items, names};
use self::methods::methods;
use self::model::CompositeModel;
use crate::codegen::signatures::rt;
use crate::ctxt::Ctxt;
use crate::expand::stub_impls;

/// Expands the derive on `input`; user errors become `compile_error!` next to a stub impl.
pub fn derive(input: &DeriveInput) -> TokenStream {
    let cx = Ctxt::new();
    let composite = Composite::from_input(&cx, input);
    let model = if composite.incomplete { None } else { CompositeModel::build(&cx, &composite) };
    let built = model.map(|mut model| {
        let linearity = model.linearity_checks(&cx);
        (model, linearity)
    });
    match (cx.into_compile_errors(), built) {
        (None, Some((mut model, linearity))) => {
            let blocks = CompositeBlocks::derive(&mut model);
            implementation(&composite, &model, &blocks, linearity)
        }
        // A generic composite has been reported; an impl for it would only add errors.
        (errors, _) if !input.generics.params.is_empty() => quote! { #errors },
        (errors, _) => {
            // One coordinate and one constraint, so that the stub's keys (index 0) are valid.
            let impls = stub_impls(composite.ident, (1, 1));
            let items = inherent_items(&composite, Targets::Stub, &TokenStream::new());
            quote! { #errors const _: () = { #impls #items }; }
        }
    }
}

/// The offsets of each subsystem and the composite's sizes, as const items.
fn layout(composite: &Composite<'_>, rows: usize) -> TokenStream {
    let p = rt();
    let d = quote! { #p::Dimensions };
    let mut out = TokenStream::new();
    let (mut q, mut h, mut v) = (quote! { 0 }, quote! { 0 }, quote! { __NH });
    for (i, sub) in composite.subsystems.iter().enumerate() {
        let ty = &sub.ty;
        let (qi, hi, vi, slot) = (
            format_ident!("__Q{}", i),
            format_ident!("__H{}", i),
            format_ident!("__V{}", i),
            format_ident!("__SLOT{}", i),
        );
        out.extend(quote! {
            const #qi: ::core::primitive::usize = #q;
            const #hi: ::core::primitive::usize = #h;
            const #vi: ::core::primitive::usize = #v;
            const #slot: #p::Slot = #p::Slot { q: #qi, h: #hi, v: #vi };
        });
        q = quote! { #qi + <#ty as #d>::NQ };
        h = quote! { #hi + <#ty as #d>::NH };
        v = quote! { #vi + (<#ty as #d>::NC - <#ty as #d>::NH) };
    }
    let rows = Literal::usize_unsuffixed(rows);
    out.extend(quote! {
        const __NQ: ::core::primitive::usize = #q;
        const __NH: ::core::primitive::usize = #h;
        const __OMEGA: ::core::primitive::usize = #v;
        const __NC: ::core::primitive::usize = __OMEGA + #rows;
    });
    out
}

fn implementation(
    composite: &Composite<'_>,
    model: &CompositeModel,
    blocks: &CompositeBlocks,
    linearity: TokenStream,
) -> TokenStream {
    let p = rt();
    let ident = composite.ident;
    let own = Own { model, blocks };
    let layout = layout(composite, model.rows.len());
    let resolutions = model.resolutions(composite);
    let structure = model.structure(composite, blocks);
    let asserts = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote_spanned! {ty.span()=>
            const _: fn() = || {
                fn subsystem<M: #p::LagrangeDirac>() where #p::DefaultAllocator: #p::Storage<M> {}
                subsystem::<#ty>();
            };
        }
    });
    let bounds = bounds(composite);
    let names = names(composite, model, &bounds);
    let counts = operation_counts(composite, &own);
    let equations = equations(composite, model);
    let methods = methods(composite, &own);
    let inherent = inherent_items(composite, Targets::Resolved(model), &bounds);
    quote! {
        const _: () = {
            #(#asserts)*
            #layout
            #resolutions
            #linearity
            #structure

            #[automatically_derived]
            impl #p::Dimensions for #ident #bounds {
                type Nq = #p::Const<{ __NQ }>;
                type Nc = #p::Const<{ __NC }>;
                type Nh = #p::Const<{ __NH }>;
                type Nk = #p::Const<{ __NQ + __NC }>;
                type Ny = #p::Const<{ 3 * __NQ + __NC }>;
            }

            #names

            #[automatically_derived]
            #[allow(clippy::approx_constant)]
            impl #p::LagrangeDirac for #ident #bounds {
                #counts
                #equations
                #methods
            }

            #inherent
        };
    }
}

/// `where Sub: LagrangeDirac, …` for every subsystem type, at the field's type: if a field is
/// not a model, this bound is the one error, and the bodies under it report nothing more.
fn bounds(composite: &Composite<'_>) -> TokenStream {
    let p = rt();
    let bounds = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote_spanned! {ty.span()=> #ty: #p::LagrangeDirac, #p::DefaultAllocator: #p::Storage<#ty> }
    });
    quote! { where #(#bounds),* }
}

fn operation_counts(composite: &Composite<'_>, own: &Own<'_>) -> TokenStream {
    let p = rt();
    let (residual, jacobian) = own.op_counts();
    let subs = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote! { .plus(<#ty as #p::LagrangeDirac>::OPERATION_COUNTS) }
    });
    let separable = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote! { <#ty as #p::LagrangeDirac>::SEPARABLE }
    });
    quote! {
        const SEPARABLE: ::core::primitive::bool = true #(&& #separable)*;
        const STRUCTURE: #p::Structure = #p::Structure { pattern: &__PATTERN, unknowns: &__UNKNOWNS };
        const OPERATION_COUNTS: #p::OperationCounts = #p::OperationCounts {
            residual: #residual,
            jacobian: #jacobian,
            residual_and_jacobian: #residual + #jacobian,
            residual_blocks: #residual,
            jacobian_blocks: #jacobian,
        } #(#subs)*;
    }
}
