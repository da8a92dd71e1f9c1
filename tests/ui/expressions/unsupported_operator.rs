use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - k * (x % 2.0))]
struct Particle {
    m: f64,
    k: f64,
}

fn main() {}
