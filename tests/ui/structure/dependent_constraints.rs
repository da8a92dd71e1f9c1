use dirac::prelude::*;

/// Two constraints on one velocity: the second multiplier is determined by no equation.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v)]
#[dirac(constraint(stop) = v, constraint(stop_again) = 2.0 * v)]
struct Overconstrained {
    m: f64,
}

fn main() {}
