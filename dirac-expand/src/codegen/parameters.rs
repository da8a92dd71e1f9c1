//! The parameter methods of a primitive model: each `f64` field read and written by index,
//! and the derivatives of the residual blocks and holonomic constraints with respect to it,
//! one straight-line schedule per parameter (its subexpressions shared) behind a `match` on
//! the parameter's index; and the residual blocks' derivatives with respect to all of them in
//! one schedule, the subexpressions common to all parameters evaluated once; and the transposed
//! blocks, a weighted sum of those derivatives for every parameter, by reverse accumulation.

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use super::signatures::{
    Arg, HOLONOMIC_DTHETA, HOLONOMIC_VJP_DTHETA, RESIDUAL_BLOCKS_DTHETA, RESIDUAL_BLOCKS_DTHETA_ALL,
    RESIDUAL_BLOCKS_VJP_DTHETA, Signature,
};
use super::{Emitter, vector};
use crate::blocks::{Blocks, ParameterBlocks};
use crate::sym::emit::{Assign, emit};

impl Emitter<'_> {
    /// `parameter_value`, `set_parameter_value`, `residual_blocks_dtheta` and
    /// `holonomic_dtheta`.
    pub(super) fn parameter_methods(&self, b: &Blocks) -> TokenStream {
        let fields = &self.model.params;
        let count = fields.len();
        let panic = quote! { ::core::panic!("the model has no parameter {}: it has {}", k, #count) };
        let k = (0..count).map(Literal::usize_unsuffixed);
        let (k1, k2) = (k.clone(), k);
        let residual = self.by_parameter(&RESIDUAL_BLOCKS_DTHETA, b, &|d| {
            let mut assigns = vector(&quote! { out.momentum_rate }, &d.momentum_rate);
            assigns.extend(vector(&quote! { out.dl_dv }, &d.dl_dv));
            assigns.extend(vector(&quote! { out.constraint_velocity }, &d.a_v));
            assigns
        });
        let holonomic = self.by_parameter(&HOLONOMIC_DTHETA, b, &|d| vector(&quote! { out }, &d.phi));
        let all = self.all_parameters(b);
        // The transposed blocks, every parameter in one reverse sweep (the trait's loops over
        // the blocks above serve a model without parameters).
        let transposed = (!b.dtheta.is_empty()).then(|| {
            let residual = self.sized(&RESIDUAL_BLOCKS_VJP_DTHETA, &b.vjp_dtheta);
            let holonomic = self.sized(&HOLONOMIC_VJP_DTHETA, &b.holonomic_vjp_dtheta);
            quote! { #residual #holonomic }
        });
        quote! {
            fn parameter_value(&self, k: ::core::primitive::usize) -> ::core::primitive::f64 {
                match k {
                    #(#k1 => self.#fields,)*
                    _ => #panic,
                }
            }
            fn set_parameter_value(&mut self, k: ::core::primitive::usize, value: ::core::primitive::f64) {
                match k {
                    #(#k2 => self.#fields = value,)*
                    _ => #panic,
                }
            }
            #residual
            #holonomic
            #all
            #transposed
        }
    }

    /// `residual_blocks_dtheta_all`: every parameter's derivatives, into `out[k]`, in one
    /// schedule (nothing for a model without parameters: the trait's loop does nothing).
    fn all_parameters(&self, b: &Blocks) -> TokenStream {
        if b.dtheta.is_empty() {
            return TokenStream::new();
        }
        let assigns: Vec<Assign> = b
            .dtheta
            .iter()
            .enumerate()
            .flat_map(|(k, d)| {
                let k = Literal::usize_unsuffixed(k);
                let mut assigns = vector(&quote! { out[#k].momentum_rate }, &d.momentum_rate);
                assigns.extend(vector(&quote! { out[#k].dl_dv }, &d.dl_dv));
                assigns.extend(vector(&quote! { out[#k].constraint_velocity }, &d.a_v));
                assigns
            })
            .collect();
        let header = RESIDUAL_BLOCKS_DTHETA_ALL.header(|arg| self.uses(&assigns, arg), !assigns.is_empty());
        let body = emit(&self.model.graph, &assigns, &|s| self.leaf(s, false));
        quote! {
            #[inline]
            #header {
                #body
            }
        }
    }

    /// A method whose body computes `assigns(∂/∂θ_k)` in the arm of parameter `k`.
    fn by_parameter(
        &self,
        sig: &Signature,
        b: &Blocks,
        assigns: &dyn Fn(&ParameterBlocks) -> Vec<Assign>,
    ) -> TokenStream {
        let per_parameter: Vec<Vec<Assign>> = b.dtheta.iter().map(assigns).collect();
        let used = |arg| arg == Arg::K || per_parameter.iter().any(|a| self.uses(a, arg));
        let header = sig.header(used, per_parameter.iter().any(|a| !a.is_empty()));
        let arms = per_parameter.iter().enumerate().map(|(k, assigns)| {
            let k = Literal::usize_unsuffixed(k);
            let body = emit(&self.model.graph, assigns, &|s| self.leaf(s, false));
            quote! { #k => { #body } }
        });
        let count = b.dtheta.len();
        quote! {
            #[inline]
            #header {
                match k {
                    #(#arms)*
                    _ => ::core::panic!("the model has no parameter {}: it has {}", k, #count),
                }
            }
        }
    }
}
