use dirac::prelude::*;

/// A unilateral constraint takes one option, its restitution.
#[derive(LagrangeDirac)]
#[dirac(coordinates(y => v))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * y)]
#[dirac(unilateral(floor, bounce = e) = y)]
struct Ball {
    m: f64,
    g: f64,
    e: f64,
}

fn main() {}
