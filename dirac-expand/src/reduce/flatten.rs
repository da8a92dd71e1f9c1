//! One model from a composite's parts, with its aliases eliminated (DESIGN §6.1).
//!
//! Every name of a part is prefixed by where the part sits (`gear.wa` is the flat model's
//! `gear__wa`); the Lagrangians, Rayleigh functions and forces add up; the parts' rows, the
//! composite's own rows and its connections become the flat model's rows. Then the rows that
//! only say how coordinates move together are solved at compile time and dropped:
//!
//! - `connect(a.x, b.y)`: `b.y` is `a.x` (the first in field order stays);
//! - a position row affine in the coordinates with constant coefficients (`p`, a ground;
//!   `phi - phi0`, a fixed flange): one of its coordinates is the rest's combination;
//! - a velocity row linear in two or more velocities with constant coefficients and nothing
//!   else (`wa - ratio * wb`, a gear; `vp - vn - k * w`, an EMF): the same for the velocities,
//!   and for the coordinates with their difference at zero.
//!
//! A velocity row of that kind is solved in its integrated form (`a - ratio * b`), so that
//! positions substitute positions. An eliminated coordinate's forces act on the coordinates it
//! is made of, scaled by their coefficients (virtual work). A row whose multiplier a part reads
//! (an output `i = -emf`) is solved only for a coordinate without inertia that no other row
//! reaches, its multiplier then read off that coordinate's momentum balance; otherwise it
//! stays a row. The reduced model moves like the composite started with the eliminated rows'
//! offsets at zero: connected coordinates equal, geared ones in ratio.

mod bodies;
mod recover;

use std::collections::HashMap;

use proc_macro2::{Span, TokenStream};
use quote::{ToTokens, format_ident, quote};
use syn::{DeriveInput, Expr, Ident};

use super::Kind;
use super::affine::{Coefficient, Role, affine, solve};
use super::derivative::{D, derivative};
use super::rewrite::{point_at_fields, rename};
use crate::ast::{ConstraintKind, Requirement};
use crate::ctxt::Ctxt;
use crate::interconnect::ast::Composite;
use crate::interconnect::joints;
use crate::symbol::DISSIPATED_POWER;

/// A part's description, filed under where it sits in the composite.
pub struct Part {
    pub prefix: Vec<Ident>,
    pub kind: Kind,
    pub input: DeriveInput,
}

/// A coordinate of the flat model.
#[derive(Clone)]
struct Coordinate {
    q: String,
    v: String,
    port: bool,
}

/// A row of the flat model.
#[derive(Clone)]
struct Row {
    kind: ConstraintKind,
    name: String,
    expr: TokenStream,
    /// A velocity row linear in two velocities or more with constant coefficients and
    /// nothing else, integrated with its offset at zero: `wa - ratio * wb` as `a - ratio * b`.
    /// The reduction solves it in this form, so that positions substitute positions.
    position: Option<TokenStream>,
    /// A composite's own row (not a part's): its force is an interconnection force, part of
    /// the efforts at the ports it reaches.
    interconnection: bool,
}

/// A connection `connect(a, b)`: the row `v_a − v_b = 0`, named as the composite unreduced
/// names it (`connect3`, `drive__connect0`).
#[derive(Clone)]
struct Connection {
    a: String,
    b: String,
    key: Ident,
    name: String,
}

/// A joint between two bodies, in the flat model's names.
#[derive(Clone)]
struct FlatJoint {
    key: Ident,
    name: String,
    /// The joint's coordinate and velocity; none for a fixed joint.
    coordinate: Option<(String, String)>,
    kind: joints::Kind,
    /// The parent body's prefix (`link1`), none for the world.
    parent: Option<String>,
    child: String,
    at_parent: [joints::S; 3],
    at_child: [joints::S; 3],
}

impl FlatJoint {
    /// `joint` of the part at `prefix`, its names prefixed, its points' parameters renamed by
    /// `rename`; errors point at `key`.
    fn new(
        joint: &joints::Joint,
        prefix: &[String],
        key: Ident,
        rename: &dyn Fn(TokenStream) -> TokenStream,
    ) -> Self {
        let flat = |path: &[String]| {
            let mut full = prefix.to_vec();
            full.extend(path.iter().cloned());
            mangle(&full)
        };
        let own = |i: &Ident| flat(&[syn::ext::IdentExt::unraw(i).to_string()]);
        FlatJoint {
            key,
            name: own(&joint.name),
            coordinate: joint.coordinate.as_ref().map(|(q, v)| (own(q), own(v))),
            kind: joint.kind,
            parent: (!joint.parent.path.is_empty()).then(|| flat(&joint.parent.path)),
            child: flat(&joint.child.path),
            at_parent: joints::point(&joint.parent.at, rename),
            at_child: joints::point(&joint.child.at, rename),
        }
    }

    /// The joint as a reduced composite describes it to the composites around it, in its flat
    /// names: `#[dirac(__joint(th => w) = revolute(y, link1 at [..], link2 at [..]))]`.
    fn attribute(&self) -> TokenStream {
        let ident = |s: &str| Ident::new(s, Span::call_site());
        let name = match &self.coordinate {
            Some((q, v)) => {
                let (q, v) = (ident(q), ident(v));
                quote! { #q => #v }
            }
            None => {
                let name = ident(&self.name);
                quote! { #name }
            }
        };
        let axis = |a: usize| ident(["x", "y", "z"][a]);
        let (kind, axis) = match self.kind {
            joints::Kind::Revolute(a) => (quote! { revolute }, Some(axis(a))),
            joints::Kind::Prismatic(a) => (quote! { prismatic }, Some(axis(a))),
            joints::Kind::Fixed => (quote! { fixed }, None),
        };
        let axis = axis.map(|a| quote! { #a, });
        let parent = ident(self.parent.as_deref().unwrap_or("world"));
        let child = ident(&self.child);
        let point = |at: &[joints::S; 3]| {
            let entries = at.iter().map(joints::S::tokens);
            quote! { [#(#entries),*] }
        };
        let (at_parent, at_child) = (point(&self.at_parent), point(&self.at_child));
        quote! {
            #[dirac(__joint(#name) = #kind(#axis #parent at #at_parent, #child at #at_child))]
        }
    }
}

/// The input without the joints a reduced composite described, and those joints.
fn split_joints(input: &DeriveInput) -> (DeriveInput, Vec<joints::Joint>) {
    let mut input = input.clone();
    let mut found = Vec::new();
    input.attrs.retain(|attr| {
        let joint = attr.path().is_ident("dirac").then(|| {
            attr.parse_args_with(|content: syn::parse::ParseStream| {
                let key: Ident = content.parse()?;
                if key != "__joint" {
                    return Err(content.error("not a joint"));
                }
                joints::parse(key, content)
            })
        });
        match joint {
            Some(Ok(joint)) => {
                found.push(joint);
                false
            }
            _ => true,
        }
    });
    (input, found)
}

/// A coordinate solved for: `q = Σ kⱼ qⱼ + k₀` (the text for the list of eliminations).
#[derive(Clone)]
struct Elimination {
    name: String,
    by: String,
}

/// What a row gives at compile time.
enum Solution {
    /// The coordinate at this index is the others' combination plus a constant; the row's
    /// coefficient of it.
    For(usize, Vec<(String, Coefficient)>, Coefficient, f64),
    /// The row prescribes the velocity of the coordinate at this index, which nothing else
    /// reads: what the velocity equals, and the row's coefficient of it.
    Prescribed(usize, TokenStream, f64),
    /// The row holds whatever the coordinates: drop it.
    Redundant,
    /// The row stays a row.
    None,
}

/// The coordinate `name` stands for after the connections so far: itself, or the one it was
/// merged into.
fn resolve(subst: &HashMap<String, TokenStream>, mut name: String) -> String {
    while let Some(to) = subst.get(&name) {
        let mut trees = to.clone().into_iter();
        match (trees.next(), trees.next()) {
            (Some(proc_macro2::TokenTree::Ident(i)), None) => name = i.to_string(),
            _ => break,
        }
    }
    name
}

/// The flat model while it is assembled.
#[derive(Default, Clone)]
struct Flat {
    /// Each field of the flat model with the path of the composite's fields it reads.
    params: Vec<(String, Vec<String>)>,
    requirements: Vec<(String, Requirement)>,
    inputs: Vec<String>,
    coordinates: Vec<Coordinate>,
    lagrangian: Vec<TokenStream>,
    dissipation: Vec<TokenStream>,
    forces: Vec<(String, TokenStream)>,
    rows: Vec<Row>,
    defines: Vec<(String, TokenStream)>,
    outputs: Vec<(String, TokenStream)>,
    units: Vec<(String, syn::LitStr)>,
    connections: Vec<Connection>,
    joints: Vec<FlatJoint>,
    /// Each body carried by a joint's coordinate, with the joint's name.
    jointed: Vec<(String, String)>,
    large: bool,
    eliminated: Vec<Elimination>,
    /// The coordinates and the Lagrangian's terms before the eliminations.
    original: Vec<Coordinate>,
    original_lagrangian: Vec<TokenStream>,
    /// The Lagrangian and the Rayleigh function split into their terms (see `recover`).
    lagrangian_terms: Vec<TokenStream>,
    dissipation_terms: Vec<TokenStream>,
    /// The rows and connections eliminated, in order, with their multipliers.
    recoveries: Vec<recover::Recovery>,
    /// The interconnection rows' terms at each port, before the eliminations.
    port_terms: Vec<recover::PortTerm>,
    /// Each part's Rayleigh function with the output its power is (`r.dissipated_power`) and
    /// the part's velocities.
    dissipations: Vec<(String, TokenStream, Vec<String>)>,
    /// What each term and row reads when the eliminations start (see `recover`).
    names_read: recover::NamesRead,
    /// What the reduced model recovers at each sample (see `recover`).
    recovered: Vec<recover::Recovered>,
}

fn mangle(path: &[String]) -> String {
    path.join("__")
}

fn strings(prefix: &[Ident]) -> Vec<String> {
    prefix.iter().map(|i| syn::ext::IdentExt::unraw(i).to_string()).collect()
}

/// The flat model's expansion, or the errors that stop it beside stub impls.
pub fn flatten(input: &DeriveInput, parts: &[Part]) -> TokenStream {
    let cx = Ctxt::new();
    let mut flat = Flat::default();
    let top = Part { prefix: Vec::new(), kind: Kind::Composite, input: input.clone() };
    for part in std::iter::once(&top).chain(parts) {
        let field = part.prefix.first().unwrap_or(&input.ident);
        match part.kind {
            Kind::Primitive => flat.primitive(&cx, part, field),
            Kind::Composite => flat.composite(&cx, part),
        }
    }
    // A composite's rows read its parts' names, which are all known now.
    for part in std::iter::once(&top).chain(parts).filter(|p| p.kind == Kind::Composite) {
        flat.composite_rows(&cx, part);
    }
    let mut described = None;
    if !cx.has_errors() {
        // A reduced composite describes itself to the composites around it before its
        // eliminations, its connections as rows: they reduce it again with their own
        // connections, and every name of its parts is theirs to connect.
        let mut whole = flat.clone();
        whole.connections_as_rows();
        described = Some(whole.input(input));
        flat.eliminate(&cx);
    }
    if let Some(errors) = cx.into_compile_errors() {
        let stub = crate::expand::stub_impls(&input.ident, (1, 1));
        return quote! { #errors #stub };
    }
    let model = flat.input(input);
    let model: DeriveInput = match syn::parse2(model) {
        Ok(model) => model,
        Err(e) => return e.to_compile_error(),
    };
    let expanded = crate::expand::derive(&model);
    let fields: HashMap<String, Vec<String>> = flat.params.iter().cloned().collect();
    let mut names: Vec<(String, String)> = flat
        .params
        .iter()
        .map(|(p, _)| p.clone())
        .chain(flat.inputs.iter().cloned())
        .chain(flat.coordinates.iter().flat_map(|c| [c.q.clone(), c.v.clone()]))
        .chain(flat.rows.iter().map(|r| r.name.clone()))
        .chain(flat.outputs.iter().map(|(o, _)| o.clone()))
        .chain(flat.defines.iter().map(|(d, _)| d.clone()))
        .filter(|n| n.contains("__"))
        .flat_map(|n| {
            let dotted = n.replace("__", ".");
            // The LaTeX of the equations escapes underscores.
            let escaped = (n.replace('_', "\\_"), dotted.replace('_', "\\_"));
            [(n, dotted), escaped]
        })
        .collect();
    names.sort_by_key(|(n, _)| std::cmp::Reverse(n.len()));
    let expanded = point_at_fields(expanded, &fields, &names);
    let description = match described.map(syn::parse2::<DeriveInput>) {
        Some(Ok(whole)) => super::description(&whole, Kind::Primitive),
        Some(Err(e)) => e.to_compile_error(),
        None => TokenStream::new(),
    };
    let eliminated = flat.eliminated.iter().map(|e| {
        let (name, by) = (e.name.replace("__", "."), e.by.replace("__", "."));
        quote! { (#name, #by) }
    });
    let (ident, vis) = (&input.ident, &input.vis);
    let fields = match &input.data {
        syn::Data::Struct(data) => data.fields.iter().filter_map(|f| f.ident.clone()).collect(),
        _ => Vec::new(),
    };
    quote! {
        #expanded
        #description
        // Not `automatically_derived`: the reads must count for the dead-code lint.
        impl ::dirac::__private::ReducedParts for #ident {
            fn read_parts(&self) {
                #(let _ = &self.#fields;)*
            }
        }
        #[automatically_derived]
        impl #ident {
            /// The coordinates the reduction solved for at compile time, each with what it
            /// equals in the coordinates that remain (`("r.p", "source.p")`, `("gear.a",
            /// "gear.ratio * load.phi")`), in the order they were eliminated.
            #vis const ELIMINATED: &'static [(&'static str, &'static str)] = &[#(#eliminated),*];
        }
    }
}

impl Flat {
    /// A primitive part: every name prefixed, its terms added.
    fn primitive(&mut self, cx: &Ctxt, part: &Part, field: &Ident) {
        let own = Ctxt::new();
        let (input, described_joints) = split_joints(&part.input);
        let model = crate::desugar::read(&own, &input);
        if own.has_errors() || model.incomplete {
            let _ = own.into_compile_errors();
            cx.error_spanned_by(field, format!("`reduce` cannot read the part `{}`", part.input.ident));
            return;
        }
        let unsupported = [
            (!model.laws.is_empty(), "laws (`friction`, `diode`, `switch`)"),
            (!model.unilaterals.is_empty(), "unilateral constraints"),
            (!model.events.is_empty(), "events"),
            (model.urdf.is_some(), "URDF robots"),
            (!model.switches.is_empty(), "contacts"),
        ];
        for (_, what) in unsupported.iter().filter(|(has, _)| *has) {
            cx.error_spanned_by(
                field,
                format!(
                    "`reduce` does not flatten {what} yet, and `{}` (the part `{}`) has them; \
                     remove `reduce` to interconnect it as it is",
                    part.input.ident,
                    strings(&part.prefix).join(".")
                ),
            );
        }
        let prefix = strings(&part.prefix);
        let mut map: HashMap<String, TokenStream> = HashMap::new();
        let mut name = |local: &str| -> String {
            let mut path = prefix.clone();
            path.push(local.to_owned());
            let flat = mangle(&path);
            let ident = format_ident!("{}", flat);
            map.insert(local.to_owned(), quote! { #ident });
            flat
        };
        let unraw = |i: &Ident| syn::ext::IdentExt::unraw(i).to_string();
        let params: Vec<String> = model.params.iter().map(|p| name(&unraw(p))).collect();
        let inputs: Vec<String> = model.inputs.iter().map(|u| name(&unraw(u))).collect();
        let coordinates: Vec<(String, String, bool)> = model
            .coordinates
            .iter()
            .map(|c| (name(&unraw(&c.name)), name(&unraw(&c.velocity)), model.ports.contains(&c.name)))
            .collect();
        // Rows by their names, the given ones or `holonomic0`, `constraint1`, … as outputs read them.
        let ordered = model.ordered_constraints();
        let rows: Vec<(ConstraintKind, String)> =
            ordered.iter().map(|c| (c.decl.kind, name(&c.name))).collect();
        let defines: Vec<String> = model.defines.iter().map(|d| name(&unraw(&d.name))).collect();
        let outputs: Vec<String> = model.outputs.iter().map(|o| name(&unraw(&o.name))).collect();
        let rename = |e: &Expr| rename(e.to_token_stream(), &map);

        for (flat, param) in params.into_iter().zip(&model.params) {
            // A reduced composite's field `l__l` is its part's `l.l`.
            let mut path = prefix.clone();
            path.extend(unraw(param).split("__").map(str::to_owned));
            self.params.push((flat, path));
        }
        self.inputs.extend(inputs);
        for (local, requirement) in &model.requirements {
            let mut path = prefix.clone();
            path.push(unraw(local));
            self.requirements.push((mangle(&path), *requirement));
        }
        for (q, v, port) in coordinates {
            self.coordinates.push(Coordinate { q, v, port });
        }
        // Also term by term, for the multipliers recovered: the balance of one coordinate then
        // reads only the terms that hold it (a nested reduced composite's Lagrangian is the sum
        // of all its parts'). The model is written with the parts' terms as they are, which the
        // simplifier combines best.
        let terms = |e: &Expr| {
            let mut terms = Vec::new();
            crate::lower::additive_terms(e, false, &mut terms);
            terms.into_iter().map(|(term, negated)| {
                let term = rename(&term);
                if negated {
                    quote! { -(#term) }
                } else {
                    term
                }
            })
        };
        if let Some((_, l)) = &model.lagrangian
            && !is_zero(l)
        {
            self.lagrangian.push(rename(l));
            let split: Vec<TokenStream> = terms(l).collect();
            self.lagrangian_terms.extend(split);
        }
        if let Some((_, r)) = &model.dissipation {
            self.dissipation.push(rename(r));
            let split: Vec<TokenStream> = terms(r).collect();
            self.dissipation_terms.extend(split);
            // Its power, an output of the part unreduced (of each of its parts, for a reduced
            // composite's description).
            let velocities: Vec<String> =
                model.coordinates.iter().map(|c| map[&unraw(&c.velocity)].to_string()).collect();
            let dotted =
                |local: &str| prefix.iter().map(String::as_str).chain([local]).collect::<Vec<_>>().join(".");
            if model.part_dissipations.is_empty() {
                self.dissipations.push((dotted(DISSIPATED_POWER), rename(r), velocities));
            } else {
                for (output, r) in &model.part_dissipations {
                    self.dissipations.push((dotted(output), rename(r), velocities.clone()));
                }
            }
        }
        for force in &model.forces {
            let key = map[&unraw(&force.coordinate)].to_string();
            self.forces.push((key, rename(&force.expr)));
        }
        for ((kind, row), c) in rows.into_iter().zip(&ordered) {
            let expr = rename(&c.decl.expr);
            let interconnection = model.interconnection_rows.contains(&c.name);
            self.rows.push(Row { kind, name: row, expr, position: None, interconnection });
        }
        for (flat, d) in defines.into_iter().zip(&model.defines) {
            self.defines.push((flat, rename(&d.expr)));
        }
        for (flat, o) in outputs.into_iter().zip(&model.outputs) {
            self.outputs.push((flat, rename(&o.expr)));
        }
        for (local, unit) in &model.units {
            if let Some(flat) = map.get(&unraw(local)) {
                self.units.push((flat.to_string(), unit.clone()));
            }
        }
        self.large |= model.large;
        // A reduced composite's joints, its bodies and points in its flat names.
        let in_flat_names = |t: TokenStream| super::rewrite::rename(t, &map);
        for joint in &described_joints {
            self.joints.push(FlatJoint::new(joint, &prefix, field.clone(), &in_flat_names));
        }
    }

    /// A composite: its own parameters, rows and connections, its parts' names by path.
    fn composite(&mut self, cx: &Ctxt, part: &Part) {
        let composite = Composite::from_input(cx, &part.input);
        if composite.incomplete {
            return;
        }
        if let Some(array) = composite.subsystems.iter().find(|s| s.array) {
            cx.error_spanned_by(
                &array.ident,
                "`reduce` does not flatten arrays of subsystems yet; remove `reduce` to interconnect them as they are",
            );
            return;
        }
        let prefix = strings(&part.prefix);
        let path_of = |dotted: &[String]| -> String {
            let mut path = prefix.clone();
            path.extend(dotted.iter().cloned());
            mangle(&path)
        };
        for param in &composite.params {
            let mut path = prefix.clone();
            path.push(syn::ext::IdentExt::unraw(param).to_string());
            self.params.push((mangle(&path), path));
        }
        for (i, c) in composite.connections.iter().enumerate() {
            let (a, b, key) = (path_of(&c.a.path), path_of(&c.b.path), c.key.clone());
            let name = path_of(&[format!("connect{i}")]);
            self.connections.push(Connection { a, b, key, name });
        }
        self.large |= composite.large;
    }

    /// A composite's own rows, their member paths read as the flat model's names.
    fn composite_rows(&mut self, cx: &Ctxt, part: &Part) {
        let own = Ctxt::new();
        let composite = Composite::from_input(&own, &part.input);
        let _ = own.into_compile_errors();
        if composite.incomplete || cx.has_errors() {
            return;
        }
        let prefix = strings(&part.prefix);
        // The rows' names read as the composite's: every name a path below it.
        let map: HashMap<String, TokenStream> = self
            .names()
            .into_iter()
            .filter_map(|flat| {
                let path: Vec<&str> = flat.split("__").collect();
                let below =
                    path.strip_prefix(prefix.iter().map(String::as_str).collect::<Vec<_>>().as_slice())?;
                let ident = format_ident!("{}", flat);
                Some((below.join("."), quote! { #ident }))
            })
            .collect();
        let rename_params = |t: TokenStream| rename(t, &map);
        for joint in &composite.joints {
            self.joints.push(FlatJoint::new(joint, &prefix, joint.key.clone(), &rename_params));
        }
        let written = &composite.holonomic[..composite.written_rows];
        let kinds =
            [(ConstraintKind::Holonomic, written), (ConstraintKind::Velocity, &composite.constraints[..])];
        for (kind, forms) in kinds {
            for (k, form) in forms.iter().enumerate() {
                let local =
                    form.name.as_ref().map_or_else(|| format!("{}{k}", form.key), ToString::to_string);
                let mut path = prefix.clone();
                path.push(local);
                self.rows.push(Row {
                    kind,
                    name: mangle(&path),
                    expr: rename(form.expr.to_token_stream(), &map),
                    position: None,
                    interconnection: true,
                });
            }
        }
    }

    /// The connections as the rows they are, `v_a − v_b = 0`, under the names the composite
    /// gives them (`connect0`, …).
    fn connections_as_rows(&mut self) {
        for Connection { a, b, name, .. } in std::mem::take(&mut self.connections) {
            let velocity =
                |q: &str| self.coordinates.iter().find(|c| c.q == q).map(|c| format_ident!("{}", c.v));
            let (Some(va), Some(vb)) = (velocity(&a), velocity(&b)) else { continue };
            self.rows.push(Row {
                kind: ConstraintKind::Velocity,
                name,
                expr: quote! { #va - #vb },
                position: None,
                interconnection: true,
            });
        }
    }

    /// Every name of the flat model so far.
    fn names(&self) -> Vec<String> {
        let mut names: Vec<String> = self.params.iter().map(|(p, _)| p.clone()).collect();
        names.extend(self.coordinates.iter().flat_map(|c| [c.q.clone(), c.v.clone()]));
        names.extend(self.rows.iter().map(|r| r.name.clone()));
        names.extend(self.defines.iter().map(|(d, _)| d.clone()));
        names.extend(self.outputs.iter().map(|(o, _)| o.clone()));
        names
    }

    /// Alias elimination: connections first, then the rows that are solvable at compile time.
    fn eliminate(&mut self, cx: &Ctxt) {
        // `subst` maps each eliminated coordinate and velocity to its expression in those left.
        let mut subst: HashMap<String, TokenStream> = HashMap::new();
        self.original = self.coordinates.clone();
        self.original_lagrangian = self.lagrangian_terms.clone();
        self.port_terms();
        self.joint_coordinates(cx, &mut subst);
        self.note_names_read();
        let positions: HashMap<String, TokenStream> = self
            .coordinates
            .iter()
            .map(|c| {
                let q = format_ident!("{}", c.q);
                (c.v.clone(), quote! { #q })
            })
            .collect();
        for k in 0..self.rows.len() {
            if self.rows[k].kind == ConstraintKind::Velocity && self.integrable(&self.rows[k].expr) {
                self.rows[k].position = Some(rename(self.rows[k].expr.clone(), &positions));
            }
        }
        let connections = std::mem::take(&mut self.connections);
        for (j, Connection { a, b, key, name }) in connections.iter().enumerate() {
            // A coordinate connected before stands for the one it was merged into.
            let (a, b) = (resolve(&subst, a.clone()), resolve(&subst, b.clone()));
            let (Some(ia), Some(ib)) = (self.coordinate(&a), self.coordinate(&b)) else {
                let missing = if self.coordinate(&a).is_none() { &a } else { &b };
                let joint = self.jointed.iter().find(|(body, _)| {
                    missing.strip_prefix(body.as_str()).is_some_and(|rest| rest.starts_with("__"))
                });
                let message = match joint {
                    Some((body, joint)) => format!(
                        "`{}` is not a coordinate of the reduced model: joint `{joint}` carries `{}` in its own \
                         coordinate under `reduce`; connect to the joint's coordinate, or leave `reduce` off \
                         to keep the body's",
                        missing.replace("__", "."),
                        body.replace("__", "."),
                        joint = joint.replace("__", "."),
                    ),
                    None => format!("`{}` is not a coordinate of the parts", missing.replace("__", ".")),
                };
                cx.error_spanned_by(key, message);
                continue;
            };
            if ia == ib {
                self.not_recovered(name);
                continue;
            }
            let (keep, drop) = if ia < ib { (ia, ib) } else { (ib, ia) };
            let pivot = if drop == ia { 1.0 } else { -1.0 };
            self.recover(&subst, name, (drop, pivot), None, &connections[j + 1..]);
            let terms = vec![(self.coordinates[keep].q.clone(), Coefficient::number(1.0))];
            self.substitute(&mut subst, drop, &terms, &Coefficient::number(0.0));
        }
        // Rows read by name (an output `i = -source`) need their multipliers: such a row is
        // solved only where the momentum balance of the coordinate it is solved for gives its
        // multiplier.
        let read: Vec<String> = self.read_names();
        loop {
            let mut progress = false;
            let mut k = 0;
            while k < self.rows.len() {
                let expr = rename(self.rows[k].expr.clone(), &subst);
                self.rows[k].expr = expr.clone();
                let position = self.rows[k].position.as_ref().map(|p| rename(p.clone(), &subst));
                self.rows[k].position.clone_from(&position);
                let solution = match &position {
                    Some(position) => self.solvable(position, ConstraintKind::Holonomic),
                    None => self.solvable(&expr, self.rows[k].kind),
                };
                let solution = match solution {
                    Solution::None => self.prescribed(&subst, k).unwrap_or(Solution::None),
                    solution => solution,
                };
                let (index, pivot) = match &solution {
                    Solution::For(index, _, _, pivot) | Solution::Prescribed(index, _, pivot) => {
                        (*index, *pivot)
                    }
                    Solution::Redundant => {
                        let name = self.rows.remove(k).name;
                        self.not_recovered(&name);
                        continue;
                    }
                    Solution::None => {
                        k += 1;
                        continue;
                    }
                };
                if read.contains(&self.rows[k].name) {
                    let Some(multiplier) = self.multiplier(&subst, k, index, pivot) else {
                        k += 1;
                        continue;
                    };
                    subst.insert(self.rows[k].name.clone(), multiplier);
                }
                let name = self.rows[k].name.clone();
                self.recover(&subst, &name, (index, pivot), Some(k), &[]);
                self.rows.remove(k);
                match solution {
                    Solution::For(_, others, constant, _) => {
                        self.substitute(&mut subst, index, &others, &constant)
                    }
                    Solution::Prescribed(_, value, _) => self.prescribe(&mut subst, index, value),
                    // Handled above.
                    Solution::Redundant | Solution::None => {}
                }
                progress = true;
            }
            if !progress {
                break;
            }
        }
        // Everything else in the coordinates that remain.
        let apply = |t: &mut TokenStream| *t = rename(t.clone(), &subst);
        self.lagrangian.iter_mut().for_each(apply);
        self.dissipation.iter_mut().for_each(apply);
        self.forces.iter_mut().for_each(|(_, f)| apply(f));
        self.rows.iter_mut().for_each(|r| apply(&mut r.expr));
        self.defines.iter_mut().for_each(|(_, d)| apply(d));
        self.outputs.iter_mut().for_each(|(_, o)| apply(o));
        self.recovered = self.recovered(&subst);
    }

    /// Whether a velocity row is linear in two velocities or more with constant coefficients
    /// and reads nothing else.
    fn integrable(&self, expr: &TokenStream) -> bool {
        let Ok(expr) = syn::parse2::<Expr>(expr.clone()) else { return false };
        let role = |name: &str| {
            if self.coordinates.iter().any(|c| c.v == name) {
                Role::Unknown
            } else if self.params.iter().any(|(p, _)| p == name) && !self.inputs.iter().any(|u| u == name) {
                Role::Constant
            } else {
                Role::Other
            }
        };
        affine(&expr, &role).is_some_and(|row| row.terms.len() >= 2 && row.constant.is_zero())
    }

    fn coordinate(&self, name: &str) -> Option<usize> {
        self.coordinates.iter().position(|c| c.q == name)
    }

    /// The names the parts' outputs, definitions and rows read.
    fn read_names(&self) -> Vec<String> {
        let mut read = Vec::new();
        let exprs = self
            .outputs
            .iter()
            .map(|(_, e)| e)
            .chain(self.defines.iter().map(|(_, e)| e))
            .chain(self.rows.iter().map(|r| &r.expr))
            .chain(self.forces.iter().map(|(_, e)| e))
            .chain(self.lagrangian.iter())
            .chain(self.dissipation.iter());
        for e in exprs {
            collect_idents(e.clone(), &mut read);
        }
        read
    }

    /// The coordinate a row can be solved for, with what it equals: a position row affine in
    /// the coordinates, or a homogeneous velocity row in two velocities or more, with constant
    /// coefficients, and a number for the coefficient of the one solved for.
    fn solvable(&self, expr: &TokenStream, kind: ConstraintKind) -> Solution {
        self.solve_row(expr, kind).unwrap_or(Solution::None)
    }

    fn solve_row(&self, expr: &TokenStream, kind: ConstraintKind) -> Option<Solution> {
        let expr: Expr = syn::parse2(expr.clone()).ok()?;
        let constants: Vec<&str> = self
            .params
            .iter()
            .map(|(p, _)| p.as_str())
            .filter(|p| !self.inputs.iter().any(|u| u == p))
            .collect();
        let holonomic = kind == ConstraintKind::Holonomic;
        let role = |name: &str| {
            let unknown = self.coordinates.iter().any(|c| if holonomic { c.q == name } else { c.v == name });
            if unknown {
                Role::Unknown
            } else if constants.contains(&name) {
                Role::Constant
            } else {
                Role::Other
            }
        };
        let row = affine(&expr, &role)?;
        // A row its eliminations have emptied (two grounds joined) says nothing more.
        if row.terms.is_empty() && row.constant.is_zero() {
            return Some(Solution::Redundant);
        }
        if !holonomic && (row.terms.len() < 2 || !row.constant.is_zero()) {
            return None;
        }
        // The last unknown with a number for coefficient: later parts hang on earlier ones.
        let (x, pivot) = row.terms.iter().rev().find(|(_, c)| c.value.is_some_and(|v| v != 0.0))?;
        let pivot = pivot.value?;
        let index = self.coordinates.iter().position(|c| if holonomic { c.q == *x } else { c.v == *x })?;
        let (others, constant) = solve(&row, x)?;
        // Coordinates, not velocities, name the terms from here on.
        let others = others
            .into_iter()
            .map(|(n, k)| {
                let q = self.coordinates.iter().find(|c| c.q == n || c.v == n).map(|c| c.q.clone());
                (q.unwrap_or(n), k)
            })
            .collect();
        Some(Solution::For(index, others, constant, pivot))
    }

    /// A velocity row that prescribes one coordinate's velocity, `a v_x = u(t)` with `a` a
    /// number and `u` read from parameters, inputs, time and definitions of those alone (a
    /// voltage source's node, a speed source's flange), where nothing reads `x` itself, `L`
    /// does not read `v_x` and no other row reaches it: `x` leaves the model, and `v_x` is `u/a`
    /// wherever it is read. The index of `x`, what `v_x` equals, and `a`.
    fn prescribed(&self, subst: &HashMap<String, TokenStream>, k: usize) -> Option<Solution> {
        let row = &self.rows[k];
        if row.kind != ConstraintKind::Velocity {
            return None;
        }
        let state = |name: &str| {
            self.coordinates.iter().any(|c| c.q == name || c.v == name)
                || self.rows.iter().any(|r| r.name == name)
                || self.outputs.iter().any(|(o, _)| o == name)
        };
        // A definition is known without the state if it reads none of it, nor another
        // definition.
        let known = |name: &str| {
            self.defines.iter().find(|(d, _)| d == name).is_some_and(|(_, e)| {
                let mut names = Vec::new();
                collect_idents(rename(e.clone(), subst), &mut names);
                !names.iter().any(|n| state(n) || self.defines.iter().any(|(d, _)| d == n))
            })
        };
        let role = |name: &str| {
            if self.coordinates.iter().any(|c| c.v == name) {
                Role::Unknown
            } else if name == "t" || self.params.iter().any(|(p, _)| p == name) || known(name) {
                Role::Constant
            } else {
                Role::Other
            }
        };
        let affine = affine(&syn::parse2::<Expr>(row.expr.clone()).ok()?, &role)?;
        let [(x, pivot)] = affine.terms.as_slice() else { return None };
        let pivot = pivot.value.filter(|p| *p != 0.0 && p.is_finite())?;
        let index = self.coordinates.iter().position(|c| c.v == *x)?;
        let (_, value) = solve(&affine, x)?;
        let Coordinate { q, v, .. } = &self.coordinates[index];
        let reads = |t: &TokenStream, name: &str| {
            let mut names = Vec::new();
            collect_idents(rename(t.clone(), subst), &mut names);
            names.iter().any(|n| n == name)
        };
        let mut everything = self
            .lagrangian
            .iter()
            .chain(&self.dissipation)
            .chain(self.forces.iter().map(|(_, f)| f))
            .chain(self.rows.iter().map(|r| &r.expr))
            .chain(self.defines.iter().map(|(_, d)| d))
            .chain(self.outputs.iter().map(|(_, o)| o));
        if everything.any(|e| reads(e, q)) || self.lagrangian.iter().any(|l| reads(l, v)) {
            return None;
        }
        let reached =
            self.rows.iter().enumerate().any(|(j, r)| j != k && (reads(&r.expr, v) || reads(&r.expr, q)));
        (!reached).then_some(Solution::Prescribed(index, value.tokens, pivot))
    }

    /// Removes coordinate `index`, whose velocity is `value` and whose position nothing reads;
    /// its forces do no work on a prescribed motion.
    fn prescribe(&mut self, subst: &mut HashMap<String, TokenStream>, index: usize, value: TokenStream) {
        let gone = self.coordinates.remove(index);
        self.eliminated.push(Elimination { name: gone.q.clone(), by: format!("∫ {value} dt") });
        // Its acceleration, for the multipliers recovered: the rate of a function of time and
        // parameters; an input's or a definition's is not known here.
        let mut read = Vec::new();
        collect_idents(value.clone(), &mut read);
        let opaque = read.iter().any(|n| self.inputs.contains(n) || self.defines.iter().any(|(d, _)| d == n));
        let rate =
            (!opaque).then(|| syn::parse2::<Expr>(value.clone()).ok().and_then(|e| derivative(&e, "t")));
        let rate = rate.flatten().map_or_else(|| quote! { __unknown }, D::into_tokens);
        let new: HashMap<String, TokenStream> =
            [(gone.v.clone(), value), (recover::acceleration(&gone.v), rate)].into();
        self.note_substitution(&new);
        for existing in subst.values_mut() {
            *existing = rename(existing.clone(), &new);
        }
        subst.extend(new);
        self.forces.retain(|(on, _)| *on != gone.q);
    }

    /// The multiplier of row `k`, about to be solved for coordinate `index` (its coefficient
    /// `pivot`), from that coordinate's momentum balance `0 = ∂L/∂x + F_x − ∂R/∂v_x + pivot λ`:
    /// only where `x` has no inertia (`L` does not read `v_x`), no other row reaches it, and
    /// the derivatives are taken here.
    fn multiplier(
        &self,
        subst: &HashMap<String, TokenStream>,
        k: usize,
        index: usize,
        pivot: f64,
    ) -> Option<TokenStream> {
        let Coordinate { q, v, .. } = &self.coordinates[index];
        let now = |t: &TokenStream| -> Option<Expr> { syn::parse2(rename(t.clone(), subst)).ok() };
        let reads = |t: &TokenStream, name: &str| {
            let mut names = Vec::new();
            collect_idents(rename(t.clone(), subst), &mut names);
            names.iter().any(|n| n == name)
        };
        if self.lagrangian.iter().any(|l| reads(l, v)) {
            return None;
        }
        let reached = self.rows.iter().enumerate().filter(|(j, _)| *j != k).any(|(_, row)| match row.kind {
            ConstraintKind::Velocity => reads(&row.expr, v),
            ConstraintKind::Holonomic => reads(&row.expr, q),
        });
        if reached {
            return None;
        }
        let mut balance = D::Zero;
        for l in &self.lagrangian {
            balance = balance.plus(derivative(&now(l)?, q)?);
        }
        for (_, f) in self.forces.iter().filter(|(on, _)| on == q) {
            balance = balance.plus(D::Of(rename(f.clone(), subst)));
        }
        for r in &self.dissipation {
            balance = balance.plus(derivative(&now(r)?, v)?.negated());
        }
        let balance = balance.into_tokens();
        let scale = super::affine::float(-1.0 / pivot);
        Some(quote! { (#scale) * (#balance) })
    }

    /// Eliminates coordinate `index`: `q = Σ kⱼ qⱼ + k₀`, `v = Σ kⱼ vⱼ`; its forces act on the
    /// `qⱼ` scaled by `kⱼ`.
    fn substitute(
        &mut self,
        subst: &mut HashMap<String, TokenStream>,
        index: usize,
        terms: &[(String, Coefficient)],
        constant: &Coefficient,
    ) {
        let gone = self.coordinates.remove(index);
        let velocity = |q: &str| self.coordinates.iter().find(|c| c.q == q).map(|c| c.v.clone());
        let combine = |names: &dyn Fn(&str) -> String, with_constant: bool| -> TokenStream {
            let mut parts: Vec<TokenStream> = terms
                .iter()
                .map(|(n, k)| {
                    let ident = format_ident!("{}", names(n));
                    match k.value {
                        Some(1.0) => quote! { #ident },
                        _ => {
                            let k = &k.tokens;
                            quote! { (#k) * #ident }
                        }
                    }
                })
                .collect();
            if with_constant && !constant.is_zero() {
                parts.push(constant.tokens.clone());
            }
            if parts.is_empty() {
                quote! { 0.0 }
            } else {
                quote! { #(#parts)+* }
            }
        };
        let q = combine(&|n| n.to_owned(), true);
        let v = combine(&|n| velocity(n).unwrap_or_else(|| n.to_owned()), false);
        let a = combine(&|n| recover::acceleration(&velocity(n).unwrap_or_else(|| n.to_owned())), false);
        let by = if q.to_string() == "0.0" { "0".to_owned() } else { q.to_string() };
        self.eliminated.push(Elimination { name: gone.q.clone(), by });
        if gone.port {
            for (n, _) in terms {
                if let Some(c) = self.coordinates.iter_mut().find(|c| c.q == *n) {
                    c.port = true;
                }
            }
        }
        let mut new = HashMap::new();
        new.insert(gone.q.clone(), q);
        new.insert(recover::acceleration(&gone.v), a);
        new.insert(gone.v.clone(), v);
        self.note_substitution(&new);
        for value in subst.values_mut() {
            *value = rename(value.clone(), &new);
        }
        subst.extend(new);
        // Virtual work: F δq = F Σ kⱼ δqⱼ.
        let mut moved = Vec::new();
        for (_, force) in self.forces.iter().filter(|(t, _)| *t == gone.q) {
            for (n, k) in terms {
                let k = &k.tokens;
                moved.push((n.clone(), quote! { (#k) * (#force) }));
            }
        }
        self.forces.retain(|(t, _)| *t != gone.q);
        self.forces.extend(moved);
    }

    /// The flat model as a derive input of `LagrangeDirac`, under the composite's name.
    fn input(&self, composite: &DeriveInput) -> TokenStream {
        let ident = |s: &str| Ident::new(s, Span::call_site());
        let mut attrs = Vec::new();
        let doc = crate::ast::doc_comment(&composite.attrs);
        if !doc.is_empty() {
            attrs.push(quote! { #[doc = #doc] });
        }
        let coordinates = self.coordinates.iter().map(|c| {
            let (q, v) = (ident(&c.q), ident(&c.v));
            quote! { #q => #v }
        });
        attrs.push(quote! { #[dirac(coordinates(#(#coordinates),*))] });
        let ports: Vec<Ident> = self.coordinates.iter().filter(|c| c.port).map(|c| ident(&c.q)).collect();
        if !ports.is_empty() {
            attrs.push(quote! { #[dirac(port(#(#ports),*))] });
        }
        if !self.inputs.is_empty() {
            let inputs = self.inputs.iter().map(|u| ident(u));
            attrs.push(quote! { #[dirac(input(#(#inputs),*))] });
        }
        let lagrangian = if self.lagrangian.is_empty() {
            quote! { 0.0 }
        } else {
            let terms = self.lagrangian.iter().map(|t| quote! { (#t) });
            quote! { #(#terms)+* }
        };
        attrs.push(quote! { #[dirac(lagrangian = #lagrangian)] });
        if !self.dissipation.is_empty() {
            let terms = self.dissipation.iter().map(|t| quote! { (#t) });
            attrs.push(quote! { #[dirac(dissipation = #(#terms)+*)] });
        }
        let mut on: Vec<(&str, Vec<&TokenStream>)> = Vec::new();
        for (q, f) in &self.forces {
            match on.iter_mut().find(|(n, _)| n == q) {
                Some((_, fs)) => fs.push(f),
                None => on.push((q, vec![f])),
            }
        }
        for (q, fs) in on {
            let q = ident(q);
            let fs = fs.iter().map(|f| quote! { (#f) });
            attrs.push(quote! { #[dirac(force(#q) = #(#fs)+*)] });
        }
        for row in &self.rows {
            let (name, expr) = (ident(&row.name), &row.expr);
            let key = match row.kind {
                ConstraintKind::Holonomic => quote! { holonomic },
                ConstraintKind::Velocity => quote! { constraint },
            };
            attrs.push(quote! { #[dirac(#key(#name) = #expr)] });
        }
        for joint in &self.joints {
            attrs.push(joint.attribute());
        }
        let interconnection = self.rows.iter().filter(|r| r.interconnection).map(|r| ident(&r.name));
        let interconnection: Vec<Ident> = interconnection.collect();
        if !interconnection.is_empty() {
            attrs.push(quote! { #[dirac(__interconnection(#(#interconnection),*))] });
        }
        for (output, r, _) in &self.dissipations {
            attrs.push(quote! { #[dirac(__dissipation(#output) = #r)] });
        }
        for (name, expr) in &self.defines {
            let name = ident(name);
            attrs.push(quote! { #[dirac(define(#name) = #expr)] });
        }
        for (name, expr) in &self.outputs {
            let name = ident(name);
            attrs.push(quote! { #[dirac(output(#name) = #expr)] });
        }
        for recover::Recovered { name, alias, value } in &self.recovered {
            let alias = alias.as_ref().map(|a| {
                let a = ident(a);
                quote! { , #a }
            });
            attrs.push(quote! { #[dirac(__recover(#name #alias) = #value)] });
        }
        for (name, requirement) in &self.requirements {
            let name = ident(name);
            let key = match requirement {
                Requirement::Positive => quote! { positive },
                Requirement::Nonnegative => quote! { nonnegative },
                Requirement::Nonzero => quote! { nonzero },
            };
            attrs.push(quote! { #[dirac(#key(#name))] });
        }
        let names = self.names();
        for (name, unit) in self.units.iter().filter(|(n, _)| names.contains(n) || self.inputs.contains(n)) {
            let name = ident(name);
            attrs.push(quote! { #[dirac(unit(#name) = #unit)] });
        }
        if self.large {
            attrs.push(quote! { #[dirac(large)] });
        }
        let (vis, name) = (&composite.vis, &composite.ident);
        let fields = self.params.iter().map(|(p, _)| ident(p));
        quote! {
            #(#attrs)*
            #vis struct #name { #(pub #fields: f64,)* }
        }
    }
}

fn is_zero(e: &Expr) -> bool {
    matches!(e, Expr::Lit(syn::ExprLit { lit: syn::Lit::Float(f), .. }) if f.base10_parse::<f64>().ok() == Some(0.0))
}

fn collect_idents(tokens: TokenStream, out: &mut Vec<String>) {
    for tree in tokens {
        match tree {
            proc_macro2::TokenTree::Ident(i) => out.push(i.to_string()),
            proc_macro2::TokenTree::Group(g) => collect_idents(g.stream(), out),
            _ => {}
        }
    }
}
