// `ground` takes its restitution and nothing else.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(urdf = "../../../../tests/robots/ground/ball.urdf", floating, ground(friction = 0.5))]
struct Ball {}

fn main() {}
