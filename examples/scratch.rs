use dirac::prelude::*;
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(rod) = x * x + y * y - l * l)]
struct Pendulum {
    m: f64,
    g: f64,
    l: f64,
}

#[derive(LagrangeDirac)]
#[dirac(coordinates(x1 => v1, x2 => v2), port(x2))]
#[dirac(lagrangian = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2 - 0.5 * k1 * x1 * x1 - 0.5 * k2 * (x2 - x1).powi(2))]
pub struct Primitive1 {
    pub m1: f64,
    pub m2: f64,
    pub k1: f64,
    pub k2: f64,
}

fn main() {
    println!(
        "{}\n{}",
        Pendulum::equations().text,
        Pendulum::equations().latex
    );
    println!(
        "{}\n{}",
        Primitive1::equations().text,
        Primitive1::equations().latex
    );
}
