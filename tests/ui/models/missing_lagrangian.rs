use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
struct Particle {
    m: f64,
}

fn main() {}
