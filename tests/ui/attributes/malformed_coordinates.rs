use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => ))]
#[dirac(lagrangian = 0.5 * m * v * v)]
struct Particle {
    m: f64,
}

fn main() {}
