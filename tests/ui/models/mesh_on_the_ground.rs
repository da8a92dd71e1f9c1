// A collision mesh asked to touch the ground: refused at the mesh's `<collision>` line, and
// nothing after it (no request for coordinates or a Lagrangian).
// The path leads from the crate trybuild writes under target/tests/trybuild back to tests/robots.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(urdf = "../../../../tests/robots/bad/mesh_on_the_ground.urdf", floating, ground)]
struct Robot {}

fn main() {}
