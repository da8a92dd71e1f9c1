//! Robots read from URDF files when the tests compile.

use dirac::prelude::*;

/// The Franka Emika Panda (`tests/robots/panda/panda.urdf`, from the `example-robot-data`
/// package): seven revolute joints and two prismatic fingers, the second mimicking the first.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/panda/panda.urdf")]
pub struct Panda;

/// The swing's start (tests/references/robots.py): the arm out to the side, fingers half open.
pub const SWING_START: [f64; 9] = [0.3, 0.5, -0.4, -1.2, 0.2, 1.4, 0.6, 0.02, 0.02];

/// The Panda's seven-joint arm (`tests/robots/panda/panda_arm.urdf`: the fingers fixed), as
/// `benches/peers/robots.sh` loads it into MuJoCo and Pinocchio too.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/panda/panda_arm.urdf")]
pub struct PandaArm;

/// The Panda's arm of [`PandaArm`] with a torque at each joint (`t1` … `t7`), for optimal
/// control: without its joints' limits, which would be unilateral constraints.
#[derive(LagrangeDirac, Clone, Debug, Default)]
#[dirac(urdf = "../tests/robots/panda/panda_arm.urdf")]
#[dirac(input(t1), input(t2), input(t3), input(t4), input(t5), input(t6), input(t7))]
#[dirac(force(panda_joint1) = t1, force(panda_joint2) = t2, force(panda_joint3) = t3, force(panda_joint4) = t4)]
#[dirac(force(panda_joint5) = t5, force(panda_joint6) = t6, force(panda_joint7) = t7)]
pub struct PandaTorques {
    pub t1: f64,
    pub t2: f64,
    pub t3: f64,
    pub t4: f64,
    pub t5: f64,
    pub t6: f64,
    pub t7: f64,
}

/// The Panda's arm moved by its seven torques from one pose to another, at rest at both ends,
/// in 2 s on `intervals` intervals: positions within `panda_arm.urdf`'s joint limits, torques
/// within its efforts (`benches/peers/optimal.py` checks both against Pinocchio's reading),
/// and a cost of `|u|²/2 + 5 |v|²` per second. The velocity term makes the optimum unique
/// enough to be found from different guesses; without it the program has many local optima.
pub fn panda_point_to_point(intervals: usize) -> dirac::optimal::Problem<PandaTorques> {
    let start = [0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 0.8];
    let end = [1.0, 0.2, -0.5, -1.5, 0.4, 1.6, 0.0];
    let lower = [-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973];
    let upper = [2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973];
    let effort = [87.0, 87.0, 87.0, 87.0, 12.0, 12.0, 12.0];
    let mut problem = dirac::optimal::Problem::new(PandaTorques::default(), 2.0, intervals)
        .start(VecQ::<PandaTorques>::from(start), VecQ::<PandaTorques>::zeros())
        .final_state(VecQ::<PandaTorques>::from(end), VecQ::<PandaTorques>::zeros());
    for i in 0..7 {
        let joint = Coordinate::checked(i).expect("seven joints");
        let torque = dirac::Input::checked(i).expect("seven torques");
        problem = problem
            .position_bounds(joint, lower[i], upper[i])
            .input_bounds(torque, -effort[i], effort[i])
            .velocity_weight(joint, 10.0, 0.0);
    }
    problem
}

/// The Panda with its joints' limits as hard stops.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/panda/panda.urdf", joint_limits)]
pub struct PandaStops;

/// The Panda floating in the world (Pinocchio's free flyer as its root joint, `root_joint`),
/// under gravity.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/panda/panda.urdf", floating)]
pub struct FloatingPanda;

/// A symmetric body, floating, without gravity (`tests/robots/free/top.urdf`).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/free/top.urdf", floating, gravity = [0.0, 0.0, 0.0])]
pub struct FreeTop;

/// A puck on a planar joint whose plane holds gravity `g` along `−y`
/// (`tests/robots/free/puck.urdf`).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/free/puck.urdf", gravity = [0.0, -g, 0.0])]
pub struct Puck {
    /// Gravity's acceleration, along −y.
    pub g: f64,
}

/// A solid ball (mass 1, radius 0.1) that floats and bounces on the ground with restitution `e`
/// (`tests/robots/ground/ball.urdf`).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/ground/ball.urdf", floating, ground(restitution = e))]
pub struct GroundBall {
    /// The restitution of its impacts on the ground.
    pub e: f64,
}

/// The ball of [`GroundBall`] under Coulomb's friction cone where it rests on the ground
/// (`ground(friction = mu)`: in its companion `RollingBallWithContacts`, the cone
/// `ball_ground_slip` on the contact's force while the contact is closed).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/ground/ball.urdf", floating, ground(friction = mu))]
pub struct RollingBall {
    /// The coefficient of friction.
    pub mu: f64,
}

/// The brick of [`Brick`] under Coulomb's friction cone at each corner that rests on the ground:
/// lying on a face, four contacts whose normal forces are redundant (four rows, three
/// freedoms). Its companion needs more than a test thread's stack (`large`).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/ground/brick.urdf", floating, large, ground(friction = mu))]
pub struct SlidingBrick {
    /// The coefficient of friction.
    pub mu: f64,
}

/// A brick and the capsule fixed to it, floating, bouncing elastically on the ground at its
/// eight corners and the capsule's two ends (`tests/robots/ground/brick.urdf`).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/ground/brick.urdf", floating, ground(restitution = 1.0))]
pub struct Brick;
