//! The methods of a composite's `LagrangeDirac` impl, written from the same signature table
//! as a primitive's: each method evaluates every subsystem's own method on its part of the
//! composite's arguments, scatters the result into the composite's output, and adds the
//! composite's own part (its interconnection rows) where the method has one.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::ast::Composite;
use super::emit::{Own, Part};
use crate::codegen::signatures::{
    Arg, CONSTRAINT_MATRIX, CONSTRAINT_RATE, DATL_DQ, DAV_DQ, DAV_DT, HOLONOMIC, JACOBIAN_BLOCKS, Out,
    REQUIRED, RESIDUAL_BLOCKS, Signature, rt,
};

/// `Ωᵀμ` scattered with the subsystems' port efforts: the one method composites add.
pub(super) const INTERCONNECTION_FORCES: Signature =
    Signature { name: "interconnection_forces", args: &[Arg::T, Arg::Q, Arg::Lambda], out: Out::VecQ };

/// The methods of a composite's trait impls.
pub struct Methods {
    /// `LagrangeDirac`.
    pub core: TokenStream,
    /// `InputsOutputs`.
    pub inputs_outputs: TokenStream,
    /// `Parameters`.
    pub parameters: TokenStream,
    /// `Hybrid`.
    pub hybrid: TokenStream,
}

/// Every method of the composite's impls.
pub fn methods(composite: &Composite<'_>, own: &Own<'_>) -> Methods {
    let mut core: TokenStream =
        REQUIRED.iter().chain([&INTERCONNECTION_FORCES]).map(|sig| method(composite, own, sig)).collect();
    core.extend(invalid_parameter(composite));
    core.extend(super::items::output_method(composite));
    let mut inputs_outputs = super::items::input_methods(composite);
    inputs_outputs.extend(super::items::linearisation_methods(composite));
    Methods {
        core,
        inputs_outputs,
        parameters: super::parameters::parameter_methods(composite, own),
        hybrid: super::items::contact_and_event_methods(composite),
    }
}

/// `fn invalid_parameter`: the composite's own `f64` fields, then each subsystem's, named by
/// their dotted paths.
fn invalid_parameter(composite: &Composite<'_>) -> TokenStream {
    let own = own_parameter_checks(composite);
    let subsystems = composite.subsystems.iter().map(|s| {
        let field = &s.ident;
        let prefix = format!("{}.", syn::ext::IdentExt::unraw(field));
        quote! {
            if let ::core::option::Option::Some((name, value, requirement)) = self.#field.invalid_parameter() {
                let mut path = ::std::string::ToString::to_string(#prefix);
                path.push_str(&name);
                return ::core::option::Option::Some((path, value, requirement));
            }
        }
    });
    quote! {
        fn invalid_parameter(&self) -> ::core::option::Option<(::std::string::String, ::core::primitive::f64, &'static ::core::primitive::str)> {
            #own
            #(#subsystems)*
            ::core::option::Option::None
        }
    }
}

/// `return Some((name, value))` for the first of the composite's own `f64` fields that is not
/// finite.
pub(super) fn own_parameter_checks(composite: &Composite<'_>) -> TokenStream {
    composite
        .params
        .iter()
        .map(|field| {
            let name = syn::ext::IdentExt::unraw(field).to_string();
            quote! {
                if !self.#field.is_finite() {
                    return ::core::option::Option::Some((::std::string::ToString::to_string(#name), self.#field, "finite"));
                }
            }
        })
        .collect()
}

fn method(composite: &Composite<'_>, own: &Own<'_>, sig: &Signature) -> TokenStream {
    let header = sig.header(|_| true, true);
    let parts: TokenStream = composite
        .subsystems
        .iter()
        .enumerate()
        .map(|(i, s)| subsystem_part(sig, &s.ident, &s.ty, i))
        .collect();
    // `#[inline]` as for primitives: the integrators' steps are generic over the model, and
    // without it whether a composite's blocks are inlined there depends on how the compiler
    // splits the crate into codegen units.
    if sig.out == Out::Scalar {
        return quote! {
            #[inline]
            #header {
                let mut total = 0.0;
                #parts
                total
            }
        };
    }
    let (zero, body) = own_part(own, sig);
    quote! {
        #[inline]
        #header {
            #parts
            #zero
            #body
        }
    }
}

/// The zeroing statements and the statements of the composite's own part of a method.
fn own_part(own: &Own<'_>, sig: &Signature) -> (TokenStream, TokenStream) {
    let out = quote! { out };
    let name = sig.name;
    let with = |part: Part, has_v: bool| (part.zero, own.body(&part.assigns, has_v));
    match name {
        _ if name == CONSTRAINT_MATRIX.name => with(own.rows_into(&out, true), false),
        _ if name == DAV_DQ.name => with(own.rows_into(&out, false), true),
        _ if name == DATL_DQ.name => with(own.datl_into(&out), false),
        // `b`: the rows with every velocity at zero.
        _ if name == CONSTRAINT_RATE.name => (TokenStream::new(), own.body(&own.omega_values(&out), false)),
        _ if name == DAV_DT.name => (TokenStream::new(), own.body(&own.time_rates(&out), true)),
        _ if name == HOLONOMIC.name => (TokenStream::new(), own.body(&own.phi_values(&out), false)),
        _ if name == RESIDUAL_BLOCKS.name => {
            let mut assigns = own.omega_values(&quote! { out.constraint_velocity });
            assigns.extend(own.forces_into(&quote! { out.momentum_rate }));
            (TokenStream::new(), own.body(&assigns, true))
        }
        _ if name == JACOBIAN_BLOCKS.name => {
            let (a, g, k) = (
                own.rows_into(&quote! { out.a }, true),
                own.rows_into(&quote! { out.dav_dq }, false),
                own.datl_into(&quote! { out.dpdot_dq }),
            );
            let (za, zg, zk) = (a.zero, g.zero, k.zero);
            let mut assigns = a.assigns;
            assigns.extend(g.assigns);
            assigns.extend(k.assigns);
            (quote! { #za #zg #zk }, own.body(&assigns, true))
        }
        _ if name == INTERCONNECTION_FORCES.name => {
            (TokenStream::new(), own.body(&own.forces_into(&out), false))
        }
        _ => (TokenStream::new(), TokenStream::new()),
    }
}

/// Subsystem `i`'s part of a method: its arguments gathered from the composite's, its method
/// called, and its output scattered into the composite's.
fn subsystem_part(sig: &Signature, field: &syn::Ident, ty: &syn::Type, i: usize) -> TokenStream {
    let p = rt();
    let slot = format_ident!("__SLOT{}", i);
    let name = format_ident!("{}", sig.name);
    let args: Vec<TokenStream> = sig
        .args
        .iter()
        .map(|arg| match arg {
            Arg::T => quote! { t },
            Arg::Q => quote! { &#p::gather_q::<#ty, Self>(q, &#slot) },
            Arg::V => quote! { &#p::gather_q::<#ty, Self>(v, &#slot) },
            Arg::Lambda => quote! { &#p::gather_c::<#ty, Self>(lambda, &#slot) },
            Arg::Y => unreachable!("composites assemble their flat methods from the blocks"),
            Arg::A => unreachable!("only a reduced composite's flat model recovers series"),
            Arg::K => quote! { k },
            Arg::WeightBlocks | Arg::WeightHolonomic => {
                unreachable!("composites write their transposed parameter blocks by hand")
            }
            Arg::WeightDlDq | Arg::WeightDlDv | Arg::WeightForce => {
                unreachable!("composites have no second-order blocks")
            }
        })
        .collect();
    if sig.out == Out::Scalar {
        return quote! { total += self.#field.#name(#(#args),*); };
    }
    let call = quote! { self.#field.#name(#(#args,)* &mut o); };
    let scatter = |part: &str, from: TokenStream, to: TokenStream| {
        let f = format_ident!("scatter_{}", part);
        quote! { #p::#f::<#ty, Self>(&#from, &#slot, #to); }
    };
    let o = quote! { o };
    let (zeros, scattered) = match sig.out {
        Out::VecQ => (quote! { #p::VecQ::<#ty>::zeros() }, scatter("q", o, quote! { out })),
        Out::VecH => (quote! { #p::VecH::<#ty>::zeros() }, scatter("h", o, quote! { out })),
        Out::VecC => (quote! { #p::VecC::<#ty>::zeros() }, scatter("c", o, quote! { out })),
        Out::MatQQ => (quote! { #p::MatQQ::<#ty>::zeros() }, scatter("qq", o, quote! { out })),
        Out::MatCQ => (quote! { #p::MatCQ::<#ty>::zeros() }, scatter("cq", o, quote! { out })),
        Out::ResidualBlocks => {
            let mut s = scatter("q", quote! { o.momentum_rate }, quote! { &mut out.momentum_rate });
            s.extend(scatter("q", quote! { o.dl_dv }, quote! { &mut out.dl_dv }));
            s.extend(scatter("c", quote! { o.constraint_velocity }, quote! { &mut out.constraint_velocity }));
            (quote! { #p::ResidualBlocks::<#ty>::zeros() }, s)
        }
        Out::JacobianBlocks => {
            let mut s = TokenStream::new();
            for (block, kind) in [
                ("dpdot_dq", "qq"),
                ("dpdot_dv", "qq"),
                ("l_vq", "qq"),
                ("l_vv", "qq"),
                ("a", "cq"),
                ("dav_dq", "cq"),
            ] {
                let b = format_ident!("{}", block);
                s.extend(scatter(kind, quote! { o.#b }, quote! { &mut out.#b }));
            }
            (quote! { #p::JacobianBlocks::<#ty>::zeros() }, s)
        }
        Out::Scalar | Out::VecY | Out::MatYY | Out::Values | Out::ResidualBlocksEach => {
            unreachable!("not a block written by subsystems")
        }
    };
    quote! {{
        let mut o = #zeros;
        #call
        #scattered
    }}
}
