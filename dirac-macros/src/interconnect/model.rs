//! The symbolic form of a composite: its interconnection rows `Ω(q) v = 0` over symbols that
//! stand for subsystem members, which are resolved to indices only when the program compiles.

use std::collections::HashSet;

use proc_macro2::TokenStream;
use quote::ToTokens;
use syn::Ident;
use syn::ext::IdentExt;

use super::ast::{Composite, MemberPath};
use crate::ctxt::Ctxt;
use crate::lower::{Context, Lowerer, Role, Scope, additive_terms};
use crate::suggest::did_you_mean;
use crate::sym::{Graph, Id};
use crate::symbol::TIME;

/// What a graph symbol of a composite stands for.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum CKind {
    Parameter(usize),
    /// A subsystem member (`refs[k]`).
    Ref(usize),
    /// The multiplier of interconnection row `j`.
    Mu(usize),
    Time,
}

/// A subsystem member named in an interconnection.
pub struct Ref {
    pub path: Vec<String>,
    pub tokens: TokenStream,
    pub id: Id,
    /// A `connect` endpoint: a port, named by its coordinate, standing for its velocity.
    pub port: bool,
}

impl Ref {
    pub fn dotted(&self) -> String {
        self.path.join(".")
    }
}

/// One interconnection row `Ω_j(q) v = 0`.
pub struct Row {
    pub name: String,
    /// The tokens that declared it, for error spans.
    pub key: Ident,
    pub omega: Id,
    /// The additive terms of a one-form with their tokens (empty for `connect`), whose
    /// linearity in the velocities is checked once names are resolved.
    pub terms: Vec<(Id, TokenStream)>,
}

/// A composite's interconnection rows in one graph.
pub struct CompositeModel {
    pub graph: Graph,
    pub kinds: Vec<CKind>,
    pub params: Vec<Ident>,
    pub refs: Vec<Ref>,
    pub rows: Vec<Row>,
    pub mu: Vec<Id>,
}

impl CompositeModel {
    pub fn kind(&self, sym: u32) -> CKind {
        self.kinds[sym as usize]
    }

    fn symbol(&mut self, name: &str, kind: CKind) -> Id {
        let id = self.graph.symbol(name);
        let sym = self.graph.as_sym(id).expect("a fresh symbol") as usize;
        if self.kinds.len() <= sym {
            self.kinds.resize(sym + 1, CKind::Time);
        }
        self.kinds[sym] = kind;
        id
    }

    /// Checks and lowers the interconnection, recording every error in `cx`.
    pub fn build(cx: &Ctxt, composite: &Composite<'_>) -> Option<CompositeModel> {
        let mut cm = CompositeModel {
            graph: Graph::new(),
            kinds: Vec::new(),
            params: composite.params.clone(),
            refs: Vec::new(),
            rows: Vec::new(),
            mu: Vec::new(),
        };
        let fields: Vec<String> = composite.subsystems.iter().map(|s| s.ident.unraw().to_string()).collect();
        let mut scope = Scope::with_subsystems(fields.clone());
        for (i, p) in composite.params.iter().enumerate() {
            let name = p.unraw().to_string();
            let id = cm.symbol(&name, CKind::Parameter(i));
            scope.declare(name, id, Role::Parameter);
        }
        let time = cm.symbol(TIME, CKind::Time);
        scope.declare(TIME.to_owned(), time, Role::Time);

        cm.connections(cx, composite, &fields);
        cm.one_forms(cx, composite, &scope);
        let names: Vec<String> = cm.rows.iter().map(|r| r.name.clone()).collect();
        for (j, name) in names.iter().enumerate() {
            let id = cm.symbol(&format!("mu:{name}"), CKind::Mu(j));
            cm.mu.push(id);
        }
        check_row_names(cx, &cm.rows);
        (!cx.has_errors()).then_some(cm)
    }

    /// `connect(a.x, b.y)`: the row `v_a.x − v_b.y`, after checking the endpoints.
    fn connections(&mut self, cx: &Ctxt, composite: &Composite<'_>, fields: &[String]) {
        let mut seen: HashSet<(String, String)> = HashSet::new();
        for (i, c) in composite.connections.iter().enumerate() {
            let known = |m: &MemberPath| {
                let ok = fields.contains(&m.path[0]);
                if !ok {
                    let hint = did_you_mean(&m.path[0], fields.iter().map(String::as_str));
                    cx.error_spanned_by(
                        &m.expr,
                        format!(
                            "unknown subsystem `{}`{hint}\nthe subsystems are: {}",
                            m.path[0],
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
            self.rows.push(Row { name: format!("connect{i}"), key: c.key.clone(), omega, terms: Vec::new() });
        }
    }

    fn port_ref(&mut self, m: &MemberPath) -> Id {
        let dotted = m.dotted();
        if let Some(r) = self.refs.iter().find(|r| r.port && r.path == m.path) {
            return r.id;
        }
        let k = self.refs.len();
        let id = self.symbol(&format!("port:{dotted}"), CKind::Ref(k));
        self.refs.push(Ref { path: m.path.clone(), tokens: m.expr.to_token_stream(), id, port: true });
        id
    }

    /// `constraint(name) = expr`: lowered term by term so each term's linearity can be checked.
    fn one_forms(&mut self, cx: &Ctxt, composite: &Composite<'_>, scope: &Scope) {
        for (i, c) in composite.constraints.iter().enumerate() {
            let name = c.name.as_ref().map(ToString::to_string).unwrap_or_else(|| format!("constraint{i}"));
            let what = format!("interconnection constraint `{name}`");
            let ctx = Context { what: &what, velocities: true, time: false };
            let mut syntactic = Vec::new();
            additive_terms(&c.expr, false, &mut syntactic);
            let mut terms = Vec::new();
            for (term, negated) in &syntactic {
                let lowered = Lowerer { cx, graph: &mut self.graph, scope }.lower(term, ctx);
                if let Some(x) = lowered {
                    let x = if *negated { self.graph.neg(x) } else { x };
                    terms.push((x, term.to_token_stream()));
                }
            }
            self.register_refs(scope);
            for (x, tokens) in &terms {
                if !self.refs.iter().any(|r| !r.port && self.graph.depends_on(*x, self.sym_of(r.id))) {
                    let message = format!(
                        "{what} must be linear in the velocities of the subsystems, but this term names no subsystem member"
                    );
                    cx.error_spanned_by(tokens, message);
                }
            }
            let ids: Vec<Id> = terms.iter().map(|(x, _)| *x).collect();
            let omega = self.graph.add(&ids);
            let key = c.name.clone().unwrap_or_else(|| c.key.clone());
            self.rows.push(Row { name, key, omega, terms });
        }
    }

    fn sym_of(&self, id: Id) -> u32 {
        self.graph.as_sym(id).expect("a reference is a symbol")
    }

    /// Records the members the lowerer met as references.
    fn register_refs(&mut self, scope: &Scope) {
        for r in scope.take_refs() {
            if self.refs.iter().any(|x| !x.port && x.path == r.path) {
                continue;
            }
            let k = self.refs.len();
            let sym = self.sym_of(r.id) as usize;
            if self.kinds.len() <= sym {
                self.kinds.resize(sym + 1, CKind::Time);
            }
            self.kinds[sym] = CKind::Ref(k);
            self.refs.push(Ref { path: r.path, tokens: r.tokens, id: r.id, port: false });
        }
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
