use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy))]
#[dirac(force(x, y) = -c * vx)]
struct Particle {
    m: f64,
    c: f64,
}

fn main() {}
