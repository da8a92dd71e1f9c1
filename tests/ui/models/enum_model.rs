use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * v * v)]
enum Particle {
    Heavy,
}

fn main() {}
