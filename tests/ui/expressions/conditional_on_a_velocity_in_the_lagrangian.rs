use dirac::prelude::*;

/// A mass that changes with the direction of motion: the momentum would jump at v = 0.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * (if v > 0.0 { m1 } else { m2 }) * v * v - 0.5 * k * x * x)]
struct Ratchet {
    m1: f64,
    m2: f64,
    k: f64,
}

/// The same through `abs`.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v.abs() - 0.5 * k * x * x)]
struct Cubic {
    m: f64,
    k: f64,
}

fn main() {}
