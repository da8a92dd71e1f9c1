//! The `const` items of a composite, evaluated when the program compiles: the resolution of
//! each subsystem member it names (`left.x2` to an index and a role), the linearity of its
//! one-forms once those roles are known, and its condensed structure with the check that it is
//! structurally nonsingular.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote, quote_spanned};
use syn::spanned::Spanned;

use super::ast::Composite;
use super::blocks::CompositeBlocks;
use super::emit::r_ident;
use super::model::CompositeModel;
use crate::codegen::signatures::rt;
use crate::ctxt::Ctxt;
use crate::sym::Id;
use crate::symbols::Sym;

fn lit(i: usize) -> Literal {
    Literal::usize_unsuffixed(i)
}

/// The last token of `tokens`' span, where errors about a member are reported.
fn last_span(tokens: &TokenStream) -> proc_macro2::Span {
    tokens.clone().into_iter().last().map_or_else(proc_macro2::Span::call_site, |t| t.span())
}

impl CompositeModel {
    /// Const items that build the composite's condensed pattern from its subsystems' and its
    /// own rows, and stop the build if it is structurally singular, naming the unknown.
    pub fn structure(&self, composite: &Composite<'_>, b: &CompositeBlocks) -> TokenStream {
        let p = rt();
        let name = composite.ident.to_string();
        let subsystems = composite.subsystems.iter().enumerate().map(|(i, sub)| {
            let ty = &sub.ty;
            let (qi, hi, vi) =
                (format_ident!("__Q{}", i), format_ident!("__H{}", i), format_ident!("__V{}", i));
            let sizes = quote_spanned! {ty.span()=>
                (<#ty as #p::Fixed>::NQ, <#ty as #p::Fixed>::NC, <#ty as #p::Fixed>::NH)
            };
            quote! {{
                let s = <#ty as #p::LagrangeDirac>::STRUCTURE;
                let (tn, tc, th) = #sizes;
                let tk = tn + tc;
                let mut a = 0;
                while a < tk {
                    let ra = #p::composite_unknown(a, tn, th, (#qi, #hi, #vi), __NQ);
                    u[ra] = s.unknowns[a];
                    let mut b = 0;
                    while b < tk {
                        if s.pattern[a * tk + b] {
                            p[ra * __K + #p::composite_unknown(b, tn, th, (#qi, #hi, #vi), __NQ)] = true;
                        }
                        b += 1;
                    }
                    a += 1;
                }
            }}
        });
        let subsystems: Vec<TokenStream> = subsystems.collect();
        let mut rows = TokenStream::new();
        for j in 0..self.rows.len() {
            let jl = lit(j);
            let message = message(&format!(
                "structurally singular interconnection: the multiplier of `{}` of `{name}` is determined by no \
                 equation: it constrains no velocity (a relation between coordinates alone is a `holonomic` \
                 row)",
                self.rows[j].name
            ));
            rows.extend(quote! { u[__NQ + __ROWS[#jl]] = #message; });
            for k in 0..self.members() {
                if self.graph.is_zero(b.d[j][k]) {
                    continue;
                }
                let r = r_ident(k);
                rows.extend(quote! {
                    p[(__NQ + __ROWS[#jl]) * __K + #r.index] = true;
                    if #r.velocity {
                        p[#r.index * __K + __NQ + __ROWS[#jl]] = true;
                    }
                });
                for l in 0..self.members() {
                    if !self.graph.is_zero(b.h[j][k][l]) {
                        let rl = r_ident(l);
                        rows.extend(quote! {
                            if #r.velocity && !#rl.velocity {
                                p[#r.index * __K + #rl.index] = true;
                            }
                        });
                    }
                }
            }
        }
        quote! {
            const __K: ::core::primitive::usize = __NQ + __NC;
            const __STRUCTURE: ([::core::primitive::bool; __K * __K], [&::core::primitive::str; __K]) = {
                let mut p = [false; __K * __K];
                let mut u = [""; __K];
                #(#subsystems)*
                #rows
                (p, u)
            };
            const __PATTERN: [::core::primitive::bool; __K * __K] = __STRUCTURE.0;
            const __UNKNOWNS: [&::core::primitive::str; __K] = __STRUCTURE.1;
            const _: () = if __RESOLVED
                && let ::core::option::Option::Some(c) = #p::undetermined_unknown::<__K>(&__PATTERN, __K, __NQ)
            {
                ::core::panic!("{}", __UNKNOWNS[c])
            };
        }
    }

    /// Const items that resolve each subsystem member and check what it is.
    pub fn resolutions(&self, composite: &Composite<'_>) -> TokenStream {
        let p = rt();
        let mut out = TokenStream::new();
        let mut oks = Vec::new();
        let positional = self.positional_members();
        for (k, (r, _)) in self.symbols.members().enumerate() {
            let head = crate::lower::path_field(&r.path[0]);
            let field = composite.subsystems.iter().position(|s| s.ident == head).expect("checked field");
            let ty = &composite.subsystems[field].ty;
            let q_offset = format_ident!("__Q{}", field);
            let rest = &r.path[1..];
            let dotted = r.dotted();
            let (sub, last) = (&r.path[..r.path.len() - 1].join("."), rest.last().expect("a member path"));
            // The field that does not resolve is the first of `rest` a subsystem lacks; the
            // message names the path as written and suggests the nearest name there.
            let unknown_field =
                Literal::string(&format!("`{dotted}`: `{sub}` has no subsystem `{}`", rest[0]));
            let unknown = Literal::string(&if r.port {
                format!("`{last}` is not a coordinate of `{sub}`")
            } else {
                format!("`{last}` is not a coordinate or velocity of `{sub}`")
            });
            let checks = if r.rate {
                // Reported once, at the coordinate the rate belongs to.
                quote! { let _ = r; }
            } else if positional.contains(&k) {
                let velocity = message(&format!(
                    "`{dotted}` is a velocity; a holonomic interconnection constraint `φ(q, t) = 0` names \
                     coordinates (write a constraint on velocities with `constraint = …`)"
                ));
                let span = last_span(&r.tokens);
                quote_spanned! {span=>
                    if r.velocity { ::core::panic!(#velocity) }
                }
            } else if r.port {
                let velocity = message(&format!(
                    "`{dotted}` is a velocity; `connect` joins ports, named by their coordinates"
                ));
                let not_port = message(&format!(
                    "`{last}` is not a port of `{sub}`; declare it with `port({last})` on its model"
                ));
                let span = last_span(&r.tokens);
                quote_spanned! {span=>
                    if r.velocity { ::core::panic!(#velocity) }
                    if !r.port { ::core::panic!(#not_port) }
                }
            } else {
                quote! { let _ = r; }
            };
            let velocity = if r.port || r.rate {
                quote! { true }
            } else {
                quote! { r.velocity }
            };
            let span = last_span(&r.tokens);
            let name = proc_macro2::Ident::new(&format!("__R{k}"), span);
            let resolve = quote! { <#ty as #p::Named>::NAMES.resolve(&[#(#rest),*]) };
            let suggest = quote! { <#ty as #p::Named>::NAMES.suggest(&[#(#rest),*]) };
            let at = last_span(&r.tokens);
            let explained = |text: &Literal| {
                quote_spanned! {at=> {
                    const MESSAGE: #p::Message<512> = match #suggest {
                        ::core::option::Option::Some(name) => #p::Message::new(&[#text, "; did you mean `", name, "`?"]),
                        ::core::option::Option::None => #p::Message::new(&[#text]),
                    };
                    ::core::panic!("{}", MESSAGE.as_str())
                }}
            };
            let (unknown_field, unknown) = (explained(&unknown_field), explained(&unknown));
            // The member itself never fails to evaluate (a placeholder stands in for a name that
            // does not resolve), so the one error is the check's, with no note from the
            // constants that use the member.
            out.extend(quote_spanned! {span=>
                const #name: #p::Resolved = match #resolve {
                    ::core::result::Result::Ok(r) => {
                        #p::Resolved { velocity: #velocity, index: r.index + #q_offset, port: r.port }
                    }
                    ::core::result::Result::Err(_) => #p::Resolved { velocity: false, index: 0, port: false },
                };
                const _: () = match #resolve {
                    ::core::result::Result::Ok(r) => { #checks }
                    ::core::result::Result::Err(#p::ResolveError::UnknownField) => #unknown_field,
                    ::core::result::Result::Err(#p::ResolveError::UnknownName) => #unknown,
                };
            });
            let ok = if r.port {
                quote! { match #resolve { ::core::result::Result::Ok(r) => !r.velocity && r.port, _ => false } }
            } else if r.rate || positional.contains(&k) {
                quote! { match #resolve { ::core::result::Result::Ok(r) => !r.velocity, _ => false } }
            } else {
                quote! { #resolve.is_ok() }
            };
            oks.push(ok);
        }
        let count = lit(oks.len());
        out.extend(quote! {
            /// Whether every member resolved to what its use needs: the checks that depend on the
            /// members' roles run only then, so that a wrong name is reported once.
            const __RESOLVED: ::core::primitive::bool = #p::all(&[#(#oks),*] as &[::core::primitive::bool; #count]);
        });
        out
    }

    /// Const checks, decided once the members' roles are known, that each term of a one-form
    /// is affine in the velocities and that each one-form has a velocity in it: a table over
    /// every assignment of roles to a term's members.
    ///
    /// Also `__PRESCRIBED_OWN`: whether some row has a part without velocities, `b ≠ 0`; and
    /// `__VARYING_OWN`: whether some row's velocity coefficients depend on coordinates or time.
    pub fn linearity_checks(&mut self, cx: &Ctxt) -> TokenStream {
        let mut out = TokenStream::new();
        let mut prescribed = Vec::new();
        let mut varying = Vec::new();
        for j in 0..self.rows.len() {
            let terms = self.rows[j].terms.clone();
            let name = self.rows[j].name.clone();
            // Per term, the expression that says whether it has a velocity in it.
            let mut has_velocity = Vec::new();
            let mut all_tokens = TokenStream::new();
            for (term, tokens) in terms {
                all_tokens.extend(tokens.clone());
                let members: Vec<usize> = (0..self.members())
                    .filter(|&k| {
                        let sym = self.graph.as_sym(self.symbols.member_id(k)).expect("a symbol");
                        self.graph.depends_on(term, sym)
                    })
                    .collect();
                if members.is_empty() {
                    // A term of parameters and time alone: all of it is `b`.
                    prescribed.push(quote! { true });
                    continue;
                }
                if members.len() > 8 {
                    cx.error_spanned_by(
                        &tokens,
                        "a term of an interconnection constraint may name at most 8 members",
                    );
                    continue;
                }
                let codes: Vec<u8> =
                    (0..1usize << members.len()).map(|mask| self.term_code(term, &members, mask)).collect();
                let count = lit(codes.len());
                let bits: Vec<TokenStream> = members
                    .iter()
                    .enumerate()
                    .map(|(b, &k)| {
                        let r = r_ident(k);
                        quote! { ((#r.velocity as ::core::primitive::usize) << #b) }
                    })
                    .collect();
                let code = quote! {{
                    const CODES: [::core::primitive::u8; #count] = [#(#codes),*];
                    CODES[0 #(| #bits)*]
                }};
                let moving: Vec<bool> = (0..1usize << members.len())
                    .map(|mask| self.varying_coefficient(term, &members, mask))
                    .collect();
                if moving.iter().any(|&m| m) {
                    let count = lit(moving.len());
                    varying.push(quote! {{
                        const MOVING: [::core::primitive::bool; #count] = [#(#moving),*];
                        MOVING[0 #(| #bits)*]
                    }});
                }
                has_velocity.push(quote! { (#code != 1) });
                if codes.iter().any(|c| matches!(c, 1 | 2)) {
                    prescribed.push(quote! { ::core::matches!(#code, 1 | 2) });
                }
                if codes.contains(&3) {
                    let what = format!(
                        "interconnection constraint `{name}` must be affine in the velocities, \
                         `Ω(q, t) v + b(q, t) = 0`, but this term is not linear in the velocities"
                    );
                    let nonlinear = spanning_panic(&tokens, &what);
                    let span = tokens.span();
                    out.extend(quote_spanned! {span=>
                        const _: () = if __RESOLVED && #code == 3 { #nonlinear };
                    });
                }
            }
            let none = spanning_panic(
                &all_tokens,
                &format!(
                    "interconnection constraint `{name}` has no velocity in it; interconnection constraints \
                     are `Ω(q, t) v + b(q, t) = 0` over the subsystems' velocities (a constraint on positions, \
                     `φ(q, t) = 0`, is `holonomic({name}) = …`)"
                ),
            );
            let span = all_tokens.span();
            if !has_velocity.is_empty() {
                out.extend(quote_spanned! {span=>
                    const _: () = if __RESOLVED && !(false #(|| #has_velocity)*) { #none };
                });
            }
        }
        // A holonomic row's coefficients `∂φ/∂q` vary unless `φ` is linear in the coordinates
        // (the rule of `varying_coefficient`: they depend on nothing but parameters and
        // constants), and it prescribes a motion where `φ` depends on time.
        let time = self.symbols.declare(&mut self.graph, Sym::Time);
        let rates: Vec<Id> = (0..self.members())
            .filter(|&k| self.symbols.member_at(k).rate)
            .map(|k| self.symbols.member_id(k))
            .collect();
        for j in 0..self.rows.len() {
            let Some(phi) = self.rows[j].holonomic else { continue };
            let rate = self.graph.diff(phi, time);
            if !self.graph.is_zero(rate) {
                prescribed.push(quote! { true });
            }
            let omega = self.rows[j].omega;
            let coefficients: Vec<Id> = rates.iter().map(|&r| self.graph.diff(omega, r)).collect();
            let moving = coefficients.iter().any(|&c| {
                self.graph
                    .deps(c)
                    .iter()
                    .any(|s| !matches!(self.symbols.kind(s), Sym::Parameter(_) | Sym::Constant(_)))
            });
            if moving {
                varying.push(quote! { true });
            }
        }
        out.extend(quote! {
            const __PRESCRIBED_OWN: ::core::primitive::bool = false #(|| #prescribed)*;
            const __VARYING_OWN: ::core::primitive::bool = false #(|| #varying)*;
        });
        out
    }

    /// Whether, when the members in `mask` are velocities, the term's coefficient of one of
    /// them depends on anything but constants and parameters: another member (a coordinate)
    /// or time.
    fn varying_coefficient(&mut self, term: Id, members: &[usize], mask: usize) -> bool {
        members.iter().enumerate().filter(|(b, _)| mask >> b & 1 == 1).any(|(_, &k)| {
            let coefficient = self.graph.diff(term, self.symbols.member_id(k));
            self.graph
                .deps(coefficient)
                .iter()
                .any(|s| !matches!(self.symbols.kind(s), Sym::Parameter(_) | Sym::Constant(_)))
        })
    }

    /// 0: linear in the velocities when the members in `mask` are velocities; 1: no velocity
    /// (a part of `b`); 2: a part without velocity besides a linear one; 3: a product of
    /// velocities.
    fn term_code(&mut self, term: Id, members: &[usize], mask: usize) -> u8 {
        let velocities: Vec<usize> =
            members.iter().enumerate().filter(|(b, _)| mask >> b & 1 == 1).map(|(_, &k)| k).collect();
        if velocities.is_empty() {
            return 1;
        }
        let zero = self.graph.num(0.0);
        let ids: Vec<Id> = velocities.iter().map(|&k| self.symbols.member_id(k)).collect();
        let at_rest = ids.iter().map(|&id| (self.graph.as_sym(id).expect("a symbol"), zero)).collect();
        let rest = self.graph.substitute(term, &at_rest);
        if !self.graph.is_zero(rest) {
            return 2;
        }
        for &k in &ids {
            for &l in &ids {
                let d = self.graph.diff(term, k);
                let h = self.graph.diff(d, l);
                if !self.graph.is_zero(h) {
                    return 3;
                }
            }
        }
        0
    }
}

/// `::core::panic!(text)` whose tokens span `tokens` from their first to their last: a const
/// evaluation error then underlines the whole term, not only its first name.
fn spanning_panic(tokens: &TokenStream, text: &str) -> TokenStream {
    let first = tokens.clone().into_iter().next().map_or_else(proc_macro2::Span::call_site, |t| t.span());
    let path = quote_spanned! {first=> ::core::panic!};
    let message = message(text);
    let mut group = proc_macro2::Group::new(proc_macro2::Delimiter::Parenthesis, quote! { #message });
    group.set_span(last_span(tokens));
    quote! { #path #group }
}

/// A string literal for `panic!`, with braces escaped.
fn message(text: &str) -> Literal {
    Literal::string(&text.replace('{', "{{").replace('}', "}}"))
}
