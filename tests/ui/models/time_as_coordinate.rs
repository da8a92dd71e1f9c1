use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(t => v))]
#[dirac(lagrangian = 0.5 * m * v * v)]
struct Clock {
    m: f64,
}

fn main() {}
