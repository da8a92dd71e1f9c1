// A drive sets the inputs within the steps, from the state too, and its derivative is not
// carried: sensitivities of a driven run are refused when it compiles.
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
    let mut drive = |_: f64, state: &State<Oscillator>, model: &mut Oscillator| model.u = -state.q(Oscillator::X);
    let mut radau = Radau::new(&mut model, RadauOptions::default()).unwrap();
    let start = State::zeros();
    let _ = radau.run(0.0, &start, 1.0).drive(&mut drive, &[]).sensitivities(&wrt).solve();
}
