//! A DC motor with a gearbox, a flexible shaft and a load from `dirac::components`, no Lagrangian
//! written (`motor_load` derives them by hand): a 12 V step and 50 % PWM whose edges are located;
//! the steady state against `V = R i + k ω`, `k i = (b/n²) ω`; the energy supplied, stored, lost;
//! and its linearisation from the source's voltage, reduced to the states that voltage reaches
//! and the outputs see (`minreal`).

use std::error::Error;

use dirac::components::electrical::{Ground, Inductor, PulseVoltage, Resistor, StepVoltage, VoltageSource};
use dirac::components::electromechanical::Emf;
use dirac::components::rotational::{Damper, Fixed, IdealGear, Inertia, SpringDamper};
use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// Armature (resistance, inductance, EMF), rotor, gearbox, shaft, and the load on its bearing.
#[derive(Interconnection, Clone)]
#[dirac(
    connect(r.n, l.p), connect(l.n, emf.p), connect(emf.n, ground.p), connect(emf.phi, rotor.phi),
    connect(rotor.phi, gear.a), connect(gear.b, shaft.a), connect(shaft.b, load.phi),
    connect(load.phi, bearing.b), connect(bearing.a, housing.phi)
)]
struct GearedMotor {
    r: Resistor,
    l: Inductor,
    emf: Emf,
    ground: Ground,
    rotor: Inertia,
    gear: IdealGear,
    shaft: SpringDamper,
    load: Inertia,
    bearing: Damper,
    housing: Fixed,
}

/// The motor on a 12 V step at t = 0.
#[derive(Interconnection, Clone)]
#[dirac(connect(source.p, motor.r.p), connect(source.n, motor.ground.p))]
struct Stepped {
    source: StepVoltage,
    motor: GearedMotor,
}

/// The motor under pulse-width modulation.
#[derive(Interconnection, Clone)]
#[dirac(connect(source.p, motor.r.p), connect(source.n, motor.ground.p))]
struct Pulsed {
    source: PulseVoltage,
    motor: GearedMotor,
}

/// The motor driven by a voltage that is an input, for its linearisation.
#[derive(Interconnection, Clone)]
#[dirac(connect(source.p, motor.r.p), connect(source.n, motor.ground.p))]
struct Driven {
    source: VoltageSource,
    motor: GearedMotor,
}

fn main() -> Result<(), Box<dyn Error>> {
    let (volts, r, k, b, n) = (12.0, 1.0, 0.5, 0.1, 4.0);
    let motor = GearedMotor {
        r: Resistor { r },
        l: Inductor { l: 0.05 },
        emf: Emf { k },
        ground: Ground {},
        rotor: Inertia { j: 0.01 },
        gear: IdealGear { ratio: n },
        shaft: SpringDamper { k: 50.0, d: 0.05, angle: 0.0 },
        load: Inertia { j: 0.05 },
        bearing: Damper { d: b },
        housing: Fixed { phi0: 0.0 },
    };
    let source = StepVoltage { offset: 0.0, height: volts, start: 0.0 };
    let stepped = Stepped { source, motor: motor.clone() };
    let zero = VecQ::<Stepped>::zeros();
    let start = consistent_state(&stepped, 0.0, &zero, &zero, Consistency::default())?;
    let options = RadauOptions::tolerances(1e-9, 1e-11);
    let step = Radau::new(&stepped, options)?.solve(0.0, &start, 10.0, &Sampling::Every(0.002))?;
    let speed = step.column("motor.rotor.w").ok_or("the rotor's speed")?;
    let current = step.column("out(motor.l.i)").ok_or("the current")?;
    let steady = volts / (k + r * b / (k * n * n));
    println!("12 V step: rotor at {:.6} rad/s at 10 s; by hand {steady:.6} rad/s", speed[step.len() - 1]);
    let t = step.t();
    let integral = |y: &[f64]| (1..y.len()).map(|j| 0.5 * (y[j] + y[j - 1]) * (t[j] - t[j - 1])).sum::<f64>();
    let supplied = integral(step.column("out(source.supplied)").ok_or("the source's power")?);
    let lost = integral(step.dissipated_power());
    let stored = step.energy()[step.len() - 1] - step.energy()[0];
    let off = supplied - stored - lost;
    println!("energy: supplied {supplied:.4} J = stored {stored:.4} + lost {lost:.4} ({off:.0e})");
    let driven = Driven { source: VoltageSource { u: 0.0 }, motor: motor.clone() };
    let zero = VecQ::<Driven>::zeros();
    let rest = consistent_state(&driven, 0.0, &zero, &zero, Consistency::default())?;
    let linear = linearize(&driven, 0.0, &rest)?;
    let minimal = linear.minreal(&driven, 1e-9)?;
    let poles = dirac::control::poles(&minimal.a)?;
    let poles: Vec<String> = poles.iter().map(|p| format!("{:.4}{:+.4}i", p.re, p.im)).collect();
    println!(
        "linearised at rest: {} states, {} of them reached and seen ({}); poles {}",
        linear.a.nrows(),
        minimal.a.nrows(),
        minimal.state_names().join(", "),
        poles.join(", ")
    );
    let source = PulseVoltage { offset: 0.0, amplitude: volts, width: 0.5, period: 0.05, start: 0.0 };
    let pulsed = Pulsed { source, motor };
    let zero = VecQ::<Pulsed>::zeros();
    let start = consistent_state(&pulsed, 0.0, &zero, &zero, Consistency::default())?;
    let pwm = Radau::new(&pulsed, options)?.solve(0.0, &start, 10.0, &Sampling::Every(0.002))?;
    let pwm_speed = pwm.column("motor.rotor.w").ok_or("the rotor's speed")?;
    let last = pwm_speed[pwm.len() - 1];
    println!("PWM 50 % at 20 Hz: rotor at {last:.4} rad/s at 10 s (6 V steady: {:.4})", steady / 2.0);
    let path = output_dir()?.join("dc_motor.svg");
    let series = vec![
        Series { name: "speed, 12 V step [rad/s]", x: t, y: speed },
        Series { name: "current, 12 V step [A]", x: t, y: current },
        Series { name: "speed, PWM [rad/s]", x: pwm.t(), y: pwm_speed },
    ];
    let (title, x_label, y_label) = ("DC motor from parts", "time t [s]", "speed, current");
    Chart { title, x_label, y_label, series, log_y: false, log_x: false }.write(&path)?;
    println!("wrote {}", path.display());
    Ok(())
}
