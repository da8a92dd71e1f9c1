// The explicit method does not carry sensitivities: a run that asks it for them is refused
// when it compiles, at the method.
use dirac::prelude::*; use dirac::State;

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
    let mut explicit = Explicit::new(&model, ExplicitOptions::default()).unwrap();
    let _ = explicit.run(0.0, &State::zeros(), 1.0).sensitivities(&wrt).solve();
}
