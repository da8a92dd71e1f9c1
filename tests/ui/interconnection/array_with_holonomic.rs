use dirac::prelude::*;

/// A ball with a floor.
#[derive(LagrangeDirac)]
#[dirac(coordinates(y => v), port(y))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * y)]

pub struct Ball {
    m: f64,
    g: f64,
}

/// A row of balls held apart: an array composite has no holonomic rows of its own yet.
#[derive(Interconnection)]
#[dirac(holonomic(tie) = balls[i + 1].y - balls[i].y - 1.0)]
pub struct Row {
    balls: Vec<Ball>,
}

fn main() {}
