//! A composite's parameter methods: each parameter index dispatched to the subsystem that owns
//! it (its derivative blocks computed on its part of the arguments and scattered into the
//! composite's), or to the composite's own `f64` fields, whose derivatives are those of the
//! interconnection rows and their forces. All parameters at once: each subsystem's together
//! (sharing what its parameters' derivatives share), the composite's own one by one.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use super::ast::Composite;
use super::emit::Own;
use super::items::parameter_offset;
use crate::codegen::signatures::rt;

/// `parameter_value`, `set_parameter_value`, `residual_blocks_dtheta`,
/// `residual_blocks_dtheta_all` and `holonomic_dtheta`.
pub fn parameter_methods(composite: &Composite<'_>, own: &Own<'_>) -> TokenStream {
    let p = rt();
    let own_start = parameter_offset(composite, composite.subsystems.len());
    let total = quote! { <Self as #p::Named>::NAMES.parameter_count() };
    let panic = quote! { ::core::panic!("the model has no parameter {}: it has {}", k, #total) };
    // `if k` is subsystem `i`'s: `call` with `k - start`, its own index.
    let dispatch = |call: &dyn Fn(&syn::Ident, &syn::Type, usize) -> TokenStream| -> TokenStream {
        composite
            .subsystems
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let (start, ty) = (parameter_offset(composite, i), &s.ty);
                let body = call(&s.ident, ty, i);
                quote! {
                    let start = #start;
                    if k >= start && k < start + <#ty as #p::Named>::NAMES.parameter_count() {
                        #body
                    }
                }
            })
            .collect()
    };
    let fields = &composite.params;
    let own_count = fields.len();
    let own_k = (0..fields.len()).map(Literal::usize_unsuffixed);
    let (own_k1, own_k2) = (own_k.clone(), own_k);
    let get = dispatch(
        &|field, ty, _| quote! { return <#ty as #p::Parameters>::parameter_value(&self.#field, k - start); },
    );
    let set = dispatch(
        &|field, ty, _| quote! { return <#ty as #p::Parameters>::set_parameter_value(&mut self.#field, k - start, value); },
    );
    let residual = dispatch(&|field, ty, i| {
        let slot = format_ident!("__SLOT{}", i);
        quote! {
            let mut o = #p::ResidualBlocks::<#ty>::zeros();
            <#ty as #p::Parameters>::residual_blocks_dtheta(
                &self.#field,
                k - start,
                t,
                &#p::gather_q::<#ty, Self>(q, &#slot),
                &#p::gather_q::<#ty, Self>(v, &#slot),
                &#p::gather_c::<#ty, Self>(lambda, &#slot),
                &mut o,
            );
            #p::scatter_q::<#ty, Self>(&o.momentum_rate, &#slot, &mut out.momentum_rate);
            #p::scatter_q::<#ty, Self>(&o.dl_dv, &#slot, &mut out.dl_dv);
            #p::scatter_c::<#ty, Self>(&o.constraint_velocity, &#slot, &mut out.constraint_velocity);
            return;
        }
    });
    let together = composite.subsystems.iter().enumerate().map(|(i, s)| {
        let (start, ty, field) = (parameter_offset(composite, i), &s.ty, &s.ident);
        let slot = format_ident!("__SLOT{}", i);
        quote! {{
            const COUNT: ::core::primitive::usize = <#ty as #p::Named>::NAMES.parameter_count();
            let start = #start;
            let mut each: [#p::ResidualBlocks<#ty>; COUNT] =
                ::core::array::from_fn(|_| #p::ResidualBlocks::<#ty>::zeros());
            <#ty as #p::Parameters>::residual_blocks_dtheta_all(
                &self.#field,
                t,
                &#p::gather_q::<#ty, Self>(q, &#slot),
                &#p::gather_q::<#ty, Self>(v, &#slot),
                &#p::gather_c::<#ty, Self>(lambda, &#slot),
                &mut each,
            );
            // Over the array, not `0..COUNT`: a subsystem without parameters would make that
            // range empty, which lints flag in the user's crate.
            for (j, o) in ::core::iter::Iterator::enumerate(each.iter()) {
                let out = &mut out[start + j];
                out.momentum_rate.fill(0.0);
                out.dl_dv.fill(0.0);
                out.constraint_velocity.fill(0.0);
                #p::scatter_q::<#ty, Self>(&o.momentum_rate, &#slot, &mut out.momentum_rate);
                #p::scatter_q::<#ty, Self>(&o.dl_dv, &#slot, &mut out.dl_dv);
                #p::scatter_c::<#ty, Self>(&o.constraint_velocity, &#slot, &mut out.constraint_velocity);
            }
        }}
    });
    // The composite's own parameters one at a time (none: no loop, which lints would flag).
    let own_each = (own_count > 0).then(|| {
        quote! {
            for j in 0..#own_count {
                <Self as #p::Parameters>::residual_blocks_dtheta(self, #own_start + j, t, q, v, lambda, &mut out[#own_start + j]);
            }
        }
    });
    // The transposed blocks: each subsystem's on its part of the arguments and weights, into
    // its range of `out`; the composite's own parameters one at a time.
    let transposed = |holonomic: bool| -> Vec<TokenStream> {
        composite
            .subsystems
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let (start, ty, field) = (parameter_offset(composite, i), &s.ty, &s.ident);
                let slot = format_ident!("__SLOT{}", i);
                let call = if holonomic {
                    quote! {
                        <#ty as #p::Parameters>::holonomic_vjp_dtheta(
                            &self.#field,
                            t,
                            &#p::gather_q::<#ty, Self>(q, &#slot),
                            &#p::gather_h::<#ty, Self>(w, &#slot),
                            &mut out[start..start + COUNT],
                        );
                    }
                } else {
                    quote! {
                        <#ty as #p::Parameters>::residual_blocks_vjp_dtheta(
                            &self.#field,
                            t,
                            &#p::gather_q::<#ty, Self>(q, &#slot),
                            &#p::gather_q::<#ty, Self>(v, &#slot),
                            &#p::gather_c::<#ty, Self>(lambda, &#slot),
                            &#p::gather_blocks::<#ty, Self>(w, &#slot),
                            &mut out[start..start + COUNT],
                        );
                    }
                };
                quote! {{
                    const COUNT: ::core::primitive::usize = <#ty as #p::Named>::NAMES.parameter_count();
                    let start = #start;
                    #call
                }}
            })
            .collect()
    };
    let residual_vjp = transposed(false);
    let holonomic_vjp = transposed(true);
    let own_vjp = (own_count > 0).then(|| {
        quote! {
            let mut each = #p::ResidualBlocks::<Self>::zeros();
            for j in 0..#own_count {
                <Self as #p::Parameters>::residual_blocks_dtheta(self, #own_start + j, t, q, v, lambda, &mut each);
                out[#own_start + j] = w.dot(&each);
            }
        }
    });
    let own_holonomic_vjp = (own_count > 0).then(|| {
        quote! {
            let mut each = #p::VecH::<Self>::zeros();
            for j in 0..#own_count {
                <Self as #p::Parameters>::holonomic_dtheta(self, #own_start + j, t, q, &mut each);
                out[#own_start + j] = w.dot(&each);
            }
        }
    });
    let holonomic = dispatch(&|field, ty, i| {
        let slot = format_ident!("__SLOT{}", i);
        quote! {
            let mut o = #p::VecH::<#ty>::zeros();
            <#ty as #p::Parameters>::holonomic_dtheta(&self.#field, k - start, t, &#p::gather_q::<#ty, Self>(q, &#slot), &mut o);
            #p::scatter_h::<#ty, Self>(&o, &#slot, out);
            return;
        }
    });
    let own_arms = own.blocks.dtheta.iter().enumerate().map(|(j, (omega, forces))| {
        let mut assigns = Own::row_values(&quote! { out.constraint_velocity }, omega);
        assigns.extend(own.forces_of(&quote! { out.momentum_rate }, forces));
        let body = own.body(&assigns, true);
        let j = Literal::usize_unsuffixed(j);
        quote! { #j => { #body } }
    });
    let own_phi_arms = own.blocks.phi_dtheta.iter().enumerate().map(|(j, phi)| {
        let body = own.body(&Own::holonomic_values(&quote! { out }, phi), false);
        let j = Literal::usize_unsuffixed(j);
        quote! { #j => { #body } }
    });
    quote! {
        fn parameter_value(&self, k: ::core::primitive::usize) -> ::core::primitive::f64 {
            #get
            match k.wrapping_sub(#own_start) {
                #(#own_k1 => self.#fields,)*
                _ => #panic,
            }
        }
        fn set_parameter_value(&mut self, k: ::core::primitive::usize, value: ::core::primitive::f64) {
            #set
            match k.wrapping_sub(#own_start) {
                #(#own_k2 => self.#fields = value,)*
                _ => #panic,
            }
        }
        #[allow(unused_variables)]
        fn residual_blocks_dtheta(
            &self,
            k: ::core::primitive::usize,
            t: ::core::primitive::f64,
            q: &#p::VecQ<Self>,
            v: &#p::VecQ<Self>,
            lambda: &#p::VecC<Self>,
            out: &mut #p::ResidualBlocks<Self>,
        ) {
            out.momentum_rate.fill(0.0);
            out.dl_dv.fill(0.0);
            out.constraint_velocity.fill(0.0);
            #residual
            match k.wrapping_sub(#own_start) {
                #(#own_arms)*
                _ => #panic,
            }
        }
        fn residual_blocks_dtheta_all(
            &self,
            t: ::core::primitive::f64,
            q: &#p::VecQ<Self>,
            v: &#p::VecQ<Self>,
            lambda: &#p::VecC<Self>,
            out: &mut [#p::ResidualBlocks<Self>],
        ) {
            #(#together)*
            #own_each
        }
        #[allow(unused_variables)]
        fn residual_blocks_vjp_dtheta(
            &self,
            t: ::core::primitive::f64,
            q: &#p::VecQ<Self>,
            v: &#p::VecQ<Self>,
            lambda: &#p::VecC<Self>,
            w: &#p::ResidualBlocks<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(out.len(), #total, "residual_blocks_vjp_dtheta: the slice must hold one value per parameter");
            #(#residual_vjp)*
            #own_vjp
        }
        #[allow(unused_variables)]
        fn holonomic_vjp_dtheta(
            &self,
            t: ::core::primitive::f64,
            q: &#p::VecQ<Self>,
            w: &#p::VecH<Self>,
            out: &mut [::core::primitive::f64],
        ) {
            ::core::assert_eq!(out.len(), #total, "holonomic_vjp_dtheta: the slice must hold one value per parameter");
            #(#holonomic_vjp)*
            #own_holonomic_vjp
        }
        #[allow(unused_variables)]
        fn holonomic_dtheta(
            &self,
            k: ::core::primitive::usize,
            t: ::core::primitive::f64,
            q: &#p::VecQ<Self>,
            out: &mut #p::VecH<Self>,
        ) {
            out.fill(0.0);
            #holonomic
            match k.wrapping_sub(#own_start) {
                #(#own_phi_arms)*
                _ => #panic,
            }
        }
    }
}
