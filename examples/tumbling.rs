//! A free body read from a URDF file and floated: spun about its intermediate axis of inertia
//! with a small disturbance, it flips over and back again and again (the tennis racket, or
//! Dzhanibekov, effect), while nothing acts on it.
//!
//! The program integrates 200 s with the variational integrator and with Radau IIA, prints the
//! time each took and how far each lets the angular momentum (an output of every floating robot)
//! and the energy drift, and plots the angular velocity in the body's axes: the spin
//! `ω_y` reverses at every flip.

use std::error::Error;
use std::time::Instant;

use dirac::prelude::*;
use dirac::{Solution, State};

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// The wing nut (`examples/robots/wing_nut.urdf`: moments 1, 2 and 3 kg m²), floating, with no
/// gravity.
#[derive(LagrangeDirac)]
#[dirac(urdf = "examples/robots/wing_nut.urdf", floating, gravity = [0.0, 0.0, 0.0])]
pub struct WingNut;

/// The angular velocity in the body's axes, `Ω̂ = RᵀṘ`, from a state's rotation and its rates.
fn body_spin(state: &State<WingNut>, r: &[usize; 9]) -> [f64; 3] {
    let (q, v) = (|i: usize, j: usize| state.q[r[3 * i + j]], |i: usize, j: usize| state.v[r[3 * i + j]]);
    let column = |a: usize, b: usize| (0..3).map(|m| q(m, a) * v(m, b)).sum::<f64>();
    [column(2, 1), column(0, 2), column(1, 0)]
}

/// The largest distance of a series from its first value.
fn drift(series: &[f64]) -> f64 {
    series.iter().map(|x| (x - series[0]).abs()).fold(0.0, f64::max)
}

/// How far a run let the angular momentum and the energy drift, and how well it held `RᵀR = I`.
fn report<S>(name: &str, solution: &Solution<WingNut, S>, seconds: f64, t_end: f64) {
    let momentum = ["x", "y", "z"]
        .map(|axis| drift(solution.column(&format!("out(angular_momentum_{axis})")).expect("a momentum")));
    println!(
        "{name}: {seconds:.2} s; over {t_end} s the angular momentum drifts by {:.1e} N m s, the energy by {:.1e} J, \
         |RᵀR - I| stays below {:.1e}",
        momentum.into_iter().fold(0.0, f64::max),
        drift(solution.energy()),
        solution.holonomic_residual().iter().copied().fold(0.0, f64::max)
    );
}

fn main() -> Result<(), Box<dyn Error>> {
    let names = WingNut::NAMES.coordinate_names();
    let r: [usize; 9] = std::array::from_fn(|k| {
        let name = format!("root_joint_r{}{}", k / 3 + 1, k % 3 + 1);
        names.iter().position(|n| *n == name).expect("a free joint")
    });
    let upright = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mut state = State::<WingNut>::zeros();
    state.place_free_body("root_joint", [0.0; 3], upright, [0.0; 3], [1e-3, 2.0, 1e-3])?;
    let start = consistent_state(&WingNut, 0.0, &state.q, &state.v, Consistency::default())?;
    let (t_end, sampling) = (200.0, Sampling::Every(0.05));
    let clock = Instant::now();
    let variational = Variational::new(&WingNut, 1e-2, VariationalOptions::default())?
        .solve(0.0, &start, t_end, &sampling)?;
    let variational_seconds = clock.elapsed().as_secs_f64();
    let clock = Instant::now();
    let radau =
        Radau::new(&WingNut, RadauOptions::tolerances(1e-6, 1e-8))?.solve(0.0, &start, t_end, &sampling)?;
    let radau_seconds = clock.elapsed().as_secs_f64();
    report("variational, h = 1e-2", &variational, variational_seconds, t_end);
    report("Radau, tol 1e-6", &radau, radau_seconds, t_end);
    let spins: Vec<[f64; 3]> =
        (0..variational.len()).map(|k| body_spin(&variational.state(k).expect("a sample"), &r)).collect();
    let flips = spins.windows(2).filter(|w| w[0][1].signum() != w[1][1].signum()).count();
    println!("the spin about the middle axis reversed {flips} times");
    let axis = |i: usize| spins.iter().map(|w| w[i]).collect::<Vec<f64>>();
    let (wx, wy, wz) = (axis(0), axis(1), axis(2));
    let path = output_dir()?.join("tumbling.svg");
    Chart {
        title: "A free body spun about its middle axis flips over and back",
        x_label: "time t [s]",
        y_label: "angular velocity in the body's axes [rad/s]",
        series: vec![
            Series { name: "ω_x", x: variational.t(), y: &wx },
            Series { name: "ω_y (the spin)", x: variational.t(), y: &wy },
            Series { name: "ω_z", x: variational.t(), y: &wz },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&path)?;
    println!("wrote {}", path.display());
    Ok(())
}
