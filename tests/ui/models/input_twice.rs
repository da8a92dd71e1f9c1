use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v), input(f, f))]
#[dirac(lagrangian = 0.5 * m * v * v, force(x) = f)]
struct Pushed {
    m: f64,
    f: f64,
}

fn main() {}
