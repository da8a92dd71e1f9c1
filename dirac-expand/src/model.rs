//! The symbolic form of a checked model: its Lagrangian, forces, constraint rows and
//! holonomic constraints as graph expressions over typed symbols.

use syn::Ident;
use syn::ext::IdentExt;

use crate::ast::{ConstraintKind, Model};
use crate::ctxt::Ctxt;
use crate::law_decl::LawKind;
use crate::lower::{Context, Lowerer, Role, Scope, additive_terms};
use crate::sym::{Graph, Id, Node};
use crate::symbol::{DISSIPATED_POWER, TIME};
use crate::symbols::{Sym, Symbols};

/// A constraint row's name and the tokens that named it.
pub struct RowName {
    pub name: String,
    /// For error spans.
    pub ident: Ident,
}

/// A model as expressions in one graph. Rows of `a` are holonomic constraints first.
pub struct SymModel {
    pub graph: Graph,
    pub symbols: Symbols,
    pub params: Vec<Ident>,
    pub coordinates: Vec<Ident>,
    pub velocities: Vec<Ident>,
    pub ports: Vec<usize>,
    pub q: Vec<Id>,
    pub v: Vec<Id>,
    pub p: Vec<Id>,
    pub lambda: Vec<Id>,
    pub lagrangian: Id,
    /// `∂L/∂q` and `∂L/∂v`, one per coordinate, where the model gives them
    /// ([`Model::gradients`](crate::ast::Model::gradients)); `None` otherwise, and the blocks
    /// differentiate the Lagrangian.
    pub gradients: Option<(Vec<Id>, Vec<Id>)>,
    pub force: Vec<Id>,
    /// `A(q, t)`, `m × n`.
    pub a: Vec<Vec<Id>>,
    /// `b(q, t)`, one per row: the part of `A v + b = 0` without velocities, `∂φ/∂t` for a
    /// holonomic row. Zero unless the constraint prescribes a motion.
    pub b: Vec<Id>,
    /// `φ(q, t)`, one per holonomic row.
    pub phi: Vec<Id>,
    /// The forces that grow with constraint forces, one per coordinate (empty without them): a
    /// friction law's slip whose kinetic force names a row, `−μ λ_n s ∂g/∂v`, linear in the
    /// multipliers.
    pub slip: Vec<Id>,
    pub constraints: Vec<RowName>,
    /// `define(name) = …`: each name with its expression, in order (the symbol
    /// [`Sym::Define`] `k` is bound to the expression).
    pub defines: Vec<(String, Id)>,
    /// `output(name) = …`: each name with its expression, in order.
    pub outputs: Vec<(String, Id)>,
    /// `__recover("name") = …`: each name with its expression, in order.
    pub recovered: Vec<(String, Id)>,
    /// The parameter symbols that are inputs, in the order declared.
    pub inputs: Vec<Id>,
    /// `unilateral(name, restitution = e) = φ`: each name with `φ(q, t)` and `e`, in order.
    pub unilaterals: Vec<Unilateral>,
    /// `event(name, direction) = g`: each name with its direction (−1 falling, 1 rising, 0
    /// either) and `g(t, q, v, λ)`, in order.
    pub events: Vec<(String, i8, Id)>,
}

/// A unilateral constraint `φ(q, t) ≥ 0` with its coefficient of restitution.
pub struct Unilateral {
    pub name: String,
    pub phi: Id,
    pub restitution: Id,
}

impl SymModel {
    pub fn n(&self) -> usize {
        self.q.len()
    }

    pub fn m(&self) -> usize {
        self.a.len()
    }

    pub fn h(&self) -> usize {
        self.phi.len()
    }

    /// What symbol `sym` stands for.
    pub fn kind(&self, sym: u32) -> Sym {
        self.symbols.kind(sym)
    }

    /// Builds the symbolic model, recording every expression error in `cx`.
    pub fn build(cx: &Ctxt, model: &Model<'_>) -> Option<SymModel> {
        let mut graph = Graph::new();
        let zero = graph.num(0.0);
        let mut sm = SymModel {
            graph,
            symbols: Symbols::default(),
            params: model.params.clone(),
            coordinates: model.coordinates.iter().map(|c| c.name.clone()).collect(),
            velocities: model.coordinates.iter().map(|c| c.velocity.clone()).collect(),
            ports: Vec::new(),
            q: Vec::new(),
            v: Vec::new(),
            p: Vec::new(),
            lambda: Vec::new(),
            lagrangian: zero,
            gradients: None,
            force: Vec::new(),
            a: Vec::new(),
            b: Vec::new(),
            phi: Vec::new(),
            slip: Vec::new(),
            constraints: Vec::new(),
            defines: Vec::new(),
            outputs: Vec::new(),
            recovered: Vec::new(),
            inputs: Vec::new(),
            unilaterals: Vec::new(),
            events: Vec::new(),
        };
        let mut scope = sm.declare_symbols();
        for u in &model.inputs {
            if let Some(i) = sm.params.iter().position(|p| p.unraw() == *u) {
                let id = sm.declare(Sym::Parameter(i));
                sm.inputs.push(id);
            }
        }
        sm.lower_defines(cx, model, &mut scope);
        sm.ports = model.ports.iter().filter_map(|p| sm.coordinates.iter().position(|c| c == p)).collect();
        sm.force = vec![zero; sm.n()];
        let mut lw = Lowerer { cx, graph: &mut sm.graph, symbols: &mut sm.symbols, scope: &scope };
        let all = Context { what: "the Lagrangian", velocities: true, switch_on_velocities: true };
        let in_lagrangian = Context { switch_on_velocities: false, ..all };
        let lagrangian = model.lagrangian.as_ref().and_then(|(_, e)| lw.lower(e, in_lagrangian));
        for f in &model.forces {
            let what = format!("the force on `{}`", f.coordinate);
            let lowered = lw.lower(&f.expr, Context { what: &what, ..all });
            let index = sm.coordinates.iter().position(|c| *c == f.coordinate);
            if let (Some(x), Some(i)) = (lowered, index) {
                sm.force[i] = x;
            }
        }
        let dissipation = model.dissipation.as_ref().and_then(|(_, e)| {
            let what = "the dissipation function";
            lw.lower(e, Context { what, ..all }).map(|r| (e, r))
        });
        let dissipated_power = dissipation.and_then(|(e, r)| sm.dissipate(cx, e, r));
        sm.lower_constraints(cx, model, &scope);
        // Outputs, events and a friction law's force may also name a constraint, standing for
        // its multiplier.
        let mut with_multipliers = scope.clone();
        for (row, &lambda) in sm.constraints.iter().zip(&sm.lambda) {
            with_multipliers.declare(row.name.clone(), lambda, Role::Multiplier);
        }
        sm.slip_forces(cx, model, &with_multipliers);
        for o in &model.outputs {
            let what = format!("the output `{}`", o.name);
            let lowered = sm.lowerer(cx, &with_multipliers).lower(&o.expr, Context { what: &what, ..all });
            sm.outputs.push((o.name.to_string(), lowered.unwrap_or(zero)));
        }
        if let Some(power) = dissipated_power {
            sm.outputs.push((DISSIPATED_POWER.to_owned(), power));
        }
        if !model.recovered.is_empty() {
            // The accelerations are read only here, as `__dt_` and the velocity's name.
            let mut recovering = with_multipliers.clone();
            for (i, v) in sm.velocities.clone().iter().enumerate() {
                let id = sm.declare(Sym::Acceleration(i));
                recovering.declare(format!("__dt_{}", v.unraw()), id, Role::Velocity);
            }
            for (name, alias, expr) in &model.recovered {
                let what = format!("the recovered series `{name}`");
                let lowered = sm.lowerer(cx, &recovering).lower(expr, Context { what: &what, ..all });
                let value = lowered.unwrap_or(zero);
                if let Some(alias) = alias {
                    recovering.declare(alias.to_string(), value, Role::Multiplier);
                }
                sm.recovered.push((name.clone(), value));
            }
        }
        for e in &model.events {
            let what = format!("the event `{}`", e.name);
            let lowered = sm.lowerer(cx, &with_multipliers).lower(&e.expr, Context { what: &what, ..all });
            sm.events.push((e.name.to_string(), e.direction, lowered.unwrap_or(zero)));
        }
        sm.lower_unilaterals(cx, model, &scope);
        sm.lagrangian = lagrangian?;
        sm.gradients = sm.lower_gradients(cx, model, &scope);
        sm.add_switching_surfaces();
        (!cx.has_errors()).then_some(sm)
    }

    /// `∂L/∂q` and `∂L/∂v` of every coordinate: the model's expressions for those it names, the
    /// Lagrangian's derivatives for the others (a law's mode, a contact's slack); `None` if the
    /// model names none.
    fn lower_gradients(&mut self, cx: &Ctxt, model: &Model<'_>, scope: &Scope) -> Option<(Vec<Id>, Vec<Id>)> {
        let named = model.gradients.as_ref()?;
        let context = Context { what: "the Lagrangian", velocities: true, switch_on_velocities: false };
        let mut dl_dq = Vec::with_capacity(self.n());
        let mut dl_dv = Vec::with_capacity(self.n());
        for i in 0..self.n() {
            let given = named.iter().find(|(name, ..)| self.coordinates[i].unraw() == *name);
            let (dq, dv) = match given {
                Some((_, dq, dv)) => {
                    let mut lw = self.lowerer(cx, scope);
                    (lw.lower(dq, context)?, lw.lower(dv, context)?)
                }
                None => {
                    let (q, v, l) = (self.q[i], self.v[i], self.lagrangian);
                    (self.graph.diff(l, q), self.graph.diff(l, v))
                }
            };
            dl_dq.push(dq);
            dl_dv.push(dv);
        }
        Some((dl_dq, dl_dv))
    }

    /// Adds an event for each switching surface `c = 0` of a non-smooth function or a
    /// conditional in the Lagrangian, the forces (the dissipation's among them) and the
    /// constraints, named `switch0`, `switch1`, … (skipping names in use), with the direction
    /// code 2 (a switching surface: located in every solve, the integration restarted there),
    /// or 9 where `c` depends on time and parameters alone (a timed switch, whose crossing every
    /// solve knows before its step and ends the step at). `c` and `−c` are one surface.
    fn add_switching_surfaces(&mut self) {
        let mut roots = vec![self.lagrangian];
        roots.extend(&self.force);
        roots.extend(self.a.iter().flatten());
        roots.extend(&self.b);
        roots.extend(&self.phi);
        let mut surfaces = Vec::new();
        for c in self.graph.switches(&roots) {
            let c = match self.graph.node(c) {
                Node::Mul(k, _) if k.get() < 0.0 => self.graph.neg(c),
                _ => c,
            };
            if !surfaces.contains(&c) {
                surfaces.push(c);
            }
        }
        let mut k = 0;
        for c in surfaces {
            let name = loop {
                let name = format!("switch{k}");
                k += 1;
                let taken = |n: &str| {
                    self.events.iter().any(|(e, ..)| e == n)
                        || self.outputs.iter().any(|(o, _)| o == n)
                        || self.constraints.iter().any(|r| r.name == n)
                        || self.coordinates.iter().chain(&self.velocities).chain(&self.params).any(|i| i == n)
                };
                if !taken(&name) {
                    break name;
                }
            };
            let state = self.q.iter().chain(&self.v).chain(&self.p).chain(&self.lambda).chain(&self.inputs);
            let timed = !state.filter_map(|&x| self.graph.as_sym(x)).any(|s| self.graph.depends_on(c, s));
            self.events.push((name, if timed { 9 } else { 2 }, c));
        }
    }

    /// Adds the forces `−∂R/∂v` of the Rayleigh function `R` to the model's and returns the
    /// power they take, `⟨∂R/∂v, v⟩`; `None` after an error at `expr` if `R` depends on no
    /// velocity or is never positive (where its form decides it).
    fn dissipate(&mut self, cx: &Ctxt, expr: &syn::Expr, r: Id) -> Option<Id> {
        let gradient: Vec<Id> = self.v.clone().iter().map(|&v| self.graph.diff(r, v)).collect();
        if gradient.iter().all(|&d| self.graph.is_zero(d)) {
            cx.error_spanned_by(
                expr,
                "the dissipation function depends on no velocity, so its forces −∂R/∂v vanish; a Rayleigh \
                 function is written in the velocities, as `dissipation = 0.5 * c * v * v`",
            );
            return None;
        }
        if never_positive(&self.graph, r) {
            cx.error_spanned_by(
                expr,
                "the dissipation function is never positive, so it would put power into the model; a \
                 Rayleigh function R ≥ 0 takes power out (its forces are −∂R/∂v), as `0.5 * c * v * v`",
            );
            return None;
        }
        let mut terms = Vec::with_capacity(gradient.len());
        for (i, &d) in gradient.iter().enumerate() {
            self.force[i] = self.graph.sub(self.force[i], d);
            terms.push(self.graph.mul2(d, self.v[i]));
        }
        Some(self.graph.add(&terms))
    }

    /// Adds the kinetic force of each friction law, `−f_k s ∂g/∂v` (`s` its mode: ±1 slipping
    /// to the side of `g`'s sign, 0 stuck), and checks that every law's `g` depends on a
    /// velocity, as its row, a velocity constraint, needs. A kinetic force that names rows
    /// (`mu * floor`: Coulomb's law on the contact force of `floor`) must be linear in their
    /// multipliers; its push goes to [`SymModel::slip`], apart from the forces of the state.
    fn slip_forces(&mut self, cx: &Ctxt, model: &Model<'_>, scope: &Scope) {
        fn all(what: &str) -> Context<'_> {
            Context { what, velocities: true, switch_on_velocities: true }
        }
        for law in &model.laws {
            let what = format!("the law `{}`", law.name);
            let mut slips = Vec::new();
            for g_expr in std::iter::once(&law.g).chain(&law.g2) {
                let Some(g) = self.lowerer(cx, scope).lower(g_expr, all(&what)) else { continue };
                let gradient: Vec<Id> = self.v.clone().iter().map(|&v| self.graph.diff(g, v)).collect();
                if gradient.iter().all(|&d| self.graph.is_zero(d)) {
                    let quantity = match law.kind {
                        LawKind::Friction => "its relative velocity, as `v - vb`",
                        LawKind::Diode => "its reverse voltage in node-flux coordinates, as `vo - va`",
                        LawKind::Switch => "its voltage in node-flux coordinates, as `va - vb`",
                    };
                    cx.error_spanned_by(
                        g_expr,
                        format!("{what} depends on no velocity; its row holds `g = 0` on the velocities: write {quantity}"),
                    );
                    continue;
                }
                slips.push((g, gradient));
            }
            if slips.len() != 1 + law.g2.iter().count() {
                continue;
            }
            let (LawKind::Friction, Some(kinetic)) = (law.kind, &law.kinetic) else { continue };
            let what = format!("the kinetic force of `{}`", law.name);
            let Some(f) = self.lowerer(cx, scope).lower(kinetic, all(&what)) else { continue };
            let multipliers = self.multiplier_symbols();
            let on_rows = multipliers.iter().any(|&l| self.graph.depends_on(f, l));
            if on_rows && !self.linear_in(f, &multipliers) {
                cx.error_spanned_by(
                    kinetic,
                    format!(
                        "{what} must be linear in the constraint forces it names, as Coulomb's law is: \
                         `mu * floor` (the friction coefficient times the contact force of `floor`)"
                    ),
                );
                continue;
            }
            // Coulomb's force takes power out: a coefficient (or a force) that its form shows
            // is never positive would push along the slip.
            let coefficients: Vec<Id> = match on_rows {
                true => self.lambda.clone().into_iter().map(|l| self.graph.diff(f, l)).collect(),
                false => vec![f],
            };
            if coefficients.iter().any(|&c| never_positive(&self.graph, c)) {
                let (what, like) = match on_rows {
                    true => ("friction coefficient", "`mu * floor` with `#[dirac(nonnegative(mu))]`"),
                    false => ("kinetic force", "`mu * m * g`"),
                };
                cx.error_spanned_by(
                    kinetic,
                    format!(
                        "the {what} of `{}` is never positive, so the friction would push along the slip and \
                         put power into the model; Coulomb's force opposes it: write {like}",
                        law.name
                    ),
                );
                continue;
            }
            let modes: Option<Vec<Id>> = law
                .modes()
                .iter()
                .map(|mode| self.coordinates.iter().position(|c| c == mode).map(|i| self.q[i]))
                .collect();
            let Some(modes) = modes else { continue };
            // Each quantity's share of the push: the mode `s` of a line, `σ (g_i + ε m_i) / |g + ε m|`
            // of a cone (see `cone_direction`).
            let shares = match modes[..] {
                [s] => vec![s],
                _ => self.cone_direction(&slips.iter().map(|(g, _)| *g).collect::<Vec<_>>(), &modes),
            };
            if on_rows && self.slip.is_empty() {
                self.slip = vec![self.graph.num(0.0); self.n()];
            }
            for ((_, gradient), share) in slips.into_iter().zip(shares) {
                let push = self.graph.mul2(f, share);
                let forces = if on_rows { &mut self.slip } else { &mut self.force };
                for (j, d) in gradient.into_iter().enumerate() {
                    let term = self.graph.mul2(push, d);
                    forces[j] = self.graph.sub(forces[j], term);
                }
            }
        }
    }

    /// The direction of a friction cone's slip `g` against the direction `m` frozen in its mode
    /// (zero while stuck), with `p = m·g` the slip along `m` and `w = m⊥·g` across it:
    ///
    /// ```text
    /// d = (√(p² + ε²) m + w m⊥) / √(p² + w² + ε²),    m⊥ = (−m₂, m₁),
    /// ```
    ///
    /// Coulomb's `g / |g|` but for a relative `O(ε² / p²)` (`ε` is
    /// [`CONE_ONSET`](crate::laws::CONE_ONSET)), and smooth everywhere: at the start of a slip from
    /// rest (`g = 0`) and through a stop along `m` it is `m`, as a friction line's is its mode.
    fn cone_direction(&mut self, g: &[Id], m: &[Id]) -> Vec<Id> {
        let (g1, g2, m1, m2) = (g[0], g[1], m[0], m[1]);
        let along = [self.graph.mul2(m1, g1), self.graph.mul2(m2, g2)];
        let p = self.graph.add(&along);
        let (a, b) = (self.graph.mul2(m1, g2), self.graph.mul2(m2, g1));
        let w = self.graph.sub(a, b);
        let eps2 = self.graph.num(crate::laws::CONE_ONSET * crate::laws::CONE_ONSET);
        let p2 = self.graph.mul2(p, p);
        let w2 = self.graph.mul2(w, w);
        let r2 = self.graph.add2(p2, eps2);
        let r = self.graph.call(crate::sym::graph::Func::Sqrt, r2);
        let n2 = self.graph.add2(r2, w2);
        let n = self.graph.call(crate::sym::graph::Func::Sqrt, n2);
        // (r m1 − w m2) / n and (r m2 + w m1) / n.
        let (rm1, wm2) = (self.graph.mul2(r, m1), self.graph.mul2(w, m2));
        let (rm2, wm1) = (self.graph.mul2(r, m2), self.graph.mul2(w, m1));
        let d1 = self.graph.sub(rm1, wm2);
        let d2 = self.graph.add2(rm2, wm1);
        vec![self.graph.div(d1, n), self.graph.div(d2, n)]
    }

    /// The symbols of the multipliers.
    fn multiplier_symbols(&self) -> Vec<u32> {
        self.lambda.iter().map(|&l| self.graph.as_sym(l).expect("a multiplier is a symbol")).collect()
    }

    /// Whether `f` is linear in the symbols `syms` (of `self.lambda`): none of its derivatives
    /// by one depends on any.
    fn linear_in(&mut self, f: Id, syms: &[u32]) -> bool {
        self.lambda.clone().into_iter().all(|l| {
            let d = self.graph.diff(f, l);
            syms.iter().all(|&s| !self.graph.depends_on(d, s))
        })
    }

    /// Lowers each `unilateral(name, restitution = e) = φ`: `φ` of the coordinates and time,
    /// `e` of the parameters (1 when not given).
    fn lower_unilaterals(&mut self, cx: &Ctxt, model: &Model<'_>, scope: &Scope) {
        for u in &model.unilaterals {
            let what = format!("unilateral constraint `{}`", u.name);
            let ctx = Context { what: &what, velocities: false, switch_on_velocities: true };
            let Some(phi) = self.lowerer(cx, scope).lower(&u.expr, ctx) else { continue };
            let q = self.q.clone();
            if q.iter().all(|&x| {
                let d = self.graph.diff(phi, x);
                self.graph.is_zero(d)
            }) {
                cx.error_spanned_by(&u.expr, format!("{what} does not depend on any coordinate"));
                continue;
            }
            let restitution = match &u.restitution {
                None => self.graph.num(1.0),
                Some(e) => {
                    let what = format!("the restitution of unilateral constraint `{}`", u.name);
                    let Some(e_id) = self
                        .lowerer(cx, scope)
                        .lower(e, Context { what: &what, velocities: false, switch_on_velocities: true })
                    else {
                        continue;
                    };
                    let time = self.symbols.declare(&mut self.graph, Sym::Time);
                    let on_state = q.iter().chain([&time]).any(|&x| {
                        let d = self.graph.diff(e_id, x);
                        !self.graph.is_zero(d)
                    });
                    if on_state {
                        cx.error_spanned_by(
                            e,
                            format!("{what} depends on the coordinates or on time; it must be a constant or a parameter"),
                        );
                        continue;
                    }
                    e_id
                }
            };
            self.unilaterals.push(Unilateral { name: u.name.to_string(), phi, restitution });
        }
    }

    /// Lowers each `define(name) = …` in order, each in the scope of the ones before it.
    fn lower_defines(&mut self, cx: &Ctxt, model: &Model<'_>, scope: &mut Scope) {
        for d in &model.defines {
            let name = d.name.to_string();
            let what = format!("the definition `{name}`");
            let ctx = Context { what: &what, velocities: true, switch_on_velocities: true };
            // A definition with errors is still declared (as zero), so that its uses report
            // nothing more; the errors already stop the expansion.
            let value = self.lowerer(cx, scope).lower(&d.expr, ctx).unwrap_or_else(|| self.graph.num(0.0));
            let id = self.declare(Sym::Define(self.defines.len()));
            self.graph.bind(id, value);
            scope.declare(name.clone(), id, Role::Define);
            self.defines.push((name, value));
        }
    }

    fn declare(&mut self, kind: Sym) -> Id {
        self.symbols.declare(&mut self.graph, kind)
    }

    fn declare_symbols(&mut self) -> Scope {
        let mut scope = Scope::new();
        for (i, p) in self.params.clone().iter().enumerate() {
            let id = self.declare(Sym::Parameter(i));
            scope.declare(p.unraw().to_string(), id, Role::Parameter);
        }
        for (i, c) in self.coordinates.clone().iter().enumerate() {
            let id = self.declare(Sym::Coordinate(i));
            self.q.push(id);
            scope.declare(c.to_string(), id, Role::Coordinate);
        }
        for (i, v) in self.velocities.clone().iter().enumerate() {
            let id = self.declare(Sym::Velocity(i));
            self.v.push(id);
            scope.declare(v.to_string(), id, Role::Velocity);
        }
        for i in 0..self.n() {
            let id = self.declare(Sym::Momentum(i));
            self.p.push(id);
        }
        let time = self.declare(Sym::Time);
        scope.declare(TIME.to_owned(), time, Role::Time);
        scope
    }

    /// Lowers holonomic constraints (rows `∂φ/∂q`) first, then velocity constraints.
    fn lower_constraints(&mut self, cx: &Ctxt, model: &Model<'_>, scope: &Scope) {
        for c in model.ordered_constraints() {
            let what = format!("constraint `{}`", c.name);
            let row = match c.decl.kind {
                ConstraintKind::Holonomic => self.holonomic_row(cx, &c.decl.expr, &what, scope),
                ConstraintKind::Velocity => self.velocity_row(cx, &c.decl.expr, (&what, &c.name), scope),
            };
            if let Some((row, b)) = row {
                self.a.push(row);
                self.b.push(b);
                self.constraints.push(RowName { name: c.name, ident: c.ident.clone() });
            }
        }
        for j in 0..self.constraints.len() {
            let id = self.declare(Sym::Multiplier(j));
            self.lambda.push(id);
        }
    }

    fn lowerer<'a>(&'a mut self, cx: &'a Ctxt, scope: &'a Scope) -> Lowerer<'a> {
        Lowerer { cx, graph: &mut self.graph, symbols: &mut self.symbols, scope }
    }

    /// The row `∂φ/∂q` of `φ(q, t) = 0` and its rate `∂φ/∂t`.
    fn holonomic_row(
        &mut self,
        cx: &Ctxt,
        expr: &syn::Expr,
        what: &str,
        scope: &Scope,
    ) -> Option<(Vec<Id>, Id)> {
        let ctx = Context { what, velocities: false, switch_on_velocities: true };
        let phi = self.lowerer(cx, scope).lower(expr, ctx)?;
        let row: Vec<Id> = self.q.clone().iter().map(|q| self.graph.diff(phi, *q)).collect();
        if row.iter().all(|d| self.graph.is_zero(*d)) {
            cx.error_spanned_by(expr, format!("{what} does not depend on any coordinate"));
            return None;
        }
        let time = self.symbols.declare(&mut self.graph, Sym::Time);
        let rate = self.graph.diff(phi, time);
        self.phi.push(phi);
        Some((row, rate))
    }

    /// Splits `a(q, t) · v + b(q, t)` into its row `a` and its rate `b`, checking that every
    /// term is affine in the velocities.
    fn velocity_row(
        &mut self,
        cx: &Ctxt,
        expr: &syn::Expr,
        (what, name): (&str, &str),
        scope: &Scope,
    ) -> Option<(Vec<Id>, Id)> {
        let ctx = Context { what, velocities: true, switch_on_velocities: true };
        let mut terms = Vec::new();
        additive_terms(expr, false, &mut terms);
        let mut lowered = Vec::new();
        let mut ok = true;
        for (term, negated) in &terms {
            let Some(x) = self.lowerer(cx, scope).lower(term, ctx) else {
                ok = false;
                continue;
            };
            if self.nonlinear_in_velocities(x) {
                cx.error_spanned_by(
                    term,
                    format!(
                        "{what} must be affine in the velocities, `A(q, t) v + b(q, t) = 0`, \
                         but this term is not linear in the velocities"
                    ),
                );
                ok = false;
            }
            lowered.push(if *negated { self.graph.neg(x) } else { x });
        }
        if !ok {
            return None;
        }
        let c = self.graph.add(&lowered);
        let row: Vec<Id> = self.v.clone().iter().map(|v| self.graph.diff(c, *v)).collect();
        if row.iter().all(|d| self.graph.is_zero(*d)) {
            cx.error_spanned_by(
                expr,
                format!(
                    "{what} has no velocity in it; velocity constraints are `A(q, t) v + b(q, t) = 0` \
                     (write a constraint on positions as `holonomic({name}) = ...`)"
                ),
            );
            return None;
        }
        let zero = self.graph.num(0.0);
        let at_rest = self.v.iter().filter_map(|v| self.graph.as_sym(*v)).map(|s| (s, zero)).collect();
        let b = self.graph.substitute(c, &at_rest);
        Some((row, b))
    }

    /// Whether a term's derivative by some velocity still depends on a velocity.
    fn nonlinear_in_velocities(&mut self, term: Id) -> bool {
        let velocities: Vec<Id> = self.v.clone();
        let syms: Vec<u32> = velocities.iter().filter_map(|v| self.graph.as_sym(*v)).collect();
        velocities.iter().any(|v| {
            let d = self.graph.diff(term, *v);
            syms.iter().any(|s| self.graph.depends_on(d, *s))
        })
    }
}

/// Whether an expression is `≥ 0` for every value of its symbols, by its form alone (even
/// powers, square roots, exponentials, and sums and positive multiples of them).
fn never_negative(graph: &Graph, id: Id) -> bool {
    use crate::sym::Func;
    match graph.node(id) {
        Node::Num(c) => c.get() >= 0.0,
        Node::Powi(_, k) => k % 2 == 0,
        Node::Call(Func::Sqrt | Func::Exp | Func::Cosh, _) => true,
        Node::Mul(c, factors) => c.get() >= 0.0 && factors.iter().all(|&f| never_negative(graph, f)),
        Node::Add(c, terms) => c.get() >= 0.0 && terms.iter().all(|&x| never_negative(graph, x)),
        _ => false,
    }
}

/// Whether an expression is `≤ 0` for every value of its symbols and not zero, by its form.
fn never_positive(graph: &Graph, id: Id) -> bool {
    let nonpositive = |x: Id| match graph.node(x) {
        Node::Num(c) => c.get() <= 0.0,
        Node::Mul(c, factors) => c.get() < 0.0 && factors.iter().all(|&f| never_negative(graph, f)),
        _ => false,
    };
    !graph.is_zero(id)
        && match graph.node(id) {
            Node::Add(c, terms) => c.get() <= 0.0 && terms.iter().all(|&x| nonpositive(x)),
            _ => nonpositive(id),
        }
}
