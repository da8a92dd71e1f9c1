// Only Radau records its steps for an adjoint: a run of the explicit method or the variational
// integrator that asks for a recording is refused when it compiles.
use dirac::prelude::*; use dirac::State;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v), input(u))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(force(x) = u)]
struct Oscillator {
    m: f64,
    k: f64,
    u: f64,
}

fn main() {
    let model = Oscillator { m: 1.0, k: 4.0, u: 0.0 };
    let mut explicit = Explicit::new(&model, ExplicitOptions::default()).unwrap();
    let _ = explicit.run(0.0, &State::zeros(), 1.0).record();
    let mut variational = Variational::new(&model, 1e-3, VariationalOptions::default()).unwrap();
    let _ = variational.run(0.0, &State::zeros(), 1.0).record();
}
