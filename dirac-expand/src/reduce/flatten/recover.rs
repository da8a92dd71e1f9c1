//! What the eliminations take out of the state, recovered at each sample (DESIGN §6.1): an
//! eliminated coordinate and its velocity from what they equal; the multiplier of an
//! eliminated row or connection from the momentum balance of the coordinate it was solved for,
//! in the model as it was then,
//!
//! ```text
//! a λ_k = d/dt ∂L/∂v_x − ∂L/∂x − F_x + ∂R/∂v_x − Σ_{r ≠ k} A_{r,x} λ_r,
//! ```
//!
//! (`a` the row's coefficient of `x`; the other rows' multipliers are those of rows still in
//! the model then: kept to the end, or recovered the same way later); and the interconnection
//! force at each port, `Σ_r Ω_{r,x} μ_r` over the connections and the composites' own rows of
//! the model unreduced. The time derivative of a momentum reads the accelerations, named
//! `__dt_` and the velocity, which follow the eliminations as the velocities do. A series
//! whose balance the derivatives here cannot take (a function they do not know, a momentum
//! that reads an input, a redundant row) is not recovered.

use std::cell::OnceCell;
use std::collections::{HashMap, HashSet};

use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Expr;

use super::{Connection, Flat, collect_idents, resolve};
use crate::ast::ConstraintKind;
use crate::reduce::affine::float;
use crate::reduce::derivative::{D, derivative};
use crate::reduce::rewrite::rename;

/// A row or connection eliminated, with its multiplier in the model as it was then (none
/// where it cannot be recovered).
#[derive(Clone)]
pub(super) struct Recovery {
    /// The row's name in the flat model (`gear__mesh`, `connect3`).
    name: String,
    multiplier: Option<TokenStream>,
}

/// A term of the interconnection force at a port: the coefficient of the port's velocity in
/// an interconnection row of the model unreduced, and the row's name.
#[derive(Clone)]
pub(super) struct PortTerm {
    port: String,
    coefficient: TokenStream,
    row: String,
}

/// A series the reduced model recovers: its name in the composite unreduced, the name later
/// series read it by, its expression.
#[derive(Clone)]
pub(super) struct Recovered {
    pub name: String,
    pub alias: Option<String>,
    pub value: TokenStream,
}

/// The names each Lagrangian term, dissipation term and row reads, kept as they are while the
/// eliminations go on (the terms themselves are rewritten once, at the end).
#[derive(Clone, Default)]
pub(super) struct NamesRead {
    lagrangian: Vec<Vec<String>>,
    dissipation: Vec<Vec<String>>,
    rows: HashMap<String, Vec<String>>,
}

/// The name under which the acceleration of velocity `v` is read.
pub(super) fn acceleration(v: &str) -> String {
    format!("__dt_{v}")
}

impl Flat {
    /// Follows an elimination in what the terms and rows read: a name that now equals an
    /// expression stands for the names that expression reads.
    pub(super) fn note_substitution(&mut self, new: &HashMap<String, TokenStream>) {
        let replacements: Vec<(&String, Vec<String>)> = new
            .iter()
            .map(|(name, value)| {
                let mut names = Vec::new();
                collect_idents(value.clone(), &mut names);
                (name, names)
            })
            .collect();
        let read = &mut self.names_read;
        let lists = read.lagrangian.iter_mut().chain(&mut read.dissipation).chain(read.rows.values_mut());
        for list in lists {
            for (name, names) in &replacements {
                if let Some(at) = list.iter().position(|n| n == *name) {
                    list.swap_remove(at);
                    list.extend(names.iter().filter(|n| !list.contains(n)).cloned().collect::<Vec<_>>());
                }
            }
        }
    }

    /// Notes what every term and row reads, before the eliminations.
    pub(super) fn note_names_read(&mut self) {
        let names = |t: &TokenStream| {
            let mut names = Vec::new();
            collect_idents(t.clone(), &mut names);
            names
        };
        self.names_read = NamesRead {
            lagrangian: self.lagrangian_terms.iter().map(names).collect(),
            dissipation: self.dissipation_terms.iter().map(names).collect(),
            rows: self.rows.iter().map(|r| (r.name.clone(), names(&r.expr))).collect(),
        };
    }

    /// The interconnection rows' terms at each port, in the names before any elimination:
    /// `+μ` at `a` and `−μ` at `b` for `connect(a, b)`, `∂ω/∂v_x μ` for a composite's row.
    pub(super) fn port_terms(&mut self) {
        let mut terms = Vec::new();
        for c in &self.connections {
            terms.push(PortTerm { port: c.a.clone(), coefficient: quote! { 1.0 }, row: c.name.clone() });
            terms.push(PortTerm { port: c.b.clone(), coefficient: quote! { -1.0 }, row: c.name.clone() });
        }
        for row in self.rows.iter().filter(|r| r.interconnection) {
            let Ok(expr) = syn::parse2::<Expr>(row.expr.clone()) else { continue };
            for c in &self.coordinates {
                let x = if row.kind == ConstraintKind::Velocity { &c.v } else { &c.q };
                match derivative(&expr, x) {
                    Some(D::Zero) => {}
                    Some(d) => terms.push(PortTerm {
                        port: c.q.clone(),
                        coefficient: d.into_tokens(),
                        row: row.name.clone(),
                    }),
                    // A term whose coefficient is not known here: the port's force is not recovered.
                    None => terms.push(PortTerm {
                        port: c.q.clone(),
                        coefficient: quote! { __unknown },
                        row: row.name.clone(),
                    }),
                }
            }
        }
        self.port_terms = terms;
    }

    /// Records the multiplier of `name` (a row, or a connection), about to be solved for
    /// coordinate `index` with coefficient `pivot`; `own` is the row's index among the rows,
    /// if it is one, and `pending` the connections not merged yet (rows too, then).
    pub(super) fn recover(
        &mut self,
        subst: &HashMap<String, TokenStream>,
        name: &str,
        (index, pivot): (usize, f64),
        own: Option<usize>,
        pending: &[Connection],
    ) {
        let multiplier = self.balance(subst, index, own, pending).map(|balance| {
            let scale = float(1.0 / pivot);
            quote! { (#scale) * (#balance) }
        });
        self.recoveries.push(Recovery { name: name.to_owned(), multiplier });
    }

    /// A row whose multiplier is not determined (a redundant row, a connection of two
    /// coordinates already merged).
    pub(super) fn not_recovered(&mut self, name: &str) {
        self.recoveries.push(Recovery { name: name.to_owned(), multiplier: None });
    }

    /// The force row `own` puts on coordinate `index` (its multiplier times its coefficient
    /// there), from that coordinate's momentum balance in the model now:
    /// `d/dt ∂L/∂v_x − ∂L/∂x − F_x + ∂R/∂v_x − Σ_{r ≠ own} A_{r,x} λ_r`.
    fn balance(
        &self,
        subst: &HashMap<String, TokenStream>,
        index: usize,
        own: Option<usize>,
        pending: &[Connection],
    ) -> Option<TokenStream> {
        let (q, v) = (&self.coordinates[index].q, &self.coordinates[index].v);
        // Whether a term or row reads `x` or `v_x` in the model now (or a definition, taken
        // to). Most of a large model's terms do not, and are neither rewritten nor parsed
        // (token work is slow inside a macro).
        let reads_x = |names: &[String]| {
            names.iter().any(|n| n == q || n == v || self.defines.iter().any(|(d, _)| d == n))
        };
        let defines: OnceCell<HashMap<String, TokenStream>> = OnceCell::new();
        // In the coordinates of the model now, the definitions written out.
        let now = |t: &TokenStream| -> Option<Expr> {
            let mut t = rename(t.clone(), subst);
            for _ in 0..=self.defines.len() {
                let mut names = Vec::new();
                collect_idents(t.clone(), &mut names);
                if !names.iter().any(|n| self.defines.iter().any(|(d, _)| d == n)) {
                    return syn::parse2(t).ok();
                }
                let defines = defines.get_or_init(|| {
                    self.defines.iter().map(|(d, e)| (d.clone(), rename(e.clone(), subst))).collect()
                });
                t = rename(t, defines);
            }
            None
        };
        let mut balance = D::Zero;
        let named = &self.names_read;
        let terms = self.lagrangian_terms.iter().zip(&named.lagrangian);
        for (l, _) in terms.filter(|(_, names)| reads_x(names)) {
            let l = now(l)?;
            balance = balance.plus(derivative(&l, q)?.negated());
            let momentum = match derivative(&l, v)? {
                D::Zero => continue,
                d => syn::parse2::<Expr>(d.into_tokens()).ok()?,
            };
            let mut read = Vec::new();
            collect_idents(quote! { #momentum }, &mut read);
            // `d/dt` of an input is not known.
            if read.iter().any(|n| self.inputs.contains(n)) {
                return None;
            }
            // `d/dt` through what the momentum reads.
            for c in self.coordinates.iter().filter(|c| read.contains(&c.q) || read.contains(&c.v)) {
                let (vc, ac) = (format_ident!("{}", c.v), format_ident!("{}", acceleration(&c.v)));
                balance = balance.plus(times(derivative(&momentum, &c.q)?, quote! { #vc }));
                balance = balance.plus(times(derivative(&momentum, &c.v)?, quote! { #ac }));
            }
            if read.iter().any(|n| n == "t") {
                balance = balance.plus(derivative(&momentum, "t")?);
            }
        }
        for (_, f) in self.forces.iter().filter(|(on, _)| on == q) {
            let f = now(f)?;
            balance = balance.plus(D::Of(quote! { #f }).negated());
        }
        for (r, _) in
            self.dissipation_terms.iter().zip(&named.dissipation).filter(|(_, names)| reads_x(names))
        {
            balance = balance.plus(derivative(&now(r)?, v)?);
        }
        let reaches = |r: &super::Row| named.rows.get(&r.name).is_none_or(|names| reads_x(names));
        for (_, row) in self.rows.iter().enumerate().filter(|(j, r)| Some(*j) != own && reaches(r)) {
            let expr = now(&row.expr)?;
            let x = if row.kind == ConstraintKind::Velocity { v } else { q };
            let lambda = format_ident!("{}", row.name);
            balance = balance.plus(times(derivative(&expr, x)?, quote! { #lambda }).negated());
        }
        for c in pending {
            let mu = format_ident!("{}", c.name);
            // `v_a − v_b`: `+1` at `a`, `−1` at `b`; nothing where both are `x` now.
            match (resolve(subst, c.a.clone()) == *q, resolve(subst, c.b.clone()) == *q) {
                (true, false) => balance = balance.plus(D::Of(quote! { #mu }).negated()),
                (false, true) => balance = balance.plus(D::Of(quote! { #mu })),
                _ => {}
            }
        }
        Some(balance.into_tokens())
    }

    /// The series recovered, once every elimination is done, each as its name unreduced, the
    /// name later series read it by (multipliers only) and its expression in the model
    /// reduced: the eliminated coordinates, velocities and momenta; the eliminated rows'
    /// multipliers, the later eliminations first (an earlier multiplier reads the later ones,
    /// by name: written out, a chain of them would grow as its square); the efforts at the
    /// ports.
    pub(super) fn recovered(&self, subst: &HashMap<String, TokenStream>) -> Vec<Recovered> {
        // What the reduced model reads: its coordinates, velocities, accelerations, rows,
        // parameters, definitions, time, and the multipliers recovered so far.
        let mut known: HashSet<String> = HashSet::new();
        for c in &self.coordinates {
            known.extend([c.q.clone(), c.v.clone(), acceleration(&c.v)]);
        }
        known.extend(self.rows.iter().map(|r| r.name.clone()));
        known.extend(self.params.iter().map(|(p, _)| p.clone()));
        known.extend(self.defines.iter().map(|(d, _)| d.clone()));
        known.insert("t".to_owned());
        // Reads only what the reduced model has (numbers, and `f64` constants by path aside).
        let readable = |t: &TokenStream, known: &HashSet<String>| {
            let mut names = Vec::new();
            collect_idents(t.clone(), &mut names);
            names.iter().all(|n| known.contains(n) || !(n.contains("__") || self.was_named(n)))
        };
        let mut out = Vec::new();
        let dotted = |n: &str| n.replace("__", ".");
        // The parts' Lagrangian, term by term, with the names each reads (none where a term
        // reads a definition, which the derivatives here do not open).
        let terms: Vec<(Vec<String>, Option<Expr>)> = self
            .original_lagrangian
            .iter()
            .map(|l| {
                let mut names = Vec::new();
                collect_idents(l.clone(), &mut names);
                let opaque = names.iter().any(|n| self.defines.iter().any(|(d, _)| d == n));
                let term = if opaque { None } else { syn::parse2::<Expr>(l.clone()).ok() };
                (names, term)
            })
            .collect();
        for e in &self.eliminated {
            let Some(coordinate) = self.original.iter().find(|c| c.q == e.name) else { continue };
            for name in [&coordinate.q, &coordinate.v] {
                if let Some(value) = subst.get(name).map(|t| rename(t.clone(), subst))
                    && readable(&value, &known)
                {
                    out.push(Recovered { name: dotted(name), alias: None, value });
                }
            }
            // Its momentum in the parts' Lagrangian, `∂L/∂v_x`, as the composite unreduced has it.
            let momentum = terms.iter().try_fold(D::Zero, |sum, (names, term)| {
                if !names.contains(&coordinate.v) {
                    return Some(sum);
                }
                Some(sum.plus(derivative(term.as_ref()?, &coordinate.v)?))
            });
            if let Some(value) = momentum.map(|p| rename(p.into_tokens(), subst))
                && readable(&value, &known)
            {
                out.push(Recovered { name: format!("p({})", dotted(&coordinate.q)), alias: None, value });
            }
        }
        // Each part's dissipated power, `Σ v ∂R/∂v` over its velocities (where the part is one
        // of the composite's: a part's own output, not the model's total).
        for (output, r, velocities) in self.dissipations.iter().filter(|(o, ..)| o.contains('.')) {
            let mut names = Vec::new();
            collect_idents(r.clone(), &mut names);
            let opaque = names.iter().any(|n| self.defines.iter().any(|(d, _)| d == n));
            let Some(r) = syn::parse2::<Expr>(r.clone()).ok().filter(|_| !opaque) else { continue };
            let power = velocities.iter().try_fold(D::Zero, |sum, v| {
                let v_ident = format_ident!("{}", v);
                Some(sum.plus(times(derivative(&r, v)?, quote! { #v_ident })))
            });
            if let Some(value) = power.map(|p| rename(p.into_tokens(), subst))
                && readable(&value, &known)
            {
                out.push(Recovered { name: format!("out({output})"), alias: None, value });
            }
        }
        // A recovered multiplier is read by its alias, `__mu_` and the row's name.
        let mut aliases: HashMap<String, TokenStream> = HashMap::new();
        for r in self.recoveries.iter().rev() {
            let Some(multiplier) = &r.multiplier else { continue };
            let value = rename(rename(multiplier.clone(), subst), &aliases);
            if readable(&value, &known) {
                let alias = format!("__mu_{}", r.name);
                let ident = format_ident!("{}", alias);
                known.insert(alias.clone());
                aliases.insert(r.name.clone(), quote! { #ident });
                out.push(Recovered {
                    name: format!("lambda({})", dotted(&r.name)),
                    alias: Some(alias),
                    value,
                });
            }
        }
        let mut ports: Vec<&str> = Vec::new();
        for term in &self.port_terms {
            if !ports.contains(&term.port.as_str()) {
                ports.push(&term.port);
            }
        }
        let jointed = |port: &str| {
            self.jointed
                .iter()
                .any(|(body, _)| port.strip_prefix(body.as_str()).is_some_and(|r| r.starts_with("__")))
        };
        for port in ports.into_iter().filter(|p| !jointed(p)) {
            let terms: Vec<TokenStream> = self
                .port_terms
                .iter()
                .filter(|t| t.port == port)
                .map(|term| {
                    let row = format_ident!("{}", term.row);
                    let coefficient = rename(term.coefficient.clone(), subst);
                    rename(quote! { (#coefficient) * #row }, &aliases)
                })
                .collect();
            let value = quote! { #(#terms)+* };
            if readable(&value, &known) {
                out.push(Recovered { name: format!("f({})", dotted(port)), alias: None, value });
            }
        }
        out
    }

    /// Whether `name` was a name of the flat model before the eliminations (a coordinate,
    /// velocity, row or connection), so that an expression reading it cannot be evaluated.
    fn was_named(&self, name: &str) -> bool {
        name == "__unknown"
            || name.starts_with("__dt_")
            || self.original.iter().any(|c| c.q == name || c.v == name)
            || self.recoveries.iter().any(|r| r.name == name)
    }
}

/// `factor · d`.
fn times(d: D, factor: TokenStream) -> D {
    match d {
        D::Zero => D::Zero,
        D::One => D::Of(factor),
        D::Of(t) => D::Of(quote! { (#factor) * (#t) }),
    }
}
