//! An L-C circuit as a degenerate Lagrange-Dirac system.
//!
//! The charges through the inductor and the capacitor are the coordinates, the inductor is a
//! mass (`½ L i_l²`), the capacitor a spring (`q_c² / 2C`), and Kirchhoff's current law for the
//! single loop, `i_l − i_c = 0`, is the constraint distribution. The Lagrangian has no kinetic
//! term in `i_c`: it is degenerate, and only the constraint determines that current. With
//! L = C = 1, q(0) = 1 and i(0) = 0 the charge is `q_c = cos t`.
//!
//! The program simulates the circuit with both integrators, compares the charge with cos t,
//! and writes CSV and plots of the charge and of the energy error.

use std::error::Error;
use std::fs::File;
use std::io::BufWriter;

use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// One loop: an inductor `ind` and a capacitor `cap` in series.
#[derive(LagrangeDirac)]
#[dirac(coordinates(q_l => i_l, q_c => i_c))]
#[dirac(lagrangian = 0.5 * ind * i_l * i_l - 0.5 * q_c * q_c / cap)]
#[dirac(constraint(kcl) = i_l - i_c)]
pub struct LcCircuit {
    /// Inductance [H].
    pub ind: f64,
    /// Capacitance [F].
    pub cap: f64,
}

fn main() -> Result<(), Box<dyn Error>> {
    let circuit = LcCircuit { ind: 1.0, cap: 1.0 };
    println!("{}\n", LcCircuit::equations().text);
    let q = VecQ::<LcCircuit>::new(1.0, 1.0);
    let start = consistent_state(&circuit, 0.0, &q, &VecQ::<LcCircuit>::zeros(), Consistency::default())?;
    let t_end = 20.0;
    let radau = Radau::new(&circuit, RadauOptions::tolerances(1e-10, 1e-12))?.solve(
        0.0,
        &start,
        t_end,
        &Sampling::Every(0.02),
    )?;
    let variational = Variational::new(&circuit, 0.02, VariationalOptions::default())?.solve(
        0.0,
        &start,
        t_end,
        &Sampling::Every(0.02),
    )?;

    let exact: Vec<f64> = radau.t().iter().map(|t| t.cos()).collect();
    let report = |name: &str, charge: &[f64], energy: &[f64], steps: usize| {
        let error = charge.iter().zip(&exact).map(|(q, e)| (q - e).abs()).fold(0.0, f64::max);
        let drift = energy.iter().map(|e| (e - energy[0]).abs()).fold(0.0, f64::max);
        println!("{name}: max |q_c - cos t| = {error:.2e}, max |E - E0| = {drift:.2e} J, {steps} steps");
    };
    report("Radau (tol 1e-10)", radau.q(LcCircuit::Q_C), radau.energy(), radau.stats.steps);
    let (charge, energy) = (variational.q(LcCircuit::Q_C), variational.energy());
    report("variational (h = 0.02)", charge, energy, variational.stats.steps);

    let dir = output_dir()?;
    let csv = dir.join("lc_circuit.csv");
    radau.write_csv(BufWriter::new(File::create(&csv)?))?;
    let charge = dir.join("lc_circuit_charge.svg");
    Chart {
        title: "LC circuit: capacitor charge",
        x_label: "time t [s]",
        y_label: "charge q_c [C]",
        series: vec![
            Series { name: "Radau", x: radau.t(), y: radau.q(LcCircuit::Q_C) },
            Series { name: "variational", x: variational.t(), y: variational.q(LcCircuit::Q_C) },
            Series { name: "cos t", x: radau.t(), y: &exact },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&charge)?;
    let energy_error = |energy: &[f64]| energy.iter().map(|e| (e - energy[0]).abs()).collect::<Vec<_>>();
    let (er, ev) = (energy_error(radau.energy()), energy_error(variational.energy()));
    let errors = dir.join("lc_circuit_energy.svg");
    Chart {
        title: "LC circuit: energy error",
        x_label: "time t [s]",
        y_label: "|E - E(0)| [J] (log10)",
        series: vec![
            Series { name: "Radau", x: radau.t(), y: &er },
            Series { name: "variational", x: variational.t(), y: &ev },
        ],
        log_y: true,
        log_x: false,
    }
    .write(&errors)?;
    for path in [&csv, &charge, &errors] {
        println!("wrote {}", path.display());
    }
    Ok(())
}
