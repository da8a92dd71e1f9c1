//! The Franka Panda's arm, read from its URDF file, moved by its seven joint torques from one
//! pose to another, at rest at both ends, within its joints' limits, their velocity limits and
//! its torques' efforts.
//!
//! First over a fixed 2 s at the least `∫ |τ|²/2 + 5 |v|² dt`: the arm turns its elbow's plane
//! (joints 1 and 3 against each other) to carry less of its weight, and joints 1, 3 and 4 run at
//! their velocity limits on the way. Then with the final time free, each solve starting from
//! the fixed optimum (the program is not convex: from a straight-line guess the solver settles
//! in a worse local optimum near 0.54 s). Priced at nothing, time settles where the effort is
//! least: holding the arm up against gravity costs effort every second, so a slow motion is not
//! a cheap one. Priced at 5000 per second, the motion is nearly time-optimal: limited by the
//! joints' velocities (DMOC bounds each interval's), not by the torques' efforts.
//!
//! `optimal::Dmoc` transcribes each with the variational integrator's discrete Lagrangian on 40
//! intervals (the robot's mass matrix, bias forces and their derivatives generated from the
//! URDF file when the example compiles), and dirac's own interior point solves them (no
//! feature needed). Writes `target/dirac-examples/panda_point_to_point.svg` (the seven joint
//! angles of the fastest motion), `panda_point_to_point_torques.svg` (its torques as fractions
//! of their efforts) and `panda_point_to_point_velocities.svg` (its velocities as fractions of
//! their limits).
//!
//!   cargo run --release --example panda_point_to_point

use std::error::Error;

use dirac::optimal::interior::InteriorOptions;
use dirac::optimal::{Dmoc, Optimum, Problem};
use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// The arm (`panda_arm.urdf`: seven revolute joints, the hand fixed) with a torque at each
/// joint. Its joints' limits are bounds of the problem below rather than hard stops of the
/// model, which a smooth transcription could not follow.
#[derive(LagrangeDirac, Clone, Default)]
#[dirac(urdf = "tests/robots/panda/panda_arm.urdf")]
#[dirac(input(t1), input(t2), input(t3), input(t4), input(t5), input(t6), input(t7))]
#[dirac(force(panda_joint1) = t1, force(panda_joint2) = t2, force(panda_joint3) = t3, force(panda_joint4) = t4)]
#[dirac(force(panda_joint5) = t5, force(panda_joint6) = t6, force(panda_joint7) = t7)]
pub struct Arm {
    /// The torque at `panda_joint1` [N m] (input).
    pub t1: f64,
    /// The torque at `panda_joint2` [N m] (input).
    pub t2: f64,
    /// The torque at `panda_joint3` [N m] (input).
    pub t3: f64,
    /// The torque at `panda_joint4` [N m] (input).
    pub t4: f64,
    /// The torque at `panda_joint5` [N m] (input).
    pub t5: f64,
    /// The torque at `panda_joint6` [N m] (input).
    pub t6: f64,
    /// The torque at `panda_joint7` [N m] (input).
    pub t7: f64,
}

/// The joints' limits, velocity limits and efforts, as `panda_arm.urdf` gives them.
const LOWER: [f64; 7] = [-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973];
const UPPER: [f64; 7] = [2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973];
const VELOCITY: [f64; 7] = [2.175, 2.175, 2.175, 2.175, 2.61, 2.61, 2.61];
const EFFORT: [f64; 7] = [87.0, 87.0, 87.0, 87.0, 12.0, 12.0, 12.0];

/// What a second of motion costs in the nearly time-optimal problem.
const RHO: f64 = 5000.0;

fn problem(horizon: f64, intervals: usize) -> Problem<Arm> {
    let start = [0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 0.8];
    let end = [1.0, 0.2, -0.5, -1.5, 0.4, 1.6, 0.0];
    let mut problem = Problem::new(Arm::default(), horizon, intervals)
        .start(VecQ::<Arm>::from(start), VecQ::<Arm>::zeros())
        .final_state(VecQ::<Arm>::from(end), VecQ::<Arm>::zeros());
    for i in 0..7 {
        let joint = Coordinate::checked(i).expect("seven joints");
        let torque = dirac::Input::checked(i).expect("seven torques");
        problem = problem
            .position_bounds(joint, LOWER[i], UPPER[i])
            .velocity_bounds(joint, -VELOCITY[i], VELOCITY[i])
            .input_bounds(torque, -EFFORT[i], EFFORT[i])
            .velocity_weight(joint, 10.0, 0.0);
    }
    problem
}

fn report(what: &str, optimum: &Optimum) {
    let horizon = optimum.times[optimum.times.len() - 1] - optimum.times[0];
    let saturated = optimum
        .inputs
        .iter()
        .flat_map(|u| u.iter().zip(&EFFORT).map(|(t, e)| t.abs() / e))
        .fold(0.0f64, f64::max);
    // Each interval's velocity, `(q_{k+1} − q_k)/h`, is what DMOC bounds.
    let h = horizon / optimum.inputs.len() as f64;
    let fastest = optimum
        .positions
        .windows(2)
        .flat_map(|pair| (0..7).map(move |i| (pair[1][i] - pair[0][i]).abs() / h / VELOCITY[i]))
        .fold(0.0f64, f64::max);
    println!(
        "{what}: T = {horizon:.4} s, cost {:.4} in {} iterations, {:.1} ms ({:.1} ms evaluating); largest torque \
         {:.0}% of its effort, largest velocity {:.0}% of its limit; equations met to {:.1e}",
        optimum.cost,
        optimum.iterations,
        optimum.wall.as_secs_f64() * 1e3,
        optimum.evaluation.as_secs_f64() * 1e3,
        100.0 * saturated,
        100.0 * fastest,
        optimum.violation
    );
}

fn main() -> Result<(), Box<dyn Error>> {
    let intervals = 40;
    let options = InteriorOptions::default();
    let fixed = Dmoc::new(problem(2.0, intervals))?.solve_interior(&options)?;
    report("fixed 2 s", &fixed);
    // The same motion with its duration free in [0.1, 4] s, starting from the 2 s optimum.
    let free = |rho| {
        problem(2.0, intervals)
            .free_final_time(0.1, 4.0)
            .time_weight(rho)
            .guess(fixed.positions.clone(), fixed.inputs.clone())
    };
    let least_effort = Dmoc::new(free(0.0))?.solve_interior(&options)?;
    report("free final time, time free of charge", &least_effort);
    let optimum = Dmoc::new(free(RHO))?.solve_interior(&options)?;
    report(&format!("free final time at {RHO} per second"), &optimum);

    let t = &optimum.times;
    let names = Arm::default().coordinate_names();
    let angles: Vec<Vec<f64>> = (0..7).map(|i| optimum.positions.iter().map(|q| q[i]).collect()).collect();
    let path = output_dir()?.join("panda_point_to_point.svg");
    Chart {
        title: "Panda point to point, nearly time-optimal (DMOC, N = 40)",
        x_label: "time t [s]",
        y_label: "joint angle [rad]",
        series: names.iter().zip(&angles).map(|(name, y)| Series { name: name.as_str(), x: t, y }).collect(),
        log_y: false,
        log_x: false,
    }
    .write(&path)?;
    println!("wrote {}", path.display());

    // The torques, held over each interval: drawn as steps, as fractions of their efforts.
    let mut steps = Vec::new();
    for k in 0..intervals {
        steps.extend([t[k], t[k + 1]]);
    }
    let torques: Vec<Vec<f64>> =
        (0..7).map(|i| optimum.inputs.iter().flat_map(|u| [u[i] / EFFORT[i]; 2]).collect()).collect();
    let inputs = Arm::default().input_names();
    let path = output_dir()?.join("panda_point_to_point_torques.svg");
    Chart {
        title: "Panda point to point: torques over their efforts (±1 is the limit)",
        x_label: "time t [s]",
        y_label: "torque / effort",
        series: inputs
            .iter()
            .zip(&torques)
            .map(|(name, y)| Series { name: name.as_str(), x: &steps, y })
            .collect(),
        log_y: false,
        log_x: false,
    }
    .write(&path)?;
    println!("wrote {}", path.display());

    // Each interval's velocity, as a fraction of its joint's limit: what bounds the motion.
    let h = (t[intervals] - t[0]) / intervals as f64;
    let velocities: Vec<Vec<f64>> = (0..7)
        .map(|i| {
            let over = |pair: &[Vec<f64>]| (pair[1][i] - pair[0][i]) / h / VELOCITY[i];
            optimum.positions.windows(2).flat_map(|pair| [over(pair); 2]).collect()
        })
        .collect();
    let path = output_dir()?.join("panda_point_to_point_velocities.svg");
    Chart {
        title: "Panda point to point: joint velocities over their limits (±1 is the limit)",
        x_label: "time t [s]",
        y_label: "velocity / limit",
        series: names
            .iter()
            .zip(&velocities)
            .map(|(name, y)| Series { name: name.as_str(), x: &steps, y })
            .collect(),
        log_y: false,
        log_x: false,
    }
    .write(&path)?;
    println!("wrote {}", path.display());
    Ok(())
}
