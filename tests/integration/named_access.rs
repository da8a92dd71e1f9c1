//! Reading and writing q, v, p and λ by name, and the names a model reports.

use dirac::Fixed;
use dirac::State;
use dirac::prelude::*;

use crate::zoo::{Pendulum, Primitive2, RollingDisk};

fn disk() -> RollingDisk {
    RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 }
}

#[test]
fn state_components_by_name() {
    let mut s = State::<RollingDisk>::zeros();
    s.set_q(RollingDisk::PHI, 0.25).set_v(RollingDisk::THETA, 2.0).set_p(RollingDisk::X, -1.0);
    s.set_lambda(RollingDisk::ROLL_Y, 3.0);
    assert_eq!(s.q(RollingDisk::PHI), 0.25);
    assert_eq!(s.v(RollingDisk::THETA), 2.0);
    assert_eq!(s.p(RollingDisk::X), -1.0);
    assert_eq!(s.lambda(RollingDisk::ROLL_Y), 3.0);
    assert_eq!(s.q[3], 0.25, "phi is the fourth coordinate");
    let y = s.to_y();
    assert_eq!(State::<RollingDisk>::from_y(RollingDisk::SIZES, &y), s);
    assert_eq!(y[4 + 2], 2.0, "y = (q, v, p, λ): v_theta at n + 2");
    assert_eq!(y[3 * 4 + 1], 3.0, "λ_roll_y at 3n + 1");
}

#[test]
fn models_report_their_names() {
    assert_eq!(disk().coordinate_names(), ["x", "y", "theta", "phi"]);
    assert_eq!(disk().velocity_names(), ["v_x", "v_y", "v_theta", "v_phi"]);
    assert_eq!(disk().constraint_names(), ["roll_x", "roll_y"]);
    assert_eq!(RollingDisk::NAMES.coordinates, &["x", "y", "theta", "phi"]);
    assert_eq!(disk().coordinate("theta"), Some(RollingDisk::THETA));
    assert_eq!(disk().coordinate("psi"), None);
    assert_eq!(Pendulum { m: 1.0, g: 9.81, l: 1.0 }.constraint("rod"), Some(Pendulum::ROD));
    assert_eq!(Pendulum::ROD.name(), "rod");
    assert_eq!(Primitive2::X2BAR.to_string(), "x2bar");
    assert_eq!(format!("{:?}", Primitive2::X3), "Coordinate(#1)");
    assert_eq!((RollingDisk::NQ, RollingDisk::NC, RollingDisk::NH), (4, 2, 0));
    assert_eq!((Pendulum::NQ, Pendulum::NC, Pendulum::NH), (2, 1, 1));
}
