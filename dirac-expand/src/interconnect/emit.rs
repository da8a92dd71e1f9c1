//! Emission of a composite's own part of each method: its interconnection rows, their
//! derivatives and forces, from the composite's block table. The symbols of those rows stand
//! for subsystem members whose indices and roles (coordinate or velocity) are constants
//! `__R<k>` resolved during compilation, so every `if __R<k>.velocity` below is decided by the
//! compiler.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use super::blocks::CompositeBlocks;
use super::model::CompositeModel;
use crate::sym::Id;
use crate::sym::emit::{Assign, emit, op_count};
use crate::symbols::Sym;

/// The constant naming subsystem member `k` once resolved.
pub fn r_ident(k: usize) -> proc_macro2::Ident {
    format_ident!("__R{}", k)
}

fn lit(i: usize) -> Literal {
    Literal::usize_unsuffixed(i)
}

/// A composite's rows and their blocks, ready to emit.
pub struct Own<'a> {
    pub model: &'a CompositeModel,
    pub blocks: &'a CompositeBlocks,
}

/// Statements that zero entries before the own assignments add to them.
pub struct Part {
    pub zero: TokenStream,
    pub assigns: Vec<Assign>,
}

impl Own<'_> {
    /// `let rK = …;` for every subsystem member the assignments read, then the statements;
    /// a member that is a velocity reads `v` when the method has velocities (`has_v`).
    pub fn body(&self, assigns: &[Assign], has_v: bool) -> TokenStream {
        let index = |k: usize| {
            let r = r_ident(k);
            quote! { #r.index }
        };
        let multiplier = |j: usize| {
            let j = lit(j);
            quote! { lambda[__ROWS[#j]] }
        };
        self.body_at(assigns, has_v, &index, &multiplier)
    }

    /// [`body`](Self::body) with member `k` at coordinate `index(k)` and row `j`'s multiplier
    /// at `multiplier(j)`.
    pub fn body_at(
        &self,
        assigns: &[Assign],
        has_v: bool,
        index: &dyn Fn(usize) -> TokenStream,
        multiplier: &dyn Fn(usize) -> TokenStream,
    ) -> TokenStream {
        let m = self.model;
        let mut used = vec![false; m.members()];
        for a in assigns {
            for s in m.graph.deps(a.value).iter() {
                if let Sym::Member(k) = m.kind(s) {
                    used[k] = true;
                }
            }
        }
        let mut preamble = TokenStream::new();
        for (k, _) in used.iter().enumerate().filter(|(_, u)| **u) {
            let (r, local, at) = (r_ident(k), format_ident!("r{}", k), index(k));
            let velocity = if has_v {
                quote! { v[#at] }
            } else {
                quote! { 0.0 }
            };
            preamble.extend(quote! { let #local = if #r.velocity { #velocity } else { q[#at] }; });
        }
        let leaf = |s: u32| match m.kind(s) {
            Sym::Parameter(i) => {
                let field = &m.params[i];
                quote! { self.#field }
            }
            Sym::Member(k) => {
                let local = format_ident!("r{}", k);
                quote! { #local }
            }
            Sym::Multiplier(j) => multiplier(j),
            Sym::Time => quote! { t },
            Sym::Constant(k) => {
                let tokens = m.symbols.constant_at(k).1;
                // Typed where the user wrote it: a constant that is not an `f64` is an error
                // at its name.
                let span = quote::ToTokens::to_token_stream(tokens)
                    .into_iter()
                    .next()
                    .map_or_else(proc_macro2::Span::call_site, |t| t.span());
                quote::quote_spanned! {span=> ::dirac::__private::constant(#tokens) }
            }
            kind => unreachable!("interconnection rows do not depend on {kind:?}"),
        };
        let statements = emit(&m.graph, assigns, &leaf);
        quote! { #preamble #statements }
    }

    /// Zeroes the interconnection rows of an `m × n` matrix, then adds their entries.
    /// `velocity` selects `A` (coefficients of velocities) or `∂(Av)/∂q` (of coordinates).
    pub fn rows_into(&self, target: &TokenStream, velocity: bool) -> Part {
        let k_rows = lit(self.model.rows.len());
        let zero = quote! {
            for __j in 0..#k_rows {
                for __i in 0..__NQ {
                    #target[(__ROWS[__j], __i)] = 0.0;
                }
            }
        };
        let mut assigns = Vec::new();
        for (j, row) in self.blocks.d.iter().enumerate() {
            for (k, &d) in row.iter().enumerate().filter(|(_, d)| !self.model.graph.is_zero(**d)) {
                let r = r_ident(k);
                let guard = if velocity {
                    quote! { #r.velocity }
                } else {
                    quote! { !#r.velocity }
                };
                let jl = lit(j);
                assigns.push(Assign::add_if(guard, quote! { #target[(__ROWS[#jl], #r.index)] }, d));
            }
        }
        Part { zero, assigns }
    }

    /// `target[j] = Ω_j` for the interconnection rows of a vector over constraints.
    pub fn omega_values(&self, target: &TokenStream) -> Vec<Assign> {
        let values: Vec<Id> = self.model.rows.iter().map(|row| row.omega).collect();
        Self::row_values(target, &values)
    }

    /// `target[j] = values[j]` for the interconnection rows of a vector over constraints.
    pub fn row_values(target: &TokenStream, values: &[Id]) -> Vec<Assign> {
        values
            .iter()
            .enumerate()
            .map(|(j, &value)| {
                let j = lit(j);
                Assign::set(quote! { #target[__ROWS[#j]] }, value)
            })
            .collect()
    }

    /// `target[j] = φ_j` for the holonomic rows (the first) of a vector over them.
    pub fn phi_values(&self, target: &TokenStream) -> Vec<Assign> {
        let phi: Vec<Id> = self.model.rows.iter().filter_map(|row| row.holonomic).collect();
        Self::holonomic_values(target, &phi)
    }

    /// `target[j] = values[j]` for the holonomic rows (the first) of a vector over them.
    pub fn holonomic_values(target: &TokenStream, values: &[Id]) -> Vec<Assign> {
        let rows = values.iter().enumerate();
        rows.map(|(j, &value)| {
            let j = lit(j);
            Assign::set(quote! { #target[#j] }, value)
        })
        .collect()
    }

    /// `target[j] = ∂Ω_j/∂t` for the interconnection rows of a vector over constraints.
    pub fn time_rates(&self, target: &TokenStream) -> Vec<Assign> {
        let rows = self.blocks.dt.iter().enumerate();
        rows.map(|(j, &dt)| {
            let j = lit(j);
            Assign::set(quote! { #target[__ROWS[#j]] }, dt)
        })
        .collect()
    }

    /// `target[i] += (Ωᵀμ)_i`: the interconnection forces, added to a vector over coordinates.
    pub fn forces_into(&self, target: &TokenStream) -> Vec<Assign> {
        self.forces_of(target, &self.blocks.mu_d)
    }

    /// `target[i] += Σ_j forces[j][k]` over the members `k` that are velocities: forces given
    /// per row and member, as `μ_j ∂Ω_j/∂s_k` or a derivative of it.
    pub fn forces_of(&self, target: &TokenStream, forces: &[Vec<Id>]) -> Vec<Assign> {
        let mut assigns = Vec::new();
        for row in forces {
            for (k, &value) in row.iter().enumerate().filter(|(_, x)| !self.model.graph.is_zero(**x)) {
                let r = r_ident(k);
                assigns.push(Assign::add_if(quote! { #r.velocity }, quote! { #target[#r.index] }, value));
            }
        }
        assigns
    }

    /// `target += ∂(Ωᵀμ)/∂q` on an `n × n` matrix whose subsystem diagonal blocks were just
    /// written: entries between two subsystems are zeroed first.
    pub fn datl_into(&self, target: &TokenStream) -> Part {
        let (mut zero, mut assigns) = (TokenStream::new(), Vec::new());
        let m = self.model;
        for row in &self.blocks.mu_h {
            for (k, column) in row.iter().enumerate() {
                for (l, &value) in column.iter().enumerate().filter(|(_, x)| !m.graph.is_zero(**x)) {
                    let (rk, rl) = (r_ident(k), r_ident(l));
                    let guard = quote! { #rk.velocity && !#rl.velocity };
                    let entry = quote! { #target[(#rk.index, #rl.index)] };
                    if m.symbols.member_at(k).path[0] != m.symbols.member_at(l).path[0] {
                        zero.extend(quote! { if #guard { #entry = 0.0; } });
                    }
                    assigns.push(Assign::add_if(guard, entry, value));
                }
            }
        }
        Part { zero, assigns }
    }

    /// Arithmetic operations of the interconnection part of the residual and Jacobian blocks.
    pub fn op_counts(&self) -> (usize, usize) {
        let out = quote! { out };
        let mut residual = self.omega_values(&out);
        residual.extend(self.forces_into(&out));
        let mut jacobian = self.rows_into(&out, true).assigns;
        jacobian.extend(self.rows_into(&out, false).assigns);
        jacobian.extend(self.datl_into(&out).assigns);
        let g = &self.model.graph;
        (op_count(g, &residual), op_count(g, &jacobian))
    }
}
