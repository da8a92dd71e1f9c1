//! A particle bouncing in a box, over 10⁵ elastic impacts: the variational integrator keeps
//! its energy error bounded across impacts, Radau's drifts.
//!
//! The particle moves in the anharmonic well `V = ½ k (x² + y²) + c x² y²` (its coupling makes
//! the motion irregular) inside the box `|x|, |y| ≤ a`, whose walls reverse the normal
//! velocity: an elastic impact, which keeps the energy exactly. So the energy at the start is
//! the reference for every later time, and the error `E(t) − E(0)` is the integrator's alone.
//!
//! The variational integrator locates each impact on its own discrete flow (a step of the
//! method to the impact time) and carries on after it on its grid, so the map across an
//! impact is as symmetric in time as the method: its energy error oscillates at the size of
//! the smooth motion's (second order in the step) and does not grow. Radau locates impacts
//! just as exactly, but its error per step, small as it is, has a sign: it adds up.
//!
//! Writes `energy_error_in_a_box.svg`: `|E(t) − E(0)|` for both, on a log scale.

use std::error::Error;
use std::ops::ControlFlow;
use std::time::Instant;

use dirac::EventContext;
use dirac::State;
use dirac::prelude::*;

#[path = "support/mod.rs"]
mod support;

use support::{Chart, Series, output_dir};

/// A particle of mass `m` in the well `V = ½ k (x² + y²) + c x² y²`.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - 0.5 * k * (x * x + y * y) - c * x * x * y * y)]
struct Well {
    /// Mass [kg].
    m: f64,
    /// Stiffness of the well [N/m].
    k: f64,
    /// Coupling [N/m³].
    c: f64,
}

/// Half the box's width [m].
const A: f64 = 0.5;
/// How long to integrate [s]: some 10⁵ impacts.
const T_END: f64 = 60_000.0;

/// The four walls, each an event when the particle reaches it.
fn walls() -> Events<'static, Well> {
    Events::new()
        .on("left", Crossing::Falling, |_, s: &State<Well>, _| s.q(Well::X) + A)
        .on("right", Crossing::Falling, |_, s: &State<Well>, _| A - s.q(Well::X))
        .on("bottom", Crossing::Falling, |_, s: &State<Well>, _| s.q(Well::Y) + A)
        .on("top", Crossing::Falling, |_, s: &State<Well>, _| A - s.q(Well::Y))
}

/// The elastic impact: the velocity normal to the wall reversed.
fn reflect<I: Integrator<Well>>(event: &Event, at: &mut EventContext<'_, Well, I>) -> ControlFlow<()> {
    let key = if event.index < 2 { Well::X } else { Well::Y };
    let s = at.state_mut();
    let (v, p) = (s.v(key), s.p(key));
    s.set_v(key, -v).set_p(key, -p);
    ControlFlow::Continue(())
}

/// The number of impacts and `|E(t) − E(0)|` of a solution, with its largest value over the
/// first and the last tenth of the run.
fn summary<S>(name: &str, solution: &Solution<Well, S>, seconds: f64) -> Vec<f64> {
    let impacts: usize = ["left", "right", "bottom", "top"]
        .iter()
        .filter_map(|w| solution.event_times(w))
        .map(|t| t.len())
        .sum();
    let energy = solution.energy();
    let error: Vec<f64> = energy.iter().map(|e| (e - energy[0]).abs()).collect();
    let tenth = error.len() / 10;
    let largest = |part: &[f64]| part.iter().copied().fold(0.0, f64::max);
    println!(
        "{name:<28} {impacts:>7} impacts in {seconds:.2} s; |E − E0| at most {:.1e} in the first tenth, {:.1e} in the last",
        largest(&error[..tenth]),
        largest(&error[error.len() - tenth..]),
    );
    error
}

fn main() -> Result<(), Box<dyn Error>> {
    let model = Well { m: 1.0, k: 1.0, c: 2.0 };
    let mut start = State::<Well>::zeros();
    start.set_q(Well::X, 0.2).set_q(Well::Y, -0.1);
    start.set_v(Well::X, 1.1).set_v(Well::Y, 0.7).set_p(Well::X, 1.1).set_p(Well::Y, 0.7);
    let sampling = Sampling::Every(10.0);

    let clock = Instant::now();
    let mut variational = Variational::new(&model, 0.01, VariationalOptions::default())?;
    let by_variational =
        variational.solve_with_events(0.0, &start, T_END, &sampling, &mut walls(), reflect)?;
    let variational_error = summary("variational, h = 0.01", &by_variational, clock.elapsed().as_secs_f64());

    let mut radau_runs = Vec::new();
    for tolerance in [1e-6, 1e-9] {
        let clock = Instant::now();
        let options =
            RadauOptions { max_steps: 10_000_000, ..RadauOptions::tolerances(tolerance, tolerance) };
        let mut radau = Radau::new(&model, options)?;
        let solution = radau.solve_with_events(0.0, &start, T_END, &sampling, &mut walls(), reflect)?;
        let name = format!("Radau, tolerance {tolerance:.0e}");
        let error = summary(&name, &solution, clock.elapsed().as_secs_f64());
        radau_runs.push((name, solution, error));
    }

    // A log scale cannot show the zeros (at the start, and wherever an error passes through
    // zero): plot a floor instead.
    let floored = |error: &[f64]| -> Vec<f64> { error.iter().map(|e| e.max(1e-9)).collect() };
    let variational_error = floored(&variational_error);
    let radau_errors: Vec<Vec<f64>> = radau_runs.iter().map(|(_, _, error)| floored(error)).collect();
    let mut series =
        vec![Series { name: "variational, h = 0.01", x: by_variational.t(), y: &variational_error }];
    for ((name, solution, _), error) in radau_runs.iter().zip(&radau_errors) {
        series.push(Series { name, x: solution.t(), y: error });
    }
    let path = output_dir()?.join("energy_error_in_a_box.svg");
    Chart {
        title: "A particle bouncing in a box: energy error over 10⁵ elastic impacts",
        x_label: "time t [s]",
        y_label: "|E(t) − E(0)| [J]",
        series,
        log_y: true,
        log_x: false,
    }
    .write(&path)?;
    println!("wrote {}", path.display());
    Ok(())
}
