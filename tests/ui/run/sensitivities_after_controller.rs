// A sampled controller feeds the state back into the model, and its derivative is not carried:
// asking for sensitivities after one is refused when it compiles, as before one.
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
    let mut model = Oscillator { m: 1.0, k: 4.0, u: 0.0 };
    let wrt = Sensitivities::new(&model).initial_position(Oscillator::X);
    let mut radau = Radau::new(&mut model, RadauOptions::default()).unwrap();
    let start = State::zeros();
    let _ = radau
        .run(0.0, &start, 1.0)
        .every(0.1, |_, state: &State<Oscillator>, model: &mut Oscillator| model.u = -state.q(Oscillator::X))
        .sensitivities(&wrt)
        .solve();
}
