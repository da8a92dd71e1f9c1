use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = if x > 0.0 { 0.5 * m * v * v } else { 0.0 })]
struct Particle {
    m: f64,
}

fn main() {}
