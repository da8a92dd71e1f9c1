use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v), port(x))]
#[dirac(lagrangian = 0.5 * m * v * v - m * g * x, unilateral(floor) = x)]
pub struct Ball {
    pub m: f64,
    pub g: f64,
}

#[derive(LagrangeDirac)]
#[dirac(coordinates(y => w), port(y))]
#[dirac(lagrangian = 0.5 * m * w * w)]
pub struct Block {
    pub m: f64,
}

#[derive(Interconnection)]
#[dirac(reduce, connect(ball.x, block.y))]
pub struct Stack {
    pub ball: Ball,
    pub block: Block,
}

fn main() {}
