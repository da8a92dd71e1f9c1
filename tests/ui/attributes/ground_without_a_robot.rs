// `ground` belongs to a robot read from a URDF file.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v), lagrangian = 0.5 * v * v, ground(restitution = 0.5))]
struct Slider {}

fn main() {}
