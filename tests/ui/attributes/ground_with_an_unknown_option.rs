// `ground` takes its restitution, its friction and the links that touch it, nothing else.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(urdf = "../../../../tests/robots/ground/ball.urdf", floating, ground(damping = 0.5))]
struct Ball {}

fn main() {}
