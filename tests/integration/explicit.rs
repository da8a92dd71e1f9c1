//! The explicit integrator (`Explicit`): order on exact solutions, constraints kept, dense
//! output, and clear errors where it does not apply.
//!
//! References, none computed by dirac: the pendulum's published x(1), y(1) (DESIGN.md §3); the
//! torn chain's exact modal solution (eigen-decomposition of M⁻¹K, as in
//! `benches/work_precision.rs`); the rolling disk's closed-form motion (constant spin and
//! turning rates, the contact point on a circle of radius r v_θ / v_φ).

use dirac::ExplicitStats;
use dirac::nalgebra::{Matrix3, SymmetricEigen, Vector3};
use dirac::prelude::*;

use crate::zoo::*;

/// The pendulum's published position at t = 1 (DESIGN.md §3), released from the horizontal.
const PENDULUM_AT_1: (f64, f64) = (-0.986_291_751_131_875_3, -0.165_010_853_125_541_17);

/// x1, x2, x3 of the chain wall–k1–m1–k2–m2–k3–m3 (m = 1, 2, 3; k = 4, 5, 6) at `t`, from
/// x1(0) = 0.1 at rest, by the eigensystem of M^{-1/2} K M^{-1/2}.
fn chain_exact(t: f64) -> Vector3<f64> {
    let (m, k) = ([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]);
    let kk = Matrix3::new(k[0] + k[1], -k[1], 0.0, -k[1], k[1] + k[2], -k[2], 0.0, -k[2], k[2]);
    let l = Matrix3::from_diagonal(&Vector3::new(m[0], m[1], m[2]).map(|x: f64| 1.0 / x.sqrt()));
    let eig = SymmetricEigen::new(l * kk * l);
    let u0 =
        Matrix3::from_diagonal(&Vector3::new(m[0], m[1], m[2]).map(f64::sqrt)) * Vector3::new(0.1, 0.0, 0.0);
    let mut u = Vector3::zeros();
    for i in 0..3 {
        let phi = eig.eigenvectors.column(i);
        u += phi * (phi.dot(&u0) * (eig.eigenvalues[i].sqrt() * t).cos());
    }
    l * u
}

fn chain_error(options: ExplicitOptions, t_end: f64) -> (f64, ExplicitStats) {
    let chain = paper_chain();
    let start = paper_chain_start(&chain);
    let mut explicit = Explicit::new(&chain, options).expect("valid options");
    let sol = explicit.solve(0.0, &start, t_end, &Sampling::Times(vec![t_end])).expect("integrates");
    let exact = chain_exact(t_end);
    let masses = [Chain::left(Primitive1::X1), Chain::left(Primitive1::X2), Chain::right(Primitive2::X3)];
    let error = masses.iter().enumerate().map(|(i, c)| (sol.q(*c)[0] - exact[i]).abs()).fold(0.0, f64::max);
    (error, sol.stats)
}

fn pendulum_error(options: ExplicitOptions) -> (f64, ExplicitStats) {
    let p = unit_pendulum();
    let mut explicit = Explicit::new(&p, options).expect("valid options");
    let sol =
        explicit.solve(0.0, &horizontal_start(&p), 1.0, &Sampling::Times(vec![1.0])).expect("integrates");
    let (x, y) = (sol.q(Pendulum::X)[0], sol.q(Pendulum::Y)[0]);
    ((x - PENDULUM_AT_1.0).abs().max((y - PENDULUM_AT_1.1).abs()), sol.stats)
}

/// The rolling disk's exact motion: v_θ, v_φ constant, φ = φ0 + v_φ t, and the contact point
/// runs on a circle, ẋ = r v_θ cos φ, ẏ = r v_θ sin φ.
fn disk_exact(disk: &RollingDisk, start: (f64, f64), t: f64) -> [f64; 4] {
    let (v_theta, v_phi) = start;
    let phi = v_phi * t;
    let radius = disk.r * v_theta / v_phi;
    [radius * phi.sin(), radius * (1.0 - phi.cos()), v_theta * t, phi]
}

fn disk_start(disk: &RollingDisk, (v_theta, v_phi): (f64, f64)) -> State<RollingDisk> {
    let mut v = VecQ::<RollingDisk>::zeros();
    v[RollingDisk::THETA.index()] = v_theta;
    v[RollingDisk::PHI.index()] = v_phi;
    v[RollingDisk::X.index()] = disk.r * v_theta;
    consistent_state(disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
        .expect("consistent")
}

fn disk_error(h: f64) -> f64 {
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let rates = (2.0, 1.5);
    let mut explicit = Explicit::new(&disk, ExplicitOptions::fixed(h)).expect("valid options");
    let sol =
        explicit.solve(0.0, &disk_start(&disk, rates), 4.0, &Sampling::Times(vec![4.0])).expect("integrates");
    let exact = disk_exact(&disk, rates, 4.0);
    let state = sol.state(0).expect("a sample");
    (0..4).map(|i| (state.q[i] - exact[i]).abs()).fold(0.0, f64::max)
}

/// The observed orders of a sequence of errors at halved steps.
fn orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect()
}

/// Fixed steps h, h/2, h/4 on three exact solutions: errors fall by 2⁵ each time (observed
/// order within [4.6, 5.4]): the holonomic pendulum (projected every step), the nonholonomic
/// rolling disk, and the interconnected chain, whose second part is degenerate.
#[test]
fn fifth_order_on_holonomic_nonholonomic_and_interconnected_models() {
    let pendulum: Vec<f64> =
        [0.04, 0.02, 0.01].iter().map(|&h| pendulum_error(ExplicitOptions::fixed(h)).0).collect();
    let disk: Vec<f64> = [0.2, 0.1, 0.05].iter().map(|&h| disk_error(h)).collect();
    let chain: Vec<f64> =
        [0.05, 0.025, 0.0125].iter().map(|&h| chain_error(ExplicitOptions::fixed(h), 5.0).0).collect();
    for (name, errors) in [("pendulum", &pendulum), ("rolling disk", &disk), ("chain", &chain)] {
        for order in orders(errors) {
            assert!((4.6..=5.4).contains(&order), "{name}: observed order {order} from errors {errors:?}");
        }
    }
}

/// With step-size control the achieved error follows the tolerance: within 30× of it on the
/// pendulum and the chain, and tighter tolerances cost more steps.
#[test]
fn adaptive_steps_follow_the_tolerance() {
    let mut steps = 0;
    for tol in [1e-5, 1e-7, 1e-9] {
        let (error, stats) = pendulum_error(ExplicitOptions::tolerances(tol, tol));
        assert!(error < 30.0 * tol, "pendulum: error {error:e} at tolerance {tol:e}");
        assert!(stats.steps > steps, "pendulum: {} steps at {tol:e} after {steps}", stats.steps);
        steps = stats.steps;
        let (error, _) = chain_error(ExplicitOptions::tolerances(tol, tol), 20.0);
        assert!(error < 30.0 * tol, "chain: error {error:e} at tolerance {tol:e}");
    }
}
