//! Recovering a spatially varying profile from a few waveforms, with many parameters and one
//! adjoint gradient an iteration: the inductance of each of the 30 cells of an LC ladder,
//! from the flux measured at three of its nodes.
//!
//! The true line has a bump of +50% at 60% of its length over a slope from 1 to 0.75 (unit
//! capacitances). It starts at rest with a flux bump in its first quarter, which travels,
//! splits and reflects; the measurements are the flux at a third, two thirds and the open
//! end, every 0.1 over three passes of a wave (901 samples a node), with Gaussian noise of
//! deviation `σ = 0.002` (about 1% of the wave). L-BFGS (the `argmin` crate) starts from a
//! uniform line and minimises `χ²/2` of the waveforms, with a small penalty on neighbours'
//! differences; each iteration's gradient with respect to all 30 inductances is one recorded
//! run and one adjoint sweep ([`Recording::gradient`](dirac::adjoint::Recording::gradient)).
//! The example prints the recovered profile against the true one, and `χ²` of the fit against
//! that of the true line on the same data, and plots both profiles.
//!
//! Run: `cargo run --release --features sparse --example profile_recovery`.

use std::error::Error;

#[path = "profile/problem.rs"]
mod problem;
#[path = "support/mod.rs"]
mod support;

use problem::{Setup, chi2, measurements, recover, true_profile};
use support::{Chart, Series, output_dir};

fn main() -> Result<(), Box<dyn Error>> {
    let setup = Setup::new(30, 0.002, 20.0);
    let data = measurements(&setup, 2026)?;
    let truth = true_profile(setup.cells);
    println!(
        "LC ladder of {} cells: flux measured at cells {:?}, {} samples each, σ = {}",
        setup.cells,
        setup.sensors,
        data[0].len(),
        setup.sigma
    );
    let recovery = recover(&setup, &data, 1.0, 300)?;
    println!(
        "L-BFGS: {} after {} iterations, {} recorded runs with their adjoint sweeps",
        recovery.termination, recovery.iterations, recovery.simulations
    );
    let (fit, exact) = (chi2(&recovery.profile, &setup, &data)?, chi2(&truth, &setup, &data)?);
    let count = data.iter().map(Vec::len).sum::<usize>();
    println!("χ² = {fit:.1} for the fit, {exact:.1} for the true line ({count} measurements)");
    let errors: Vec<f64> = recovery.profile.iter().zip(&truth).map(|(l, t)| (l - t) / t).collect();
    let rms = (errors.iter().map(|e| e * e).sum::<f64>() / errors.len() as f64).sqrt();
    let worst = errors.iter().fold(0.0f64, |m, e| m.max(e.abs()));
    println!("relative error of the recovered inductances: rms {rms:.2e}, worst {worst:.2e}");
    println!("cell  true    recovered");
    for (j, (l, t)) in recovery.profile.iter().zip(&truth).enumerate() {
        println!("{j:>4}  {t:.4}  {l:.4}");
    }
    let cells: Vec<f64> = (0..setup.cells).map(|j| j as f64).collect();
    let uniform = vec![1.0; setup.cells];
    let dir = output_dir()?;
    let chart = Chart {
        title: "LC ladder: inductance profile recovered from three waveforms",
        x_label: "cell",
        y_label: "inductance",
        series: vec![
            Series { name: "true", x: &cells, y: &truth },
            Series { name: "start", x: &cells, y: &uniform },
        ],
        log_y: false,
        log_x: false,
    };
    chart.write_with_markers(
        &dir.join("profile_recovery.svg"),
        &[Series { name: "recovered", x: &cells, y: &recovery.profile }],
    )?;
    println!("plot: {}", dir.join("profile_recovery.svg").display());
    Ok(())
}
