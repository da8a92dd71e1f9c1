use dirac::prelude::*;

/// Each of a cone's tangent quantities is a velocity: a position among them is refused where
/// it is written.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy, z => vz))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy + vz * vz) - m * g * z)]
#[dirac(holonomic(floor) = z)]
#[dirac(friction(slip, kinetic = mu * floor) = (vx, y))]
struct Puck {
    m: f64,
    g: f64,
    mu: f64,
}

fn main() {}
