//! Constraints may depend on time and be affine in the velocities: `φ(q, t) = 0`,
//! `A(q, t) v + b(q, t) = 0`, in primitives and interconnections, through `t`, definitions
//! and inputs.

use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy), input(speed))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy))]
#[dirac(define(angle) = w * t)]
#[dirac(holonomic(rod) = x * sin(angle) - y * cos(angle))]
#[dirac(constraint(belt) = vx + vy - speed * (1.0 + x * x))]
pub struct Driven {
    pub m: f64,
    pub w: f64,
    pub speed: f64,
}

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v), port(x), lagrangian = 0.5 * m * v * v)]
pub struct Mass {
    pub m: f64,
}

#[derive(Interconnection)]
#[dirac(constraint(slip) = right.v - left.v - c * t)]
pub struct Pair {
    pub left: Mass,
    pub right: Mass,
    pub c: f64,
}

fn main() {
    let driven = Driven { m: 1.0, w: 2.0, speed: 0.5 };
    assert_eq!(driven.constraint_names(), ["rod", "belt"]);
    let pair = Pair { left: Mass { m: 1.0 }, right: Mass { m: 2.0 }, c: 0.3 };
    assert_eq!(pair.constraint_names(), ["slip"]);
}
