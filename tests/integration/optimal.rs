//! Optimal control by DMOC and by Radau IIA collocation: the transcriptions' Jacobians and
//! Lagrangian Hessians against central differences of their own equations and gradients, a
//! cart-pole swing-up solved by IPOPT and replayed by the variational integrator (DMOC) and by
//! Radau (collocation) with the inputs found, momentum maps kept or not, and the typed errors
//! of malformed problems.

use dirac::optimal::interior::InteriorOptions;
use dirac::optimal::ipopt::IpoptOptions;
use dirac::optimal::{Collocation, Dmoc, Mpc, Nlp, OptimalError, Problem};
use dirac::prelude::*;

use crate::zoo::robots::{PandaTorques, panda_point_to_point};
use crate::zoo::{Acrobot, CartPole, acrobot, cart_pole, cart_pole_balance, unit_pendulum};

/// Installs IPOPT's library from Debian's packages if it is missing (`.ci/ipopt.sh`), before
/// anything in this process tries to load it: a newcomer's `cargo test` needs nothing more.
fn with_ipopt() {
    static INSTALL: std::sync::Once = std::sync::Once::new();
    INSTALL.call_once(|| {
        let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../.ci/ipopt.sh");
        let status = std::process::Command::new("bash").arg(script).status().expect("bash runs");
        assert!(status.success(), "{script} could not install IPOPT (coinor-libipopt-dev)");
    });
}

/// A model whose inputs enter its Lagrangian, its momenta and its forces, so that every block
/// of the transcription's derivatives (`∂²L/∂q∂u`, `∂²L/∂v∂u`, `∂F/∂u`) is exercised: a
/// mass on a spring whose anchor `a` moves, in a field coupling `b` to its velocity, with a
/// damper and a push `f` that grows with the position.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v, y => vy), input(a), input(b), input(f))]
#[dirac(lagrangian = 0.5 * m * (v * v + vy * vy) + b * x * vy - 0.5 * k * (x - a).powi(2)
    - 0.5 * k * (y - x).powi(2) + a * b * sin(y) * v)]
#[dirac(force(x) = -c * v * v * v + f * (1.0 + 0.1 * y * y), force(y) = -c * vy + a * f * x)]
pub struct Steered {
    pub m: f64,
    pub k: f64,
    pub c: f64,
    pub a: f64,
    pub b: f64,
    pub f: f64,
}

/// The swing-up: from hanging at rest at `x = 0` to upright at rest at `x = 0` in 2 s, with
/// the cart within ±1.5 m and the push within ±20 N.
fn swing_up(intervals: usize) -> Problem<CartPole> {
    Problem::new(cart_pole(), 2.0, intervals)
        .final_state(VecQ::<CartPole>::from([0.0, std::f64::consts::PI]), VecQ::<CartPole>::zeros())
        .position_bounds(CartPole::X, -1.5, 1.5)
        .input_bounds(CartPole::F, -20.0, 20.0)
}

/// A deterministic point away from any symmetry.
fn scattered(len: usize, seed: f64) -> Vec<f64> {
    (0..len).map(|i| (seed + 1.7 * i as f64).sin() * 0.8 + 0.1 * i as f64 / len as f64).collect()
}

/// `max |a − b|` relative to `max(1, max |b|)`.
fn relative_gap(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / scale
}

/// The sparse Jacobian as a dense matrix, row-major.
fn dense_jacobian(nlp: &mut impl Nlp, z: &[f64]) -> Vec<f64> {
    let (n, m) = (nlp.variables(), nlp.constraints());
    let pattern = nlp.jacobian_pattern().to_vec();
    let mut values = vec![0.0; pattern.len()];
    nlp.jacobian_values(z, &mut values);
    let mut dense = vec![0.0; m * n];
    for (&(r, c), v) in pattern.iter().zip(values) {
        dense[r * n + c] += v;
    }
    dense
}

/// Checks the cost's gradient against central differences of the cost, the Jacobian against
/// central differences of the constraint values, and the
/// Lagrangian's Hessian against central differences of its gradient `σ∇f + Jᵀμ` (built from
/// the Jacobian just checked).
fn check_derivatives(nlp: &mut impl Nlp, z: &[f64], tol: f64) {
    let (n, m) = (nlp.variables(), nlp.constraints());
    let eps = 1e-6;
    let mut gradient = vec![0.0; n];
    nlp.gradient(z, &mut gradient);
    let fd_gradient: Vec<f64> = (0..n)
        .map(|c| {
            let mut zp = z.to_vec();
            zp[c] += eps;
            let plus = nlp.objective(&zp);
            zp[c] -= 2.0 * eps;
            (plus - nlp.objective(&zp)) / (2.0 * eps)
        })
        .collect();
    let gap = relative_gap(&gradient, &fd_gradient);
    assert!(gap < tol, "the cost's gradient against central differences: {gap:e}");
    let jacobian = dense_jacobian(nlp, z);
    let mut fd = vec![0.0; m * n];
    let (mut plus, mut minus) = (vec![0.0; m], vec![0.0; m]);
    for c in 0..n {
        let mut zp = z.to_vec();
        zp[c] += eps;
        nlp.constraint_values(&zp, &mut plus);
        zp[c] -= 2.0 * eps;
        nlp.constraint_values(&zp, &mut minus);
        for r in 0..m {
            fd[r * n + c] = (plus[r] - minus[r]) / (2.0 * eps);
        }
    }
    let gap = relative_gap(&jacobian, &fd);
    assert!(gap < tol, "Jacobian against central differences: {gap:e}");

    let sigma = 0.7;
    let mu = scattered(m, 0.3);
    let lagrangian_gradient = |nlp: &mut dyn FnMut(&[f64]) -> Vec<f64>, z: &[f64]| nlp(z);
    let mut gradient_at = |z: &[f64]| -> Vec<f64> {
        let mut g = vec![0.0; n];
        nlp.gradient(z, &mut g);
        let jac = dense_jacobian(nlp, z);
        for c in 0..n {
            g[c] *= sigma;
            for r in 0..m {
                g[c] += mu[r] * jac[r * n + c];
            }
        }
        g
    };
    let mut fd_hessian = vec![0.0; n * n];
    for c in 0..n {
        let mut zp = z.to_vec();
        zp[c] += eps;
        let gp = lagrangian_gradient(&mut gradient_at, &zp);
        zp[c] -= 2.0 * eps;
        let gm = lagrangian_gradient(&mut gradient_at, &zp);
        for r in 0..n {
            fd_hessian[r * n + c] = (gp[r] - gm[r]) / (2.0 * eps);
        }
    }
    let pattern = nlp.hessian_pattern().to_vec();
    assert!(pattern.iter().all(|&(r, c)| r >= c), "the Hessian's pattern is its lower triangle");
    let mut values = vec![0.0; pattern.len()];
    nlp.hessian_values(z, sigma, &mu, &mut values);
    let mut hessian = vec![0.0; n * n];
    for (&(r, c), v) in pattern.iter().zip(values) {
        hessian[r * n + c] += v;
        if r != c {
            hessian[c * n + r] += v;
        }
    }
    let gap = relative_gap(&hessian, &fd_hessian);
    assert!(gap < tol, "Lagrangian Hessian against central differences: {gap:e}");
}

#[test]
fn the_transcriptions_derivatives_match_central_differences() {
    // The cart-pole with a full final state and every cost term.
    let problem = swing_up(6)
        .position_weight(CartPole::THETA, 0.3, 1.0)
        .velocity_weight(CartPole::X, 0.2, 0.1)
        .terminal_weight(CartPole::X, 2.0, 0.5)
        .start(VecQ::<CartPole>::from([0.1, 0.2]), VecQ::<CartPole>::from([0.3, -0.4]))
        .velocity_bounds(CartPole::THETA, -9.0, 9.0);
    let mut collocation = Collocation::new(problem.clone()).expect("a well-formed problem");
    let z = scattered(collocation.variables(), 0.1);
    check_derivatives(&mut collocation, &z, 1e-6);
    let mut dmoc = Dmoc::new(problem).expect("a well-formed problem");
    let z = scattered(dmoc.variables(), 0.1);
    check_derivatives(&mut dmoc, &z, 1e-6);

    // Inputs in the Lagrangian, the momenta and the forces, with and without a final velocity.
    let steered = Steered { m: 1.3, k: 2.0, c: 0.4, a: 0.0, b: 0.0, f: 0.0 };
    let start = (VecQ::<Steered>::from([0.2, -0.1]), VecQ::<Steered>::from([0.5, 0.7]));
    for final_velocity in [false, true] {
        let mut problem = Problem::new(steered.clone(), 1.0, 5).start(start.0, start.1);
        if final_velocity {
            problem =
                problem.final_state(VecQ::<Steered>::from([1.0, 0.5]), VecQ::<Steered>::from([0.1, 0.2]));
        }
        let mut collocation = Collocation::new(problem.clone()).expect("a well-formed problem");
        let z = scattered(collocation.variables(), 0.4);
        check_derivatives(&mut collocation, &z, 1e-6);
        let mut dmoc = Dmoc::new(problem).expect("a well-formed problem");
        let z = scattered(dmoc.variables(), 0.4);
        check_derivatives(&mut dmoc, &z, 1e-6);
    }

    // A robot from its URDF file, whose `L_qq` is assembled from its Jacobian blocks: the
    // transcription reuses its buffers from one point to the next.
    let problem = Problem::new(PandaTorques::default(), 1.0, 3).final_state(
        VecQ::<PandaTorques>::from([1.0, 0.2, -0.5, -1.5, 0.4, 1.6, 0.0]),
        VecQ::<PandaTorques>::zeros(),
    );
    let mut collocation = Collocation::new(problem.clone()).expect("a well-formed problem");
    let z = scattered(collocation.variables(), 0.2);
    check_derivatives(&mut collocation, &z, 1e-6);
    let mut dmoc = Dmoc::new(problem).expect("a well-formed problem");
    let z = scattered(dmoc.variables(), 0.2);
    check_derivatives(&mut dmoc, &z, 1e-6);
}

/// A scattered point of a free-final-time program (either transcription) whose `intervals`
/// variables from `first`, the steps, are positive and unequal, so that each interval's own
/// step is exercised.
fn with_steps(variables: usize, first: usize, intervals: usize, seed: f64) -> Vec<f64> {
    let mut z = scattered(variables, seed);
    for (k, h) in z[first..first + intervals].iter_mut().enumerate() {
        *h = 0.3 + 0.05 * k as f64;
    }
    z
}

/// [`check_derivatives`] on both transcriptions of a free-final-time `problem` on `intervals`
/// intervals, at a point of [`with_steps`].
fn check_both_with_steps<M>(problem: Problem<M>, intervals: usize, seed: f64)
where
    M: dirac::DenseModel + dirac::InputsOutputs + Clone,
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    // The steps follow the inputs: after `3N + 1` points of `(q, v)` in collocation, after
    // `N + 1` nodes of `q` in DMOC (bounded velocities come after them).
    let (n, nu) = (M::NQ, problem.model().input_names().len());
    let mut collocation = Collocation::new(problem.clone()).expect("a well-formed problem");
    let first = (3 * intervals + 1) * 2 * n + intervals * nu;
    let z = with_steps(collocation.variables(), first, intervals, seed);
    check_derivatives(&mut collocation, &z, 1e-6);
    let mut dmoc = Dmoc::new(problem).expect("a well-formed problem");
    let first = (intervals + 1) * n + intervals * nu;
    let z = with_steps(dmoc.variables(), first, intervals, seed);
    check_derivatives(&mut dmoc, &z, 1e-6);
}

#[test]
fn a_free_final_times_derivatives_match_central_differences() {
    // The step enters every term: `h/2 L_q`, `h/2 F` and the velocity `(q_{k+1} − q_k)/h` of
    // every point, and the running cost; each interval reads its own step.
    let problem = swing_up(4)
        .position_weight(CartPole::THETA, 0.3, 1.0)
        .velocity_weight(CartPole::X, 0.2, 0.1)
        .terminal_weight(CartPole::X, 2.0, 0.5)
        .start(VecQ::<CartPole>::from([0.1, 0.2]), VecQ::<CartPole>::from([0.3, -0.4]))
        .free_final_time(0.5, 4.0)
        .time_weight(0.7);
    check_both_with_steps(problem.clone(), 4, 0.1);
    // A bounded velocity's row `q_{k+1} − q_k − h_k w_k` is bilinear in the step.
    let bounded = problem.velocity_bounds(CartPole::THETA, -9.0, 9.0).velocity_bounds(CartPole::X, -2.0, 3.0);
    check_both_with_steps(bounded, 4, 0.3);

    let steered = Steered { m: 1.3, k: 2.0, c: 0.4, a: 0.0, b: 0.0, f: 0.0 };
    let problem = Problem::new(steered, 1.0, 5)
        .start(VecQ::<Steered>::from([0.2, -0.1]), VecQ::<Steered>::from([0.5, 0.7]))
        .final_state(VecQ::<Steered>::from([1.0, 0.5]), VecQ::<Steered>::from([0.1, 0.2]))
        .free_final_time(0.5, 3.0);
    check_both_with_steps(problem, 5, 0.4);

    let problem = Problem::new(PandaTorques::default(), 1.0, 3)
        .final_state(
            VecQ::<PandaTorques>::from([1.0, 0.2, -0.5, -1.5, 0.4, 1.6, 0.0]),
            VecQ::<PandaTorques>::zeros(),
        )
        .free_final_time(0.5, 2.0)
        .time_weight(3.0);
    check_both_with_steps(problem, 3, 0.2);
}

/// A mass pushed along a line by `f`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), input(f))]
#[dirac(lagrangian = 0.5 * m * v * v)]
#[dirac(force(x) = f)]
pub struct Pushed {
    pub m: f64,
    pub f: f64,
}

/// A pushed mass on a spring whose anchor is shaken in time: its equations read `t`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), input(f))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * (x - 0.1 * sin(3.0 * t)).powi(2))]
#[dirac(force(x) = f)]
pub struct ShakenAnchor {
    pub m: f64,
    pub k: f64,
    pub f: f64,
}

#[test]
fn a_free_final_time_trades_time_against_effort_as_the_closed_form_does() {
    with_ipopt();
    // From rest at 0 to rest at D, `min ∫ f²/2 dt + ρ T`. For a fixed T the optimal push is
    // linear in time and costs `6 m² D² / T³` (Pontryagin: the costate of the velocity is
    // linear), so the best horizon is `T* = (18 m² D² / ρ)^{1/4}` and the optimal cost
    // `J* = 4 ρ T* / 3`. With m = D = 1 and ρ = 18: T* = 1, J* = 24.
    let (m, distance, rho): (f64, f64, f64) = (1.0, 1.0, 18.0);
    let exact_t = (18.0 * m * m * distance * distance / rho).powf(0.25);
    let exact_cost = 4.0 * rho * exact_t / 3.0;
    let problem = |intervals| {
        Problem::new(Pushed { m, f: 0.0 }, 0.6, intervals)
            .final_state(VecQ::<Pushed>::from([distance]), VecQ::<Pushed>::zeros())
            .free_final_time(0.1, 10.0)
            .time_weight(rho)
    };
    // Both transcriptions hold the push over each interval, so both are second order in the
    // cost. Under a held push this model's motion is a quadratic in time, which both integrate
    // exactly, so their optima are the same program's: equal to round-off.
    let mut optima = Vec::new();
    for collocated in [false, true] {
        let mut errors = Vec::new();
        for intervals in [10, 20, 40] {
            let solve = |interior: bool| {
                let options = (IpoptOptions::default(), InteriorOptions::default());
                match (collocated, interior) {
                    (false, false) => Dmoc::new(problem(intervals)).expect("well-formed").solve(&options.0),
                    (false, true) => {
                        Dmoc::new(problem(intervals)).expect("well-formed").solve_interior(&options.1)
                    }
                    (true, false) => {
                        Collocation::new(problem(intervals)).expect("well-formed").solve(&options.0)
                    }
                    (true, true) => {
                        Collocation::new(problem(intervals)).expect("well-formed").solve_interior(&options.1)
                    }
                }
            };
            let reference = solve(false).expect("IPOPT solves it");
            let ours = solve(true).expect("the interior point solves it");
            let horizon = ours.times[intervals] - ours.times[0];
            eprintln!(
                "{} N = {intervals}: T = {horizon:.10} (exact {exact_t}), cost {:.10} (exact {exact_cost}), \
                 IPOPT {:.10}; iterations {} and {} (IPOPT)",
                if collocated { "collocation" } else { "DMOC" },
                ours.cost,
                reference.cost,
                ours.iterations,
                reference.iterations
            );
            assert!(
                (ours.cost - reference.cost).abs() <= 1e-8 * reference.cost,
                "the solvers' optima differ"
            );
            // The steps stay equal: the nodes are evenly spaced.
            let h = horizon / intervals as f64;
            for (k, t) in ours.times.iter().enumerate() {
                assert!((t - k as f64 * h).abs() < 1e-9 * horizon, "node {k} at {t}, not {}", k as f64 * h);
            }
            errors.push(((horizon - exact_t).abs(), (ours.cost - exact_cost).abs()));
            optima.push((horizon, ours.cost));
        }
        for pair in errors.windows(2) {
            let horizon_order = (pair[0].0 / pair[1].0).log2();
            let cost_order = (pair[0].1 / pair[1].1).log2();
            assert!(
                (1.8..2.3).contains(&horizon_order),
                "the horizon converges at order {horizon_order}: {errors:?}"
            );
            assert!((1.8..2.3).contains(&cost_order), "the cost converges at order {cost_order}: {errors:?}");
        }
    }
    // The horizons to the solvers' tolerance (1e-8 on the optimality error): the cost is flat
    // in the horizon at the optimum, so the horizon is held less tightly than the cost.
    for (dmoc, collocated) in optima[..3].iter().zip(&optima[3..]) {
        assert!((dmoc.0 - collocated.0).abs() < 1e-8, "horizons {dmoc:?} and {collocated:?}");
        assert!((dmoc.1 - collocated.1).abs() < 1e-9 * dmoc.1, "costs {dmoc:?} and {collocated:?}");
    }
}

#[test]
fn a_bounded_velocity_coasts_at_its_bound_as_the_closed_form_does() {
    with_ipopt();
    // From rest at 0 to rest at D in T, `min ∫ f²/2 dt` with `v ≤ V`. Without the bound the
    // velocity peaks at `3D/(2T)`; below that, the optimum (Pontryagin with a first-order state
    // constraint: the push is linear in time off the bound and vanishes where it meets it)
    // accelerates over `τ`, coasts at `V` and stops over `τ`. Each end covers `2Vτ/3`, so
    // `D = VT − 2Vτ/3`, `τ = 3(VT − D)/(2V)`, and the cost is `4V²/(3τ)`. With D = T = 1 and
    // V = 1.2: τ = 1/4, J* = 7.68 (against 6 unbounded).
    let (distance, horizon, fastest): (f64, f64, f64) = (1.0, 1.0, 1.2);
    let tau = 3.0 * (fastest * horizon - distance) / (2.0 * fastest);
    let exact_cost = 4.0 * fastest * fastest / (3.0 * tau);
    let problem = |intervals| {
        Problem::new(Pushed { m: 1.0, f: 0.0 }, horizon, intervals)
            .final_state(VecQ::<Pushed>::from([distance]), VecQ::<Pushed>::zeros())
            .velocity_bounds(Pushed::X, f64::NEG_INFINITY, fastest)
    };
    for collocated in [false, true] {
        let mut errors = Vec::new();
        for intervals in [16, 32, 64] {
            let (ipopt, interior) = (IpoptOptions::default(), InteriorOptions::default());
            let (reference, ours, fastest_found) = if collocated {
                let mut transcription = Collocation::new(problem(intervals)).expect("well-formed");
                let reference = transcription.solve(&ipopt).expect("IPOPT solves it");
                let ours = transcription.solve_interior(&interior).expect("the interior point solves it");
                // Under a held push the velocity is linear within an interval, so it is largest at
                // one of its ends, `(q_{k+1} − q_k)/h ± h f_k / 2` (m = 1).
                let h = horizon / intervals as f64;
                let fastest_found = (0..intervals)
                    .map(|k| {
                        (ours.positions[k + 1][0] - ours.positions[k][0]) / h
                            + 0.5 * h * ours.inputs[k][0].abs()
                    })
                    .fold(f64::NEG_INFINITY, f64::max);
                (reference, ours, fastest_found)
            } else {
                let mut transcription = Dmoc::new(problem(intervals)).expect("well-formed");
                let reference = transcription.solve(&ipopt).expect("IPOPT solves it");
                let ours = transcription.solve_interior(&interior).expect("the interior point solves it");
                let h = horizon / intervals as f64;
                let fastest_found = (0..intervals)
                    .map(|k| (ours.positions[k + 1][0] - ours.positions[k][0]) / h)
                    .fold(f64::NEG_INFINITY, f64::max);
                (reference, ours, fastest_found)
            };
            eprintln!(
                "{} N = {intervals}: cost {:.10} (exact {exact_cost}), IPOPT {:.10}, fastest {fastest_found:.10}; \
                 iterations {} and {} (IPOPT)",
                if collocated { "collocation" } else { "DMOC" },
                ours.cost,
                reference.cost,
                ours.iterations,
                reference.iterations
            );
            assert!(
                (ours.cost - reference.cost).abs() <= 1e-7 * reference.cost,
                "the solvers' optima differ"
            );
            // The bound is met and active.
            assert!(fastest_found <= fastest * (1.0 + 1e-7), "the velocity {fastest_found} passes its bound");
            assert!(fastest_found >= fastest * (1.0 - 1e-6), "the bound is not reached: {fastest_found}");
            if collocated {
                // Collocation's pushes are held and its velocities bounded everywhere: its optimum
                // is feasible for the continuous problem and cannot beat it.
                assert!(ours.cost >= exact_cost * (1.0 - 1e-9), "{} beats the exact {exact_cost}", ours.cost);
            }
            errors.push((ours.cost - exact_cost).abs());
        }
        for pair in errors.windows(2) {
            let order = (pair[0] / pair[1]).log2();
            assert!((1.8..2.4).contains(&order), "the cost converges at order {order}: {errors:?}");
        }
    }
}

#[test]
fn a_bounded_velocity_costs_the_same_relative_error_in_tonnes_and_kilometres() {
    // The coasting mass of the test above rescaled: 1 t moved 1 km in 1000 s at no more than
    // 1.2 m/s. The closed form is the same with units: τ = 3(VT − D)/(2V) = 250 s and
    // J* = m² 4V²/(3τ) = 7680. On the same grid the program is the unit one rescaled, so the
    // relative error of the optimal cost must not depend on the units.
    let relative_error = |m: f64, distance: f64, horizon: f64, fastest: f64| {
        let tau = 3.0 * (fastest * horizon - distance) / (2.0 * fastest);
        let exact = m * m * 4.0 * fastest * fastest / (3.0 * tau);
        let problem = Problem::new(Pushed { m, f: 0.0 }, horizon, 16)
            .final_state(VecQ::<Pushed>::from([distance]), VecQ::<Pushed>::zeros())
            .velocity_bounds(Pushed::X, f64::NEG_INFINITY, fastest);
        let optimum = Dmoc::new(problem).expect("well-formed").solve_interior(&InteriorOptions::default());
        let optimum = optimum.expect("the interior point solves it");
        (optimum.cost - exact) / exact
    };
    let unit = relative_error(1.0, 1.0, 1.0, 1.2);
    let large = relative_error(1000.0, 1000.0, 1000.0, 1.2);
    eprintln!(
        "relative cost error at N = 16: {unit:e} in SI units of one, {large:e} in tonnes and kilometres"
    );
    assert!(unit > 0.0 && unit < 0.02, "the unit problem's error {unit}");
    assert!((unit - large).abs() < 1e-6, "{unit} against {large}");
}

#[test]
fn a_time_optimal_swing_up_is_a_motion_of_the_variational_integrator_with_its_own_step() {
    with_ipopt();
    // The swing-up with the horizon free in [1, 4] s and each second priced at 10: the optimum
    // is replayed by the variational integrator with the step it chose and its pushes.
    let intervals = 40;
    let problem = swing_up(intervals).free_final_time(1.0, 4.0).time_weight(10.0);
    let reference =
        Dmoc::new(problem.clone()).expect("well-formed").solve(&IpoptOptions::default()).expect("IPOPT");
    let optimum = Dmoc::new(problem)
        .expect("well-formed")
        .solve_interior(&InteriorOptions::default())
        .expect("the interior point solves it");
    let horizon = optimum.times[intervals];
    eprintln!(
        "time-optimal swing-up: T = {horizon:.6} s, cost {:.8} in {} iterations (IPOPT {:.8} in {})",
        optimum.cost, optimum.iterations, reference.cost, reference.iterations
    );
    assert!((optimum.cost - reference.cost).abs() <= 1e-6 * reference.cost, "the solvers' optima differ");
    assert!(horizon > 1.0 + 1e-3 && horizon < 4.0 - 1e-3, "the horizon {horizon} is chosen, not bound");
    assert!(optimum.violation < 1e-9, "equations violated by {:e}", optimum.violation);

    let h = horizon / intervals as f64;
    let mut model = cart_pole();
    let start = consistent_state(
        &model,
        0.0,
        &VecQ::<CartPole>::zeros(),
        &VecQ::<CartPole>::zeros(),
        Consistency::default(),
    )
    .expect("consistent");
    let mut vi = Variational::new(&mut model, h, VariationalOptions::default()).expect("valid");
    vi.start(0.0, &start, horizon).expect("starts");
    let mut gap = 0.0f64;
    for (k, u) in optimum.inputs.iter().enumerate() {
        vi.set_input(CartPole::F, u[0]).expect("an input");
        vi.step().expect("steps");
        for (x, expected) in vi.state().q.iter().zip(&optimum.positions[k + 1]) {
            gap = gap.max((x - expected).abs());
        }
    }
    eprintln!("replayed with h = {h:.6}: largest gap to the optimal nodes {gap:.2e}");
    assert!(gap < 1e-7, "the replay leaves the optimal nodes by {gap:e}");
}

#[test]
fn a_robots_l_qq_does_not_read_back_the_buffer_it_is_given() {
    use dirac::{LagrangeDirac, MatQQ};
    // `L_qq` of a URDF robot is `∂ṗ/∂q − F_q` from its Jacobian blocks; into a buffer that
    // holds another point's `L_qq`, it must come out as into a fresh one.
    let panda = PandaTorques::default();
    let q = VecQ::<PandaTorques>::from([0.3, -0.2, 0.4, -1.5, 0.2, 1.6, 0.5]);
    let v = VecQ::<PandaTorques>::from([0.5, -0.4, 0.3, 0.2, -0.6, 0.1, 0.7]);
    let mut fresh = MatQQ::<PandaTorques>::zeros();
    panda.l_qq(0.0, &q, &v, &mut fresh);
    let mut reused = MatQQ::<PandaTorques>::zeros();
    panda.l_qq(0.0, &(q * 0.5), &v, &mut reused);
    panda.l_qq(0.0, &q, &v, &mut reused);
    assert!(fresh.amax() > 1.0, "a nonzero L_qq");
    assert_eq!(fresh, reused, "L_qq depends on what the buffer held");
}

#[test]
fn the_cart_pole_swings_up_and_the_variational_integrator_replays_it() {
    with_ipopt();
    let intervals = 50;
    let mut dmoc = Dmoc::new(swing_up(intervals)).expect("a well-formed problem");
    let optimum = dmoc.solve(&IpoptOptions::default()).expect("IPOPT solves the swing-up");
    assert!(optimum.violation < 1e-9, "discrete equations violated by {:e}", optimum.violation);
    let end = optimum.positions.last().expect("nodes");
    assert!((end[1] - std::f64::consts::PI).abs() < 1e-12 && end[0].abs() < 1e-12, "ends upright: {end:?}");
    assert!(optimum.inputs.iter().all(|u| u[0].abs() <= 20.0 + 1e-7), "pushes within their bounds");
    assert!(optimum.positions.iter().all(|q| q[0].abs() <= 1.5 + 1e-7), "the cart within its track");

    // The variational integrator with the same step, the push held over each interval,
    // reproduces the nodes: the optimum is one of its trajectories.
    let h = 2.0 / intervals as f64;
    let mut model = cart_pole();
    let start = consistent_state(
        &model,
        0.0,
        &VecQ::<CartPole>::zeros(),
        &VecQ::<CartPole>::zeros(),
        Consistency::default(),
    )
    .expect("consistent");
    let mut vi = Variational::new(&mut model, h, VariationalOptions::default()).expect("valid");
    vi.start(0.0, &start, 2.0).expect("starts");
    let mut worst = 0.0f64;
    for k in 0..intervals {
        vi.set_input(CartPole::F, optimum.inputs[k][0]).expect("input set");
        vi.step().expect("steps");
        let q = &vi.state().q;
        worst = worst
            .max((q[0] - optimum.positions[k + 1][0]).abs())
            .max((q[1] - optimum.positions[k + 1][1]).abs());
    }
    assert!(worst < 1e-10, "the replay leaves the optimal nodes by {worst:e}");
}

/// A pushed mass on a spring in front of a wall: its contact would be passed through by a
/// smooth transcription.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), input(f))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x, force(x) = f)]
#[dirac(unilateral(wall, restitution = 0.5) = 1.0 - x)]
pub struct PushedToAWall {
    pub m: f64,
    pub k: f64,
    pub f: f64,
}

/// A pushed mass sliding with a Coulomb friction law, whose modes switch its equations.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), input(f))]
#[dirac(lagrangian = 0.5 * m * v * v, force(x) = f)]
#[dirac(friction(slide, kinetic = mu * m * g) = v)]
pub struct PushedWithFriction {
    pub m: f64,
    pub g: f64,
    pub mu: f64,
    pub f: f64,
}

/// A pushed mass in a potential defined only for `x ≥ 0`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), input(f))]
#[dirac(lagrangian = 0.5 * m * v * v - k * x.sqrt(), force(x) = f)]
pub struct RootWell {
    pub m: f64,
    pub k: f64,
    pub f: f64,
}

#[test]
fn malformed_problems_are_refused_by_name() {
    with_ipopt();
    // Contacts and laws, which a smooth transcription would get wrong.
    let wall = PushedToAWall { m: 1.0, k: 1.0, f: 0.0 };
    match Dmoc::new(Problem::new(wall, 1.0, 10)).err().expect("refused") {
        OptimalError::Unsupported { why, .. } => assert!(why.contains("unilateral"), "{why}"),
        other => panic!("{other}"),
    }
    let sliding = PushedWithFriction { m: 1.0, g: 9.81, mu: 0.3, f: 0.0 };
    match Dmoc::new(Problem::new(sliding, 1.0, 10)).err().expect("refused") {
        OptimalError::Unsupported { why, .. } => assert!(why.contains("laws"), "{why}"),
        other => panic!("{other}"),
    }
    // A model without inputs.
    let error = Dmoc::new(Problem::new(unit_pendulum(), 1.0, 10)).err().expect("refused");
    assert!(matches!(error, OptimalError::NoInputs { .. }), "{error}");
    // Crossed bounds, named by their input.
    let problem = swing_up(10).input_bounds(CartPole::F, 1.0, -1.0);
    match Dmoc::new(problem).err().expect("refused") {
        OptimalError::InfeasibleBounds { name, .. } => assert_eq!(name, "f"),
        other => panic!("{other}"),
    }
    // A target outside the track.
    let problem = swing_up(10).final_position(CartPole::X, 2.0);
    match Dmoc::new(problem).err().expect("refused") {
        OptimalError::InfeasibleBounds { name, value, .. } => assert_eq!((name.as_str(), value), ("x", 2.0)),
        other => panic!("{other}"),
    }
    // Velocity bounds that cross, are not numbers, or leave out the start or final velocity,
    // named by the velocity, on both transcriptions.
    let start = (VecQ::<CartPole>::zeros(), VecQ::<CartPole>::from([2.5, 0.0]));
    for (problem, value) in [
        (swing_up(10).velocity_bounds(CartPole::X, 1.0, -1.0), None),
        (swing_up(10).velocity_bounds(CartPole::X, -2.0, 2.0).start(start.0, start.1), Some(2.5)),
        (swing_up(10).velocity_bounds(CartPole::X, 0.5, 2.0), Some(0.0)),
    ] {
        for error in [Dmoc::new(problem.clone()).err(), Collocation::new(problem).err()] {
            match error.expect("refused") {
                OptimalError::InfeasibleBounds { name, value: found, .. } => {
                    assert_eq!(name, "x's velocity");
                    assert!(value.is_none_or(|v| v == found), "{found} is not {value:?}");
                }
                other => panic!("{other}"),
            }
        }
    }
    let problem = swing_up(10).velocity_bounds(CartPole::THETA, f64::NAN, 2.0);
    match Dmoc::new(problem).err().expect("refused") {
        OptimalError::NotFinite { name, .. } => assert_eq!(name, "theta's velocity"),
        other => panic!("{other}"),
    }
    // No grid.
    let error = Dmoc::new(Problem::new(cart_pole(), 0.0, 10)).err().expect("refused");
    assert!(matches!(error, OptimalError::InvalidGrid { .. }), "{error}");
    // A grid whose program could not be indexed, refused before anything is allocated.
    let error = Dmoc::new(Problem::new(cart_pole(), 1.0, usize::MAX / 2)).err().expect("refused");
    assert!(matches!(error, OptimalError::InvalidGrid { .. }), "{error}");
    let error = Dmoc::new(Problem::new(cart_pole(), 1.0, 200_000_000)).err().expect("refused");
    assert!(matches!(error, OptimalError::InvalidGrid { .. }), "{error}");
    // A weight that is not a number.
    let error = Dmoc::new(swing_up(10).input_weight(CartPole::F, f64::NAN)).err().expect("refused");
    assert!(matches!(error, OptimalError::NotFinite { .. }), "{error}");
    // Equations that are not numbers where the guess starts, named before IPOPT runs.
    let well = RootWell { m: 1.0, k: 1.0, f: 0.0 };
    let problem = Problem::new(well, 1.0, 10)
        .start(VecQ::<RootWell>::from([-1.0]), VecQ::<RootWell>::zeros())
        .final_position(RootWell::X, 1.0);
    match Dmoc::new(problem.clone())
        .expect("well-formed")
        .solve(&IpoptOptions::default())
        .expect_err("refused")
    {
        OptimalError::NotFiniteAtGuess { detail, .. } => {
            assert!(detail.contains("`x` at node 0"), "{detail}")
        }
        other => panic!("{other}"),
    }
    // The same in the collocation's stage equations, by stage and interval.
    let mut collocation = Collocation::new(problem).expect("well-formed");
    match collocation.solve_interior(&InteriorOptions::default()).expect_err("refused") {
        OptimalError::NotFiniteAtGuess { detail, .. } => {
            assert!(detail.contains("momentum balance of `x` at stage 1 of interval 0"), "{detail}")
        }
        other => panic!("{other}"),
    }
    let error = Collocation::new(Problem::new(cart_pole(), 1.0, 200_000_000)).err().expect("refused");
    assert!(matches!(error, OptimalError::InvalidGrid { .. }), "{error}");
    // A free final time with no room, or a start outside it.
    for (shortest, longest) in [(0.0, 3.0), (-1.0, 3.0), (1.0, f64::INFINITY), (3.0, 4.0), (2.5, 1.0)] {
        let problem = swing_up(10).free_final_time(shortest, longest);
        match Dmoc::new(problem).err().expect("refused") {
            OptimalError::InfeasibleBounds { name, .. } => assert_eq!(name, "the final time"),
            other => panic!("{other}"),
        }
    }
    // Bounds or a time weight that are not numbers.
    for problem in [
        swing_up(10).free_final_time(f64::NAN, 3.0),
        swing_up(10).free_final_time(1.0, f64::NAN),
        swing_up(10).free_final_time(1.0, 3.0).time_weight(f64::NAN),
        swing_up(10).time_weight(f64::INFINITY),
    ] {
        for error in [Dmoc::new(problem.clone()).err(), Collocation::new(problem).err()] {
            match error.expect("refused") {
                OptimalError::NotFinite { name, .. } => assert_eq!(name, "the final time"),
                other => panic!("{other}"),
            }
        }
    }
    // A receding horizon keeps its length, and a model whose equations move with time cannot
    // have its horizon moved.
    let free = swing_up(10).free_final_time(1.0, 3.0);
    let error = Mpc::new(free, InteriorOptions::default()).err().expect("refused");
    assert!(matches!(error, OptimalError::FixedTimeOnly { what: "Mpc", .. }), "{error}");
    let shaken = ShakenAnchor { m: 1.0, k: 4.0, f: 0.0 };
    let problem =
        Problem::new(shaken, 1.0, 10).final_position(ShakenAnchor::X, 1.0).free_final_time(0.5, 2.0);
    let options = InteriorOptions::default();
    let errors = [
        Dmoc::new(problem.clone()).expect("well-formed").solve_interior(&options).expect_err("refused"),
        Collocation::new(problem).expect("well-formed").solve_interior(&options).expect_err("refused"),
    ];
    for error in errors {
        match error {
            OptimalError::Unsupported { why, .. } => assert!(why.contains("change with time"), "{why}"),
            other => panic!("{other}"),
        }
    }
    // A swing-up the bounded push cannot reach: IPOPT's own status, by name.
    let problem = swing_up(20).input_bounds(CartPole::F, -0.1, 0.1);
    let error = Dmoc::new(problem).expect("well-formed").solve(&IpoptOptions::default()).expect_err("fails");
    match error {
        OptimalError::Solver { status, .. } => {
            assert!(["Infeasible_Problem_Detected", "Restoration_Failed"].contains(&status), "{status}")
        }
        other => panic!("{other}"),
    }
}

/// A satellite whose body turns freely about its centre and carries an arm on a hinge `r` from
/// it, driven by the torque `u` between them: `L` does not read the body's angle `theta`, so
/// its momentum `p_theta` (the total angular momentum) is conserved whatever `u` does.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(theta => w, phi => wp), input(u))]
#[dirac(lagrangian = 0.5 * ib * w * w + 0.5 * ia * (w + wp) * (w + wp)
    + 0.5 * m * (r * r * w * w + c * c * (w + wp) * (w + wp) + 2.0 * r * c * w * (w + wp) * cos(phi)))]
#[dirac(force(phi) = u)]
pub struct Satellite {
    pub ib: f64,
    pub ia: f64,
    pub m: f64,
    pub r: f64,
    pub c: f64,
    pub u: f64,
}

#[test]
fn a_satellite_turned_by_its_arm_keeps_its_angular_momentum_to_round_off() {
    with_ipopt();
    // Turned from rest through 1 rad with its arm back where it started, at rest: only by
    // moving the arm out and back along different paths (a falling cat's turn). Starting at
    // rest, the angular momentum is zero, and DMOC's discrete momentum map stays zero at every
    // node of the optimum (Ober-Blöbaum, Junge and Marsden 2011, the discrete Noether theorem).
    let satellite = Satellite { ib: 2.0, ia: 0.2, m: 1.0, r: 0.6, c: 0.5, u: 0.0 };
    let problem = Problem::new(satellite, 3.0, 60)
        .final_state(VecQ::<Satellite>::from([1.0, 0.0]), VecQ::<Satellite>::zeros())
        .guess(
            (0..=60)
                .map(|k| {
                    let s = k as f64 / 60.0;
                    vec![s, 2.0 * (std::f64::consts::PI * s).sin()]
                })
                .collect(),
            vec![vec![0.0]; 60],
        );
    let optimum = Dmoc::new(problem).expect("well-formed").solve(&IpoptOptions::default()).expect("solves");
    let scale = optimum.momenta.iter().flatten().fold(0.0f64, |m, p| m.max(p.abs()));
    let drift = optimum.momenta.iter().fold(0.0f64, |m, p| m.max(p[0].abs()));
    eprintln!(
        "satellite: p_theta within {drift:e} of zero, momenta up to {scale}, {} iterations",
        optimum.iterations
    );
    assert!(scale > 0.1, "the arm moves: its momentum reaches {scale}");
    assert!(drift < 1e-12 * scale.max(1.0), "p_theta leaves zero by {drift:e} (momenta up to {scale})");
}

/// Two masses in the plane on a spring, pushed apart by a force `u` between them: free in
/// space and moved by internal forces alone, so the total angular momentum about the origin,
/// `Σ x p_y − y p_x`, is a momentum map, and one that is not linear in the momenta's
/// components (as a cyclic coordinate's momentum is).
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x1 => vx1, y1 => vy1, x2 => vx2, y2 => vy2), input(u))]
#[dirac(lagrangian = 0.5 * m * (vx1 * vx1 + vy1 * vy1 + vx2 * vx2 + vy2 * vy2)
    - 0.5 * k * (sqrt((x2 - x1).powi(2) + (y2 - y1).powi(2)) - d).powi(2))]
#[dirac(force(x1) = -u * (x2 - x1) / sqrt((x2 - x1).powi(2) + (y2 - y1).powi(2)),
    force(y1) = -u * (y2 - y1) / sqrt((x2 - x1).powi(2) + (y2 - y1).powi(2)),
    force(x2) = u * (x2 - x1) / sqrt((x2 - x1).powi(2) + (y2 - y1).powi(2)),
    force(y2) = u * (y2 - y1) / sqrt((x2 - x1).powi(2) + (y2 - y1).powi(2)))]
pub struct Dumbbell {
    pub m: f64,
    pub k: f64,
    pub d: f64,
    pub u: f64,
}

/// The dumbbell spinning at 1 rad/s, pulled in to a third of its length and turned to 2.5 rad
/// in 2 s (a skater's spin): `N` intervals.
fn spin(intervals: usize) -> Problem<Dumbbell> {
    let (radius, angle) = (0.3, 2.5f64);
    Problem::new(Dumbbell { m: 1.0, k: 20.0, d: 1.0, u: 0.0 }, 2.0, intervals)
        .start(VecQ::<Dumbbell>::from([-0.5, 0.0, 0.5, 0.0]), VecQ::<Dumbbell>::from([0.0, -0.5, 0.0, 0.5]))
        .terminal_weight(Dumbbell::X2, 100.0, radius * angle.cos())
        .terminal_weight(Dumbbell::Y2, 100.0, radius * angle.sin())
}

/// The largest distance of `Σ x p_y − y p_x` at the nodes from its value at the start.
fn angular_momentum_drift(optimum: &dirac::optimal::Optimum) -> (f64, f64) {
    let j: Vec<f64> = optimum
        .positions
        .iter()
        .zip(&optimum.momenta)
        .map(|(q, p)| q[0] * p[1] - q[1] * p[0] + q[2] * p[3] - q[3] * p[2])
        .collect();
    (j[0], j.iter().fold(0.0f64, |m, x| m.max((x - j[0]).abs())))
}

#[test]
fn dmoc_keeps_the_angular_momentum_that_collocation_lets_drift() {
    with_ipopt();
    // The discrete Noether theorem (Ober-Blöbaum, Junge and Marsden 2011): the trapezoidal
    // discrete Lagrangian and the midpoint forces are invariant under rotations, and internal
    // forces do no virtual work along them, so DMOC's discrete angular momentum is the start's
    // at every node. Radau IIA is not symplectic: its momenta are right to its order only, and
    // the quadratic momentum map drifts, less as N grows.
    let mut collocated = Vec::new();
    for intervals in [20, 40] {
        let dmoc =
            Dmoc::new(spin(intervals)).expect("well-formed").solve(&IpoptOptions::default()).expect("DMOC");
        let radau = Collocation::new(spin(intervals))
            .expect("well-formed")
            .solve(&IpoptOptions::default())
            .expect("Radau");
        let (j0, dmoc_drift) = angular_momentum_drift(&dmoc);
        let (radau_j0, radau_drift) = angular_momentum_drift(&radau);
        eprintln!(
            "spin, N = {intervals}: angular momentum {j0} kept by DMOC to {dmoc_drift:e}, by collocation to \
             {radau_drift:e} (costs {} and {}, {} and {} iterations)",
            dmoc.cost, radau.cost, dmoc.iterations, radau.iterations
        );
        assert!((j0 - 0.5).abs() < 1e-14 && (radau_j0 - 0.5).abs() < 1e-14, "both start with J = 1/2");
        let reach = dmoc.positions.last().map(|q| q[2].hypot(q[3])).expect("nodes");
        assert!((reach - 0.3).abs() < 0.05, "the spin is pulled in: radius {reach}");
        // Node by node, J moves by the equations' residual applied to the rotation's
        // generator, `|⟨c_k, ξ q_k⟩| ≤ violation · 4 max |q|`: DMOC conserves it to what the
        // solve leaves of the equations (round-off, or IPOPT's last step).
        let size = dmoc.positions.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
        let bound = intervals as f64 * dmoc.violation * 4.0 * size + 1e-14;
        eprintln!("  DMOC's equations hold to {:e}: J may move by {bound:e}", dmoc.violation);
        assert!(dmoc_drift <= bound, "DMOC's angular momentum drifts by {dmoc_drift:e}, beyond {bound:e}");
        assert!(radau_drift > 1e3 * dmoc_drift.max(1e-16), "collocation keeps J to {radau_drift:e}");
        collocated.push(radau_drift);
    }
    // Radau IIA is of order 5 at the nodes: 2.8e-5 and 9.2e-7 here, order 4.9.
    let order = (collocated[0] / collocated[1]).log2();
    assert!(order > 4.0, "collocation's drift falls at order {order} as N doubles ({collocated:?})");

    // A cyclic coordinate's momentum is a component of the momenta collocation integrates,
    // whose rate is zero at every stage: the satellite's `p_theta` stays zero in both. (The
    // final velocity is left free: given, it makes `p_theta`'s equations one too many, as
    // they already hold it at the start's zero, and IPOPT does not converge.)
    let satellite = Satellite { ib: 2.0, ia: 0.2, m: 1.0, r: 0.6, c: 0.5, u: 0.0 };
    let problem = Problem::new(satellite, 3.0, 30)
        .final_position(Satellite::THETA, 1.0)
        .final_position(Satellite::PHI, 0.0)
        .guess(
            (0..=30)
                .map(|k| vec![k as f64 / 30.0, 2.0 * (std::f64::consts::PI * k as f64 / 30.0).sin()])
                .collect(),
            vec![vec![0.0]; 30],
        );
    let optimum =
        Collocation::new(problem).expect("well-formed").solve(&IpoptOptions::default()).expect("solves");
    let scale = optimum.momenta.iter().flatten().fold(0.0f64, |m, p| m.max(p.abs()));
    let drift = optimum.momenta.iter().fold(0.0f64, |m, p| m.max(p[0].abs()));
    // Node by node, `p_theta` moves by its rows' residuals alone (three stages per interval).
    let bound = 3.0 * 30.0 * optimum.violation + 1e-14 * scale;
    eprintln!(
        "satellite by collocation: p_theta within {drift:e} of zero (equations to {:e}, bound {bound:e}), \
         momenta up to {scale}",
        optimum.violation
    );
    assert!(scale > 0.1 && drift <= bound, "p_theta leaves zero by {drift:e}, beyond {bound:e}");
}

#[test]
fn radau_collocation_swings_the_cart_pole_up_along_the_models_own_motion() {
    with_ipopt();
    // Replayed by the Radau integrator at 1e-12 with the push held over each interval, the
    // collocation's nodes are the model's motion to the method's accuracy: order 5 at the
    // nodes, so halving h divides the replay's distance from them by about 32.
    let mut gaps = Vec::new();
    let mut costs = Vec::new();
    for intervals in [25, 50] {
        let optimum = Collocation::new(swing_up(intervals))
            .expect("well-formed")
            .solve(&IpoptOptions::default())
            .expect("IPOPT solves the collocated swing-up");
        assert!(optimum.violation < 1e-9, "stage equations violated by {:e}", optimum.violation);
        let end = optimum.positions.last().expect("nodes");
        assert!(
            (end[1] - std::f64::consts::PI).abs() < 1e-12 && end[0].abs() < 1e-12,
            "ends upright: {end:?}"
        );
        let h = 2.0 / intervals as f64;
        let mut model = cart_pole();
        model.f = optimum.inputs[0][0];
        let zero = VecQ::<CartPole>::zeros();
        let start = consistent_state(&model, 0.0, &zero, &zero, Consistency::default()).expect("consistent");
        let mut radau = Radau::new(&mut model, RadauOptions::tolerances(1e-12, 1e-12)).expect("valid");
        radau.start(0.0, &start, h).expect("starts");
        let mut gap = 0.0f64;
        for k in 0..intervals {
            if k > 0 {
                radau.model_mut().expect("held exclusively").f = optimum.inputs[k][0];
                radau.restart_until((k + 1) as f64 * h).expect("restarts");
            }
            while !radau.finished() {
                radau.step().expect("steps");
            }
            let q = &radau.state().q;
            gap = gap
                .max((q[0] - optimum.positions[k + 1][0]).abs())
                .max((q[1] - optimum.positions[k + 1][1]).abs());
        }
        eprintln!("collocation, N = {intervals}: cost {}, replay within {gap:e}", optimum.cost);
        gaps.push(gap);
        costs.push(optimum.cost);
    }
    let order = (gaps[0] / gaps[1]).log2();
    assert!(order > 4.0, "the replay's distance falls at order {order} ({gaps:?})");
    // The same continuous optimum as DMOC's: the collocation's cost converges to DMOC's on a
    // fine grid (itself within about 1e-3 of the limit: 2e-3 relative at N = 100, second
    // order). Inputs held over each interval make both transcriptions' costs second order.
    let reference =
        Dmoc::new(swing_up(800)).expect("well-formed").solve(&IpoptOptions::default()).expect("solves").cost;
    let errors: Vec<f64> = costs.iter().map(|c| (c - reference).abs()).collect();
    let order = (errors[0] / errors[1]).log2();
    eprintln!("collocation costs {costs:?} against DMOC's {reference} at N = 800: order {order}");
    assert!((1.8..2.3).contains(&order), "the collocation's cost converges at order {order} ({errors:?})");

    // dirac's interior point reaches IPOPT's optimum of the collocated program.
    let reference =
        Collocation::new(swing_up(50)).expect("well-formed").solve(&IpoptOptions::default()).expect("IPOPT");
    let ours = Collocation::new(swing_up(50))
        .expect("well-formed")
        .solve_interior(&InteriorOptions::default())
        .expect("the interior point solves the collocated swing-up");
    eprintln!(
        "collocation, N = 50: interior point {} in {} iterations, IPOPT {} in {}",
        ours.cost, ours.iterations, reference.cost, reference.iterations
    );
    assert!(
        (ours.cost - reference.cost).abs() <= 1e-6 * reference.cost,
        "the interior point's optimum differs"
    );
}

#[test]
fn the_cart_poles_optimal_cost_converges_at_second_order() {
    with_ipopt();
    // The reference is the same problem on 800 intervals; DMOC with the trapezoidal discrete
    // Lagrangian is second order, so doubling N divides the cost's error by about 4.
    let cost = |n| {
        Dmoc::new(swing_up(n)).expect("well-formed").solve(&IpoptOptions::default()).expect("solves").cost
    };
    let reference = cost(800);
    let errors: Vec<f64> = [25, 50, 100].into_iter().map(|n| (cost(n) - reference).abs()).collect();
    eprintln!("cart-pole cost errors at N = 25, 50, 100 against N = 800: {errors:?}");
    for pair in errors.windows(2) {
        let order = (pair[0] / pair[1]).log2();
        assert!((1.8..2.3).contains(&order), "observed order {order} (errors {errors:?})");
    }
}

#[test]
fn the_pure_rust_interior_point_finds_ipopts_optimum() {
    with_ipopt();
    // The reference is IPOPT's optimum of the same program (same transcription, same
    // derivatives, its own MA27/MUMPS factorisation and restoration phase); the interior
    // point must reach the same local optimum from the same guess.
    for intervals in [25, 50, 100] {
        let reference = Dmoc::new(swing_up(intervals))
            .expect("well-formed")
            .solve(&IpoptOptions::default())
            .expect("IPOPT");
        let ours = Dmoc::new(swing_up(intervals))
            .expect("well-formed")
            .solve_interior(&InteriorOptions::default())
            .expect("the interior point solves the swing-up");
        let positions: Vec<f64> = ours.positions.iter().flatten().copied().collect();
        let expected: Vec<f64> = reference.positions.iter().flatten().copied().collect();
        eprintln!(
            "N = {intervals}: cost {} against IPOPT's {}, {} iterations against {}",
            ours.cost, reference.cost, ours.iterations, reference.iterations
        );
        assert!(
            (ours.cost - reference.cost).abs() <= 1e-6 * reference.cost.abs(),
            "N = {intervals}: cost {} against IPOPT's {}",
            ours.cost,
            reference.cost
        );
        assert!(relative_gap(&positions, &expected) < 1e-5, "N = {intervals}: the optimal nodes differ");
        assert!(ours.violation < 1e-9, "N = {intervals}: equations violated by {:e}", ours.violation);
        assert!(ours.inputs.iter().all(|u| u[0].abs() <= 20.0), "pushes within their bounds");
        // The same algorithm takes as many steps, within 10%.
        assert!(
            10 * ours.iterations <= 11 * reference.iterations,
            "N = {intervals}: {} iterations against IPOPT's {}",
            ours.iterations,
            reference.iterations
        );
    }
    // The acrobot, swung up by its elbow alone: no bounds, a nonconvex program whose steps
    // need the inertia correction.
    let problem = || {
        Problem::new(acrobot(), 3.0, 50).final_state(
            VecQ::<Acrobot>::from([std::f64::consts::PI, std::f64::consts::PI]),
            VecQ::<Acrobot>::zeros(),
        )
    };
    let reference =
        Dmoc::new(problem()).expect("well-formed").solve(&IpoptOptions::default()).expect("IPOPT");
    let ours = Dmoc::new(problem())
        .expect("well-formed")
        .solve_interior(&InteriorOptions::default())
        .expect("solves");
    eprintln!(
        "acrobot: cost {} against IPOPT's {}, {} iterations against {}",
        ours.cost, reference.cost, ours.iterations, reference.iterations
    );
    assert!((ours.cost - reference.cost).abs() <= 1e-6 * reference.cost.abs(), "acrobot: cost differs");
    assert!(ours.violation < 1e-9, "acrobot: equations violated by {:e}", ours.violation);
    assert!(
        10 * ours.iterations <= 11 * reference.iterations,
        "acrobot: more iterations than IPOPT's, by over 10%"
    );

    // The Panda between two poses within its joints' limits and efforts: near the optimum the
    // torques at their bounds make the barrier terms 1e10 times the constraint rows' pivots,
    // which must not be taken for zero ones.
    let reference = Dmoc::new(panda_point_to_point(10))
        .expect("well-formed")
        .solve(&IpoptOptions::default())
        .expect("IPOPT");
    let ours = Dmoc::new(panda_point_to_point(10))
        .expect("well-formed")
        .solve_interior(&InteriorOptions::default())
        .expect("solves the Panda");
    eprintln!(
        "Panda: cost {} against IPOPT's {}, {} iterations against {}",
        ours.cost, reference.cost, ours.iterations, reference.iterations
    );
    assert!((ours.cost - reference.cost).abs() <= 1e-6 * reference.cost, "Panda: cost differs");
    assert!(ours.violation < 1e-8, "Panda: equations violated by {:e}", ours.violation);
}

#[test]
fn a_100_hz_mpc_stabilises_the_cart_pole_simulated_by_radau() {
    // The plant is the cart-pole integrated by Radau, tilted 0.5 rad from upright at rest; the
    // controller solves a 1 s horizon on N = 20 intervals at every 10 ms sample, warm started,
    // with the push within ±20 N and the cart within ±1.5 m.
    let upright = std::f64::consts::PI;
    let problem = cart_pole_balance(20);
    let mut mpc = Mpc::new(problem, InteriorOptions::default()).expect("a well-formed problem");
    let mut plant = cart_pole();
    let q = VecQ::<CartPole>::from([0.0, upright - 0.5]);
    let start = consistent_state(&plant, 0.0, &q, &VecQ::<CartPole>::zeros(), Consistency::default())
        .expect("consistent");
    let mut radau = Radau::new(&mut plant, RadauOptions::default()).expect("valid");
    let solution = radau
        .run(0.0, &start, 4.0)
        .sampling(Sampling::Every(0.01))
        .every(0.01, |t, state, plant: &mut CartPole| mpc.apply(t, state, plant))
        .solve()
        .expect("the run completes");
    let samples = mpc.samples();
    let failed: Vec<_> = samples.iter().filter(|s| s.status != "Solve_Succeeded").collect();
    let iterations: Vec<usize> = samples.iter().map(|s| s.iterations).collect();
    eprintln!(
        "MPC: {} samples, median solve {:?} (debug build), iterations up to {}, {} failed",
        samples.len(),
        mpc.median_solve(),
        iterations.iter().max().expect("samples"),
        failed.len()
    );
    assert_eq!(samples.len(), 400, "one solve per 10 ms sample over 4 s");
    assert!(failed.is_empty(), "every sample solves: {failed:?}");
    assert!(samples.iter().all(|s| s.inputs[0].abs() <= 20.0), "pushes within their bounds");
    let (theta, x) = (solution.q(CartPole::THETA), solution.q(CartPole::X));
    let last = theta.len() - 1;
    // Upright and centred after 4 s, the cart never off its track.
    assert!((theta[last] - upright).abs() < 1e-3, "the pole ends at {} rad", theta[last]);
    assert!(x[last].abs() < 1e-2, "the cart ends at {} m", x[last]);
    assert!(x.iter().all(|x| x.abs() <= 1.5), "the cart stays on its track");
}

#[test]
fn an_mpc_keeps_its_plants_velocity_within_its_bound() {
    // A pushed mass, simulated by Radau from rest at 0, is driven to 1 m by a 20 Hz MPC over a
    // 1 s horizon on N = 10 intervals. Unbounded, the controller rushes (a position weight of
    // 100 against a push weight of 0.1); with the velocity bounded by 0.5 m/s it must coast.
    // The warm start moves each interval's velocity variable and its row's multiplier forward
    // with the plan.
    let run = |bounded: bool| {
        let mut problem = Problem::new(Pushed { m: 1.0, f: 0.0 }, 1.0, 10)
            .position_weight(Pushed::X, 100.0, 1.0)
            .terminal_weight(Pushed::X, 100.0, 1.0)
            .input_weight(Pushed::F, 0.1)
            .input_bounds(Pushed::F, -10.0, 10.0);
        if bounded {
            problem = problem.velocity_bounds(Pushed::X, -0.5, 0.5);
        }
        let mut mpc = Mpc::new(problem, InteriorOptions::default()).expect("a well-formed problem");
        let mut plant = Pushed { m: 1.0, f: 0.0 };
        let start = consistent_state(
            &plant,
            0.0,
            &VecQ::<Pushed>::zeros(),
            &VecQ::<Pushed>::zeros(),
            Consistency::default(),
        )
        .expect("consistent");
        let mut radau = Radau::new(&mut plant, RadauOptions::default()).expect("valid");
        let solution = radau
            .run(0.0, &start, 4.0)
            .sampling(Sampling::Every(0.01))
            .every(0.05, |t, state, plant: &mut Pushed| mpc.apply(t, state, plant))
            .solve()
            .expect("the run completes");
        let failed = mpc.samples().iter().filter(|s| s.status != "Solve_Succeeded").count();
        assert_eq!(failed, 0, "every sample solves");
        let fastest = solution.v(Pushed::X).iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let x = solution.q(Pushed::X);
        (fastest, x[x.len() - 1])
    };
    let (free, free_end) = run(false);
    let (bounded, bounded_end) = run(true);
    eprintln!(
        "fastest {free:.4} m/s unbounded (ends at {free_end:.6}), {bounded:.4} m/s bounded (ends at {bounded_end:.6})"
    );
    assert!(free > 1.0, "unbounded, the controller rushes: {free}");
    // The plan bounds each 0.1 s interval's mean velocity, `v_0 + 0.05 f` under a held push,
    // which DMOC integrates exactly on this model: the plant's velocity at the next sample,
    // 0.05 s later. The velocity is linear in between, so the plant stays within the bound.
    assert!(bounded <= 0.5 + 1e-6, "bounded, the plant reaches {bounded} m/s");
    assert!(bounded < 0.6 * free, "the bound slows the plant: {bounded} against {free}");
    assert!((bounded_end - 1.0).abs() < 1e-3, "it still arrives: {bounded_end}");
}
