//! Joints between rigid bodies (DESIGN §5): `joint(th => w) = revolute(y, parent at [..],
//! child at [..])`, `prismatic(axis, ..)` and `fixed(parent at [..], child at [..])`.
//!
//! A body is any part with the coordinates of `dirac::components::bodies::RigidBody`: its
//! centre `(x, y, z)` in space and the entries `r11 … r33` of its rotation. A joint holds the
//! point `a_p` of the parent (in the parent's axes) on the point `a_c` of the child and, at
//! zero joint coordinate, the child's axes along the parent's:
//!
//! - revolute about the parent's axis `e_k`: `R_c = R_p A_k(θ)`, `x_c = x_p + R_p a_p − R_c a_c`;
//! - prismatic along `e_k`: `R_c = R_p`, `x_c = x_p + R_p (a_p + s e_k) − R_c a_c`;
//! - fixed: `R_c = R_p`, `x_c = x_p + R_p a_p − R_c a_c`.
//!
//! Without `reduce`, a joint is the holonomic rows that say so (a revolute's three rows of the
//! point and two of the axis; five for a prismatic, six for a fixed joint). With `reduce`, a
//! joint whose child has no other parent re-expresses the child in the joint's coordinate
//! (`reduce/flatten.rs`): its pose is [`Frame::child`] of its parent's, and only a joint that
//! closes a loop keeps its rows.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream};
use syn::{Expr, Ident, Token};

/// An entry of a pose while it is built: zero and one are kept apart so that products with
/// them vanish, and a planar mechanism's out-of-plane rows are recognised as zero.
#[derive(Clone, Debug)]
pub enum S {
    Zero,
    One,
    E(TokenStream),
}

impl S {
    pub fn tokens(&self) -> TokenStream {
        match self {
            S::Zero => quote! { 0.0 },
            S::One => quote! { 1.0 },
            S::E(t) => quote! { (#t) },
        }
    }

    pub fn is_zero(&self) -> bool {
        matches!(self, S::Zero)
    }

    fn from_expr(expr: &Expr) -> S {
        let literal = match expr {
            Expr::Lit(syn::ExprLit { lit: syn::Lit::Float(f), .. }) => f.base10_parse::<f64>().ok(),
            Expr::Lit(syn::ExprLit { lit: syn::Lit::Int(i), .. }) => i.base10_parse::<f64>().ok(),
            _ => None,
        };
        match literal {
            Some(0.0) => S::Zero,
            Some(1.0) => S::One,
            _ => S::E(quote! { #expr }),
        }
    }
}

fn mul(a: &S, b: &S) -> S {
    match (a, b) {
        (S::Zero, _) | (_, S::Zero) => S::Zero,
        (S::One, x) | (x, S::One) => x.clone(),
        (a, b) => {
            let (a, b) = (a.tokens(), b.tokens());
            S::E(quote! { #a * #b })
        }
    }
}

fn add(a: &S, b: &S) -> S {
    match (a, b) {
        (S::Zero, x) | (x, S::Zero) => x.clone(),
        (a, b) => {
            let (a, b) = (a.tokens(), b.tokens());
            S::E(quote! { #a + #b })
        }
    }
}

fn neg(a: &S) -> S {
    match a {
        S::Zero => S::Zero,
        a => {
            let a = a.tokens();
            S::E(quote! { -#a })
        }
    }
}

fn sub(a: &S, b: &S) -> S {
    add(a, &neg(b))
}

type V3 = [S; 3];
type M3 = [[S; 3]; 3];

fn mat_vec(m: &M3, v: &V3) -> V3 {
    std::array::from_fn(|i| (0..3).fold(S::Zero, |acc, k| add(&acc, &mul(&m[i][k], &v[k]))))
}

fn mat_mat(a: &M3, b: &M3) -> M3 {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..3).fold(S::Zero, |acc, k| add(&acc, &mul(&a[i][k], &b[k][j]))))
    })
}

fn vec_add(a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| add(&a[i], &b[i]))
}

fn vec_sub(a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| sub(&a[i], &b[i]))
}

fn dot(a: &V3, b: &V3) -> S {
    (0..3).fold(S::Zero, |acc, k| add(&acc, &mul(&a[k], &b[k])))
}

fn column(m: &M3, j: usize) -> V3 {
    std::array::from_fn(|i| m[i][j].clone())
}

fn zero3() -> V3 {
    [S::Zero, S::Zero, S::Zero]
}

fn zero33() -> M3 {
    [zero3(), zero3(), zero3()]
}

fn unit(k: usize) -> V3 {
    std::array::from_fn(|i| if i == k { S::One } else { S::Zero })
}

fn identity() -> M3 {
    std::array::from_fn(unit)
}

/// The rotation about axis `k` by the angle whose cosine and sine are `c`, `s`, and its
/// derivative in the angle.
fn rotation(k: usize, c: &S, s: &S) -> (M3, M3) {
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    let mut a = zero33();
    let mut da = zero33();
    a[k][k] = S::One;
    a[i][i] = c.clone();
    a[j][j] = c.clone();
    a[i][j] = neg(s);
    a[j][i] = s.clone();
    da[i][i] = neg(s);
    da[j][j] = neg(s);
    da[i][j] = neg(c);
    da[j][i] = c.clone();
    (a, da)
}

/// The kind of a joint, with its axis (0, 1, 2 for the parent's x, y, z).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Kind {
    Revolute(usize),
    Prismatic(usize),
    Fixed,
}

/// A body a joint names, with the point of it the joint holds (in its own axes).
pub struct End {
    /// The body's path below the composite; empty for `world`.
    pub path: Vec<String>,
    pub at: [Expr; 3],
}

/// `joint(th => w) = revolute(y, parent at [..], child at [..])`.
pub struct Joint {
    pub key: Ident,
    pub name: Ident,
    /// The joint's coordinate and velocity; none for a fixed joint.
    pub coordinate: Option<(Ident, Ident)>,
    pub kind: Kind,
    pub parent: End,
    pub child: End,
}

const COORDINATES: [&str; 12] =
    ["x", "y", "z", "r11", "r12", "r13", "r21", "r22", "r23", "r31", "r32", "r33"];

/// The coordinate names of a body, in the order of its pose: centre, then the rotation by rows.
pub fn body_coordinates() -> [&'static str; 12] {
    COORDINATES
}

/// The rows that hold `RᵀR = I` in a body.
pub const BODY_ROWS: [&str; 6] = ["unit1", "unit2", "unit3", "square12", "square13", "square23"];

/// A body's pose and, for each velocity it moves with, the derivative of the pose along it.
#[derive(Clone)]
pub struct Frame {
    pub x: V3,
    pub r: M3,
    /// `(coordinate, velocity, ∂x, ∂R)`: the pose's rate is `Σ (∂x, ∂R) · velocity`.
    pub partials: Vec<(String, String, V3, M3)>,
    /// Where the rotation is one turn about a fixed axis by a sum of joint angles (a chain of
    /// hinges about parallel axes, the world's identity with no axis and no angle): the
    /// axis and the angles, so that a hinge on it turns by the sum, `R_y(θ₁ + θ₂)`, as a
    /// person writes a planar chain, not by the product of the two rotations.
    turn: Option<(Option<usize>, Vec<String>)>,
}

impl Frame {
    pub fn world() -> Frame {
        Frame { x: zero3(), r: identity(), partials: Vec::new(), turn: Some((None, Vec::new())) }
    }

    /// A body's own pose: its twelve coordinates `name(c)` moving with their velocities
    /// `rate(c)`.
    pub fn own(
        name: &dyn Fn(&str) -> TokenStream,
        velocity: &dyn Fn(&str) -> Option<(String, String)>,
    ) -> Frame {
        let entry = |c: &str| S::E(name(c));
        let x = [entry("x"), entry("y"), entry("z")];
        let r = std::array::from_fn(|i| std::array::from_fn(|j| entry(&format!("r{}{}", i + 1, j + 1))));
        let mut partials = Vec::new();
        for (n, c) in COORDINATES.iter().enumerate() {
            let Some((q, v)) = velocity(c) else { continue };
            let (mut dx, mut dr) = (zero3(), zero33());
            if n < 3 {
                dx[n] = S::One;
            } else {
                dr[(n - 3) / 3][(n - 3) % 3] = S::One;
            }
            partials.push((q, v, dx, dr));
        }
        Frame { x, r, partials, turn: None }
    }

    /// The child's pose through `joint` from this, its parent's; `q`, `v` the joint's
    /// coordinate and velocity as the flat model names them.
    pub fn child(&self, kind: Kind, at_parent: &V3, at_child: &V3, qv: Option<(&str, &str)>) -> Frame {
        let coordinate = qv.map(|(q, _)| {
            let q = format_ident!("{}", q);
            quote! { #q }
        });
        // A hinge about the axis its parent already turns about: the child turns by the sum of
        // the angles, and its rotation's derivative along each of them is the same.
        let turn = match (kind, qv, &self.turn) {
            (Kind::Revolute(k), Some((q, _)), Some((axis, angles))) if axis.is_none_or(|a| a == k) => {
                let mut angles = angles.clone();
                angles.push(q.to_owned());
                Some((Some(k), angles))
            }
            (Kind::Revolute(_), _, _) => None,
            _ => self.turn.clone(),
        };
        let summed = match &turn {
            Some((Some(k), angles)) if matches!(kind, Kind::Revolute(_)) => {
                let angles: Vec<Ident> = angles.iter().map(|a| format_ident!("{}", a)).collect();
                let sum = if angles.len() == 1 {
                    quote! { #(#angles)* }
                } else {
                    quote! { (#(#angles)+*) }
                };
                Some(rotation(*k, &S::E(quote! { #sum.cos() }), &S::E(quote! { #sum.sin() })))
            }
            _ => None,
        };
        let (r, own_dr, own_dx) = match (kind, &coordinate, &summed) {
            (Kind::Revolute(_), Some(_), Some((a, da))) => {
                let dx = neg3(&mat_vec(da, at_child));
                (a.clone(), Some(da.clone()), Some(dx))
            }
            (Kind::Revolute(k), Some(q), None) => {
                let (c, s) = (S::E(quote! { #q.cos() }), S::E(quote! { #q.sin() }));
                let (a, da) = rotation(k, &c, &s);
                let dr = mat_mat(&self.r, &da);
                let dx = neg3(&mat_vec(&dr, at_child));
                (mat_mat(&self.r, &a), Some(dr), Some(dx))
            }
            (Kind::Prismatic(k), Some(_), _) => (self.r.clone(), Some(zero33()), Some(column(&self.r, k))),
            _ => (self.r.clone(), None, None),
        };
        // The point held on the parent, with the slide along the axis for a prismatic joint.
        let along = match (kind, &coordinate) {
            (Kind::Prismatic(k), Some(q)) => {
                let mut along = at_parent.clone();
                along[k] = add(&along[k], &S::E(q.clone()));
                along
            }
            _ => at_parent.clone(),
        };
        let x = vec_sub(&vec_add(&self.x, &mat_vec(&self.r, &along)), &mat_vec(&r, at_child));
        let mut partials = Vec::new();
        let angles = match &turn {
            Some((_, angles)) => angles.as_slice(),
            None => &[],
        };
        for (q, v, dx_p, dr_p) in &self.partials {
            let dr = match (kind, &summed) {
                (Kind::Revolute(_), Some((_, da))) if angles.contains(q) => da.clone(),
                (Kind::Revolute(_), Some(_)) => zero33(),
                (Kind::Revolute(k), None) => {
                    let theta = coordinate.clone().expect("a revolute joint has a coordinate");
                    let (a, _) = rotation(k, &S::E(quote! { #theta.cos() }), &S::E(quote! { #theta.sin() }));
                    mat_mat(dr_p, &a)
                }
                _ => dr_p.clone(),
            };
            let dx = vec_sub(&vec_add(dx_p, &mat_vec(dr_p, &along)), &mat_vec(&dr, at_child));
            partials.push((q.clone(), v.clone(), dx, dr));
        }
        if let (Some((q, v)), Some(dr), Some(dx)) = (qv, own_dr, own_dx) {
            partials.push((q.to_owned(), v.to_owned(), dx, dr));
        }
        Frame { x, r, partials, turn }
    }

    /// The pose's entry `n` (in [`body_coordinates`] order), its rate, and its derivative
    /// along each velocity.
    pub fn entry(&self, n: usize) -> S {
        if n < 3 { self.x[n].clone() } else { self.r[(n - 3) / 3][(n - 3) % 3].clone() }
    }

    pub fn partial(dx: &V3, dr: &M3, n: usize) -> S {
        if n < 3 { dx[n].clone() } else { dr[(n - 3) / 3][(n - 3) % 3].clone() }
    }

    pub fn rate(&self, n: usize) -> S {
        self.partials.iter().fold(S::Zero, |acc, (_, v, dx, dr)| {
            let v = format_ident!("{}", v);
            add(&acc, &mul(&Frame::partial(dx, dr, n), &S::E(quote! { #v })))
        })
    }
}

fn neg3(a: &V3) -> V3 {
    std::array::from_fn(|i| neg(&a[i]))
}

const AXES: [&str; 3] = ["x", "y", "z"];

/// The rows that hold a joint between the poses of its parent and child, each with its
/// suffix; the rows that are zero whatever the coordinates are left out.
pub fn rows(kind: Kind, parent: &Frame, at_parent: &V3, child: &Frame, at_child: &V3) -> Vec<(String, S)> {
    let gap = vec_sub(
        &vec_add(&parent.x, &mat_vec(&parent.r, at_parent)),
        &vec_add(&child.x, &mat_vec(&child.r, at_child)),
    );
    let turn = || {
        [(0, 1), (0, 2), (1, 2)].map(|(i, j)| {
            (format!("turn_{}{}", AXES[i], AXES[j]), dot(&column(&parent.r, i), &column(&child.r, j)))
        })
    };
    let mut rows: Vec<(String, S)> = Vec::new();
    match kind {
        Kind::Revolute(k) => {
            rows.extend((0..3).map(|i| (AXES[i].to_owned(), gap[i].clone())));
            for i in [(k + 1) % 3, (k + 2) % 3] {
                rows.push((format!("axis_{}", AXES[i]), dot(&column(&parent.r, k), &column(&child.r, i))));
            }
        }
        Kind::Prismatic(k) => {
            for i in [(k + 1) % 3, (k + 2) % 3] {
                rows.push((format!("across_{}", AXES[i]), dot(&gap, &column(&parent.r, i))));
            }
            rows.extend(turn());
        }
        Kind::Fixed => {
            rows.extend((0..3).map(|i| (AXES[i].to_owned(), gap[i].clone())));
            rows.extend(turn());
        }
    }
    rows.retain(|(_, s)| !s.is_zero());
    rows
}

/// The attachment point as entries.
pub fn point(at: &[Expr; 3], rename: &dyn Fn(TokenStream) -> TokenStream) -> V3 {
    std::array::from_fn(|i| match S::from_expr(&at[i]) {
        S::E(t) => S::E(rename(t)),
        s => s,
    })
}

/// The holonomic rows of a joint written with member paths, for a composite that is not
/// reduced: every body in its own coordinates.
pub fn member_rows(joint: &Joint) -> Vec<(Ident, Expr)> {
    let frame = |end: &End| -> Frame {
        if end.path.is_empty() {
            return Frame::world();
        }
        let path: Vec<Ident> = end.path.iter().map(|p| format_ident!("{}", p)).collect();
        Frame::own(
            &|c| {
                let c = format_ident!("{}", c);
                quote! { #(#path).* . #c }
            },
            &|_| None,
        )
    };
    let same = |t: TokenStream| t;
    let (at_parent, at_child) = (point(&joint.parent.at, &same), point(&joint.child.at, &same));
    rows(joint.kind, &frame(&joint.parent), &at_parent, &frame(&joint.child), &at_child)
        .into_iter()
        .filter_map(|(suffix, s)| {
            let name = format_ident!("{}_{}", joint.name, suffix, span = joint.name.span());
            let expr = syn::parse2(s.tokens()).ok()?;
            Some((name, expr))
        })
        .collect()
}

fn parse_axis(input: ParseStream) -> syn::Result<usize> {
    let axis = input.call(Ident::parse_any)?;
    AXES.iter().position(|a| axis == a).ok_or_else(|| {
        syn::Error::new(
            axis.span(),
            format!("a joint's axis is one of the parent's axes `x`, `y`, `z`, not `{axis}`"),
        )
    })
}

fn parse_end(input: ParseStream, world: bool) -> syn::Result<End> {
    let first = input.call(Ident::parse_any)?;
    let mut path = vec![first.unraw().to_string()];
    while input.peek(Token![.]) {
        input.parse::<Token![.]>()?;
        path.push(input.call(Ident::parse_any)?.unraw().to_string());
    }
    if path == ["world"] {
        if !world {
            return Err(syn::Error::new(first.span(), "`world` is a joint's parent, never its child"));
        }
        path.clear();
    }
    let zero: Expr = syn::parse_quote!(0.0);
    let mut at = [zero.clone(), zero.clone(), zero];
    if input.peek(Ident) && input.fork().call(Ident::parse_any).is_ok_and(|i| i == "at") {
        input.call(Ident::parse_any)?;
        let content;
        let bracket = syn::bracketed!(content in input);
        let entries = content.parse_terminated(Expr::parse, Token![,])?;
        if entries.len() != 3 {
            return Err(syn::Error::new(
                bracket.span.join(),
                "a joint's point is three numbers or parameters in the body's axes: `at [0.0, 0.0, a]`",
            ));
        }
        for (slot, e) in at.iter_mut().zip(entries) {
            *slot = e;
        }
    }
    Ok(End { path, at })
}

/// `joint(th => w) = revolute(y, world at [..], link at [..])`, after the key.
pub fn parse(key: Ident, input: ParseStream) -> syn::Result<Joint> {
    let content;
    syn::parenthesized!(content in input);
    let name = content.call(Ident::parse_any)?.unraw();
    let velocity = if content.peek(Token![=>]) {
        content.parse::<Token![=>]>()?;
        Some(content.call(Ident::parse_any)?.unraw())
    } else {
        None
    };
    if !content.is_empty() {
        return Err(
            content.error("expected `joint(coordinate => velocity)`, or `joint(name)` for a fixed joint")
        );
    }
    input.parse::<Token![=]>()?;
    let kind_ident = input.call(Ident::parse_any)?;
    let args;
    syn::parenthesized!(args in input);
    let kind = match kind_ident.to_string().as_str() {
        "revolute" | "prismatic" => {
            let axis = parse_axis(&args)?;
            args.parse::<Token![,]>()?;
            if kind_ident == "revolute" { Kind::Revolute(axis) } else { Kind::Prismatic(axis) }
        }
        "fixed" => Kind::Fixed,
        other => {
            return Err(syn::Error::new(
                kind_ident.span(),
                format!(
                    "unknown joint `{other}`; expected `revolute(axis, ..)`, `prismatic(axis, ..)` or `fixed(..)`"
                ),
            ));
        }
    };
    let parent = parse_end(&args, true)?;
    args.parse::<Token![,]>()?;
    let child = parse_end(&args, false)?;
    if !args.is_empty() {
        return Err(args
            .error("a joint names its parent and its child: `revolute(y, parent at [..], child at [..])`"));
    }
    let coordinate = match (kind, velocity) {
        (Kind::Fixed, None) => None,
        (Kind::Fixed, Some(v)) => {
            return Err(syn::Error::new(
                v.span(),
                "a fixed joint has no coordinate: write `joint(name) = fixed(..)`",
            ));
        }
        (_, Some(v)) => Some((name.clone(), v)),
        (_, None) => {
            return Err(syn::Error::new(
                name.span(),
                format!(
                    "a {kind_ident} joint has a coordinate and its velocity: `joint({name} => w_{name})`"
                ),
            ));
        }
    };
    Ok(Joint { key, name, coordinate, kind, parent, child })
}
