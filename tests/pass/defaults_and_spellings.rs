//! Velocity names default to `v_<coordinate>`; free-function and method spellings, `PI`, and
//! several `#[dirac]` attributes are accepted.

use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(theta, phi))]
#[dirac(lagrangian = 0.5 * m * (v_theta * v_theta + sin(theta).powi(2) * v_phi * v_phi)
                   - m * g * f64::cos(theta) + 0.0 * PI)]
#[dirac(force(phi) = -c * v_phi, holonomic = theta - phi * 0.5)]
pub struct Spherical {
    pub m: f64,
    pub g: f64,
    pub c: f64,
}

/// Raw identifiers name coordinates and parameters like any other name.
#[derive(LagrangeDirac)]
#[dirac(coordinates(r#type => r#move))]
#[dirac(lagrangian = 0.5 * r#mut * r#move * r#move - r#type * 0.0)]
pub struct Raw {
    pub r#mut: f64,
}

fn main() {
    assert_eq!(Spherical::NAMES.velocity_names(), ["v_theta", "v_phi"]);
    assert_eq!(Spherical::NAMES.constraint_names(), ["holonomic0"]);
    let _ = Spherical::HOLONOMIC0;
    assert_eq!(Raw::NAMES.coordinate_names(), ["type"]);
    assert_eq!(Raw::TYPE.name(), "type");
}
