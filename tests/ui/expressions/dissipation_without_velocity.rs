use dirac::prelude::*;

/// A Rayleigh function of the position only: its forces −∂R/∂v would vanish.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(dissipation = 0.5 * c * x * x)]
struct Damped {
    m: f64,
    k: f64,
    c: f64,
}

fn main() {}
