use dirac::prelude::*;

/// A block on the floor, whose friction pushes with its contact force.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy), port(x))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(floor) = y)]
#[dirac(friction(slide, kinetic = mu * floor) = vx)]
pub struct Block {
    m: f64,
    g: f64,
    mu: f64,
}

/// A mass on a spring.
#[derive(LagrangeDirac)]
#[dirac(coordinates(z => vz), port(z))]
#[dirac(lagrangian = 0.5 * m * vz * vz - 0.5 * k * z * z)]
pub struct Mass {
    m: f64,
    k: f64,
}

/// An interconnection does not carry the friction's rows `B − A` of its subsystems yet.
#[derive(Interconnection)]
#[dirac(connect(block.x, mass.z))]
pub struct Pushed {
    block: Block,
    mass: Mass,
}

fn main() {}
