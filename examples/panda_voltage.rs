//! The Franka Panda read from its URDF file with its joint limits (each limited joint's
//! `<limit lower upper>` as two hard stops), its elbow (joint 4) driven by a DC motor through a
//! 100:1 gearbox and fed by a voltage source through the winding's resistance: the source's
//! voltage set by a joint-space PD controller sampled at 1 kHz, with a progress bar while it
//! runs. One run composes all of it: the controller, the stops watched at every step, the
//! progress report.
//!
//! The arm starts at rest with its elbow at −1.2 rad; the other six arm joints are held at their
//! start angles by joint torques from the same 1 kHz controller (a PD law each, as a robot's
//! joint controllers hold it), and so are the fingers, half open. At t = 0.5 s the elbow's set point steps to
//! −0.8 rad. The controller
//! reads the elbow's angle and rate and commands `u = kp (θ_ref − θ) − kd θ̇`, limited to ±24 V;
//! a voltage source's voltage is a constraint on the circuit, so each new command moves the
//! circuit's node voltages at once, as the impulse through the source would. Writes
//! `target/dirac-examples/panda_voltage.svg` (the set point, the elbow's angle, the voltage and
//! the current).

use std::error::Error;
use std::io::Write;
use std::time::Duration;

use dirac::components::electrical::{Ground, Resistor, VoltageSource};
use dirac::components::electromechanical::Emf;
use dirac::components::rotational::{IdealGear, Inertia};
use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// The robot with its joint limits as hard stops (`panda_joint4_lower`, `panda_joint4_upper`, …),
/// a torque on each arm joint but the elbow, which its motor drives, and a force on the fingers.
#[derive(LagrangeDirac, Clone)]
#[dirac(urdf = "tests/robots/panda/panda.urdf", joint_limits)]
#[dirac(input(tau1, tau2, tau3, tau5, tau6, tau7, grip))]
#[dirac(force(panda_joint1) = tau1, force(panda_joint2) = tau2, force(panda_joint3) = tau3)]
#[dirac(force(panda_joint5) = tau5, force(panda_joint6) = tau6, force(panda_joint7) = tau7)]
#[dirac(force(panda_finger_joint1) = grip)]
pub struct Panda {
    tau1: f64,
    tau2: f64,
    tau3: f64,
    tau5: f64,
    tau6: f64,
    tau7: f64,
    grip: f64,
}

/// The arm, and the elbow's drive: a voltage source, the winding's resistance, the motor's EMF,
/// the rotor, and the gearbox onto joint 4.
#[derive(Interconnection, Clone)]
#[dirac(
    connect(source.p, winding.p), connect(winding.n, emf.p), connect(emf.n, ground.p),
    connect(source.n, ground.p),
    connect(emf.phi, rotor.phi), connect(rotor.phi, gear.a), connect(gear.b, arm.panda_joint4)
)]
pub struct Workcell {
    arm: Panda,
    source: VoltageSource,
    winding: Resistor,
    emf: Emf,
    ground: Ground,
    rotor: Inertia,
    gear: IdealGear,
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut cell = Workcell {
        arm: Panda { tau1: 0.0, tau2: 0.0, tau3: 0.0, tau5: 0.0, tau6: 0.0, tau7: 0.0, grip: 0.0 },
        source: VoltageSource { u: 0.0 },
        winding: Resistor { r: 0.5 },
        emf: Emf { k: 0.1 },
        ground: Ground {},
        rotor: Inertia { j: 5e-5 },
        gear: IdealGear { ratio: 100.0 },
    };
    let (kp, kd, limit) = (60.0, 2.0, 24.0);
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
    let source = Workcell::source_input(VoltageSource::U);
    // The held joints, their torques, the angles they are held at and their gains (stiffness,
    // damping), the wrist's softer: a sample-and-hold PD is stable while `kd h / I` stays well
    // below 2 for the joint's inertia `I` and the period `h`.
    let gains = [
        (1, 600.0, 40.0),
        (2, 600.0, 40.0),
        (3, 300.0, 20.0),
        (5, 50.0, 1.0),
        (6, 50.0, 1.0),
        (7, 20.0, 0.5),
    ];
    let torques = [Panda::TAU1, Panda::TAU2, Panda::TAU3, Panda::TAU5, Panda::TAU6, Panda::TAU7];
    let held: Vec<_> = gains
        .into_iter()
        .zip(torques)
        .map(|((k, kp, kd), tau)| {
            let joint = cell.coordinate(&format!("arm.panda_joint{k}")).ok_or("an arm joint")?;
            Ok((joint, Workcell::arm_input(tau), start_angles[k - 1], kp, kd))
        })
        .collect::<Result<_, &str>>()?;
    let finger = cell.coordinate("arm.panda_finger_joint1").ok_or("a finger")?;
    let grip = Workcell::arm_input(Panda::GRIP);
    let mut radau = Radau::new(&mut cell, RadauOptions::tolerances(1e-8, 1e-8))?;
    let solution = radau
        .run(0.0, &start, 2.0)
        .sampling(Sampling::Every(0.002))
        .every(1e-3, |t, s, cell: &mut Workcell| {
            let error = set_point(t) - s.q[elbow.index()];
            let u = (kp * error - kd * s.v[elbow.index()]).clamp(-limit, limit);
            cell.set_input(source, u);
            for &(joint, tau, angle, kp, kd) in &held {
                let torque = kp * (angle - s.q[joint.index()]) - kd * s.v[joint.index()];
                cell.set_input(tau, torque);
            }
            cell.set_input(grip, 20.0 * (0.02 - s.q[finger.index()]) - 2.0 * s.v[finger.index()]);
        })
        .progress(Duration::from_millis(250), |progress| {
            eprint!("\r{} {progress}", progress.bar(30));
            let _ = std::io::stderr().flush();
        })
        .solve()?;
    eprintln!();

    let t = solution.t();
    let angle = solution.q(elbow);
    let voltage = solution.input(source);
    let current = solution.output(Workcell::winding_output(Resistor::I));
    let last = solution.len() - 1;
    println!(
        "elbow at t = 2 s: {:.4} rad (set point -0.8), {:.2} V, {:.3} A; {} steps, {} stop strikes",
        angle[last],
        voltage[last],
        current[last],
        solution.stats.steps,
        solution.impacts().len()
    );
    // Every limited joint stayed within its stops.
    for name in Panda::NAMES.coordinate_names().iter().take(7) {
        let column = solution.column(&format!("arm.{name}")).ok_or("a joint")?;
        let (low, high) = column.iter().fold((f64::MAX, f64::MIN), |(l, h), &x| (l.min(x), h.max(x)));
        println!("{name}: from {low:.3} to {high:.3} rad");
    }

    let dir = output_dir()?;
    let reference: Vec<f64> = t.iter().map(|&t| set_point(t)).collect();
    let tenths: Vec<f64> = voltage.iter().map(|v| v / 10.0).collect();
    let path = dir.join("panda_voltage.svg");
    Chart {
        title: "The Panda's elbow, voltage-driven under a 1 kHz PD controller, within its joint limits",
        x_label: "time t [s]",
        y_label: "angle [rad], voltage [10 V], current [A]",
        series: vec![
            Series { name: "set point [rad]", x: t, y: &reference },
            Series { name: "elbow angle [rad]", x: t, y: angle },
            Series { name: "voltage [10 V]", x: t, y: &tenths },
            Series { name: "current [A]", x: t, y: current },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&path)?;
    println!("wrote {}", path.display());
    Ok(())
}
