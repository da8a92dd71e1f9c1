use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x1 => v1, x2 => v2), port(x2))]
#[dirac(lagrangian = 0.5 * m * (v1 * v1 + v2 * v2) - 0.5 * k * (x2 - x1).powi(2))]
pub struct Left {
    pub m: f64,
    pub k: f64,
}

/// Not a model. The macro cannot know; the generated impls require every subsystem type to
/// be a model, and each error says that this one is not (at the field's type or the derive),
/// without a cascade from the bodies of the impls.
pub struct Right {
    pub m: f64,
}

#[derive(Interconnection)]
#[dirac(connect(left.x2, right.x2bar))]
pub struct Chain {
    pub left: Left,
    pub right: Right,
}

fn main() {}
