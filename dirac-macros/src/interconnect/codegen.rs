//! Emission of the runtime trait impls for a composite.
//!
//! Subsystem parts are gathered from the composite's vectors, evaluated by the subsystems' own
//! generated code, and scattered back; the interconnection rows are emitted from the graph.
//! Their symbols stand for subsystem members whose indices and roles (coordinate or velocity)
//! are constants `__R<k>` resolved during compilation, so every `if __R<k>.velocity` below is
//! decided by the compiler.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote, quote_spanned};
use syn::spanned::Spanned;

use super::ast::Composite;
use super::model::{CKind, CompositeModel};
use crate::ctxt::Ctxt;
use crate::sym::Id;
use crate::sym::emit::{Assign, emit, op_count};

/// The path to the runtime's items for generated code.
pub fn rt() -> TokenStream {
    quote! { ::dirac::__private }
}

pub fn r_ident(k: usize) -> proc_macro2::Ident {
    format_ident!("__R{}", k)
}

fn lit(i: usize) -> Literal {
    Literal::usize_unsuffixed(i)
}

impl CompositeModel {
    /// `∂Ω_j/∂s_k`.
    fn d(&mut self, j: usize, k: usize) -> Id {
        let (omega, s) = (self.rows[j].omega, self.refs[k].id);
        self.graph.diff(omega, s)
    }

    /// `∂²Ω_j/∂s_k∂s_l`.
    fn h(&mut self, j: usize, k: usize, l: usize) -> Id {
        let d = self.d(j, k);
        let s = self.refs[l].id;
        self.graph.diff(d, s)
    }

    fn mu_times(&mut self, j: usize, x: Id) -> Id {
        let mu = self.mu[j];
        self.graph.mul2(mu, x)
    }

    /// `let rK = …;` for every subsystem member the assignments read, and the statements.
    pub fn body(&self, assigns: &[Assign], has_v: bool) -> TokenStream {
        let mut used = vec![false; self.refs.len()];
        for a in assigns {
            for s in self.graph.deps(a.value).iter() {
                if let CKind::Ref(k) = self.kind(s) {
                    used[k] = true;
                }
            }
        }
        let mut preamble = TokenStream::new();
        for (k, _) in used.iter().enumerate().filter(|(_, u)| **u) {
            let (r, local) = (r_ident(k), format_ident!("r{}", k));
            let velocity = if has_v {
                quote! { v[#r.index] }
            } else {
                quote! { 0.0 }
            };
            preamble.extend(quote! { let #local = if #r.velocity { #velocity } else { q[#r.index] }; });
        }
        let leaf = |s: u32| match self.kind(s) {
            CKind::Parameter(i) => {
                let field = &self.params[i];
                quote! { self.#field }
            }
            CKind::Ref(k) => {
                let local = format_ident!("r{}", k);
                quote! { #local }
            }
            CKind::Mu(j) => {
                let j = lit(j);
                quote! { lambda[__OMEGA + #j] }
            }
            CKind::Time => unreachable!("interconnection constraints do not depend on time"),
        };
        let statements = emit(&self.graph, assigns, &leaf);
        quote! { #preamble #statements }
    }

    /// Zeroes the interconnection rows of an `m × n` matrix, then adds their entries.
    /// `velocity` selects `A` (coefficients of velocities) or `∂(Av)/∂q` (of coordinates).
    pub fn rows_into(&mut self, target: &TokenStream, velocity: bool) -> (TokenStream, Vec<Assign>) {
        let k_rows = lit(self.rows.len());
        let zero = quote! {
            for __j in 0..#k_rows {
                for __i in 0..__NQ {
                    #target[(__OMEGA + __j, __i)] = 0.0;
                }
            }
        };
        let mut assigns = Vec::new();
        for j in 0..self.rows.len() {
            for k in 0..self.refs.len() {
                let d = self.d(j, k);
                if self.graph.is_zero(d) {
                    continue;
                }
                let r = r_ident(k);
                let guard = if velocity {
                    quote! { #r.velocity }
                } else {
                    quote! { !#r.velocity }
                };
                let jl = lit(j);
                assigns.push(Assign::add_if(guard, quote! { #target[(__OMEGA + #jl, #r.index)] }, d));
            }
        }
        (zero, assigns)
    }

    /// `target[j] = Ω_j` for the interconnection rows of a vector over constraints.
    pub fn omega_values(&self, target: &TokenStream) -> Vec<Assign> {
        self.rows
            .iter()
            .enumerate()
            .map(|(j, row)| {
                let j = lit(j);
                Assign::set(quote! { #target[__OMEGA + #j] }, row.omega)
            })
            .collect()
    }

    /// `target[i] += (Ωᵀμ)_i`: the interconnection forces, added to a vector over coordinates.
    pub fn forces_into(&mut self, target: &TokenStream) -> Vec<Assign> {
        let mut assigns = Vec::new();
        for j in 0..self.rows.len() {
            for k in 0..self.refs.len() {
                let d = self.d(j, k);
                if self.graph.is_zero(d) {
                    continue;
                }
                let value = self.mu_times(j, d);
                let r = r_ident(k);
                assigns.push(Assign::add_if(quote! { #r.velocity }, quote! { #target[#r.index] }, value));
            }
        }
        assigns
    }

    /// `target += ∂(Ωᵀμ)/∂q` on an `n × n` matrix whose subsystem diagonal blocks were just
    /// written: entries between two subsystems are zeroed first.
    pub fn datl_into(&mut self, target: &TokenStream) -> (TokenStream, Vec<Assign>) {
        let mut zero = TokenStream::new();
        let mut assigns = Vec::new();
        for j in 0..self.rows.len() {
            for k in 0..self.refs.len() {
                for l in 0..self.refs.len() {
                    let h = self.h(j, k, l);
                    if self.graph.is_zero(h) {
                        continue;
                    }
                    let (rk, rl) = (r_ident(k), r_ident(l));
                    let guard = quote! { #rk.velocity && !#rl.velocity };
                    let entry = quote! { #target[(#rk.index, #rl.index)] };
                    if self.refs[k].path[0] != self.refs[l].path[0] {
                        zero.extend(quote! { if #guard { #entry = 0.0; } });
                    }
                    let value = self.mu_times(j, h);
                    assigns.push(Assign::add_if(guard, entry, value));
                }
            }
        }
        (zero, assigns)
    }

    /// Arithmetic operations of the interconnection part of the residual and Jacobian blocks.
    pub fn op_counts(&mut self) -> (usize, usize) {
        let mut residual = self.omega_values(&quote! { out });
        residual.extend(self.forces_into(&quote! { out }));
        let (_, mut jacobian) = self.rows_into(&quote! { out }, true);
        jacobian.extend(self.rows_into(&quote! { out }, false).1);
        jacobian.extend(self.datl_into(&quote! { out }).1);
        (op_count(&self.graph, &residual), op_count(&self.graph, &jacobian))
    }

    /// Const items that build the composite's condensed pattern from its subsystems' and its
    /// own rows, and stop the build if it is structurally singular, naming the unknown.
    pub fn structure(&mut self, composite: &Composite<'_>) -> TokenStream {
        let p = rt();
        let name = composite.ident.to_string();
        let subsystems = composite.subsystems.iter().enumerate().map(|(i, sub)| {
            let ty = &sub.ty;
            let (qi, hi, vi) = (format_ident!("__Q{}", i), format_ident!("__H{}", i), format_ident!("__V{}", i));
            quote! {{
                let s = <#ty as #p::LagrangeDirac>::STRUCTURE;
                let (tn, tc, th) = (<#ty as #p::Dimensions>::NQ, <#ty as #p::Dimensions>::NC, <#ty as #p::Dimensions>::NH);
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
                 equation: it constrains velocities that other constraints already fix",
                self.rows[j].name
            ));
            rows.extend(quote! { u[__NQ + __OMEGA + #jl] = #message; });
            for k in 0..self.refs.len() {
                let d = self.d(j, k);
                if self.graph.is_zero(d) {
                    continue;
                }
                let r = r_ident(k);
                rows.extend(quote! {
                    p[(__NQ + __OMEGA + #jl) * __K + #r.index] = true;
                    if #r.velocity {
                        p[#r.index * __K + __NQ + __OMEGA + #jl] = true;
                    }
                });
                for l in 0..self.refs.len() {
                    let h = self.h(j, k, l);
                    if !self.graph.is_zero(h) {
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
            const __K: usize = __NQ + __NC;
            const __STRUCTURE: ([bool; __K * __K], [&str; __K]) = {
                let mut p = [false; __K * __K];
                let mut u = [""; __K];
                #(#subsystems)*
                #rows
                (p, u)
            };
            const __PATTERN: [bool; __K * __K] = __STRUCTURE.0;
            const __UNKNOWNS: [&str; __K] = __STRUCTURE.1;
            const _: () = if let ::core::option::Option::Some(c) = #p::unpaired_unknown::<__K>(&__PATTERN, __K) {
                ::core::panic!("{}", __UNKNOWNS[c])
            };
        }
    }

    /// Const items that resolve each subsystem member and check what it is.
    pub fn resolutions(&self, composite: &Composite<'_>) -> TokenStream {
        let p = rt();
        let mut out = TokenStream::new();
        for (k, r) in self.refs.iter().enumerate() {
            let field =
                composite.subsystems.iter().position(|s| s.ident == r.path[0]).expect("checked field");
            let ty = &composite.subsystems[field].ty;
            let q_offset = format_ident!("__Q{}", field);
            let rest = &r.path[1..];
            let dotted = r.dotted();
            let (sub, last) = (&r.path[..r.path.len() - 1].join("."), rest.last().expect("a member path"));
            let unknown_field = message(&format!("`{dotted}`: `{sub}` has no subsystem `{}`", rest[0]));
            let unknown = if r.port {
                message(&format!("`{last}` is not a coordinate of `{sub}`"))
            } else {
                message(&format!("`{last}` is not a coordinate or velocity of `{sub}`"))
            };
            let checks = if r.port {
                let velocity = message(&format!(
                    "`{dotted}` is a velocity; `connect` joins ports, named by their coordinates"
                ));
                let not_port = message(&format!(
                    "`{last}` is not a port of `{sub}`; declare it with `port({last})` on its model"
                ));
                let span = r
                    .tokens
                    .clone()
                    .into_iter()
                    .last()
                    .map_or_else(proc_macro2::Span::call_site, |t| t.span());
                quote_spanned! {span=>
                    if r.velocity { ::core::panic!(#velocity) }
                    if !r.port { ::core::panic!(#not_port) }
                }
            } else {
                TokenStream::new()
            };
            let velocity = if r.port {
                quote! { true }
            } else {
                quote! { r.velocity }
            };
            let span =
                r.tokens.clone().into_iter().last().map_or_else(proc_macro2::Span::call_site, |t| t.span());
            let name = proc_macro2::Ident::new(&format!("__R{k}"), span);
            out.extend(quote_spanned! {span=>
                const #name: #p::Resolved = {
                    let r = match <#ty as #p::LagrangeDirac>::NAMES.resolve(&[#(#rest),*]) {
                        ::core::result::Result::Ok(r) => r,
                        ::core::result::Result::Err(#p::ResolveError::UnknownField) => ::core::panic!(#unknown_field),
                        ::core::result::Result::Err(#p::ResolveError::UnknownName) => ::core::panic!(#unknown),
                    };
                    #checks
                    #p::Resolved { velocity: #velocity, index: r.index + #q_offset, port: r.port }
                };
            });
        }
        out
    }

    /// Const checks that each term of a one-form is linear in the velocities, decided once the
    /// members' roles are known: a table over every assignment of roles to the term's members.
    pub fn linearity_checks(&mut self, cx: &Ctxt) -> TokenStream {
        let mut out = TokenStream::new();
        for j in 0..self.rows.len() {
            let terms = self.rows[j].terms.clone();
            let name = self.rows[j].name.clone();
            for (term, tokens) in terms {
                let members: Vec<usize> = (0..self.refs.len())
                    .filter(|&k| {
                        self.graph.depends_on(term, self.graph.as_sym(self.refs[k].id).expect("symbol"))
                    })
                    .collect();
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
                if codes.iter().all(|c| *c == 0) {
                    continue;
                }
                let bits = members.iter().enumerate().map(|(b, &k)| {
                    let r = r_ident(k);
                    quote! { ((#r.velocity as usize) << #b) }
                });
                let what = format!(
                    "interconnection constraint `{name}` must be linear in the velocities, but this term"
                );
                let none = message(&format!("{what} has no velocity in it"));
                let affine = message(&format!("{what} has a part without a velocity"));
                let nonlinear = message(&format!("{what} is not linear in the velocities"));
                let span = tokens.span();
                out.extend(quote_spanned! {span=>
                    const _: () = {
                        const CODES: [u8; #count] = [#(#codes),*];
                        match CODES[0 #(| #bits)*] {
                            1 => ::core::panic!(#none),
                            2 => ::core::panic!(#affine),
                            3 => ::core::panic!(#nonlinear),
                            _ => {}
                        }
                    };
                });
            }
        }
        out
    }

    /// 0: linear in the velocities when the members in `mask` are velocities; 1: no velocity;
    /// 2: a part without velocity; 3: a product of velocities.
    fn term_code(&mut self, term: Id, members: &[usize], mask: usize) -> u8 {
        let velocities: Vec<usize> =
            members.iter().enumerate().filter(|(b, _)| mask >> b & 1 == 1).map(|(_, &k)| k).collect();
        if velocities.is_empty() {
            return 1;
        }
        let zero = self.graph.num(0.0);
        let at_rest =
            velocities.iter().map(|&k| (self.graph.as_sym(self.refs[k].id).expect("symbol"), zero)).collect();
        let rest = self.graph.substitute(term, &at_rest);
        if !self.graph.is_zero(rest) {
            return 2;
        }
        for &k in &velocities {
            for &l in &velocities {
                let d = self.graph.diff(term, self.refs[k].id);
                let h = self.graph.diff(d, self.refs[l].id);
                if !self.graph.is_zero(h) {
                    return 3;
                }
            }
        }
        0
    }
}

/// A string literal for `panic!`, with braces escaped.
fn message(text: &str) -> Literal {
    Literal::string(&text.replace('{', "{{").replace('}', "}}"))
}
