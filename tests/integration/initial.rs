//! Consistent initial states: projections, multipliers, and the errors when none exists.

use dirac::State;
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

/// A spring and a mass whose mass nothing requires to be positive.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
struct LooseOscillator {
    m: f64,
    k: f64,
}

/// Two bodies on a spring, written with a kinetic energy that is negative along one motion (the
/// cross term larger than the masses allow: `m1 m2 < c²`), and a third coordinate without
/// inertia held by a row: degenerate there, which is allowed.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(a => va, b => vb, z => vz))]
#[dirac(lagrangian = 0.5 * m1 * va * va + 0.5 * m2 * vb * vb + c * va * vb - 0.5 * k * (a - b) * (a - b))]
#[dirac(holonomic(held) = z)]
struct CrossedOscillator {
    m1: f64,
    m2: f64,
    c: f64,
    k: f64,
}

/// A negative mass is a wrong model, refused before anything runs with the coordinate it moves
/// (it used to run, to x(5) = 74 m from x = 1); so is an inertia that is indefinite only through
/// its cross terms, with the coordinates of the motion whose kinetic energy is negative. The
/// same models with positive inertia start and run; and a degenerate inertia (`z`, none)
/// stays allowed.
#[test]
fn a_negative_or_indefinite_inertia_is_refused_naming_the_coordinates() {
    let q = VecQ::<LooseOscillator>::from([1.0]);
    let zero = VecQ::<LooseOscillator>::zeros();
    let negative = LooseOscillator { m: -1.0, k: 1.0 };
    let named = |error: SimError, coordinates: &[&str]| match error {
        SimError::NegativeInertia { coordinates: found, .. } => {
            for c in coordinates {
                assert!(found.contains(&format!("`{c}`")), "{found}");
            }
        }
        other => panic!("expected a negative inertia, got {other}"),
    };
    named(consistent_state(&negative, 0.0, &q, &zero, Consistency::default()).expect_err("refused"), &["x"]);
    // A state made by hand is refused by the integrators' start too.
    let mut state = State::<LooseOscillator>::zeros();
    state.set_q(LooseOscillator::X, 1.0);
    let radau = Radau::new(&negative, RadauOptions::default()).expect("valid").solve(
        0.0,
        &state,
        5.0,
        &Sampling::Steps,
    );
    named(radau.expect_err("refused"), &["x"]);
    let explicit = Explicit::new(&negative, ExplicitOptions::default()).expect("valid").solve(
        0.0,
        &state,
        5.0,
        &Sampling::Steps,
    );
    named(explicit.expect_err("refused"), &["x"]);
    let positive = LooseOscillator { m: 1.0, k: 1.0 };
    let start =
        consistent_state(&positive, 0.0, &q, &zero, Consistency::default()).expect("a positive mass starts");
    let run = Radau::new(&positive, RadauOptions::tolerances(1e-10, 1e-10))
        .expect("valid")
        .solve(0.0, &start, 5.0, &Sampling::Steps)
        .expect("runs");
    // x = cos t.
    assert!((run.q(LooseOscillator::X)[run.len() - 1] - 5f64.cos()).abs() < 1e-8);

    let crossed = CrossedOscillator { m1: 1.0, m2: 1.0, c: 2.0, k: 1.0 };
    let q = VecQ::<CrossedOscillator>::from([1.0, 0.0, 0.0]);
    let zero = VecQ::<CrossedOscillator>::zeros();
    named(
        consistent_state(&crossed, 0.0, &q, &zero, Consistency::default()).expect_err("refused"),
        &["a", "b"],
    );
    let sound = CrossedOscillator { c: 0.5, ..crossed };
    consistent_state(&sound, 0.0, &q, &zero, Consistency::default())
        .expect("positive definite on a, b; none on z");
}
