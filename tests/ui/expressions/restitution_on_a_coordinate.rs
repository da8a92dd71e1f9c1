use dirac::prelude::*;

/// A restitution that changes with the position: it must be a constant or a parameter.
#[derive(LagrangeDirac)]
#[dirac(coordinates(y => v))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * y)]
#[dirac(unilateral(floor, restitution = 0.5 + 0.1 * y) = y)]
struct Ball {
    m: f64,
    g: f64,
}

fn main() {}
