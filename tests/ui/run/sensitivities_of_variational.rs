// The variational integrator does not carry sensitivities: asking it to is refused when it
// compiles.
use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
struct Oscillator {
    m: f64,
    k: f64,
}

fn main() {
    let model = Oscillator { m: 1.0, k: 4.0 };
    let wrt = Sensitivities::new(&model).initial_position(Oscillator::X);
    let mut variational = Variational::new(&model, 1e-3, VariationalOptions::default()).unwrap();
    let _ = variational.carry_sensitivities(&wrt);
}
