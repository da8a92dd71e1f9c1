use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x1 => v1, x2 => v2), port(x3))]
#[dirac(lagrangian = 0.5 * m * (v1 * v1 + v2 * v2))]
struct Pair {
    m: f64,
}

fn main() {}
