use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx))]
#[dirac(lagrangian = 0.5 * m * vx * vx)]
#[dirac(holonomic(clock) = t - 1.0)]
struct Clock {
    m: f64,
}

fn main() {}
