use dirac::prelude::*;

/// Coulomb's force opposes the slip: a friction coefficient that is never positive would push
/// along it, and is refused at the kinetic force.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy, z => vz))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy + vz * vz) - m * g * z)]
#[dirac(holonomic(floor) = z)]
#[dirac(friction(slip, kinetic = -0.3 * floor) = (vx, vy))]
struct Puck {
    m: f64,
    g: f64,
}

fn main() {}
