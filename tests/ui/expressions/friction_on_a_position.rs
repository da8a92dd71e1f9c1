use dirac::prelude::*;

/// Friction acts on a relative velocity: its row holds `g = 0` on the velocities while stuck.
/// A law on a position is refused at the law's quantity.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(friction(grip, kinetic = mu * n) = x - x0)]
struct Slider {
    m: f64,
    k: f64,
    mu: f64,
    n: f64,
    x0: f64,
}

fn main() {}
