use dirac::prelude::*;

/// Coulomb's law pushes with the friction coefficient times the contact force: a kinetic force
/// that is not linear in the rows it names is refused at that force.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(floor) = y)]
#[dirac(friction(slide, kinetic = mu * floor * floor) = vx)]
struct Block {
    m: f64,
    g: f64,
    mu: f64,
}

fn main() {}
