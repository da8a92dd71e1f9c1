use dirac::prelude::*;

/// A constant of the surrounding code that is not an `f64`.
const N: i32 = 3;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * v * v - N * x * x)]
struct Spring {}

fn main() {}
