// An adjoint recording does not transpose a drive's inputs: a driven run is not recorded, refused
// when it compiles.
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
    let mut drive = |t: f64, _: &State<Oscillator>, model: &mut Oscillator| model.u = t.sin();
    let mut radau = Radau::new(&mut model, RadauOptions::default()).unwrap();
    let start = State::zeros();
    let _ = radau.run(0.0, &start, 1.0).drive(&mut drive, &[]).record();
}
