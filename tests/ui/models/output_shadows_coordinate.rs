use dirac::prelude::*;

// Outputs share the model's namespace: `x` is already a coordinate.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v), output(x) = 2.0 * x)]
#[dirac(lagrangian = 0.5 * m * v * v)]
struct Particle {
    m: f64,
}

fn main() {}
