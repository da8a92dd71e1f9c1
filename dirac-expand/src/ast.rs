//! The parsed form of a `#[derive(LagrangeDirac)]` model. Every item keeps the user's tokens,
//! so later stages can point errors at the exact identifier or term.

use syn::ext::IdentExt;
use syn::parse::ParseStream;
use syn::punctuated::Punctuated;
use syn::{Data, DeriveInput, Expr, Fields, Ident, Token, Type, Visibility};

use crate::ctxt::Ctxt;
use crate::law_decl::{self, LawDecl, LawKind};
use crate::symbol::{
    CONSTRAINT, COORDINATES, CROSSINGS, DEFINE, DIODE, DIRAC, DISSIPATION, EVENT, FLOATING, FORCE, FRICTION,
    GRAVITY, GROUND, HOLONOMIC, INPUT, JOINT_LIMITS, LAGRANGIAN, LARGE, MODEL_KEYS, NONNEGATIVE, NONZERO,
    OUTPUT, PORT, PORTS, POSITIVE, RESTITUTION, SWITCH, UNILATERAL, UNIT, URDF,
};

/// A model as written by the user.
pub struct Model<'a> {
    pub ident: &'a Ident,
    pub vis: &'a Visibility,
    /// The struct's `f64` fields.
    pub params: Vec<Ident>,
    pub coordinates: Vec<CoordinateDecl>,
    pub ports: Vec<Ident>,
    /// `input(u, ...)`: the `f64` fields that are inputs, in the order written.
    pub inputs: Vec<Ident>,
    /// The key `lagrangian` (for error spans) and the expression.
    pub lagrangian: Option<(Ident, Expr)>,
    pub constraints: Vec<ConstraintDecl>,
    pub forces: Vec<ForceDecl>,
    /// The key `dissipation` (for error spans) and the Rayleigh function `R(q, v, t)`.
    pub dissipation: Option<(Ident, Expr)>,
    /// `define(name) = expr`, in the order written.
    pub defines: Vec<DefineDecl>,
    /// `output(name) = expr`, in the order written.
    pub outputs: Vec<DefineDecl>,
    /// `__recover("name") = expr` or `__recover("name", alias) = expr`, written by `reduce`
    /// on the model it flattens: the series its eliminations took out of the state (an
    /// eliminated coordinate, a connection's multiplier, a port's effort) in the names of the
    /// model unreduced. Their expressions may also read the multipliers by row name, the
    /// accelerations as `__dt_` and a velocity, and the series before them by alias.
    pub recovered: Vec<(String, Option<Ident>, Expr)>,
    /// `__interconnection(row, ...)` and `__dissipation("r.dissipated_power") = R`, written by
    /// `reduce` in the description of a composite it flattens: which of its rows are the
    /// composite's (connections, its own rows) rather than its parts', and each part's
    /// Rayleigh function, so that a composite around it recovers their forces and powers.
    pub interconnection_rows: Vec<String>,
    pub part_dissipations: Vec<(String, Expr)>,
    /// `unilateral(name, restitution = e) = expr`, in the order written.
    pub unilaterals: Vec<UnilateralDecl>,
    /// `event(name, direction) = expr`, in the order written, then the events of the laws.
    pub events: Vec<EventDecl>,
    /// `friction(...)` and `diode(...)`, in the order written; each is also written into the
    /// coordinates, constraints, events and Lagrangian (the `laws` module's `desugar`).
    pub laws: Vec<LawDecl>,
    /// `__contacts(a, ...)`, written by the derive on the companion it makes of a model with
    /// unilateral constraints: the field that closes each contact, in their order.
    pub switches: Vec<Ident>,
    /// `positive(r, ...)`, `nonnegative(d, ...)` and `nonzero(k, ...)`: each parameter named
    /// with its requirement, in the order written.
    pub requirements: Vec<(Ident, Requirement)>,
    /// `large`: the model may take more stack than the limit.
    pub large: bool,
    /// The struct's doc comment.
    pub doc: String,
    /// The doc comments of the `f64` fields that have one.
    pub param_docs: Vec<(Ident, String)>,
    /// `unit(name, ...) = "text"`: each name with its unit, in the order written.
    pub units: Vec<(Ident, syn::LitStr)>,
    /// `urdf = "path"`: the robot file the model is read from.
    pub urdf: Option<syn::LitStr>,
    /// `joint_limits`: the URDF's joint limits as unilateral constraints (the key, for spans).
    pub joint_limits: Option<Ident>,
    /// `floating`: the URDF robot's root moves freely (the key, for spans).
    pub floating: Option<Ident>,
    /// `gravity = [gx, gy, gz]`: the URDF robot's gravity, with its key.
    pub gravity: Option<(Ident, Expr)>,
    /// `ground`, `ground(restitution = e, friction = mu)`: the URDF robot's collision shapes
    /// touch the ground.
    pub ground: Option<Ground>,
    /// The kinematic tree of a URDF robot fixed in the world, for the recursions of its
    /// joint-space dynamics.
    pub tree: Option<crate::urdf::tree::Tree>,
    /// `∂L/∂q` and `∂L/∂v` of the coordinates named, by the recursions of a URDF robot's tree
    /// (its composite momenta and weights): what the blocks differentiate in place of the
    /// Lagrangian's gradient, which they equal. Every other coordinate's come from the
    /// Lagrangian.
    pub gradients: Option<Vec<(String, Expr, Expr)>>,
    /// `LINKS` of `impl Shapes` for a URDF robot: its links as a view draws them.
    pub shapes: Option<proc_macro2::TokenStream>,
    /// Files the model was read from, which the expansion names so that Cargo rebuilds it when
    /// they change.
    pub tracked_files: Vec<String>,
    /// Whether an attribute failed to parse, so items may be missing: later stages then skip
    /// the rules that would only report consequences of the syntax error.
    pub incomplete: bool,
}

/// What a parameter's value must be, besides finite.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Requirement {
    /// `positive(r)`: greater than zero.
    Positive,
    /// `nonnegative(d)`: zero or more.
    Nonnegative,
    /// `nonzero(ratio)`: anything but zero.
    Nonzero,
}

impl Requirement {
    /// The requirement as the error names it.
    pub fn text(self) -> &'static str {
        match self {
            Requirement::Positive => "positive",
            Requirement::Nonnegative => "non-negative",
            Requirement::Nonzero => "nonzero",
        }
    }
}

/// `x => v`: a coordinate and the name of its velocity.
pub struct CoordinateDecl {
    pub name: Ident,
    pub velocity: Ident,
}

/// Whether a constraint is on positions or on velocities.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum ConstraintKind {
    /// `φ(q, t) = 0`; its row of `A` is `∂φ/∂q`, its rate `b` is `∂φ/∂t`.
    Holonomic,
    /// `A(q, t) v + b(q, t) = 0`, possibly nonholonomic.
    Velocity,
}

/// `constraint(name) = expr` or `holonomic(name) = expr`.
pub struct ConstraintDecl {
    pub kind: ConstraintKind,
    pub key: Ident,
    pub name: Option<Ident>,
    pub expr: Expr,
}

/// A constraint in the order of the rows of `A(q)` (holonomic first), with its name: the one
/// given, or `holonomic0`, `constraint1`, … by kind and position.
pub struct OrderedConstraint<'m> {
    pub decl: &'m ConstraintDecl,
    pub name: String,
    /// The tokens naming it (its name, or its key), for error spans and constants.
    pub ident: &'m Ident,
}

/// `define(name) = expr`: a named intermediate quantity.
pub struct DefineDecl {
    pub name: Ident,
    pub expr: Expr,
}

/// `unilateral(name) = expr` or `unilateral(name, restitution = e) = expr`: the contact
/// `φ(q, t) ≥ 0`.
pub struct UnilateralDecl {
    pub name: Ident,
    pub restitution: Option<Expr>,
    pub expr: Expr,
}

/// `event(name) = expr` or `event(name, falling | rising | either) = expr`.
pub struct EventDecl {
    pub name: Ident,
    /// −1 falling, 1 rising, 0 either (the default).
    pub direction: i8,
    pub expr: Expr,
}

/// `force(x) = expr`.
pub struct ForceDecl {
    pub coordinate: Ident,
    pub expr: Expr,
}

impl<'a> Model<'a> {
    /// Parses the struct and its `#[dirac(...)]` attributes, recording every error in `cx`.
    pub fn from_input(cx: &Ctxt, input: &'a DeriveInput) -> Model<'a> {
        let mut model = Model {
            ident: &input.ident,
            vis: &input.vis,
            params: Vec::new(),
            coordinates: Vec::new(),
            ports: Vec::new(),
            inputs: Vec::new(),
            outputs: Vec::new(),
            recovered: Vec::new(),
            interconnection_rows: Vec::new(),
            part_dissipations: Vec::new(),
            unilaterals: Vec::new(),
            events: Vec::new(),
            laws: Vec::new(),
            switches: Vec::new(),
            lagrangian: None,
            constraints: Vec::new(),
            forces: Vec::new(),
            dissipation: None,
            defines: Vec::new(),
            requirements: Vec::new(),
            large: false,
            doc: doc_comment(&input.attrs),
            param_docs: Vec::new(),
            units: Vec::new(),
            urdf: None,
            joint_limits: None,
            floating: None,
            gravity: None,
            ground: None,
            tree: None,
            gradients: None,
            shapes: None,
            tracked_files: Vec::new(),
            incomplete: false,
        };
        if !input.generics.params.is_empty() {
            cx.error_spanned_by(
                &input.generics,
                "a dirac model cannot be generic: its parameters are `f64` fields",
            );
        }
        model.params = parse_params(cx, input);
        if let Data::Struct(s) = &input.data {
            model.param_docs = s
                .fields
                .iter()
                .filter_map(|f| Some((f.ident.as_ref()?.unraw(), doc_comment(&f.attrs))))
                .filter(|(_, doc)| !doc.is_empty())
                .collect();
        }
        for attr in input.attrs.iter().filter(|a| a.path().is_ident(DIRAC)) {
            let parser = |stream: ParseStream| parse_items(cx, &mut model, stream);
            if let Err(e) = attr.parse_args_with(parser) {
                cx.syn_error(e);
                model.incomplete = true;
            }
        }
        model
    }
}

impl Model<'_> {
    /// The constraints in row order, holonomic rows first, each with its name.
    pub fn ordered_constraints(&self) -> Vec<OrderedConstraint<'_>> {
        let mut out = Vec::new();
        for kind in [ConstraintKind::Holonomic, ConstraintKind::Velocity] {
            for (k, decl) in self.constraints.iter().filter(|c| c.kind == kind).enumerate() {
                let name = decl.name.as_ref().map_or_else(|| format!("{}{k}", decl.key), ToString::to_string);
                out.push(OrderedConstraint { decl, name, ident: decl.name.as_ref().unwrap_or(&decl.key) });
            }
        }
        out
    }
}

/// The text of `///` comments (`#[doc = "..."]` attributes), lines joined by spaces.
pub fn doc_comment(attrs: &[syn::Attribute]) -> String {
    let lines = attrs.iter().filter_map(|a| match &a.meta {
        syn::Meta::NameValue(nv) if nv.path.is_ident("doc") => match &nv.value {
            Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(s), .. }) => Some(s.value().trim().to_string()),
            _ => None,
        },
        _ => None,
    });
    lines.filter(|l| !l.is_empty()).collect::<Vec<_>>().join(" ")
}

fn parse_params(cx: &Ctxt, input: &DeriveInput) -> Vec<Ident> {
    let fields = match &input.data {
        Data::Struct(s) => &s.fields,
        Data::Enum(e) => {
            cx.error_spanned_by(
                e.enum_token,
                "a dirac model must be a struct whose fields are `f64` parameters",
            );
            return Vec::new();
        }
        Data::Union(u) => {
            cx.error_spanned_by(
                u.union_token,
                "a dirac model must be a struct whose fields are `f64` parameters",
            );
            return Vec::new();
        }
    };
    match fields {
        Fields::Named(named) => named
            .named
            .iter()
            .filter_map(|f| {
                if !is_f64(&f.ty) {
                    cx.error_spanned_by(
                        &f.ty,
                        "model parameters must have type `f64`: every field of a dirac model is a parameter",
                    );
                }
                f.ident.clone()
            })
            .collect(),
        Fields::Unnamed(unnamed) => {
            cx.error_spanned_by(unnamed, "model parameters need names: use a struct with named `f64` fields");
            Vec::new()
        }
        Fields::Unit => Vec::new(),
    }
}

/// Whether a field's type is `f64` (a parameter), looking through groups and parentheses.
pub fn is_f64(ty: &Type) -> bool {
    match ty {
        Type::Path(p) => p.qself.is_none() && p.path.is_ident("f64"),
        Type::Group(g) => is_f64(&g.elem),
        Type::Paren(p) => is_f64(&p.elem),
        _ => false,
    }
}

/// Parses `key ..., key ..., ...` inside one `#[dirac(...)]`.
fn parse_items(cx: &Ctxt, model: &mut Model<'_>, input: ParseStream) -> syn::Result<()> {
    while !input.is_empty() {
        let key = input.call(Ident::parse_any)?;
        match key.to_string().as_str() {
            COORDINATES => parse_coordinates(model, input)?,
            PORT | PORTS => {
                let content;
                syn::parenthesized!(content in input);
                let names = Punctuated::<Ident, Token![,]>::parse_terminated(&content)?;
                model.ports.extend(names.iter().map(IdentExt::unraw));
            }
            LAGRANGIAN => {
                input.parse::<Token![=]>()?;
                let expr: Expr = input.parse()?;
                if model.lagrangian.is_some() {
                    cx.error_spanned_by(&key, "duplicate `lagrangian`: a model has one Lagrangian");
                } else {
                    model.lagrangian = Some((key, expr));
                }
            }
            DISSIPATION => {
                input.parse::<Token![=]>()?;
                let expr: Expr = input.parse()?;
                if model.dissipation.is_some() {
                    cx.error_spanned_by(
                        &key,
                        "duplicate `dissipation`: a model has one Rayleigh function; add the terms into one",
                    );
                } else {
                    model.dissipation = Some((key, expr));
                }
            }
            CONSTRAINT | HOLONOMIC => {
                let kind =
                    if key == HOLONOMIC { ConstraintKind::Holonomic } else { ConstraintKind::Velocity };
                let name = parse_optional_name(input)?;
                input.parse::<Token![=]>()?;
                let expr: Expr = input.parse()?;
                model.constraints.push(ConstraintDecl { kind, key, name, expr });
            }
            INPUT => {
                let content;
                syn::parenthesized!(content in input);
                let names = Punctuated::<Ident, Token![,]>::parse_terminated(&content)?;
                model.inputs.extend(names.iter().map(IdentExt::unraw));
            }
            LARGE => model.large = true,
            JOINT_LIMITS => model.joint_limits = Some(key.clone()),
            FLOATING => model.floating = Some(key.clone()),
            GROUND => {
                let ground = parse_ground(input, key.clone())?;
                if model.ground.is_some() {
                    cx.error_spanned_by(&key, "duplicate `ground`: a robot touches one");
                } else {
                    model.ground = Some(ground);
                }
            }
            GRAVITY => {
                input.parse::<Token![=]>()?;
                let expr: Expr = input.parse()?;
                if model.gravity.is_some() {
                    cx.error_spanned_by(&key, "duplicate `gravity`: a robot has one");
                } else {
                    model.gravity = Some((key, expr));
                }
            }
            URDF => {
                input.parse::<Token![=]>()?;
                let path: syn::LitStr = input.parse()?;
                if model.urdf.is_some() {
                    cx.error_spanned_by(&key, "duplicate `urdf`: a model is read from one robot file");
                } else {
                    model.urdf = Some(path);
                }
            }
            POSITIVE | NONNEGATIVE | NONZERO => {
                let requirement = match key.to_string().as_str() {
                    POSITIVE => Requirement::Positive,
                    NONNEGATIVE => Requirement::Nonnegative,
                    _ => Requirement::Nonzero,
                };
                let content;
                syn::parenthesized!(content in input);
                let names = Punctuated::<Ident, Token![,]>::parse_terminated(&content)?;
                model.requirements.extend(names.iter().map(|n| (n.unraw(), requirement)));
            }
            DEFINE | OUTPUT => {
                let content;
                syn::parenthesized!(content in input);
                let name = content.parse::<Ident>()?.unraw();
                if !content.is_empty() {
                    return Err(content.error(format!("expected one name: `{key}(name) = expr`")));
                }
                input.parse::<Token![=]>()?;
                let expr: Expr = input.parse()?;
                let list = if key == DEFINE { &mut model.defines } else { &mut model.outputs };
                list.push(DefineDecl { name, expr });
            }
            UNILATERAL => model.unilaterals.push(parse_unilateral(input)?),
            UNIT => {
                let content;
                syn::parenthesized!(content in input);
                let names = Punctuated::<Ident, Token![,]>::parse_terminated(&content)?;
                input.parse::<Token![=]>()?;
                let unit: syn::LitStr = input.parse()?;
                if unit.value().trim().is_empty() {
                    return Err(syn::Error::new(
                        unit.span(),
                        "a unit cannot be empty: write `unit(x) = \"m\"`",
                    ));
                }
                model.units.extend(names.iter().map(|n| (n.unraw(), unit.clone())));
            }
            EVENT => model.events.push(parse_event(input)?),
            FRICTION => model.laws.push(law_decl::parse(LawKind::Friction, input)?),
            DIODE => model.laws.push(law_decl::parse(LawKind::Diode, input)?),
            SWITCH => model.laws.push(law_decl::parse(LawKind::Switch, input)?),
            "__interconnection" => {
                let content;
                syn::parenthesized!(content in input);
                let names = Punctuated::<Ident, Token![,]>::parse_terminated(&content)?;
                model.interconnection_rows.extend(names.iter().map(|n| n.unraw().to_string()));
            }
            "__dissipation" => {
                let content;
                syn::parenthesized!(content in input);
                let name: syn::LitStr = content.parse()?;
                input.parse::<Token![=]>()?;
                model.part_dissipations.push((name.value(), input.parse()?));
            }
            "__recover" => {
                let content;
                syn::parenthesized!(content in input);
                let name: syn::LitStr = content.parse()?;
                let alias = if content.parse::<Option<Token![,]>>()?.is_some() {
                    Some(content.parse()?)
                } else {
                    None
                };
                input.parse::<Token![=]>()?;
                model.recovered.push((name.value(), alias, input.parse()?));
            }
            "__contacts" => {
                let content;
                syn::parenthesized!(content in input);
                let names = Punctuated::<Ident, Token![,]>::parse_terminated(&content)?;
                model.switches.extend(names.iter().map(IdentExt::unraw));
            }
            FORCE => {
                let content;
                syn::parenthesized!(content in input);
                let coordinate = content.parse::<Ident>()?.unraw();
                if !content.is_empty() {
                    return Err(content.error("expected one coordinate: `force(x) = expr`"));
                }
                input.parse::<Token![=]>()?;
                let expr: Expr = input.parse()?;
                model.forces.push(ForceDecl { coordinate, expr });
            }
            other => {
                return Err(syn::Error::new(
                    key.span(),
                    format!("unknown dirac attribute `{other}`; expected one of: {}", MODEL_KEYS.join(", ")),
                ));
            }
        }
        if input.is_empty() {
            break;
        }
        input.parse::<Token![,]>()?;
    }
    Ok(())
}

fn parse_coordinates(model: &mut Model<'_>, input: ParseStream) -> syn::Result<()> {
    let content;
    let paren = syn::parenthesized!(content in input);
    let decls = Punctuated::<CoordinateDecl, Token![,]>::parse_terminated_with(&content, |s| {
        let name = s.parse::<Ident>()?.unraw();
        let velocity = if s.peek(Token![=>]) {
            s.parse::<Token![=>]>()?;
            s.parse::<Ident>()?.unraw()
        } else {
            Ident::new(&format!("v_{name}"), name.span())
        };
        Ok(CoordinateDecl { name, velocity })
    })?;
    if decls.is_empty() {
        return Err(syn::Error::new(
            paren.span.join(),
            "`coordinates()` is empty: write `coordinates(x => v, ...)`",
        ));
    }
    model.coordinates.extend(decls);
    Ok(())
}

/// `(name) = expr` or `(name, direction) = expr`, after `event`.
fn parse_event(input: ParseStream) -> syn::Result<EventDecl> {
    let content;
    syn::parenthesized!(content in input);
    let name = content.parse::<Ident>()?.unraw();
    let mut direction = 0;
    if !content.is_empty() {
        content.parse::<Token![,]>()?;
        let key = content.call(Ident::parse_any)?;
        direction = match key.to_string().as_str() {
            "falling" => -1,
            "rising" => 1,
            "either" => 0,
            other => {
                return Err(syn::Error::new(
                    key.span(),
                    format!(
                        "unknown direction `{other}` of an event; expected one of: {}",
                        CROSSINGS.join(", ")
                    ),
                ));
            }
        };
        if !content.is_empty() {
            return Err(content.error(format!("expected `{EVENT}(name, falling) = expr`")));
        }
    }
    input.parse::<Token![=]>()?;
    let expr: Expr = input.parse()?;
    Ok(EventDecl { name, direction, expr })
}

/// `ground`, `ground(restitution = e, friction = mu)`.
pub struct Ground {
    /// The key, for spans.
    pub key: Ident,
    /// The restitution of the impacts on it (0 unless given).
    pub restitution: Option<Expr>,
    /// The coefficient of Coulomb's friction cone at each point that rests on it (none unless
    /// given).
    pub friction: Option<Expr>,
    /// `links = ["foot", …]`: the links whose collision shapes touch it (all unless given).
    pub links: Option<Expr>,
}

/// `(restitution = e, friction = mu, links = [...])` (each optional, in any order) after
/// `ground`, if there is one.
fn parse_ground(input: ParseStream, key: Ident) -> syn::Result<Ground> {
    let mut ground = Ground { key, restitution: None, friction: None, links: None };
    if !input.peek(syn::token::Paren) {
        return Ok(ground);
    }
    let content;
    syn::parenthesized!(content in input);
    while !content.is_empty() {
        let option = content.call(Ident::parse_any)?;
        let slot = match option.to_string().as_str() {
            RESTITUTION => &mut ground.restitution,
            FRICTION => &mut ground.friction,
            "links" => &mut ground.links,
            _ => {
                return Err(syn::Error::new(
                    option.span(),
                    format!(
                        "unknown option `{option}` of `{GROUND}`; expected `{RESTITUTION} = e` (of its impacts), \
                         `{FRICTION} = mu` (Coulomb's coefficient where a point rests on it) or \
                         `links = [\"foot\", …]` (the links that touch it, all unless given)"
                    ),
                ));
            }
        };
        if slot.is_some() {
            return Err(syn::Error::new(option.span(), format!("`{option}` given twice")));
        }
        content.parse::<Token![=]>()?;
        *slot = Some(content.parse::<Expr>()?);
        if !content.is_empty() {
            content.parse::<Token![,]>()?;
        }
    }
    Ok(ground)
}

fn parse_unilateral(input: ParseStream) -> syn::Result<UnilateralDecl> {
    let content;
    syn::parenthesized!(content in input);
    let name = content.parse::<Ident>()?.unraw();
    let mut restitution = None;
    if !content.is_empty() {
        content.parse::<Token![,]>()?;
        let key = content.call(Ident::parse_any)?;
        if key != RESTITUTION {
            return Err(syn::Error::new(
                key.span(),
                format!("unknown option `{key}` of a unilateral constraint; expected `{RESTITUTION} = e`"),
            ));
        }
        content.parse::<Token![=]>()?;
        restitution = Some(content.parse::<Expr>()?);
        if !content.is_empty() {
            return Err(content.error(format!("expected `{UNILATERAL}(name, {RESTITUTION} = e) = expr`")));
        }
    }
    input.parse::<Token![=]>()?;
    let expr: Expr = input.parse()?;
    Ok(UnilateralDecl { name, restitution, expr })
}

fn parse_optional_name(input: ParseStream) -> syn::Result<Option<Ident>> {
    if !input.peek(syn::token::Paren) {
        return Ok(None);
    }
    let content;
    syn::parenthesized!(content in input);
    let name = content.parse::<Ident>()?.unraw();
    if !content.is_empty() {
        return Err(content.error("expected one name: `constraint(name) = expr`"));
    }
    Ok(Some(name))
}
