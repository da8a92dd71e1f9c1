use dirac::prelude::*; use dirac::State;

/// Three independent mistakes are all reported, and using the model afterwards adds no error.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy), port(z))]
#[dirac(lagrangian = 0.5 * mass * (vx * vx + vy * vy) - m * g * y.floor())]
#[dirac(constraint = vx * vy)]
struct Particle {
    m: f64,
    g: f64,
}

fn main() {
    let p = Particle { m: 1.0, g: 9.81 };
    let mut s = State::<Particle>::zeros();
    s.set_q(Particle::X, 1.0);
    let _ = p.lagrangian(0.0, &s.q, &s.v);
}
