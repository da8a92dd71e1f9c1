use dirac::prelude::*;

/// The dissipation's power is an output with a key and a unit, like the user's.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(dissipation = 0.5 * c * v * v)]
#[dirac(output(speed) = v, unit(dissipated_power) = "W", unit(speed) = "m/s")]
struct Damped {
    m: f64,
    k: f64,
    c: f64,
}

fn main() {
    assert_eq!(Damped::SPEED.index(), 0);
    assert_eq!(Damped::DISSIPATED_POWER.index(), 1);
}
