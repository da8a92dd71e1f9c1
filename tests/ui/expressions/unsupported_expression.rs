use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = match x { _ => 0.5 * m * v * v })]
struct Particle {
    m: f64,
}

fn main() {}
