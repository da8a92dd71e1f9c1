//! Linearisation about equilibria against textbook matrices: the inverted pendulum in its
//! angle (eigenvalues ±√(g/l)), the same pendulum in Cartesian coordinates with its rod as a
//! holonomic constraint (which must reduce to the same two states), and the cart-pole about
//! upright (A and B derived by hand below); and against simulated responses of the nonlinear
//! model to small perturbations, propagated by the matrix exponential of the linear one.

use dirac::State;
use dirac::nalgebra::{DMatrix, DVector};
use dirac::prelude::*;

use crate::zoo::Pendulum;

/// A pendulum balanced upright: `θ` from the vertical, torque `tau` at the pivot, the tip's
/// horizontal position as output.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(theta => omega), input(tau), output(tip_x) = l * theta.sin())]
#[dirac(lagrangian = 0.5 * m * l * l * omega * omega - m * g * l * theta.cos(), force(theta) = tau)]
struct Inverted {
    m: f64,
    l: f64,
    g: f64,
    tau: f64,
}

/// A cart (mass `mc`, position `x`) carrying a pole (point mass `mp` at length `l`, angle `th`
/// from upright), pushed by the force `u`; outputs the cart position and the pole angle.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(x => vx, th => w), input(u), output(cart) = x, output(angle) = th)]
#[dirac(lagrangian = 0.5 * (mc + mp) * vx * vx + mp * l * vx * w * th.cos() + 0.5 * mp * l * l * w * w
                   - mp * g * l * th.cos())]
#[dirac(force(x) = u)]
struct CartPole {
    mc: f64,
    mp: f64,
    l: f64,
    g: f64,
    u: f64,
}

fn at_rest<M: DenseModel>(model: &M, q: &[f64]) -> State<M>
where
    DefaultAllocator: Storage<M>,
{
    let q = VecQ::<M>::from_column_slice(q);
    consistent_state(model, 0.0, &q, &VecQ::<M>::zeros(), Consistency::default()).expect("consistent")
}

fn assert_close(a: &DMatrix<f64>, b: &DMatrix<f64>, tol: f64) {
    assert_eq!(a.shape(), b.shape());
    assert!((a - b).amax() <= tol, "{a} against {b}");
}

#[test]
fn the_inverted_pendulum_has_its_textbook_matrices() {
    let (m, l, g) = (0.7, 0.9, 9.81);
    let model = Inverted { m, l, g, tau: 0.0 };
    let lin = linearize(&model, 0.0, &at_rest(&model, &[0.0])).expect("an equilibrium");
    assert_close(&lin.a, &DMatrix::from_row_slice(2, 2, &[0.0, 1.0, g / l, 0.0]), 1e-12);
    assert_close(&lin.b, &DMatrix::from_row_slice(2, 1, &[0.0, 1.0 / (m * l * l)]), 1e-12);
    assert_close(&lin.c, &DMatrix::from_row_slice(1, 2, &[l, 0.0]), 1e-12);
    assert_close(&lin.d, &DMatrix::zeros(1, 1), 0.0);
    // Without constraints the state is the model's own coordinate and velocity, named so.
    assert_eq!(lin.basis, dirac::Basis::Coordinates(vec!["theta".into()]));
    assert_eq!(lin.state_names(), ["δq(theta)", "δv(theta)"]);
    let mut eigenvalues: Vec<f64> = lin.a.complex_eigenvalues().iter().map(|z| z.re).collect();
    eigenvalues.sort_by(f64::total_cmp);
    let rate = (g / l).sqrt();
    assert!(
        (eigenvalues[0] + rate).abs() < 1e-12 && (eigenvalues[1] - rate).abs() < 1e-12,
        "{eigenvalues:?}"
    );
}

/// The eigenvalues of a 2 × 2 state matrix from its trace and determinant.
fn trace_and_determinant(a: &DMatrix<f64>) -> (f64, f64) {
    assert_eq!(a.shape(), (2, 2));
    (a.trace(), a.determinant())
}

#[test]
fn the_cartesian_pendulum_reduces_to_the_two_states_of_the_angle_form() {
    let (m, g, l) = (1.3, 9.81, 0.8);
    let model = Pendulum { m, g, l };
    // Upright, (0, l): unstable, eigenvalues ±√(g/l), so trace 0 and determinant −g/l.
    let up = linearize(&model, 0.0, &at_rest(&model, &[0.0, l])).expect("an equilibrium");
    // Constrained: along an orthonormal basis of the free directions, named so.
    assert_eq!(
        (up.basis.clone(), up.state_names()),
        (dirac::Basis::Orthonormal, vec!["δz[0]".into(), "δw[0]".into()])
    );
    assert_eq!((up.positions_count(), up.a.nrows()), (1, 2), "one position and one velocity");
    let (trace, det) = trace_and_determinant(&up.a);
    assert!(trace.abs() < 1e-12 && (det + g / l).abs() < 1e-10, "trace {trace}, determinant {det}");
    // Hanging, (0, −l): oscillating at √(g/l): determinant +g/l. The constraint's curvature
    // through λ* gives the whole stiffness: in Cartesian coordinates gravity alone has none.
    let down = linearize(&model, 0.0, &at_rest(&model, &[0.0, -l])).expect("an equilibrium");
    let (trace, det) = trace_and_determinant(&down.a);
    assert!(trace.abs() < 1e-12 && (det - g / l).abs() < 1e-10, "trace {trace}, determinant {det}");
    assert_eq!((down.b.ncols(), down.c.nrows()), (0, 0), "no inputs, no outputs");
}

#[test]
fn the_cart_pole_about_upright_has_its_closed_form() {
    // (mc + mp) ẍ + mp l θ̈ = u and mp l ẍ + mp l² θ̈ − mp g l θ = 0 at θ = 0 give
    // ẍ = (u − mp g θ)/mc and θ̈ = ((mc + mp) g θ − u)/(mc l).
    let (mc, mp, l, g) = (1.5, 0.4, 0.6, 9.81);
    let model = CartPole { mc, mp, l, g, u: 0.0 };
    let lin = linearize(&model, 0.0, &at_rest(&model, &[0.3, 0.0])).expect("an equilibrium");
    #[rustfmt::skip]
    let a = DMatrix::from_row_slice(4, 4, &[
        0.0, 0.0, 1.0, 0.0,
        0.0, 0.0, 0.0, 1.0,
        0.0, -mp * g / mc, 0.0, 0.0,
        0.0, (mc + mp) * g / (mc * l), 0.0, 0.0,
    ]);
    let b = DMatrix::from_row_slice(4, 1, &[0.0, 0.0, 1.0 / mc, -1.0 / (mc * l)]);
    assert_close(&lin.a, &a, 1e-12);
    assert_close(&lin.b, &b, 1e-12);
    assert_close(&lin.c, &DMatrix::from_row_slice(2, 4, &[1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]), 0.0);
}

/// `(δx(T), δy(T))` of the nonlinear cart-pole started at `δx0` from upright with the input
/// held at `u`, integrated by Radau at tight tolerances.
fn simulated(model: &CartPole, dx0: &[f64; 4], u: f64, t_end: f64) -> DVector<f64> {
    let mut model = model.clone();
    let start = consistent_state(
        &model,
        0.0,
        &VecQ::<CartPole>::from([dx0[0], dx0[1]]),
        &VecQ::<CartPole>::from([dx0[2], dx0[3]]),
        Consistency::default(),
    )
    .expect("consistent");
    model.u = u;
    let mut radau = Radau::new(&model, RadauOptions::tolerances(1e-12, 1e-14)).expect("valid");
    let end = radau.solve(0.0, &start, t_end, &Sampling::Times(vec![t_end])).expect("integrates");
    let s = end.last().expect("a sample");
    DVector::from_column_slice(&[s.q[0], s.q[1], s.v[0], s.v[1]])
}

#[test]
fn the_linear_model_predicts_small_simulated_responses() {
    let (mc, mp, l, g) = (1.5, 0.4, 0.6, 9.81);
    let model = CartPole { mc, mp, l, g, u: 0.0 };
    let lin = linearize(&model, 0.0, &at_rest(&model, &[0.0, 0.0])).expect("an equilibrium");
    let t_end = 0.3;
    // A tilt of the pole: δx(T) = e^{A T} δx0.
    let dx0 = [0.0, 1e-5, 0.0, 0.0];
    let linear = (&lin.a * t_end).exp() * DVector::from_column_slice(&dx0);
    let nonlinear = simulated(&model, &dx0, 0.0, t_end);
    assert!((&nonlinear - &linear).amax() < 1e-4 * linear.amax(), "{nonlinear} against {linear}");
    // A small push: δx(T) = ∫₀ᵀ e^{A s} B ε ds, the top-right block of exp([[A, B], [0, 0]] T).
    let epsilon = 1e-5;
    let mut augmented = DMatrix::zeros(5, 5);
    augmented.view_mut((0, 0), (4, 4)).copy_from(&lin.a);
    augmented.view_mut((0, 4), (4, 1)).copy_from(&lin.b);
    let linear = (augmented * t_end).exp().view((0, 4), (4, 1)).column(0) * epsilon;
    let nonlinear = simulated(&model, &[0.0; 4], epsilon, t_end);
    assert!((&nonlinear - &linear).amax() < 1e-4 * linear.amax(), "{nonlinear} against {linear}");
}

#[test]
fn linearising_away_from_an_equilibrium_is_refused() {
    let model = Inverted { m: 1.0, l: 1.0, g: 9.81, tau: 0.0 };
    // Tilted: the momentum changes.
    let error = linearize(&model, 0.0, &at_rest(&model, &[0.3])).expect_err("not an equilibrium");
    assert!(
        matches!(&error, SimError::NotEquilibrium { detail, .. } if detail.contains("`theta`")),
        "{error}"
    );
    // Moving.
    let q = VecQ::<Inverted>::from([0.0]);
    let moving = consistent_state(&model, 0.0, &q, &VecQ::<Inverted>::from([0.5]), Consistency::default())
        .expect("consistent");
    let error = linearize(&model, 0.0, &moving).expect_err("not at rest");
    assert!(
        matches!(&error, SimError::NotEquilibrium { detail, .. } if detail.contains("velocity")),
        "{error}"
    );
    // Held by a torque, a tilted pendulum is an equilibrium again.
    let held = Inverted { tau: -9.81 * 0.3f64.sin(), ..model };
    linearize(&held, 0.0, &at_rest(&held, &[0.3])).expect("held still by the torque");
}

#[test]
fn a_composite_linearises_through_its_members_blocks() {
    // Two springs whose ends are joined: (m1 + m2) ẍ + (k1 + k2) x = f1 + f2, and the output
    // `left.stretch` is k1 x. The joint is a velocity constraint, so the positions keep the
    // offset between the two ends as a mode of its own (a zero eigenvalue) that no input moves;
    // transfer functions do not see it: G(s) = k1 / ((m1 + m2) s² + k1 + k2) from either force.
    use crate::zoo::{ForcedPair, ForcedSpring};
    let (m1, m2, k1, k2) = (1.0, 2.0, 4.0, 5.0);
    let pair = ForcedPair {
        left: ForcedSpring { m: m1, k: k1, f: 0.0 },
        right: ForcedSpring { m: m2, k: k2, f: 0.0 },
    };
    let lin = linearize(&pair, 0.0, &at_rest(&pair, &[0.0, 0.0])).expect("an equilibrium");
    assert_eq!((lin.positions_count(), lin.a.nrows(), lin.b.ncols(), lin.c.nrows()), (2, 3, 2, 4));
    let s = 1.0;
    let resolvent =
        (DMatrix::<f64>::identity(3, 3) * s - &lin.a).try_inverse().expect("s is not an eigenvalue");
    let g = &lin.c * resolvent * &lin.b + &lin.d;
    let denominator = (m1 + m2) * s * s + k1 + k2;
    let left_stretch = ForcedPair::left_output(ForcedSpring::STRETCH).index();
    let right_stretch = ForcedPair::right_output(ForcedSpring::STRETCH).index();
    for input in [ForcedPair::left_input(ForcedSpring::F), ForcedPair::right_input(ForcedSpring::F)] {
        let u = input.index();
        assert!((g[(left_stretch, u)] - k1 / denominator).abs() < 1e-12, "{g}");
        assert!((g[(right_stretch, u)] - k2 / denominator).abs() < 1e-12, "{g}");
        // The energies are quadratic: no first-order response at rest.
        assert!(g[(ForcedPair::left_output(ForcedSpring::ENERGY).index(), u)].abs() < 1e-12);
    }
}

/// The nonlinear response `(δq(T), δv(T))` of `model` from `equilibrium` moved by `(dq, dv)`
/// (made consistent), against the linear model's `e^{A T} x0` mapped back through its bases.
fn simulated_against_linear<M: DenseModel + InputsOutputs>(
    model: &M,
    equilibrium: &State<M>,
    dq: &[f64],
    dv: &[f64],
    t_end: f64,
) -> (DVector<f64>, DVector<f64>)
where
    DefaultAllocator: Storage<M>,
{
    let lin = linearize(model, 0.0, equilibrium).expect("an equilibrium");
    let n = dq.len();
    let q0 = VecQ::<M>::from_fn(|i, _| equilibrium.q[i] + dq[i]);
    let v0 = VecQ::<M>::from_fn(|i, _| dv[i]);
    let start = consistent_state(model, 0.0, &q0, &v0, Consistency::default()).expect("consistent");
    let mut radau = Radau::new(model, RadauOptions::tolerances(1e-12, 1e-14)).expect("valid");
    let end = radau.solve(0.0, &start, t_end, &Sampling::Times(vec![t_end])).expect("integrates");
    let end = end.last().expect("a sample");
    let nonlinear =
        DVector::from_fn(2 * n, |i, _| if i < n { end.q[i] - equilibrium.q[i] } else { end.v[i - n] });
    // x0 from the consistent perturbed start, in the linear model's coordinates.
    let dq0 = DVector::from_fn(n, |i, _| start.q[i] - equilibrium.q[i]);
    let dv0 = DVector::from_fn(n, |i, _| start.v[i]);
    let (z0, w0) = (lin.positions.transpose() * dq0, lin.velocities.transpose() * dv0);
    let x0 = DVector::from_iterator(z0.len() + w0.len(), z0.iter().chain(w0.iter()).copied());
    let x = (&lin.a * t_end).exp() * x0;
    let nz = lin.positions_count();
    let dq = &lin.positions * x.rows(0, nz);
    let dv = &lin.velocities * x.rows(nz, x.len() - nz);
    let linear = DVector::from_iterator(2 * n, dq.iter().chain(dv.iter()).copied());
    (nonlinear, linear)
}

#[test]
fn both_pendulum_forms_predict_their_simulated_responses() {
    // Angle form, upright: a tilt of 1e-6 rad grows as cosh(√(g/l) t).
    let inverted = Inverted { m: 0.7, l: 0.9, g: 9.81, tau: 0.0 };
    let upright = at_rest(&inverted, &[0.0]);
    let (nonlinear, linear) = simulated_against_linear(&inverted, &upright, &[1e-6], &[0.0], 0.5);
    assert!((&nonlinear - &linear).amax() < 1e-4 * linear.amax(), "{nonlinear} against {linear}");
    // Cartesian form, hanging: a small push sideways; the rod's constraint keeps δy second
    // order, which the linear model (moving along the tangent) has as zero.
    let (m, g, l) = (1.3, 9.81, 0.8);
    let pendulum = Pendulum { m, g, l };
    let hanging = at_rest(&pendulum, &[0.0, -l]);
    let (nonlinear, linear) = simulated_against_linear(&pendulum, &hanging, &[0.0, 0.0], &[1e-6, 0.0], 0.7);
    assert!((&nonlinear - &linear).amax() < 1e-4 * linear.amax(), "{nonlinear} against {linear}");
}

/// A sparse model linearises as a dense one: the LC ladder at rest, whose frequencies are
/// known in closed form (`zoo::modal_solution`'s eigenpairs: `ω_k² = 4 sin²(θ_k/2)` with
/// `θ_k = (2k − 1)π/(2N + 1)` for unit cells).
#[test]
fn a_sparse_model_linearises_to_its_modes() {
    let n = 10;
    let ladder = crate::zoo::unit_ladder(n);
    let rest = crate::zoo::ladder_at_rest(&ladder, &[0.0; 10]);
    let linear = linearize(&ladder, 0.0, &rest).expect("a sparse model linearises");
    let eigenvalues = linear.a.complex_eigenvalues();
    assert!(eigenvalues.iter().all(|z| z.re.abs() < 1e-9), "undamped: {eigenvalues}");
    let mut squares: Vec<f64> = eigenvalues.iter().map(|z| z.im * z.im).filter(|&w| w > 1e-9).collect();
    squares.sort_by(f64::total_cmp);
    squares.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    let mut expected: Vec<f64> = (1..=n)
        .map(|k| {
            let theta = (2 * k - 1) as f64 * std::f64::consts::PI / (2 * n + 1) as f64;
            4.0 * (theta / 2.0).sin().powi(2)
        })
        .collect();
    expected.sort_by(f64::total_cmp);
    assert_eq!(squares.len(), n, "{squares:?}");
    for (w, e) in squares.iter().zip(&expected) {
        assert!((w - e).abs() < 1e-9, "{w} against {e}");
    }
}

/// The cart-pole in Cartesian coordinates: the cart at `x`, the bob at `(bx, by)` on a rod of
/// length `l` from the cart, the force `u` on the cart.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(x => vx, bx => vbx, by => vby), input(u), output(cart) = x)]
#[dirac(lagrangian = 0.5 * mc * vx * vx + 0.5 * mp * (vbx * vbx + vby * vby) - mp * g * by)]
#[dirac(force(x) = u, holonomic(rod) = (bx - x) * (bx - x) + by * by - l * l)]
struct CartesianCartPole {
    mc: f64,
    mp: f64,
    l: f64,
    g: f64,
    u: f64,
}

#[test]
fn linearize_in_named_coordinates_gives_the_textbook_matrices() {
    // By hand, upright in (x, bx), s = bx − x: by = √(l² − s²) ≈ l − s²/(2l), so the
    // potential is mp g l − mp g s²/(2l) and the kinetic energy ½ mc ẋ² + ½ mp ḃx² to second
    // order: mc ẍ = u − (mp g/l)(bx − x), mp b̈x = (mp g/l)(bx − x).
    let (mc, mp, l, g) = (1.5, 0.4, 0.6, 9.81);
    let cartesian = CartesianCartPole { mc, mp, l, g, u: 0.0 };
    let up = at_rest(&cartesian, &[0.2, 0.2, l]);
    let lin = linearize(&cartesian, 0.0, &up)
        .expect("an equilibrium")
        .in_coordinates(&cartesian, &[CartesianCartPole::X, CartesianCartPole::BX])
        .expect("they parametrise the rod");
    let (k1, k2) = (mp * g / (mc * l), g / l);
    #[rustfmt::skip]
    let a = DMatrix::from_row_slice(4, 4, &[
        0.0, 0.0, 1.0, 0.0,
        0.0, 0.0, 0.0, 1.0,
        k1, -k1, 0.0, 0.0,
        -k2, k2, 0.0, 0.0,
    ]);
    assert_close(&lin.a, &a, 1e-10);
    assert_close(&lin.b, &DMatrix::from_row_slice(4, 1, &[0.0, 0.0, 1.0 / mc, 0.0]), 1e-10);
    assert_close(&lin.c, &DMatrix::from_row_slice(1, 4, &[1.0, 0.0, 0.0, 0.0]), 1e-10);
    assert_eq!(lin.basis, dirac::Basis::Coordinates(vec!["x".into(), "bx".into()]));
    // δq from the named coordinates: by does not move to first order.
    assert_close(&lin.positions, &DMatrix::from_row_slice(3, 2, &[1.0, 0.0, 0.0, 1.0, 0.0, 0.0]), 1e-10);

    // The angle form of the same machine: the same eigenvalues and the same transfer
    // function from the force to the cart's position, G(s) = C (sI − A)⁻¹ B.
    let angle = CartPole { mc, mp, l, g, u: 0.0 };
    let polar = linearize(&angle, 0.0, &at_rest(&angle, &[0.2, 0.0])).expect("an equilibrium");
    let sorted = |a: &DMatrix<f64>| {
        let mut e: Vec<(f64, f64)> = a.complex_eigenvalues().iter().map(|z| (z.re, z.im)).collect();
        e.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.total_cmp(&y.1)));
        e
    };
    for (x, y) in sorted(&lin.a).iter().zip(sorted(&polar.a)) {
        assert!((x.0 - y.0).abs() < 1e-6 && (x.1 - y.1).abs() < 1e-6, "{x:?} against {y:?}");
    }
    let transfer = |lin: &dirac::Linearization, s: f64| {
        let resolvent = (DMatrix::identity(4, 4) * s - &lin.a).try_inverse().expect("s is no eigenvalue");
        (lin.c.rows(0, 1) * resolvent * &lin.b)[(0, 0)]
    };
    for s in [0.5, 1.7, 3.1, -2.2, 10.0] {
        let (g1, g2) = (transfer(&lin, s), transfer(&polar, s));
        assert!((g1 - g2).abs() < 1e-10 * (1.0 + g2.abs()), "G({s}) = {g1} against {g2}");
    }

    // Coordinates that do not parametrise the rod (the bob's height at the top) are refused.
    let error = linearize(&cartesian, 0.0, &up)
        .expect("an equilibrium")
        .in_coordinates(&cartesian, &[CartesianCartPole::X, CartesianCartPole::BY])
        .expect_err("the height is fixed to first order");
    assert!(error.to_string().contains("do not parametrise"), "{error}");
    // The same coordinate twice, and too few or too many, are refused by name and count.
    let lin = linearize(&cartesian, 0.0, &up).expect("an equilibrium");
    let twice =
        lin.in_coordinates(&cartesian, &[CartesianCartPole::X, CartesianCartPole::X]).expect_err("twice");
    assert!(twice.to_string().contains("do not parametrise"), "{twice}");
    for chosen in [
        &[][..],
        &[CartesianCartPole::X][..],
        &[CartesianCartPole::X, CartesianCartPole::BX, CartesianCartPole::BY][..],
    ] {
        let error = lin.in_coordinates(&cartesian, chosen).expect_err("a wrong count");
        assert!(error.to_string().contains("the constraints leave 2 free: name 2"), "{error}");
    }
}

mod from_parts {
    //! A DC motor from ten parts (source, resistor, inductor, EMF, ground, rotor, gear, load,
    //! bearing, housing: 17 coordinates, 22 rows) linearises with every node flux and flange
    //! angle; its minimal realisation is the motor's own second-order model. The reference is the
    //! motor's equations reduced by hand: `l di/dt = u − r i − k ω`,
    //! `(jm + jl/n²) dω/dt = k i − (b/n²) ω`.

    use dirac::components::electrical::{BranchInductor, Ground, Inductor, Resistor, VoltageSource};
    use dirac::components::electromechanical::Emf;
    use dirac::components::rotational::{Damper, Fixed, IdealGear, Inertia};
    use dirac::control;
    use dirac::nalgebra::{Complex, DMatrix};
    use dirac::prelude::*;

    const R: f64 = 1.0;
    const L: f64 = 0.05;
    const K: f64 = 0.5;
    const JM: f64 = 0.01;
    const JL: f64 = 0.05;
    const B: f64 = 0.1;
    const N: f64 = 4.0;

    #[derive(Interconnection, Clone, Debug)]
    #[dirac(
        connect(source.p, r.p), connect(r.n, l.p), connect(l.n, emf.p), connect(emf.n, ground.p),
        connect(source.n, ground.p), connect(emf.phi, rotor.phi), connect(rotor.phi, gear.a),
        connect(gear.b, load.phi), connect(load.phi, bearing.b), connect(bearing.a, housing.phi)
    )]
    struct Drive {
        source: VoltageSource,
        r: Resistor,
        l: Inductor,
        emf: Emf,
        ground: Ground,
        rotor: Inertia,
        gear: IdealGear,
        load: Inertia,
        bearing: Damper,
        housing: Fixed,
    }

    fn drive() -> Drive {
        Drive {
            source: VoltageSource { u: 0.0 },
            r: Resistor { r: R },
            l: Inductor { l: L },
            emf: Emf { k: K },
            ground: Ground {},
            rotor: Inertia { j: JM },
            gear: IdealGear { ratio: N },
            load: Inertia { j: JL },
            bearing: Damper { d: B },
            housing: Fixed { phi0: 0.0 },
        }
    }

    /// `(A, B)` of the hand-reduced motor in `(i, ω)`, the input the source's voltage.
    fn by_hand() -> (DMatrix<f64>, DMatrix<f64>) {
        let j = JM + JL / (N * N);
        let a = DMatrix::from_row_slice(2, 2, &[-R / L, -K / L, K / j, -B / (N * N) / j]);
        (a, DMatrix::from_column_slice(2, 1, &[1.0 / L, 0.0]))
    }

    #[test]
    fn the_parts_built_motor_has_the_hand_models_two_states_and_poles() {
        let model = drive();
        let zero = VecQ::<Drive>::zeros();
        let rest = consistent_state(&model, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
        let linear = linearize(&model, 0.0, &rest).expect("linearises");
        // The inductor's flux, the seven flange angles the holonomic rows leave free (the
        // connections hold their offsets by their rates) and the speed: 9 where every node flux
        // made 16, the levels of the fluxes that nothing reads not being states.
        assert_eq!(linear.a.nrows(), 9, "{:?}", linear.state_names());
        let minimal = linear.minreal(&model, 1e-9).expect("a minimal realisation");
        assert_eq!(
            minimal.a.nrows(),
            2,
            "{} states before, {:?} after",
            linear.a.nrows(),
            minimal.state_names()
        );
        let (a, b) = by_hand();
        let (got, expected) =
            (control::poles(&minimal.a).expect("poles"), control::poles(&a).expect("poles"));
        for (g, e) in got.iter().zip(&expected) {
            assert!((g - e).norm() < 1e-10 * e.norm(), "pole {g} against {e} (all: {got:?})");
        }
        // The transfer function from the voltage to the rotor's speed, both ways and against the
        // unreduced linearisation.
        let speed =
            Drive::NAMES.output_names().iter().position(|n| n == "rotor.momentum").expect("an output");
        let response = |a: &DMatrix<f64>, b: &DMatrix<f64>, c: &DMatrix<f64>, w: f64| {
            let complex = |m: &DMatrix<f64>| m.map(|x| Complex::new(x, 0.0));
            let n = a.nrows();
            let s = DMatrix::identity(n, n) * Complex::new(0.0, w) - complex(a);
            (complex(c) * s.lu().solve(&complex(b)).expect("regular"))[(0, 0)]
        };
        let momentum = |l: &Linearization| l.c.rows(speed, 1).into_owned();
        for w in [0.1, 3.0, 20.0, 400.0] {
            let hand = response(&a, &b, &DMatrix::from_row_slice(1, 2, &[0.0, JM]), w);
            for (what, l) in [("full", &linear), ("minimal", &minimal)] {
                let got = response(&l.a, &l.b, &momentum(l), w);
                assert!((got - hand).norm() < 1e-10 * hand.norm(), "{what} at ω = {w}: {got} against {hand}");
            }
        }
        // Every state is named, and reads what its name says: a velocity's row of the map from
        // the state is that state alone, an output's row of C too.
        let names = minimal.state_names();
        // In the model's order: the flux of the inductor's node (the current times `l`, the
        // ground's flux fixed), then the rotor's speed.
        assert_eq!(names, ["δq(l.p)", "δv(emf.phi)"]);
        let coordinates = Drive::NAMES.coordinate_names();
        let outputs = Drive::NAMES.output_names();
        for (i, name) in names.iter().enumerate() {
            let unit = DMatrix::from_fn(1, 2, |_, j| if i == j { 1.0 } else { 0.0 });
            let inside = |prefix: &str| name.strip_prefix(prefix).and_then(|n| n.strip_suffix(')'));
            let row = if let Some(c) = inside("δq(") {
                minimal
                    .positions
                    .row(coordinates.iter().position(|n| n == c).expect("a coordinate"))
                    .into_owned()
            } else if let Some(c) = inside("δv(") {
                minimal
                    .velocities
                    .row(coordinates.iter().position(|n| n == c).expect("a coordinate"))
                    .into_owned()
            } else if let Some(y) = inside("δy(") {
                minimal.c.row(outputs.iter().position(|n| n == y).expect("an output")).into_owned()
            } else {
                panic!("a state without a name: {names:?}")
            };
            assert!((&row - &unit).amax() < 1e-12, "{name} reads {row}");
        }
    }

    /// The same ten parts, reduced when the program compiles.
    #[derive(Interconnection, Clone, Debug)]
    #[dirac(reduce)]
    #[dirac(
        connect(source.p, r.p), connect(r.n, l.p), connect(l.n, emf.p), connect(emf.n, ground.p),
        connect(source.n, ground.p), connect(emf.phi, rotor.phi), connect(rotor.phi, gear.a),
        connect(gear.b, load.phi), connect(load.phi, bearing.b), connect(bearing.a, housing.phi)
    )]
    struct Reduced {
        source: VoltageSource,
        r: Resistor,
        l: Inductor,
        emf: Emf,
        ground: Ground,
        rotor: Inertia,
        gear: IdealGear,
        load: Inertia,
        bearing: Damper,
        housing: Fixed,
    }

    #[test]
    fn the_reduced_motor_linearises_to_its_physical_states_and_the_hand_models_poles() {
        let d = drive();
        let model = Reduced {
            source: d.source,
            r: d.r,
            l: d.l,
            emf: d.emf,
            ground: d.ground,
            rotor: d.rotor,
            gear: d.gear,
            load: d.load,
            bearing: d.bearing,
            housing: d.housing,
        };
        let zero = VecQ::<Reduced>::zeros();
        let rest = consistent_state(&model, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
        let linear = linearize(&model, 0.0, &rest).expect("linearises");
        // The load's angle and speed, and the flux of the node between resistor and inductor
        // (the current, times l, with the EMF's node `k n θ`): 3 states where the unreduced
        // motor has 16.
        assert_eq!(linear.a.nrows(), 3, "{:?}", linear.state_names());
        let (a, _) = by_hand();
        let expected = control::poles(&a).expect("poles");
        let got = control::poles(&linear.a).expect("poles");
        // One at zero (the load's angle, which nothing reads), then the motor's pair.
        let (zeros, motor): (Vec<&Complex<f64>>, Vec<&Complex<f64>>) =
            got.iter().partition(|p| p.norm() < 1e-10);
        assert_eq!(zeros.len(), 1, "{got:?}");
        for e in &expected {
            assert!(motor.iter().any(|g| (*g - e).norm() < 1e-10 * e.norm()), "no pole {e} in {got:?}");
        }
        // What the input reaches and the outputs see is the hand model's two states.
        let minimal = linear.minreal(&model, 1e-9).expect("a minimal realisation");
        assert_eq!(minimal.a.nrows(), 2, "{:?}", minimal.state_names());
    }

    /// The same ten parts with the inductor that carries its current as a coordinate's rate,
    /// reduced: one assembly for any inductance, zero included.
    #[derive(Interconnection, Clone, Debug)]
    #[dirac(reduce)]
    #[dirac(
        connect(source.p, r.p), connect(r.n, l.p), connect(l.n, emf.p), connect(emf.n, ground.p),
        connect(source.n, ground.p), connect(emf.phi, rotor.phi), connect(rotor.phi, gear.a),
        connect(gear.b, load.phi), connect(load.phi, bearing.b), connect(bearing.a, housing.phi)
    )]
    struct Branch {
        source: VoltageSource,
        r: Resistor,
        l: BranchInductor,
        emf: Emf,
        ground: Ground,
        rotor: Inertia,
        gear: IdealGear,
        load: Inertia,
        bearing: Damper,
        housing: Fixed,
    }

    fn branch(l: f64, u: f64) -> Branch {
        let d = drive();
        Branch {
            source: VoltageSource { u },
            r: d.r,
            l: BranchInductor { l },
            emf: d.emf,
            ground: d.ground,
            rotor: d.rotor,
            gear: d.gear,
            load: d.load,
            bearing: d.bearing,
            housing: d.housing,
        }
    }

    /// With inductance the motor has its 3 states (the current, the load's angle and speed)
    /// and the hand model's poles; with `l = 0` the same assembly has 2 (the angle and the
    /// speed) and the pole of `j ω̇ = k (u − k ω)/r − (b/n²) ω`, the hand model without its
    /// inductor. One pole at zero each time: the load's angle, which nothing reads.
    #[test]
    fn one_assembly_linearises_to_three_states_and_to_two_without_inductance() {
        let j = JM + JL / (N * N);
        for (l, states) in [(L, 3), (0.0, 2)] {
            let model = branch(l, 0.0);
            let zero = VecQ::<Branch>::zeros();
            let rest = consistent_state(&model, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
            let linear = linearize(&model, 0.0, &rest).expect("linearises");
            assert_eq!(linear.a.nrows(), states, "l = {l}: {:?}", linear.state_names());
            let expected = if l > 0.0 {
                control::poles(&by_hand().0).expect("poles")
            } else {
                vec![Complex::new(-(K * K / R + B / (N * N)) / j, 0.0)]
            };
            let got = control::poles(&linear.a).expect("poles");
            let (zeros, motor): (Vec<&Complex<f64>>, Vec<&Complex<f64>>) =
                got.iter().partition(|p| p.norm() < 1e-10);
            assert_eq!((zeros.len(), motor.len()), (1, expected.len()), "l = {l}: {got:?}");
            for e in &expected {
                assert!(motor.iter().any(|g| (*g - e).norm() < 1e-10 * e.norm()), "no pole {e} in {got:?}");
            }
        }
    }

    /// Without inductance the current follows the speed, `i = (u − k ω)/r`, and the speed the
    /// first-order step response `ω = ω∞ (1 − e^(−t/τ))` with `τ = j/(k²/r + b/n²)` and
    /// `ω∞ = (k u/r) τ/j`: Radau and Explicit at 1e-10 within 1e-7 of it.
    #[test]
    fn without_inductance_the_motor_is_first_order_on_every_integrator() {
        let (u, j) = (12.0, JM + JL / (N * N));
        let tau = j / (K * K / R + B / (N * N));
        let (top, times): (f64, Vec<f64>) = (K * u / R * tau / j, vec![0.01, 0.05, 0.1, 0.3]);
        let model = branch(0.0, u);
        let zero = VecQ::<Branch>::zeros();
        let start = consistent_state(&model, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
        let check = |what: &str, speed: &[f64], current: &[f64]| {
            for ((t, w), i) in times.iter().zip(speed).zip(current) {
                let exact = top * (1.0 - (-*t / tau).exp());
                assert!((w - exact).abs() < 1e-7 * top, "{what} at t = {t}: ω = {w} against {exact}");
                assert!((i - (u - K * w) / R).abs() < 1e-7 * u / R, "{what} at t = {t}: i = {i}");
            }
        };
        let sampling = Sampling::Times(times.clone());
        let radau = Radau::new(&model, RadauOptions::tolerances(1e-10, 1e-10))
            .expect("valid")
            .solve(0.0, &start, 0.3, &sampling)
            .expect("integrates");
        let explicit = Explicit::new(&model, ExplicitOptions::tolerances(1e-10, 1e-10))
            .expect("valid")
            .solve(0.0, &start, 0.3, &sampling)
            .expect("integrates");
        let read = |w: Option<&[f64]>, i: Option<&[f64]>| {
            (w.expect("the speed").to_vec(), i.expect("the current").to_vec())
        };
        let (w, i) = read(radau.column("rotor.w"), radau.column("l.i"));
        check("Radau", &w, &i);
        let (w, i) = read(explicit.column("rotor.w"), explicit.column("l.i"));
        check("Explicit", &w, &i);
    }

    #[test]
    fn minreal_refuses_a_tolerance_outside_zero_to_one() {
        let model = drive();
        let zero = VecQ::<Drive>::zeros();
        let rest = consistent_state(&model, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
        let linear = linearize(&model, 0.0, &rest).expect("linearises");
        for tolerance in [0.0, -1e-9, 1.0, f64::NAN, f64::INFINITY] {
            let error = linear.minreal(&model, tolerance).expect_err("not a tolerance");
            assert!(matches!(error, SimError::InvalidOption { what: "tolerance", .. }), "{error}");
        }
        // Another model than the one linearised: its names cannot name these states.
        let other = super::Inverted { m: 1.0, l: 1.0, g: 9.81, tau: 0.0 };
        let error = linear.minreal(&other, 1e-9).expect_err("another model");
        assert!(error.to_string().contains("pass the model that was linearised"), "{error}");
        // A non-finite entry is named.
        let mut broken = linear.clone();
        broken.a[(0, 1)] = f64::NAN;
        let error = broken.minreal(&model, 1e-9).expect_err("a NaN");
        assert!(error.to_string().contains("non-finite"), "{error}");
        // A minimal realisation names its own states; it does not take others.
        let minimal = linear.minreal(&model, 1e-9).expect("a minimal realisation");
        let error = minimal
            .in_coordinates(&model, &[model.coordinate("rotor.phi").expect("a coordinate")])
            .expect_err("already named");
        assert!(matches!(error, SimError::InvalidOption { what: "coordinates", .. }), "{error}");
    }
}
