use dirac::prelude::*;

/// A contact whose gap depends on a velocity: unilateral constraints are on positions.
#[derive(LagrangeDirac)]
#[dirac(coordinates(y => v))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * y)]
#[dirac(unilateral(floor) = y + 0.1 * v)]
struct Ball {
    m: f64,
    g: f64,
}

fn main() {}
