use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy))]
#[dirac(constraint(speed) = vx * vx + vy * vy - 1.0)]
struct Walker {
    m: f64,
}

fn main() {}
