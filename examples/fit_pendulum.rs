//! Fitting a model to measurements: a damped pendulum's length and damping recovered from 60
//! noisy measurements of its angle, from a start 30% off, by Levenberg-Marquardt (the
//! `levenberg-marquardt` crate) with the Jacobian from dirac's forward sensitivities.
//!
//! The measurements are the true pendulum's angle (l = 0.8 m, c = 0.15 N·m·s, released from
//! rest at 1 rad) every 0.1 s for 6 s, with Gaussian noise of deviation σ = 0.01 rad. Each
//! evaluation of the residuals is one simulation that also carries `∂θ/∂l` and `∂θ/∂c`. The
//! example prints the estimate with its 95% confidence interval (±1.96 standard errors from
//! `(JᵀJ)⁻¹`), the iterations it took, and plots the data against the fitted and the start
//! models.
//!
//! Run: `cargo run --release --example fit_pendulum`.

use std::error::Error;

use dirac::prelude::*;

#[path = "fitting/problem.rs"]
mod problem;
#[path = "support/mod.rs"]
mod support;

use problem::{DampedPendulum, SIGMA, fit, measurements, start, times, truth};
use support::{Chart, Series, output_dir};

fn angle(model: &DampedPendulum) -> Result<Vec<f64>, SimError> {
    let grid: Vec<f64> = (0..=600).map(|i| 0.01 * i as f64).collect();
    let solution = Radau::new(model, RadauOptions::tolerances(1e-10, 1e-10))?.solve(
        0.0,
        &start(model),
        6.0,
        &Sampling::Times(grid),
    )?;
    Ok(solution.q(DampedPendulum::THETA).to_vec())
}

fn main() -> Result<(), Box<dyn Error>> {
    let data = measurements(2026);
    let truth = truth();
    let from = (1.3 * truth.l, 1.3 * truth.c);
    let estimate = fit(data.clone(), from);
    println!("damped pendulum: {} measurements of θ, σ = {SIGMA} rad", data.len());
    println!("start (30% off): l = {:.4} m, c = {:.4} N·m·s", from.0, from.1);
    println!(
        "{:?} after {} iterations, {} evaluations of the residuals ({} simulations, each with both sensitivities)",
        estimate.termination, estimate.iterations, estimate.evaluations, estimate.simulations
    );
    println!("χ² = {:.1} for {} degrees of freedom", estimate.chi2, data.len() - 2);
    for (k, (name, exact)) in [("l", truth.l), ("c", truth.c)].into_iter().enumerate() {
        let (value, half) = (estimate.values[k], 1.96 * estimate.standard_errors[k]);
        let inside = (value - exact).abs() <= half;
        println!(
            "{name} = {value:.5} ± {half:.5} (95%), true {exact}: {}",
            if inside { "inside the interval" } else { "OUTSIDE the interval" }
        );
    }

    let grid: Vec<f64> = (0..=600).map(|i| 0.01 * i as f64).collect();
    let fitted = DampedPendulum { l: estimate.values[0], c: estimate.values[1], ..truth.clone() };
    let first = DampedPendulum { l: from.0, c: from.1, ..truth.clone() };
    let (fitted_angle, first_angle) = (angle(&fitted)?, angle(&first)?);
    let t = times();
    let dir = output_dir()?;
    let chart = Chart {
        title: "Damped pendulum: measurements, the start 30% off, and the fit",
        x_label: "t [s]",
        y_label: "θ [rad]",
        series: vec![
            Series { name: "fitted model", x: &grid, y: &fitted_angle },
            Series { name: "start (30% off)", x: &grid, y: &first_angle },
        ],
        log_y: false,
        log_x: false,
    };
    chart.write_with_markers(
        &dir.join("fit_pendulum.svg"),
        &[Series { name: "measurements", x: &t, y: &data }],
    )?;
    println!("plot: {}", dir.join("fit_pendulum.svg").display());
    Ok(())
}
