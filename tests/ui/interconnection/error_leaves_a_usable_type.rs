use dirac::prelude::*; use dirac::State;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x1 => v1, x2 => v2), port(x2))]
#[dirac(lagrangian = 0.5 * m * (v1 * v1 + v2 * v2) - 0.5 * k * (x2 - x1).powi(2))]
pub struct Left {
    pub m: f64,
    pub k: f64,
}

#[derive(LagrangeDirac)]
#[dirac(coordinates(x2bar => v2bar, x3 => v3), port(x2bar))]
#[dirac(lagrangian = 0.5 * m * v3 * v3 - 0.5 * k * (x3 - x2bar).powi(2))]
pub struct Right {
    pub m: f64,
    pub k: f64,
}

/// One mistake in the interconnection (`rigth`): the composite is still a model to the rest
/// of the program (a stub impl is emitted next to the error), so using it adds no error.
#[derive(Interconnection)]
#[dirac(connect(left.x2, rigth.x2bar))]
pub struct Chain {
    pub left: Left,
    pub right: Right,
}

fn main() {
    let state = State::<Chain>::zeros();
    let _ = state.q(Chain::left(Left::X1));
    let _ = Chain::LEFT_X2;
    let _ = Chain::NAMES.coordinate_names();
}
