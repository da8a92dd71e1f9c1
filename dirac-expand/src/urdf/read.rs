//! Reading a URDF file into a kinematic tree: links with their inertia, joints with their
//! frames and axes. Every malformed or unsupported element is an error naming it and its line.

use std::collections::HashMap;
use std::fmt;

/// A 3 × 3 matrix, row-major.
pub type Mat3 = [[f64; 3]; 3];

/// A robot as its URDF describes it, with the links in tree order (parents before children).
pub struct Robot {
    /// The links; the first is the root, fixed in the world.
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
pub fn parse(text: &str) -> Result<Robot, Error> {
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
    let mut links = Vec::new();
    let mut link_nodes = Vec::new();
    let mut joint_nodes = Vec::new();
    for child in root.children().filter(Node::is_element) {
        match child.tag_name().name() {
            "link" => {
                links.push(read_link(child, &at)?);
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
    let mut joints = Vec::new();
    let mut position = vec![usize::MAX; links.len()];
    position[root_link] = 0;
    let mut k = 0;
    while k < order.len() {
        let parent = order[k];
        for (joint, child) in read.iter().filter(|(j, _)| j.parent == parent) {
            position[*child] = order.len();
            order.push(*child);
            joints.push((joint, *child));
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
    let joints = joints
        .into_iter()
        .map(|(j, _)| Joint {
            name: j.name.clone(),
            kind: j.kind,
            parent: position[j.parent],
            xyz: j.xyz,
            rotation: j.rotation,
            axis: j.axis,
            mimic: j.mimic.as_ref().map(|m| Mimic {
                joint: m.joint.clone(),
                multiplier: m.multiplier,
                offset: m.offset,
            }),
            damping: j.damping,
            friction: j.friction,
            limits: j.limits,
        })
        .collect();
    let mut slots: Vec<Option<Link>> = links.into_iter().map(Some).collect();
    let links = order.iter().map(|&i| slots[i].take().expect("each link once")).collect();
    Ok(Robot { links, joints })
}

fn read_link(node: Node<'_, '_>, at: &impl Fn(Node<'_, '_>, String) -> Error) -> Result<Link, Error> {
    let name = required(node, "name", at)?.to_owned();
    let mut link = Link { name, mass: 0.0, com: [0.0; 3], inertia: [[0.0; 3]; 3] };
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
        other => {
            return Err(at(
                node,
                format!(
                    "joint `{name}` is `{other}`, which is not supported; joints may be revolute, continuous, \
                     prismatic or fixed"
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
    if kind != Kind::Fixed && (norm == 0.0 || !norm.is_finite()) {
        return Err(at(node, format!("joint `{name}` has a zero axis")));
    }
    if kind != Kind::Fixed {
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
        if kind != Kind::Fixed && !continuous {
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
    m.map(|row| row.map(|x| if x.abs() < 1e-15 { 0.0 } else { x }))
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
        parse(&format!("<robot name=\"r\">\n{body}\n</robot>"))
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

    #[test]
    fn every_malformed_or_unsupported_element_is_refused_with_its_line() {
        let joint = |kind: &str, extra: &str| {
            arm(&format!(
                "<joint name=\"j\" type=\"{kind}\"><parent link=\"base\"/><child link=\"arm\"/>{extra}</joint>"
            ))
        };
        let cases: Vec<(String, &str, u32)> = vec![
            ("<robot".to_owned(), "not well-formed XML", 3),
            (joint("floating", ""), "joint `j` is `floating`, which is not supported", 4),
            (joint("planar", ""), "`planar`, which is not supported", 4),
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
        let e = parse("<model/>").err().expect("refused");
        assert!(e.message.contains("a URDF's is `<robot>`"), "{e}");
    }
}
