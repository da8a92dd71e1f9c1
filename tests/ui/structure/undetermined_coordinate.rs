use dirac::prelude::*;

/// `free` has no kinetic energy, no potential and no constraint: nothing determines it.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, free => v_free))]
#[dirac(lagrangian = 0.5 * m * vx * vx - 0.5 * k * x * x)]
struct Undetermined {
    m: f64,
    k: f64,
}

fn main() {}
