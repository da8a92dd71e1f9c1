// `ground(links = ...)` takes the links' names as strings in a list.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(urdf = "../../../../tests/robots/ground/brick.urdf", floating, ground(links = [brick]))]
struct Brick {}

fn main() {}
