use dirac::prelude::*;

/// A friction law needs its kinetic force; the message shows the full form.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v)]
#[dirac(friction(grip, stiction = mu * n) = v - vb)]
struct Slider {
    m: f64,
    mu: f64,
    n: f64,
    vb: f64,
}

fn main() {}
