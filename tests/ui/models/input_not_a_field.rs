use dirac::prelude::*;

// An input names an `f64` field; `torque` is misspelt.
#[derive(LagrangeDirac)]
#[dirac(coordinates(theta => omega), input(torqe))]
#[dirac(lagrangian = 0.5 * j * omega * omega, force(theta) = torque)]
struct Motor {
    j: f64,
    torque: f64,
}

fn main() {}
