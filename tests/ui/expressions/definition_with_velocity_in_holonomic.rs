use dirac::prelude::*;

/// A definition that depends on a velocity, used in a constraint on positions.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(define(speed2) = vx * vx + vy * vy)]
#[dirac(lagrangian = 0.5 * speed2)]
#[dirac(holonomic(rod) = x * x + y * y - speed2)]
struct Pendulum {}

fn main() {}
