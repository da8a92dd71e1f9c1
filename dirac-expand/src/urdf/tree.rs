//! The joint-space dynamics of a robot fixed in the world, written out as straight-line code
//! from its kinematic tree: the composite rigid body recursion for the mass matrix and the
//! recursive Newton-Euler one for the gravity and bias torques (Featherstone, *Rigid Body
//! Dynamics Algorithms*, 2008, §6.2 and §5.3), in each link's own axes.
//!
//! A spatial quantity is a pair of 3-vectors: a motion `(ω, v)` (angular velocity, velocity of
//! the point at the link's origin), a force `(n, f)` (moment about the origin, force), an inertia
//! `(m, h, I)` (mass, first moment `m c`, rotational inertia about the origin). Joint `k` moves
//! link `k + 1` from its parent `p` by the rotation `R = E Rot(a, q)` (the child's axes in the
//! parent's) and the offset `d` of the child's origin (`xyz`, plus `a q` along a slide):
//!
//! ```text
//! motion to the child:  ω' = Rᵀ ω,  v' = Rᵀ (v + ω × d)
//! force to the parent:  f' = R f,   n' = R n + d × f'
//! inertia to the parent: h' = R h + m d,
//!                        I' = R I Rᵀ + m (|d|² 1 − d dᵀ) + 2 (d·R h) 1 − d (R h)ᵀ − (R h) dᵀ
//! ```
//!
//! The links' inertias, frames and axes are numbers when the model compiles, so every product
//! with a zero or a one folds away ([`Poly`]) and each step is bound to a local, as the
//! Lagrangian's definitions are. Gravity is the base's acceleration `−g`, so the same pass gives
//! `g(q)` (at `v = 0`) and `b(q, v)`.

use proc_macro2::TokenStream;
use quote::quote;
use syn::Expr;

use super::poly::{Atom, Poly};
use super::read::{Kind, Mat3, Robot};
use crate::ast::Model;
use crate::codegen::signatures::rt;

/// What the recursions need of a robot: its joints and links as numbers, its joints'
/// coordinates by name, and its gravity when the model gives it.
pub struct Tree {
    joints: Vec<Joint>,
    /// Link `l`'s mass, first moment `m c` and rotational inertia about its origin.
    links: Vec<Body>,
    /// `gravity = [gx, gy, gz]` as written; `(0, 0, −9.81)` otherwise.
    gravity: Option<[Expr; 3]>,
}

struct Joint {
    moves: bool,
    prismatic: bool,
    parent: usize,
    xyz: [f64; 3],
    rotation: Mat3,
    axis: [f64; 3],
    coordinate: String,
}

#[derive(Clone)]
struct Body {
    mass: f64,
    first: [f64; 3],
    inertia: Mat3,
}

impl Tree {
    /// The tree of `robot`, whose joints' coordinates are named `joints`; `None` for a robot
    /// with a floating joint (its embedded rotation is not a joint of the recursions).
    pub fn of(robot: &Robot, joints: &[String], gravity: Option<[Expr; 3]>) -> Option<Tree> {
        if robot.joints.iter().any(|j| matches!(j.kind, Kind::Floating | Kind::Planar)) {
            return None;
        }
        let joints = robot
            .joints
            .iter()
            .zip(joints)
            .map(|(j, name)| Joint {
                moves: matches!(j.kind, Kind::Revolute | Kind::Prismatic),
                prismatic: j.kind == Kind::Prismatic,
                parent: j.parent,
                xyz: j.xyz,
                rotation: j.rotation,
                axis: j.axis,
                coordinate: name.clone(),
            })
            .collect();
        let links = robot
            .links
            .iter()
            .map(|l| {
                let c = l.com;
                let cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
                let inertia = std::array::from_fn(|i| {
                    std::array::from_fn(|j| {
                        l.inertia[i][j] + l.mass * (if i == j { cc } else { 0.0 } - c[i] * c[j])
                    })
                });
                Body { mass: l.mass, first: c.map(|x| l.mass * x), inertia }
            })
            .collect();
        Some(Tree { joints, links, gravity })
    }
}

/// `impl JointSpace` for the model: the recursions of its tree where it has one and every other
/// coordinate is a slack of unit mass the derive added (a law's mode, a contact's slack), the
/// provided methods otherwise; and, with the recursions, the `LagrangeDirac::tree_dynamics` that
/// reads them (nothing otherwise).
pub fn joint_space(model: &Model<'_>) -> (TokenStream, TokenStream) {
    let p = rt();
    let ident = model.ident;
    let methods = model.tree.as_ref().and_then(|tree| methods(tree, model));
    // With the recursions, the accelerations read the balance and the mass matrix from them.
    let hook = methods.as_ref().map(|_| {
        quote! {
            fn tree_dynamics(
                &self,
                t: ::core::primitive::f64,
                q: &#p::VecQ<Self>,
                v: &#p::VecQ<Self>,
                rate: &mut #p::VecQ<Self>,
                l_vv: &mut #p::MatQQ<Self>,
            ) -> ::core::primitive::bool {
                <Self as #p::JointSpace>::mass_matrix(self, t, q, l_vv);
                <Self as #p::JointSpace>::bias_torques(self, t, q, v, rate);
                let mut force = #p::VecQ::<Self>::zeros();
                #p::LagrangeDirac::force(self, t, q, v, &mut force);
                for (r, f) in rate.iter_mut().zip(force.iter()) {
                    *r = f - *r;
                }
                true
            }
        }
    });
    let methods = methods.unwrap_or_default();
    let implementation = quote! {
        #[automatically_derived]
        #[allow(clippy::approx_constant)]
        impl #p::JointSpace for #ident {
            #methods
        }
    };
    (implementation, hook.unwrap_or_default())
}

fn methods(tree: &Tree, model: &Model<'_>) -> Option<TokenStream> {
    let names: Vec<String> = model.coordinates.iter().map(|c| c.name.to_string()).collect();
    let index = |name: &str| names.iter().position(|n| n == name);
    let mut slots = vec![None; tree.joints.len()];
    for (slot, joint) in slots.iter_mut().zip(&tree.joints) {
        if joint.moves {
            *slot = Some(index(&joint.coordinate)?);
        }
    }
    // Every other coordinate must be a unit slack, `½ rate²` in the Lagrangian: a law's mode,
    // and a contact's slack in the companion that can close contacts (the one with switches).
    let mut slacks: Vec<String> = model.laws.iter().flat_map(|l| l.modes()).map(|m| m.to_string()).collect();
    if !model.switches.is_empty() {
        slacks.extend(model.unilaterals.iter().map(|u| format!("{}_slack", u.name)));
    }
    let mut units = Vec::new();
    for (i, name) in names.iter().enumerate() {
        if slots.contains(&Some(i)) {
            continue;
        }
        if !slacks.contains(name) {
            return None;
        }
        units.push(i);
    }
    let p = rt();
    let params = &model.params;
    let gravity_lets = match &tree.gravity {
        Some([gx, gy, gz]) => quote! {
            #(let #params: ::core::primitive::f64 = self.#params;)*
            let __gravity: [::core::primitive::f64; 3] = [#gx, #gy, #gz];
        },
        None => quote! {},
    };
    let parse = |text: String| -> TokenStream { text.parse().expect("generated code parses") };
    let mass = parse(crba(tree, &slots, &units));
    let gravity = parse(rnea(tree, &slots, false));
    let bias = parse(rnea(tree, &slots, true));
    let forward = parse(aba(tree, &slots, &units));
    Some(quote! {
        const RECURSIVE: ::core::primitive::bool = true;

        #[allow(unused_variables, clippy::all)]
        fn mass_matrix(&self, t: ::core::primitive::f64, q: &#p::VecQ<Self>, out: &mut #p::MatQQ<Self>) {
            #mass
        }

        #[allow(unused_variables, clippy::all)]
        fn gravity_torques(&self, t: ::core::primitive::f64, q: &#p::VecQ<Self>, out: &mut #p::VecQ<Self>) {
            #gravity_lets
            #gravity
        }

        #[allow(unused_variables, clippy::all)]
        fn bias_torques(
            &self,
            t: ::core::primitive::f64,
            q: &#p::VecQ<Self>,
            v: &#p::VecQ<Self>,
            out: &mut #p::VecQ<Self>,
        ) {
            #gravity_lets
            #bias
        }

        #[allow(unused_variables, clippy::all)]
        fn forward_dynamics(
            &self,
            t: ::core::primitive::f64,
            q: &#p::VecQ<Self>,
            v: &#p::VecQ<Self>,
            tau: &#p::VecQ<Self>,
            out: &mut #p::VecQ<Self>,
        ) -> ::core::primitive::bool {
            #gravity_lets
            #forward
            out.iter().all(|x| x.is_finite())
        }
    })
}

type V3 = [Poly; 3];

/// Straight-line code: each step bound to a local unless it is a number or a name already.
struct Code {
    text: String,
    next: usize,
}

impl Code {
    fn new() -> Code {
        Code { text: String::new(), next: 0 }
    }

    fn bind(&mut self, p: Poly) -> Poly {
        if p.as_atom().is_some() {
            return p;
        }
        let name = format!("__t{}", self.next);
        self.next += 1;
        self.text.push_str(&format!("let {name}: f64 = {};\n", p.render()));
        Poly::atom(&Atom::Name(name))
    }

    fn bind3(&mut self, v: V3) -> V3 {
        v.map(|x| self.bind(x))
    }

    /// `1 / x`, bound.
    fn reciprocal(&mut self, x: &Poly) -> Poly {
        let name = format!("__t{}", self.next);
        self.next += 1;
        self.text.push_str(&format!("let {name}: f64 = 1.0 / ({});\n", x.render()));
        Poly::atom(&Atom::Name(name))
    }

    fn line(&mut self, text: &str) {
        self.text.push_str(text);
        self.text.push('\n');
    }

    /// The cosine and sine of each revolute joint's angle, or the slide of a prismatic one.
    fn joint_values(&mut self, tree: &Tree, slots: &[Option<usize>]) -> Vec<Option<(Poly, Poly)>> {
        tree.joints
            .iter()
            .zip(slots)
            .map(|(joint, slot)| {
                let i = (*slot)?;
                if joint.prismatic {
                    Some((Poly::atom(&Atom::Name(format!("q[{i}]"))), Poly::num(0.0)))
                } else {
                    let (c, s) = (format!("__c{i}"), format!("__s{i}"));
                    self.line(&format!("let ({s}, {c}) = q[{i}].sin_cos();"));
                    Some((Poly::atom(&Atom::Name(c)), Poly::atom(&Atom::Name(s))))
                }
            })
            .collect()
    }
}

fn num3(x: [f64; 3]) -> V3 {
    x.map(Poly::num)
}

fn dot(a: &V3, b: &V3) -> Poly {
    let mut s = a[0].mul(&b[0]);
    s.add(&a[1].mul(&b[1]), 1.0);
    s.add(&a[2].mul(&b[2]), 1.0);
    s
}

fn cross(a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let mut s = a[j].mul(&b[k]);
        s.add(&a[k].mul(&b[j]), -1.0);
        s
    })
}

fn plus(a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| {
        let mut s = a[i].clone();
        s.add(&b[i], 1.0);
        s
    })
}

fn scaled(a: &V3, x: &Poly) -> V3 {
    std::array::from_fn(|i| a[i].mul(x))
}

/// `m x` for a numeric matrix.
fn matvec(m: &Mat3, x: &V3) -> V3 {
    std::array::from_fn(|i| {
        let mut s = Poly::default();
        for (j, xj) in x.iter().enumerate() {
            s.add(xj, m[i][j]);
        }
        s
    })
}

fn transpose(m: &Mat3) -> Mat3 {
    std::array::from_fn(|i| std::array::from_fn(|j| m[j][i]))
}

/// `Rot(a, θ) x = cos θ (x − a (a·x)) + sin θ (a × x) + a (a·x)`; `back` turns by `−θ`.
fn turn(code: &mut Code, axis: &[f64; 3], (cos, sin): &(Poly, Poly), x: &V3, back: bool) -> V3 {
    let a = num3(*axis);
    let along = code.bind(dot(&a, x));
    let across = cross(&a, x);
    let sign = if back { -1.0 } else { 1.0 };
    let out = std::array::from_fn(|i| {
        let mut perp = x[i].clone();
        perp.add(&along, -axis[i]);
        let mut out = cos.mul(&perp);
        out.add(&sin.mul(&across[i]), sign);
        out.add(&along, axis[i]);
        out
    });
    code.bind3(out)
}

impl Joint {
    /// `Rᵀ x`: a vector of the parent's axes in the child's.
    fn to_child(&self, code: &mut Code, value: &Option<(Poly, Poly)>, x: &V3) -> V3 {
        let y = code.bind3(matvec(&transpose(&self.rotation), x));
        match value {
            Some(cs) if !self.prismatic => turn(code, &self.axis, cs, &y, true),
            _ => y,
        }
    }

    /// `R x`: a vector of the child's axes in the parent's.
    fn to_parent(&self, code: &mut Code, value: &Option<(Poly, Poly)>, x: &V3) -> V3 {
        let y = match value {
            Some(cs) if !self.prismatic => turn(code, &self.axis, cs, x, false),
            _ => x.clone(),
        };
        code.bind3(matvec(&self.rotation, &y))
    }

    /// `R X Rᵀ`: a matrix of the child's axes in the parent's (R applied to the columns, then
    /// to the rows).
    fn rotate(&self, code: &mut Code, value: &Option<(Poly, Poly)>, x: &[V3; 3]) -> [V3; 3] {
        let columns: [V3; 3] = std::array::from_fn(|j| {
            let column = [x[0][j].clone(), x[1][j].clone(), x[2][j].clone()];
            self.to_parent(code, value, &column)
        });
        std::array::from_fn(|i| {
            let row = [columns[0][i].clone(), columns[1][i].clone(), columns[2][i].clone()];
            self.to_parent(code, value, &row)
        })
    }

    /// The child's origin in the parent's frame.
    fn offset(&self, code: &mut Code, value: &Option<(Poly, Poly)>) -> V3 {
        let mut d = num3(self.xyz);
        if let (true, Some((slide, _))) = (self.prismatic, value) {
            let along = matvec(&self.rotation, &num3(self.axis));
            d = plus(&d, &scaled(&along, slide));
        }
        code.bind3(d)
    }
}

/// The motion subspace of a joint in its child's axes: `(a, 0)` for a turn, `(0, a)` for a
/// slide; `Sᵀ (n, f)` is `a·n` or `a·f`.
fn project(joint: &Joint, (n, f): &(V3, V3)) -> Poly {
    dot(&num3(joint.axis), if joint.prismatic { f } else { n })
}

/// A force `(n, f)` of the child's axes in the parent's, about the parent's origin.
fn force_to_parent(
    code: &mut Code,
    joint: &Joint,
    value: &Option<(Poly, Poly)>,
    d: &V3,
    (n, f): &(V3, V3),
) -> (V3, V3) {
    let f = joint.to_parent(code, value, f);
    let n = joint.to_parent(code, value, n);
    let n = code.bind3(plus(&n, &cross(d, &f)));
    (n, f)
}

/// The composite rigid body recursion: `out` is the mass matrix.
fn crba(tree: &Tree, slots: &[Option<usize>], units: &[usize]) -> String {
    let mut code = Code::new();
    code.line("out.fill(0.0);");
    let values = code.joint_values(tree, slots);
    // The composite inertia of each link's subtree, in its axes: (m, h, I).
    let mut composite: Vec<(f64, V3, [V3; 3])> =
        tree.links.iter().map(|b| (b.mass, num3(b.first), b.inertia.map(num3))).collect();
    let mut offsets: Vec<V3> = Vec::new();
    for (k, joint) in tree.joints.iter().enumerate() {
        offsets.push(joint.offset(&mut code, &values[k]));
    }
    for (k, joint) in tree.joints.iter().enumerate().rev() {
        let (m, h, inertia) = composite[k + 1].clone();
        let value = &values[k];
        let d = &offsets[k];
        let rh = joint.to_parent(&mut code, value, &h);
        let rotated = joint.rotate(&mut code, value, &inertia);
        let dd = dot(d, d);
        let dh = dot(d, &rh);
        let moved: [V3; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let mut x = rotated[i][j].clone();
                if i == j {
                    x.add(&dd, m);
                    x.add(&dh, 2.0);
                }
                x.add(&d[i].mul(&d[j]), -m);
                x.add(&d[i].mul(&rh[j]), -1.0);
                x.add(&rh[i].mul(&d[j]), -1.0);
                x
            })
        });
        let parent = &mut composite[joint.parent];
        parent.0 += m;
        parent.1 = code.bind3(plus(&parent.1, &plus(&rh, &scaled(d, &Poly::num(m)))));
        for (row, added) in parent.2.iter_mut().zip(&moved) {
            for (x, y) in row.iter_mut().zip(added) {
                x.add(y, 1.0);
                *x = code.bind(std::mem::take(x));
            }
        }
    }
    let write = |code: &mut Code, i: usize, j: usize, x: Poly| {
        let x = code.bind(x);
        code.line(&format!("out[({i}, {j})] = {};", x.render()));
        if i != j {
            code.line(&format!("out[({j}, {i})] = {};", x.render()));
        }
    };
    for (k, joint) in tree.joints.iter().enumerate() {
        let Some(ck) = slots[k] else { continue };
        let (m, h, inertia) = &composite[k + 1];
        let a = num3(joint.axis);
        // F = I S: (I a, a × h) for a turn, (h × a, m a) for a slide.
        let mut force = if joint.prismatic {
            (cross(h, &a), scaled(&a, &Poly::num(*m)))
        } else {
            (matvec_poly(inertia, &a), cross(&a, h))
        };
        force = (code.bind3(force.0), code.bind3(force.1));
        write(&mut code, ck, ck, project(joint, &force));
        let mut link = k + 1;
        while link != 0 {
            let j = link - 1;
            let below = &tree.joints[j];
            force = force_to_parent(&mut code, below, &values[j], &offsets[j], &force);
            link = below.parent;
            if link == 0 {
                break;
            }
            if let Some(cj) = slots[link - 1] {
                write(&mut code, ck, cj, project(&tree.joints[link - 1], &force));
            }
        }
    }
    for i in units {
        code.line(&format!("out[({i}, {i})] = 1.0;"));
    }
    code.text
}

/// `I x` for a matrix of polynomials.
fn matvec_poly(m: &[V3; 3], x: &V3) -> V3 {
    std::array::from_fn(|i| dot(&m[i], x))
}

/// The recursive Newton-Euler recursion at zero acceleration: `out` is the bias torques (with
/// `velocities`) or the gravity torques.
fn rnea(tree: &Tree, slots: &[Option<usize>], velocities: bool) -> String {
    let mut code = Code::new();
    code.line("out.fill(0.0);");
    let values = code.joint_values(tree, slots);
    let zero = || num3([0.0; 3]);
    let gravity: V3 = match &tree.gravity {
        Some(_) => std::array::from_fn(|i| Poly::atom(&Atom::Name(format!("__gravity[{i}]")))),
        None => num3([0.0, 0.0, -super::GRAVITY]),
    };
    // The base's acceleration is −g: every link then feels gravity as an acceleration.
    let mut motion: Vec<(V3, V3, V3, V3)> = vec![(zero(), zero(), zero(), gravity.map(|g| g.scaled(-1.0)))];
    let mut offsets = Vec::new();
    for (k, joint) in tree.joints.iter().enumerate() {
        let value = &values[k];
        let d = joint.offset(&mut code, value);
        let (w, u, alpha, a) = motion[joint.parent].clone();
        let mut w2 = joint.to_child(&mut code, value, &w);
        let mut u2 = joint.to_child(&mut code, value, &plus(&u, &cross(&w, &d)));
        let alpha2 = joint.to_child(&mut code, value, &alpha);
        let mut a2 = joint.to_child(&mut code, value, &plus(&a, &cross(&alpha, &d)));
        let mut alpha2 = alpha2;
        if let (Some(i), true) = (slots[k], velocities) {
            let rate = Poly::atom(&Atom::Name(format!("v[{i}]")));
            let s = scaled(&num3(joint.axis), &rate);
            let s = code.bind3(s);
            // v × S q̇: (ω × s, v × s) for a turn, (0, ω × s) for a slide, with v after the joint.
            if joint.prismatic {
                u2 = code.bind3(plus(&u2, &s));
                a2 = code.bind3(plus(&a2, &cross(&w2, &s)));
            } else {
                w2 = code.bind3(plus(&w2, &s));
                alpha2 = code.bind3(plus(&alpha2, &cross(&w2, &s)));
                a2 = code.bind3(plus(&a2, &cross(&u2, &s)));
            }
        }
        offsets.push(d);
        motion.push((w2, u2, alpha2, a2));
    }
    // Each link's force: f = I a + v ×* I v.
    let mut forces: Vec<(V3, V3)> = Vec::with_capacity(tree.links.len());
    for (l, body) in tree.links.iter().enumerate() {
        let (w, u, alpha, a) = &motion[l];
        if l == 0 || body.mass == 0.0 && body.inertia.iter().flatten().all(|x| *x == 0.0) {
            forces.push((zero(), zero()));
            continue;
        }
        let h = num3(body.first);
        let inertia = body.inertia.map(num3);
        let m = Poly::num(body.mass);
        let angular = code.bind3(plus(&matvec_poly(&inertia, w), &cross(&h, u)));
        let linear = code.bind3(plus(&scaled(u, &m), &cross(w, &h)));
        let n = plus(
            &plus(&matvec_poly(&inertia, alpha), &cross(&h, a)),
            &plus(&cross(w, &angular), &cross(u, &linear)),
        );
        let f = plus(&plus(&scaled(a, &m), &cross(alpha, &h)), &cross(w, &linear));
        forces.push((code.bind3(n), code.bind3(f)));
    }
    for (k, joint) in tree.joints.iter().enumerate().rev() {
        let force = forces[k + 1].clone();
        if let Some(i) = slots[k] {
            let tau = code.bind(project(joint, &force));
            code.line(&format!("out[{i}] = {};", tau.render()));
        }
        if joint.parent != 0 {
            let (n, f) = force_to_parent(&mut code, joint, &values[k], &offsets[k], &force);
            let parent = &mut forces[joint.parent];
            parent.0 = code.bind3(plus(&parent.0, &n));
            parent.1 = code.bind3(plus(&parent.1, &f));
        }
    }
    code.text
}

type M3 = [V3; 3];

fn mat_mul(a: &M3, b: &M3) -> M3 {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut s = Poly::default();
            for k in 0..3 {
                s.add(&a[i][k].mul(&b[k][j]), 1.0);
            }
            s
        })
    })
}

fn mat_transpose(a: &M3) -> M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| a[j][i].clone()))
}

/// `[d]×`, the matrix of `x ↦ d × x`.
fn skew(d: &V3) -> M3 {
    let z = || Poly::num(0.0);
    [
        [z(), d[2].scaled(-1.0), d[1].clone()],
        [d[2].clone(), z(), d[0].scaled(-1.0)],
        [d[1].scaled(-1.0), d[0].clone(), z()],
    ]
}

/// `Σ scale · terms`, entry by entry, bound.
fn combine(code: &mut Code, terms: &[(&M3, f64)]) -> M3 {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut s = Poly::default();
            for (m, scale) in terms {
                s.add(&m[i][j], *scale);
            }
            code.bind(s)
        })
    })
}

/// A joint's `U = I S`, `1 / D` and `u` from the backward pass of the articulated-body
/// recursion.
type Solved = ((V3, V3), Poly, Poly);

/// An articulated-body inertia, the map `(ω, v) ↦ (A ω + B v, Bᵀ ω + C v)`.
#[derive(Clone)]
struct Articulated {
    a: M3,
    b: M3,
    c: M3,
}

impl Articulated {
    fn apply(&self, (w, u): &(V3, V3)) -> (V3, V3) {
        let bt = mat_transpose(&self.b);
        (
            plus(&matvec_poly(&self.a, w), &matvec_poly(&self.b, u)),
            plus(&matvec_poly(&bt, w), &matvec_poly(&self.c, u)),
        )
    }
}

/// The articulated-body recursion: `out` is the accelerations `M⁻¹ (τ − b)` under the torques
/// `tau`.
fn aba(tree: &Tree, slots: &[Option<usize>], units: &[usize]) -> String {
    let mut code = Code::new();
    let values = code.joint_values(tree, slots);
    let zero = || num3([0.0; 3]);
    let gravity: V3 = match &tree.gravity {
        Some(_) => std::array::from_fn(|i| Poly::atom(&Atom::Name(format!("__gravity[{i}]")))),
        None => num3([0.0, 0.0, -super::GRAVITY]),
    };
    // Velocities, the joints' velocity products `c = v × S q̇`, and each body's inertia and bias
    // force `v ×* I v`, as the articulated ones start.
    let mut velocity: Vec<(V3, V3)> = vec![(zero(), zero())];
    let mut products: Vec<(V3, V3)> = Vec::new();
    let mut offsets = Vec::new();
    for (k, joint) in tree.joints.iter().enumerate() {
        let value = &values[k];
        let d = joint.offset(&mut code, value);
        let (w, u) = velocity[joint.parent].clone();
        let mut w2 = joint.to_child(&mut code, value, &w);
        let mut u2 = joint.to_child(&mut code, value, &plus(&u, &cross(&w, &d)));
        let mut c = (zero(), zero());
        if let Some(i) = slots[k] {
            let s = code.bind3(scaled(&num3(joint.axis), &Poly::atom(&Atom::Name(format!("v[{i}]")))));
            if joint.prismatic {
                u2 = code.bind3(plus(&u2, &s));
                c.1 = code.bind3(cross(&w2, &s));
            } else {
                w2 = code.bind3(plus(&w2, &s));
                c = (code.bind3(cross(&w2, &s)), code.bind3(cross(&u2, &s)));
            }
        }
        offsets.push(d);
        products.push(c);
        velocity.push((w2, u2));
    }
    let mut inertia: Vec<Articulated> = Vec::new();
    let mut bias: Vec<(V3, V3)> = Vec::new();
    for (l, body) in tree.links.iter().enumerate() {
        let h = num3(body.first);
        let mass = Poly::num(body.mass);
        let ident: M3 = std::array::from_fn(|i| {
            std::array::from_fn(|j| if i == j { mass.clone() } else { Poly::num(0.0) })
        });
        inertia.push(Articulated { a: body.inertia.map(num3), b: skew(&h), c: ident });
        let (w, u) = &velocity[l];
        if l == 0 || body.mass == 0.0 && body.inertia.iter().flatten().all(|x| *x == 0.0) {
            bias.push((zero(), zero()));
            continue;
        }
        let (angular, linear) = inertia[l].apply(&(w.clone(), u.clone()));
        let (angular, linear) = (code.bind3(angular), code.bind3(linear));
        let n = plus(&cross(w, &angular), &cross(u, &linear));
        let f = cross(w, &linear);
        bias.push((code.bind3(n), code.bind3(f)));
    }
    // Backward: each joint's U = I S, D = Sᵀ U, u = τ − Sᵀ p, and what the parent feels.
    let mut solved: Vec<Option<Solved>> = vec![None; tree.joints.len()];
    for (k, joint) in tree.joints.iter().enumerate().rev() {
        let l = k + 1;
        let mut ia = inertia[l].clone();
        let mut pa = bias[l].clone();
        if let Some(i) = slots[k] {
            let a = num3(joint.axis);
            let (u_w, u_v) = if joint.prismatic {
                (matvec_poly(&ia.b, &a), matvec_poly(&ia.c, &a))
            } else {
                (matvec_poly(&ia.a, &a), matvec_poly(&mat_transpose(&ia.b), &a))
            };
            let big_u = (code.bind3(u_w), code.bind3(u_v));
            let d = code.bind(project(joint, &big_u));
            let inverse = code.reciprocal(&d);
            let mut small_u = Poly::atom(&Atom::Name(format!("tau[{i}]")));
            small_u.add(&project(joint, &pa), -1.0);
            let small_u = code.bind(small_u);
            let outer = |x: &V3, y: &V3| -> M3 {
                std::array::from_fn(|r| std::array::from_fn(|s| x[r].mul(&y[s]).mul(&inverse)))
            };
            ia = Articulated {
                a: combine(&mut code, &[(&ia.a, 1.0), (&outer(&big_u.0, &big_u.0), -1.0)]),
                b: combine(&mut code, &[(&ia.b, 1.0), (&outer(&big_u.0, &big_u.1), -1.0)]),
                c: combine(&mut code, &[(&ia.c, 1.0), (&outer(&big_u.1, &big_u.1), -1.0)]),
            };
            let ratio = code.bind(small_u.mul(&inverse));
            let pushed = ia.apply(&products[k]);
            pa = (
                code.bind3(plus(&plus(&pa.0, &pushed.0), &scaled(&big_u.0, &ratio))),
                code.bind3(plus(&plus(&pa.1, &pushed.1), &scaled(&big_u.1, &ratio))),
            );
            solved[k] = Some((big_u, inverse, small_u));
        }
        if joint.parent == 0 {
            continue;
        }
        let value = &values[k];
        let rotated = Articulated {
            a: joint.rotate(&mut code, value, &ia.a),
            b: joint.rotate(&mut code, value, &ia.b),
            c: joint.rotate(&mut code, value, &ia.c),
        };
        let dm = skew(&offsets[k]);
        let bd = mat_mul(&rotated.b, &dm);
        let dc = mat_mul(&dm, &rotated.c);
        let dcd = mat_mul(&dc, &dm);
        let moved = Articulated {
            a: combine(
                &mut code,
                &[(&rotated.a, 1.0), (&bd, -1.0), (&mat_transpose(&bd), -1.0), (&dcd, -1.0)],
            ),
            b: combine(&mut code, &[(&rotated.b, 1.0), (&dc, 1.0)]),
            c: rotated.c,
        };
        let pushed = force_to_parent(&mut code, joint, value, &offsets[k], &pa);
        let parent = &mut inertia[joint.parent];
        *parent = Articulated {
            a: combine(&mut code, &[(&parent.a.clone(), 1.0), (&moved.a, 1.0)]),
            b: combine(&mut code, &[(&parent.b.clone(), 1.0), (&moved.b, 1.0)]),
            c: combine(&mut code, &[(&parent.c.clone(), 1.0), (&moved.c, 1.0)]),
        };
        let parent = &mut bias[joint.parent];
        parent.0 = code.bind3(plus(&parent.0, &pushed.0));
        parent.1 = code.bind3(plus(&parent.1, &pushed.1));
    }
    // Forward: the accelerations, from the base's `−g`.
    let mut acceleration: Vec<(V3, V3)> = vec![(zero(), gravity.map(|g| g.scaled(-1.0)))];
    for (k, joint) in tree.joints.iter().enumerate() {
        let value = &values[k];
        let (alpha, a) = acceleration[joint.parent].clone();
        let alpha2 = joint.to_child(&mut code, value, &alpha);
        let a2 = joint.to_child(&mut code, value, &plus(&a, &cross(&alpha, &offsets[k])));
        let mut next = (code.bind3(plus(&alpha2, &products[k].0)), code.bind3(plus(&a2, &products[k].1)));
        if let (Some(i), Some((big_u, inverse, small_u))) = (slots[k], &solved[k]) {
            let mut x = small_u.clone();
            x.add(&dot(&big_u.0, &next.0), -1.0);
            x.add(&dot(&big_u.1, &next.1), -1.0);
            let x = code.bind(x);
            let qdd = code.bind(x.mul(inverse));
            code.line(&format!("out[{i}] = {};", qdd.render()));
            let s = scaled(&num3(joint.axis), &qdd);
            if joint.prismatic {
                next.1 = code.bind3(plus(&next.1, &s));
            } else {
                next.0 = code.bind3(plus(&next.0, &s));
            }
        }
        acceleration.push(next);
    }
    for i in units {
        code.line(&format!("out[{i}] = tau[{i}];"));
    }
    code.text
}
