//! The vertical rolling disk: a nonholonomic Lagrange-Dirac system.
//!
//! A disk of radius r stands upright on a plane, rolls without slipping and turns about the
//! vertical. Its configuration is the contact point (x, y), the rolling angle θ and the heading
//! φ; rolling without slipping is the velocity constraint
//!
//! ```text
//! ẋ = r cos φ θ̇,   ẏ = r sin φ θ̇
//! ```
//!
//! which no position constraint integrates. With constant θ̇ and φ̇ the contact point runs on a
//! circle of radius r θ̇ / φ̇. The program simulates it with Radau and with the variational
//! integrator (discrete Lagrange-d'Alembert), reports energy and slip, and plots the path,
//! the energy error and the slip residual.

use std::error::Error;
use std::fs::File;
use std::io::BufWriter;

use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// The vertical rolling disk.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v_x, y => v_y, theta => v_theta, phi => v_phi))]
#[dirac(lagrangian = 0.5 * m * (v_x * v_x + v_y * v_y) + 0.5 * i_roll * v_theta * v_theta
                   + 0.5 * i_turn * v_phi * v_phi)]
#[dirac(constraint(roll_x) = v_x - r * phi.cos() * v_theta)]
#[dirac(constraint(roll_y) = v_y - r * phi.sin() * v_theta)]
pub struct RollingDisk {
    /// Mass [kg].
    pub m: f64,
    /// Radius [m].
    pub r: f64,
    /// Moment of inertia about the axle [kg m²].
    pub i_roll: f64,
    /// Moment of inertia about the vertical [kg m²].
    pub i_turn: f64,
}

fn main() -> Result<(), Box<dyn Error>> {
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    println!("{}\n", RollingDisk::equations().text);
    // θ̇ = 2, φ̇ = 1, heading along x: rolling gives ẋ = r θ̇ = 0.6, ẏ = 0. (Velocities that
    // break the constraints would be projected in the kinetic metric, changing θ̇ as well.)
    let v = VecQ::<RollingDisk>::new(0.6, 0.0, 2.0, 1.0);
    let start = consistent_state(&disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())?;
    let t_end = 50.0;
    let radau = Radau::new(&disk, RadauOptions::tolerances(1e-9, 1e-11))?.solve(
        0.0,
        &start,
        t_end,
        &Sampling::Every(0.05),
    )?;
    let variational = Variational::new(&disk, 0.05, VariationalOptions::default())?.solve(
        0.0,
        &start,
        t_end,
        &Sampling::Every(0.05),
    )?;
    let radius = disk.r * start.v(RollingDisk::THETA) / start.v(RollingDisk::PHI);
    println!("the contact point circles with radius r θ̇/φ̇ = {radius:.6} m");
    let report = |name: &str, energy: &[f64], slips: &[f64], steps: usize| {
        let e0 = energy[0];
        let drift = energy.iter().map(|e| ((e - e0) / e0).abs()).fold(0.0, f64::max);
        let slip = slips.iter().copied().fold(0.0, f64::max);
        println!("{name}: relative energy error {drift:.1e}, largest slip {slip:.1e} m/s, {steps} steps");
    };
    report("Radau (tol 1e-9)", radau.energy(), radau.constraint_residual(), radau.stats.steps);
    let (energy, slips) = (variational.energy(), variational.constraint_residual());
    report("variational (h = 0.05)", energy, slips, variational.stats.steps);

    let dir = output_dir()?;
    let csv = dir.join("rolling_disk.csv");
    radau.write_csv(BufWriter::new(File::create(&csv)?))?;
    let path = dir.join("rolling_disk_path.svg");
    Chart {
        title: "Rolling disk: contact point",
        x_label: "x [m]",
        y_label: "y [m]",
        series: vec![
            Series { name: "Radau", x: radau.q(RollingDisk::X), y: radau.q(RollingDisk::Y) },
            Series {
                name: "variational",
                x: variational.q(RollingDisk::X),
                y: variational.q(RollingDisk::Y),
            },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&path)?;
    let energy_error = |energy: &[f64]| energy.iter().map(|e| (e - energy[0]).abs()).collect::<Vec<_>>();
    let (er, ev) = (energy_error(radau.energy()), energy_error(variational.energy()));
    let errors = dir.join("rolling_disk_errors.svg");
    Chart {
        title: "Rolling disk: energy error and slip",
        x_label: "time t [s]",
        y_label: "absolute value (log10)",
        series: vec![
            Series { name: "|E - E(0)| Radau [J]", x: radau.t(), y: &er },
            Series { name: "|E - E(0)| variational [J]", x: variational.t(), y: &ev },
            Series { name: "slip |A v| Radau [m/s]", x: radau.t(), y: radau.constraint_residual() },
            Series {
                name: "slip |A v| variational [m/s]",
                x: variational.t(),
                y: variational.constraint_residual(),
            },
        ],
        log_y: true,
        log_x: false,
    }
    .write(&errors)?;
    for p in [&csv, &path, &errors] {
        println!("wrote {}", p.display());
    }
    Ok(())
}
