//! The symbolic form of a composite: its interconnection rows `Ω(q, t) v + b(q, t) = 0` over
//! symbols that stand for subsystem members, which are resolved to indices only when the
//! program compiles.

use std::collections::HashSet;

use proc_macro2::TokenStream;
use quote::ToTokens;
use syn::Ident;
use syn::ext::IdentExt;

use super::ast::{Composite, MemberPath};
use crate::ctxt::Ctxt;
use crate::lower::{Context, Lowerer, Role, Scope, additive_terms, path_field};
use crate::suggest::did_you_mean;
use crate::sym::{Graph, Id};
use crate::symbol::TIME;
use crate::symbols::{Sym, Symbols};

/// One interconnection row `Ω_j(q, t) v + b_j(q, t) = 0`.
pub struct Row {
    pub name: String,
    /// The tokens that declared it, for error spans.
    pub key: Ident,
    pub omega: Id,
    /// The additive terms of a one-form with their tokens (empty for `connect` and holonomic
    /// rows), whose linearity in the velocities is checked once names are resolved.
    pub terms: Vec<(Id, TokenStream)>,
    /// A holonomic row's `φ(q, t)`, whose one-form `Ω = ∂φ/∂q v + ∂φ/∂t` is `omega`.
    pub holonomic: Option<Id>,
}

/// A composite's interconnection rows in one graph, over symbols for its parameters, its
/// subsystems' members ([`Sym::Member`]) and its own multipliers μ ([`Sym::Multiplier`]).
pub struct CompositeModel {
    pub graph: Graph,
    pub symbols: Symbols,
    pub params: Vec<Ident>,
    pub rows: Vec<Row>,
    pub mu: Vec<Id>,
    /// How many of the rows, the first ones, are holonomic.
    pub holonomic: usize,
}

impl CompositeModel {
    pub fn kind(&self, sym: u32) -> Sym {
        self.symbols.kind(sym)
    }

    /// The number of subsystem members the rows name.
    pub fn members(&self) -> usize {
        self.symbols.member_count()
    }

    /// Checks and lowers the interconnection, recording every error in `cx`.
    pub fn build(cx: &Ctxt, composite: &Composite<'_>) -> Option<CompositeModel> {
        let mut cm = CompositeModel {
            graph: Graph::new(),
            symbols: Symbols::default(),
            params: composite.params.clone(),
            rows: Vec::new(),
            mu: Vec::new(),
            holonomic: 0,
        };
        let fields: Vec<String> = composite.subsystems.iter().map(|s| s.ident.unraw().to_string()).collect();
        let mut scope = Scope::with_subsystems(fields.clone());
        for (i, p) in composite.params.iter().enumerate() {
            let id = cm.symbols.declare(&mut cm.graph, Sym::Parameter(i));
            scope.declare(p.unraw().to_string(), id, Role::Parameter);
        }
        let time = cm.symbols.declare(&mut cm.graph, Sym::Time);
        scope.declare(TIME.to_owned(), time, Role::Time);

        cm.holonomic_rows(cx, composite, &scope);
        cm.connections(cx, composite, &fields);
        cm.one_forms(cx, composite, &scope);
        for j in 0..cm.rows.len() {
            let id = cm.symbols.declare(&mut cm.graph, Sym::Multiplier(j));
            cm.mu.push(id);
        }
        check_row_names(cx, &cm.rows);
        if !cx.has_errors() {
            cm.check_elements(cx, composite);
        }
        (!cx.has_errors()).then_some(cm)
    }

    /// `connect(a.x, b.y)`: the row `v_a.x − v_b.y`, after checking the endpoints.
    fn connections(&mut self, cx: &Ctxt, composite: &Composite<'_>, fields: &[String]) {
        let mut seen: HashSet<(String, String)> = HashSet::new();
        for (i, c) in composite.connections.iter().enumerate() {
            let known = |m: &MemberPath| {
                let field = path_field(&m.path[0]);
                let ok = fields.iter().any(|f| f == field);
                if !ok {
                    let hint = did_you_mean(field, fields.iter().map(String::as_str));
                    cx.error_spanned_by(
                        &m.expr,
                        format!(
                            "unknown subsystem `{}`{hint}\nthe subsystems are: {}",
                            field,
                            fields.join(", ")
                        ),
                    );
                }
                ok
            };
            let (ok_a, ok_b) = (known(&c.a), known(&c.b));
            if !(ok_a && ok_b) {
                continue;
            }
            let (a, b) = (c.a.dotted(), c.b.dotted());
            if a == b {
                cx.error_spanned_by(&c.b.expr, format!("port `{a}` is connected to itself"));
                continue;
            }
            let pair = if a < b { (a.clone(), b.clone()) } else { (b.clone(), a.clone()) };
            if !seen.insert(pair) {
                cx.error_spanned_by(&c.key, format!("`{a}` and `{b}` are already connected"));
                continue;
            }
            let sa = self.port_ref(&c.a);
            let sb = self.port_ref(&c.b);
            let omega = self.graph.sub(sa, sb);
            let (name, key) = (format!("connect{i}"), c.key.clone());
            self.rows.push(Row { name, key, omega, terms: Vec::new(), holonomic: None });
        }
    }

    fn port_ref(&mut self, m: &MemberPath) -> Id {
        self.symbols.member(&mut self.graph, m.path.clone(), m.expr.to_token_stream(), true)
    }

    /// `constraint(name) = expr`: lowered term by term so each term's linearity can be checked.
    fn one_forms(&mut self, cx: &Ctxt, composite: &Composite<'_>, scope: &Scope) {
        for (i, c) in composite.constraints.iter().enumerate() {
            let name = c.name.as_ref().map(ToString::to_string).unwrap_or_else(|| format!("constraint{i}"));
            let what = format!("interconnection constraint `{name}`");
            let ctx = Context { what: &what, velocities: true, switch_on_velocities: true };
            let mut syntactic = Vec::new();
            additive_terms(&c.expr, false, &mut syntactic);
            let mut terms = Vec::new();
            for (term, negated) in &syntactic {
                let mut lowerer = Lowerer { cx, graph: &mut self.graph, symbols: &mut self.symbols, scope };
                if let Some(x) = lowerer.lower(term, ctx) {
                    let x = if *negated { self.graph.neg(x) } else { x };
                    terms.push((x, term.to_token_stream()));
                }
            }
            let names_a_member = terms.iter().any(|(x, _)| {
                self.symbols.members().any(|(m, id)| !m.port && self.graph.depends_on(*x, self.sym_of(id)))
            });
            if !names_a_member && !terms.is_empty() {
                let message = format!(
                    "{what} names no velocity of a subsystem; interconnection constraints are \
                     `Ω(q, t) v + b(q, t) = 0` over the subsystems' velocities"
                );
                cx.error_spanned_by(&c.expr, message);
            }
            let ids: Vec<Id> = terms.iter().map(|(x, _)| *x).collect();
            let omega = self.graph.add(&ids);
            let key = c.name.clone().unwrap_or_else(|| c.key.clone());
            self.rows.push(Row { name, key, omega, terms, holonomic: None });
        }
    }

    /// `holonomic(name) = expr`: the position constraint `φ(q, t) = 0` between subsystems,
    /// whose row is its rate `∂φ/∂q v + ∂φ/∂t`. Its members must be coordinates, which is
    /// checked once they are resolved.
    fn holonomic_rows(&mut self, cx: &Ctxt, composite: &Composite<'_>, scope: &Scope) {
        for (i, c) in composite.holonomic.iter().enumerate() {
            if composite.has_arrays() {
                let message = "a composite with arrays of subsystems has no holonomic interconnection \
                               constraints yet: hold the positions in a subsystem's own `holonomic` row, or \
                               write the constraint on velocities with `constraint = …`";
                cx.error_spanned_by(&c.key, message);
                continue;
            }
            let name = c.name.as_ref().map(ToString::to_string).unwrap_or_else(|| format!("holonomic{i}"));
            let what = format!("holonomic interconnection constraint `{name}`");
            let ctx = Context { what: &what, velocities: false, switch_on_velocities: false };
            let mut lowerer = Lowerer { cx, graph: &mut self.graph, symbols: &mut self.symbols, scope };
            let Some(phi) = lowerer.lower(&c.expr, ctx) else { continue };
            let members: Vec<usize> = (0..self.symbols.member_count())
                .filter(|&k| {
                    let m = self.symbols.member_at(k);
                    !m.rate && !m.port && self.graph.depends_on(phi, self.sym_of(self.symbols.member_id(k)))
                })
                .collect();
            if members.is_empty() {
                let message = format!(
                    "{what} names no coordinate of a subsystem; holonomic interconnection constraints are \
                     `φ(q, t) = 0` over the subsystems' coordinates"
                );
                cx.error_spanned_by(&c.expr, message);
                continue;
            }
            let mut terms = Vec::new();
            for k in members {
                let rate = self.symbols.rate(&mut self.graph, k);
                let slope = self.graph.diff(phi, self.symbols.member_id(k));
                terms.push(self.graph.mul2(slope, rate));
            }
            let time = self.symbols.declare(&mut self.graph, Sym::Time);
            terms.push(self.graph.diff(phi, time));
            let omega = self.graph.add(&terms);
            let key = c.name.clone().unwrap_or_else(|| c.key.clone());
            self.rows.push(Row { name, key, omega, terms: Vec::new(), holonomic: Some(phi) });
            self.holonomic += 1;
        }
    }

    /// The members a holonomic row's `φ` names: they must resolve to coordinates.
    pub fn positional_members(&self) -> Vec<usize> {
        (0..self.members())
            .filter(|&k| {
                let m = self.symbols.member_at(k);
                !m.rate
                    && !m.port
                    && self
                        .rows
                        .iter()
                        .filter_map(|r| r.holonomic)
                        .any(|phi| self.graph.depends_on(phi, self.sym_of(self.symbols.member_id(k))))
            })
            .collect()
    }

    /// An array field is named by an element (`cells[i]`), any other field without one.
    fn check_elements(&self, cx: &Ctxt, composite: &Composite<'_>) {
        for (member, _) in self.symbols.members() {
            let head = &member.path[0];
            let field = path_field(head);
            let Some(sub) = composite.subsystems.iter().find(|s| s.ident.unraw() == field) else {
                continue;
            };
            let indexed = head.contains('[');
            if sub.array && !indexed {
                let message = format!(
                    "`{field}` is an array of subsystems; name one element, as `{field}[i].{}` for every element \
                     `i`, `{field}[0]` or `{field}[last]`",
                    member.path[1..].join(".")
                );
                cx.error_spanned_by(&member.tokens, message);
            } else if !sub.array && indexed {
                cx.error_spanned_by(&member.tokens, format!("`{field}` is one subsystem, not an array"));
            }
        }
    }

    fn sym_of(&self, id: Id) -> u32 {
        self.graph.as_sym(id).expect("a reference is a symbol")
    }
}

/// Interconnection rows have distinct names.
fn check_row_names(cx: &Ctxt, rows: &[Row]) {
    let mut seen = HashSet::new();
    for row in rows {
        if !seen.insert(row.name.clone()) {
            cx.error_spanned_by(&row.key, format!("`{}` names two interconnection constraints", row.name));
        }
    }
}
