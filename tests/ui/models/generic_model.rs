use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v)]
struct Particle<T> {
    m: f64,
    marker: std::marker::PhantomData<T>,
}

fn main() {}
