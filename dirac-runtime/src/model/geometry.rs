//! The shapes of a robot's links as its URDF file draws them, for views of its motion.

/// A shape's form, in its own frame: a box about its centre, a sphere, a cylinder or a capsule
/// along its `z` axis, or a mesh, named by its file and not read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Geometry {
    /// `<box size="x y z"/>`.
    Box {
        /// The edges' lengths along `x`, `y` and `z`.
        size: [f64; 3],
    },
    /// `<sphere radius="r"/>`.
    Sphere {
        /// The radius.
        radius: f64,
    },
    /// `<cylinder radius="r" length="l"/>`.
    Cylinder {
        /// The radius.
        radius: f64,
        /// The length along `z`.
        length: f64,
    },
    /// `<capsule radius="r" length="l"/>`.
    Capsule {
        /// The radius of the cylinder and its end caps.
        radius: f64,
        /// The length along `z` between the end caps' centres.
        length: f64,
    },
    /// `<mesh filename="…"/>`: a view draws the link's frame and the line to its parent.
    Mesh {
        /// The file named.
        file: &'static str,
    },
}

/// One `<visual>` of a link.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shape {
    /// Its form.
    pub geometry: Geometry,
    /// Its frame's origin in the link's frame.
    pub origin: [f64; 3],
    /// Its frame's rotation in the link's, row by row (the columns are its axes).
    pub rotation: [[f64; 3]; 3],
    /// Its colour (`<material><color rgba="…"/>`), red, green, blue and alpha in `[0, 1]`,
    /// where the file gives one.
    pub color: Option<[f64; 4]>,
}

/// A link as a view draws it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Link {
    /// Its name, whose pose in the world is the model's outputs `<name>_x`, `_y`, `_z` (its
    /// origin) and `<name>_r11` … `_r33` (its rotation).
    pub name: &'static str,
    /// The link it hangs from, `None` for the root.
    pub parent: Option<&'static str>,
    /// Its shapes.
    pub shapes: &'static [Shape],
}

/// A model whose links have shapes: a robot read from a URDF file, whose derive implements it.
/// `dirac::plot::Scene` draws its motion in 3D.
pub trait Shapes {
    /// The links, root first, each after the link it hangs from.
    const LINKS: &'static [Link];
}
