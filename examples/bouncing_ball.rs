//! A bouncing ball: its floor a unilateral constraint, each touchdown an impact by the law the
//! model's own constraint gives, its apexes events.
//!
//! A ball dropped from h0 = 1 m falls under gravity onto the floor `y ≥ 0`, declared with its
//! restitution e = 0.8; at each touchdown the impact law reverses the momentum along the
//! floor's one-form and scales it by e, an impulse `m (1 + e) v`. Between touchdowns it flies
//! on parabolas, so everything has a closed form, a geometric series:
//!
//! ```text
//! touchdown n at   T_n = t1 (1 + 2 (e + e² + … + eⁿ)),   t1 = √(2 h0 / g),
//! apex n at        T_{n−1} + eⁿ t1,   height e²ⁿ h0,
//! ```
//!
//! with impulse `m (1 + e) eⁿ √(2 g h0)` at touchdown n, and the touchdowns accumulate at the
//! Zeno time `t∞ = t1 (1 + 2e / (1 − e))`, after which the ball rests on the floor. The
//! example integrates the ball's companion with contacts that can rest (`with_contacts`) past
//! t∞, prints the located times, heights and impulses against the closed form and when the
//! ball came to rest, and plots the height with the events marked.

use std::error::Error;
use std::ops::ControlFlow;

use dirac::State;
use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// A ball moving vertically under gravity above a floor.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(y => v))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * y)]
#[dirac(unilateral(floor, restitution = e) = y)]
struct Ball {
    /// Mass [kg].
    m: f64,
    /// Gravity [m/s²].
    g: f64,
    /// Coefficient of restitution of the floor.
    e: f64,
}

fn main() -> Result<(), Box<dyn Error>> {
    let (h0, e) = (1.0, 0.8);
    let ball = Ball { m: 0.1, g: 9.81, e };
    let t1 = (2.0 * h0 / ball.g).sqrt();
    let zeno = t1 * (1.0 + 2.0 * e / (1.0 - e));
    let mut start = State::<BallWithContacts>::zeros();
    start.set_q(BallWithContacts::Y, h0);

    // The floor's impacts, and the apexes (the velocity falling through zero while the ball
    // is off the floor).
    let mut model = ball.with_contacts();
    let apex = |_, s: &State<BallWithContacts>, m: &BallWithContacts| {
        if m.contact_closed(0) { 1.0 } else { s.v(BallWithContacts::Y) }
    };
    let mut events = Events::new().contacts(&model).on("apex", Crossing::Falling, apex);
    let mut radau = Radau::new(&mut model, RadauOptions::tolerances(1e-12, 1e-12))?;
    let t_end = 1.2 * zeno;
    let solution =
        radau.solve_with_events(0.0, &start, t_end, &Sampling::Every(0.005), &mut events, |_, _| {
            ControlFlow::Continue(())
        })?;

    let touchdown_at = |n: i32| t1 * (1.0 + 2.0 * (1..=n).map(|k| e.powi(k)).sum::<f64>());
    let touchdowns = solution.event_times("floor").ok_or("no floor contact")?;
    let apexes = solution.event_times("apex").ok_or("no apex event")?;
    println!(
        "{} touchdowns and {} apexes up to t = {t_end:.4} s (Zeno time {zeno:.4} s)",
        touchdowns.len(),
        apexes.len()
    );
    // The first ten bounces against the closed form (later ones are too small to compare
    // relatively: their heights approach round-off).
    const FIRST: usize = 10;
    let worst_time = touchdowns
        .iter()
        .take(FIRST)
        .enumerate()
        .map(|(n, t)| ((t - touchdown_at(n as i32)) / touchdown_at(n as i32)).abs())
        .fold(0.0, f64::max);
    println!("first {FIRST} touchdown times against the closed form: worst relative error {worst_time:.1e}");
    // The samples the solution records at its events: the apex heights.
    let (t, y) = (solution.t(), solution.q(BallWithContacts::Y));
    let at_events = |times: &[f64]| -> Vec<f64> {
        times.iter().filter_map(|te| t.iter().position(|ts| ts == te).map(|i| y[i])).collect()
    };
    let heights = at_events(&apexes);
    let worst_height = heights
        .iter()
        .take(FIRST)
        .enumerate()
        .map(|(n, h)| ((h - e.powi(2 * (n as i32 + 1)) * h0) / (e.powi(2 * (n as i32 + 1)) * h0)).abs())
        .fold(0.0, f64::max);
    println!("first {FIRST} apex heights against e^(2n) h0: worst relative error {worst_height:.1e}");
    let impacts = solution.impacts_at("floor").ok_or("no floor contact")?;
    let first = ball.m * (1.0 + e) * (2.0 * ball.g * h0).sqrt();
    let worst_impulse = impacts
        .iter()
        .take(FIRST)
        .enumerate()
        .map(|(n, i)| ((i.impulse - first * e.powi(n as i32)) / (first * e.powi(n as i32))).abs())
        .fold(0.0, f64::max);
    println!(
        "first {FIRST} impulses against m (1 + e) e^n √(2 g h0): worst relative error {worst_impulse:.1e}"
    );
    // From the Zeno time on, the floor holds the ball: its row's multiplier is the force.
    let force = solution.lambda(BallWithContacts::FLOOR_FORCE);
    let rest = t.iter().zip(force).position(|(_, f)| *f > 1e-6).ok_or("the ball never came to rest")?;
    println!(
        "at rest on the floor from t = {:.9} s (t∞ = {zeno:.9} s), the floor carrying {:.12} N (m g = {:.12} N)",
        t[rest],
        force.last().ok_or("no samples")?,
        ball.m * ball.g
    );
    for (n, (ta, h)) in apexes.iter().zip(&heights).take(4).enumerate() {
        println!("  apex {}: t = {ta:.6} s, height {h:.6} m", n + 1);
    }
    println!("{:?}", solution.stats);

    let floor = at_events(&touchdowns);
    let path = output_dir()?.join("bouncing_ball.svg");
    Chart {
        title: "A ball bouncing with restitution 0.8 comes to rest at its Zeno time",
        x_label: "time t [s]",
        y_label: "height y [m]",
        series: vec![Series { name: "height", x: t, y }],
        log_y: false,
        log_x: false,
    }
    .write_with_markers(
        &path,
        &[
            Series { name: "touchdown", x: &touchdowns, y: &floor },
            Series { name: "apex", x: &apexes, y: &heights },
        ],
    )?;
    println!("wrote {}", path.display());
    Ok(())
}
