//! The parsed form of a `#[derive(Interconnection)]` composite.

use syn::ext::IdentExt;
use syn::parse::ParseStream;
use syn::{Data, DeriveInput, Expr, Fields, Ident, Token, Type, Visibility};

use super::joints::{self, Joint};
use crate::ast::is_f64;
use crate::ctxt::Ctxt;
use crate::lower::member_path;
use crate::symbol::{CONNECT, CONSTRAINT, DIRAC, HOLONOMIC, INTERCONNECTION_KEYS, JOINT, LARGE, REDUCE};

/// A composite as written by the user.
pub struct Composite<'a> {
    pub ident: &'a Ident,
    pub vis: &'a Visibility,
    /// `f64` fields: parameters of the interconnection constraints.
    pub params: Vec<Ident>,
    /// Every other field: the subsystems, in field order.
    pub subsystems: Vec<SubsystemField>,
    pub connections: Vec<Connection>,
    pub constraints: Vec<OneForm>,
    /// `holonomic(name) = expr`: position constraints between subsystems, `φ(q, t) = 0`.
    pub holonomic: Vec<OneForm>,
    /// `joint(th => w) = revolute(..)`: joints between rigid bodies. Their rows are also in
    /// `holonomic`, after the written ones, under names that start with the joint's.
    pub joints: Vec<Joint>,
    /// How many of `holonomic` were written as rows; the rest are the joints'.
    pub written_rows: usize,
    /// `large`: the composite may take more stack than the limit.
    pub large: bool,
    /// `reduce`: the composite is flattened into one model with its aliases eliminated.
    pub reduce: bool,
    /// Whether an attribute failed to parse (later stages then report nothing more).
    pub incomplete: bool,
    /// The struct's doc comment.
    pub doc: String,
    /// The doc comments of the `f64` fields that have one.
    pub param_docs: Vec<(Ident, String)>,
}

/// A field holding a subsystem, or an array of them.
pub struct SubsystemField {
    pub ident: Ident,
    /// The subsystem's type: the element type of an array.
    pub ty: Type,
    /// Whether the field is an array of subsystems (`Vec<Cell>` or `[Cell; N]`).
    pub array: bool,
}

impl Composite<'_> {
    /// Whether a field is an array of subsystems: such a composite is sized when it runs.
    pub fn has_arrays(&self) -> bool {
        self.subsystems.iter().any(|s| s.array)
    }
}

/// The element type of `Vec<T>` or `[T; N]`.
fn element_type(ty: &Type) -> Option<&Type> {
    match ty {
        Type::Array(a) => Some(&a.elem),
        Type::Path(p) if p.qself.is_none() => {
            let last = p.path.segments.last()?;
            let syn::PathArguments::AngleBracketed(args) = &last.arguments else {
                return None;
            };
            match (last.ident == "Vec", args.args.first(), args.args.len()) {
                (true, Some(syn::GenericArgument::Type(t)), 1) => Some(t),
                _ => None,
            }
        }
        _ => None,
    }
}

/// A subsystem member named by a dotted path: `left.x2`, `chain.right.x3`.
pub struct MemberPath {
    pub path: Vec<String>,
    pub expr: Expr,
}

impl MemberPath {
    pub fn dotted(&self) -> String {
        self.path.join(".")
    }
}

/// `connect(a.x, b.y)`.
pub struct Connection {
    pub key: Ident,
    pub a: MemberPath,
    pub b: MemberPath,
}

/// `constraint(name) = expr`: an interconnection one-form, linear in subsystem velocities.
pub struct OneForm {
    pub key: Ident,
    pub name: Option<Ident>,
    pub expr: Expr,
}

impl<'a> Composite<'a> {
    /// Parses the struct and its attributes, recording every error in `cx`.
    pub fn from_input(cx: &Ctxt, input: &'a DeriveInput) -> Composite<'a> {
        let mut composite = Composite {
            ident: &input.ident,
            vis: &input.vis,
            params: Vec::new(),
            subsystems: Vec::new(),
            connections: Vec::new(),
            constraints: Vec::new(),
            holonomic: Vec::new(),
            joints: Vec::new(),
            written_rows: 0,
            large: false,
            reduce: false,
            incomplete: false,
            doc: crate::ast::doc_comment(&input.attrs),
            param_docs: Vec::new(),
        };
        if !input.generics.params.is_empty() {
            cx.error_spanned_by(
                &input.generics,
                "an interconnection cannot be generic: name its subsystem types",
            );
        }
        composite.parse_fields(cx, input);
        for attr in input.attrs.iter().filter(|a| a.path().is_ident(DIRAC)) {
            let parser = |stream: ParseStream| parse_items(cx, &mut composite, stream);
            if let Err(e) = attr.parse_args_with(parser) {
                cx.syn_error(e);
                composite.incomplete = true;
            }
        }
        composite.written_rows = composite.holonomic.len();
        for joint in &composite.joints {
            for (name, expr) in joints::member_rows(joint) {
                composite.holonomic.push(OneForm { key: joint.key.clone(), name: Some(name), expr });
            }
        }
        composite
    }

    fn parse_fields(&mut self, cx: &Ctxt, input: &DeriveInput) {
        let Data::Struct(data) = &input.data else {
            cx.error_spanned_by(
                input.ident.clone(),
                "an interconnection must be a struct whose fields are subsystems",
            );
            return;
        };
        let Fields::Named(named) = &data.fields else {
            cx.error_spanned_by(&data.fields, "an interconnection needs named fields: one per subsystem");
            return;
        };
        for field in &named.named {
            let ident = field.ident.clone().expect("named fields have names");
            if is_f64(&field.ty) {
                let doc = crate::ast::doc_comment(&field.attrs);
                if !doc.is_empty() {
                    self.param_docs.push((ident.unraw(), doc));
                }
                self.params.push(ident);
            } else if let Some(elem) = element_type(&field.ty) {
                if let Some(name) = never_a_model(elem).or_else(|| is_f64(elem).then(|| "f64".to_owned())) {
                    cx.error_spanned_by(
                        elem,
                        format!(
                            "`{name}` is not a model: an array field of an interconnection holds subsystems \
                             (types that derive `LagrangeDirac` or `Interconnection`)"
                        ),
                    );
                } else {
                    if !cfg!(feature = "sparse") && !self.has_arrays() {
                        cx.error_spanned_by(
                            &field.ty,
                            format!(
                                "`{ident}` is an array of subsystems: a composite with one is sized when it runs \
                                 and stored sparse, which needs the feature `sparse` of dirac, off in this build; \
                                 turn it on in Cargo.toml: `dirac = {{ version = \"0.1\", features = [\"sparse\"] }}`"
                            ),
                        );
                    }
                    self.subsystems.push(SubsystemField { ident, ty: elem.clone(), array: true });
                }
            } else if let Some(name) = never_a_model(&field.ty) {
                cx.error_spanned_by(
                    &field.ty,
                    format!(
                        "`{name}` is not a model: the fields of an interconnection are subsystems (types that \
                         derive `LagrangeDirac` or `Interconnection`) and `f64` parameters"
                    ),
                );
            } else {
                self.subsystems.push(SubsystemField { ident, ty: field.ty.clone(), array: false });
            }
        }
        if self.subsystems.is_empty() {
            cx.error_spanned_by(
                input.ident.clone(),
                "an interconnection needs subsystems: fields whose types derive `LagrangeDirac` or `Interconnection`",
            );
        }
    }
}

/// Types that are certainly not models: primitives other than `f64` and common std containers.
fn never_a_model(ty: &Type) -> Option<String> {
    const NOT_MODELS: &[&str] = &[
        "f32", "i8", "i16", "i32", "i64", "i128", "isize", "u8", "u16", "u32", "u64", "u128", "usize",
        "bool", "char", "str", "String", "Vec", "Option", "Box", "HashMap", "BTreeMap",
    ];
    match ty {
        Type::Path(p) if p.qself.is_none() => {
            let last = p.path.segments.last()?.ident.to_string();
            NOT_MODELS.contains(&last.as_str()).then_some(last)
        }
        Type::Reference(_) | Type::Array(_) | Type::Slice(_) | Type::Tuple(_) | Type::Ptr(_) => {
            Some(quote::ToTokens::to_token_stream(ty).to_string())
        }
        _ => None,
    }
}

fn parse_items(cx: &Ctxt, composite: &mut Composite<'_>, input: ParseStream) -> syn::Result<()> {
    while !input.is_empty() {
        let key = input.call(Ident::parse_any)?;
        match key.to_string().as_str() {
            LARGE => composite.large = true,
            REDUCE => composite.reduce = true,
            CONNECT => {
                let content;
                syn::parenthesized!(content in input);
                let a = parse_member(&content)?;
                content.parse::<Token![,]>()?;
                let b = parse_member(&content)?;
                if !content.is_empty() {
                    return Err(content.error("`connect` joins two ports: `connect(a.x, b.y)`"));
                }
                composite.connections.push(Connection { key, a, b });
            }
            JOINT => composite.joints.push(joints::parse(key, input)?),
            CONSTRAINT | HOLONOMIC => {
                let holonomic = key == HOLONOMIC;
                let name = if input.peek(syn::token::Paren) {
                    let content;
                    syn::parenthesized!(content in input);
                    let name = content.parse::<Ident>()?.unraw();
                    if !content.is_empty() {
                        return Err(content.error(format!("expected one name: `{key}(name) = expr`")));
                    }
                    Some(name)
                } else {
                    None
                };
                input.parse::<Token![=]>()?;
                let expr: Expr = input.parse()?;
                let form = OneForm { key, name, expr };
                if holonomic {
                    composite.holonomic.push(form);
                } else {
                    composite.constraints.push(form);
                }
            }
            other => {
                let _ = cx;
                return Err(syn::Error::new(
                    key.span(),
                    format!(
                        "unknown interconnection attribute `{other}`; expected one of: {}",
                        INTERCONNECTION_KEYS.join(", ")
                    ),
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

fn parse_member(input: ParseStream) -> syn::Result<MemberPath> {
    let expr: Expr = input.parse()?;
    match member_path(&expr) {
        Some(path) if path.len() >= 2 => Ok(MemberPath { path, expr }),
        _ => Err(syn::Error::new_spanned(
            &expr,
            "expected a subsystem's port, such as `left.x2`, or an array element's, such as `cells[i + 1].left` \
             (an element is `i`, `i + k`, `i - k`, an integer `k`, `last` or `last - k`)",
        )),
    }
}
