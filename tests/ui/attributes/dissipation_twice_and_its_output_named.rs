use dirac::prelude::*;

/// Two Rayleigh functions, and an output under the name the dissipation's power is recorded.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(dissipation = 0.5 * c * v * v, dissipation = 0.5 * c * v * v * v * v)]
#[dirac(output(dissipated_power) = c * v * v)]
struct Twice {
    m: f64,
    k: f64,
    c: f64,
}

fn main() {}
