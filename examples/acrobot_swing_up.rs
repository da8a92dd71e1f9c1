//! Swinging an acrobot up by its elbow alone: two links on a fixed pivot, a torque only between
//! them, from hanging at rest to balanced upright at rest in 3 s at the least `∫ τ²/2 dt`.
//!
//! The shoulder has no motor, so the elbow must pump energy into the whole chain through the
//! coupling of the two links. `optimal::Dmoc` transcribes the problem with the variational
//! integrator's discrete Lagrangian on 60 intervals, and dirac's own interior point solves it
//! (no feature needed): a nonconvex program whose steps need the inertia correction. The
//! optimum is then replayed by `Variational` with the same step and the torques found.
//! Writes `target/dirac-examples/acrobot_swing_up.svg` (angles and torque against time) and
//! `acrobot_swing_up.html` (the motion, animated).
//!
//!   cargo run --release --example acrobot_swing_up

use std::error::Error;
use std::f64::consts::PI;

use dirac::optimal::interior::InteriorOptions;
use dirac::optimal::{Dmoc, Problem};
use dirac::plot::Animation;
use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// Two equal point-mass links `l` long on a fixed pivot; `th1` and `th2` are their absolute
/// angles from hanging straight down, and the torque `tau` acts between them.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(th1 => w1, th2 => w2), input(tau))]
#[dirac(lagrangian = m * l * l * w1 * w1 + 0.5 * m * l * l * w2 * w2 + m * l * l * w1 * w2 * cos(th1 - th2)
    + 2.0 * m * g * l * cos(th1) + m * g * l * cos(th2))]
#[dirac(force(th1) = -tau, force(th2) = tau)]
pub struct Acrobot {
    /// Mass at the end of each link [kg].
    pub m: f64,
    /// Length of each link [m].
    pub l: f64,
    /// Gravity [m/s²].
    pub g: f64,
    /// The elbow's torque [N m] (input).
    pub tau: f64,
}

fn main() -> Result<(), Box<dyn Error>> {
    let model = Acrobot { m: 1.0, l: 1.0, g: 9.81, tau: 0.0 };
    let (horizon, intervals) = (3.0, 60);
    let upright = VecQ::<Acrobot>::from([PI, PI]);
    let problem =
        Problem::new(model.clone(), horizon, intervals).final_state(upright, VecQ::<Acrobot>::zeros());
    let optimum = Dmoc::new(problem)?.solve_interior(&InteriorOptions::default())?;
    println!(
        "acrobot swing-up: cost {:.6} in {} interior-point iterations, {:.1} ms ({:.1} ms evaluating the \
         equations and their derivatives); discrete equations met to {:.1e}",
        optimum.cost,
        optimum.iterations,
        optimum.wall.as_secs_f64() * 1e3,
        optimum.evaluation.as_secs_f64() * 1e3,
        optimum.violation
    );
    let peak = optimum.inputs.iter().fold(0.0f64, |m, u| m.max(u[0].abs()));
    println!("largest elbow torque {peak:.2} N m");

    // The variational integrator with the same step and the torques held over each interval.
    let h = horizon / intervals as f64;
    let mut replayed = model.clone();
    let rest = VecQ::<Acrobot>::zeros();
    let start = consistent_state(&replayed, 0.0, &rest, &rest, Consistency::default())?;
    let mut vi = Variational::new(&mut replayed, h, VariationalOptions::default())?;
    vi.start(0.0, &start, horizon)?;
    let mut gap = 0.0f64;
    for (k, u) in optimum.inputs.iter().enumerate() {
        vi.set_input(Acrobot::TAU, u[0])?;
        vi.step()?;
        for (x, node) in vi.state().q.iter().zip(&optimum.positions[k + 1]) {
            gap = gap.max((x - node).abs());
        }
    }
    println!("replayed by the variational integrator: within {gap:.1e} of the optimal nodes");

    let t = &optimum.times;
    let th1: Vec<f64> = optimum.positions.iter().map(|q| q[0]).collect();
    let th2: Vec<f64> = optimum.positions.iter().map(|q| q[1]).collect();
    let (mut tt, mut tau) = (Vec::new(), Vec::new());
    for (k, u) in optimum.inputs.iter().enumerate() {
        tt.extend([t[k], t[k + 1]]);
        tau.extend([u[0] / 10.0, u[0] / 10.0]);
    }
    let path = output_dir()?.join("acrobot_swing_up.svg");
    Chart {
        title: "Acrobot swing-up by DMOC (N = 60), the elbow's torque alone",
        x_label: "time t [s]",
        y_label: "angle [rad], torque / 10 [N m]",
        series: vec![
            Series { name: "upper link th1 [rad]", x: t, y: &th1 },
            Series { name: "lower link th2 [rad]", x: t, y: &th2 },
            Series { name: "elbow torque / 10 [N m]", x: &tt, y: &tau },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&path)?;
    println!("wrote {}", path.display());

    let l = model.l;
    let elbow_x: Vec<f64> = th1.iter().map(|a| l * a.sin()).collect();
    let elbow_y: Vec<f64> = th1.iter().map(|a| -l * a.cos()).collect();
    let tip_x: Vec<f64> = elbow_x.iter().zip(&th2).map(|(x, b)| x + l * b.sin()).collect();
    let tip_y: Vec<f64> = elbow_y.iter().zip(&th2).map(|(y, b)| y - l * b.cos()).collect();
    let path = output_dir()?.join("acrobot_swing_up.html");
    Animation::new("Acrobot swing-up by DMOC", t)?
        .fixed("pivot", 0.0, 0.0)
        .point("elbow", &elbow_x, &elbow_y)?
        .point("tip", &tip_x, &tip_y)?
        .link("pivot", "elbow")?
        .link("elbow", "tip")?
        .write_html(&path)?;
    println!("wrote {}", path.display());
    Ok(())
}
