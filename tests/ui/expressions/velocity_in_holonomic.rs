use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(rod) = x * vx + y * vy)]
struct Pendulum {
    m: f64,
    g: f64,
}

fn main() {}
