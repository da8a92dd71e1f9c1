use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy))]
#[dirac(constraint(guide) = vx - t * vy)]
struct Slider {
    m: f64,
}

fn main() {}
