use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v)]
#[dirac(lagrangian = 0.5 * m * v * v - x)]
struct Particle {
    m: f64,
}

fn main() {}
