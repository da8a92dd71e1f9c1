//! Swinging a pole up on a cart by optimal control: the push that brings the pole from hanging
//! at rest to upright at rest in 2 s, with the cart on a ±1.5 m track and the push within
//! ±20 N, at the least `∫ f²/2 dt`.
//!
//! `optimal::Problem` states it; `optimal::Dmoc` transcribes it with the variational
//! integrator's discrete Lagrangian (DMOC) on 50 intervals, its Jacobian and Hessian from the
//! derive's blocks; IPOPT solves it (feature `ipopt`; its library is Debian's
//! `coinor-libipopt-dev`). The optimum is then replayed by `Variational` with the same step and
//! the pushes it found, which lands on the same nodes. Writes
//! `target/dirac-examples/cart_pole_swing_up.svg` (positions and push against time) and
//! `cart_pole_swing_up.html` (the motion, animated).
//!
//!   cargo run --release --features ipopt --example cart_pole_swing_up

use std::error::Error;
use std::f64::consts::PI;

use dirac::optimal::ipopt::IpoptOptions;
use dirac::optimal::{Dmoc, Problem};
use dirac::plot::Animation;
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
    let (horizon, intervals) = (2.0, 50);
    let problem = Problem::new(model.clone(), horizon, intervals)
        .final_state(VecQ::<CartPole>::from([0.0, PI]), VecQ::<CartPole>::zeros())
        .position_bounds(CartPole::X, -1.5, 1.5)
        .input_bounds(CartPole::F, -20.0, 20.0);
    let optimum = Dmoc::new(problem)?.solve(&IpoptOptions::default())?;
    println!(
        "swing-up: cost {:.6} in {} IPOPT iterations, {:.1} ms ({:.1} ms evaluating the equations and their \
         derivatives); discrete equations met to {:.1e}",
        optimum.cost,
        optimum.iterations,
        optimum.wall.as_secs_f64() * 1e3,
        optimum.evaluation.as_secs_f64() * 1e3,
        optimum.violation
    );

    // The variational integrator with the same step and the pushes held over each interval.
    let h = horizon / intervals as f64;
    let mut replayed = model.clone();
    let start = consistent_state(
        &replayed,
        0.0,
        &VecQ::<CartPole>::zeros(),
        &VecQ::<CartPole>::zeros(),
        Consistency::default(),
    )?;
    let mut vi = Variational::new(&mut replayed, h, VariationalOptions::default())?;
    vi.start(0.0, &start, horizon)?;
    let mut gap = 0.0f64;
    for (k, u) in optimum.inputs.iter().enumerate() {
        vi.set_input(CartPole::F, u[0])?;
        vi.step()?;
        let node = &optimum.positions[k + 1];
        gap = gap.max((vi.state().q[0] - node[0]).abs()).max((vi.state().q[1] - node[1]).abs());
    }
    println!("replayed by the variational integrator: within {gap:.1e} of the optimal nodes");

    let t = &optimum.times;
    let x: Vec<f64> = optimum.positions.iter().map(|q| q[0]).collect();
    let theta: Vec<f64> = optimum.positions.iter().map(|q| q[1]).collect();
    // The push, held over each interval: drawn as steps.
    let (mut ft, mut f) = (Vec::new(), Vec::new());
    for (k, u) in optimum.inputs.iter().enumerate() {
        ft.extend([t[k], t[k + 1]]);
        f.extend([u[0] / 10.0, u[0] / 10.0]);
    }
    let path = output_dir()?.join("cart_pole_swing_up.svg");
    Chart {
        title: "Cart-pole swing-up by DMOC (N = 50)",
        x_label: "time t [s]",
        y_label: "angle [rad], cart [m], push / 10 [N]",
        series: vec![
            Series { name: "pole angle theta [rad]", x: t, y: &theta },
            Series { name: "cart position x [m]", x: t, y: &x },
            Series { name: "push f / 10 [N]", x: &ft, y: &f },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&path)?;
    println!("wrote {}", path.display());

    let l = model.l;
    let tip_x: Vec<f64> = x.iter().zip(&theta).map(|(x, th)| x + l * th.sin()).collect();
    let tip_y: Vec<f64> = theta.iter().map(|th| -l * th.cos()).collect();
    let path = output_dir()?.join("cart_pole_swing_up.html");
    let animation = Animation::new("Cart-pole swing-up by DMOC", t)?
        .point("cart", &x, &vec![0.0; x.len()])?
        .point("tip", &tip_x, &tip_y)?
        .link("cart", "tip")?;
    animation.write_html(&path)?;
    println!("wrote {} (open it in a browser: it plays, loops and scrubs)", path.display());
    Ok(())
}
