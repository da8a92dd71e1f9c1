use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, x => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy))]
struct Particle {
    m: f64,
}

fn main() {}
