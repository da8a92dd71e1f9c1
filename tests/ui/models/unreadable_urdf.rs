// A URDF that cannot be read is the one error: nothing after it asks for the coordinates or the
// Lagrangian the robot would have given.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(urdf = "robots/no_such_robot.urdf")]
struct Robot {}

fn main() {}
