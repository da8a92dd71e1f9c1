//! A slider crank driven at constant crank speed: prescribed motion.
//!
//! A crank (uniform bar, length r, mass m1) turns about the origin; a connecting rod (uniform,
//! length l, mass m2) joins its tip to a slider (mass m3) on the x axis, which a damper c
//! slows. Gravity acts on the crank and the rod. Three coordinates (crank angle θ, rod angle
//! β, slider position x), three holonomic constraints: the loop closes in x and in y, and the
//! crank is driven, `θ − ω t = 0`. The motion is prescribed entirely,
//!
//! ```text
//! x(t) = r cos ωt + √(l² − r² sin² ωt),
//! ```
//!
//! and the drive's multiplier is the torque that keeps the crank at ω against inertia,
//! gravity and the damper. Its power `−λ ∂φ/∂t = λ ω` is recorded as the solution's
//! `constraint_power`; with the damper's power it accounts for every change of the energy.
//! Both integrators run the mechanism; the example prints the slider's error against the
//! closed form and the energy balance, and plots the slider, the torque and the balance.

use std::error::Error;
use std::f64::consts::PI;

use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// The slider crank, its crank turned at `w`.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(theta => v_theta, beta => v_beta, x => v_x))]
#[dirac(define(rod_vx) = -r * sin(theta) * v_theta - 0.5 * l * sin(beta) * v_beta)]
#[dirac(define(rod_vy) = r * cos(theta) * v_theta - 0.5 * l * cos(beta) * v_beta)]
#[dirac(define(rod_y) = r * sin(theta) - 0.5 * l * sin(beta))]
#[dirac(lagrangian = 0.5 * m1 * r * r / 3.0 * v_theta * v_theta
                   + 0.5 * m2 * (rod_vx * rod_vx + rod_vy * rod_vy)
                   + 0.5 * m2 * l * l / 12.0 * v_beta * v_beta
                   + 0.5 * m3 * v_x * v_x
                   - m1 * g * 0.5 * r * sin(theta) - m2 * g * rod_y)]
#[dirac(force(x) = -c * v_x)]
#[dirac(holonomic(loop_x) = r * cos(theta) + l * cos(beta) - x)]
#[dirac(holonomic(loop_y) = r * sin(theta) - l * sin(beta))]
#[dirac(holonomic(drive) = theta - w * t)]
pub struct SliderCrank {
    /// Crank mass [kg].
    pub m1: f64,
    /// Rod mass [kg].
    pub m2: f64,
    /// Slider mass [kg].
    pub m3: f64,
    /// Crank length [m].
    pub r: f64,
    /// Rod length [m].
    pub l: f64,
    /// Gravity [m/s²].
    pub g: f64,
    /// Damping on the slider [N s/m].
    pub c: f64,
    /// Crank speed [rad/s].
    pub w: f64,
}

impl SliderCrank {
    /// The slider's position in closed form.
    fn slider(&self, t: f64) -> f64 {
        let (sin, cos) = (self.w * t).sin_cos();
        self.r * cos + (self.l * self.l - self.r * self.r * sin * sin).sqrt()
    }
}

/// `∫ y dt` over samples at equal spacing `dt`, by Simpson's rule (an even number of
/// intervals).
fn simpson(y: &[f64], dt: f64) -> f64 {
    let n = y.len() - 1;
    assert!(n.is_multiple_of(2), "Simpson's rule needs an even number of intervals");
    let inner: f64 = (1..n).map(|i| if i % 2 == 1 { 4.0 * y[i] } else { 2.0 * y[i] }).sum();
    (y[0] + inner + y[n]) * dt / 3.0
}

/// What one run shows: the slider's largest error, the largest |φ|, and the energy balance
/// `|ΔE − ∫ (P_damper + P_drive) dt|` relative to the work the drive did.
fn report<S>(name: &str, crank: &SliderCrank, sol: &Solution<SliderCrank, S>, dt: f64) {
    let t = sol.t();
    let x = sol.q(SliderCrank::X);
    let error = t.iter().zip(x).map(|(t, x)| (x - crank.slider(*t)).abs()).fold(0.0, f64::max);
    let phi = sol.holonomic_residual().iter().fold(0.0f64, |m, r| m.max(*r));
    let total: Vec<f64> = sol.power().iter().zip(sol.constraint_power()).map(|(f, c)| f + c).collect();
    let (work, drive) = (simpson(&total, dt), simpson(sol.constraint_power(), dt));
    let (e, last) = (sol.energy(), sol.len() - 1);
    let gained = e[last] - e[0];
    println!(
        "{name}: slider error {error:.1e} m, |phi| up to {phi:.1e}; energy gained {gained:.6} J, work of \
         drive and damper {work:.6} J, differing by {:.1e} of the drive's work {drive:.4} J",
        (gained - work).abs() / drive.abs(),
    );
}

fn main() -> Result<(), Box<dyn Error>> {
    let crank = SliderCrank { m1: 1.0, m2: 2.0, m3: 0.5, r: 0.3, l: 1.0, g: 9.81, c: 0.8, w: 2.0 * PI };
    println!("{}\n", SliderCrank::equations().text);
    // The crank at 0 with the rod along the axis; the consistent state gives it ω.
    let q = VecQ::<SliderCrank>::new(0.0, 0.0, crank.r + crank.l);
    let start = consistent_state(&crank, 0.0, &q, &VecQ::<SliderCrank>::zeros(), Consistency::default())?;
    println!("start: crank speed {:.4} rad/s (ω = {:.4})", start.v[0], crank.w);

    let dt = 1e-3;
    let radau = Radau::new(&crank, RadauOptions::tolerances(1e-10, 1e-10))?.solve(
        0.0,
        &start,
        2.25,
        &Sampling::Every(dt),
    )?;
    let variational = Variational::new(&crank, dt, VariationalOptions::default())?.solve(
        0.0,
        &start,
        2.25,
        &Sampling::Every(dt),
    )?;
    report("Radau (tolerance 1e-10)", &crank, &radau, dt);
    report("variational (h = 1e-3)", &crank, &variational, dt);

    let t = radau.t();
    let torque = radau.lambda(SliderCrank::DRIVE);
    let (low, high) = torque.iter().fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(*x), b.max(*x)));
    println!("drive torque between {low:.3} and {high:.3} N m");
    let dir = output_dir()?;
    let motion = dir.join("slider_crank.svg");
    Chart {
        title: "Slider crank at 1 turn/s: slider position and drive torque",
        x_label: "time t [s]",
        y_label: "slider x [m], torque [N m]",
        series: vec![
            Series { name: "slider x [m]", x: t, y: radau.q(SliderCrank::X) },
            Series { name: "drive torque [N m]", x: t, y: torque },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&motion)?;
    let damper: Vec<f64> = radau.power().iter().map(|p| -p).collect();
    // The rate of change of the stored energy, by central differences of the recorded energy:
    // on the plot it is the drive's power less the damper's.
    let e = radau.energy();
    let rate: Vec<f64> = (1..e.len() - 1).map(|k| (e[k + 1] - e[k - 1]) / (2.0 * dt)).collect();
    let power = dir.join("slider_crank_power.svg");
    Chart {
        title: "Where the drive's power goes",
        x_label: "time t [s]",
        y_label: "power [W]",
        series: vec![
            Series { name: "drive, -lambda b = lambda w", x: t, y: radau.constraint_power() },
            Series { name: "into the damper, c v_x^2", x: t, y: &damper },
            Series { name: "stored, dE/dt", x: &t[1..t.len() - 1], y: &rate },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&power)?;
    for p in [&motion, &power] {
        println!("wrote {}", p.display());
    }
    Ok(())
}
