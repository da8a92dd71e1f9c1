// A floating base with no mass, nor any link fixed to it, would move without inertia: refused
// at its joint's line.
// The path leads from the crate trybuild writes under target/tests/trybuild back to tests/robots.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(urdf = "../../../../tests/robots/bad/massless_floating_base.urdf")]
struct Robot {}

fn main() {}
