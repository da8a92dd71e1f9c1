// A robot's gravity is three expressions; anything else is refused at the expression.
// The path leads from the crate trybuild writes under target/tests/trybuild back to tests/robots.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(urdf = "../../../../tests/robots/free/top.urdf", floating, gravity = -9.81)]
struct Top {}

fn main() {}
