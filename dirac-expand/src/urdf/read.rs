//! Reading a URDF file into a kinematic tree: links with their inertia, joints with their
//! frames and axes. Every malformed or unsupported element is an error naming it and its line.

use std::collections::HashMap;
use std::fmt;

/// A 3 × 3 matrix, row-major.
pub type Mat3 = [[f64; 3]; 3];

/// A robot as its URDF describes it, with the links in tree order (parents before children).
pub struct Robot {
    /// The links; the first is the root, fixed in the world (a frame of its own, not shown, when
    /// the robot is asked to float).
    pub links: Vec<Link>,
    /// The joints in tree order: joint `k` moves `links[k + 1]`.
    pub joints: Vec<Joint>,
}

/// A link: a rigid body with its mass, centre of mass and inertia in its own frame.
pub struct Link {
    pub name: String,
    pub mass: f64,
    /// The centre of mass in the link's frame.
    pub com: [f64; 3],
    /// The inertia tensor about the centre of mass, in the link's axes.
    pub inertia: Mat3,
    /// Whether the link is the file's (its pose an output), not a frame the reader added: the
    /// world a floating robot moves in, or the frames between a planar joint's three motions.
    pub shown: bool,
    /// Its `<visual>` shapes, as a view draws them.
    pub visuals: Vec<Shape>,
    /// Its `<collision>` shapes, where it touches the ground.
    pub collisions: Vec<Collision>,
}

/// A `<collision>`: its shape (no colour), and where it is written, for errors about it.
pub struct Collision {
    pub shape: Shape,
    pub line: u32,
    pub column: u32,
}

/// A `<visual>`: its geometry, its frame in the link's, and its colour.
pub struct Shape {
    pub geometry: Geometry,
    pub xyz: [f64; 3],
    pub rotation: Mat3,
    /// `<material>`'s `<color rgba="…"/>`, inline or by the name of the robot's material.
    pub color: Option<[f64; 4]>,
}

/// A `<geometry>`'s shape.
pub enum Geometry {
    Box([f64; 3]),
    Sphere(f64),
    Cylinder { radius: f64, length: f64 },
    Capsule { radius: f64, length: f64 },
    Mesh(String),
}

/// The kinds of joints this reader accepts.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Kind {
    /// `revolute` and `continuous`: a rotation about the axis.
    Revolute,
    /// A slide along the axis.
    Prismatic,
    /// No motion.
    Fixed,
    /// A free motion in space (six degrees of freedom), its rotation carried by the nine
    /// entries of a matrix held orthogonal; only between the root and its child.
    Floating,
    /// `planar` as written, a motion in the plane normal to the axis; the reader turns it into
    /// two slides and a turn, so no joint of a [`Robot`] has this kind.
    Planar,
}

/// A joint: the frame of its child link in its parent's, and its motion.
pub struct Joint {
    pub name: String,
    pub kind: Kind,
    /// The parent link's index in [`Robot::links`].
    pub parent: usize,
    /// The translation of the joint frame in the parent link's frame.
    pub xyz: [f64; 3],
    /// The rotation of the joint frame in the parent link's frame.
    pub rotation: Mat3,
    /// The unit axis, in the joint frame.
    pub axis: [f64; 3],
    /// `<mimic joint multiplier offset>`: this joint follows another.
    pub mimic: Option<Mimic>,
    /// `<dynamics damping>`: a viscous torque (or force) `−d q̇`.
    pub damping: f64,
    /// `<dynamics friction>`: the Coulomb friction torque (or force) that holds the joint
    /// while it can and opposes its motion while it slips.
    pub friction: f64,
    /// `<limit lower upper>` of a revolute or prismatic joint.
    pub limits: Option<(f64, f64)>,
}

/// `<mimic joint="…" multiplier="…" offset="…"/>`: `q = multiplier · q_joint + offset`.
pub struct Mimic {
    pub joint: String,
    pub multiplier: f64,
    pub offset: f64,
}

/// What is wrong with a URDF, and where.
#[derive(Debug)]
pub struct Error {
    pub line: u32,
    pub column: u32,
    pub message: String,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}, column {}: {}", self.line, self.column, self.message)
    }
}

type Node<'a, 'i> = roxmltree::Node<'a, 'i>;

/// Reads a robot from the text of a URDF file.
/// Reads a robot from the text of a URDF file; with `float_root`, its root moves freely in the
/// world, by a floating joint [`FLOATING_ROOT`] from a world frame of its own.
pub fn parse(text: &str, float_root: bool) -> Result<Robot, Error> {
    let doc = roxmltree::Document::parse(text).map_err(|e| {
        let pos = e.pos();
        Error { line: pos.row, column: pos.col, message: format!("not well-formed XML: {e}") }
    })?;
    let at = |node: Node<'_, '_>, message: String| {
        let pos = doc.text_pos_at(node.range().start);
        Error { line: pos.row, column: pos.col, message }
    };
    let root = doc.root_element();
    if root.tag_name().name() != "robot" {
        return Err(at(
            root,
            format!("the root element is `<{}>`; a URDF's is `<robot>`", root.tag_name().name()),
        ));
    }
    // The robot's named materials, which a visual may name.
    let mut materials = HashMap::new();
    for material in root.children().filter(|c| c.is_element() && c.tag_name().name() == "material") {
        if let (Some(name), Some(color)) = (material.attribute("name"), element(material, "color")) {
            materials.insert(name.to_owned(), rgba(color, &at)?);
        }
    }
    let mut links = Vec::new();
    let mut link_nodes = Vec::new();
    let mut joint_nodes = Vec::new();
    for child in root.children().filter(Node::is_element) {
        match child.tag_name().name() {
            "link" => {
                links.push(read_link(child, &materials, &at)?);
                link_nodes.push(child);
            }
            "joint" => joint_nodes.push(child),
            // Not dynamics: materials, sensors, Gazebo and transmission settings.
            "material" | "gazebo" | "transmission" | "sensor" => {}
            other => {
                return Err(at(
                    child,
                    format!(
                        "`<{other}>` is not supported; a robot is made of `<link>` and `<joint>` elements"
                    ),
                ));
            }
        }
    }
    let mut index: HashMap<&str, usize> = HashMap::new();
    for (i, l) in links.iter().enumerate() {
        if index.insert(l.name.as_str(), i).is_some() {
            return Err(at(link_nodes[i], format!("a second link named `{}`", l.name)));
        }
    }
    // Each joint: its parent and child link indices, read in the file's order.
    let mut read = Vec::new();
    let mut parent_of: Vec<Option<usize>> = vec![None; links.len()];
    for node in &joint_nodes {
        let (joint, child) = read_joint(*node, &index, &at)?;
        if parent_of[child].is_some() {
            return Err(at(
                *node,
                format!(
                    "link `{}` is the child of a second joint, `{}`: a URDF is a tree (close loops with \
                     `holonomic` rows on an interconnection)",
                    links[child].name, joint.name
                ),
            ));
        }
        if read.iter().any(|(j, _): &(Joint, usize)| j.name == joint.name) {
            return Err(at(*node, format!("a second joint named `{}`", joint.name)));
        }
        parent_of[child] = Some(read.len());
        read.push((joint, child));
    }
    // A cycle of joints, named by its joints, at the first of them in the file.
    let cycle_from = |link: usize| {
        let (mut seen, mut at_link) = (Vec::new(), link);
        while let Some(j) = parent_of[at_link] {
            if let Some(k) = seen.iter().position(|&(l, _)| l == at_link) {
                let mut cycle: Vec<(usize, usize)> = seen[k..].to_vec();
                cycle.reverse();
                let names: Vec<String> =
                    cycle.iter().map(|&(_, j)| format!("`{}`", read[j].0.name)).collect();
                let path: Vec<&str> =
                    cycle.iter().map(|&(_, j)| links[read[j].0.parent].name.as_str()).collect();
                let first = cycle.iter().map(|&(_, j)| j).min().expect("a cycle has joints");
                return Some(at(
                    joint_nodes[first],
                    format!(
                        "the joints {} close a cycle ({} → {}): a URDF is a tree (close loops with `holonomic` rows \
                         on an interconnection)",
                        names.join(", "),
                        path.join(" → "),
                        path[0]
                    ),
                ));
            }
            seen.push((at_link, j));
            at_link = read[j].0.parent;
        }
        None
    };
    let roots: Vec<usize> = (0..links.len()).filter(|&i| parent_of[i].is_none()).collect();
    if roots.is_empty()
        && let Some(error) = cycle_from(0)
    {
        return Err(error);
    }
    let &[root_link] = roots.as_slice() else {
        let names: Vec<&str> = roots.iter().map(|&i| links[i].name.as_str()).collect();
        return Err(at(
            root,
            if names.is_empty() {
                "the robot has no root link: every link is some joint's child".to_owned()
            } else {
                format!("the robot has {} root links ({}); a URDF has one", names.len(), names.join(", "))
            },
        ));
    };
    // Tree order: breadth first from the root, children in the file's order.
    let mut order = vec![root_link];
    let mut tree = Vec::new();
    let mut position = vec![usize::MAX; links.len()];
    position[root_link] = 0;
    let mut k = 0;
    while k < order.len() {
        let parent = order[k];
        for (j, (joint, child)) in read.iter().enumerate().filter(|(_, (j, _))| j.parent == parent) {
            position[*child] = order.len();
            order.push(*child);
            tree.push((j, joint, *child));
        }
        k += 1;
    }
    if order.len() != links.len() {
        // Links outside the tree hang from a cycle.
        let lost = (0..links.len()).find(|i| position[*i] == usize::MAX).expect("a link outside the tree");
        if let Some(error) = cycle_from(lost) {
            return Err(error);
        }
        return Err(at(
            link_nodes[lost],
            format!("link `{}` is on a cycle of joints: a URDF is a tree", links[lost].name),
        ));
    }
    // A floating joint joins the root, fixed in the world, to the robot: a robot asked to float
    // has none of its own.
    for (j, joint, _) in &tree {
        if joint.kind != Kind::Floating {
            continue;
        }
        let parent = &links[joint.parent].name;
        if float_root {
            return Err(at(
                joint_nodes[*j],
                format!(
                    "joint `{}` is `floating`, and the model floats the whole robot (`floating`): remove one of \
                     the two",
                    joint.name
                ),
            ));
        }
        if joint.parent != root_link {
            return Err(at(
                joint_nodes[*j],
                format!(
                    "joint `{}` is `floating` with the parent `{parent}`, a link that moves: a floating joint joins \
                     the root, fixed in the world, to a body that moves freely",
                    joint.name
                ),
            ));
        }
    }
    // The joints in tree order, a planar one as its three motions, each followed by its child.
    let mut slots: Vec<Option<Link>> = links.into_iter().map(Some).collect();
    let mut robot = Robot { links: Vec::new(), joints: Vec::new() };
    let mut index = vec![usize::MAX; slots.len()];
    if float_root {
        robot.links.push(Link::frame("world".to_owned()));
        robot.joints.push(Joint::moving(FLOATING_ROOT, Kind::Floating, 0, [0.0; 3]));
    }
    index[root_link] = robot.links.len();
    robot.links.push(slots[root_link].take().expect("each link once"));
    for (_, joint, child) in tree {
        let parent = index[joint.parent];
        let moved = slots[child].take().expect("each link once");
        if joint.kind == Kind::Planar {
            let [along, across] = in_plane(&joint.axis);
            let frame = |suffix: &str| Link::frame(format!("__{}_{suffix}", joint.name));
            let mut x = Joint::moving(&format!("{}_x", joint.name), Kind::Prismatic, parent, along);
            (x.xyz, x.rotation, x.damping) = (joint.xyz, joint.rotation, joint.damping);
            robot.joints.push(x);
            robot.links.push(frame("x"));
            let mut y =
                Joint::moving(&format!("{}_y", joint.name), Kind::Prismatic, robot.links.len() - 1, across);
            y.damping = joint.damping;
            robot.joints.push(y);
            robot.links.push(frame("y"));
            let mut turn = Joint::moving(
                &format!("{}_theta", joint.name),
                Kind::Revolute,
                robot.links.len() - 1,
                joint.axis,
            );
            turn.damping = joint.damping;
            robot.joints.push(turn);
        } else {
            robot.joints.push(Joint {
                name: joint.name.clone(),
                kind: joint.kind,
                parent,
                xyz: joint.xyz,
                rotation: joint.rotation,
                axis: joint.axis,
                mimic: joint.mimic.as_ref().map(|m| Mimic {
                    joint: m.joint.clone(),
                    multiplier: m.multiplier,
                    offset: m.offset,
                }),
                damping: joint.damping,
                friction: joint.friction,
                limits: joint.limits,
            });
        }
        index[child] = robot.links.len();
        robot.links.push(moved);
    }
    // The names a planar joint's motions take are free.
    let mut names = std::collections::HashSet::new();
    if let Some(twice) = robot.joints.iter().find(|j| !names.insert(j.name.as_str())) {
        return Err(at(
            root,
            format!(
                "two joints are named `{}` (a planar joint's motions are `<joint>_x`, `_y` and `_theta`; the free motion of a floating robot is `{FLOATING_ROOT}`)",
                twice.name
            ),
        ));
    }
    // A floating body must have inertia to move: its own mass or that of the links fixed to it.
    for (k, joint) in robot.joints.iter().enumerate() {
        if joint.kind == Kind::Floating && robot.rigid_mass(k + 1) == 0.0 {
            let body = &robot.links[k + 1].name;
            let node = tree_node(&joint_nodes, &read, &joint.name).unwrap_or(root);
            return Err(at(
                node,
                format!(
                    "the floating base `{body}` has no mass, nor has any link fixed to it: a body that moves freely \
                     needs inertia (give `{body}` an `<inertial>`)"
                ),
            ));
        }
    }
    Ok(robot)
}

/// The name of the free motion of a robot asked to float, as Pinocchio names its free flyer.
pub const FLOATING_ROOT: &str = "root_joint";

fn tree_node<'a, 'i>(nodes: &[Node<'a, 'i>], read: &[(Joint, usize)], name: &str) -> Option<Node<'a, 'i>> {
    read.iter().position(|(j, _)| j.name == name).map(|j| nodes[j])
}

impl Robot {
    /// The mass of link `k` and of every link fixed to it, directly or through other fixed joints.
    fn rigid_mass(&self, k: usize) -> f64 {
        let mut mass = self.links[k].mass;
        for (j, joint) in self.joints.iter().enumerate() {
            if joint.parent == k && joint.kind == Kind::Fixed {
                mass += self.rigid_mass(j + 1);
            }
        }
        mass
    }
}

impl Link {
    /// A frame the reader adds (the world a floating robot moves in, the frames between a planar
    /// joint's motions): no mass, no shapes, its pose no output.
    fn frame(name: String) -> Link {
        Link {
            name,
            mass: 0.0,
            com: [0.0; 3],
            inertia: [[0.0; 3]; 3],
            shown: false,
            visuals: Vec::new(),
            collisions: Vec::new(),
        }
    }
}

impl Joint {
    /// A joint the reader adds: no offset, damping, friction, limits or mimic.
    fn moving(name: &str, kind: Kind, parent: usize, axis: [f64; 3]) -> Joint {
        Joint {
            name: name.to_owned(),
            kind,
            parent,
            xyz: [0.0; 3],
            rotation: rpy([0.0; 3]),
            axis,
            mimic: None,
            damping: 0.0,
            friction: 0.0,
            limits: None,
        }
    }
}

/// Two unit directions in the plane normal to the unit `axis`, `b` and `axis × b`: `b` from the
/// coordinate axis least along `axis` (x, then y), so the plane normal to z has x and y.
fn in_plane(axis: &[f64; 3]) -> [[f64; 3]; 2] {
    let least = (0..3).min_by(|&i, &j| axis[i].abs().total_cmp(&axis[j].abs())).expect("three entries");
    let mut b = [0.0; 3];
    b[least] = 1.0;
    let along = axis[least];
    b.iter_mut().zip(axis).for_each(|(x, a)| *x -= along * a);
    let norm = (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]).sqrt();
    let b = b.map(|x| x / norm);
    let c =
        [axis[1] * b[2] - axis[2] * b[1], axis[2] * b[0] - axis[0] * b[2], axis[0] * b[1] - axis[1] * b[0]];
    [b.map(snap), c.map(snap)]
}

/// Within 1e-15 of zero is zero.
fn snap(x: f64) -> f64 {
    if x.abs() < 1e-15 { 0.0 } else { x }
}

fn read_link(
    node: Node<'_, '_>,
    materials: &HashMap<String, [f64; 4]>,
    at: &impl Fn(Node<'_, '_>, String) -> Error,
) -> Result<Link, Error> {
    let name = required(node, "name", at)?.to_owned();
    let mut visuals = Vec::new();
    for visual in node.children().filter(|c| c.is_element() && c.tag_name().name() == "visual") {
        visuals.push(read_shape(visual, &name, materials, at)?);
    }
    let mut collisions = Vec::new();
    for collision in node.children().filter(|c| c.is_element() && c.tag_name().name() == "collision") {
        let shape = read_shape(collision, &name, materials, at)?;
        let Error { line, column, .. } = at(collision, String::new());
        collisions.push(Collision { shape, line, column });
    }
    let mut link =
        Link { name, mass: 0.0, com: [0.0; 3], inertia: [[0.0; 3]; 3], shown: true, visuals, collisions };
    let Some(inertial) = element(node, "inertial") else { return Ok(link) };
    let (com, rotation) = read_origin(inertial, at)?;
    let mass_node = element(inertial, "mass").ok_or_else(|| {
        at(inertial, format!("link `{}`: `<inertial>` has no `<mass value=\"…\"/>`", link.name))
    })?;
    let mass = number(mass_node, "value", at)?;
    if mass < 0.0 {
        return Err(at(mass_node, format!("link `{}`: a negative mass, {mass}", link.name)));
    }
    let inertia_node = element(inertial, "inertia")
        .ok_or_else(|| at(inertial, format!("link `{}`: `<inertial>` has no `<inertia …/>`", link.name)))?;
    let mut i = [[0.0; 3]; 3];
    for (key, (r, c)) in
        [("ixx", (0, 0)), ("iyy", (1, 1)), ("izz", (2, 2)), ("ixy", (0, 1)), ("ixz", (0, 2)), ("iyz", (1, 2))]
    {
        let value = number(inertia_node, key, at)?;
        i[r][c] = value;
        i[c][r] = value;
    }
    let [a, b, c] = [i[0][0], i[1][1], i[2][2]];
    let slack = 1e-12 * (a.abs() + b.abs() + c.abs());
    if a < 0.0 || b < 0.0 || c < 0.0 || a + b < c - slack || b + c < a - slack || a + c < b - slack {
        return Err(at(
            inertia_node,
            format!(
                "link `{}`: principal moments ixx = {a}, iyy = {b}, izz = {c} are no rigid body's: each must be \
                 non-negative and at most the sum of the other two",
                link.name
            ),
        ));
    }
    // The products of inertia turn the axes: the moments about the principal axes must hold the
    // same, or the tensor is no rigid body's (an indefinite one makes an energy that is not
    // positive).
    let [p, q, r] = principal_moments(&i);
    let slack = 1e-12 * (p.abs() + q.abs() + r.abs());
    if p < -slack || p + q < r - slack {
        return Err(at(
            inertia_node,
            format!(
                "link `{}`: the inertia tensor (ixx = {a}, iyy = {b}, izz = {c}, ixy = {}, ixz = {}, iyz = {}) has \
                 principal moments {p:.6e}, {q:.6e}, {r:.6e}, no rigid body's: each must be non-negative and at \
                 most the sum of the other two (products of inertia this large need larger moments)",
                link.name, i[0][1], i[0][2], i[1][2]
            ),
        ));
    }
    // The inertia about the centre of mass, turned from the inertial frame into the link's.
    let ri = mul(&rotation, &i);
    link.inertia = mul(&ri, &transpose(&rotation));
    link.mass = mass;
    link.com = com;
    Ok(link)
}

/// A `<visual>` or `<collision>` of link `link`: its origin, its geometry and its colour (a
/// visual's).
fn read_shape(
    node: Node<'_, '_>,
    link: &str,
    materials: &HashMap<String, [f64; 4]>,
    at: &impl Fn(Node<'_, '_>, String) -> Error,
) -> Result<Shape, Error> {
    let (xyz, rotation) = read_origin(node, at)?;
    let geometry = element(node, "geometry").ok_or_else(|| {
        at(node, format!("link `{link}`: `<{}>` has no `<geometry>`", node.tag_name().name()))
    })?;
    let Some(shape) = geometry.children().find(Node::is_element) else {
        return Err(at(geometry, format!("link `{link}`: `<geometry>` holds no shape")));
    };
    let positive = |key: &str| -> Result<f64, Error> {
        let x = number(shape, key, at)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(at(
                shape,
                format!(
                    "link `{link}`: a `<{}>` whose `{key}` is {x}, not positive",
                    shape.tag_name().name()
                ),
            ))
        }
    };
    let geometry = match shape.tag_name().name() {
        "box" => {
            let size = triple(shape, "size", at)?;
            if size.iter().any(|x| *x <= 0.0) {
                return Err(at(
                    shape,
                    format!("link `{link}`: a `<box>` whose size {size:?} is not positive"),
                ));
            }
            Geometry::Box(size)
        }
        "sphere" => Geometry::Sphere(positive("radius")?),
        "cylinder" => Geometry::Cylinder { radius: positive("radius")?, length: positive("length")? },
        "capsule" => Geometry::Capsule { radius: positive("radius")?, length: positive("length")? },
        "mesh" => Geometry::Mesh(required(shape, "filename", at)?.to_owned()),
        other => {
            return Err(at(
                shape,
                format!(
                    "link `{link}`: `<{other}>` is no URDF geometry; a shape is a box, sphere, cylinder, capsule or mesh"
                ),
            ));
        }
    };
    let color = match element(node, "material") {
        None => None,
        Some(material) => match element(material, "color") {
            Some(color) => Some(rgba(color, at)?),
            None => material.attribute("name").and_then(|name| materials.get(name).copied()),
        },
    };
    Ok(Shape { geometry, xyz, rotation, color })
}

/// `<color rgba="r g b a"/>`, each in `[0, 1]`.
fn rgba(node: Node<'_, '_>, at: &impl Fn(Node<'_, '_>, String) -> Error) -> Result<[f64; 4], Error> {
    let text = required(node, "rgba", at)?;
    let values: Vec<f64> = text.split_whitespace().filter_map(parse_number).collect();
    match values.as_slice() {
        [r, g, b, a] if values.iter().all(|x| (0.0..=1.0).contains(x)) => Ok([*r, *g, *b, *a]),
        _ => Err(at(node, format!("`rgba=\"{text}\"` is not four numbers between 0 and 1"))),
    }
}

/// A joint as written, with its parent and child as indices of the file's links.
fn read_joint(
    node: Node<'_, '_>,
    index: &HashMap<&str, usize>,
    at: &impl Fn(Node<'_, '_>, String) -> Error,
) -> Result<(Joint, usize), Error> {
    let name = required(node, "name", at)?.to_owned();
    let kind = match required(node, "type", at)? {
        "revolute" | "continuous" => Kind::Revolute,
        "prismatic" => Kind::Prismatic,
        "fixed" => Kind::Fixed,
        "floating" => Kind::Floating,
        "planar" => Kind::Planar,
        other => {
            return Err(at(
                node,
                format!(
                    "joint `{name}` is `{other}`, which is not supported; joints may be revolute, continuous, \
                     prismatic, fixed, planar or floating"
                ),
            ));
        }
    };
    let link_of = |key: &str| -> Result<usize, Error> {
        let element = element(node, key)
            .ok_or_else(|| at(node, format!("joint `{name}` has no `<{key} link=\"…\"/>`")))?;
        let link = required(element, "link", at)?;
        index
            .get(link)
            .copied()
            .ok_or_else(|| at(element, format!("joint `{name}`: no link is named `{link}`")))
    };
    let (parent, child) = (link_of("parent")?, link_of("child")?);
    if parent == child {
        return Err(at(node, format!("joint `{name}` joins link {parent} to itself")));
    }
    let (xyz, rotation) = read_origin(node, at)?;
    let mut axis = [1.0, 0.0, 0.0];
    if let Some(a) = element(node, "axis") {
        axis = triple(a, "xyz", at)?;
    }
    let norm = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let axial = matches!(kind, Kind::Revolute | Kind::Prismatic | Kind::Planar);
    if axial && (norm == 0.0 || !norm.is_finite()) {
        return Err(at(node, format!("joint `{name}` has a zero axis")));
    }
    if axial {
        axis = axis.map(|x| x / norm);
    }
    let (mut damping, mut friction) = (0.0, 0.0);
    if let Some(d) = element(node, "dynamics") {
        damping = optional_number(d, "damping", at)?.unwrap_or(0.0);
        friction = optional_number(d, "friction", at)?.unwrap_or(0.0);
        if damping < 0.0 || friction < 0.0 {
            return Err(at(
                d,
                format!("joint `{name}`: a negative damping or friction, {damping} and {friction}"),
            ));
        }
    }
    let mut limits = None;
    let continuous = node.attribute("type") == Some("continuous");
    if let Some(l) = element(node, "limit") {
        // A continuous joint's limit names its effort and velocity only.
        if matches!(kind, Kind::Revolute | Kind::Prismatic) && !continuous {
            let lower = optional_number(l, "lower", at)?;
            let upper = optional_number(l, "upper", at)?;
            if let (Some(lower), Some(upper)) = (lower, upper) {
                limits = Some((lower, upper));
            }
        }
    }
    let mimic = match element(node, "mimic") {
        None => None,
        Some(m) => Some(Mimic {
            joint: required(m, "joint", at)?.to_owned(),
            multiplier: optional_number(m, "multiplier", at)?.unwrap_or(1.0),
            offset: optional_number(m, "offset", at)?.unwrap_or(0.0),
        }),
    };
    Ok((Joint { name, kind, parent, xyz, rotation, axis, mimic, damping, friction, limits }, child))
}

/// `<origin xyz="…" rpy="…"/>` of an element: its translation and rotation, identity if absent.
fn read_origin(
    node: Node<'_, '_>,
    at: &impl Fn(Node<'_, '_>, String) -> Error,
) -> Result<([f64; 3], Mat3), Error> {
    let Some(origin) = element(node, "origin") else { return Ok(([0.0; 3], rpy([0.0; 3]))) };
    let xyz = if origin.has_attribute("xyz") { triple(origin, "xyz", at)? } else { [0.0; 3] };
    let angles = if origin.has_attribute("rpy") { triple(origin, "rpy", at)? } else { [0.0; 3] };
    Ok((xyz, rpy(angles)))
}

/// The rotation of URDF's roll, pitch and yaw: `Rz(yaw) Ry(pitch) Rx(roll)`. Entries within
/// 1e-15 of zero are zero (the cosine of a right angle is 6e-17 in floating point).
pub fn rpy([roll, pitch, yaw]: [f64; 3]) -> Mat3 {
    let (sr, cr) = roll.sin_cos();
    let (sp, cp) = pitch.sin_cos();
    let (sy, cy) = yaw.sin_cos();
    let m = [
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ];
    m.map(|row| row.map(snap))
}

/// The eigenvalues of the symmetric `a`, ascending: the principal moments of an inertia tensor,
/// in closed form (the roots of the characteristic cubic, by their trigonometric form).
fn principal_moments(a: &Mat3) -> [f64; 3] {
    let off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    let mut moments = if off == 0.0 {
        [a[0][0], a[1][1], a[2][2]]
    } else {
        let mean = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
        let d = [a[0][0] - mean, a[1][1] - mean, a[2][2] - mean];
        let spread = ((d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + 2.0 * off) / 6.0).sqrt();
        // B = (A − mean I) / spread has eigenvalues 2 cos(φ + 2πk/3), φ = acos(det B / 2) / 3.
        let b = |r: usize, c: usize| (a[r][c] - if r == c { mean } else { 0.0 }) / spread;
        let det = b(0, 0) * (b(1, 1) * b(2, 2) - b(1, 2) * b(2, 1))
            - b(0, 1) * (b(1, 0) * b(2, 2) - b(1, 2) * b(2, 0))
            + b(0, 2) * (b(1, 0) * b(2, 1) - b(1, 1) * b(2, 0));
        let phi = (det / 2.0).clamp(-1.0, 1.0).acos() / 3.0;
        let third = 2.0 * std::f64::consts::PI / 3.0;
        [0.0, 1.0, 2.0].map(|k| mean + 2.0 * spread * (phi + k * third).cos())
    };
    moments.sort_by(f64::total_cmp);
    moments
}

pub fn mul(a: &Mat3, b: &Mat3) -> Mat3 {
    let mut out = [[0.0; 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    out
}

pub fn transpose(a: &Mat3) -> Mat3 {
    let mut out = [[0.0; 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = a[j][i];
        }
    }
    out
}

fn element<'a, 'i>(node: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    node.children().find(|c| c.is_element() && c.tag_name().name() == name)
}

fn required<'a>(
    node: Node<'a, '_>,
    key: &str,
    at: &impl Fn(Node<'_, '_>, String) -> Error,
) -> Result<&'a str, Error> {
    node.attribute(key)
        .ok_or_else(|| at(node, format!("`<{}>` has no `{key}` attribute", node.tag_name().name())))
}

fn number(node: Node<'_, '_>, key: &str, at: &impl Fn(Node<'_, '_>, String) -> Error) -> Result<f64, Error> {
    let text = required(node, key, at)?;
    parse_number(text).ok_or_else(|| at(node, format!("`{key}=\"{text}\"` is not a finite number")))
}

fn optional_number(
    node: Node<'_, '_>,
    key: &str,
    at: &impl Fn(Node<'_, '_>, String) -> Error,
) -> Result<Option<f64>, Error> {
    if node.has_attribute(key) { number(node, key, at).map(Some) } else { Ok(None) }
}

fn triple(
    node: Node<'_, '_>,
    key: &str,
    at: &impl Fn(Node<'_, '_>, String) -> Error,
) -> Result<[f64; 3], Error> {
    let text = required(node, key, at)?;
    let values: Vec<Option<f64>> = text.split_whitespace().map(parse_number).collect();
    match values.as_slice() {
        [Some(a), Some(b), Some(c)] => Ok([*a, *b, *c]),
        _ => Err(at(node, format!("`{key}=\"{text}\"` is not three finite numbers"))),
    }
}

fn parse_number(text: &str) -> Option<f64> {
    text.trim().parse::<f64>().ok().filter(|x| x.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    const LINK: &str = r#"<link name="base"/>"#;

    fn robot(body: &str) -> Result<Robot, Error> {
        parse(&format!("<robot name=\"r\">\n{body}\n</robot>"), false)
    }

    fn refused(body: &str) -> Error {
        match robot(body) {
            Ok(_) => panic!("accepted: {body}"),
            Err(e) => e,
        }
    }

    fn arm(joint: &str) -> String {
        format!(
            "{LINK}\n<link name=\"arm\"><inertial><mass value=\"2\"/>\
             <inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n{joint}"
        )
    }

    #[test]
    fn a_two_link_robot_reads_in_tree_order() {
        let r = robot(&arm(r#"<joint name="j" type="continuous"><parent link="base"/><child link="arm"/>
               <origin xyz="0 0 1" rpy="0 0 1.5707963267948966"/><axis xyz="0 2 0"/>
               <dynamics damping="0.5"/></joint>"#))
        .expect("a robot");
        assert_eq!(r.links.len(), 2);
        assert_eq!(r.links[0].name, "base");
        let j = &r.joints[0];
        assert_eq!(
            (j.kind, j.parent, j.xyz, j.axis, j.damping),
            (Kind::Revolute, 0, [0.0, 0.0, 1.0], [0.0, 1.0, 0.0], 0.5)
        );
        // A yaw of 90°: x to y, y to −x, with the cosines' 6e-17 snapped to zero.
        assert_eq!(j.rotation, [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
    }

    #[test]
    fn inertia_is_turned_into_the_links_axes() {
        let r = robot(&format!(
            "{LINK}<link name=\"arm\"><inertial><origin xyz=\"1 2 3\" rpy=\"0 0 1.5707963267948966\"/>\
             <mass value=\"2\"/><inertia ixx=\"1\" iyy=\"2\" izz=\"3\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\
             <joint name=\"j\" type=\"fixed\"><parent link=\"base\"/><child link=\"arm\"/></joint>"
        ))
        .expect("a robot");
        // Turned by 90° about z, the x and y moments swap.
        assert_eq!(r.links[1].inertia, [[2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 3.0]]);
        assert_eq!(r.links[1].com, [1.0, 2.0, 3.0]);
    }

    /// The principal moments of `R diag(1, 2, 3) Rᵀ`, a tensor built from them by a rotation
    /// (the reference), and of a diagonal one, to round-off.
    #[test]
    fn principal_moments_are_the_eigenvalues_a_rotation_hid() {
        let (c, s) = (0.7_f64.cos(), 0.7_f64.sin());
        let (c2, s2) = (0.3_f64.cos(), 0.3_f64.sin());
        let rz = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]];
        let rx = [[1.0, 0.0, 0.0], [0.0, c2, -s2], [0.0, s2, c2]];
        let r = super::mul(&rz, &rx);
        let d = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]];
        let tensor = super::mul(&super::mul(&r, &d), &super::transpose(&r));
        let moments = super::principal_moments(&tensor);
        for (got, want) in moments.iter().zip([1.0, 2.0, 3.0]) {
            assert!((got - want).abs() < 1e-13, "{moments:?}");
        }
        assert_eq!(
            super::principal_moments(&[[3.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 2.0]]),
            [1.0, 2.0, 3.0]
        );
    }

    /// A planar joint is a slide along each of two directions in the plane normal to its
    /// axis (the first from the coordinate axis least along it) and a turn about the axis,
    /// between two frames the reader adds and does not show.
    #[test]
    fn a_planar_joint_is_two_slides_and_a_turn() {
        let r = robot(&arm(r#"<joint name="j" type="planar"><parent link="base"/><child link="arm"/>
               <origin xyz="0 0 1"/><axis xyz="0 0 1"/><dynamics damping="0.5"/></joint>"#))
        .expect("a robot");
        let kinds: Vec<(&str, Kind, usize, [f64; 3])> =
            r.joints.iter().map(|j| (j.name.as_str(), j.kind, j.parent, j.axis)).collect();
        assert_eq!(
            kinds,
            [
                ("j_x", Kind::Prismatic, 0, [1.0, 0.0, 0.0]),
                ("j_y", Kind::Prismatic, 1, [0.0, 1.0, 0.0]),
                ("j_theta", Kind::Revolute, 2, [0.0, 0.0, 1.0])
            ]
        );
        assert_eq!((r.joints[0].xyz, r.joints[1].xyz), ([0.0, 0.0, 1.0], [0.0; 3]));
        assert!(r.joints.iter().all(|j| j.damping == 0.5));
        let shown: Vec<(&str, bool)> = r.links.iter().map(|l| (l.name.as_str(), l.shown)).collect();
        assert_eq!(shown, [("base", true), ("__j_x", false), ("__j_y", false), ("arm", true)]);
        // Any axis: two unit directions normal to it and to each other, right-handed.
        let a = [0.6, 0.0, 0.8];
        let [b, c] = super::in_plane(&a);
        let dot = |x: &[f64; 3], y: &[f64; 3]| x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
        assert!(dot(&a, &b).abs() < 1e-15 && dot(&a, &c).abs() < 1e-15 && dot(&b, &c).abs() < 1e-15);
        assert!((dot(&b, &b) - 1.0).abs() < 1e-15 && (dot(&c, &c) - 1.0).abs() < 1e-15);
        let triple = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]);
        assert!((triple - 1.0).abs() < 1e-15, "{triple}");
    }

    /// A robot asked to float hangs from a world frame of its own by `root_joint`; a floating
    /// joint of the file's joins the root to a body that moves freely.
    #[test]
    fn a_floating_robot_hangs_from_a_world_of_its_own() {
        // The massless base carries the arm's mass through a fixed joint.
        let text = format!(
            "<robot name=\"r\">\n{}\n</robot>",
            arm(r#"<joint name="j" type="fixed"><parent link="base"/><child link="arm"/></joint>"#)
        );
        let r = parse(&text, true).expect("a robot");
        let joints: Vec<(&str, Kind, usize)> =
            r.joints.iter().map(|j| (j.name.as_str(), j.kind, j.parent)).collect();
        assert_eq!(joints, [(FLOATING_ROOT, Kind::Floating, 0), ("j", Kind::Fixed, 1)]);
        // Through a hinge, the base would turn about it without inertia.
        let hinged = text.replace(r#"type="fixed">"#, r#"type="continuous"><axis xyz="0 0 1"/>"#);
        let e = parse(&hinged, true).err().expect("refused");
        assert!(e.message.contains("the floating base `base` has no mass"), "{e}");
        assert_eq!((r.links[0].shown, r.links[1].name.as_str(), r.links[1].shown), (false, "base", true));
        let text = format!(
            "<robot name=\"r\">\n{}\n</robot>",
            arm(r#"<joint name="free" type="floating"><parent link="base"/><child link="arm"/></joint>"#)
        );
        let r = parse(&text, false).expect("a robot");
        assert_eq!((r.joints[0].kind, r.links[0].shown), (Kind::Floating, true));
        // Asked to float a robot that floats already.
        let e = parse(&text, true).err().expect("refused");
        assert!(
            e.message.contains("joint `free` is `floating`, and the model floats the whole robot"),
            "{e}"
        );
        assert_eq!(e.line, 4);
        // Asked to float a massless root.
        let e = parse("<robot name=\"r\">\n<link name=\"a\"/>\n</robot>", true).err().expect("refused");
        assert!(e.message.contains("the floating base `a` has no mass"), "{e}");
    }

    #[test]
    fn visuals_are_read_with_their_frames_and_colours() {
        let robot = robot(
            r#"<material name="steel"><color rgba="0.5 0.5 0.6 1"/></material>
            <link name="base">
              <visual><origin xyz="0 0 0.1" rpy="0 0 1.5707963267948966"/><geometry><box size="1 2 3"/></geometry>
                <material name="steel"/></visual>
              <visual><geometry><cylinder radius="0.1" length="0.5"/></geometry></visual>
              <visual><geometry><mesh filename="package://arm/base.stl"/></geometry>
                <material name="red"><color rgba="1 0 0 1"/></material></visual>
            </link>"#,
        )
        .expect("a robot");
        let visuals = &robot.links[0].visuals;
        assert_eq!(visuals.len(), 3);
        assert!(matches!(visuals[0].geometry, Geometry::Box(size) if size == [1.0, 2.0, 3.0]));
        assert_eq!(visuals[0].xyz, [0.0, 0.0, 0.1]);
        // A quarter turn about z: the shape's x axis along the link's y.
        assert_eq!([visuals[0].rotation[0][0], visuals[0].rotation[1][0]], [0.0, 1.0]);
        assert_eq!(visuals[0].color, Some([0.5, 0.5, 0.6, 1.0]));
        assert!(
            matches!(visuals[1].geometry, Geometry::Cylinder { radius, length } if (radius, length) == (0.1, 0.5))
        );
        assert_eq!(visuals[1].color, None);
        assert!(matches!(&visuals[2].geometry, Geometry::Mesh(file) if file == "package://arm/base.stl"));
        assert_eq!(visuals[2].color, Some([1.0, 0.0, 0.0, 1.0]));
    }

    #[test]
    fn collisions_are_read_with_their_frames_and_lines() {
        let robot = robot(
            "<link name=\"foot\">\n<visual><geometry><box size=\"1 1 1\"/></geometry></visual>\n\
             <collision><origin xyz=\"0 0 -0.1\"/><geometry><sphere radius=\"0.05\"/></geometry></collision>\n\
             <collision><geometry><mesh filename=\"foot.stl\"/></geometry></collision>\n</link>",
        )
        .expect("a robot");
        let collisions = &robot.links[0].collisions;
        assert_eq!(collisions.len(), 2);
        assert!(matches!(collisions[0].shape.geometry, Geometry::Sphere(r) if r == 0.05));
        assert_eq!(collisions[0].shape.xyz, [0.0, 0.0, -0.1]);
        assert_eq!((collisions[0].line, collisions[1].line), (4, 5));
        assert!(matches!(&collisions[1].shape.geometry, Geometry::Mesh(file) if file == "foot.stl"));
        let e = refused("<link name=\"foot\">\n<collision/></link>");
        assert!(e.message.contains("link `foot`: `<collision>` has no `<geometry>`"), "{e}");
        assert_eq!(e.line, 3);
    }

    #[test]
    fn every_malformed_or_unsupported_element_is_refused_with_its_line() {
        let joint = |kind: &str, extra: &str| {
            arm(&format!(
                "<joint name=\"j\" type=\"{kind}\"><parent link=\"base\"/><child link=\"arm\"/>{extra}</joint>"
            ))
        };
        let cases: Vec<(String, &str, u32)> = vec![
            ("<robot".to_owned(), "not well-formed XML", 3),
            (joint("spherical", ""), "joint `j` is `spherical`, which is not supported", 4),
            (joint("planar", "<axis xyz=\"0 0 0\"/>"), "joint `j` has a zero axis", 4),
            (
                // The arm floats from the base, and the hand from the arm, which moves.
                format!(
                    "{}\n<link name=\"hand\"><inertial><mass value=\"1\"/>\
                     <inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n\
                     <joint name=\"k\" type=\"floating\"><parent link=\"arm\"/><child link=\"hand\"/></joint>",
                    joint("floating", "")
                ),
                "joint `k` is `floating` with the parent `arm`, a link that moves",
                6,
            ),
            (
                format!(
                    "{LINK}\n<link name=\"shell\"/>\n<link name=\"tip\"/>\n\
                     <joint name=\"free\" type=\"floating\"><parent link=\"base\"/><child link=\"shell\"/></joint>\n\
                     <joint name=\"weld\" type=\"fixed\"><parent link=\"shell\"/><child link=\"tip\"/></joint>"
                ),
                "the floating base `shell` has no mass, nor has any link fixed to it",
                5,
            ),
            (
                arm(
                    "<joint name=\"j\" type=\"planar\"><parent link=\"base\"/><child link=\"arm\"/></joint>\n\
                     <link name=\"x\"/><joint name=\"j_x\" type=\"fixed\"><parent link=\"arm\"/><child link=\"x\"/></joint>",
                ),
                "two joints are named `j_x` (a planar joint's motions are `<joint>_x`, `_y` and `_theta`",
                1,
            ),
            (joint("revolute", "<axis xyz=\"0 0 0\"/>"), "joint `j` has a zero axis", 4),
            (joint("revolute", "<axis xyz=\"0 1\"/>"), "`xyz=\"0 1\"` is not three finite numbers", 4),
            (joint("revolute", "<origin xyz=\"0 nan 0\"/>"), "is not three finite numbers", 4),
            (joint("revolute", "<dynamics damping=\"-1\"/>"), "a negative damping or friction", 4),
            (joint("revolute", "<dynamics friction=\"-1\"/>"), "a negative damping or friction", 4),
            (
                arm("<joint name=\"j\" type=\"fixed\"><parent link=\"base\"/><child link=\"hand\"/></joint>"),
                "no link is named `hand`",
                4,
            ),
            (
                arm("<joint name=\"j\" type=\"fixed\"><parent link=\"base\"/></joint>"),
                "has no `<child link",
                4,
            ),
            (format!("{LINK}\n<link name=\"base\"/>"), "a second link named `base`", 3),
            (format!("{LINK}\n<link name=\"x\"/>"), "2 root links (base, x)", 1),
            (
                format!("{LINK}\n<link name=\"a\"><inertial><mass value=\"-1\"/></inertial></link>"),
                "a negative mass",
                3,
            ),
            (
                format!(
                    "{LINK}\n<link name=\"a\"><inertial><mass value=\"1\"/>\n<inertia ixx=\"1\" iyy=\"1\" izz=\"3\" \
                     ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>"
                ),
                "at most the sum of the other two",
                4,
            ),
            (
                // Principal moments 3, 1 and −1: the products of inertia make it indefinite.
                format!(
                    "{LINK}\n<link name=\"a\"><inertial><mass value=\"1\"/>\n<inertia ixx=\"1\" iyy=\"1\" izz=\"1\" \
                     ixy=\"2\" ixz=\"0\" iyz=\"0\"/></inertial></link>"
                ),
                "principal moments -1.000000e0, 1.000000e0, 3.000000e0, no rigid body's",
                4,
            ),
            (
                "<link name=\"base\"><visual>\n<geometry><sphere radius=\"-1\"/></geometry></visual></link>"
                    .to_owned(),
                "link `base`: a `<sphere>` whose `radius` is -1, not positive",
                3,
            ),
            (
                "<link name=\"base\"><visual>\n<geometry><cone radius=\"1\"/></geometry></visual></link>"
                    .to_owned(),
                "`<cone>` is no URDF geometry",
                3,
            ),
            (
                "<link name=\"base\">\n<visual/></link>".to_owned(),
                "link `base`: `<visual>` has no `<geometry>`",
                3,
            ),
            (
                "<link name=\"base\"><visual><geometry><box size=\"1 1 1\"/></geometry>\n\
                 <material name=\"m\"><color rgba=\"1 0 0\"/></material></visual></link>"
                    .to_owned(),
                "`rgba=\"1 0 0\"` is not four numbers between 0 and 1",
                3,
            ),
            (
                format!("{LINK}\n<link name=\"a\"><inertial><mass value=\"1\"/></inertial></link>"),
                "has no `<inertia",
                3,
            ),
            (format!("{LINK}\n<plugin name=\"s\"/>"), "`<plugin>` is not supported", 3),
            (
                arm(
                    "<joint name=\"j\" type=\"fixed\"><parent link=\"base\"/><child link=\"arm\"/></joint>\n\
                     <joint name=\"k\" type=\"fixed\"><parent link=\"base\"/><child link=\"arm\"/></joint>",
                ),
                "link `arm` is the child of a second joint, `k`",
                5,
            ),
            (
                "<link name=\"a\"/><link name=\"b\"/>\n\
                 <joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>\n\
                 <joint name=\"k\" type=\"fixed\"><parent link=\"b\"/><child link=\"a\"/></joint>"
                    .to_owned(),
                "the joints `j`, `k` close a cycle (a → b → a)",
                3,
            ),
            (
                "<link name=\"base\"/><link name=\"b\"/><link name=\"c\"/>\n\
                 <joint name=\"m\" type=\"fixed\"><parent link=\"b\"/><child link=\"c\"/></joint>\n\
                 <joint name=\"n\" type=\"fixed\"><parent link=\"c\"/><child link=\"b\"/></joint>"
                    .to_owned(),
                "the joints `m`, `n` close a cycle (b → c → b)",
                3,
            ),
        ];
        for (body, message, line) in cases {
            let e = refused(&body);
            assert!(e.message.contains(message), "{body}\ngave: {e}\nexpected: {message}");
            assert_eq!(e.line, line, "{body}\ngave: {e}");
        }
        let e = parse("<model/>", false).err().expect("refused");
        assert!(e.message.contains("a URDF's is `<robot>`"), "{e}");
    }
}
