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
use super::{Emitter, zeroed_vector};
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
        let residual = self.by_parameter(&RESIDUAL_BLOCKS_DTHETA, b, &|d| self.blocks(&quote! { out }, d));
        let holonomic = self.by_parameter(&HOLONOMIC_DTHETA, b, &|d| {
            zeroed_vector(&self.model.graph, &quote! { out }, &d.phi)
        });
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
        let mut zero = TokenStream::new();
        let mut assigns: Vec<Assign> = Vec::new();
        for (k, d) in b.dtheta.iter().enumerate() {
            let k = Literal::usize_unsuffixed(k);
            let (z, a) = self.blocks(&quote! { out[#k] }, d);
            zero.extend(z);
            assigns.extend(a);
        }
        let header = RESIDUAL_BLOCKS_DTHETA_ALL
            .header(|arg| self.uses(&assigns, arg), !assigns.is_empty() || !zero.is_empty());
        let body = emit(&self.model.graph, &assigns, &|s| self.leaf(s, false));
        quote! {
            #[inline]
            #header {
                #zero
                #body
            }
        }
    }

    /// One parameter's derivatives of the residual blocks into `out.momentum_rate`, `out.dl_dv`
    /// and `out.constraint_velocity`: the statements that zero a mostly zero block first, and
    /// the assignments.
    fn blocks(&self, out: &TokenStream, d: &ParameterBlocks) -> (TokenStream, Vec<Assign>) {
        let g = &self.model.graph;
        let (mut zero, mut assigns) = zeroed_vector(g, &quote! { #out.momentum_rate }, &d.momentum_rate);
        for (target, values) in
            [(quote! { #out.dl_dv }, &d.dl_dv), (quote! { #out.constraint_velocity }, &d.a_v)]
        {
            let (z, a) = zeroed_vector(g, &target, values);
            zero.extend(z);
            assigns.extend(a);
        }
        (zero, assigns)
    }

    /// A method whose body computes `assigns(∂/∂θ_k)` in the arm of parameter `k`.
    fn by_parameter(
        &self,
        sig: &Signature,
        b: &Blocks,
        assigns: &dyn Fn(&ParameterBlocks) -> (TokenStream, Vec<Assign>),
    ) -> TokenStream {
        let per_parameter: Vec<(TokenStream, Vec<Assign>)> = b.dtheta.iter().map(assigns).collect();
        let used = |arg| arg == Arg::K || per_parameter.iter().any(|(_, a)| self.uses(a, arg));
        let header = sig.header(used, per_parameter.iter().any(|(z, a)| !a.is_empty() || !z.is_empty()));
        let arms = per_parameter.iter().enumerate().map(|(k, (zero, assigns))| {
            let k = Literal::usize_unsuffixed(k);
            let body = emit(&self.model.graph, assigns, &|s| self.leaf(s, false));
            quote! { #k => { #zero #body } }
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
