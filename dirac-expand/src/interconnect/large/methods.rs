//! The methods of a composite with arrays: a loop over every field's subsystems that gathers
//! their arguments, calls their method and writes the result in place, then a loop over each
//! own row pattern's instances.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::{Large, lit};
use crate::codegen::signatures::{
    Arg, CONSTRAINT_MATRIX, CONSTRAINT_RATE, DATL_DQ, DAV_DQ, DAV_DT, JACOBIAN_BLOCKS, Out, REQUIRED,
    RESIDUAL_BLOCKS, Signature, rt,
};
use crate::interconnect::emit::r_ident;
use crate::interconnect::methods::{INTERCONNECTION_FORCES, own_parameter_checks};
use crate::sym::emit::Assign;

/// Which own entries a method writes.
#[derive(Clone, Copy)]
enum Entries {
    /// `A(q)`: the coefficients of velocities.
    A,
    /// `∂(A v)/∂q`: the coefficients of coordinates.
    Dav,
    /// `∂(Aᵀλ)/∂q`.
    Datl,
    /// The rows' values `Ω`.
    Values,
    /// `∂Ω/∂t`.
    TimeRates,
    /// The forces `Ωᵀμ`.
    Forces,
}

impl Large<'_> {
    /// The methods of the `LagrangeDirac` impl but `ports`.
    pub(super) fn methods(&self) -> TokenStream {
        let mut out: TokenStream =
            REQUIRED.iter().chain([&INTERCONNECTION_FORCES]).map(|sig| self.method(sig)).collect();
        out.extend(self.invalid_parameter());
        out.extend(self.outputs_method());
        out
    }

    fn method(&self, sig: &Signature) -> TokenStream {
        let header = sig.header(|_| true, true);
        let members: TokenStream =
            (0..self.composite.subsystems.len()).map(|f| self.member_part(sig, f)).collect();
        if sig.out == Out::Scalar {
            return quote! {
                #[allow(unused_variables)]
                #header {
                    let __pl = self.__placement();
                    let mut total = 0.0;
                    #members
                    total
                }
            };
        }
        let own = self.own_part(sig);
        quote! {
            #[allow(unused_variables)]
            #header {
                let __pl = self.__placement();
                #members
                #own
            }
        }
    }

    /// Field `f`'s part of a method: for each of its subsystems, the arguments gathered, the
    /// method called, the result written in place.
    fn member_part(&self, sig: &Signature, f: usize) -> TokenStream {
        let p = rt();
        let s = &self.composite.subsystems[f];
        let (field, ty, fl) = (&s.ident, &s.ty, lit(f));
        let count = self.count(f);
        let sub = if s.array {
            quote! { &self.#field[__e] }
        } else {
            quote! { &self.#field }
        };
        let name = format_ident!("{}", sig.name);
        let args: Vec<TokenStream> = sig
            .args
            .iter()
            .map(|arg| match arg {
                Arg::T => quote! { t },
                Arg::Q => quote! { &#p::gather_q::<#ty, Self>(q, &__s) },
                Arg::V => quote! { &#p::gather_q::<#ty, Self>(v, &__s) },
                Arg::Lambda => quote! { &#p::gather_c::<#ty, Self>(lambda, &__s) },
                Arg::Y
                | Arg::K
                | Arg::A
                | Arg::WeightBlocks
                | Arg::WeightHolonomic
                | Arg::WeightDlDq
                | Arg::WeightDlDv
                | Arg::WeightForce => {
                    unreachable!("arrays assemble no flat, parameter or second-order methods this way")
                }
            })
            .collect();
        let qq_at = quote! { __pl.qq_at(#fl, __e) };
        let cq_at = quote! { __pl.cq_at(#fl, __e) };
        let put = |from: TokenStream, to: TokenStream, at: &TokenStream| {
            quote! { #p::put(&mut #to.values, #at, #from.as_slice()); }
        };
        let (zeros, written) = match sig.out {
            Out::Scalar => {
                let body = quote! { total += __sub.#name(#(#args),*); };
                return self.over_members(f, &sub, &count, &body);
            }
            Out::VecQ => {
                (quote! { #p::VecQ::<#ty>::zeros() }, quote! { #p::scatter_q::<#ty, Self>(&o, &__s, out); })
            }
            Out::VecH => {
                (quote! { #p::VecH::<#ty>::zeros() }, quote! { #p::scatter_h::<#ty, Self>(&o, &__s, out); })
            }
            Out::VecC => {
                (quote! { #p::VecC::<#ty>::zeros() }, quote! { #p::scatter_c::<#ty, Self>(&o, &__s, out); })
            }
            Out::MatQQ => (quote! { #p::MatQQ::<#ty>::zeros() }, put(quote! { o }, quote! { out }, &qq_at)),
            Out::MatCQ => (quote! { #p::MatCQ::<#ty>::zeros() }, put(quote! { o }, quote! { out }, &cq_at)),
            Out::ResidualBlocks => (
                quote! { #p::ResidualBlocks::<#ty>::zeros() },
                quote! {
                    #p::scatter_q::<#ty, Self>(&o.momentum_rate, &__s, &mut out.momentum_rate);
                    #p::scatter_q::<#ty, Self>(&o.dl_dv, &__s, &mut out.dl_dv);
                    #p::scatter_c::<#ty, Self>(&o.constraint_velocity, &__s, &mut out.constraint_velocity);
                },
            ),
            Out::JacobianBlocks => {
                let mut w = TokenStream::new();
                for (block, at) in [
                    ("dpdot_dq", &qq_at),
                    ("dpdot_dv", &qq_at),
                    ("l_vq", &qq_at),
                    ("l_vv", &qq_at),
                    ("a", &cq_at),
                    ("dav_dq", &cq_at),
                ] {
                    let b = format_ident!("{}", block);
                    w.extend(put(quote! { o.#b }, quote! { out.#b }, at));
                }
                (quote! { #p::JacobianBlocks::<#ty>::zeros() }, w)
            }
            Out::VecY | Out::MatYY | Out::Values | Out::ResidualBlocksEach => {
                unreachable!("not a block written by subsystems")
            }
        };
        let body = quote! {
            let mut o = #zeros;
            __sub.#name(#(#args,)* &mut o);
            #written
        };
        self.over_members(f, &sub, &count, &body)
    }

    fn over_members(
        &self,
        f: usize,
        sub: &TokenStream,
        count: &TokenStream,
        body: &TokenStream,
    ) -> TokenStream {
        let fl = lit(f);
        quote! {
            for __e in 0..#count {
                let __s = __pl.slot(#fl, __e);
                let __sub = #sub;
                #body
            }
        }
    }

    /// The composite's own part of a method: a loop over each row pattern's instances.
    fn own_part(&self, sig: &Signature) -> TokenStream {
        let name = sig.name;
        let (entries, has_v): (Vec<(Entries, TokenStream)>, bool) = match name {
            _ if name == CONSTRAINT_MATRIX.name => (vec![(Entries::A, quote! { out })], false),
            _ if name == DAV_DQ.name => (vec![(Entries::Dav, quote! { out })], true),
            _ if name == DATL_DQ.name => (vec![(Entries::Datl, quote! { out })], false),
            // `b`: the rows with every velocity at zero.
            _ if name == CONSTRAINT_RATE.name => (vec![(Entries::Values, quote! { out })], false),
            _ if name == DAV_DT.name => (vec![(Entries::TimeRates, quote! { out })], true),
            _ if name == RESIDUAL_BLOCKS.name => (
                vec![
                    (Entries::Values, quote! { out.constraint_velocity }),
                    (Entries::Forces, quote! { out.momentum_rate }),
                ],
                true,
            ),
            _ if name == JACOBIAN_BLOCKS.name => (
                vec![
                    (Entries::A, quote! { out.a }),
                    (Entries::Dav, quote! { out.dav_dq }),
                    (Entries::Datl, quote! { out.dpdot_dq }),
                ],
                true,
            ),
            _ if name == INTERCONNECTION_FORCES.name => (vec![(Entries::Forces, quote! { out })], false),
            _ => return TokenStream::new(),
        };
        (0..self.rows.len())
            .map(|j| {
                let assigns: Vec<Assign> =
                    entries.iter().flat_map(|(what, target)| self.assigns(j, *what, target)).collect();
                let index = |k: usize| {
                    let g = format_ident!("__g{}", k);
                    quote! { #g }
                };
                let multiplier = |_: usize| quote! { lambda[__row] };
                let body = self.own.body_at(&assigns, has_v, &index, &multiplier);
                self.instances(j, &body)
            })
            .collect()
    }

    /// Row `j`'s assignments of one kind into `target`.
    fn assigns(&self, j: usize, what: Entries, target: &TokenStream) -> Vec<Assign> {
        let (b, row) = (self.own.blocks, &self.rows[j]);
        let jl = lit(j);
        let guarded = |guard: TokenStream, target: TokenStream, value| Assign {
            target,
            value,
            guard: Some(guard),
            accumulate: false,
        };
        match what {
            Entries::A | Entries::Dav => row
                .cq
                .iter()
                .enumerate()
                .map(|(e, &k)| {
                    let r = r_ident(k);
                    let guard = if matches!(what, Entries::A) {
                        quote! { #r.velocity }
                    } else {
                        quote! { !#r.velocity }
                    };
                    let at = quote! { #target.values[__pl.own_cq_at(#jl, __n) + #e] };
                    guarded(guard, at, b.d[j][k])
                })
                .collect(),
            Entries::Datl => row
                .qq
                .iter()
                .enumerate()
                .map(|(e, &(k, l))| {
                    let (rk, rl) = (r_ident(k), r_ident(l));
                    let at = quote! { #target.values[__pl.own_qq_at(#jl, __n) + #e] };
                    guarded(quote! { #rk.velocity && !#rl.velocity }, at, b.mu_h[j][k][l])
                })
                .collect(),
            Entries::Values => vec![Assign::set(quote! { #target[__row] }, self.own.model.rows[j].omega)],
            Entries::TimeRates => vec![Assign::set(quote! { #target[__row] }, b.dt[j])],
            Entries::Forces => row
                .cq
                .iter()
                .map(|&k| {
                    let (r, g) = (r_ident(k), format_ident!("__g{}", k));
                    Assign::add_if(quote! { #r.velocity }, quote! { #target[#g] }, b.mu_d[j][k])
                })
                .collect(),
        }
    }

    /// `fn invalid_parameter`: the composite's own `f64` fields, then each subsystem's,
    /// named by their paths (`cells[3].c`).
    fn invalid_parameter(&self) -> TokenStream {
        let own = own_parameter_checks(self.composite);
        let fields = self.composite.subsystems.iter().map(|s| {
            let field = &s.ident;
            let name = syn::ext::IdentExt::unraw(field).to_string();
            let (sub, prefix) = if s.array {
                (quote! { self.#field[__e] }, quote! { ::std::format!("{}[{}].", #name, __e) })
            } else {
                (quote! { self.#field }, quote! { ::std::format!("{}.", #name) })
            };
            let count = if s.array {
                quote! { self.#field.len() }
            } else {
                quote! { 1 }
            };
            quote! {
                for __e in 0..#count {
                    if let ::core::option::Option::Some((name, value, requirement)) = #sub.invalid_parameter() {
                        return ::core::option::Option::Some((#prefix + &name, value, requirement));
                    }
                }
            }
        });
        quote! {
            fn invalid_parameter(&self) -> ::core::option::Option<(::std::string::String, ::core::primitive::f64, &'static ::core::primitive::str)> {
                #own
                #(#fields)*
                ::core::option::Option::None
            }
        }
    }
}

impl Large<'_> {
    /// The parameters of a composite with arrays: its subsystems', in field order and each
    /// array element in turn, named by their paths (`cells[3].c`). `parameter_names` for the
    /// `Named` impl, and the `Parameters` impl's methods: each finds the subsystem that holds
    /// parameter `k` by the subsystems' parameter counts, and calls it there with its own
    /// arguments gathered, writing its derivatives in place and zero elsewhere (a subsystem's
    /// parameter enters no other subsystem's equations and no connection).
    pub(super) fn parameters(&self) -> (TokenStream, TokenStream) {
        let p = rt();
        let per_member = |body: &dyn Fn(&syn::Type, TokenStream) -> TokenStream| -> TokenStream {
            self.composite
                .subsystems
                .iter()
                .enumerate()
                .map(|(f, s)| {
                    let (field, ty, fl) = (&s.ident, &s.ty, lit(f));
                    let count = self.count(f);
                    let sub = if s.array {
                        quote! { self.#field[__e] }
                    } else {
                        quote! { self.#field }
                    };
                    let body = body(ty, sub);
                    quote! {
                        for __e in 0..#count {
                            let __n = <#ty as #p::Named>::NAMES.parameter_count();
                            if __k < __n {
                                let __s = __pl.slot(#fl, __e);
                                #body
                            }
                            __k -= __n;
                        }
                    }
                })
                .collect()
        };
        let names = self.composite.subsystems.iter().map(|s| {
            let (field, ty) = (&s.ident, &s.ty);
            let name = syn::ext::IdentExt::unraw(field).to_string();
            let (count, prefix) = if s.array {
                (quote! { self.#field.len() }, quote! { ::std::format!("{}[{}].", #name, __e) })
            } else {
                (quote! { 1 }, quote! { ::std::format!("{}.", #name) })
            };
            quote! {
                for __e in 0..#count {
                    let __prefix = #prefix;
                    for n in <#ty as #p::Named>::NAMES.parameter_names() {
                        out.push(__prefix.clone() + &n);
                    }
                }
            }
        });
        let counts = self.composite.subsystems.iter().enumerate().map(|(f, s)| {
            let (ty, count) = (&s.ty, self.count(f));
            quote! { __total += #count * <#ty as #p::Named>::NAMES.parameter_count(); }
        });
        let value = per_member(&|_, sub| quote! { return #sub.parameter_value(__k); });
        let set = per_member(&|_, sub| quote! { return #sub.set_parameter_value(__k, value); });
        let blocks = per_member(&|ty, sub| {
            quote! {
                let mut o = #p::ResidualBlocks::<#ty>::zeros();
                let (__q, __v) = (#p::gather_q::<#ty, Self>(q, &__s), #p::gather_q::<#ty, Self>(v, &__s));
                let __lambda = #p::gather_c::<#ty, Self>(lambda, &__s);
                #sub.residual_blocks_dtheta(__k, t, &__q, &__v, &__lambda, &mut o);
                #p::scatter_q::<#ty, Self>(&o.momentum_rate, &__s, &mut out.momentum_rate);
                #p::scatter_q::<#ty, Self>(&o.dl_dv, &__s, &mut out.dl_dv);
                #p::scatter_c::<#ty, Self>(&o.constraint_velocity, &__s, &mut out.constraint_velocity);
                return;
            }
        });
        let holonomic = per_member(&|ty, sub| {
            quote! {
                let mut o = #p::VecH::<#ty>::zeros();
                #sub.holonomic_dtheta(__k, t, &#p::gather_q::<#ty, Self>(q, &__s), &mut o);
                #p::scatter_h::<#ty, Self>(&o, &__s, out);
                return;
            }
        });
        // The transposed blocks: every member on its part of the arguments and weights, into
        // its range of `out`, in parameter order; one pass over the members.
        let each_member = |call: &dyn Fn(&syn::Type, TokenStream) -> TokenStream| -> Vec<TokenStream> {
            self.composite
                .subsystems
                .iter()
                .enumerate()
                .map(|(f, s)| {
                    let (field, ty, fl) = (&s.ident, &s.ty, lit(f));
                    let count = self.count(f);
                    let sub = if s.array {
                        quote! { self.#field[__e] }
                    } else {
                        quote! { self.#field }
                    };
                    let call = call(ty, sub);
                    quote! {
                        let __n = <#ty as #p::Named>::NAMES.parameter_count();
                        if __n > 0 {
                            for __e in 0..#count {
                                let __s = __pl.slot(#fl, __e);
                                #call
                                __at += __n;
                            }
                        }
                    }
                })
                .collect()
        };
        let residual_vjp = each_member(&|ty, sub| {
            quote! {
                #sub.residual_blocks_vjp_dtheta(
                    t,
                    &#p::gather_q::<#ty, Self>(q, &__s),
                    &#p::gather_q::<#ty, Self>(v, &__s),
                    &#p::gather_c::<#ty, Self>(lambda, &__s),
                    &#p::gather_blocks::<#ty, Self>(w, &__s),
                    &mut out[__at..__at + __n],
                );
            }
        });
        let holonomic_vjp = each_member(&|ty, sub| {
            quote! {
                #sub.holonomic_vjp_dtheta(
                    t,
                    &#p::gather_q::<#ty, Self>(q, &__s),
                    &#p::gather_h::<#ty, Self>(w, &__s),
                    &mut out[__at..__at + __n],
                );
            }
        });
        let missing = quote! {
            ::core::panic!("the model has no parameter {}: it has {}", k, #p::Parameters::parameter_count(self))
        };
        let named = quote! {
            #[allow(unused_variables)]
            fn parameter_names(&self) -> ::std::vec::Vec<::std::string::String> {
                let mut out = ::std::vec::Vec::new();
                #(#names)*
                out
            }
        };
        let parameters = quote! {
            fn parameter_count(&self) -> ::core::primitive::usize {
                let mut __total = 0;
                #(#counts)*
                __total
            }

            #[allow(unused_variables, unused_mut, unreachable_code)]
            fn parameter_value(&self, k: ::core::primitive::usize) -> ::core::primitive::f64 {
                let (__pl, mut __k) = (self.__placement(), k);
                #value
                #missing
            }

            #[allow(unused_variables, unused_mut, unreachable_code)]
            fn set_parameter_value(&mut self, k: ::core::primitive::usize, value: ::core::primitive::f64) {
                let (__pl, mut __k) = (self.__placement(), k);
                #set
                #missing
            }

            #[allow(unused_variables, unused_mut, unreachable_code)]
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
                let (__pl, mut __k) = (self.__placement(), k);
                #blocks
                #missing
            }

            #[allow(unused_variables, unused_mut)]
            fn residual_blocks_vjp_dtheta(
                &self,
                t: ::core::primitive::f64,
                q: &#p::VecQ<Self>,
                v: &#p::VecQ<Self>,
                lambda: &#p::VecC<Self>,
                w: &#p::ResidualBlocks<Self>,
                out: &mut [::core::primitive::f64],
            ) {
                ::core::assert_eq!(
                    out.len(),
                    #p::Parameters::parameter_count(self),
                    "residual_blocks_vjp_dtheta: the slice must hold one value per parameter",
                );
                let (__pl, mut __at) = (self.__placement(), 0usize);
                #(#residual_vjp)*
            }

            #[allow(unused_variables, unused_mut)]
            fn holonomic_vjp_dtheta(
                &self,
                t: ::core::primitive::f64,
                q: &#p::VecQ<Self>,
                w: &#p::VecH<Self>,
                out: &mut [::core::primitive::f64],
            ) {
                ::core::assert_eq!(
                    out.len(),
                    #p::Parameters::parameter_count(self),
                    "holonomic_vjp_dtheta: the slice must hold one value per parameter",
                );
                let (__pl, mut __at) = (self.__placement(), 0usize);
                #(#holonomic_vjp)*
            }

            #[allow(unused_variables, unused_mut, unreachable_code)]
            fn holonomic_dtheta(
                &self,
                k: ::core::primitive::usize,
                t: ::core::primitive::f64,
                q: &#p::VecQ<Self>,
                out: &mut #p::VecH<Self>,
            ) {
                out.fill(0.0);
                let (__pl, mut __k) = (self.__placement(), k);
                #holonomic
                #missing
            }
        };
        (named, parameters)
    }
}
