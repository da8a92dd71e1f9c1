use dirac::prelude::*;

/// A ball with a floor.
#[derive(LagrangeDirac)]
#[dirac(coordinates(y => v), port(y))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * y)]
#[dirac(unilateral(floor) = y)]
pub struct Ball {
    m: f64,
    g: f64,
}

/// A row of balls: an array composite does not gather its elements' contacts.
#[derive(Interconnection)]
#[dirac(constraint(tie) = balls[i + 1].v - balls[i].v)]
pub struct Row {
    balls: Vec<Ball>,
}

fn main() {}
