//! `#[derive(Interconnection)]`: a composite of Lagrange-Dirac systems joined by a Dirac
//! structure, itself a Lagrange-Dirac system (paper §IV–V): `L = Σ Lᵢ`, `F = ⊕ Fᵢ`, constraint
//! rows `[blockdiag(Aᵢ); Ω]` with multipliers `(λᵢ, μ)`.
//!
//! Parse ([`ast`]), lower the interconnection rows ([`model`]), check their linearity, derive
//! their block table ([`blocks`]), then emit: the `const` items that resolve and check the
//! composite when the program compiles ([`consts`]), the methods from the signature table
//! ([`methods`], with the rows' own parts from [`emit`]) and the named items ([`items`]).

pub(crate) mod ast;
mod blocks;
mod consts;
mod emit;
mod items;
pub(crate) mod joints;
mod large;
mod methods;
mod model;
mod parameters;

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote, quote_spanned};
use syn::DeriveInput;
use syn::spanned::Spanned;

use self::ast::Composite;
use self::blocks::CompositeBlocks;
use self::emit::Own;
use self::items::{Targets, equations, inherent_items, names};
use self::methods::{Methods, methods};
use self::model::CompositeModel;
use crate::codegen::signatures::rt;
use crate::ctxt::Ctxt;
use crate::expand::stub_impls;

/// Expands the derive on `input`; user errors become `compile_error!` next to a stub impl. A
/// composite that asks for `reduce` is expanded by `reduce` (the reduction's start) once it
/// is checked.
pub fn derive(
    input: &DeriveInput,
    reduce: impl FnOnce(&Composite<'_>, &DeriveInput) -> TokenStream,
) -> TokenStream {
    let cx = Ctxt::new();
    let composite = Composite::from_input(&cx, input);
    let model = if composite.incomplete { None } else { CompositeModel::build(&cx, &composite) };
    let built = model.map(|mut model| {
        let linearity = model.linearity_checks(&cx);
        (model, linearity)
    });
    match (cx.into_compile_errors(), built) {
        (None, Some(_)) if composite.reduce => reduce(&composite, input),
        (None, Some((mut model, linearity))) => {
            let blocks = CompositeBlocks::derive(&mut model);
            if composite.has_arrays() {
                large::implementation(&composite, &model, &blocks, linearity)
            } else {
                implementation(&composite, &model, &blocks, linearity)
            }
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

/// Whether a composite asks for `reduce` (its errors are the derive's to report).
pub fn asks_reduce(input: &DeriveInput) -> bool {
    let cx = Ctxt::new();
    let reduce = Composite::from_input(&cx, input).reduce;
    let _ = cx.into_compile_errors();
    reduce
}

/// The offsets of each subsystem and the composite's sizes, as const items. Each offset is a
/// prefix sum over arrays of the subsystems' sizes, not a chain of constants, so that the
/// compiler's query depth does not grow with the number of subsystems.
fn layout(composite: &Composite<'_>, rows: usize, holonomic: usize) -> TokenStream {
    let p = rt();
    let u = quote! { ::core::primitive::usize };
    let count = Literal::usize_unsuffixed(composite.subsystems.len());
    // Spanned at each field's type, so that a field that is not a model is reported there.
    let size = |name: &str| -> Vec<TokenStream> {
        let subsystems = composite.subsystems.iter();
        subsystems
            .map(|s| {
                let ty = &s.ty;
                let name = syn::Ident::new(name, ty.span());
                quote_spanned! {ty.span()=> <#ty as ::dirac::__private::Fixed>::#name }
            })
            .collect()
    };
    let (nqs, nhs, ncs) = (size("NQ"), size("NH"), size("NC"));
    let mut out = quote! {
        const __NQS: [#u; #count] = [#(#nqs),*];
        const __NHS: [#u; #count] = [#(#nhs),*];
        const __NCS: [#u; #count] = [#(#ncs),*];
    };
    for i in 0..composite.subsystems.len() {
        let (qi, hi, vi, slot) = (
            format_ident!("__Q{}", i),
            format_ident!("__H{}", i),
            format_ident!("__V{}", i),
            format_ident!("__SLOT{}", i),
        );
        let i = Literal::usize_unsuffixed(i);
        out.extend(quote! {
            const #qi: #u = #p::prefix_sum(&__NQS, #i);
            const #hi: #u = __HOWN + #p::prefix_sum(&__NHS, #i);
            const #vi: #u = __NH + #p::prefix_sum(&__NCS, #i) - #p::prefix_sum(&__NHS, #i);
            const #slot: #p::Offsets = #p::Offsets { q: #qi, h: #hi, v: #vi };
        });
    }
    if !composite.large {
        let message = format!(
            "`{}` is too large for dirac's stack-allocated integrators: a Radau integrator of it holds more \
             than the {} KiB of stack a model may take without asking (threads Rust spawns have 2 MiB, and \
             overflowing a stack aborts the process); add `#[dirac(large)]` and run the simulation on a \
             thread with a larger stack, such as `std::thread::Builder::new().stack_size(64 << 20)`",
            composite.ident,
            dirac_stack_limit() / 1024
        );
        out.extend(quote! {
            const _: () = if #p::stack_bytes(__NQ, __NC) > #p::STACK_LIMIT { ::core::panic!(#message) };
        });
    }
    // The composite's own rows: its holonomic ones first of all (before its subsystems'), its
    // others last; `__ROWS[j]` is own row `j`'s index among the composite's.
    let velocity_rows = Literal::usize_unsuffixed(rows - holonomic);
    let own_rows = (0..rows).map(|j| {
        if j < holonomic {
            let j = Literal::usize_unsuffixed(j);
            quote! { #j }
        } else {
            let j = Literal::usize_unsuffixed(j - holonomic);
            quote! { __OMEGA + #j }
        }
    });
    let (holonomic, rows) = (Literal::usize_unsuffixed(holonomic), Literal::usize_unsuffixed(rows));
    out.extend(quote! {
        const __HOWN: #u = #holonomic;
        const __NQ: #u = #p::prefix_sum(&__NQS, #count);
        const __NH: #u = __HOWN + #p::prefix_sum(&__NHS, #count);
        const __OMEGA: #u = __HOWN + #p::prefix_sum(&__NCS, #count);
        const __NC: #u = __OMEGA + #velocity_rows;
        #[allow(clippy::identity_op)]
        const __ROWS: [#u; #rows] = [#(#own_rows),*];
    });
    out
}

fn dirac_stack_limit() -> usize {
    dirac_structure::stack::STACK_LIMIT
}

fn implementation(
    composite: &Composite<'_>,
    model: &CompositeModel,
    blocks: &CompositeBlocks,
    linearity: TokenStream,
) -> TokenStream {
    let p = rt();
    let input_values = crate::expand::input_values();
    let ident = composite.ident;
    let own = Own { model, blocks };
    let layout = layout(composite, model.rows.len(), model.holonomic);
    let resolutions = model.resolutions(composite);
    let structure = model.structure(composite, blocks);
    let asserts = subsystem_asserts(composite);
    let bounds = bounds(composite);
    let names = names(composite, model, &bounds);
    let (consts, counts) = operation_counts(composite, &own);
    let equations = equations(composite, model);
    let Methods { core, inputs_outputs, parameters, hybrid } = methods(composite, &own);
    let inherent = inherent_items(composite, Targets::Resolved(model), &bounds);
    quote! {
        const _: () = {
            #asserts
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
                #consts
                #core
                #input_values
            }

            #[automatically_derived]
            impl #p::Derivation for #ident #bounds {
                #counts
                #equations
            }

            #[automatically_derived]
            impl #p::InputsOutputs for #ident #bounds {
                #inputs_outputs
            }

            #[automatically_derived]
            #[allow(clippy::approx_constant)]
            impl #p::Parameters for #ident #bounds {
                #parameters
            }

            #[automatically_derived]
            impl #p::Hybrid for #ident #bounds {
                #hybrid
            }

            #[automatically_derived]
            impl #p::JointSpace for #ident #bounds {}

            #inherent
        };
    }
}

/// A check, at each field's type, that the type is a model.
/// For a composite with arrays: its subsystems may not have unilateral constraints or declared
/// events, which it does not gather.
fn no_contacts_or_events(composite: &Composite<'_>) -> TokenStream {
    let p = rt();
    composite
        .subsystems
        .iter()
        .map(|s| {
            let ty = &s.ty;
            quote_spanned! {ty.span()=>
                const _: () = ::core::assert!(
                    <#ty as #p::Named>::NAMES.unilateral_count() == 0 && <#ty as #p::Named>::NAMES.event_count() == 0,
                    "a composite with arrays of subsystems does not gather their unilateral constraints or declared \
                     events yet: declare them on a composite of named subsystems, or add the events with `Events::on`"
                );
            }
        })
        .collect()
}

fn subsystem_asserts(composite: &Composite<'_>) -> TokenStream {
    let p = rt();
    composite
        .subsystems
        .iter()
        .map(|s| {
            let ty = &s.ty;
            quote_spanned! {ty.span()=>
                const _: fn() = || {
                    fn subsystem<M: #p::LagrangeDirac>() where #p::DefaultAllocator: #p::Storage<M> {}
                    subsystem::<#ty>();
                };
                const _: () = ::core::assert!(
                    !<#ty as #p::LagrangeDirac>::NON_ASSOCIATED,
                    "a subsystem whose friction pushes with a contact force (`kinetic = mu * floor`) is \
                     simulated on its own, not interconnected"
                );
            }
        })
        .collect()
}

/// `where Sub: Member, …` (a model of fixed size with every capability) for every subsystem type, at the field's type: if a field is
/// not a model, this bound is the one error, and the bodies under it report nothing more.
fn bounds(composite: &Composite<'_>) -> TokenStream {
    let p = rt();
    let bounds = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote_spanned! {ty.span()=> #ty: #p::Member, #p::DefaultAllocator: #p::Storage<#ty> }
    });
    quote! { where #(#bounds),* }
}

/// The associated constants of the `LagrangeDirac` impl, and the operation counts of the
/// `Derivation` impl.
fn operation_counts(composite: &Composite<'_>, own: &Own<'_>) -> (TokenStream, TokenStream) {
    let p = rt();
    let (residual, jacobian) = own.op_counts();
    let subs = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote! { .plus(<#ty as #p::Derivation>::OPERATION_COUNTS) }
    });
    let separable = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote! { <#ty as #p::LagrangeDirac>::SEPARABLE }
    });
    let prescribed = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote! { <#ty as #p::LagrangeDirac>::PRESCRIBED }
    });
    let constant = composite.subsystems.iter().map(|s| {
        let ty = &s.ty;
        quote! { <#ty as #p::LagrangeDirac>::CONSTANT_CONSTRAINTS }
    });
    let sizes = quote! { #p::Sizes { nq: __NQ, nc: __NC, nh: __NH } };
    let storage = crate::codegen::signatures::fixed_storage(&sizes);
    let consts = quote! {
        #storage
        const SEPARABLE: ::core::primitive::bool = true #(&& #separable)*;
        const PRESCRIBED: ::core::primitive::bool = __PRESCRIBED_OWN #(|| #prescribed)*;
        const CONSTANT_CONSTRAINTS: ::core::primitive::bool =
            !__PRESCRIBED_OWN && !__VARYING_OWN #(&& #constant)*;
        const STRUCTURE: #p::Structure = #p::Structure { pattern: &__PATTERN, unknowns: &__UNKNOWNS };
    };
    let counts = quote! {
        const OPERATION_COUNTS: #p::OperationCounts = #p::OperationCounts {
            residual: #residual,
            jacobian: #jacobian,
            residual_and_jacobian: #residual + #jacobian,
            residual_blocks: #residual,
            jacobian_blocks: #jacobian,
        } #(#subs)*;
    };
    (consts, counts)
}
