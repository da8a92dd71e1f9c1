//! Derivatives of a stick-slip motion: forward sensitivities and an adjoint gradient carried
//! across a friction law's switches.
//!
//! A mass on a spring sits on a belt moving at `vb`, with stiction `μs N` and kinetic friction
//! `μk N` (the law `friction(grip, …) = v − vb`). From rest it slips, sticks where its speed
//! reaches the belt's, rides the belt until the spring's pull reaches `μs N`, and slips again:
//! at each switch the mode changes and the acceleration jumps, so a change of a parameter that
//! moves a switch moves everything after it. The jump `S = I + (f⁻ − f⁺) ∂t*/∂x` carries each
//! sensitivity across (a release's time follows from the law's force, a multiplier).
//!
//! The example prints `∂x/∂μs` in the first slip after the release against its closed form,
//! the adjoint gradient of `x(T)` with respect to every parameter against the forward
//! sensitivities of the same run, and plots `x` and `∂x/∂μs` with the switches marked.

use std::error::Error;

use dirac::State;
use dirac::adjoint::Objective;
use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// A mass on a spring to the wall, on a belt, with Coulomb friction and stiction.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(friction(grip, kinetic = mu_k * n, stiction = mu_s * n) = v - vb)]
struct Belt {
    /// Mass [kg].
    m: f64,
    /// Spring stiffness [N/m].
    k: f64,
    /// Belt speed [m/s].
    vb: f64,
    /// Normal force [N].
    n: f64,
    /// Static and kinetic friction coefficients.
    mu_s: f64,
    mu_k: f64,
}

fn main() -> Result<(), Box<dyn Error>> {
    let belt = Belt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 };
    let t_end = 6.5;
    let start = State::<Belt>::zeros();
    let options = RadauOptions::tolerances(1e-10, 1e-12);
    let wrt = Sensitivities::all_parameters(&belt);
    let solution = Radau::new(&belt, options)?.with_sensitivities(&wrt)?.solve_with_sensitivities(
        0.0,
        &start,
        t_end,
        &Sampling::Every(0.01),
    )?;
    for event in solution.events() {
        println!("{:>11} at t = {:.6} s", solution.event_name(event), event.t);
    }

    // Closed form: slipping from rest, x = x_e (1 − cos ωt) about x_e = μk N/k until v = vb at
    // t₁; stuck until k x = μs N at t₂; then x = x_e + d cos ωτ + (vb/ω) sin ωτ, τ = t − t₂.
    let exact = |b: &Belt, t: f64| {
        let w = (b.k / b.m).sqrt();
        let xe = b.mu_k * b.n / b.k;
        let t1 = (b.vb / (w * xe)).asin() / w;
        let x1 = xe * (1.0 - (w * t1).cos());
        let t2 = t1 + (b.mu_s * b.n / b.k - x1) / b.vb;
        let d = (b.mu_s - b.mu_k) * b.n / b.k;
        xe + d * (w * (t - t2)).cos() + b.vb / w * (w * (t - t2)).sin()
    };
    let release = solution.event_times("grip_slips").ok_or("no release")?[0];
    let (t, dx) = (solution.t(), solution.dq(Belt::X, "mu_s").ok_or("no sensitivity")?);
    let h = 1e-6;
    let (mut plus, mut minus) = (belt.clone(), belt.clone());
    (plus.mu_s, minus.mu_s) = (belt.mu_s + h, belt.mu_s - h);
    let worst = t
        .iter()
        .zip(dx)
        .filter(|(ti, _)| **ti > release + 0.05 && **ti < release + 2.0)
        .map(|(ti, d)| (d - (exact(&plus, *ti) - exact(&minus, *ti)) / (2.0 * h)).abs())
        .fold(0.0, f64::max);
    println!("∂x/∂μs over the first slip after the release against the closed form: worst {worst:.1e}");

    // One adjoint sweep: the gradient of G = x(T) with respect to every parameter, equal to the
    // forward sensitivities at T.
    let recording = Radau::new(&belt, options)?.record(0.0, &start, t_end)?;
    let terminal = |_: f64, y: &State<Belt>, out: &mut State<Belt>| {
        out.set_q(Belt::X, 1.0);
        y.q(Belt::X)
    };
    let gradient = recording.gradient(&belt, &Objective::terminal(&terminal))?;
    let forward = Radau::new(&belt, options)?.with_sensitivities(&wrt)?.solve_with_sensitivities(
        0.0,
        &start,
        t_end,
        &Sampling::Times(vec![t_end]),
    )?;
    println!("∂x(T)/∂θ at T = {t_end} s:      adjoint          forward");
    for (k, name) in belt.parameter_names().iter().enumerate() {
        let by_forward = forward.dq(Belt::X, name).ok_or("no sensitivity")?[0];
        println!("  {name:>5}   {:>16.12}   {by_forward:>16.12}", gradient.parameters[k]);
    }

    let switches = solution.events().iter().map(|e| e.t).collect::<Vec<_>>();
    let x = solution.q(Belt::X);
    let at_switches: Vec<f64> =
        switches.iter().map(|ts| t.iter().position(|ti| ti >= ts).map_or(0.0, |i| x[i])).collect();
    let path = output_dir()?.join("stick_slip_gradients.svg");
    Chart {
        title: "Stick-slip on a belt: the position and its derivative by the stiction coefficient",
        x_label: "time t [s]",
        y_label: "x [m], ∂x/∂μs [m]",
        series: vec![Series { name: "x", x: t, y: x }, Series { name: "∂x/∂μs", x: t, y: dx }],
        log_y: false,
        log_x: false,
    }
    .write_with_markers(&path, &[Series { name: "switch", x: &switches, y: &at_switches }])?;
    println!("wrote {}", path.display());
    Ok(())
}
