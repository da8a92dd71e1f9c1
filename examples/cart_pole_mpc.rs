//! Model-predictive control of a cart-pole: the pole starts 0.5 rad off upright, and at every
//! 10 ms sample the controller solves, from the measured state, the optimal control problem
//! over the next second (DMOC on 20 intervals, the push within ±20 N, the cart within ±1.5 m)
//! and applies the first push of its plan. The plant is the same model integrated by Radau.
//!
//! The solves run on dirac's own interior point (`optimal::interior`), warm started from the
//! last plan moved forward by 10 ms; no feature or external library is needed. Prints the
//! solve times per sample and writes `target/dirac-examples/cart_pole_mpc.svg` (the angle, the
//! cart and the push against time).
//!
//!   cargo run --release --example cart_pole_mpc

use std::error::Error;
use std::f64::consts::PI;

use dirac::optimal::interior::InteriorOptions;
use dirac::optimal::{Mpc, Problem};
use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// A cart pushed by `f`, carrying a pole (a point mass `mp` at length `l`) whose angle `theta`
/// is measured from hanging straight down.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(x => vx, theta => w), input(f))]
#[dirac(lagrangian = 0.5 * (mc + mp) * vx * vx + mp * l * vx * w * theta.cos() + 0.5 * mp * l * l * w * w
                   + mp * g * l * theta.cos())]
#[dirac(force(x) = f)]
pub struct CartPole {
    /// Cart mass [kg].
    pub mc: f64,
    /// Pole mass [kg].
    pub mp: f64,
    /// Pole length [m].
    pub l: f64,
    /// Gravity [m/s²].
    pub g: f64,
    /// The push on the cart [N] (input).
    pub f: f64,
}

fn main() -> Result<(), Box<dyn Error>> {
    let model = CartPole { mc: 1.0, mp: 0.3, l: 0.5, g: 9.81, f: 0.0 };
    // Upright and centred is the goal: weights on the midpoint positions and velocities of
    // each interval, heavier at the horizon's end, and a light one on the push.
    let problem = Problem::new(model.clone(), 1.0, 20)
        .position_weight(CartPole::X, 1.0, 0.0)
        .position_weight(CartPole::THETA, 20.0, PI)
        .velocity_weight(CartPole::X, 0.1, 0.0)
        .velocity_weight(CartPole::THETA, 0.1, 0.0)
        .terminal_weight(CartPole::X, 10.0, 0.0)
        .terminal_weight(CartPole::THETA, 100.0, PI)
        .input_weight(CartPole::F, 0.01)
        .position_bounds(CartPole::X, -1.5, 1.5)
        .input_bounds(CartPole::F, -20.0, 20.0);
    let mut mpc = Mpc::new(problem, InteriorOptions::default())?;

    let mut plant = model;
    let tilted = VecQ::<CartPole>::from([0.0, PI - 0.5]);
    let start = consistent_state(&plant, 0.0, &tilted, &VecQ::<CartPole>::zeros(), Consistency::default())?;
    let mut radau = Radau::new(&mut plant, RadauOptions::default())?;
    let solution = radau
        .run(0.0, &start, 4.0)
        .sampling(Sampling::Every(0.01))
        .every(0.01, |t, state, plant: &mut CartPole| mpc.apply(t, state, plant))
        .solve()?;

    let samples = mpc.samples();
    let mut times: Vec<f64> = samples.iter().map(|s| s.solve.as_secs_f64() * 1e6).collect();
    times.sort_by(f64::total_cmp);
    let quantile = |q: f64| times[((times.len() - 1) as f64 * q).round() as usize];
    let iterations = samples.iter().map(|s| s.iterations).max().unwrap_or(0);
    let failed = samples.iter().filter(|s| s.status != "Solve_Succeeded").count();
    println!(
        "{} samples at 100 Hz: solve median {:.0} µs, 90% {:.0} µs, slowest {:.0} µs; at most {iterations} \
         iterations; {failed} failed",
        samples.len(),
        quantile(0.5),
        quantile(0.9),
        quantile(1.0)
    );
    let (t, theta, x) = (solution.t(), solution.q(CartPole::THETA), solution.q(CartPole::X));
    let last = t.len() - 1;
    println!(
        "after {:.1} s: the pole {:.1e} rad from upright, the cart at {:.1e} m",
        t[last],
        theta[last] - PI,
        x[last]
    );

    let tilt: Vec<f64> = theta.iter().map(|th| th - PI).collect();
    let (mut ft, mut f) = (Vec::new(), Vec::new());
    for pair in samples.windows(2) {
        ft.extend([pair[0].t, pair[1].t]);
        f.extend([pair[0].inputs[0] / 10.0; 2]);
    }
    let path = output_dir()?.join("cart_pole_mpc.svg");
    Chart {
        title: "Cart-pole under a 100 Hz MPC (N = 20 over 1 s)",
        x_label: "time t [s]",
        y_label: "tilt [rad], cart [m], push / 10 [N]",
        series: vec![
            Series { name: "tilt theta - pi [rad]", x: t, y: &tilt },
            Series { name: "cart position x [m]", x: t, y: x },
            Series { name: "push f / 10 [N]", x: &ft, y: &f },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&path)?;
    println!("wrote {}", path.display());
    Ok(())
}
