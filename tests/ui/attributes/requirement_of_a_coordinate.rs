use dirac::prelude::*;

/// `positive` names parameters: a coordinate, or a parameter required twice, is refused.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v), positive(m, x), nonnegative(m))]
#[dirac(lagrangian = 0.5 * m * v * v)]
struct Mass {
    m: f64,
}

fn main() {}
