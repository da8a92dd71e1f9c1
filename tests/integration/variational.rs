//! The variational integrator: order, constraints, long-time energy, momentum maps.
//!
//! References: the pendulum's published x(1), y(1) (DESIGN.md §3); the chain's exact modal
//! solution; momentum maps from the models' symmetries (Noether); energy from the models.

use dirac::State;
use dirac::prelude::*;

use crate::zoo::*;

fn pendulum_start(p: &Pendulum) -> State<Pendulum> {
    consistent_state(
        p,
        0.0,
        &VecQ::<Pendulum>::new(1.0, 0.0),
        &VecQ::<Pendulum>::zeros(),
        Consistency::default(),
    )
    .expect("consistent")
}

fn chain() -> Chain {
    paper_chain()
}

fn chain_start(c: &Chain) -> State<Chain> {
    let mut q = VecQ::<Chain>::zeros();
    q[0] = 0.1;
    consistent_state(c, 0.0, &q, &VecQ::<Chain>::zeros(), Consistency::default()).expect("consistent")
}

fn pendulum_error(h: f64) -> f64 {
    let p = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let mut vi = Variational::new(&p, h, VariationalOptions::default()).expect("valid");
    let sol = vi.solve(0.0, &pendulum_start(&p), 1.0, &Sampling::Times(vec![1.0])).expect("integrates");
    let (x, y) = (sol.q(Pendulum::X)[0], sol.q(Pendulum::Y)[0]);
    (x + 0.986_291_751_131_875_3).abs().max((y + 0.165_010_853_125_541_17).abs())
}

/// Errors at h, h/2, h/4 fall by 4 each time: order 2 (observed order within [1.9, 2.1]).
#[test]
fn second_order_on_the_pendulum() {
    let e: Vec<f64> = [1e-2, 5e-3, 2.5e-3].iter().map(|&h| pendulum_error(h)).collect();
    for w in e.windows(2) {
        let order = (w[0] / w[1]).log2();
        assert!((1.9..=2.1).contains(&order), "observed order {order} from errors {e:?}");
    }
}

#[test]
fn second_order_on_the_torn_chain() {
    let c = chain();
    let start = chain_start(&c);
    let reference = {
        let mut radau = Radau::new(&c, RadauOptions::tolerances(1e-13, 1e-14)).expect("valid");
        radau
            .solve(0.0, &start, 5.0, &Sampling::Times(vec![5.0]))
            .expect("integrates")
            .state(0)
            .expect("a sample")
    };
    let error = |h: f64| {
        let mut vi = Variational::new(&c, h, VariationalOptions::default()).expect("valid");
        let sol = vi.solve(0.0, &start, 5.0, &Sampling::Times(vec![5.0])).expect("integrates");
        (sol.state(0).expect("a sample").q - reference.q).amax()
    };
    let e: Vec<f64> = [1e-2, 5e-3, 2.5e-3].iter().map(|&h| error(h)).collect();
    for w in e.windows(2) {
        let order = (w[0] / w[1]).log2();
        assert!((1.9..=2.1).contains(&order), "observed order {order} from errors {e:?}");
    }
}

/// ‖φ(q_k)‖ ≤ 1e-12 at every step of a 10⁵-step pendulum run.
#[test]
fn holonomic_constraint_holds_at_every_step() {
    let p = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let mut vi = Variational::new(&p, 1e-3, VariationalOptions::default()).expect("valid");
    vi.start(0.0, &pendulum_start(&p), 100.0).expect("starts");
    let mut worst: f64 = 0.0;
    let mut phi = VecH::<Pendulum>::zeros();
    for _ in 0..100_000 {
        vi.step().expect("steps");
        p.holonomic(vi.t(), &vi.state().q, &mut phi);
        worst = worst.max(phi.amax());
    }
    assert!(worst <= 1e-12, "largest |phi| {worst:e}");
}

/// Total linear momentum of a free two-mass spring and the vertical angular momentum of a
/// spherical pendulum are conserved up to round-off accumulation.
#[test]
fn momentum_maps_are_conserved() {
    let s = FreeSpring { m1: 1.0, m2: 3.0, k: 7.0, d: 0.5 };
    let start = consistent_state(
        &s,
        0.0,
        &VecQ::<FreeSpring>::new(0.0, 1.2),
        &VecQ::<FreeSpring>::new(0.3, -0.7),
        Consistency::default(),
    )
    .expect("consistent");
    let mut vi = Variational::new(&s, 0.01, VariationalOptions::default()).expect("valid");
    let sol = vi.solve(0.0, &start, 100.0, &Sampling::Steps).expect("integrates");
    let total = |i: usize| sol.p(FreeSpring::X1)[i] + sol.p(FreeSpring::X2)[i];
    let drift = (0..sol.len()).map(|i| (total(i) - total(0)).abs()).fold(0.0, f64::max);
    assert!(drift < 1e-12, "linear momentum drift {drift:e}");

    let sp = SphericalPendulum { m: 1.0, g: 9.81, l: 1.0 };
    let q = VecQ::<SphericalPendulum>::new(0.6, 0.0, -0.8);
    let v = VecQ::<SphericalPendulum>::new(0.0, 1.5, 0.0);
    let start = consistent_state(&sp, 0.0, &q, &v, Consistency::default()).expect("consistent");
    let mut vi = Variational::new(&sp, 0.01, VariationalOptions::default()).expect("valid");
    let sol = vi.solve(0.0, &start, 100.0, &Sampling::Steps).expect("integrates");
    let lz = |i: usize| {
        sol.q(SphericalPendulum::X)[i] * sol.p(SphericalPendulum::Y)[i]
            - sol.q(SphericalPendulum::Y)[i] * sol.p(SphericalPendulum::X)[i]
    };
    let drift = (0..sol.len()).map(|i| (lz(i) - lz(0)).abs()).fold(0.0, f64::max);
    assert!(drift < 1e-11, "angular momentum drift {drift:e}");
}

/// Energy error of a run: the largest |E − E0| over the first and over the last 10% of steps.
fn energy_error_windows<M: DenseModel>(model: &M, start: &State<M>, h: f64, steps: usize) -> (f64, f64)
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut vi = Variational::new(model, h, VariationalOptions::default()).expect("valid");
    vi.start(0.0, start, h * steps as f64).expect("starts");
    let e0 = model.energy(0.0, &start.q, &start.v, &start.p);
    let window = steps / 10;
    let (mut first, mut last) = (0.0f64, 0.0f64);
    for k in 1..=steps {
        vi.step().expect("steps");
        let s = vi.state();
        let error = (model.energy(vi.t(), &s.q, &s.v, &s.p) - e0).abs();
        if k <= window {
            first = first.max(error);
        } else if k > steps - window {
            last = last.max(error);
        }
    }
    (first, last)
}

/// 10⁶ steps of the torn, interconnected chain (degenerate primitive system 2) and of the
/// pendulum: the energy error stays bounded, the last 10% no worse than 1.2× the first 10%.
#[test]
fn energy_error_is_bounded_over_a_million_steps() {
    let c = chain();
    let (first, last) = energy_error_windows(&c, &chain_start(&c), 0.02, 1_000_000);
    assert!(last <= 1.2 * first, "chain: first 10% {first:e}, last 10% {last:e}");
    let p = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let (first, last) = energy_error_windows(&p, &pendulum_start(&p), 0.01, 1_000_000);
    assert!(last <= 1.2 * first, "pendulum: first 10% {first:e}, last 10% {last:e}");
}

/// Models are flagged separable (`½ vᵀ M v − V`, constant M, no forces) from their structure;
/// the flags are constants, so these are checked when the test compiles.
#[test]
fn separability_is_read_from_the_model() {
    const {
        assert!(
            Pendulum::SEPARABLE
                && FreeSpring::SEPARABLE
                && SphericalPendulum::SEPARABLE
                && RollingDisk::SEPARABLE
        );
        // Both primitives are separable; the chain's mass matrix is singular, which the
        // integrator checks when it starts.
        assert!(Chain::SEPARABLE);
        // Its mass matrix depends on the angles.
        assert!(!Pendulum8::SEPARABLE);
        // It has forces.
        assert!(!DrivenOscillator::SEPARABLE);
        assert!(!AllFunctions::SEPARABLE);
    }
}

/// The shortcut for separable models solves the same discrete equations: pendulum and rolling
/// disk trajectories agree with the general Newton path to round-off.
#[test]
fn separable_shortcut_solves_the_same_equations() {
    let general = VariationalOptions { use_structure: false, ..VariationalOptions::default() };
    let p = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let start = pendulum_start(&p);
    let a = Variational::new(&p, 0.01, VariationalOptions::default())
        .expect("valid")
        .solve(0.0, &start, 5.0, &Sampling::Every(0.5))
        .expect("integrates");
    let b = Variational::new(&p, 0.01, general)
        .expect("valid")
        .solve(0.0, &start, 5.0, &Sampling::Every(0.5))
        .expect("integrates");
    for i in 0..a.len() {
        let (sa, sb) = (a.state(i).expect("sample"), b.state(i).expect("sample"));
        assert!((sa.q - sb.q).amax() < 1e-11 && (sa.p - sb.p).amax() < 1e-10, "sample {i}");
        assert!((sa.lambda - sb.lambda).amax() < 1e-8, "sample {i}: multipliers");
    }
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let v = VecQ::<RollingDisk>::new(0.6, 0.0, 2.0, 1.0);
    let start = consistent_state(&disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
        .expect("consistent");
    let a = Variational::new(&disk, 0.01, VariationalOptions::default())
        .expect("valid")
        .solve(0.0, &start, 5.0, &Sampling::Every(0.5))
        .expect("integrates");
    let b = Variational::new(&disk, 0.01, general)
        .expect("valid")
        .solve(0.0, &start, 5.0, &Sampling::Every(0.5))
        .expect("integrates");
    for i in 0..a.len() {
        let (sa, sb) = (a.state(i).expect("sample"), b.state(i).expect("sample"));
        assert!((sa.q - sb.q).amax() < 1e-11 && (sa.v - sb.v).amax() < 1e-10, "sample {i}");
    }
}

/// The rolling disk (nonholonomic): no slip at every step to 1e-10, and its energy, which the
/// discrete Lagrange-d'Alembert step keeps to second order, stays bounded over 10⁵ steps.
#[test]
fn rolling_disk_rolls_without_slipping() {
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let v = VecQ::<RollingDisk>::new(0.6, 0.0, 2.0, 1.0);
    let start = consistent_state(&disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
        .expect("consistent");
    let sol = Variational::new(&disk, 0.01, VariationalOptions::default())
        .expect("valid")
        .solve(0.0, &start, 1000.0, &Sampling::Every(1.0))
        .expect("integrates");
    assert!(sol.constraint_residual().iter().all(|r| *r < 1e-10), "slip");
    let e0 = sol.energy()[0];
    let worst = sol.energy().iter().map(|e| ((e - e0) / e0).abs()).fold(0.0, f64::max);
    assert!(worst < 1e-6, "relative energy error {worst:e}");
}

/// The LC circuit as a degenerate system closed by Kirchhoff's law: q_c follows cos t to
/// second order, and the charge error falls by four when h halves.
#[test]
fn lc_circuit_to_second_order() {
    let lc = LcCircuit { ind: 1.0, cap: 1.0 };
    let start = consistent_state(
        &lc,
        0.0,
        &VecQ::<LcCircuit>::new(1.0, 1.0),
        &VecQ::<LcCircuit>::zeros(),
        Consistency::default(),
    )
    .expect("consistent");
    let error = |h: f64| {
        let sol = Variational::new(&lc, h, VariationalOptions::default())
            .expect("valid")
            .solve(0.0, &start, 5.0, &Sampling::Times(vec![5.0]))
            .expect("integrates");
        (sol.q(LcCircuit::Q_C)[0] - 5f64.cos()).abs()
    };
    let (e1, e2) = (error(0.01), error(0.005));
    let order = (e1 / e2).log2();
    assert!((1.9..=2.1).contains(&order) && e1 < 1e-4, "errors {e1:e}, {e2:e}");
}

/// The discrete power balance: with damping and a drive, the change of energy over a run
/// equals the work of the forces, ∫ ⟨F, v⟩ dt (trapezoidal sum over the steps), to second
/// order: the mismatch falls by four when h halves.
#[test]
fn discrete_power_balance_is_second_order() {
    let osc = DrivenOscillator { m: 1.0, k: 2.0, c: 0.3, a: 0.5, w: 1.7 };
    let start = consistent_state(
        &osc,
        0.0,
        &VecQ::<DrivenOscillator>::new(1.0),
        &VecQ::<DrivenOscillator>::zeros(),
        Consistency::default(),
    )
    .expect("consistent");
    let mismatch = |h: f64| {
        let sol = Variational::new(&osc, h, VariationalOptions::default())
            .expect("valid")
            .solve(0.0, &start, 10.0, &Sampling::Steps)
            .expect("integrates");
        let (t, power, energy) = (sol.t(), sol.power(), sol.energy());
        let work: f64 = (1..sol.len()).map(|i| 0.5 * (power[i] + power[i - 1]) * (t[i] - t[i - 1])).sum();
        (energy[sol.len() - 1] - energy[0] - work).abs()
    };
    let (m1, m2) = (mismatch(0.01), mismatch(0.005));
    let order = (m1 / m2).log2();
    assert!((1.8..=2.2).contains(&order) && m1 < 1e-3, "mismatches {m1:e}, {m2:e}");
}

/// The multipliers the variational integrator reports are second-order accurate: against
/// Radau at tolerance 1e-12 (an independent method), the error in the pendulum's rod tension
/// falls by four when the step halves.
#[test]
fn multipliers_converge_at_second_order() {
    let p = crate::zoo::unit_pendulum();
    let start = crate::zoo::horizontal_start(&p);
    let sampling = Sampling::Every(1e-2);
    let mut radau = Radau::new(&p, RadauOptions::tolerances(1e-12, 1e-12)).expect("valid");
    let reference = radau.solve(0.0, &start, 1.0, &sampling).expect("integrates");
    let error = |h: f64| {
        let mut vi = Variational::new(&p, h, VariationalOptions::default()).expect("valid");
        let solution = vi.solve(0.0, &start, 1.0, &sampling).expect("integrates");
        let (a, b) = (solution.lambda(Pendulum::ROD), reference.lambda(Pendulum::ROD));
        a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max)
    };
    let (coarse, fine) = (error(5e-3), error(2.5e-3));
    let order = (coarse / fine).log2();
    assert!((order - 2.0).abs() < 0.2, "order {order:.3} (errors {coarse:e}, {fine:e})");
    assert!(fine < 2e-3, "largest error {fine:e} in a tension of about 30");
}

#[test]
fn a_step_beyond_the_stability_limit_ends_in_unstable_at_once() {
    // The paper's interconnected chain: its fastest mode has ω = 3.374 (the square root of the
    // largest eigenvalue, 11.38, of M⁻¹K with M = diag(1, 2, 3) and K = [9 −5 0; −5 11 −6;
    // 0 −6 6], by power iteration), so the method's limit h < 2/ω is 0.593. Beyond it the discrete solution grows
    // geometrically; a run used to succeed with the energy grown 10³¹-fold, or stop at NaN
    // after a hundred steps.
    let chain = crate::zoo::paper_chain();
    let start = crate::zoo::paper_chain_start(&chain);
    for h in [0.8, 1.5, 2.0, 3.0] {
        for t_end in [20.0, 200.0] {
            let mut vi = Variational::new(&chain, h, VariationalOptions::default()).expect("valid");
            match vi.solve(0.0, &start, t_end, &Sampling::Steps) {
                Err(SimError::Unstable { t, h: step, detail }) => {
                    assert!(t <= 4.0 * h, "h = {h}: found at t = {t}, after {} steps", t / h);
                    assert_eq!(step, h);
                    assert!(detail.contains("take a smaller step") && detail.contains("h < 2/ω"), "{detail}");
                }
                other => panic!("h = {h}, t_end = {t_end}: {:?}", other.map(|s| s.energy()[s.len() - 1])),
            }
        }
    }
    // Within the limit the same run ends, its energy bounded.
    for h in [0.05, 0.25] {
        let solution = Variational::new(&chain, h, VariationalOptions::default())
            .expect("valid")
            .solve(0.0, &start, 200.0, &Sampling::Steps)
            .expect("stable");
        let e0 = solution.energy()[0];
        assert!(solution.energy().iter().all(|e| (e - e0).abs() < 0.5 * e0), "h = {h}");
    }
}

/// A run whose energy is zero at the start is judged by the energy its motion exchanges, not by
/// the start's: the pendulum released from the horizontal (energy 0, the energy's parts near 0
/// again at the top of each swing) at h = 0.3 (h ω = 0.94 for small swings, inside the limit 2)
/// ends at t = 10, its energy within half of m g l (9.81, the kinetic energy at the bottom) of
/// 0, which is exact: the rod does no work. It used to end in `Unstable` at t = 10 ("the energy
/// went from 0 to −3.50"). The chain beyond its limit is still refused at once (the test above).
#[test]
fn a_stable_run_from_zero_energy_is_not_called_unstable() {
    let p = crate::zoo::unit_pendulum();
    let start = crate::zoo::horizontal_start(&p);
    for h in [0.1, 0.2, 0.3] {
        let solution = Variational::new(&p, h, VariationalOptions::default())
            .expect("valid")
            .solve(0.0, &start, 10.0, &Sampling::Steps)
            .unwrap_or_else(|e| panic!("h = {h}: {e}"));
        assert_eq!(solution.t()[solution.len() - 1], 10.0);
        let worst = solution.energy().iter().fold(0.0f64, |w, e| w.max(e.abs()));
        assert!(worst < 0.5 * 9.81, "h = {h}: the energy reached {worst:e}");
    }
}

#[test]
fn the_pendulum_converges_at_every_step_up_to_a_quarter_period() {
    // Released at 1 rad its period is 2.139 s (4 K(sin ½) / √g with the complete elliptic
    // integral K(0.479) = 1.6747, by the arithmetic-geometric mean); at steps above a seventh of
    // it RATTLE's projection of a step swinging through more than the rod's length has no
    // solution, and Newton diverged. Such steps are taken as sub-steps. Over one period every
    // step converges; over 10 s the step T/4 ends in `Unstable`, its energy 90% off after 16
    // steps, which is the answer such a step deserves.
    let pendulum = crate::zoo::unit_pendulum();
    let q = VecQ::<crate::zoo::Pendulum>::from([1f64.sin(), -1f64.cos()]);
    let start =
        consistent_state(&pendulum, 0.0, &q, &VecQ::<crate::zoo::Pendulum>::zeros(), Consistency::default())
            .expect("consistent");
    let period = 2.139;
    let mut substeps = 0;
    for k in [4.0, 5.0, 6.0, 7.0, 8.0, 12.0, 16.0, 32.0, 64.0] {
        let h = period / k;
        let solution = Variational::new(&pendulum, h, VariationalOptions::default())
            .expect("valid")
            .solve(0.0, &start, period, &Sampling::Steps)
            .unwrap_or_else(|e| panic!("h = T/{k}: {e}"));
        substeps += solution.stats.substeps;
        // Every state on the circle.
        let last = solution.last().expect("recorded");
        assert!((last.q.norm() - 1.0).abs() < 1e-10, "h = T/{k}");
    }
    assert!(substeps > 0, "some steps were sub-stepped");
}

/// Andrews' squeezing mechanism (Hairer & Wanner, *Solving ODEs II*, §VII.7; the Test Set for
/// IVP solvers, problem `andrews`), in its index-3 form: seven rigid bodies in the plane,
/// driven by the torque `mom` on the crank, with a spring between a point of body 3 and the
/// frame. The kinetic energy is `½ q̇ᵀ M(q) q̇` with the Test Set's mass matrix (its Coriolis
/// forces are the Euler-Lagrange equations of it), the spring a potential, the six loop
/// closures holonomic constraints; all constants in SI units as there.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(beta => bep, theta => thp, gamma => gap, phi => php, delta => dep, omega => omp, epsilon => epp))]
#[dirac(lagrangian = 0.5 * ((0.04325 * 92e-5 * 92e-5 + 0.00365 * (7e-3 * 7e-3 - 2.0 * 115e-4 * 7e-3 * theta.cos() + 115e-4 * 115e-4) + 2.194e-6 + 4.410e-7) * bep * bep
        + 2.0 * (0.00365 * (115e-4 * 115e-4 - 115e-4 * 7e-3 * theta.cos()) + 4.410e-7) * bep * thp
        + (0.00365 * 115e-4 * 115e-4 + 4.410e-7) * thp * thp
        + (0.02373 * (1874e-5 * 1874e-5 + 1043e-5 * 1043e-5) + 5.255e-6) * gap * gap
        + (0.00706 * (2e-2 - 1421e-5) * (2e-2 - 1421e-5) + 5.667e-7) * php * php
        + 2.0 * (0.00706 * ((2e-2 - 1421e-5) * (2e-2 - 1421e-5) + 4e-2 * (2e-2 - 1421e-5) * phi.sin()) + 5.667e-7) * php * dep
        + (0.00706 * (4e-2 * 4e-2 + 2.0 * 4e-2 * (2e-2 - 1421e-5) * phi.sin() + (2e-2 - 1421e-5) * (2e-2 - 1421e-5))
            + 0.07050 * (2308e-5 * 2308e-5 + 916e-5 * 916e-5) + 5.667e-7 + 1.169e-5) * dep * dep
        + (0.00706 * (2e-2 - 1421e-5) * (2e-2 - 1421e-5) + 5.667e-7) * omp * omp
        + 2.0 * (0.00706 * ((2e-2 - 1421e-5) * (2e-2 - 1421e-5) - 4e-2 * (2e-2 - 1421e-5) * omega.sin()) + 5.667e-7) * omp * epp
        + (0.00706 * ((2e-2 - 1421e-5) * (2e-2 - 1421e-5) - 2.0 * 4e-2 * (2e-2 - 1421e-5) * omega.sin() + 4e-2 * 4e-2)
            + 0.05498 * (1228e-5 * 1228e-5 + 449e-5 * 449e-5) + 5.667e-7 + 1.912e-5) * epp * epp)
    - 0.5 * 4530.0 * (((2e-2 * gamma.cos() + 18e-3 * gamma.sin() - 0.03635 - 0.014).powi(2)
        + (2e-2 * gamma.sin() - 18e-3 * gamma.cos() + 0.03273 - 0.072).powi(2)).sqrt() - 7785e-5).powi(2))]
#[dirac(force(beta) = 0.033)]
#[dirac(holonomic(g1) = 7e-3 * beta.cos() - 28e-3 * (beta + theta).cos() - 35e-3 * gamma.sin() + 0.03635)]
#[dirac(holonomic(g2) = 7e-3 * beta.sin() - 28e-3 * (beta + theta).sin() + 35e-3 * gamma.cos() - 0.03273)]
#[dirac(holonomic(g3) = 7e-3 * beta.cos() - 28e-3 * (beta + theta).cos() - 2e-2 * (phi + delta).sin() - 4e-2 * delta.cos() + 0.06934)]
#[dirac(holonomic(g4) = 7e-3 * beta.sin() - 28e-3 * (beta + theta).sin() + 2e-2 * (phi + delta).cos() - 4e-2 * delta.sin() + 0.00227)]
#[dirac(holonomic(g5) = 7e-3 * beta.cos() - 28e-3 * (beta + theta).cos() - 2e-2 * (omega + epsilon).cos() - 4e-2 * epsilon.sin() + 0.06934)]
#[dirac(holonomic(g6) = 7e-3 * beta.sin() - 28e-3 * (beta + theta).sin() - 2e-2 * (omega + epsilon).sin() + 4e-2 * epsilon.cos() + 0.00227)]
pub struct Squeezer {}

/// The Test Set's start (at rest, its 30 digits kept as published) and its reference positions
/// at t = 0.03 (PSIDE at rtol = atol = 1e-14).
#[allow(clippy::excessive_precision)]
const SQUEEZER_START: [f64; 7] = [
    -0.0617138900142764496358948458001,
    0.0,
    0.455279819163070380255912382449,
    0.222668390165885884674473185609,
    0.487364979543842550225598953530,
    -0.222668390165885884674473185609,
    1.23054744454982119249735015568,
];
const SQUEEZER_AT_0_03: [f64; 7] = [
    0.1581077119629904e2,
    -0.1575637105984298e2,
    0.4082224013073101e-1,
    -0.5347301163226948,
    0.5244099658805304,
    0.5347301163226948,
    0.1048080741042263e1,
];

fn squeezer_error(state: &State<Squeezer>) -> f64 {
    (0..7).map(|i| (state.q[i] - SQUEEZER_AT_0_03[i]).abs()).fold(0.0, f64::max)
}

fn squeezer_start() -> State<Squeezer> {
    let q = VecQ::<Squeezer>::from(SQUEEZER_START);
    consistent_state(&Squeezer {}, 0.0, &q, &VecQ::<Squeezer>::zeros(), Consistency::default())
        .expect("consistent")
}

#[test]
fn andrews_squeezer_transcribed_matches_the_test_set_through_radau() {
    // The model against the published reference, through Radau at a tight tolerance: the
    // transcription is right before the variational integrator is judged on it.
    let start = squeezer_start();
    let mut radau = Radau::new(&Squeezer {}, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let solution = radau.solve(0.0, &start, 0.03, &Sampling::Steps).expect("integrates");
    let error = squeezer_error(&solution.last().expect("recorded"));
    assert!(error < 1e-6, "{error:e}");
}

#[test]
fn andrews_squeezer_integrates_with_default_options_at_second_order() {
    let start = squeezer_start();
    let error = |h: f64| {
        let solution = Variational::new(&Squeezer {}, h, VariationalOptions::default())
            .expect("valid")
            .solve(0.0, &start, 0.03, &Sampling::Steps)
            .unwrap_or_else(|e| panic!("h = {h}: {e}"));
        squeezer_error(&solution.last().expect("recorded"))
    };
    // Measured: 3.1e-5 and 2.8e-6 (the largest angle error; the crank has turned 15.8 rad).
    // Newton used to diverge at the first step: its updates stalled at round-off above the
    // absolute tolerance on this model's scales.
    let (coarse, fine) = (error(1e-5), error(3e-6));
    assert!(coarse < 1e-4 && fine < 1e-5, "errors {coarse:e}, {fine:e}");
    let order = (coarse / fine).ln() / (1e-5f64 / 3e-6).ln();
    assert!((order - 2.0).abs() < 0.2, "order {order:.3} (errors {coarse:e}, {fine:e})");
}
