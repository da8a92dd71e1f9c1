//! Joints between rigid bodies (`joint(th => w) = revolute(..)`, `prismatic`, `fixed`): the
//! rows a joint stands for without `reduce`, and the joint coordinates `reduce` compiles a tree
//! of bodies to. References: hand-written models in the joints' angles and slides (their
//! Lagrangians from the bodies' centres by hand), the spatial pendulum written with its rows
//! by hand (`zoo::bodies::SpatialDoublePendulum`), and the four-bar's loop closed by the
//! intersection of two circles.

// The derives' accessors and constants of these models are not all read here.
#![allow(dead_code)]

use dirac::State;
use dirac::components::bodies::RigidBody;
use dirac::prelude::*;

use crate::every_method::{Fineness, Method};
use crate::zoo::bodies::{
    JointedDoublePendulum, PlanarDoublePendulum, ReducedDoublePendulum, double_pendulums, spatial_start,
};

fn largest(xs: impl IntoIterator<Item = f64>) -> f64 {
    xs.into_iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

#[test]
fn a_joint_stands_for_the_rows_written_by_hand() {
    // The named joints make the rows the zoo's pendulum writes by hand: the same count, the
    // same motion.
    assert_eq!(JointedDoublePendulum::NAMES.constraint_names().len(), 22);
    let (spatial, _) = double_pendulums();
    let jointed = JointedDoublePendulum::new(&spatial);
    let (th, w) = ([0.9, -0.4], [0.3, 1.1]);
    let start = spatial_start(&spatial, th, w);
    let mut phi = VecH::<JointedDoublePendulum>::zeros();
    jointed.holonomic(0.0, &start.q, &mut phi);
    assert!(phi.amax() < 1e-15, "the hand rows' start satisfies the joints: {phi}");
    let times = [0.5, 1.0];
    let tight = RadauOptions { projection: true, ..RadauOptions::tolerances(1e-12, 1e-12) };
    let by_hand = Radau::new(&spatial, tight)
        .expect("valid")
        .solve(0.0, &start, 1.0, &Sampling::Times(times.to_vec()))
        .expect("it swings");
    let begin = consistent_state(&jointed, 0.0, &start.q, &start.v, Consistency::default()).expect("a start");
    let joints = Radau::new(&jointed, tight)
        .expect("valid")
        .solve(0.0, &begin, 1.0, &Sampling::Times(times.to_vec()))
        .expect("it swings");
    for (k, t) in times.iter().enumerate() {
        let (a, b) = (by_hand.state(k).expect("a sample"), joints.state(k).expect("a sample"));
        assert!((a.q - b.q).amax() < 1e-9, "t = {t}");
    }
}

#[test]
fn a_tree_of_bodies_reduces_to_its_joint_angles_and_moves_as_the_planar_model() {
    assert_eq!(ReducedDoublePendulum::NAMES.coordinate_names(), ["th1", "th2"]);
    assert!(ReducedDoublePendulum::NAMES.constraint_names().is_empty());
    // Every coordinate of the bodies is read off the angles.
    let eliminated = ReducedDoublePendulum::ELIMINATED;
    for name in ["link1.x", "link1.r33", "link2.z", "link2.r11"] {
        assert!(eliminated.iter().any(|(n, _)| *n == name), "{name} not in {eliminated:?}");
    }
    let (spatial, planar) = double_pendulums();
    let reduced = ReducedDoublePendulum::new(&spatial);
    let (th, w) = ([0.9, -0.4], [0.3, 1.1]);
    // Link 2's joint angle is its angle to link 1.
    let mut start = State::<ReducedDoublePendulum>::zeros();
    start.set_q(ReducedDoublePendulum::TH1, th[0]).set_q(ReducedDoublePendulum::TH2, th[1] - th[0]);
    start.set_v(ReducedDoublePendulum::TH1, w[0]).set_v(ReducedDoublePendulum::TH2, w[1] - w[0]);
    let mut hand = State::<PlanarDoublePendulum>::zeros();
    hand.set_q(PlanarDoublePendulum::TH1, th[0]).set_q(PlanarDoublePendulum::TH2, th[1]);
    hand.set_v(PlanarDoublePendulum::TH1, w[0]).set_v(PlanarDoublePendulum::TH2, w[1]);
    let start = consistent_state(&reduced, 0.0, &start.q, &start.v, Consistency::default()).expect("a start");
    let hand = consistent_state(&planar, 0.0, &hand.q, &hand.v, Consistency::default()).expect("a start");
    let times: Vec<f64> = (1..=10).map(|k| 0.2 * k as f64).collect();
    let fineness = Fineness::new(1e-12, 1e-12, 1e-3);
    let mut ends = Vec::new();
    each_integrator!(&planar, fineness, |method, integrator| {
        let solution = integrator.solve(0.0, &hand, 2.0, &Sampling::Times(times.clone())).expect("it swings");
        ends.push((
            method,
            (0..times.len()).map(|k| solution.state(k).expect("a sample")).collect::<Vec<_>>(),
        ));
    });
    each_integrator!(&reduced, fineness, |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 2.0, &Sampling::Times(times.clone())).expect("it swings");
        let (_, reference) = ends.iter().find(|(m, _)| *m == method).expect("the hand model's run");
        let mut error = 0.0f64;
        for (k, b) in reference.iter().enumerate() {
            let a = solution.state(k).expect("a sample");
            error = error.max((a.q[0] - b.q[0]).abs()).max((a.q[0] + a.q[1] - b.q[1]).abs());
        }
        // The adaptive methods to their tolerance; the variational method takes the same steps
        // in both, and its discrete Lagrangian commutes with the linear change of angles, so
        // the two agree to its solver's tolerance, not only to its order.
        println!("{}: joint coordinates against the planar model: max |Δθ| = {error:.1e}", method.name());
        assert!(error < 1e-9, "{}: {error:e}", method.name());
    });
    // The bodies' outputs read through the angles: link 2's energy and the whole energy.
    let jointed = JointedDoublePendulum::new(&spatial);
    let body_start = spatial_start(&spatial, th, w);
    let body_start = consistent_state(&jointed, 0.0, &body_start.q, &body_start.v, Consistency::default())
        .expect("a start");
    let tight = RadauOptions { projection: true, ..RadauOptions::tolerances(1e-12, 1e-12) };
    let bodies = Radau::new(&jointed, tight)
        .expect("valid")
        .solve(0.0, &body_start, 1.0, &Sampling::Times(vec![0.5, 1.0]))
        .expect("it swings");
    let angles = Radau::new(&reduced, RadauOptions::tolerances(1e-12, 1e-12))
        .expect("valid")
        .solve(0.0, &start, 1.0, &Sampling::Times(vec![0.5, 1.0]))
        .expect("it swings");
    for column in ["out(link2.energy)", "out(link1.wy)", "out(link2.hy)", "energy"] {
        let (a, b) = (bodies.column(column).expect("a column"), angles.column(column).expect("a column"));
        let apart = largest(a.iter().zip(b).map(|(x, y)| x - y));
        assert!(apart < 1e-8, "{column}: {a:?} against {b:?}");
    }
}

#[test]
fn joint_coordinates_have_the_derivatives_their_differences_say() {
    let (spatial, _) = double_pendulums();
    let reduced = ReducedDoublePendulum::new(&spatial);
    crate::util::check_jacobian_by_differences(&reduced, 51, 3);
    crate::blocks::check_blocks(&reduced, 52);
    crate::sensitivities::check_parameter_derivatives(&reduced, 53, 2);
    let cart = cart_pole();
    crate::util::check_jacobian_by_differences(&cart, 54, 3);
    crate::sensitivities::check_parameter_derivatives(&cart, 55, 2);
    let loop_ = four_bar();
    crate::util::check_jacobian_by_differences(&loop_, 56, 3);
    crate::blocks::check_blocks(&loop_, 57);
}

macro_rules! cart_pole_with_bob {
    ($(#[$attr:meta])* $name:ident) => {
        /// A cart sliding along space's `x` axis, a pole hinged on it about `y` at `hp` above
        /// the pole's centre, and a bob welded to the pole's lower end.
        #[derive(Interconnection, Clone, Debug)]
        $(#[$attr])*
        #[dirac(joint(s => vs) = prismatic(x, world, cart))]
        #[dirac(joint(th => w) = revolute(y, cart, pole at [0.0, 0.0, hp]))]
        #[dirac(joint(weld) = fixed(pole at [0.0, 0.0, -hp], bob))]
        pub struct $name {
            pub cart: RigidBody,
            pub pole: RigidBody,
            pub bob: RigidBody,
            pub hp: f64,
        }
    };
}

// Its 36 coordinates take more stack than a model may without asking; only its rows are read.
cart_pole_with_bob!(
    #[dirac(large)]
    CartPole
);
cart_pole_with_bob!(
    #[dirac(reduce)]
    CartPoleReduced
);

/// The same by hand: the pole's centre at `(s − hp sin θ, −hp cos θ)` in `(x, z)`, the bob's
/// at `(s − 2 hp sin θ, −2 hp cos θ)`, both turning at `θ'` about `y`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(s => vs, th => w))]
#[dirac(define(c) = th.cos(), define(sn) = th.sin())]
#[dirac(lagrangian = 0.5 * mc * vs * vs
    + 0.5 * mp * ((vs - hp * c * w).powi(2) + (hp * sn * w).powi(2)) + 0.5 * jp * w * w
    + 0.5 * mb * ((vs - 2.0 * hp * c * w).powi(2) + (2.0 * hp * sn * w).powi(2)) + 0.5 * jb * w * w
    + mp * g * hp * c + mb * g * 2.0 * hp * c)]
pub struct CartPoleByHand {
    pub mc: f64,
    pub mp: f64,
    pub jp: f64,
    pub mb: f64,
    pub jb: f64,
    pub hp: f64,
    pub g: f64,
}

fn cart_pole() -> CartPoleReduced {
    let g = 9.81;
    CartPoleReduced {
        cart: RigidBody::new(2.0, [0.1, 0.2, 0.3]).with_gravity(g),
        pole: RigidBody::new(0.5, [0.05, 0.06, 0.01]).with_gravity(g),
        bob: RigidBody::new(0.3, [0.002, 0.003, 0.004]).with_gravity(g),
        hp: 0.4,
    }
}

#[test]
fn a_slide_a_hinge_and_a_weld_reduce_to_the_cart_poles_two_coordinates() {
    assert_eq!(CartPoleReduced::NAMES.coordinate_names(), ["s", "th"]);
    assert!(CartPoleReduced::NAMES.constraint_names().is_empty());
    let reduced = cart_pole();
    let hand = CartPoleByHand {
        mc: reduced.cart.m,
        mp: reduced.pole.m,
        jp: reduced.pole.jyy,
        mb: reduced.bob.m,
        jb: reduced.bob.jyy,
        hp: reduced.hp,
        g: 9.81,
    };
    let (q, v) = ([0.1, 0.8], [-0.5, 1.2]);
    let mut start = State::<CartPoleReduced>::zeros();
    let mut hand_start = State::<CartPoleByHand>::zeros();
    for k in 0..2 {
        (start.q[k], start.v[k], hand_start.q[k], hand_start.v[k]) = (q[k], v[k], q[k], v[k]);
    }
    let start = consistent_state(&reduced, 0.0, &start.q, &start.v, Consistency::default()).expect("a start");
    let hand_start =
        consistent_state(&hand, 0.0, &hand_start.q, &hand_start.v, Consistency::default()).expect("a start");
    let times: Vec<f64> = (1..=10).map(|k| 0.2 * k as f64).collect();
    let fineness = Fineness::new(1e-12, 1e-12, 1e-3);
    let mut references = Vec::new();
    each_integrator!(&hand, fineness, |method, integrator| {
        let solution =
            integrator.solve(0.0, &hand_start, 2.0, &Sampling::Times(times.clone())).expect("it swings");
        references.push((
            method,
            (0..times.len()).map(|k| solution.state(k).expect("a sample")).collect::<Vec<_>>(),
        ));
    });
    each_integrator!(&reduced, fineness, |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 2.0, &Sampling::Times(times.clone())).expect("it swings");
        let (_, reference) = references.iter().find(|(m, _)| *m == method).expect("the hand model's run");
        let error = largest((0..times.len()).flat_map(|k| {
            let (a, b) = (solution.state(k).expect("a sample"), &reference[k]);
            [a.q[0] - b.q[0], a.q[1] - b.q[1], a.v[0] - b.v[0], a.v[1] - b.v[1]]
        }));
        println!("{}: slide, hinge and weld against the hand model: {error:.1e}", method.name());
        assert!(error < 1e-9, "{}: {error:e}", method.name());
    });
    // The unreduced composite's rows hold where the reduced model puts the bodies, and only
    // there: its bodies' coordinates from the reduced model's outputs of position.
    let plain = CartPole {
        cart: reduced.cart.clone(),
        pole: reduced.pole.clone(),
        bob: reduced.bob.clone(),
        hp: reduced.hp,
    };
    let (s, th) = (q[0], q[1]);
    let turn = crate::zoo::bodies::about_y(th);
    let eye = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let hp = reduced.hp;
    let (cart_q, _) = plain.cart.state([s, 0.0, 0.0], eye, [0.0; 3], [0.0; 3]);
    let (pole_q, _) = plain.pole.state([s - hp * th.sin(), 0.0, -hp * th.cos()], turn, [0.0; 3], [0.0; 3]);
    let (bob_q, _) =
        plain.bob.state([s - 2.0 * hp * th.sin(), 0.0, -2.0 * hp * th.cos()], turn, [0.0; 3], [0.0; 3]);
    let mut full = VecQ::<CartPole>::zeros();
    for (k, part) in [cart_q, pole_q, bob_q].iter().enumerate() {
        full.rows_mut(12 * k, 12).copy_from(part);
    }
    let mut phi = VecH::<CartPole>::zeros();
    plain.holonomic(0.0, &full, &mut phi);
    assert_eq!(phi.len(), 18 + 5 + 5 + 6);
    assert!(phi.amax() < 1e-15, "{phi}");
    // The bob a centimetre off the pole's end, or turned against it, breaks the weld's rows.
    for (index, by) in [(26, 0.01), (29, 0.01)] {
        let mut off = full;
        off[index] += by;
        plain.holonomic(0.0, &off, &mut phi);
        let weld = CartPole::NAMES
            .constraint_names()
            .iter()
            .position(|n| n.starts_with("weld"))
            .expect("the weld's rows");
        assert!(largest(phi.iter().skip(weld).take(6).copied()) > 1e-3, "coordinate {index}: {phi}");
    }
}

/// A planar four-bar of bodies about `y`: a crank from the origin, a coupler, a rocker from
/// `(d, 0, 0)`, each a rod of length `2 h` with its ends at `(0, 0, ±h)`; the joint between
/// the coupler and the rocker closes the loop.
#[derive(Interconnection, Clone, Debug)]
#[dirac(reduce)]
#[dirac(joint(th1 => w1) = revolute(y, world, crank at [0.0, 0.0, h1]))]
#[dirac(joint(th2 => w2) = revolute(y, crank at [0.0, 0.0, -h1], coupler at [0.0, 0.0, h2]))]
#[dirac(joint(th3 => w3) = revolute(y, world at [d, 0.0, 0.0], rocker at [0.0, 0.0, h3]))]
#[dirac(joint(th4 => w4) = revolute(y, coupler at [0.0, 0.0, -h2], rocker at [0.0, 0.0, -h3]))]
pub struct FourBar {
    pub crank: RigidBody,
    pub coupler: RigidBody,
    pub rocker: RigidBody,
    pub h1: f64,
    pub h2: f64,
    pub h3: f64,
    pub d: f64,
}

/// The same by hand in the links' absolute angles `p1, p2, p3` (about `y`, zero hanging),
/// the loop closed by two rows: the coupler's far end on the rocker's.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(p1 => w1, p2 => w2, p3 => w3))]
#[dirac(define(s1) = p1.sin(), define(c1) = p1.cos(), define(s2) = p2.sin(), define(c2) = p2.cos())]
#[dirac(define(s3) = p3.sin(), define(c3) = p3.cos())]
#[dirac(lagrangian = 0.5 * m1 * h1 * h1 * w1 * w1 + 0.5 * j1 * w1 * w1
    + 0.5 * m2 * ((2.0 * h1 * c1 * w1 + h2 * c2 * w2).powi(2) + (2.0 * h1 * s1 * w1 + h2 * s2 * w2).powi(2))
    + 0.5 * j2 * w2 * w2
    + 0.5 * m3 * h3 * h3 * w3 * w3 + 0.5 * j3 * w3 * w3
    + m1 * g * h1 * c1 + m2 * g * (2.0 * h1 * c1 + h2 * c2) + m3 * g * h3 * c3)]
#[dirac(holonomic(close_x) = -2.0 * h1 * s1 - 2.0 * h2 * s2 - d + 2.0 * h3 * s3)]
#[dirac(holonomic(close_z) = -2.0 * h1 * c1 - 2.0 * h2 * c2 + 2.0 * h3 * c3)]
pub struct FourBarByHand {
    pub m1: f64,
    pub m2: f64,
    pub m3: f64,
    pub j1: f64,
    pub j2: f64,
    pub j3: f64,
    pub h1: f64,
    pub h2: f64,
    pub h3: f64,
    pub d: f64,
    pub g: f64,
}

/// A rod of mass `m` and length `2 h` along its `z` axis, thin (its section 0.02 across),
/// under gravity.
pub(crate) fn rod(m: f64, h: f64) -> RigidBody {
    let across = m * (4.0 * h * h + 4e-4) / 12.0;
    RigidBody::new(m, [across, across, m * 8e-4 / 12.0]).with_gravity(9.81)
}

/// The four-bar's half-lengths `h1, h2, h3` of crank, coupler and rocker and the distance `d`
/// between the pivots.
pub(crate) const FOUR_BAR: [f64; 4] = [0.2, 0.5, 0.4, 0.7];

fn four_bar() -> FourBar {
    let [h1, h2, h3, d] = FOUR_BAR;
    FourBar { crank: rod(0.5, h1), coupler: rod(0.8, h2), rocker: rod(0.6, h3), h1, h2, h3, d }
}

/// The coupler's and rocker's angles where the crank is at `p1`, the rocker hanging: the far
/// end `B` of the coupler is where the circle of radius `2 h2` about the crank's end meets the
/// circle of radius `2 h3` about the rocker's pivot, the lower of the two points.
pub(crate) fn closed_loop([h1, h2, h3, d]: [f64; 4], p1: f64) -> (f64, f64) {
    let (l1, l2, l3) = (2.0 * h1, 2.0 * h2, 2.0 * h3);
    let a = [-l1 * p1.sin(), -l1 * p1.cos()];
    let o = [d, 0.0];
    let (dx, dz) = (o[0] - a[0], o[1] - a[1]);
    let gap = (dx * dx + dz * dz).sqrt();
    let along = (l2 * l2 - l3 * l3 + gap * gap) / (2.0 * gap);
    let across = (l2 * l2 - along * along).sqrt();
    let mid = [a[0] + along * dx / gap, a[1] + along * dz / gap];
    let candidates = [
        [mid[0] - across * dz / gap, mid[1] + across * dx / gap],
        [mid[0] + across * dz / gap, mid[1] - across * dx / gap],
    ];
    let b = if candidates[0][1] < candidates[1][1] { candidates[0] } else { candidates[1] };
    // B = A − l2 (sin p2, cos p2) = O − l3 (sin p3, cos p3).
    ((a[0] - b[0]).atan2(a[1] - b[1]), (o[0] - b[0]).atan2(o[1] - b[1]))
}

/// The coupler's and rocker's rates where the crank turns at `w1`, from the loop's rows
/// differentiated: `l1 c1 w1 + l2 c2 w2 = l3 c3 w3`, `l1 s1 w1 + l2 s2 w2 = l3 s3 w3`.
pub(crate) fn loop_rates([h1, h2, h3, _]: [f64; 4], (p1, p2, p3): (f64, f64, f64), w1: f64) -> (f64, f64) {
    let (l1, l2, l3) = (2.0 * h1, 2.0 * h2, 2.0 * h3);
    let (r1, r2) = (-l1 * p1.cos() * w1, -l1 * p1.sin() * w1);
    let det = l2 * p2.cos() * (-l3 * p3.sin()) + l3 * p3.cos() * l2 * p2.sin();
    let w2 = (r1 * (-l3 * p3.sin()) + l3 * p3.cos() * r2) / det;
    let w3 = (l2 * p2.cos() * r2 - l2 * p2.sin() * r1) / det;
    (w2, w3)
}

#[test]
fn a_four_bar_of_bodies_keeps_one_cut_joints_rows_and_closes_as_the_circles_say() {
    assert_eq!(FourBar::NAMES.coordinate_names(), ["th1", "th2", "th3"]);
    // The planar loop's cut keeps its two rows in the plane; its rows across the plane and of
    // its axis are zero whatever the angles, and leave.
    assert_eq!(FourBar::NAMES.constraint_names(), ["th4_x", "th4_z"]);
    let model = four_bar();
    let j = |b: &RigidBody| b.jyy;
    let hand = FourBarByHand {
        m1: model.crank.m,
        m2: model.coupler.m,
        m3: model.rocker.m,
        j1: j(&model.crank),
        j2: j(&model.coupler),
        j3: j(&model.rocker),
        h1: model.h1,
        h2: model.h2,
        h3: model.h3,
        d: model.d,
        g: 9.81,
    };
    // Started closed: the crank at 0.3 rad turning at 1.5 rad/s.
    let (p1, w1) = (0.3, 1.5);
    let (p2, p3) = closed_loop(FOUR_BAR, p1);
    let (w2, w3) = loop_rates(FOUR_BAR, (p1, p2, p3), w1);
    let mut start = State::<FourBar>::zeros();
    (start.q[0], start.q[1], start.q[2]) = (p1, p2 - p1, p3);
    (start.v[0], start.v[1], start.v[2]) = (w1, w2 - w1, w3);
    let start = consistent_state(&model, 0.0, &start.q, &start.v, Consistency::default()).expect("a start");
    let mut hand_start = State::<FourBarByHand>::zeros();
    (hand_start.q[0], hand_start.q[1], hand_start.q[2]) = (p1, p2, p3);
    (hand_start.v[0], hand_start.v[1], hand_start.v[2]) = (w1, w2, w3);
    let hand_start =
        consistent_state(&hand, 0.0, &hand_start.q, &hand_start.v, Consistency::default()).expect("a start");
    let times: Vec<f64> = (1..=10).map(|k| 0.2 * k as f64).collect();
    let tight = RadauOptions { projection: true, ..RadauOptions::tolerances(1e-12, 1e-12) };
    let reference = Radau::new(&hand, tight)
        .expect("valid")
        .solve(0.0, &hand_start, 2.0, &Sampling::Times(times.clone()))
        .expect("it swings");
    each_integrator!(&model, Fineness::new(1e-12, 1e-12, 1e-4).projected(), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 2.0, &Sampling::Times(times.clone())).expect("it swings");
        let (mut apart, mut closure) = (0.0f64, 0.0f64);
        for k in 0..times.len() {
            let (a, b) = (solution.state(k).expect("a sample"), reference.state(k).expect("a sample"));
            let angles = [a.q[0], a.q[0] + a.q[1], a.q[2]];
            apart = apart.max(largest((0..3).map(|i| angles[i] - b.q[i])));
            let (p2, p3) = closed_loop(FOUR_BAR, angles[0]);
            closure = closure.max((p2 - angles[1]).abs()).max((p3 - angles[2]).abs());
        }
        let drift = largest(solution.holonomic_residual().iter().copied());
        println!(
            "{}: four-bar against the hand model {apart:.1e}, against the closed loop {closure:.1e}, rows {drift:.1e}",
            method.name()
        );
        let bound = if method == Method::Variational { 1e-5 } else { 1e-8 };
        assert!(apart < bound, "{}: {apart:e}", method.name());
        assert!(closure < 1e-11 && drift < 1e-13, "{}: {closure:e} {drift:e}", method.name());
    });
    // It moved through the loop: the crank swung.
    let crank: Vec<f64> = (0..times.len()).map(|k| reference.state(k).expect("a sample").q[0]).collect();
    let swing = crank.iter().fold(f64::MIN, |m, x| m.max(*x)) - crank.iter().fold(f64::MAX, |m, x| m.min(*x));
    assert!(swing > 0.1, "{crank:?}");
}

macro_rules! damped_pivot {
    ($(#[$attr:meta])* $name:ident) => {
        /// The zoo's reduced pendulum with a rotational damper between its pivot's angle and a
        /// fixed housing.
        #[derive(Interconnection, Clone, Debug)]
        $(#[$attr])*
        #[dirac(connect(pendulum.th1, damper.b), connect(damper.a, housing.phi))]
        pub struct $name {
            pub pendulum: ReducedDoublePendulum,
            pub damper: dirac::components::rotational::Damper,
            pub housing: dirac::components::rotational::Fixed,
        }
    };
}

damped_pivot!(DampedPivot);
damped_pivot!(
    #[dirac(reduce)]
    DampedPivotReduced
);

/// A reduced composite nested in a reduced one keeps its joint coordinates: the outer
/// reduction receives the joints, not their rows. Reference: the same composite without
/// `reduce` on the outer level (the inner pendulum reduced on its own, checked against the
/// planar model above), at 1e-12.
#[test]
fn joints_of_a_nested_reduced_composite_stay_joint_coordinates() {
    assert_eq!(DampedPivotReduced::NAMES.coordinate_names(), ["pendulum.th1", "pendulum.th2"]);
    assert!(DampedPivotReduced::NAMES.constraint_names().is_empty());
    let (spatial, _) = double_pendulums();
    let damper = dirac::components::rotational::Damper { d: 0.7 };
    let housing = dirac::components::rotational::Fixed { phi0: 0.0 };
    let pendulum = ReducedDoublePendulum::new(&spatial);
    let nested = DampedPivot { pendulum: pendulum.clone(), damper: damper.clone(), housing: housing.clone() };
    let flat = DampedPivotReduced { pendulum, damper, housing };
    let (q, v) = ([0.9, -1.3], [0.3, 0.8]);
    let mut start = State::<DampedPivotReduced>::zeros();
    start.q.copy_from_slice(&q);
    start.v.copy_from_slice(&v);
    let start = consistent_state(&flat, 0.0, &start.q, &start.v, Consistency::default()).expect("a start");
    let names = DampedPivot::NAMES.coordinate_names();
    let at = |name: &str| names.iter().position(|n| n == name).expect("a coordinate");
    let (mut q0, mut v0) = (VecQ::<DampedPivot>::zeros(), VecQ::<DampedPivot>::zeros());
    for (k, name) in ["pendulum.th1", "pendulum.th2"].iter().enumerate() {
        q0[at(name)] = q[k];
        v0[at(name)] = v[k];
    }
    q0[at("damper.b")] = q[0];
    v0[at("damper.b")] = v[0];
    let reference_start = consistent_state(&nested, 0.0, &q0, &v0, Consistency::default()).expect("a start");
    let times: Vec<f64> = (1..=5).map(|k| 0.4 * k as f64).collect();
    let tight = RadauOptions::tolerances(1e-12, 1e-12);
    let reference = Radau::new(&nested, tight)
        .expect("valid")
        .solve(0.0, &reference_start, 2.0, &Sampling::Times(times.clone()))
        .expect("it swings");
    let got = Radau::new(&flat, tight)
        .expect("valid")
        .solve(0.0, &start, 2.0, &Sampling::Times(times.clone()))
        .expect("it swings");
    let mut apart = 0.0f64;
    for k in 0..times.len() {
        let (a, b) = (got.state(k).expect("a sample"), reference.state(k).expect("a sample"));
        apart = apart.max(largest((0..2).map(|i| a.q[i] - b.q[at(["pendulum.th1", "pendulum.th2"][i])])));
    }
    println!("nested joints against the composite: max |Δθ| = {apart:.1e}");
    assert!(apart < 1e-9, "{apart:e}");
    // The damper took energy out: the reference is not at rest.
    let energy = reference.column("energy").expect("the energy");
    assert!(energy[energy.len() - 1] < energy[0] - 1e-3, "{energy:?}");
}
