use dirac::prelude::*;

/// `−½ v²` is never positive: it would put power in, not take it out.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(dissipation = -0.5 * v * v - 2.0 * (x * v).powi(2))]
struct Pumped {
    m: f64,
    k: f64,
}

fn main() {}
