use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x1 => v1))]
#[dirac(lagrangian = 0.5 * m * v1 * v1)]
#[dirac(force(x2) = -c * v1)]
struct Particle {
    m: f64,
    c: f64,
}

fn main() {}
