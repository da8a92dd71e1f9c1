// Two units for one coordinate.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx), unit(x) = "m", unit(x, vx) = "mm")]
#[dirac(lagrangian = 0.5 * m * vx * vx)]
struct Mass {
    m: f64,
}

fn main() {}
