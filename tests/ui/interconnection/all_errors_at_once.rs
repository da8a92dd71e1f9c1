use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(phi => omega), port(phi))]
#[dirac(lagrangian = 0.5 * j * omega * omega)]
pub struct Load {
    pub j: f64,
}

#[derive(LagrangeDirac)]
#[dirac(coordinates(theta => w), port(theta))]
#[dirac(lagrangian = 0.5 * j * w * w - 0.5 * k * theta * theta)]
pub struct Motor {
    pub j: f64,
    pub k: f64,
}

// A misspelt coordinate, a misspelt velocity in a one-form and a misspelt subsystem, in two
// interconnections: every one is reported, each with the name it was likely meant to be.
#[derive(Interconnection)]
#[dirac(connect(motor.theta, load.phii))]
#[dirac(constraint(gear) = motor.ww - 2.0 * load.omega)]
pub struct Drive {
    pub motor: Motor,
    pub load: Load,
}

#[derive(Interconnection)]
#[dirac(connect(motr.theta, load.phi))]
pub struct Other {
    pub motor: Motor,
    pub load: Load,
}

#[derive(Interconnection)]
#[dirac(connect(motor.thetta, load.phi))]
pub struct Third {
    pub motor: Motor,
    pub load: Load,
}

fn main() {}
