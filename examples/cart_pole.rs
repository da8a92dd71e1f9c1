//! Balancing a pole on a cart: linearise about upright, design a sampled LQR gain, and run the
//! nonlinear model under the 100 Hz controller from a tilted start.
//!
//! The cart (mass `mc`, position `x`) is pushed by the input force `u`; the pole is a point
//! mass `mp` at length `l`, its angle `th` measured from upright. `linearize` gives the
//! continuous-time `(A, B)` about `x = th = 0` from the generated derivatives. The controller
//! holds its output for `dt` = 10 ms, so the gain is designed for the sampled system:
//! `control::zero_order_hold` gives `(A_d, B_d)`, exact under the hold, and `control::dlqr` the
//! gain from the discrete Riccati equation (checked against python-control in
//! `tests/integration/control.rs`).
//!
//! The nonlinear cart-pole then runs under `u_k = −K x(t_k)`, restarted at every sample by
//! `solve_sampled`. Writes `target/dirac-examples/cart_pole.svg` (angle and input against time)
//! and `target/dirac-examples/cart_pole.html` (the motion, animated).

use std::error::Error;

use dirac::control;
use dirac::nalgebra::{DMatrix, DVector};
use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use dirac::plot::Animation;
use support::{Chart, Series, output_dir};

/// A cart carrying an inverted pendulum, pushed by the force `u`.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(x => vx, th => w), input(u), output(cart) = x, output(angle) = th)]
#[dirac(lagrangian = 0.5 * (mc + mp) * vx * vx + mp * l * vx * w * th.cos() + 0.5 * mp * l * l * w * w
                   - mp * g * l * th.cos())]
#[dirac(force(x) = u)]
pub struct CartPole {
    /// Cart mass [kg].
    pub mc: f64,
    /// Pole mass [kg].
    pub mp: f64,
    /// Pole length [m].
    pub l: f64,
    /// Gravity [m/s²].
    pub g: f64,
    /// The force on the cart [N], set by the controller.
    pub u: f64,
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut model = CartPole { mc: 1.0, mp: 0.3, l: 0.5, g: 9.81, u: 0.0 };
    let upright = consistent_state(
        &model,
        0.0,
        &VecQ::<CartPole>::zeros(),
        &VecQ::<CartPole>::zeros(),
        Consistency::default(),
    )?;
    let lin = linearize(&model, 0.0, &upright)?;
    println!("A about upright (state x, th, vx, w):{}B:{}", lin.a, lin.b);
    let mut eigenvalues: Vec<f64> = lin.a.complex_eigenvalues().iter().map(|z| z.re).collect();
    eigenvalues.sort_by(f64::total_cmp);
    println!("open-loop eigenvalues (real parts): {eigenvalues:.3?}: the upright pole falls");

    // The LQR design for the 100 Hz controller: sample the linear model under a held force,
    // then solve the discrete Riccati equation.
    let dt = 0.01;
    let (ad, bd) = control::zero_order_hold(&lin.a, &lin.b, dt)?;
    let q = DMatrix::from_diagonal(&DVector::from_column_slice(&[1.0, 10.0, 0.1, 0.1]));
    let r = DMatrix::from_element(1, 1, 0.1);
    let design = control::dlqr(&ad, &bd, &q, &r)?;
    let k = design.gain.clone();
    let radius = design.poles.iter().map(|z| z.norm()).fold(0.0, f64::max);
    println!("LQR gain K = {:.3} (Riccati residual {:.1e})", k.row(0), design.residual);
    println!("closed-loop spectral radius of A_d - B_d K: {radius:.4} (< 1: stable at {} Hz)", 1.0 / dt);

    let tilted = consistent_state(
        &model,
        0.0,
        &VecQ::<CartPole>::from([0.0, 0.2]),
        &VecQ::<CartPole>::zeros(),
        Consistency::default(),
    )?;
    let mut inputs: Vec<(f64, f64)> = Vec::new();
    let (positions, velocities) = (lin.positions.clone(), lin.velocities.clone());
    let mut radau = Radau::new(&mut model, RadauOptions::tolerances(1e-8, 1e-8))?;
    let solution = radau.solve_sampled(0.0, &tilted, 6.0, dt, &Sampling::Every(0.005), |t, s, cart| {
        // The linear model's state: δz = N_hᵀ δq, δw = Nᵀ δv (here the identity: no constraints).
        let z = positions.transpose() * DVector::from_column_slice(s.q.as_slice());
        let w = velocities.transpose() * DVector::from_column_slice(s.v.as_slice());
        let x = DVector::from_iterator(4, z.iter().chain(w.iter()).copied());
        let u = -(&k * x)[0];
        cart.set_input(CartPole::U, u);
        inputs.push((t, u));
    })?;
    let (t, angle, cart) = (solution.t(), solution.output(CartPole::ANGLE), solution.output(CartPole::CART));
    let last = solution.len() - 1;
    let peak = inputs.iter().map(|(_, u)| u.abs()).fold(0.0, f64::max);
    println!(
        "from th = 0.2 rad: at t = 6 s th = {:.2e} rad, cart at {:.2e} m; largest force {peak:.2} N; {} steps",
        angle[last], cart[last], solution.stats.steps
    );

    let path = output_dir()?.join("cart_pole.svg");
    let (ut, u): (Vec<f64>, Vec<f64>) = inputs.into_iter().unzip();
    let scaled: Vec<f64> = u.iter().map(|u| u / 10.0).collect();
    Chart {
        title: "Cart-pole under a 100 Hz LQR controller",
        x_label: "time t [s]",
        y_label: "angle [rad], cart [m], force / 10 [N]",
        series: vec![
            Series { name: "pole angle th [rad]", x: t, y: angle },
            Series { name: "cart position x [m]", x: t, y: cart },
            Series { name: "force u / 10 [N]", x: &ut, y: &scaled },
        ],
        log_y: false,
        log_x: false,
    }
    .write(&path)?;
    println!("wrote {}", path.display());

    // The cart and the pole's tip, (x + l sin θ, l cos θ), as an animation to play in a browser.
    let l = model.l;
    let tip_x: Vec<f64> = cart.iter().zip(angle).map(|(x, th)| x + l * th.sin()).collect();
    let tip_y: Vec<f64> = angle.iter().map(|th| l * th.cos()).collect();
    let path = output_dir()?.join("cart_pole.html");
    let animation = Animation::of(&solution, "Cart-pole under a 100 Hz LQR controller")?
        .point("cart", cart, &vec![0.0; cart.len()])?
        .point("tip", &tip_x, &tip_y)?
        .link("cart", "tip")?;
    animation.write_html(&path)?;
    println!("wrote {} (open it in a browser: it plays, loops and scrubs)", path.display());
    // The same as an image that plays by itself wherever SVG is shown.
    let path = output_dir()?.join("cart_pole_animated.svg");
    animation.write_svg(&path)?;
    println!("wrote {}", path.display());
    Ok(())
}
