//! A wave travelling down a long LC ladder (a lumped transmission line) of 2000 cells: one
//! interconnection with an array field, `cells: Vec<Cell>`, connected cell to cell by one
//! pattern, `connect(cells[i].b, cells[i + 1].a)`.
//!
//! A flux pulse at node 400 splits into two waves travelling one node per unit time
//! (`1/√(LC)`); the one going left reflects, inverted, from the grounded end. The program
//! prints the model's size and equations, simulates 600 time units with Radau on the sparse
//! path, checks the energy (the ladder is lossless), and draws the node voltages at five
//! times and the energy against time.

use std::error::Error;

use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// One section: a series inductor from the previous node `a` to this node `b`, and a
/// capacitor from `b` to ground. Coordinates are node fluxes; their rates are node voltages.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(a => va, b => vb), port(a, b))]
#[dirac(lagrangian = 0.5 * c * vb * vb - (b - a) * (b - a) / (2.0 * l))]
struct Cell {
    l: f64,
    c: f64,
}

/// The ground node, held at zero flux.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(g => vg), port(g))]
#[dirac(lagrangian = 0.0 * vg)]
#[dirac(holonomic(grounded) = g)]
struct Ground {}

/// Ground, then `cells.len()` sections, open at the far end.
#[derive(Interconnection, Clone)]
#[dirac(connect(ground.g, cells[0].a), connect(cells[i].b, cells[i + 1].a))]
struct Ladder {
    ground: Ground,
    cells: Vec<Cell>,
}

fn main() -> Result<(), Box<dyn Error>> {
    let n = 2000;
    let ladder = Ladder { ground: Ground {}, cells: vec![Cell { l: 1.0, c: 1.0 }; n] };
    let sizes = ladder.sizes();
    println!("{} cells: {} coordinates, {} constraints", n, sizes.nq, sizes.nc);
    println!("{}\n", Ladder::equations().text);

    // A flux pulse at node 400, at rest: fluxes of connected nodes agree.
    let pulse = |j: usize| (-((j as f64 - 400.0) / 8.0).powi(2)).exp();
    let mut q = sizes.zeros_q::<Ladder>();
    for j in 0..n {
        q[ladder.cells(j, Cell::B).index()] = pulse(j + 1);
        if j + 1 < n {
            q[ladder.cells(j + 1, Cell::A).index()] = pulse(j + 1);
        }
    }
    let start = consistent_state(&ladder, 0.0, &q, &sizes.zeros_q::<Ladder>(), Consistency::default())?;
    let times = [0.0, 150.0, 300.0, 450.0, 600.0];
    let options = RadauOptions { error_norm: ErrorNorm::Max, ..RadauOptions::tolerances(1e-7, 1e-7) };
    let clock = std::time::Instant::now();
    let sol = Radau::new(&ladder, options)?.solve(0.0, &start, 600.0, &Sampling::Every(5.0))?;
    println!("simulated {} samples in {:.2?}: {:?}", sol.len(), clock.elapsed(), sol.stats);

    let e0 = sol.energy()[0];
    let drift = sol.energy().iter().map(|e| (e - e0).abs()).fold(0.0, f64::max);
    println!("energy {e0:.6}, largest change {drift:.2e} (relative {:.2e})", drift / e0);

    // Node voltages v_b at the chosen times.
    let nodes: Vec<f64> = (1..=n).map(|j| j as f64).collect();
    let voltages: Vec<Vec<f64>> = times
        .iter()
        .map(|&t| {
            let i = sol.t().iter().position(|&s| (s - t).abs() < 1e-9).expect("a sample at t");
            (0..n).map(|j| sol.v(ladder.cells(j, Cell::B))[i]).collect()
        })
        .collect();
    let names: Vec<String> = times.iter().map(|t| format!("t = {t}")).collect();
    let dir = output_dir()?;
    let wave = dir.join("ladder_wave.svg");
    Chart {
        title: "A pulse on a 2000-cell LC ladder: node voltages",
        x_label: "node",
        y_label: "voltage dφ/dt [V]",
        series: names.iter().zip(&voltages).map(|(name, y)| Series { name, x: &nodes, y }).collect(),
        log_y: false,
        log_x: false,
    }
    .write(&wave)?;
    let energy_change: Vec<f64> = sol.energy().iter().map(|e| (e - e0).abs().max(1e-16)).collect();
    let energy = dir.join("ladder_energy.svg");
    Chart {
        title: "Energy of the ladder: |E(t) − E(0)|",
        x_label: "time t",
        y_label: "|E − E(0)| [J] (log10)",
        series: vec![Series { name: "Radau, tolerance 1e-7", x: sol.t(), y: &energy_change }],
        log_y: true,
        log_x: false,
    }
    .write(&energy)?;
    println!("wrote {} and {}", wave.display(), energy.display());
    Ok(())
}
