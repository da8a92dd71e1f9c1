use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates())]
#[dirac(lagrangian = 0.5 * m)]
struct Particle {
    m: f64,
}

fn main() {}
