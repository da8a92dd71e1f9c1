use dirac::prelude::*;

/// A lever end without inertia: legitimate as an open port of a primitive.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, tip => v_tip), port(x, tip))]
#[dirac(lagrangian = 0.5 * m * vx * vx)]
pub struct Lever {
    pub m: f64,
}

#[derive(LagrangeDirac)]
#[dirac(coordinates(y => vy), port(y))]
#[dirac(lagrangian = 0.5 * m * vy * vy - 0.5 * k * y * y)]
pub struct Mass {
    pub m: f64,
    pub k: f64,
}

/// Connecting x but leaving the massless tip free: nothing determines the tip's velocity.
#[derive(Interconnection)]
#[dirac(connect(lever.x, mass.y))]
pub struct Machine {
    pub lever: Lever,
    pub mass: Mass,
}

fn main() {}
