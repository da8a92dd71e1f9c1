use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - k * x.floor())]
struct Particle {
    m: f64,
    k: f64,
}

fn main() {}
