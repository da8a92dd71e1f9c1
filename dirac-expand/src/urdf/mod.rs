//! `#[dirac(urdf = "robot.urdf")]`: a robot read from its URDF when the model compiles and
//! written into the model as joint coordinates, definitions, a Lagrangian and outputs, which
//! then go through the derive like any model written by hand.
//!
//! The Lagrangian is the links' kinetic energy less their potential in gravity, `(0, 0, −9.81)`
//! unless `gravity = [gx, gy, gz]` gives it as expressions in the model's parameters, in the
//! joint coordinates. Each link's angular velocity `ω` and the velocity `v` of its
//! frame's origin are carried in the link's own axes by the usual recursion from the root,
//!
//! ```text
//! ω_k = Rᵀ ω_p + a q̇            (revolute; Rᵀ ω_p for a prismatic or fixed joint)
//! v_k = Rᵀ (v_p + ω_p × d)       (+ a q̇ for a prismatic joint)
//! ```
//!
//! with `R` the joint's rotation (its origin's, times the rotation about the axis `a`) and `d`
//! the offset of the child's origin in the parent's frame. Then
//! `T_k = ½ m |v + ω × c|² + ½ ωᵀ I_c ω` with `c` the centre of mass and `I_c` the inertia about
//! it, and `V_k = m g z_c` with the height of the centre of mass from the third row of the
//! link's rotation in the world. Every step is a definition, so the derive's graph shares them
//! and differentiates each once.
//!
//! For a robot whose joints form a tree fixed in the world, the blocks do not differentiate this
//! Lagrangian: its gradient is written out too, from the momentum `H` and the weight `W` of the
//! links beyond each joint, carried from the leaves to the root (`∂L/∂v = Sᵀ H`, `∂L/∂q = Hᵀ (V ×
//! S) + Sᵀ W`, `Writer::gradients`), and the Jacobian blocks differentiate that. The
//! Lagrangian's own gradient reaches every link's energy through the whole chain above it, and
//! its derivatives again, so its code grew with the cube of the chain's length; the recursion's
//! gradient grows with the number of links and its derivatives with their square.
//!
//! A `floating` joint (from the root, fixed in the world), or the whole robot with the model's
//! `floating` (a free joint `root_joint` from the world to the root, as Pinocchio's free
//! flyer), moves its child freely: the coordinates `<joint>_x`, `_y`, `_z` are the child's
//! origin and `<joint>_r11` … `_r33` its rotation `R` in the joint's frame, held orthogonal by
//! six holonomic rows (`<joint>_unit1` …, `<joint>_square12` …), the embedding of
//! `RigidBody`. The recursion starts from the child's `ω` read off `Ω̂ = RᵀṘ` and its origin's
//! velocity `Rᵀ ẋ`; the Lagrangian keeps the symmetries of the free robot, so the variational
//! integrator keeps its momenta, which are outputs (`linear_momentum_x` …, `angular_momentum_x`
//! … about the world's origin). A floating base must have mass (its own or a link's fixed to
//! it). A `planar` joint is a slide along two directions of the plane normal to its axis and a
//! turn about the axis: coordinates `<joint>_x`, `<joint>_y` and `<joint>_theta`.
//!
//! `<mimic>` becomes a holonomic row, `<dynamics damping>` a Rayleigh dissipation and
//! `<dynamics friction>` a `friction` law (Coulomb friction with stiction); every joint
//! coordinate is a port (a motor from the component library attaches to any joint), and each
//! link's pose in the world is an output, the root's too: its origin (`<link>_x`, `_y`, `_z`)
//! and its rotation (`<link>_r11` to `<link>_r33`, entry `(i, j)` of the matrix whose columns
//! are the link's axes in the world, Pinocchio's `oMf[link].rotation`). With `joint_limits`, each
//! limited joint's `<limit lower upper>` is two unilateral constraints, `<joint>_lower` and
//! `<joint>_upper`, with restitution 0: hard stops the joint rests against.
//!
//! With `ground` (or `ground(restitution = e)`), the plane `z = 0` of the world: each point of
//! the links' `<collision>` shapes that can touch it is a unilateral constraint, its height
//! above the ground from the link's rotation and origin in the world: a sphere's centre less its
//! radius, a capsule's two ends less its radius, a box's eight corners. The height of a
//! cylinder's lowest rim point, `z_c − r √(1 − a_z²)`, has no derivative where the cylinder
//! stands on a face, and a mesh is not read: both are refused. `ground(links = ["foot", …])`
//! lets only the shapes of the links named touch it (a robot's feet, its other shapes left out
//! of the contacts).
//!
//! `ground(friction = mu)` puts Coulomb's isotropic friction cone at each such point while it
//! rests on the ground: in the companion with contacts that can rest (`with_contacts()`), the
//! cone `<contact>_slip` on the point's slip in the world's `(x, y)`, `R (v + ω × p) + ω_w × (0,
//! 0, −r)`, with the kinetic force `mu` times the contact's force `<contact>_force`, its rows
//! and events on only while `<contact>_closed` is 1 (open, its rows hold its mode still and its
//! events stay away from zero). Impacts are frictionless: friction acts on a resting contact.

mod poly;
mod read;
pub mod tree;
mod view;

use proc_macro2::Span;
use syn::{Expr, Ident, LitStr};

use crate::ast::{ConstraintDecl, ConstraintKind, CoordinateDecl, DefineDecl, Model, UnilateralDecl};
use crate::ctxt::Ctxt;
use crate::law_decl::{LawDecl, LawKind};
use poly::{Atom, Poly};
use read::{Kind, Mat3, Robot};

/// The acceleration of gravity, along −z, as Pinocchio and MuJoCo assume it, unless the model
/// gives its own.
pub const GRAVITY: f64 = 9.81;

/// Reads the URDF named by `path` (relative to the crate being compiled) and writes the robot
/// into `model`; every problem is an error at `path`.
pub fn desugar(cx: &Ctxt, model: &mut Model<'_>, path: &LitStr) {
    let dir = std::env::var("CARGO_MANIFEST_DIR").unwrap_or_else(|_| ".".to_owned());
    let full = std::path::Path::new(&dir).join(path.value());
    let text = match std::fs::read_to_string(&full) {
        Ok(text) => text,
        Err(e) => {
            let message = format!(
                "cannot read the URDF `{}` (a path relative to the crate's root, where its Cargo.toml is): {e}",
                path.value()
            );
            cx.error_spanned_by(path, message);
            // Nothing of the robot is in the model: its other errors would only mislead.
            model.incomplete = true;
            return;
        }
    };
    let robot = match read::parse(&text, model.floating.is_some()) {
        Ok(robot) => robot,
        Err(e) => {
            cx.error_spanned_by(path, format!("{}, {e}", path.value()));
            model.incomplete = true;
            return;
        }
    };
    if model.lagrangian.is_some() {
        cx.error_spanned_by(
            path,
            "a model read from a URDF has the robot's Lagrangian; remove `lagrangian = …`",
        );
        return;
    }
    model.tracked_files.push(full.display().to_string());
    let mut writer = Writer { cx, model, span: path.span(), path };
    writer.robot(&robot);
}

struct Writer<'c, 'm, 'a> {
    cx: &'c Ctxt,
    model: &'m mut Model<'a>,
    span: Span,
    path: &'c LitStr,
}

/// A link's motion: angular velocity and origin velocity in its own axes, rotation and origin
/// in the world.
struct Frame {
    omega: [Atom; 3],
    velocity: [Atom; 3],
    rotation: [[Atom; 3]; 3],
    origin: [Atom; 3],
    /// The cosine and sine of a revolute joint's angle (`None` for another joint).
    turn: Option<(Atom, Atom)>,
    /// The link's origin in its parent's frame (`xyz`, and the slide of a prismatic joint).
    offset: [Poly; 3],
}

const XYZ: [&str; 3] = ["x", "y", "z"];

impl Writer<'_, '_, '_> {
    fn robot(&mut self, robot: &Robot) {
        let Some(names) = self.identifiers(robot) else { return };
        let (links, joints) = names;
        let Some(gravity) = self.gravity() else { return };
        let written = match &self.model.gravity {
            Some((_, Expr::Array(array))) => {
                let elems: Vec<Expr> = array.elems.iter().cloned().collect();
                elems.try_into().ok()
            }
            _ => None,
        };
        self.model.tree = tree::Tree::of(robot, &joints, written);
        self.model.shapes = Some(view::links(robot, &links));
        let zero = || [Atom::Num(0.0), Atom::Num(0.0), Atom::Num(0.0)];
        let identity = read::rpy([0.0; 3]).map(|row| row.map(Atom::Num));
        let root = Frame {
            omega: zero(),
            velocity: zero(),
            rotation: identity,
            origin: zero(),
            turn: None,
            offset: [0.0; 3].map(Poly::num),
        };
        if robot.links[0].shown {
            self.pose_outputs(&links[0], &root);
        }
        let mut frames = vec![root];
        let mut kinetic = Vec::new();
        let mut potential = Vec::new();
        let mut momenta = Momenta::default();
        let floats = robot.joints.iter().any(|j| j.kind == Kind::Floating);
        for (k, joint) in robot.joints.iter().enumerate() {
            let link = &links[k + 1];
            let frame = match joint.kind {
                Kind::Floating => self.free_frame(joint, link, &joints[k]),
                _ => self.moved_frame(joint, link, &joints[k], &frames[joint.parent]),
            };
            // The link's energies, and its momenta when the robot floats.
            let body = &robot.links[k + 1];
            if body.mass > 0.0 || body.inertia.iter().flatten().any(|x| *x != 0.0) {
                let w: [Poly; 3] = frame.omega.clone().map(|a| Poly::atom(&a));
                let mut vc = cross(&w, &body.com.map(Poly::num));
                vc.iter_mut().zip(&frame.velocity).for_each(|(c, u)| c.add(&Poly::atom(u), 1.0));
                let vc = self.bind3(&format!("{link}_vc"), vc);
                let mut t = Poly::default();
                for c in &vc {
                    let c = Poly::atom(c);
                    t.add(&c.mul(&c), 0.5 * body.mass);
                }
                for i in 0..3 {
                    for j in 0..3 {
                        t.add(&w[i].mul(&w[j]), 0.5 * body.inertia[i][j]);
                    }
                }
                kinetic.push(self.bind(format!("{link}_kinetic"), t));
                if body.mass > 0.0 {
                    // The centre of mass in the world, row by row, as far as gravity needs it.
                    let centre = |i: usize| {
                        let mut z = Poly::atom(&frame.origin[i]);
                        for (r, c) in frame.rotation[i].iter().zip(body.com) {
                            z.add(&Poly::atom(r), c);
                        }
                        z
                    };
                    let v = match &gravity {
                        None => centre(2).scaled(body.mass * GRAVITY),
                        Some(g) => {
                            let mut v = Poly::default();
                            for (i, gi) in g.iter().enumerate() {
                                v.add(&Poly::atom(gi).mul(&centre(i)), -body.mass);
                            }
                            v
                        }
                    };
                    potential.push(self.bind(format!("{link}_potential"), v));
                }
                if floats {
                    momenta.add(self, link, body, &frame, &vc);
                }
            }
            if body.shown {
                self.pose_outputs(link, &frame);
            }
            frames.push(frame);
        }
        momenta.outputs(self);
        self.gradients(robot, &links, &joints, &frames, &gravity);
        if self.model.ground.is_some() {
            self.ground_contacts(robot, &links, &frames);
        }
        let mut lagrangian = Poly::default();
        kinetic.iter().for_each(|t| lagrangian.add(&Poly::atom(t), 1.0));
        potential.iter().for_each(|u| lagrangian.add(&Poly::atom(u), -1.0));
        self.joint_laws(robot, &joints);
        // In the companion with contacts that can rest, each contact's slack has unit mass:
        // what `contacts::companion` writes into a Lagrangian written by hand.
        if !self.model.switches.is_empty() {
            for u in &self.model.unilaterals {
                let rate = Poly::atom(&Atom::Name(format!("{}_slack_rate", u.name)));
                lagrangian.add(&rate.mul(&rate), 0.5);
            }
        }
        let key = Ident::new("lagrangian", self.span);
        self.model.lagrangian = Some((key, self.expr(&lagrangian.render())));
    }

    /// `∂L/∂v` and `∂L/∂q` of each joint of a robot whose joints form a tree fixed in the world,
    /// from the momentum `H` and the weight `W` of the links beyond the joint, in the axes of the
    /// link it moves and about its origin (forces: moment, then force):
    ///
    /// ```text
    /// ∂L/∂v = Sᵀ H,    ∂L/∂q = Hᵀ (V × S) + Sᵀ W
    /// ```
    ///
    /// with `S` the joint's motion (`(a, 0)` for a turn about `a`, `(0, a)` for a slide) and `V =
    /// (ω, v)` the link's velocity. Each link adds its own momentum `(I ω + m c × v, m v + ω × m c)`
    /// (inertia about its origin) and weight `(m c × g, m g)` to its parent's, moved by the joint
    /// (`f' = R f`, `n' = R n + d × f'`). The first term is `Σ ∂T/∂q` over the links beyond the
    /// joint: turning the joint moves each of their velocities by `S × (V_b − V_parent)` and turns
    /// their inertias by `S×`, which leaves `h_bᵀ (V_parent × S)`, and `V_parent × S = V × S`.
    /// These are linear in the number of links; the Lagrangian's gradient, differentiated link by
    /// link through the chain, is not. Nothing for a floating or planar robot.
    fn gradients(
        &mut self,
        robot: &Robot,
        links: &[String],
        joints: &[String],
        frames: &[Frame],
        gravity: &Option<[Atom; 3]>,
    ) {
        if robot.joints.iter().any(|j| matches!(j.kind, Kind::Floating | Kind::Planar)) {
            return;
        }
        type Force = [[Poly; 3]; 2];
        let empty = || -> Force { Default::default() };
        let mut momentum: Vec<Force> = (0..robot.links.len()).map(|_| empty()).collect();
        let mut weight: Vec<Force> = (0..robot.links.len()).map(|_| empty()).collect();
        for (l, body) in robot.links.iter().enumerate().skip(1) {
            if body.mass == 0.0 && body.inertia.iter().flatten().all(|x| *x == 0.0) {
                continue;
            }
            let frame = &frames[l];
            let c = body.com;
            let cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
            let first: [Poly; 3] = c.map(|x| Poly::num(body.mass * x));
            let w: [Poly; 3] = frame.omega.clone().map(|a| Poly::atom(&a));
            let u: [Poly; 3] = frame.velocity.clone().map(|a| Poly::atom(&a));
            let mut n = cross(&first, &u);
            for (i, ni) in n.iter_mut().enumerate() {
                for (j, wj) in w.iter().enumerate() {
                    let about_origin =
                        body.inertia[i][j] + body.mass * (if i == j { cc } else { 0.0 } - c[i] * c[j]);
                    ni.add(wj, about_origin);
                }
            }
            let mut f = cross(&w, &first);
            for (fi, ui) in f.iter_mut().zip(&u) {
                fi.add(ui, body.mass);
            }
            momentum[l] = [n, f];
            if body.mass > 0.0 {
                // Gravity in the link's axes: column j of its rotation in the world, dotted with g.
                let g: [Poly; 3] = std::array::from_fn(|j| match gravity {
                    None => Poly::atom(&frame.rotation[2][j]).scaled(-GRAVITY),
                    Some(g) => {
                        let mut s = Poly::default();
                        for (row, gi) in frame.rotation.iter().zip(g) {
                            s.add(&Poly::atom(&row[j]).mul(&Poly::atom(gi)), 1.0);
                        }
                        s
                    }
                });
                let g = self.bind3(&format!("{}_gravity", links[l]), g).map(|a| Poly::atom(&a));
                weight[l] = [cross(&first, &g), g.map(|x| x.scaled(body.mass))];
            }
        }
        let mut gradients = Vec::new();
        for (k, joint) in robot.joints.iter().enumerate().rev() {
            let (l, link) = (k + 1, &links[k + 1]);
            let [hn, hf] = std::mem::take(&mut momentum[l]);
            let [wn, wf] = std::mem::take(&mut weight[l]);
            let bind = |w: &mut Self, name: &str, x: [Poly; 3]| {
                w.bind3(&format!("{link}_{name}"), x).map(|a| Poly::atom(&a))
            };
            let (hn, hf) = (bind(self, "hn", hn), bind(self, "hf", hf));
            let (wn, wf) = (bind(self, "wn", wn), bind(self, "wf", wf));
            if matches!(joint.kind, Kind::Revolute | Kind::Prismatic) {
                let frame = &frames[l];
                let a = joint.axis.map(Poly::num);
                let w: [Poly; 3] = frame.omega.clone().map(|x| Poly::atom(&x));
                let u: [Poly; 3] = frame.velocity.clone().map(|x| Poly::atom(&x));
                let dot = |x: &[Poly; 3], y: &[Poly; 3]| {
                    let mut s = Poly::default();
                    for (xi, yi) in x.iter().zip(y) {
                        s.add(&xi.mul(yi), 1.0);
                    }
                    s
                };
                let (dv, mut dq) = if joint.kind == Kind::Revolute {
                    // V × (a, 0) = (ω × a, v × a).
                    let mut dq = dot(&hn, &cross(&w, &a));
                    dq.add(&dot(&hf, &cross(&u, &a)), 1.0);
                    (dot(&a, &hn), dq)
                } else {
                    // V × (0, a) = (0, ω × a).
                    (dot(&a, &hf), dot(&hf, &cross(&w, &a)))
                };
                dq.add(&dot(&a, if joint.kind == Kind::Revolute { &wn } else { &wf }), 1.0);
                gradients.push((joints[k].clone(), self.expr(&dq.render()), self.expr(&dv.render())));
            }
            if joint.parent == 0 {
                continue;
            }
            for (what, forces, (n, f)) in [("h", &mut momentum, (hn, hf)), ("w", &mut weight, (wn, wf))] {
                if n.iter().chain(&f).all(|x| x.as_atom() == Some(Atom::Num(0.0))) {
                    continue;
                }
                let (n, f) = self.moved_to_parent(joint, &format!("{link}_{what}"), &frames[l], n, f);
                for (total, x) in forces[joint.parent].iter_mut().flatten().zip(n.iter().chain(&f)) {
                    total.add(x, 1.0);
                }
            }
        }
        gradients.reverse();
        self.model.gradients = Some(gradients);
    }

    /// A force `(n, f)` in the axes of the link a joint moves, about its origin, in its parent's
    /// axes about the parent's origin: `(R n + d × R f, R f)`, its steps defined as `<name>_…`.
    fn moved_to_parent(
        &mut self,
        joint: &read::Joint,
        name: &str,
        frame: &Frame,
        n: [Poly; 3],
        f: [Poly; 3],
    ) -> ([Poly; 3], [Poly; 3]) {
        let turn = |w: &mut Self, step: &str, x: [Poly; 3]| -> [Poly; 3] {
            let x = w.bind3(&format!("{name}_{step}"), x);
            let turned = match &frame.turn {
                Some((cos, sin)) => {
                    w.bind3(&format!("{name}_{step}t"), rotate(&joint.axis, cos, sin, &x, 1.0))
                }
                None => x,
            };
            matvec(&joint.rotation, &turned)
        };
        let f = turn(self, "fp", f);
        let f = self.bind3(&format!("{name}_fq"), f).map(|a| Poly::atom(&a));
        let mut n = turn(self, "np", n);
        for (ni, di) in n.iter_mut().zip(cross(&frame.offset, &f)) {
            ni.add(&di, 1.0);
        }
        (n, f)
    }

    /// With `ground`, each point of the links' `<collision>` shapes that can touch the ground
    /// `z = 0` as a unilateral constraint, its height above the ground (less the radius of a
    /// sphere or capsule about it): a sphere's centre, a capsule's two ends, a box's eight
    /// corners. A cylinder's rim and a mesh are refused with their line.
    fn ground_contacts(&mut self, robot: &Robot, links: &[String], frames: &[Frame]) {
        let Some(ground) = self.model.ground.as_ref() else { return };
        let (key, friction) = (ground.key.clone(), ground.friction.clone());
        let restitution = ground.restitution.clone().unwrap_or_else(|| self.expr("0.0"));
        // Friction acts where a point rests: in the companion with contacts that can rest.
        let friction = friction.filter(|_| !self.model.switches.is_empty());
        let Some(only) = self.touching_links(robot) else { return };
        let mut touching = false;
        for ((link, name), frame) in robot.links.iter().zip(links).zip(frames) {
            if only.as_ref().is_some_and(|only| !only.contains(&link.name)) {
                continue;
            }
            let mut points = Vec::new();
            for collision in &link.collisions {
                let shape = &collision.shape;
                let at = |local: [f64; 3]| -> [f64; 3] {
                    std::array::from_fn(|i| {
                        shape.xyz[i] + (0..3).map(|j| shape.rotation[i][j] * local[j]).sum::<f64>()
                    })
                };
                match shape.geometry {
                    read::Geometry::Sphere(r) => points.push((at([0.0; 3]), r)),
                    read::Geometry::Capsule { radius, length } => {
                        points.push((at([0.0, 0.0, length / 2.0]), radius));
                        points.push((at([0.0, 0.0, -length / 2.0]), radius));
                    }
                    read::Geometry::Box([a, b, c]) => {
                        for corner in 0..8 {
                            let sign = |bit: usize| if corner >> bit & 1 == 0 { -0.5 } else { 0.5 };
                            points.push((at([sign(0) * a, sign(1) * b, sign(2) * c]), 0.0));
                        }
                    }
                    read::Geometry::Cylinder { .. } | read::Geometry::Mesh(_) => {
                        let why = match &shape.geometry {
                            read::Geometry::Mesh(file) => {
                                format!("a collision mesh (`{file}`) cannot touch the `ground`: its file is not read")
                            }
                            _ => "a collision cylinder cannot touch the `ground`: the height of its lowest point \
                                  has no derivative where it stands on a face"
                                .to_owned(),
                        };
                        let message = format!(
                            "{}, line {}, column {}: link `{}`: {why}; a shape that touches the ground is a \
                             sphere, a capsule or a box",
                            self.path.value(),
                            collision.line,
                            collision.column,
                            link.name
                        );
                        self.cx.error_spanned_by(self.path, message);
                        self.model.incomplete = true;
                        return;
                    }
                }
            }
            for (k, (point, radius)) in points.iter().enumerate() {
                let mut height = Poly::atom(&frame.origin[2]);
                for (r, x) in frame.rotation[2].iter().zip(point) {
                    height.add(&Poly::atom(r), *x);
                }
                height.add(&Poly::num(1.0), -radius);
                let contact = if points.len() == 1 {
                    format!("{name}_ground")
                } else {
                    format!("{name}_ground{}", k + 1)
                };
                self.model.unilaterals.push(UnilateralDecl {
                    name: Ident::new(&contact, self.span),
                    restitution: Some(restitution.clone()),
                    expr: self.expr(&height.render()),
                });
                if let Some(mu) = &friction {
                    let law = self.ground_cone(&contact, mu, frame, point, *radius);
                    self.model.laws.push(law);
                }
                touching = true;
            }
        }
        if !touching {
            self.cx.error_spanned_by(
                &key,
                format!(
                    "`ground`: no link of `{}` has a `<collision>` shape to touch it with",
                    self.path.value()
                ),
            );
        }
    }

    /// The names in `ground(links = ["foot", …])`, each a link of `robot` with a collision
    /// shape: `Some(None)` where it is not given (every link touches), `None` after an error.
    fn touching_links(&mut self, robot: &Robot) -> Option<Option<Vec<String>>> {
        let Some(expr) = self.model.ground.as_ref().and_then(|ground| ground.links.clone()) else {
            return Some(None);
        };
        let fail = |writer: &mut Self, at: &dyn quote::ToTokens, message: String| {
            writer.cx.error_spanned_by(at, message);
            writer.model.incomplete = true;
            None
        };
        let Expr::Array(array) = &expr else {
            return fail(
                self,
                &expr,
                "`links` names the links that touch the ground: `links = [\"foot\", …]`".into(),
            );
        };
        let mut names = Vec::new();
        for elem in &array.elems {
            let Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(name), .. }) = elem else {
                return fail(self, elem, "a link's name in `links`, as a string: `\"foot\"`".into());
            };
            let value = name.value();
            let Some(link) = robot.links.iter().find(|link| link.name == value) else {
                let hint = crate::suggest::did_you_mean(&value, robot.links.iter().map(|l| l.name.as_str()));
                return fail(self, name, format!("no link `{value}` in `{}`{hint}", self.path.value()));
            };
            if link.collisions.is_empty() {
                return fail(
                    self,
                    name,
                    format!("link `{value}` has no `<collision>` shape to touch the ground with"),
                );
            }
            names.push(value);
        }
        if names.is_empty() {
            return fail(
                self,
                &expr,
                "`links` is empty: name at least one link that touches the ground".into(),
            );
        }
        Some(Some(names))
    }

    /// Coulomb's cone `<contact>_slip` at the point `point` (in the axes of the link at
    /// `frame`) less `radius` below it, where it rests on the ground: against the point's slip
    /// `(ẋ, ẏ)` in the world, `R (v + ω × p) + ω_w × (0, 0, −r)` (`ω_w = R ω`), with the kinetic
    /// force `mu` times the contact's force, and on only while the contact is closed.
    fn ground_cone(
        &mut self,
        contact: &str,
        mu: &Expr,
        frame: &Frame,
        point: &[f64; 3],
        radius: f64,
    ) -> LawDecl {
        let omega: [Poly; 3] = frame.omega.clone().map(|a| Poly::atom(&a));
        let mut moving = cross(&omega, &point.map(Poly::num));
        moving.iter_mut().zip(&frame.velocity).for_each(|(m, v)| m.add(&Poly::atom(v), 1.0));
        let world = |i: usize, of: &[Poly; 3]| {
            let mut s = Poly::default();
            for (r, x) in frame.rotation[i].iter().zip(of) {
                s.add(&Poly::atom(r).mul(x), 1.0);
            }
            s
        };
        let (mut x, mut y) = (world(0, &moving), world(1, &moving));
        x.add(&world(1, &omega), -radius);
        y.add(&world(0, &omega), radius);
        let force = Ident::new(&format!("{contact}_force"), self.span);
        let kinetic: Expr = syn::parse_quote_spanned!(self.span=> (#mu) * #force);
        LawDecl {
            kind: LawKind::Friction,
            name: Ident::new(&format!("{contact}_slip"), self.span),
            g: self.expr(&x.render()),
            g2: Some(self.expr(&y.render())),
            kinetic: Some(kinetic),
            stiction: None,
            closed: None,
            gate: Some(Ident::new(&format!("{contact}_closed"), self.span)),
        }
    }

    /// `gravity = [gx, gy, gz]` as three definitions, `None` inside for `(0, 0, −9.81)`; the
    /// outer `None` after an error.
    fn gravity(&mut self) -> Option<Option<[Atom; 3]>> {
        let Some((key, expr)) = self.model.gravity.clone() else { return Some(None) };
        let elems = match &expr {
            Expr::Array(array) if array.elems.len() == 3 => array.elems.iter().cloned().collect::<Vec<_>>(),
            _ => {
                self.cx.error_spanned_by(
                    &expr,
                    format!(
                        "`{key}` is three expressions, `[gx, gy, gz]`: the acceleration of gravity in the world's \
                         axes, in m/s² (`[0.0, 0.0, -9.81]` pulls down the z axis)"
                    ),
                );
                self.model.incomplete = true;
                return None;
            }
        };
        let mut atoms = Vec::new();
        for (axis, expr) in XYZ.iter().zip(elems) {
            let name = format!("gravity_{axis}");
            self.model.defines.push(DefineDecl { name: Ident::new(&name, key.span()), expr });
            atoms.push(Atom::Name(name));
        }
        Some(Some(atoms.try_into().expect("three axes")))
    }

    /// The frame of a link a floating joint moves: its coordinates are the link's origin and
    /// rotation `R` in the joint's frame, held orthogonal by six holonomic rows. Its angular
    /// velocity in its own axes is read off `Ω̂ = RᵀṘ` and its origin's velocity is `Rᵀ ẋ`.
    fn free_frame(&mut self, joint: &read::Joint, link: &str, name: &str) -> Frame {
        let coordinate = |suffix: &str| Atom::Name(format!("{name}_{suffix}"));
        let rate = |suffix: &str| Atom::Name(format!("v_{name}_{suffix}"));
        let r: [[Atom; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|j| coordinate(&format!("r{}{}", i + 1, j + 1))));
        let dr: [[Atom; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|j| rate(&format!("r{}{}", i + 1, j + 1))));
        // Column products: c_a · ċ_b.
        let column = |a: usize, b: usize| {
            let mut s = Poly::default();
            for m in 0..3 {
                s.add(&Poly::atom(&r[m][a]).mul(&Poly::atom(&dr[m][b])), 1.0);
            }
            s
        };
        let omega = self.bind3(&format!("{link}_w"), [column(2, 1), column(0, 2), column(1, 0)]);
        let velocity = self.bind3(
            &format!("{link}_v"),
            std::array::from_fn(|i| {
                let mut s = Poly::default();
                for (m, axis) in XYZ.iter().enumerate() {
                    s.add(&Poly::atom(&r[m][i]).mul(&Poly::atom(&rate(axis))), 1.0);
                }
                s
            }),
        );
        // In the world (the root's frame is the world's): E R and xyz + E x.
        let rotation = std::array::from_fn(|i| {
            let row = std::array::from_fn(|j| {
                let mut s = Poly::default();
                for (m, rm) in r.iter().enumerate() {
                    s.add(&Poly::atom(&rm[j]), joint.rotation[i][m]);
                }
                s
            });
            self.bind3(&format!("{link}_r{}", i + 1), row)
        });
        let origin = std::array::from_fn(|i| {
            let mut s = Poly::num(joint.xyz[i]);
            for (m, axis) in XYZ.iter().enumerate() {
                s.add(&Poly::atom(&coordinate(axis)), joint.rotation[i][m]);
            }
            s
        });
        let origin = self.bind3(&format!("{link}_o"), origin);
        // RᵀR = I: unit columns, orthogonal to each other.
        for (a, b) in [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)] {
            let mut phi = Poly::default();
            for rm in &r {
                phi.add(&Poly::atom(&rm[a]).mul(&Poly::atom(&rm[b])), 1.0);
            }
            let row_name = if a == b {
                phi.add(&Poly::num(1.0), -1.0);
                format!("{name}_unit{}", a + 1)
            } else {
                format!("{name}_square{}{}", a + 1, b + 1)
            };
            self.model.constraints.push(ConstraintDecl {
                kind: ConstraintKind::Holonomic,
                key: Ident::new("holonomic", self.span),
                name: Some(Ident::new(&row_name, self.span)),
                expr: self.expr(&phi.render()),
            });
        }
        Frame { omega, velocity, rotation, origin, turn: None, offset: joint.xyz.map(Poly::num) }
    }

    /// The frame of a link a revolute, prismatic or fixed joint moves from its parent's.
    fn moved_frame(&mut self, joint: &read::Joint, link: &str, coordinate: &str, parent: &Frame) -> Frame {
        let zero = || [Atom::Num(0.0), Atom::Num(0.0), Atom::Num(0.0)];
        let (q, v) = (Atom::Name(coordinate.to_owned()), Atom::Name(format!("v_{coordinate}")));
        // The rotation about the axis, as (cos, sin) definitions, for a revolute joint.
        let turn = (joint.kind == Kind::Revolute).then(|| {
            let cos = self.define(format!("{link}_cos"), &format!("{coordinate}.cos()"));
            let sin = self.define(format!("{link}_sin"), &format!("{coordinate}.sin()"));
            (cos, sin)
        });
        // d: the child's origin in the parent's frame.
        let mut d: [Poly; 3] = joint.xyz.map(Poly::num);
        if joint.kind == Kind::Prismatic {
            let along = matvec(&joint.rotation, &joint.axis.map(Atom::Num));
            for (di, ai) in d.iter_mut().zip(&along) {
                di.add(&ai.mul(&Poly::atom(&q)), 1.0);
            }
        }
        // ω_k and v_k in the child's axes.
        let w_in_joint =
            self.bind3(&format!("{link}_wj"), matvec(&read::transpose(&joint.rotation), &parent.omega));
        let mut arm = cross(&parent.omega.clone().map(|a| Poly::atom(&a)), &d);
        for (ai, vi) in arm.iter_mut().zip(&parent.velocity) {
            ai.add(&Poly::atom(vi), 1.0);
        }
        let arm = self.bind3(&format!("{link}_uj"), arm);
        let arm_in_joint = self.bind3(&format!("{link}_vj"), matvec(&read::transpose(&joint.rotation), &arm));
        let (mut omega, mut velocity) = match &turn {
            Some((cos, sin)) => (
                rotate_back(&joint.axis, cos, sin, &w_in_joint),
                rotate_back(&joint.axis, cos, sin, &arm_in_joint),
            ),
            None => {
                (w_in_joint.clone().map(|a| Poly::atom(&a)), arm_in_joint.clone().map(|a| Poly::atom(&a)))
            }
        };
        let rate = Poly::atom(&v);
        match joint.kind {
            Kind::Revolute => omega.iter_mut().zip(joint.axis).for_each(|(w, a)| w.add(&rate, a)),
            Kind::Prismatic => velocity.iter_mut().zip(joint.axis).for_each(|(u, a)| u.add(&rate, a)),
            Kind::Fixed | Kind::Floating | Kind::Planar => {}
        }
        let omega = self.bind3(&format!("{link}_w"), omega);
        let velocity = self.bind3(&format!("{link}_v"), velocity);
        // The rotation and origin in the world: R_p E Rot(a, q), and o_p + R_p d.
        let pe: [[Poly; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let mut s = Poly::default();
                for m in 0..3 {
                    s.add(&Poly::atom(&parent.rotation[i][m]), joint.rotation[m][j]);
                }
                s
            })
        });
        let mut rotation: [[Atom; 3]; 3] = std::array::from_fn(|_| zero());
        for (i, row) in pe.into_iter().enumerate() {
            let row = self.bind3(&format!("{link}_e{}", i + 1), row);
            let row = match &turn {
                // Row i of R_p E Rot is Rotᵀ applied to row i of R_p E.
                Some((cos, sin)) => rotate_back(&joint.axis, cos, sin, &row),
                None => row.map(|a| Poly::atom(&a)),
            };
            rotation[i] = self.bind3(&format!("{link}_r{}", i + 1), row);
        }
        let mut origin: [Poly; 3] = parent.origin.clone().map(|a| Poly::atom(&a));
        for (i, o) in origin.iter_mut().enumerate() {
            for (m, dm) in d.iter().enumerate() {
                o.add(&Poly::atom(&parent.rotation[i][m]).mul(dm), 1.0);
            }
        }
        let origin = self.bind3(&format!("{link}_o"), origin);
        Frame { omega, velocity, rotation, origin, turn, offset: d }
    }

    /// Mimic joints as holonomic rows, damping as a Rayleigh function.
    fn joint_laws(&mut self, robot: &Robot, joints: &[String]) {
        let mut rayleigh = Poly::default();
        for (k, joint) in robot.joints.iter().enumerate() {
            if matches!(joint.kind, Kind::Fixed | Kind::Floating) {
                continue;
            }
            let v = Poly::atom(&Atom::Name(format!("v_{}", joints[k])));
            rayleigh.add(&v.mul(&v), 0.5 * joint.damping);
            if joint.friction > 0.0 {
                self.model.laws.push(LawDecl {
                    kind: LawKind::Friction,
                    name: Ident::new(&format!("{}_friction", joints[k]), self.span),
                    g: self.expr(&v.render()),
                    g2: None,
                    kinetic: Some(self.expr(&format!("{:?}", joint.friction))),
                    stiction: None,
                    closed: None,
                    gate: None,
                });
            }
            if let (Some((lower, upper)), true, None) =
                (joint.limits, self.model.joint_limits.is_some(), &joint.mimic)
            {
                // A mimic joint's stops are its leader's: both would be redundant rows.
                let zero = self.expr("0.0");
                for (side, phi) in [
                    ("lower", format!("{} - {lower:?}", joints[k])),
                    ("upper", format!("{upper:?} - {}", joints[k])),
                ] {
                    self.model.unilaterals.push(UnilateralDecl {
                        name: Ident::new(&format!("{}_{side}", joints[k]), self.span),
                        restitution: Some(zero.clone()),
                        expr: self.expr(&phi),
                    });
                }
            }
            if let Some(mimic) = &joint.mimic {
                let Some(leader) = robot.joints.iter().position(|j| {
                    j.name == mimic.joint && matches!(j.kind, Kind::Revolute | Kind::Prismatic)
                }) else {
                    let message = format!(
                        "{}: joint `{}` mimics `{}`, which is no moving joint of the robot",
                        self.path.value(),
                        joint.name,
                        mimic.joint
                    );
                    self.cx.error_spanned_by(self.path, message);
                    continue;
                };
                let mut phi = Poly::atom(&Atom::Name(joints[k].clone()));
                phi.add(&Poly::atom(&Atom::Name(joints[leader].clone())), -mimic.multiplier);
                phi.add(&Poly::num(mimic.offset), -1.0);
                let name = Ident::new(&format!("{}_mimic", joints[k]), self.span);
                self.model.constraints.push(ConstraintDecl {
                    kind: ConstraintKind::Holonomic,
                    key: Ident::new("holonomic", self.span),
                    name: Some(name),
                    expr: self.expr(&phi.render()),
                });
            }
        }
        if !rayleigh.terms.is_empty() {
            if self.model.dissipation.is_some() {
                let message = "the URDF's joints have `damping`, which is the model's dissipation; \
                               remove `dissipation = …` or the damping";
                self.cx.error_spanned_by(self.path, message);
                return;
            }
            self.model.dissipation =
                Some((Ident::new("dissipation", self.span), self.expr(&rayleigh.render())));
        }
    }

    /// The identifiers of the links and the moving joints, or `None` after an error.
    fn identifiers(&mut self, robot: &Robot) -> Option<(Vec<String>, Vec<String>)> {
        let mut ok = true;
        // A link's name only starts the names of its quantities (`box_x`, so `box` will do); a
        // joint's is its coordinate's.
        let mut ident = |what: &str, name: &str, used: &str| {
            let id: String =
                name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '_' { c } else { '_' }).collect();
            let id = if id.starts_with(|c: char| c.is_ascii_digit()) { format!("_{id}") } else { id };
            if syn::parse_str::<Ident>(&format!("{id}{used}")).is_err() {
                let message = format!("{}: {what} `{name}` cannot be a Rust name", self.path.value());
                self.cx.error_spanned_by(self.path, message);
                ok = false;
            }
            id
        };
        let links: Vec<String> = robot.links.iter().map(|l| ident("link", &l.name, "_x")).collect();
        let joints: Vec<String> = robot.joints.iter().map(|j| ident("joint", &j.name, "")).collect();
        if !ok {
            // Nothing of the robot is in the model: its other errors would only mislead.
            self.model.incomplete = true;
            return None;
        }
        for (k, joint) in robot.joints.iter().enumerate() {
            let names = match joint.kind {
                Kind::Fixed => continue,
                // The origin, then the rotation row by row.
                Kind::Floating => XYZ
                    .iter()
                    .map(|axis| format!("{}_{axis}", joints[k]))
                    .chain(
                        (1..=3)
                            .flat_map(|i| (1..=3).map(move |j| (i, j)))
                            .map(|(i, j)| format!("{}_r{i}{j}", joints[k])),
                    )
                    .collect(),
                _ => vec![joints[k].clone()],
            };
            for coordinate in names {
                let name = Ident::new(&coordinate, self.span);
                let velocity = Ident::new(&format!("v_{coordinate}"), self.span);
                self.model.ports.push(name.clone());
                self.model.coordinates.push(CoordinateDecl { name, velocity });
            }
        }
        if self.model.coordinates.is_empty() {
            let message = format!("{}: the robot has no moving joint", self.path.value());
            self.cx.error_spanned_by(self.path, message);
            self.model.incomplete = true;
            return None;
        }
        Some((links, joints))
    }

    fn expr(&self, text: &str) -> Expr {
        let expr: Expr = syn::parse_str(text).expect("a rendered expression parses");
        respan(expr, self.span)
    }

    fn define(&mut self, name: String, text: &str) -> Atom {
        let expr = self.expr(text);
        self.model.defines.push(DefineDecl { name: Ident::new(&name, self.span), expr });
        Atom::Name(name)
    }

    /// The link's origin in the world, `<link>_x`, `_y`, `_z`, and its rotation, `<link>_r11`
    /// to `_r33`: entry `(i, j)` of the matrix whose columns are the link's axes in the world.
    fn pose_outputs(&mut self, link: &str, frame: &Frame) {
        for (axis, value) in XYZ.iter().zip(&frame.origin) {
            self.output(format!("{link}_{axis}"), &Poly::atom(value).render());
        }
        for (i, row) in frame.rotation.iter().enumerate() {
            for (j, value) in row.iter().enumerate() {
                self.output(format!("{link}_r{}{}", i + 1, j + 1), &Poly::atom(value).render());
            }
        }
    }

    fn output(&mut self, name: String, text: &str) {
        let expr = self.expr(text);
        self.model.outputs.push(DefineDecl { name: Ident::new(&name, self.span), expr });
    }

    /// The quantity as a definition, unless it is a number or a name already.
    fn bind(&mut self, name: String, p: Poly) -> Atom {
        match p.as_atom() {
            Some(atom) => atom,
            None => self.define(name, &p.render()),
        }
    }

    fn bind3(&mut self, name: &str, p: [Poly; 3]) -> [Atom; 3] {
        let [a, b, c] = p;
        [self.bind(format!("{name}x"), a), self.bind(format!("{name}y"), b), self.bind(format!("{name}z"), c)]
    }
}

/// The momenta of a floating robot, summed link by link in the world's axes: the linear momentum
/// `Σ m W v_c` and the angular momentum about the world's origin `Σ W I ω + c × m W v_c`.
#[derive(Default)]
struct Momenta {
    linear: [Poly; 3],
    angular: [Poly; 3],
}

impl Momenta {
    fn add(
        &mut self,
        writer: &mut Writer<'_, '_, '_>,
        link: &str,
        body: &read::Link,
        frame: &Frame,
        vc: &[Atom; 3],
    ) {
        let world = |writer: &mut Writer<'_, '_, '_>, name: &str, x: [Poly; 3]| {
            let x = writer.bind3(name, x).map(|a| Poly::atom(&a));
            let turned = std::array::from_fn(|i| {
                let mut s = Poly::default();
                for (r, xj) in frame.rotation[i].iter().zip(&x) {
                    s.add(&Poly::atom(r).mul(xj), 1.0);
                }
                s
            });
            writer.bind3(&format!("{name}_world"), turned).map(|a| Poly::atom(&a))
        };
        let momentum =
            world(writer, &format!("{link}_p"), vc.clone().map(|a| Poly::atom(&a).scaled(body.mass)));
        let spin = std::array::from_fn(|i| {
            let mut s = Poly::default();
            for (w, inertia) in frame.omega.iter().zip(body.inertia[i]) {
                s.add(&Poly::atom(w), inertia);
            }
            s
        });
        let spin = world(writer, &format!("{link}_h"), spin);
        let centre: [Poly; 3] = std::array::from_fn(|i| {
            let mut s = Poly::atom(&frame.origin[i]);
            for (r, c) in frame.rotation[i].iter().zip(body.com) {
                s.add(&Poly::atom(r), c);
            }
            s
        });
        let centre = writer.bind3(&format!("{link}_cw"), centre).map(|a| Poly::atom(&a));
        let moment = cross(&centre, &momentum);
        for i in 0..3 {
            self.linear[i].add(&momentum[i], 1.0);
            self.angular[i].add(&spin[i], 1.0);
            self.angular[i].add(&moment[i], 1.0);
        }
    }

    /// `linear_momentum_x` … and `angular_momentum_x` …, if any link moved.
    fn outputs(self, writer: &mut Writer<'_, '_, '_>) {
        if self.linear.iter().all(|p| p.terms.is_empty()) && self.angular.iter().all(|p| p.terms.is_empty()) {
            return;
        }
        for (what, momentum) in [("linear", &self.linear), ("angular", &self.angular)] {
            for (axis, p) in XYZ.iter().zip(momentum) {
                writer.output(format!("{what}_momentum_{axis}"), &p.render());
            }
        }
    }
}

/// `m x` for a numeric matrix.
fn matvec(m: &Mat3, x: &[Atom; 3]) -> [Poly; 3] {
    std::array::from_fn(|i| {
        let mut s = Poly::default();
        for (j, xj) in x.iter().enumerate() {
            s.add(&Poly::atom(xj), m[i][j]);
        }
        s
    })
}

fn cross(a: &[Poly; 3], b: &[Poly; 3]) -> [Poly; 3] {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let mut s = a[j].mul(&b[k]);
        s.add(&a[k].mul(&b[j]), -1.0);
        s
    })
}

/// `Rot(a, q)ᵀ y = cos q (y − a (a·y)) − sin q (a × y) + a (a·y)`.
fn rotate_back(axis: &[f64; 3], cos: &Atom, sin: &Atom, y: &[Atom; 3]) -> [Poly; 3] {
    rotate(axis, cos, sin, y, -1.0)
}

/// `Rot(a, ±q) y = cos q (y − a (a·y)) ± sin q (a × y) + a (a·y)`, the sign `turn`.
fn rotate(axis: &[f64; 3], cos: &Atom, sin: &Atom, y: &[Atom; 3], turn: f64) -> [Poly; 3] {
    let y: [Poly; 3] = y.clone().map(|a| Poly::atom(&a));
    let mut along = Poly::default();
    for (a, yi) in axis.iter().zip(&y) {
        along.add(yi, *a);
    }
    let a: [Poly; 3] = axis.map(Poly::num);
    let a_cross_y = cross(&a, &y);
    let (cos, sin) = (Poly::atom(cos), Poly::atom(sin));
    std::array::from_fn(|i| {
        let mut perp = y[i].clone();
        perp.add(&along, -axis[i]);
        let mut out = cos.mul(&perp);
        out.add(&sin.mul(&a_cross_y[i]), turn);
        out.add(&along, axis[i]);
        out
    })
}

/// The expression with every token at `span`, so errors and lints point at the attribute.
fn respan(expr: Expr, span: Span) -> Expr {
    use quote::ToTokens;
    let tokens: proc_macro2::TokenStream = expr
        .into_token_stream()
        .into_iter()
        .map(|mut t| {
            set_span(&mut t, span);
            t
        })
        .collect();
    syn::parse2(tokens).expect("respanned tokens parse")
}

fn set_span(token: &mut proc_macro2::TokenTree, span: Span) {
    use proc_macro2::{Group, TokenTree};
    match token {
        TokenTree::Group(g) => {
            let inner = g
                .stream()
                .into_iter()
                .map(|mut t| {
                    set_span(&mut t, span);
                    t
                })
                .collect();
            let mut group = Group::new(g.delimiter(), inner);
            group.set_span(span);
            *g = group;
        }
        other => other.set_span(span),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_malformed_file_is_an_error_at_the_attribute_with_its_line() {
        let dir = std::env::temp_dir().join(format!("dirac-urdf-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary folder");
        let file = dir.join("bad.urdf");
        let text = "<robot name=\"r\">\n<link name=\"a\"/>\n<joint name=\"j\" type=\"spherical\">\n</joint>\n</robot>";
        std::fs::write(&file, text).expect("written");
        let path = file.display().to_string();
        let input: syn::DeriveInput = syn::parse_quote! {
            #[dirac(urdf = #path)]
            struct Bad;
        };
        let out = crate::lagrange_dirac(&input).to_string();
        assert!(out.contains("line 3, column 1: joint `j` is `spherical`, which is not supported"), "{out}");
        let input: syn::DeriveInput = syn::parse_quote! {
            #[dirac(urdf = "no/such.urdf")]
            struct Missing;
        };
        let out = crate::lagrange_dirac(&input).to_string();
        assert!(out.contains("cannot read the URDF `no/such.urdf`"), "{out}");
        std::fs::remove_dir_all(&dir).ok();
    }

    /// `ground` refuses a collision cylinder at its line and a robot with nothing to touch it
    /// with, and writes a box's eight corners as contacts.
    #[test]
    fn the_ground_is_touched_by_spheres_capsules_and_boxes_only() {
        let dir = std::env::temp_dir().join(format!("dirac-ground-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary folder");
        let expand = |name: &str, link: &str| {
            let file = dir.join(name);
            let inertial = "<inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>";
            let text = format!("<robot name=\"r\">\n<link name=\"a\">{inertial}\n{link}\n</link>\n</robot>");
            std::fs::write(&file, text).expect("written");
            let path = file.display().to_string();
            let input: syn::DeriveInput = syn::parse_quote! {
                #[dirac(urdf = #path, floating, ground)]
                struct Robot;
            };
            crate::lagrange_dirac(&input).to_string()
        };
        let out = expand(
            "cylinder.urdf",
            "<collision><geometry><cylinder radius=\"1\" length=\"1\"/></geometry></collision>",
        );
        assert!(
            out.contains("line 3, column 1: link `a`: a collision cylinder cannot touch the `ground`"),
            "{out}"
        );
        let out = expand("none.urdf", "");
        assert!(out.contains("no link of"), "{out}");
        let out = expand("box.urdf", "<collision><geometry><box size=\"1 1 1\"/></geometry></collision>");
        assert!(!out.contains("compile_error"), "{}", &out[..out.len().min(3000)]);
        for k in 1..=8 {
            assert!(out.contains(&format!("\"a_ground{k}\"")), "corner {k}");
        }
        assert!(!out.contains("\"a_ground9\""));
        std::fs::remove_dir_all(&dir).ok();
    }

    /// `ground(friction = mu, links = [...])`: the cone of each point of the links named, in the
    /// companion only (the model itself has no contact force to push with), gated by its
    /// contact's `closed`; the other link's shapes touch nothing.
    #[test]
    fn the_ground_with_friction_puts_a_cone_at_each_resting_point_of_the_links_named() {
        let dir = std::env::temp_dir().join(format!("dirac-ground-friction-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary folder");
        let file = dir.join("two.urdf");
        let inertial = "<inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>";
        let sphere = "<collision><geometry><sphere radius=\"0.1\"/></geometry></collision>";
        let text = format!(
            "<robot name=\"r\"><link name=\"a\">{inertial}{sphere}</link>\
             <joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/><origin xyz=\"1 0 0\"/></joint>\
             <link name=\"b\">{inertial}{sphere}</link></robot>"
        );
        std::fs::write(&file, text).expect("written");
        let path = file.display().to_string();
        let input: syn::DeriveInput = syn::parse_quote! {
            #[dirac(urdf = #path, floating, ground(friction = mu, links = ["b"]))]
            struct Robot { mu: f64 }
        };
        let out = crate::lagrange_dirac(&input).to_string();
        assert!(!out.contains("compile_error"), "{}", &out[..out.len().min(3000)]);
        assert!(out.contains("\"b_ground\"") && !out.contains("\"a_ground\""), "only `b` touches");
        // The model's own names list no cone; its companion's does, with both events.
        let model = out.find("RobotWithContacts").expect("a companion");
        assert!(!out[..model].contains("b_ground_slip"), "no cone outside the companion");
        for name in ["\"b_ground_slip_stops\"", "\"b_ground_slip_slips\"", "\"b_ground_slip_mode_1\""] {
            assert!(out[model..].contains(name), "{name}");
        }
        assert!(out[model..].contains("b_ground_closed"), "gated by the contact");
        std::fs::remove_dir_all(&dir).ok();
    }

    /// The humanoid (4 s unoptimised): only with `DIRAC_TALOS=1`, from
    /// `benches/robot_build.sh`'s instructions.
    #[test]
    fn talos_expands() {
        if std::env::var_os("DIRAC_TALOS").is_none() {
            return;
        }
        let input: syn::DeriveInput = syn::parse_quote! {
            #[dirac(urdf = "../tests/robots/talos/talos_reduced.urdf", large)]
            struct Talos;
        };
        let start = std::time::Instant::now();
        let out = crate::lagrange_dirac(&input).to_string();
        eprintln!("expanded in {:?}, {} bytes", start.elapsed(), out.len());
        assert!(!out.contains("compile_error"), "{}", &out[..out.len().min(3000)]);
    }

    /// The joints' `∂L/∂q` and `∂L/∂v` that the blocks read, from the tree's momenta and weights
    /// ([`Writer::gradients`]), against the Lagrangian's gradient that the graph differentiates
    /// link by link (the reference: the links' energies as written), at states of the Panda's
    /// nine joints (seven turns, two slides, one mimicking the other) drawn from a fixed
    /// sequence, under its default gravity and under a gravity of three parameters, and of
    /// Talos's 32 (a tree of five branches; its 20 friction laws' modes are the Lagrangian's).
    #[test]
    fn a_trees_gradients_from_its_momenta_equal_the_lagrangians() {
        let inputs: [(syn::DeriveInput, usize); 3] = [
            (
                syn::parse_quote! {
                    #[dirac(urdf = "../tests/robots/panda/panda.urdf")]
                    struct Panda;
                },
                9,
            ),
            (
                syn::parse_quote! {
                    #[dirac(urdf = "../tests/robots/panda/panda.urdf", gravity = [gx, gy, gz - 1.0])]
                    struct Panda { gx: f64, gy: f64, gz: f64 }
                },
                9,
            ),
            (
                syn::parse_quote! {
                    #[dirac(urdf = "../tests/robots/talos/talos_reduced.urdf", large)]
                    struct Talos;
                },
                32,
            ),
        ];
        for (input, joints) in &inputs {
            let cx = crate::ctxt::Ctxt::new();
            let model = crate::desugar::read(&cx, input);
            let mut sym = crate::model::SymModel::build(&cx, &model).expect("the Panda lowers");
            assert!(cx.into_compile_errors().is_none());
            let (dl_dq, dl_dv) = sym.gradients.clone().expect("a tree fixed in the world");
            assert_eq!(model.gradients.as_ref().map(Vec::len), Some(*joints));
            // Every symbol a value of its own, in [−1, 1].
            let value = |s: u32| (f64::from(s) * 12.9898 + 0.7).sin();
            for i in 0..sym.n() {
                let (q, v, l) = (sym.q[i], sym.v[i], sym.lagrangian);
                for (given, wrt) in [(dl_dq[i], q), (dl_dv[i], v)] {
                    let reference = sym.graph.diff(l, wrt);
                    let (a, b) = (sym.graph.eval(given, &value), sym.graph.eval(reference, &value));
                    assert!(
                        (a - b).abs() <= 1e-12 * (1.0 + b.abs()),
                        "{}: {a} against {b}",
                        sym.coordinates[i]
                    );
                }
            }
        }
    }

    #[test]
    fn panda_expands() {
        let input: syn::DeriveInput = syn::parse_quote! {
            #[dirac(urdf = "../tests/robots/panda/panda.urdf")]
            struct Panda;
        };
        let start = std::time::Instant::now();
        let out = crate::lagrange_dirac(&input).to_string();
        eprintln!("expanded in {:?}, {} bytes", start.elapsed(), out.len());
        assert!(!out.contains("compile_error"), "{}", &out[..out.len().min(3000)]);
    }
}
