// `floating` and `gravity` are a URDF robot's: a model written by hand has its own Lagrangian.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v), lagrangian = 0.5 * v * v, floating, gravity = [0.0, 0.0, -9.81])]
struct Point {}

fn main() {}
