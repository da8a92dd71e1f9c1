//! An electro-mechanical system: a DC motor circuit driving a mechanical load through a shaft.
//!
//! The motor is one primitive Lagrange-Dirac system on (q, θ): the armature charge q with
//! inductance L_a, resistance R and a voltage source V, and the rotor angle θ with inertia J_m.
//! The motor's gyrator (torque = k i, back-emf = k ω) couples an effort of one domain to the
//! flow of the other; in the Lagrangian picture it is the gyroscopic term −k q ω, which yields
//!
//! ```text
//! L_a di/dt = V − R i − k ω,      J_m dω/dt = k i + f_θ
//! ```
//!
//! with f_θ the torque at the motor's mechanical port θ. The load, a flywheel J_l with viscous
//! friction b, is a second primitive with port φ. The shaft interconnects them:
//! `connect(motor.theta, load.phi)`, ω_θ = ω_φ and f_θ + f_φ = 0. The power through the port,
//! f_φ ω, is what the motor delivers to the load; the source's power V i goes into it, into the
//! resistor R i² and into the motor's stored energy, and the energy balance closes.
//!
//! The supply voltage is an input: a second part drives the motor from a table, a ramp from
//! 0 to 12 V over 2 s read with linear interpolation by a drive (inside the steps), then the
//! same motor under 50% pulse-width modulation at 20 Hz, its edges met by restarts
//! (`solve_sampled` at the half period), and plots the speeds.

use std::error::Error;
use std::fs::File;
use std::io::BufWriter;

use dirac::State;
use dirac::prelude::*;
use dirac::sources::{Hold, Table};

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// A DC motor: armature circuit and rotor, coupled by the gyrator constant k.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(q => i, theta => omega), port(theta), input(volt))]
#[dirac(lagrangian = 0.5 * la * i * i + 0.5 * jm * omega * omega - k * q * omega)]
#[dirac(force(q) = volt - r * i)]
pub struct Motor {
    /// Armature inductance [H].
    pub la: f64,
    /// Armature resistance [Ω].
    pub r: f64,
    /// Supply voltage [V].
    pub volt: f64,
    /// Rotor inertia [kg m²].
    pub jm: f64,
    /// Torque and back-emf constant [N m/A = V s].
    pub k: f64,
}

/// A flywheel with viscous friction.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(phi => w), port(phi))]
#[dirac(lagrangian = 0.5 * jl * w * w)]
#[dirac(force(phi) = -b * w)]
pub struct Load {
    /// Inertia [kg m²].
    pub jl: f64,
    /// Friction [N m s].
    pub b: f64,
}

/// The motor driving the load through a rigid shaft.
#[derive(Interconnection)]
#[dirac(connect(motor.theta, load.phi))]
pub struct Drive {
    /// The motor.
    pub motor: Motor,
    /// The load.
    pub load: Load,
}

fn main() -> Result<(), Box<dyn Error>> {
    let drive = Drive {
        motor: Motor { la: 0.05, r: 1.0, volt: 12.0, jm: 0.01, k: 0.5 },
        load: Load { jl: 0.05, b: 0.1 },
    };
    println!("{}\n", Drive::equations().text);
    let start = consistent_state(
        &drive,
        0.0,
        &VecQ::<Drive>::zeros(),
        &VecQ::<Drive>::zeros(),
        Consistency::default(),
    )?;
    let sol = Radau::new(&drive, RadauOptions::tolerances(1e-9, 1e-11))?.solve(
        0.0,
        &start,
        5.0,
        &Sampling::Every(0.0005),
    )?;

    let (i, omega) = (sol.v(Drive::motor(Motor::Q)), sol.v(Drive::MOTOR_THETA));
    let port_force = sol.interconnection_force(Drive::LOAD_PHI).ok_or("phi is a port")?;
    let t = sol.t();
    let source: Vec<f64> = i.iter().map(|i| drive.motor.volt * i).collect();
    let resistor: Vec<f64> = i.iter().map(|i| drive.motor.r * i * i).collect();
    let friction: Vec<f64> = omega.iter().map(|w| drive.load.b * w * w).collect();
    let to_load: Vec<f64> = port_force.iter().zip(omega).map(|(f, w)| f * w).collect();
    // Energy balance over the run: stored energy change = work of the source − losses,
    // integrated with the trapezoidal rule on the samples.
    let integral = |y: &[f64]| (1..y.len()).map(|k| 0.5 * (y[k] + y[k - 1]) * (t[k] - t[k - 1])).sum::<f64>();
    let stored = sol.energy()[sol.len() - 1] - sol.energy()[0];
    let balance = stored - (integral(&source) - integral(&resistor) - integral(&friction));
    let (motor, load) = (&drive.motor, &drive.load);
    let steady = motor.k * motor.volt / (motor.r * load.b + motor.k * motor.k);
    println!("steady state by hand (k i = b w, V = R i + k w): w = k V / (R b + k^2) = {steady:.4} rad/s");
    let last = sol.len() - 1;
    println!(
        "t = 5 s: current {:.4} A, speed {:.4} rad/s, torque at the shaft {:.4} N m",
        i[last], omega[last], port_force[last]
    );
    println!(
        "power into the load through the port: {:.4} W (friction takes {:.4} W)",
        to_load[last], friction[last]
    );
    println!(
        "energy: stored {stored:.6} J, source - losses {:.6} J, balance {balance:.1e} J",
        stored - balance
    );
    let tellegen = sol.interconnection_power().iter().map(|p| p.abs()).fold(0.0, f64::max);
    println!(
        "the shaft itself stores and dissipates nothing: largest |interconnection power| {tellegen:.1e} W"
    );

    let dir = output_dir()?;
    let csv = dir.join("motor_load.csv");
    sol.write_csv(BufWriter::new(File::create(&csv)?))?;
    let states = dir.join("motor_load_states.svg");
    Chart {
        title: "DC motor and load: current and speed",
        x_label: "time t [s]",
        y_label: "current [A], speed [rad/s]",
        series: vec![
            Series { name: "current i [A]", x: t, y: i },
            Series { name: "speed omega [rad/s]", x: t, y: omega },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&states)?;
    let power = dir.join("motor_load_power.svg");
    Chart {
        title: "Power flows",
        x_label: "time t [s]",
        y_label: "power [W]",
        series: vec![
            Series { name: "source V i", x: t, y: &source },
            Series { name: "resistor R i^2", x: t, y: &resistor },
            Series { name: "into the load f omega", x: t, y: &to_load },
            Series { name: "friction b omega^2", x: t, y: &friction },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&power)?;
    let driven = driven_by_tables(&drive, &start)?;
    for p in [&csv, &states, &power, &driven] {
        println!("wrote {}", p.display());
    }
    Ok(())
}

/// The motor from rest under a voltage ramp and under PWM; the speed plot's path.
fn driven_by_tables(drive: &Drive, start: &State<Drive>) -> Result<std::path::PathBuf, Box<dyn Error>> {
    let volt = Drive::motor_input(Motor::VOLT);
    let options = RadauOptions::tolerances(1e-9, 1e-11);
    // A ramp to 12 V over 2 s, held after: the drive sets the voltage before every evaluation.
    let ramp = Table::new(vec![0.0, 2.0], vec![0.0, 12.0], Hold::Linear)?;
    let mut model = Drive { motor: Motor { volt: 0.0, ..drive.motor.clone() }, load: drive.load.clone() };
    let mut source = |t: f64, _: &State<Drive>, d: &mut Drive| d.set_input(volt, ramp.at(t));
    let mut radau = Radau::new(&mut model, options)?;
    radau.drive(&mut source)?;
    let ramped = radau.solve(0.0, start, 5.0, &Sampling::Every(0.005))?;
    // 12 V for 25 ms, 0 V for 25 ms: a zero-order-hold table whose edges are sample times.
    let edges: Vec<f64> = (0..200).map(|k| 0.025 * k as f64).collect();
    let levels: Vec<f64> = (0..200).map(|k| if k % 2 == 0 { 12.0 } else { 0.0 }).collect();
    let pwm = Table::new(edges, levels, Hold::Zero)?;
    let mut model = Drive { motor: Motor { volt: 0.0, ..drive.motor.clone() }, load: drive.load.clone() };
    let mut radau = Radau::new(&mut model, options)?;
    let pulsed = radau.solve_sampled(0.0, start, 5.0, 0.025, &Sampling::Every(0.005), |t, _, d| {
        d.set_input(volt, pwm.at(t));
    })?;
    let (m, l) = (&drive.motor, &drive.load);
    let steady = |v: f64| m.k * v / (m.r * l.b + m.k * m.k);
    let speed = |s: &Solution<Drive, dirac::RadauStats>| s.v(Drive::MOTOR_THETA)[s.len() - 1];
    println!(
        "ramp to 12 V: speed at t = 5 s {:.4} rad/s (steady state at 12 V: {:.4}); PWM 50%: {:.4} rad/s \
         (steady state at the mean 6 V: {:.4}), {} restarts",
        speed(&ramped),
        steady(12.0),
        speed(&pulsed),
        steady(6.0),
        (5.0f64 / 0.025) as usize
    );
    let path = output_dir()?.join("motor_driven_speed.svg");
    Chart {
        title: "DC motor driven from voltage tables: speed",
        x_label: "time t [s]",
        y_label: "speed [rad/s]",
        series: vec![
            Series { name: "ramp 0-12 V over 2 s", x: ramped.t(), y: ramped.v(Drive::MOTOR_THETA) },
            Series { name: "PWM 50% at 20 Hz, 12 V", x: pulsed.t(), y: pulsed.v(Drive::MOTOR_THETA) },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&path)?;
    Ok(path)
}
