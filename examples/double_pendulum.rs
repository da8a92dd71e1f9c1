//! A double pendulum in Cartesian coordinates: two point masses, two rods as holonomic
//! constraints `x1² + y1² = l1²` and `(x2 − x1)² + (y2 − y1)² = l2²`.
//!
//! The program runs it for a long time with both integrators at a comparable cost: the
//! variational integrator (RATTLE-shaped for this separable model) keeps the energy error
//! bounded and the rods exact at every step; Radau IIA, far more accurate over a short time,
//! lets its energy error grow. It prints the numbers and plots the energy error of both and the
//! constraint residuals. It also prints the size of the packed Jacobian the derive emits for
//! solvers outside dirac.

use std::error::Error;
use std::fs::File;
use std::io::BufWriter;
use std::time::Instant;

use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// Two masses on rods, gravity along −y.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x1 => vx1, y1 => vy1, x2 => vx2, y2 => vy2))]
#[dirac(lagrangian = 0.5 * m1 * (vx1 * vx1 + vy1 * vy1) + 0.5 * m2 * (vx2 * vx2 + vy2 * vy2)
                   - g * (m1 * y1 + m2 * y2))]
#[dirac(holonomic(rod1) = x1 * x1 + y1 * y1 - l1 * l1)]
#[dirac(holonomic(rod2) = (x2 - x1).powi(2) + (y2 - y1).powi(2) - l2 * l2)]
pub struct DoublePendulum {
    /// First mass [kg].
    pub m1: f64,
    /// Second mass [kg].
    pub m2: f64,
    /// First rod [m].
    pub l1: f64,
    /// Second rod [m].
    pub l2: f64,
    /// Gravity [m/s²].
    pub g: f64,
}

fn main() -> Result<(), Box<dyn Error>> {
    let model = DoublePendulum { m1: 1.0, m2: 1.0, l1: 1.0, l2: 1.0, g: 9.81 };
    println!("{}\n", DoublePendulum::equations().text);
    // The same equations for another solver: the flat Jacobian ∂f/∂y, packed (SparseJacobian).
    let (ny, stored) =
        (DoublePendulum::JACOBIAN_COLUMN_STARTS.len() - 1, DoublePendulum::JACOBIAN_ROW_INDICES.len());
    println!("flat Jacobian: {ny} × {ny}, {stored} structural nonzeros in compressed sparse columns\n");
    // Both rods horizontal to the right, at rest: a chaotic swing.
    let q = VecQ::<DoublePendulum>::new(1.0, 0.0, 2.0, 0.0);
    let start = consistent_state(&model, 0.0, &q, &VecQ::<DoublePendulum>::zeros(), Consistency::default())?;
    let t_end = 1000.0;
    let sampling = Sampling::Every(0.5);
    let clock = Instant::now();
    let variational = Variational::new(&model, 1e-3, VariationalOptions::default())?
        .solve(0.0, &start, t_end, &sampling)?;
    let variational_seconds = clock.elapsed().as_secs_f64();
    let clock = Instant::now();
    let radau =
        Radau::new(&model, RadauOptions::tolerances(1e-6, 1e-8))?.solve(0.0, &start, t_end, &sampling)?;
    let radau_seconds = clock.elapsed().as_secs_f64();
    let e0 = variational.energy()[0];
    let energy_error = |energy: &[f64]| energy.iter().map(|e| (e - e0).abs()).collect::<Vec<_>>();
    let (ev, er) = (energy_error(variational.energy()), energy_error(radau.energy()));
    let tail = |e: &[f64]| e[e.len() * 9 / 10..].iter().copied().fold(0.0, f64::max);
    let head = |e: &[f64]| e[..e.len() / 10].iter().copied().fold(0.0, f64::max);
    println!("t in [0, {t_end}], E(0) = {e0:.6} J");
    println!(
        "  variational, h = 1e-3: {:.2} s, |E-E0| first 10% {:.1e}, last 10% {:.1e}, largest |phi| {:.1e}",
        variational_seconds,
        head(&ev),
        tail(&ev),
        variational.holonomic_residual().iter().copied().fold(0.0, f64::max)
    );
    println!(
        "  Radau, tol 1e-6:       {:.2} s, |E-E0| first 10% {:.1e}, last 10% {:.1e}, largest |phi| {:.1e}",
        radau_seconds,
        head(&er),
        tail(&er),
        radau.holonomic_residual().iter().copied().fold(0.0, f64::max)
    );

    let dir = output_dir()?;
    let csv = dir.join("double_pendulum.csv");
    variational.write_csv(BufWriter::new(File::create(&csv)?))?;
    let energy = dir.join("double_pendulum_energy.svg");
    Chart {
        title: "Double pendulum: energy error over a long run",
        x_label: "time t [s]",
        y_label: "|E - E(0)| [J] (log10)",
        series: vec![
            Series { name: "variational, h = 1e-3", x: variational.t(), y: &ev },
            Series { name: "Radau, tol 1e-6", x: radau.t(), y: &er },
        ],
        log_y: true,
        log_x: false,
    }
    .write(&energy)?;
    let residuals = dir.join("double_pendulum_constraints.svg");
    Chart {
        title: "Double pendulum: rod constraints",
        x_label: "time t [s]",
        y_label: "max |phi(q)| [m²] (log10)",
        series: vec![
            Series { name: "variational", x: variational.t(), y: variational.holonomic_residual() },
            Series { name: "Radau", x: radau.t(), y: radau.holonomic_residual() },
        ],
        log_y: true,
        log_x: false,
    }
    .write(&residuals)?;
    for p in [&csv, &energy, &residuals] {
        println!("wrote {}", p.display());
    }
    Ok(())
}
