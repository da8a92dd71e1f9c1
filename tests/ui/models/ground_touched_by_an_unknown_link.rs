// `ground(links = [...])` names a link the robot does not have: refused at that name, with the
// link it is nearest to, and nothing after it (no request for coordinates or a Lagrangian).
// The path leads from the crate trybuild writes under target/tests/trybuild back to tests/robots.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(urdf = "../../../../tests/robots/ground/brick.urdf", floating, ground(links = ["brick", "handel"]))]
struct Brick {}

fn main() {}
