// A floating joint joins the world to a body; one from a link that moves is refused at its line,
// and nothing after the error asks for what the robot would have given.
// The path leads from the crate trybuild writes under target/tests/trybuild back to tests/robots.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(urdf = "../../../../tests/robots/bad/floating_from_a_moving_link.urdf")]
struct Robot {}

fn main() {}
