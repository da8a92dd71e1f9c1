use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(theta => omega))]
#[dirac(lagrangian = 0.5 * m * l * l * omega * omega + m * g * l * thetta.cos())]
struct Pendulum {
    m: f64,
    g: f64,
    l: f64,
}

fn main() {}
