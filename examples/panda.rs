//! The Franka Panda read from its URDF file, swinging under gravity, its elbow (joint 4) held by
//! a DC motor through a 100:1 gearbox, all from `dirac::components`: a current-controlled drive
//! (a current source into the motor's EMF, as a servo amplifier's current loop does), its
//! current set by a joint-space PD controller sampled at 1 kHz.
//!
//! The arm starts at rest with its elbow at −1.2 rad; the other six joints are free and swing.
//! At t = 0.5 s the controller's set point steps to −0.8 rad. The controller reads the joint's
//! angle and rate and commands `i = kp (θ_ref − θ) − kd θ̇`, limited to ±20 A; the motor's
//! torque `k i` reaches the joint through the gearbox, the rotor's inertia with it. Writes
//! `target/dirac-examples/panda_joints.svg` (the seven joint angles) and `panda_motor.svg`
//! (the set point, the elbow's angle, the current and the motor's voltage).

use std::error::Error;

use dirac::components::electrical::{CurrentSource, Ground};
use dirac::components::electromechanical::Emf;
use dirac::components::rotational::{IdealGear, Inertia};
use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// The robot: nine joints (seven revolute, two prismatic fingers, the second mimicking the
/// first), named as in the file: `panda_joint1` … `panda_joint7`, `panda_finger_joint1`, `2`.
#[derive(LagrangeDirac, Clone)]
#[dirac(urdf = "tests/robots/panda/panda.urdf")]
pub struct Panda;

/// The arm, and the elbow's drive: a current source into the motor's EMF, the rotor, and the
/// gearbox onto joint 4.
#[derive(Interconnection, Clone)]
#[dirac(
    connect(source.n, emf.p), connect(source.p, ground.p), connect(emf.n, ground.p),
    connect(emf.phi, rotor.phi), connect(rotor.phi, gear.a), connect(gear.b, arm.panda_joint4)
)]
pub struct Workcell {
    arm: Panda,
    source: CurrentSource,
    emf: Emf,
    ground: Ground,
    rotor: Inertia,
    gear: IdealGear,
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut cell = Workcell {
        arm: Panda,
        source: CurrentSource { i: 0.0 },
        emf: Emf { k: 0.1 },
        ground: Ground {},
        rotor: Inertia { j: 5e-5 },
        gear: IdealGear { ratio: 100.0 },
    };
    let (kp, kd, limit) = (400.0, 40.0, 20.0);
    let set_point = |t: f64| if t < 0.5 { -1.2 } else { -0.8 };

    // The arm out to the side, fingers half open; the motor's angle follows the elbow's.
    let mut q = VecQ::<Workcell>::zeros();
    let start_angles = [0.3, 0.5, -0.4, -1.2, 0.2, 1.4, 0.6, 0.02, 0.02];
    for (name, angle) in Panda::NAMES.coordinate_names().iter().zip(start_angles) {
        let c = cell.coordinate(&format!("arm.{name}")).ok_or("an arm joint")?;
        q[c.index()] = angle;
    }
    let rotor = cell.coordinate("rotor.phi").ok_or("the rotor")?;
    q[rotor.index()] = 100.0 * -1.2;
    let start = consistent_state(&cell, 0.0, &q, &VecQ::<Workcell>::zeros(), Consistency::default())?;

    let elbow = cell.coordinate("arm.panda_joint4").ok_or("the elbow")?;
    let mut commands: Vec<(f64, f64)> = Vec::new();
    let mut radau = Radau::new(&mut cell, RadauOptions::tolerances(1e-8, 1e-8))?;
    let solution = radau.solve_sampled(0.0, &start, 2.0, 1e-3, &Sampling::Every(0.002), |t, s, cell| {
        let error = set_point(t) - s.q[elbow.index()];
        let u = (kp * error - kd * s.v[elbow.index()]).clamp(-limit, limit);
        cell.set_input(Workcell::source_input(CurrentSource::I), u);
        commands.push((t, u));
    })?;
    let t = solution.t();
    let angle = solution.q(elbow);
    let voltage = solution.column("out(source.v)").ok_or("the motor's voltage")?;
    let last = solution.len() - 1;
    println!(
        "elbow at t = 2 s: {:.4} rad (set point -0.8), current {:.3} A; {} steps, {} samples of the controller",
        angle[last],
        commands.last().map_or(0.0, |c| c.1),
        solution.stats.steps,
        commands.len()
    );
    // The tool's pose: its origin and the direction its z axis points (the third column of
    // its rotation), outputs of the robot read by name.
    let tool = |name: &str| solution.column(&format!("out(arm.panda_hand_tcp_{name})")).map(|c| c[last]);
    let (position, axis) = (["x", "y", "z"].map(tool), ["r13", "r23", "r33"].map(tool));
    if let ([Some(x), Some(y), Some(z)], [Some(ax), Some(ay), Some(az)]) = (position, axis) {
        println!("tool at ({x:.4}, {y:.4}, {z:.4}) m, pointing along ({ax:.3}, {ay:.3}, {az:.3})");
    }
    let residual = solution.holonomic_residual().iter().fold(0.0_f64, |m, r| m.max(r.abs()));
    println!("the gearbox and the mimic finger hold to {residual:.1e}");

    let dir = output_dir()?;
    let names: Vec<String> = (1..=7).map(|k| format!("panda_joint{k}")).collect();
    let columns: Vec<&[f64]> = names
        .iter()
        .map(|n| solution.column(&format!("arm.{n}")).ok_or("a joint"))
        .collect::<Result<_, _>>()?;
    let series = names.iter().zip(&columns).map(|(name, y)| Series { name, x: t, y }).collect();
    let joints = dir.join("panda_joints.svg");
    Chart {
        title: "Panda under gravity, elbow driven by a PD-controlled DC motor",
        x_label: "time t [s]",
        y_label: "joint angle [rad]",
        series,
        log_y: false,
        log_x: false,
    }
    .write(&joints)?;
    let (ut, u): (Vec<f64>, Vec<f64>) = commands.into_iter().unzip();
    let tenths: Vec<f64> = voltage.iter().map(|v| v / 10.0).collect();
    let reference: Vec<f64> = t.iter().map(|&t| set_point(t)).collect();
    let motor = dir.join("panda_motor.svg");
    Chart {
        title: "The elbow's drive",
        x_label: "time t [s]",
        y_label: "angle [rad], current [A], voltage [10 V]",
        series: vec![
            Series { name: "set point [rad]", x: t, y: &reference },
            Series { name: "elbow angle [rad]", x: t, y: angle },
            Series { name: "current [A]", x: &ut, y: &u },
            Series { name: "voltage [10 V]", x: t, y: &tenths },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&motor)?;
    println!("wrote {} and {}", joints.display(), motor.display());
    Ok(())
}
