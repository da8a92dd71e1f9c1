use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(lagrangian = 0.5 * m)]
struct Nothing {
    m: f64,
}

fn main() {}
