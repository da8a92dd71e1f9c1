use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy))]
#[dirac(constraint(drift) = x - r * y.cos())]
struct Drifter {
    m: f64,
    r: f64,
}

fn main() {}
