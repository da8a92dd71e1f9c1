use dirac::prelude::*;

/// An event's direction is one of falling, rising, either.
#[derive(LagrangeDirac)]
#[dirac(coordinates(y => v))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * y)]
#[dirac(event(touchdown, downwards) = y)]
struct Ball {
    m: f64,
    g: f64,
}

fn main() {}
