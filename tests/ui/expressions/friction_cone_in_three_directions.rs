use dirac::prelude::*;

/// A friction cone slips in the plane of its two tangent velocities: three are refused at the
/// tuple.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy, z => vz))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy + vz * vz) - m * g * z)]
#[dirac(holonomic(floor) = z)]
#[dirac(friction(slip, kinetic = mu * floor) = (vx, vy, vz))]
struct Puck {
    m: f64,
    g: f64,
    mu: f64,
}

fn main() {}
