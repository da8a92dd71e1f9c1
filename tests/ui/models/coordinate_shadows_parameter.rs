use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(l => v))]
#[dirac(lagrangian = 0.5 * m * v * v)]
struct Particle {
    m: f64,
    l: f64,
}

fn main() {}
