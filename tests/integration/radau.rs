//! The Radau IIA integrator against exact and published solutions.
//!
//! References: the pendulum's x(1), y(1) and period are the values of DESIGN.md §3 (elliptic
//! integrals, recomputable by anyone); the chain's exact solution comes from the generalised
//! eigenproblem of (M, K) solved here with nalgebra's symmetric eigensolver; the LC circuit's
//! is q = cos t; the rolling disk's energy is constant and its no-slip constraint exact.

use dirac::State;
use dirac::nalgebra::{Matrix3, SymmetricEigen, Vector3};
use dirac::prelude::*;

use crate::zoo::*;

fn pendulum_start(p: &Pendulum) -> State<Pendulum> {
    let (q, v) = (VecQ::<Pendulum>::new(1.0, 0.0), VecQ::<Pendulum>::zeros());
    consistent_state(p, 0.0, &q, &v, Consistency::default()).expect("consistent start")
}

/// Pendulum of length 1 released from rest at the horizontal: x(1), y(1) to 1e-9.
#[test]
fn pendulum_position_at_t_1() {
    let p = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let start = pendulum_start(&p);
    let mut radau = Radau::new(&p, RadauOptions::tolerances(1e-12, 1e-12)).expect("valid options");
    let sol = radau.solve(0.0, &start, 1.0, &Sampling::Times(vec![1.0])).expect("integrates");
    let (x, y) = (sol.q(Pendulum::X)[0], sol.q(Pendulum::Y)[0]);
    let (x_ref, y_ref) = (-0.986_291_751_131_875_3, -0.165_010_853_125_541_17);
    assert!((x - x_ref).abs() < 1e-9, "x(1) = {x}, reference {x_ref}, error {:e}", x - x_ref);
    assert!((y - y_ref).abs() < 1e-9, "y(1) = {y}, reference {y_ref}, error {:e}", y - y_ref);
}

/// The period, from two zero crossings of x located on the dense output: to 1e-9.
#[test]
fn pendulum_period() {
    let p = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let start = pendulum_start(&p);
    let mut radau = Radau::new(&p, RadauOptions::tolerances(1e-12, 1e-12)).expect("valid options");
    radau.start(0.0, &start, 3.0).expect("starts");
    let mut crossings = Vec::new();
    let mut y = State::<Pendulum>::zeros();
    while !radau.finished() && crossings.len() < 2 {
        let x_before = radau.state().q(Pendulum::X);
        let h = radau.step().expect("steps");
        let x_after = radau.state().q(Pendulum::X);
        if x_before.signum() != x_after.signum() {
            let (mut lo, mut hi) = (radau.t() - h, radau.t());
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                radau.interpolate(mid, &mut y);
                if y.q(Pendulum::X).signum() == x_before.signum() { lo = mid } else { hi = mid }
            }
            crossings.push(0.5 * (lo + hi));
        }
    }
    let period = 2.0 * (crossings[1] - crossings[0]);
    let reference = 2.367_841_947_576_237_4;
    assert!(
        (period - reference).abs() < 1e-9,
        "period {period}, reference {reference}, error {:e}",
        period - reference
    );
}

/// The exact solution of M ẍ = −K x, x(0) = x0, ẋ(0) = 0: with L = M^{-1/2}, the symmetric
/// eigensystem of L K L gives modes φ and ω², and x(t) = L Σ φ_k cos(ω_k t) φ_kᵀ L⁻¹ x0.
fn chain_exact(t: f64) -> Vector3<f64> {
    let (m, k) = ([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]);
    let kk = Matrix3::new(k[0] + k[1], -k[1], 0.0, -k[1], k[1] + k[2], -k[2], 0.0, -k[2], k[2]);
    let l = Matrix3::from_diagonal(&Vector3::new(m[0], m[1], m[2]).map(|x: f64| 1.0 / x.sqrt()));
    let eig = SymmetricEigen::new(l * kk * l);
    let x0 = Vector3::new(0.1, 0.0, 0.0);
    let u0 = l.try_inverse().expect("diagonal") * x0;
    let mut u = Vector3::zeros();
    for i in 0..3 {
        let phi = eig.eigenvectors.column(i);
        u += phi * (phi.dot(&u0) * (eig.eigenvalues[i].sqrt() * t).cos());
    }
    l * u
}

/// The paper's example, torn and interconnected, against the exact solution over [0, 20];
/// its energy is constant and the port efforts satisfy f̄2 = −k3 (x3 − x̄2) = −f2.
#[test]
fn torn_chain_matches_the_exact_solution() {
    let chain = paper_chain();
    let mut q = VecQ::<Chain>::zeros();
    q[Chain::left(Primitive1::X1).index()] = 0.1;
    let start = consistent_state(&chain, 0.0, &q, &VecQ::<Chain>::zeros(), Consistency::default())
        .expect("consistent");
    let mut radau = Radau::new(&chain, RadauOptions::tolerances(1e-13, 1e-14)).expect("valid options");
    let sol = radau.solve(0.0, &start, 20.0, &Sampling::Every(0.1)).expect("integrates");
    let (x1, x2, x2bar, x3) = (
        sol.q(Chain::left(Primitive1::X1)),
        sol.q(Chain::left(Primitive1::X2)),
        sol.q(Chain::right(Primitive2::X2BAR)),
        sol.q(Chain::right(Primitive2::X3)),
    );
    let mut worst: f64 = 0.0;
    for (i, &t) in sol.t().iter().enumerate() {
        let exact = chain_exact(t);
        worst =
            worst.max((x1[i] - exact[0]).abs()).max((x2[i] - exact[1]).abs()).max((x3[i] - exact[2]).abs());
        worst = worst.max((x2bar[i] - exact[1]).abs());
    }
    assert!(worst < 1e-8, "largest deviation from the exact solution {worst:e}");
    // The same chain written as one model matches the exact solution too.
    let whole = MassSpringChain { m1: 1.0, m2: 2.0, m3: 3.0, k1: 4.0, k2: 5.0, k3: 6.0 };
    let q = VecQ::<MassSpringChain>::new(0.1, 0.0, 0.0);
    let whole_start =
        consistent_state(&whole, 0.0, &q, &VecQ::<MassSpringChain>::zeros(), Consistency::default())
            .expect("consistent");
    let whole_sol = Radau::new(&whole, RadauOptions::tolerances(1e-13, 1e-14))
        .expect("valid")
        .solve(0.0, &whole_start, 20.0, &Sampling::Every(0.1))
        .expect("integrates");
    for (i, &t) in whole_sol.t().iter().enumerate() {
        let exact = chain_exact(t);
        for (c, k) in [(MassSpringChain::X1, 0), (MassSpringChain::X2, 1), (MassSpringChain::X3, 2)] {
            assert!((whole_sol.q(c)[i] - exact[k]).abs() < 1e-8, "monolithic x{} at t = {t}", k + 1);
        }
    }
    let e0 = sol.energy()[0];
    let drift = sol.energy().iter().map(|e| (e - e0).abs()).fold(0.0, f64::max) / e0;
    assert!(drift < 1e-9, "relative energy drift {drift:e}");
    let (f2, f2bar) = (
        sol.interconnection_force(Chain::LEFT_X2).expect("a port"),
        sol.interconnection_force(Chain::RIGHT_X2BAR).expect("a port"),
    );
    for i in 0..sol.len() {
        assert!((f2bar[i] + 6.0 * (x3[i] - x2bar[i])).abs() < 1e-8, "f2bar = -k3 (x3 - x2bar)");
        assert!((f2[i] + f2bar[i]).abs() < 1e-12, "f2 + f2bar = 0");
        assert!(sol.interconnection_power()[i].abs() < 1e-10, "Tellegen");
    }
}

/// An LC loop with L = C = 1, q(0) = 1, i(0) = 0: q_c = cos t.
#[test]
fn lc_circuit_is_a_cosine() {
    let lc = LcCircuit { ind: 1.0, cap: 1.0 };
    let q = VecQ::<LcCircuit>::new(1.0, 1.0);
    let start = consistent_state(&lc, 0.0, &q, &VecQ::<LcCircuit>::zeros(), Consistency::default())
        .expect("consistent");
    let mut radau = Radau::new(&lc, RadauOptions::tolerances(1e-12, 1e-12)).expect("valid options");
    let sol = radau.solve(0.0, &start, 10.0, &Sampling::Every(0.25)).expect("integrates");
    for (t, q_c) in sol.t().iter().zip(sol.q(LcCircuit::Q_C)) {
        assert!((q_c - t.cos()).abs() < 1e-9, "q_c({t}) = {q_c}, cos t = {}", t.cos());
    }
}

/// The vertical rolling disk: energy constant to 1e-9 and no slip to 1e-10 throughout.
#[test]
fn rolling_disk_conserves_energy_and_rolls() {
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let mut v = VecQ::<RollingDisk>::zeros();
    v[RollingDisk::THETA.index()] = 2.0;
    v[RollingDisk::PHI.index()] = 1.0;
    v[RollingDisk::X.index()] = 0.6;
    let start = consistent_state(&disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
        .expect("consistent");
    assert_eq!(start.v, v, "already consistent: ẋ = r cos φ θ̇, ẏ = r sin φ θ̇ at φ = 0");
    let mut radau = Radau::new(&disk, RadauOptions::tolerances(1e-11, 1e-12)).expect("valid options");
    let sol = radau.solve(0.0, &start, 20.0, &Sampling::Steps).expect("integrates");
    let e0 = sol.energy()[0];
    for (e, slip) in sol.energy().iter().zip(sol.constraint_residual()) {
        assert!(((e - e0) / e0).abs() < 1e-9, "energy {e} vs {e0}");
        assert!(*slip < 1e-10, "slip {slip:e}");
    }
    // The disk turns at a constant rate and its contact point runs on a circle of radius
    // r θ̇ / φ̇ = 0.6: x = 0.6 sin t, y = 0.6 (1 − cos t).
    let last = sol.len() - 1;
    let t = sol.t()[last];
    assert!((sol.q(RollingDisk::X)[last] - 0.6 * t.sin()).abs() < 1e-8);
    assert!((sol.q(RollingDisk::Y)[last] - 0.6 * (1.0 - t.cos())).abs() < 1e-8);
}

/// Bad input is a typed error, never a panic.
#[test]
fn invalid_input_is_a_typed_error() {
    let p = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    assert!(matches!(
        Radau::new(&p, RadauOptions::tolerances(-1.0, 1e-8)),
        Err(SimError::InvalidTolerance { what: "rtol", .. })
    ));
    assert!(matches!(
        Radau::new(&p, RadauOptions::tolerances(1e-6, f64::NAN)),
        Err(SimError::InvalidTolerance { what: "atol", .. })
    ));
    let start = pendulum_start(&p);
    let mut radau = Radau::new(&p, RadauOptions::default()).expect("valid");
    assert!(matches!(radau.solve(1.0, &start, 0.0, &Sampling::Steps), Err(SimError::InvalidTimeSpan { .. })));
    assert!(matches!(
        radau.solve(0.0, &start, 1.0, &Sampling::Times(vec![0.5, 0.2])),
        Err(SimError::InvalidSampling { .. })
    ));
    let q = VecQ::<Pendulum>::new(f64::NAN, 0.0);
    let err = consistent_state(&p, 0.0, &q, &VecQ::<Pendulum>::zeros(), Consistency::default()).err();
    assert_eq!(err, Some(SimError::NonFinite { t: 0.0, component: "x".into() }));
}

/// Global error tracks the tolerance: over rtol = atol = 1e-4 … 1e-12 the pendulum's error at
/// t = 1 stays within two decades below and one above the tolerance, and falls with it. Run
/// with `--nocapture` to see the table recorded in BENCHMARKS.md.
#[test]
fn global_error_tracks_tolerance() {
    let p = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let start = pendulum_start(&p);
    let (x_ref, y_ref) = (-0.986_291_751_131_875_3, -0.165_010_853_125_541_17);
    let mut previous = f64::INFINITY;
    println!("tolerance  error(t=1)  steps  rejected");
    for k in [4, 6, 8, 10, 12] {
        let tol = 10f64.powi(-k);
        let mut radau = Radau::new(&p, RadauOptions::tolerances(tol, tol)).expect("valid options");
        let sol = radau.solve(0.0, &start, 1.0, &Sampling::Times(vec![1.0])).expect("integrates");
        let err = (sol.q(Pendulum::X)[0] - x_ref).abs().max((sol.q(Pendulum::Y)[0] - y_ref).abs());
        println!("{tol:9.0e}  {err:10.2e}  {:5}  {:8}", sol.stats.steps, sol.stats.rejected);
        assert!(err < 10.0 * tol && err > 1e-3 * tol, "error {err:e} at tolerance {tol:e}");
        assert!(err < previous, "error falls with the tolerance");
        previous = err;
    }
}

/// The condensed and the full Newton solver take the same first steps to within the Newton
/// iteration's tolerance, and
/// whole trajectories agree to well within the tolerance: condensation changes the cost of a
/// step, not its result. (Round-off can flip a step-size decision later on, after which the two
/// runs take different but equally accurate steps.)
#[test]
fn condensed_and_full_solvers_agree() {
    let chain = paper_chain();
    let start = paper_chain_start(&chain);
    let options = RadauOptions::tolerances(1e-8, 1e-10);
    let full = || dirac::runtime::newton::Full::<Chain>::default();
    let mut a = Radau::new(&chain, options).expect("valid");
    let mut b = Radau::with_solver(&chain, options, full()).expect("valid");
    a.start(0.0, &start, 10.0).expect("starts");
    b.start(0.0, &start, 10.0).expect("starts");
    for _ in 0..5 {
        let (ha, hb) = (a.step().expect("steps"), b.step().expect("steps"));
        assert!((ha - hb).abs() <= 1e-9 * ha, "step sizes {ha} and {hb}");
        // Within the Newton iteration's stopping criterion (the two solvers' iterates differ in
        // their last bits, and each stops within its tolerance): 1.0e-12 measured.
        let difference = (a.state().to_y() - b.state().to_y()).amax();
        assert!(difference < 1e-11, "states differ by {difference:e}");
    }
    let sampling = Sampling::Every(1.0);
    let sa =
        Radau::new(&chain, options).expect("valid").solve(0.0, &start, 10.0, &sampling).expect("integrates");
    let sb = Radau::with_solver(&chain, options, full())
        .expect("valid")
        .solve(0.0, &start, 10.0, &sampling)
        .expect("integrates");
    for i in 0..sa.len() {
        let dq = (sa.state(i).expect("a sample").q - sb.state(i).expect("a sample").q).amax();
        assert!(dq < 1e-7, "sample {i}: q differs by {dq:e}");
    }
}

/// A force that blows up at t = 1: the integration stops there with a typed error that says
/// when, never a panic or a silent NaN.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * v * v)]
#[dirac(force(x) = 1.0 / (1.0 - t))]
struct BlowUp {}

#[test]
fn failing_integrations_are_typed_errors_that_say_when() {
    let model = BlowUp {};
    let start = consistent_state(
        &model,
        0.0,
        &VecQ::<BlowUp>::zeros(),
        &VecQ::<BlowUp>::zeros(),
        Consistency::default(),
    )
    .expect("consistent");
    let err = Radau::new(&model, RadauOptions::default())
        .expect("valid")
        .solve(0.0, &start, 2.0, &Sampling::Steps)
        .err();
    let t = match err {
        Some(
            SimError::StepSizeTooSmall { t, .. }
            | SimError::NonFinite { t, .. }
            | SimError::NewtonDiverged { t, .. },
        ) => t,
        other => panic!("expected a failure near t = 1, got {other:?}"),
    };
    assert!((0.99..=1.0).contains(&t), "failed at t = {t}");

    let p = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let options = RadauOptions { max_steps: 10, ..RadauOptions::default() };
    let err = Radau::new(&p, options)
        .expect("valid")
        .solve(0.0, &pendulum_start(&p), 100.0, &Sampling::Steps)
        .err();
    assert!(matches!(err, Some(SimError::TooManySteps { max_steps: 10, .. })), "{err:?}");
}

/// A coordinate without inertia that no constraint determines makes every iteration matrix
/// singular: the error names its velocity.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, free => v_free), port(free))]
#[dirac(lagrangian = 0.5 * vx * vx - 0.5 * x * x)]
struct Undetermined {}

#[test]
fn singular_iteration_matrix_names_the_unknown() {
    let model = Undetermined {};
    let mut start = State::<Undetermined>::zeros();
    start.set_q(Undetermined::X, 1.0);
    let err = Radau::new(&model, RadauOptions::default())
        .expect("valid")
        .solve(0.0, &start, 1.0, &Sampling::Steps)
        .err();
    match err {
        Some(SimError::SingularMatrix { t, detail, .. }) => {
            assert_eq!(t, 0.0);
            assert!(detail.contains("`v_free`"), "{detail}");
        }
        other => panic!("expected a singular matrix, got {other:?}"),
    }
}

/// A simulated solution curve of the torn chain lies in the interconnected Dirac structure
/// (eq. 2) at sampled points: q̇ and ṗ are estimated by central differences of the sampled
/// q(t) and p(t) (independently of the equations), α = (−∂L/∂q − F, v), and the membership
/// residuals are at the level of the difference formula's error.
#[test]
fn simulated_curve_lies_in_the_dirac_structure() {
    let chain = paper_chain();
    let start = paper_chain_start(&chain);
    let dt = 1e-4;
    let times: Vec<f64> = [1.0, 4.0, 9.0].iter().flat_map(|&t| [t - dt, t, t + dt]).collect();
    let sol = Radau::new(&chain, RadauOptions::tolerances(1e-13, 1e-14))
        .expect("valid")
        .solve(0.0, &start, 10.0, &Sampling::Times(times))
        .expect("integrates");
    let omega = dirac::nalgebra::DMatrix::from_row_slice(1, 4, &[0.0, 1.0, -1.0, 0.0]);
    for k in 0..3 {
        let (before, at, after) = (
            sol.state(3 * k).expect("sample"),
            sol.state(3 * k + 1).expect("sample"),
            sol.state(3 * k + 2).expect("sample"),
        );
        let qdot: Vec<f64> = ((after.q - before.q) / (2.0 * dt)).iter().copied().collect();
        let pdot: Vec<f64> = ((after.p - before.p) / (2.0 * dt)).iter().copied().collect();
        let (mut dl_dq, mut force) = (VecQ::<Chain>::zeros(), VecQ::<Chain>::zeros());
        chain.dl_dq(0.0, &at.q, &at.v, &mut dl_dq);
        chain.force(0.0, &at.q, &at.v, &mut force);
        let beta: Vec<f64> = (-(dl_dq + force)).iter().copied().collect();
        let u: Vec<f64> = at.v.iter().copied().collect();
        let q1 = VecQ::<Primitive1>::new(at.q[0], at.q[1]);
        let q2 = VecQ::<Primitive2>::new(at.q[2], at.q[3]);
        let dc = DiracStructure::of_model(&chain.left, 0.0, &q1)
            .product(&DiracStructure::of_model(&chain.right, 0.0, &q2))
            .interconnect(&omega);
        let membership = dc.membership(&qdot, &pdot, &beta, &u);
        assert!(membership.max() < 1e-7, "sample {k}: {membership:?}");
    }
}

/// A chaotic double pendulum over a long run at a loose tolerance: the step size must never
/// collapse. Two things once made it: at small steps the multipliers' pivots of an unscaled
/// condensed matrix fell far below the velocities' and were taken for singular (the matrix is
/// now equilibrated); and when a multiplier crossed zero, the constraint remainder that
/// Newton's tolerance leaves in a state entered the error estimate at 1/h (the estimate now
/// measures algebraic rows from that remainder).
#[test]
fn chaotic_double_pendulum_runs_through() {
    let model = DoublePendulum { m1: 1.0, m2: 1.0, l1: 1.0, l2: 1.0, g: 9.81 };
    let q = VecQ::<DoublePendulum>::new(1.0, 0.0, 2.0, 0.0);
    let start = consistent_state(&model, 0.0, &q, &VecQ::<DoublePendulum>::zeros(), Consistency::default())
        .expect("consistent");
    let sol = Radau::new(&model, RadauOptions::tolerances(1e-6, 1e-8))
        .expect("valid")
        .solve(0.0, &start, 1000.0, &Sampling::Every(1.0))
        .expect("integrates");
    let e0 = sol.energy()[0];
    let worst = sol.energy().iter().map(|e| (e - e0).abs()).fold(0.0, f64::max);
    assert!(worst < 1e-2, "energy error {worst:e} over a chaotic run at tol 1e-6");
    assert!(sol.t().last().is_some_and(|t| (t - 1000.0).abs() < 1e-9), "reached the end");
}
