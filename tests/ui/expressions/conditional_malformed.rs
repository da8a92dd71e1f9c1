use dirac::prelude::*;

/// A condition that is not a comparison, and a conditional without `else`.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v)]
#[dirac(force(x) = if x > 0.0 && v > 0.0 { -k * x } else { 0.0 } + if x < 1.0 { 1.0 })]
struct Malformed {
    m: f64,
    k: f64,
}

fn main() {}
