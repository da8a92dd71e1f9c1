//! Consistent initial states: projections, multipliers, and the errors when none exists.

use dirac::prelude::*;

use crate::zoo::*;

/// Off the circle and moving across the rod, the pendulum is projected back: |q| = l and
/// q · v = 0. At the bottom with speed 1 the rod carries m (g + v²/l): ÿ = v²/l = 1 with
/// m ÿ = −m g + 2 y λ gives λ = −m (1 + g)/2 (derived by hand).
#[test]
fn pendulum_is_projected_and_its_tension_found() {
    let p = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let s = consistent_state(
        &p,
        0.0,
        &VecQ::<Pendulum>::new(0.6, -0.9),
        &VecQ::<Pendulum>::new(0.3, 0.4),
        Consistency::default(),
    )
    .expect("consistent");
    assert!((s.q.norm() - 1.0).abs() < 1e-13);
    assert!(s.q.dot(&s.v).abs() < 1e-13);
    let s = consistent_state(
        &p,
        0.0,
        &VecQ::<Pendulum>::new(0.0, -1.0),
        &VecQ::<Pendulum>::new(1.0, 0.0),
        Consistency::default(),
    )
    .expect("consistent");
    assert!((s.lambda(Pendulum::ROD) + 0.5 * (1.0 + 9.81)).abs() < 1e-12, "{}", s.lambda(Pendulum::ROD));
    assert_eq!(s.p, s.v, "p = m v with m = 1");
}

/// The chain with v2 = 1 and v̄2 = 0 given: v̄2 has no inertia, so it takes the correction and
/// v2 keeps the value given. μ = k3 (x3 − x̄2) from ṗ̄2 = 0.
#[test]
fn degenerate_velocities_take_up_the_correction() {
    let chain = paper_chain();
    let (x2, x2bar, x3) =
        (Chain::left(Primitive1::X2), Chain::right(Primitive2::X2BAR), Chain::right(Primitive2::X3));
    let mut q = VecQ::<Chain>::zeros();
    q[x2.index()] = 0.2;
    q[x2bar.index()] = 0.2;
    q[x3.index()] = 0.5;
    let mut v = VecQ::<Chain>::zeros();
    v[x2.index()] = 1.0;
    let s = consistent_state(&chain, 0.0, &q, &v, Consistency::default()).expect("consistent");
    assert!((s.v(x2) - 1.0).abs() < 1e-8, "v2 kept: {}", s.v(x2));
    assert!((s.v(x2bar) - s.v(x2)).abs() < 1e-13, "v2bar = v2");
    assert!((s.lambda(Chain::CONNECT0) - 6.0 * (0.5 - 0.2)).abs() < 1e-12);
}

/// A circle of imaginary radius: no consistent state exists, and the error names the equation.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * (vx * vx + vy * vy))]
#[dirac(holonomic(impossible) = x * x + y * y + 1.0)]
struct Impossible {}

/// A degenerate coordinate that nothing determines: the consistency system is singular.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, free => v_free), port(free))]
#[dirac(lagrangian = 0.5 * vx * vx - 0.5 * x * x)]
struct Undetermined {}

#[test]
fn no_consistent_state_is_a_typed_error() {
    let err = consistent_state(
        &Impossible {},
        0.0,
        &VecQ::<Impossible>::new(1.0, 0.0),
        &VecQ::<Impossible>::zeros(),
        Consistency::default(),
    );
    match err {
        Err(SimError::InconsistentInitialState { equation, .. }) => {
            assert_eq!(equation, "holonomic constraint `impossible`")
        }
        other => panic!("expected an inconsistent state, got {other:?}"),
    }
    let err = consistent_state(
        &Undetermined {},
        0.0,
        &VecQ::<Undetermined>::new(1.0, 0.0),
        &VecQ::<Undetermined>::zeros(),
        Consistency::default(),
    );
    match err {
        Err(SimError::NotDetermined { cause, .. }) => {
            assert!(cause.contains("velocity of `free` is not determined"), "{cause}")
        }
        other => panic!("expected an undetermined coordinate, got {other:?}"),
    }
}
