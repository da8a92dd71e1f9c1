//! The paper's example (Yoshimura, Jacobs & Marsden, §VI): the mass-spring chain
//!
//! ```text
//! wall —k1— m1 —k2— m2 —k3— m3
//! ```
//!
//! torn into two primitive Lagrange-Dirac systems with boundary ports (Fig. 2):
//!
//! - primitive system 1 on Q1 = (x1, x2): L1 = ½(m1 v1² + m2 v2²) − ½(k1 x1² + k2 (x2 − x1)²);
//! - primitive system 2 on Q2 = (x̄2, x3): L2 = ½ m3 v3² − ½ k3 (x3 − x̄2)², degenerate: it has
//!   no kinetic energy in v̄2, so p̄2 = 0;
//!
//! and interconnected through the Dirac structure of `v2 = v̄2`, `f2 + f̄2 = 0` (eq. 8). The
//! program prints the derived equations (the paper's eqs. 9, 10 and 12–14), simulates the
//! interconnected system with Radau IIA from x(0) = (0.1, 0, 0) at rest over t ∈ [0, 20] with
//! m = (1, 2, 3), k = (4, 5, 6), checks it against the same chain written as one model, reports
//! energy, the interconnection's power (zero: Tellegen) and the port efforts, and writes the
//! trajectory as CSV.

use std::error::Error;
use std::fs::File;
use std::io::BufWriter;

use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// Primitive system 1: wall —k1— m1 —k2— m2, port at x2.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x1 => v1, x2 => v2), port(x2))]
#[dirac(lagrangian = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2
                   - 0.5 * k1 * x1 * x1 - 0.5 * k2 * (x2 - x1).powi(2))]
pub struct Primitive1 {
    /// Mass m1.
    pub m1: f64,
    /// Mass m2.
    pub m2: f64,
    /// Spring constant k1 (wall to m1).
    pub k1: f64,
    /// Spring constant k2 (m1 to m2).
    pub k2: f64,
}

/// Primitive system 2: x̄2 —k3— m3, port at x̄2.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x2bar => v2bar, x3 => v3), port(x2bar))]
#[dirac(lagrangian = 0.5 * m3 * v3 * v3 - 0.5 * k3 * (x3 - x2bar).powi(2))]
pub struct Primitive2 {
    /// Mass m3.
    pub m3: f64,
    /// Spring constant k3 (m2 to m3).
    pub k3: f64,
}

/// The interconnection: ports x2 and x̄2 move together and their efforts balance.
#[derive(Interconnection)]
#[dirac(connect(left.x2, right.x2bar))]
pub struct Chain {
    /// Primitive system 1.
    pub left: Primitive1,
    /// Primitive system 2.
    pub right: Primitive2,
}

/// The untorn chain of Fig. 1 as one model, for comparison.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x1 => v1, x2 => v2, x3 => v3))]
#[dirac(lagrangian = 0.5 * (m1 * v1 * v1 + m2 * v2 * v2 + m3 * v3 * v3)
                   - 0.5 * (k1 * x1 * x1 + k2 * (x2 - x1).powi(2) + k3 * (x3 - x2).powi(2)))]
pub struct Monolithic {
    /// Masses.
    pub m1: f64,
    /// Mass m2.
    pub m2: f64,
    /// Mass m3.
    pub m3: f64,
    /// Spring constants.
    pub k1: f64,
    /// Spring constant k2.
    pub k2: f64,
    /// Spring constant k3.
    pub k3: f64,
}

fn main() -> Result<(), Box<dyn Error>> {
    let (m, k) = ([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]);
    let chain = Chain {
        left: Primitive1 { m1: m[0], m2: m[1], k1: k[0], k2: k[1] },
        right: Primitive2 { m3: m[2], k3: k[2] },
    };
    println!("Primitive system 1 (the paper's eq. 9):\n{}\n", Primitive1::equations().text);
    println!("Primitive system 2 (eq. 10):\n{}\n", Primitive2::equations().text);
    println!("Interconnected (eqs. 12-14):\n{}\n", Chain::equations().text);

    // x(0) = (0.1, 0, 0), at rest; x̄2 = x2 and μ follow from consistency.
    let mut q = VecQ::<Chain>::zeros();
    q[Chain::left(Primitive1::X1).index()] = 0.1;
    let start = consistent_state(&chain, 0.0, &q, &VecQ::<Chain>::zeros(), Consistency::default())?;
    let options = RadauOptions::tolerances(1e-10, 1e-12);
    let sampling = Sampling::Every(0.01);
    let torn = Radau::new(&chain, options)?.solve(0.0, &start, 20.0, &sampling)?;

    let whole = Monolithic { m1: m[0], m2: m[1], m3: m[2], k1: k[0], k2: k[1], k3: k[2] };
    let q = VecQ::<Monolithic>::new(0.1, 0.0, 0.0);
    let whole_start =
        consistent_state(&whole, 0.0, &q, &VecQ::<Monolithic>::zeros(), Consistency::default())?;
    let reference = Radau::new(&whole, options)?.solve(0.0, &whole_start, 20.0, &sampling)?;

    let pairs = [
        ("x1", torn.q(Chain::left(Primitive1::X1)), reference.q(Monolithic::X1)),
        ("x2", torn.q(Chain::left(Primitive1::X2)), reference.q(Monolithic::X2)),
        ("x3", torn.q(Chain::right(Primitive2::X3)), reference.q(Monolithic::X3)),
    ];
    println!(
        "Simulated t in [0, 20]: {} steps, {} rejected, {} LU factorisations",
        torn.stats.steps, torn.stats.rejected, torn.stats.factorizations
    );
    for (name, a, b) in &pairs {
        let deviation = a.iter().zip(b.iter()).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
        println!("  max |{name} torn - {name} monolithic| = {deviation:.2e}");
    }
    let e0 = torn.energy()[0];
    let drift = torn.energy().iter().map(|e| (e - e0).abs()).fold(0.0, f64::max) / e0;
    let tellegen = torn.interconnection_power().iter().map(|p| p.abs()).fold(0.0, f64::max);
    println!("  energy E = {e0:.6}, largest relative drift {drift:.1e}");
    println!("  largest |interconnection power| {tellegen:.1e} (Tellegen: zero)");
    let f2 = torn.interconnection_force(Chain::LEFT_X2).ok_or("x2 is a port")?;
    let f2bar = torn.interconnection_force(Chain::RIGHT_X2BAR).ok_or("x2bar is a port")?;
    let last = torn.len() - 1;
    println!("  port efforts at t = 20: f2 = {:.6}, f2bar = {:.6}", f2[last], f2bar[last]);

    let dir = output_dir()?;
    let csv = dir.join("mass_spring_chain.csv");
    torn.write_csv(BufWriter::new(File::create(&csv)?))?;
    let t = torn.t();
    let positions = dir.join("mass_spring_chain_positions.svg");
    Chart {
        title: "Torn and interconnected chain: positions",
        x_label: "time t [s]",
        y_label: "position [m]",
        series: vec![
            Series { name: "x1", x: t, y: torn.q(Chain::left(Primitive1::X1)) },
            Series { name: "x2 (= x2bar)", x: t, y: torn.q(Chain::left(Primitive1::X2)) },
            Series { name: "x3", x: t, y: torn.q(Chain::right(Primitive2::X3)) },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&positions)?;
    let energy_error: Vec<f64> = torn.energy().iter().map(|e| (e - e0).abs()).collect();
    let deviation: Vec<f64> = (0..torn.len())
        .map(|i| pairs.iter().map(|(_, a, b)| (a[i] - b[i]).abs()).fold(0.0, f64::max))
        .collect();
    let errors = dir.join("mass_spring_chain_errors.svg");
    Chart {
        title: "Energy error and deviation from the monolithic chain",
        x_label: "time t [s]",
        y_label: "absolute error (log10)",
        series: vec![
            Series { name: "|E - E(0)| [J]", x: t, y: &energy_error },
            Series { name: "max |x torn - x whole| [m]", x: t, y: &deviation },
        ],
        log_y: true,
        log_x: false,
    }
    .write(&errors)?;
    let forces = dir.join("mass_spring_chain_port_forces.svg");
    Chart {
        title: "Efforts at the ports: f2 + f2bar = 0",
        x_label: "time t [s]",
        y_label: "force [N]",
        series: vec![Series { name: "f2", x: t, y: f2 }, Series { name: "f2bar", x: t, y: f2bar }],
        log_y: false,
        log_x: false,
    }
    .write(&forces)?;
    for path in [&csv, &positions, &errors, &forces] {
        println!("wrote {}", path.display());
    }
    Ok(())
}
