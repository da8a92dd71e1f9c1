//! Reading and writing q, v, p and λ by name, and the names a model reports.

use dirac::prelude::*;

use crate::zoo::{Pendulum, Primitive2, RollingDisk};

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
    assert_eq!(State::<RollingDisk>::from_y(&y), s);
    assert_eq!(y[4 + 2], 2.0, "y = (q, v, p, λ): v_theta at n + 2");
    assert_eq!(y[3 * 4 + 1], 3.0, "λ_roll_y at 3n + 1");
}

#[test]
fn models_report_their_names() {
    assert_eq!(RollingDisk::coordinate_names(), ["x", "y", "theta", "phi"]);
    assert_eq!(RollingDisk::velocity_names(), ["v_x", "v_y", "v_theta", "v_phi"]);
    assert_eq!(RollingDisk::constraint_names(), ["roll_x", "roll_y"]);
    assert_eq!(RollingDisk::NAMES.coordinates, &["x", "y", "theta", "phi"]);
    assert_eq!(RollingDisk::coordinate("theta"), Some(RollingDisk::THETA));
    assert_eq!(RollingDisk::coordinate("psi"), None);
    assert_eq!(Pendulum::constraint("rod"), Some(Pendulum::ROD));
    assert_eq!(Pendulum::ROD.name(), "rod");
    assert_eq!(Primitive2::X2BAR.to_string(), "x2bar");
    assert_eq!(format!("{:?}", Primitive2::X3), "Coordinate(#1)");
    assert_eq!((RollingDisk::NQ, RollingDisk::NC, RollingDisk::NH), (4, 2, 0));
    assert_eq!((Pendulum::NQ, Pendulum::NC, Pendulum::NH), (2, 1, 1));
}
