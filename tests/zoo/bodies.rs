//! Rigid bodies joined by joints, with the planar models they reduce to: shared by the
//! integration tests (`tests/integration/bodies.rs`) and the `bodies` benchmark.

use dirac::State;
use dirac::components::bodies::RigidBody;
use dirac::prelude::*;

/// Two bodies hung by revolute joints about space's `y` axis: link 1 from a pivot at the
/// origin at `a1` above its centre, link 2 from link 1 at `b1` below link 1's centre and `a2`
/// above its own. Each joint holds a point of one body on a point of the other (three rows)
/// and keeps their `y` axes parallel (two rows): the pivot's rows are linear in the embedded
/// coordinates, the hinge's axis rows bilinear.
#[derive(Interconnection, Clone, Debug)]
#[dirac(holonomic(pivot_x) = link1.x + a1 * link1.r13, holonomic(pivot_y) = link1.y + a1 * link1.r23)]
#[dirac(holonomic(pivot_z) = link1.z + a1 * link1.r33)]
#[dirac(holonomic(pivot_axis_x) = link1.r12, holonomic(pivot_axis_z) = link1.r32)]
#[dirac(holonomic(hinge_x) = link1.x - b1 * link1.r13 - link2.x - a2 * link2.r13)]
#[dirac(holonomic(hinge_y) = link1.y - b1 * link1.r23 - link2.y - a2 * link2.r23)]
#[dirac(holonomic(hinge_z) = link1.z - b1 * link1.r33 - link2.z - a2 * link2.r33)]
// Link 1's y axis (its second column) across link 2's x and z axes.
#[dirac(holonomic(hinge_axis_1) = link1.r12 * link2.r11 + link1.r22 * link2.r21 + link1.r32 * link2.r31)]
#[dirac(holonomic(hinge_axis_3) = link1.r12 * link2.r13 + link1.r22 * link2.r23 + link1.r32 * link2.r33)]
pub struct SpatialDoublePendulum {
    pub link1: RigidBody,
    pub link2: RigidBody,
    pub a1: f64,
    pub b1: f64,
    pub a2: f64,
}

macro_rules! jointed_double_pendulum {
    ($(#[$attr:meta])* $name:ident) => {
        /// The spatial double pendulum with its joints named: link 1 turns about space's `y`
        /// axis through the pivot at the origin, link 2 about link 1's `y` axis through the hinge
        /// (`th2` is link 2's angle to link 1).
        #[derive(Interconnection, Clone, Debug)]
        $(#[$attr])*
        #[dirac(joint(th1 => w1) = revolute(y, world, link1 at [0.0, 0.0, a1]))]
        #[dirac(joint(th2 => w2) = revolute(y, link1 at [0.0, 0.0, -b1], link2 at [0.0, 0.0, a2]))]
        pub struct $name {
            pub link1: RigidBody,
            pub link2: RigidBody,
            pub a1: f64,
            pub b1: f64,
            pub a2: f64,
        }

        impl $name {
            pub fn new(spatial: &SpatialDoublePendulum) -> $name {
                let s = spatial.clone();
                $name { link1: s.link1, link2: s.link2, a1: s.a1, b1: s.b1, a2: s.a2 }
            }
        }
    };
}

jointed_double_pendulum!(JointedDoublePendulum);
jointed_double_pendulum!(
    #[dirac(reduce)]
    ReducedDoublePendulum
);

/// The same pendulum in its two joint angles (about `y`, zero hanging down), written by hand:
/// the centres at `(−a1 sin θ1, −a1 cos θ1)` and `(−l1 sin θ1 − a2 sin θ2, …)` in `(x, z)`,
/// `l1 = a1 + b1`, and each link's own inertia about `y`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(th1 => w1, th2 => w2))]
#[dirac(define(l1) = a1 + b1)]
#[dirac(define(vx2) = -l1 * th1.cos() * w1 - a2 * th2.cos() * w2)]
#[dirac(define(vz2) = l1 * th1.sin() * w1 + a2 * th2.sin() * w2)]
#[dirac(lagrangian = 0.5 * (m1 * a1 * a1 + j1) * w1 * w1 + 0.5 * m2 * (vx2 * vx2 + vz2 * vz2) + 0.5 * j2 * w2 * w2
    + m1 * g * a1 * th1.cos() + m2 * g * (l1 * th1.cos() + a2 * th2.cos()))]
pub struct PlanarDoublePendulum {
    pub m1: f64,
    pub m2: f64,
    pub j1: f64,
    pub j2: f64,
    pub a1: f64,
    pub b1: f64,
    pub a2: f64,
    pub g: f64,
}

/// `R_y(θ)` as rows.
pub fn about_y(theta: f64) -> [[f64; 3]; 3] {
    let (s, c) = theta.sin_cos();
    [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]]
}

/// The spatial pendulum at joint angles `th` and rates `w`, with its constraints' multipliers
/// found by `consistent_state`.
pub fn spatial_start(
    model: &SpatialDoublePendulum,
    th: [f64; 2],
    w: [f64; 2],
) -> State<SpatialDoublePendulum> {
    let (a1, b1, a2) = (model.a1, model.b1, model.a2);
    let l1 = a1 + b1;
    let centre1 = [-a1 * th[0].sin(), 0.0, -a1 * th[0].cos()];
    let velocity1 = [-a1 * th[0].cos() * w[0], 0.0, a1 * th[0].sin() * w[0]];
    let centre2 = [-l1 * th[0].sin() - a2 * th[1].sin(), 0.0, -l1 * th[0].cos() - a2 * th[1].cos()];
    let velocity2 = [
        -l1 * th[0].cos() * w[0] - a2 * th[1].cos() * w[1],
        0.0,
        l1 * th[0].sin() * w[0] + a2 * th[1].sin() * w[1],
    ];
    let (q1, v1) = model.link1.state(centre1, about_y(th[0]), velocity1, [0.0, w[0], 0.0]);
    let (q2, v2) = model.link2.state(centre2, about_y(th[1]), velocity2, [0.0, w[1], 0.0]);
    let (mut q, mut v) = (VecQ::<SpatialDoublePendulum>::zeros(), VecQ::<SpatialDoublePendulum>::zeros());
    q.rows_mut(0, 12).copy_from(&q1);
    q.rows_mut(12, 12).copy_from(&q2);
    v.rows_mut(0, 12).copy_from(&v1);
    v.rows_mut(12, 12).copy_from(&v2);
    consistent_state(model, 0.0, &q, &v, Consistency::default()).expect("a consistent start")
}

pub fn double_pendulums() -> (SpatialDoublePendulum, PlanarDoublePendulum) {
    let (m1, m2, g) = (1.5, 0.8, 9.81);
    // Boxes: link 1 of 0.1 × 0.2 × 1.0 m, link 2 of 0.3 × 0.1 × 0.6 m.
    let box_moments = |m: f64, [x, y, z]: [f64; 3]| {
        [m * (y * y + z * z) / 12.0, m * (x * x + z * z) / 12.0, m * (x * x + y * y) / 12.0]
    };
    let (j1, j2) = (box_moments(m1, [0.1, 0.2, 1.0]), box_moments(m2, [0.3, 0.1, 0.6]));
    let (a1, b1, a2) = (0.5, 0.5, 0.3);
    let spatial = SpatialDoublePendulum {
        link1: RigidBody::new(m1, j1).with_gravity(g),
        link2: RigidBody::new(m2, j2).with_gravity(g),
        a1,
        b1,
        a2,
    };
    let planar = PlanarDoublePendulum { m1, m2, j1: j1[1], j2: j2[1], a1, b1, a2, g };
    (spatial, planar)
}

/// A 6-6 Stewart platform: a platform body held by six legs between six points of the ground
/// `b_i` and six points of the platform `p_i` (in its frame), all distinct. The legs are
/// massless actuators (spherical joints at both ends, a prismatic joint between), each a
/// holonomic row closing its loop through the ground and the platform: the squared length
/// `|x + R p_i − b_i|²` prescribed as `c_i (1 + 0.1 sin(2 t + i))`, with `c_i` the squared
/// length of the nominal pose (the platform level at height 1). The points:
/// `b = (1, ±0.2, 0), (−0.3, ±0.95, 0), (−0.7, ±0.75, 0)`,
/// `p = (0.45, ±0.35, 0), (0.1, ±0.55, 0), (−0.55, ±0.2, 0)`.
#[derive(Interconnection, Clone, Debug)]
#[dirac(holonomic(leg1) = (top.x + 0.45 * top.r11 + 0.35 * top.r12 - 1.0).powi(2)
    + (top.y + 0.45 * top.r21 + 0.35 * top.r22 - 0.2).powi(2)
    + (top.z + 0.45 * top.r31 + 0.35 * top.r32).powi(2) - 1.325 * (1.0 + 0.1 * (2.0 * t + 1.0).sin()))]
#[dirac(holonomic(leg2) = (top.x + 0.1 * top.r11 + 0.55 * top.r12 + 0.3).powi(2)
    + (top.y + 0.1 * top.r21 + 0.55 * top.r22 - 0.95).powi(2)
    + (top.z + 0.1 * top.r31 + 0.55 * top.r32).powi(2) - 1.32 * (1.0 + 0.1 * (2.0 * t + 2.0).sin()))]
#[dirac(holonomic(leg3) = (top.x - 0.55 * top.r11 + 0.2 * top.r12 + 0.7).powi(2)
    + (top.y - 0.55 * top.r21 + 0.2 * top.r22 - 0.75).powi(2)
    + (top.z - 0.55 * top.r31 + 0.2 * top.r32).powi(2) - 1.325 * (1.0 + 0.1 * (2.0 * t + 3.0).sin()))]
#[dirac(holonomic(leg4) = (top.x - 0.55 * top.r11 - 0.2 * top.r12 + 0.7).powi(2)
    + (top.y - 0.55 * top.r21 - 0.2 * top.r22 + 0.75).powi(2)
    + (top.z - 0.55 * top.r31 - 0.2 * top.r32).powi(2) - 1.325 * (1.0 + 0.1 * (2.0 * t + 4.0).sin()))]
#[dirac(holonomic(leg5) = (top.x + 0.1 * top.r11 - 0.55 * top.r12 + 0.3).powi(2)
    + (top.y + 0.1 * top.r21 - 0.55 * top.r22 + 0.95).powi(2)
    + (top.z + 0.1 * top.r31 - 0.55 * top.r32).powi(2) - 1.32 * (1.0 + 0.1 * (2.0 * t + 5.0).sin()))]
#[dirac(holonomic(leg6) = (top.x + 0.45 * top.r11 - 0.35 * top.r12 - 1.0).powi(2)
    + (top.y + 0.45 * top.r21 - 0.35 * top.r22 + 0.2).powi(2)
    + (top.z + 0.45 * top.r31 - 0.35 * top.r32).powi(2) - 1.325 * (1.0 + 0.1 * (2.0 * t + 6.0).sin()))]
pub struct Stewart {
    pub top: RigidBody,
}
