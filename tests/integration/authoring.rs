//! What model authors write besides the Lagrangian: named intermediate quantities
//! (`define`), constants of their own code, and names that the printed equations must not
//! confuse.

use dirac::prelude::*;

use crate::util::{Rng, random_y};
use crate::zoo::Pendulum;

/// Gravity as a constant of this code, read by the generated code where it runs.
const G: f64 = 9.81;

mod units {
    /// A constant reached by a path.
    pub const ROD_LENGTH: f64 = 1.0;
}

/// The zoo's pendulum written with a definition for the squared radius, used in the
/// Lagrangian (through a second definition) and in the rod, and with constants for g and l.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(define(r2) = x * x + y * y)]
#[dirac(define(kinetic) = 0.5 * m * (vx * vx + vy * vy))]
#[dirac(lagrangian = kinetic - m * G * y + 0.0 * r2)]
#[dirac(holonomic(rod) = r2 - units::ROD_LENGTH * units::ROD_LENGTH)]
struct Defined {
    m: f64,
}

/// Same residuals and Jacobians as the pendulum written inline, at random states.
#[test]
fn definitions_and_constants_generate_the_same_model() {
    let (defined, inline) = (Defined { m: 1.3 }, Pendulum { m: 1.3, g: G, l: 1.0 });
    let mut rng = Rng::new(31);
    for _ in 0..20 {
        let y = random_y(&inline, &mut rng);
        let y2 = VecY::<Defined>::from_column_slice(y.as_slice());
        let (f1, f2) = (inline.residual_vector(0.3, &y), defined.residual_vector(0.3, &y2));
        assert!(f1.iter().zip(f2.iter()).all(|(a, b)| (a - b).abs() <= 1e-14 * a.abs().max(1.0)));
        let (j1, j2) = (inline.jacobian_matrix(0.3, &y), defined.jacobian_matrix(0.3, &y2));
        assert!(j1.iter().zip(j2.iter()).all(|(a, b)| (a - b).abs() <= 1e-14 * a.abs().max(1.0)));
    }
    const { assert!(Defined::SEPARABLE, "constants count as parameters for separability") };
}

/// Definitions are printed by name, each with its own line; constants by the path written.
#[test]
fn definitions_are_printed_by_name() {
    let text = Defined::equations().text;
    assert!(text.contains("r2 = x^2 + y^2    (definition)"), "{text}");
    assert!(text.contains("kinetic = 0.5*m*(vx^2 + vy^2)    (definition)"), "{text}");
    assert!(text.contains("0 = r2 - units::ROD_LENGTH^2    (rod, holonomic)"), "{text}");
    assert!(text.contains("dp_y/dt = -m*G + 2*y*lambda_rod"), "{text}");
}

/// A coordinate `ep` whose velocity is `epp` next to a velocity named `dep`: the derivative
/// of `ep` is printed `d(ep)/dt`, not `dep/dt`, which would read as the other velocity.
#[derive(LagrangeDirac)]
#[dirac(coordinates(ep => epp, q2 => dep))]
#[dirac(lagrangian = 0.5 * epp * epp + 0.5 * dep * dep - 0.5 * ep * ep)]
struct Colliding {}

#[test]
fn made_up_names_do_not_collide_with_the_model_s() {
    let text = Colliding::equations().text;
    assert!(text.contains("d(ep)/dt = epp"), "{text}");
    assert!(text.contains("dq2/dt = dep"), "{text}");
}
