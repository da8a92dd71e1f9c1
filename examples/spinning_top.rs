//! A spinning top on the floor, its tip under Coulomb's friction cone.
//!
//! A top of 0.5 kg spins at 200 rad/s on its point tip, tilted 0.3 rad, its centre thrown
//! sideways at 0.3 m/s: the tip slides, friction (`μ` = 0.3 times the floor's force, against the
//! slip's direction, which turns as the tip moves) drags it to a hold, and from there the top
//! precesses and nods about its tip as the Lagrange top does. The friction cone is one line,
//! `friction(tip, kinetic = mu * floor) = (vtx, vty)` on the tip's velocity in the floor.
//!
//! Prints what the physics fixes: the spin about the axis (friction at the tip has no moment
//! about it), the energy less the friction's work, and, once the tip holds, the tilt's range
//! against the turning points of the Lagrange top with the integrals it holds with; plots the
//! tip's and the centre's paths on the floor.
//!
//! ```sh
//! cargo run --release --example spinning_top
//! ```

use std::error::Error;

use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// A symmetric top: centre of mass `(x, y, z)`, ZXZ Euler angles (`psi` precession, `theta`
/// tilt, `phi` spin), its point tip at `l` below the centre along the axis, held on the floor
/// by the row `floor`; moments `a` across the axis and `c` about it, at the centre.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy, z => vz, psi => wpsi, theta => wtheta, phi => wphi))]
#[dirac(
    lagrangian = 0.5 * m * (vx * vx + vy * vy + vz * vz)
        + 0.5 * a * (wtheta * wtheta + wpsi * wpsi * sin(theta) * sin(theta))
        + 0.5 * c * (wphi + wpsi * cos(theta)) * (wphi + wpsi * cos(theta))
        - m * g * z
)]
#[dirac(holonomic(floor) = z - l * cos(theta))]
#[dirac(define(vtx) = vx - l * (cos(theta) * wtheta * sin(psi) + sin(theta) * cos(psi) * wpsi))]
#[dirac(define(vty) = vy + l * (cos(theta) * wtheta * cos(psi) - sin(theta) * sin(psi) * wpsi))]
#[dirac(friction(tip, kinetic = mu * floor) = (vtx, vty))]
#[dirac(nonnegative(mu))]
struct Top {
    /// Mass [kg].
    m: f64,
    /// Gravity [m/s²].
    g: f64,
    /// The tip's distance below the centre [m].
    l: f64,
    /// Moment of inertia across the axis, at the centre [kg m²].
    a: f64,
    /// Moment of inertia about the axis [kg m²].
    c: f64,
    /// Friction coefficient.
    mu: f64,
}

fn main() -> Result<(), Box<dyn Error>> {
    let top = Top { m: 0.5, g: 9.81, l: 0.04, a: 1.5e-4, c: 2e-4, mu: 0.3 };
    let theta0 = 0.3f64;
    let (mut q, mut v) = (VecQ::<Top>::zeros(), VecQ::<Top>::zeros());
    q[Top::THETA.index()] = theta0;
    q[Top::Z.index()] = top.l * theta0.cos();
    (v[Top::X.index()], v[Top::PHI.index()]) = (0.3, 200.0);
    let start = consistent_state(&top, 0.0, &q, &v, Consistency::default())?;
    let solution = Radau::new(&top, RadauOptions::tolerances(1e-11, 1e-11))?.solve(
        0.0,
        &start,
        1.0,
        &Sampling::Every(1e-4),
    )?;
    let t = solution.t();
    let (x, y) = (solution.q(Top::X), solution.q(Top::Y));
    let (psi, theta) = (solution.q(Top::PSI), solution.q(Top::THETA));
    let (w_psi, w_theta, w_phi) = (solution.v(Top::PSI), solution.v(Top::THETA), solution.v(Top::PHI));
    let holds = *solution.event_times("tip_stops").ok_or("no law")?.last().ok_or("the tip never holds")?;
    println!("the tip slides until t = {holds:.9} s and holds from there");

    let spin: Vec<f64> = (0..t.len()).map(|k| w_phi[k] + w_psi[k] * theta[k].cos()).collect();
    let drift = spin.iter().map(|w| (w - spin[0]).abs()).fold(0.0, f64::max);
    println!("spin about the axis {:.6} rad/s, drifting by {drift:.1e}", spin[0]);
    let (energy, power) = (solution.energy(), solution.constraint_power());
    let (mut work, mut balance) = (0.0, 0.0f64);
    for k in 1..t.len() {
        work += 0.5 * (power[k] + power[k - 1]) * (t[k] - t[k - 1]);
        balance = balance.max((energy[k] - energy[0] - work).abs());
    }
    println!(
        "friction took {:.9} J of {:.9} J; energy less that work off by at most {balance:.1e} J",
        -work, energy[0]
    );

    // Held, the Lagrange top about its tip: `u = cos θ` moves between the roots in [−1, 1] of
    // `(1 − u²)(α − β u) − (b − a' u)²`, from its energy and momenta there.
    let k0 = t.iter().position(|&s| s > holds).ok_or("no sample after the hold")?;
    let i1 = top.a + top.m * top.l * top.l;
    let lz = i1 * w_psi[k0] * theta[k0].sin().powi(2) + top.c * spin[k0] * theta[k0].cos();
    let e = 0.5 * i1 * (w_theta[k0].powi(2) + (w_psi[k0] * theta[k0].sin()).powi(2))
        + top.m * top.g * top.l * theta[k0].cos();
    let (alpha, beta) = (2.0 * e / i1, 2.0 * top.m * top.g * top.l / i1);
    let (b, a) = (lz / i1, top.c * spin[k0] / i1);
    let f = |u: f64| (1.0 - u * u) * (alpha - beta * u) - (b - a * u).powi(2);
    let turns = roots(&f);
    let low = theta[k0..].iter().copied().fold(f64::INFINITY, f64::min);
    let high = theta[k0..].iter().copied().fold(f64::NEG_INFINITY, f64::max);
    println!("held, the tilt nods in [{low:.9}, {high:.9}] rad");
    let turns: Vec<String> = turns.iter().map(|u| format!("{:.9}", u.acos())).collect();
    println!("the Lagrange top's turning points: {} rad", turns.join(", "));

    let tip_x: Vec<f64> = (0..t.len()).map(|k| x[k] - top.l * theta[k].sin() * psi[k].sin()).collect();
    let tip_y: Vec<f64> = (0..t.len()).map(|k| y[k] + top.l * theta[k].sin() * psi[k].cos()).collect();
    let path = output_dir()?.join("spinning_top.svg");
    Chart {
        title: "A top's tip slides until friction holds it; its centre then circles about it",
        x_label: "x [m]",
        y_label: "y [m]",
        series: vec![Series { name: "tip", x: &tip_x, y: &tip_y }, Series { name: "centre", x, y }],
        log_y: false,
        log_x: false,
    }
    .write_with_markers(&path, &[Series { name: "the tip holds", x: &[tip_x[k0]], y: &[tip_y[k0]] }])?;
    println!("wrote {}", path.display());
    Ok(())
}

/// The roots of `f` in `[−1, 1]`: its sign changes over 10⁵ pieces, bisected.
fn roots(f: &dyn Fn(f64) -> f64) -> Vec<f64> {
    let n = 100_000;
    let at = |i: usize| -1.0 + 2.0 * i as f64 / n as f64;
    let mut out = Vec::new();
    for i in 0..n {
        let (mut lo, mut hi) = (at(i), at(i + 1));
        if f(lo) * f(hi) >= 0.0 {
            continue;
        }
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if f(lo) * f(mid) <= 0.0 { hi = mid } else { lo = mid }
        }
        out.push(0.5 * (lo + hi));
    }
    out
}
