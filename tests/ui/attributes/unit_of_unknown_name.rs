// A unit for a name the model does not have: the misspelt velocity `vz`.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx), unit(x) = "m", unit(vz) = "m/s")]
#[dirac(lagrangian = 0.5 * m * vx * vx)]
struct Mass {
    m: f64,
}

fn main() {}
