//! Adjoint gradients of Radau integrations.
//!
//! References: the forward sensitivities of the same run, solved exactly each step by the
//! three stages' coupled system (the derivative of the discrete solution, so the two must
//! agree to round-off, not to the tolerance); and central differences of whole simulations at
//! perturbed parameters and initial values (to the tolerance).

use dirac::State;
use dirac::adjoint::{Objective, Recording};
use dirac::nalgebra::DefaultAllocator;
use dirac::prelude::*;
use dirac::{Storage, Wrt};

use crate::util::Rng;
use crate::zoo::*;

fn tight() -> RadauOptions {
    RadauOptions { rtol: 1e-9, atol: 1e-11, ..RadauOptions::default() }
}

/// A random linear functional of the state: `cᵀ y` over every part of it.
fn random_weights<M: LagrangeDirac>(model: &M, seed: u64) -> State<M>
where
    DefaultAllocator: Storage<M>,
{
    let mut rng = Rng::new(seed);
    let sizes = model.sizes();
    let mut y = sizes.zeros_y::<M>();
    y.iter_mut().for_each(|x| *x = rng.uniform(-1.0, 1.0));
    State::from_y(sizes, &y)
}

fn dot<M: LagrangeDirac>(a: &State<M>, b: &State<M>) -> f64
where
    DefaultAllocator: Storage<M>,
{
    a.q.dot(&b.q) + a.v.dot(&b.v) + a.p.dot(&b.p) + a.lambda.dot(&b.lambda)
}

/// Sensitivities with respect to every parameter and every initial position and velocity.
fn everything<M: Parameters>(model: &M) -> Sensitivities<M>
where
    DefaultAllocator: Storage<M>,
{
    let mut wrt = Sensitivities::all_parameters(model);
    for name in &model.coordinate_names() {
        let c = model.coordinate(name).expect("a coordinate");
        wrt = wrt.initial_position(c).initial_velocity(c);
    }
    wrt
}

/// The run recorded whole, or within `budget` bytes.
fn record<M: Parameters + dirac::Hybrid>(
    radau: &mut Radau<'_, M>,
    start: &State<M>,
    t_end: f64,
    budget: Option<usize>,
) -> Recording<M>
where
    DefaultAllocator: Storage<M>,
{
    match budget {
        None => radau.record(0.0, start, t_end),
        Some(bytes) => radau.record_within(0.0, start, t_end, bytes),
    }
    .expect("integrates")
}

/// The adjoint gradient of `cᵀ y(T)` with respect to every parameter, initial position and
/// initial velocity equals `cᵀ s(T)` of the forward sensitivities of the same run, to
/// `1e-10` relative to the largest of them (and of 1e-3: a zero sensitivity is zero to
/// round-off of the others); measured from 3e-15 (the LC circuit) to 1e-13 (two subsystems
/// coupled by a one-form). The forward sensitivities are asked for all at once, so that each
/// step solves them exactly (checked from the statistics).
pub(crate) fn check_against_forward<M: Parameters + dirac::Hybrid>(
    model: &M,
    start: &State<M>,
    t_end: f64,
    seed: u64,
) where
    DefaultAllocator: Storage<M>,
{
    compare_with_forward(model, start, t_end, seed, None);
}

/// As [`check_against_forward`], the run recorded within `budget` bytes
/// ([`Radau::record_within`]) and so solved again step by step in the sweep; the forward run
/// solves its stages to round-off as the recorded one does. Returns the recording's steps and
/// bytes.
fn compare_with_forward<M: Parameters + dirac::Hybrid>(
    model: &M,
    start: &State<M>,
    t_end: f64,
    seed: u64,
    budget: Option<usize>,
) -> (usize, usize)
where
    DefaultAllocator: Storage<M>,
{
    let wrt = everything(model);
    let options = RadauOptions { exact_stages: budget.is_some(), ..tight() };
    let mut radau = Radau::new(model, options).expect("valid").with_sensitivities(&wrt).expect("valid");
    let recording = record(&mut radau, start, t_end, budget);
    let stats = radau.stats();
    // Exactly: by the coupled system, or (a linear model's) by one direct solve per column
    // with the step's factored matrix, which is then the stage system's own.
    let direct = stats.sensitivity_iterations == stats.steps * wrt.len();
    assert!(
        stats.coupled_sensitivity_steps == stats.steps || direct,
        "every step's sensitivities solved exactly: {stats:?}"
    );
    assert_eq!(recording.steps(), stats.steps);
    let c = random_weights(model, seed);
    let (value, _) = terminal_against_forward(model, &radau, &wrt, &recording, &c);
    let end = recording.end(model);
    assert!((value - dot(&c, &end)).abs() <= 1e-14 * value.abs().max(1.0));
    (recording.steps(), recording.bytes())
}

/// The adjoint gradient of `cᵀ y(T)` over `recording` against `cᵀ s(T)` of the forward
/// sensitivities `radau` carried to the same end, to `1e-10` relative to the largest (and of
/// 1e-3: a zero sensitivity is zero to round-off of the others). Returns the objective's value
/// and the worst relative difference.
fn terminal_against_forward<M: Parameters + dirac::Hybrid>(
    model: &M,
    radau: &Radau<'_, M>,
    wrt: &Sensitivities<M>,
    recording: &Recording<M>,
    c: &State<M>,
) -> (f64, f64)
where
    DefaultAllocator: Storage<M>,
{
    let terminal = |_: f64, y: &State<M>, out: &mut State<M>| {
        out.clone_from(c);
        dot(c, y)
    };
    let gradient = recording.gradient(model, &Objective::terminal(&terminal)).expect("a gradient");
    let mut s = State::with_sizes(model.sizes());
    let mut pairs = Vec::new();
    for (j, wrt) in wrt.wrt().iter().enumerate() {
        assert!(radau.sensitivity(j, &mut s));
        let adjoint = match *wrt {
            Wrt::Parameter(k) => gradient.parameters[k],
            Wrt::InitialPosition(i) => gradient.positions[i],
            Wrt::InitialVelocity(i) => gradient.velocities[i],
        };
        pairs.push((dot(c, &s), adjoint));
    }
    let scale = pairs.iter().fold(1e-3f64, |m, (f, _)| m.max(f.abs()));
    let mut worst = 0.0f64;
    for (j, (f, a)) in pairs.iter().enumerate() {
        let name = &radau.sensitivity_names()[j];
        assert!((f - a).abs() <= 1e-10 * scale, "∂G/∂{name}: forward {f}, adjoint {a} (scale {scale})");
        worst = worst.max((f - a).abs() / scale);
    }
    (gradient.value, worst)
}

#[test]
fn adjoint_gradients_equal_forward_sensitivities_of_the_same_run() {
    let pendulum = Pendulum { m: 1.3, g: 9.81, l: 0.7 };
    let q = VecQ::<Pendulum>::new(0.7 * 0.8f64.sin(), -0.7 * 0.8f64.cos());
    let start =
        consistent_state(&pendulum, 0.0, &q, &VecQ::<Pendulum>::new(0.2, 0.1), Consistency::default())
            .expect("a consistent start");
    check_against_forward(&pendulum, &start, 2.0, 1);

    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let mut v = VecQ::<RollingDisk>::zeros();
    (v[0], v[2], v[3]) = (0.6, 2.0, 0.7);
    let start = consistent_state(&disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
        .expect("consistent");
    check_against_forward(&disk, &start, 2.0, 2);

    let circuit = LcCircuit { ind: 1.5, cap: 0.4 };
    let start = consistent_state(
        &circuit,
        0.0,
        &VecQ::<LcCircuit>::new(0.0, 0.5),
        &VecQ::<LcCircuit>::zeros(),
        Consistency::default(),
    )
    .expect("consistent");
    check_against_forward(&circuit, &start, 3.0, 3);

    let chain = paper_chain();
    check_against_forward(&chain, &paper_chain_start(&chain), 2.0, 4);

    let coupled =
        CoupledByOneForm { wheel: Wheel { j: 0.2, k_theta: 3.0 }, cart: Cart { m: 1.5, k: 2.0 }, c: 0.7 };
    let mut q = VecQ::<CoupledByOneForm>::zeros();
    q[0] = 0.3;
    let start =
        consistent_state(&coupled, 0.0, &q, &VecQ::<CoupledByOneForm>::zeros(), Consistency::default())
            .expect("consistent");
    check_against_forward(&coupled, &start, 2.0, 5);

    // Stored sparse: an array of cells that differ, and the same ladder as a network.
    let mut ladder = unit_ladder(8);
    for (j, cell) in ladder.cells.iter_mut().enumerate() {
        cell.l = 1.0 + 0.3 * (j as f64).sin();
    }
    let start = ladder_at_rest(&ladder, &pulse(8));
    check_against_forward(&ladder, &start, 3.0, 6);
    let network = network_ladder(8);
    let mut at = State::<dirac::network::Network>::with_sizes(network.sizes());
    let start = ladder_at_rest(&unit_ladder(8), &pulse(8));
    at.q.copy_from_slice(start.q.as_slice());
    at.v.copy_from_slice(start.v.as_slice());
    at.p.copy_from_slice(start.p.as_slice());
    at.lambda.copy_from_slice(start.lambda.as_slice());
    check_against_forward(&network, &at, 3.0, 7);
}

/// Recorded within a memory budget, so small that the sweep solves the steps between
/// checkpoints again at two or more levels, the gradient still equals the forward
/// sensitivities of the same run to 1e-10 (the replayed stages are the recorded ones to
/// round-off); the recording's bytes stay within the budget, however many steps.
/// The pendulum of length 0.7 at 0.8 rad from the bottom, moving.
fn start_of_pendulum(pendulum: &Pendulum) -> State<Pendulum> {
    let q = VecQ::<Pendulum>::new(0.7 * 0.8f64.sin(), -0.7 * 0.8f64.cos());
    consistent_state(pendulum, 0.0, &q, &VecQ::<Pendulum>::new(0.2, 0.1), Consistency::default())
        .expect("a consistent start")
}

#[test]
fn checkpointed_adjoint_gradients_equal_forward_sensitivities() {
    let pendulum = Pendulum { m: 1.3, g: 9.81, l: 0.7 };
    let start = start_of_pendulum(&pendulum);
    // A pendulum's state and its step's index and time. Forty of them: twenty checkpoints of
    // the run (every 32nd step's start), ten for a segment's and two whole steps, so that a
    // segment is cut into pieces of four steps and these into two; a thousand: every second
    // step's start, and segments solved again whole.
    let state = 8 * 7 + 16;
    // And a budget far above what the run needs, which allocates only what it needs.
    for budget in [40 * state, 64 * state, 1000 * state, usize::MAX] {
        let (steps, bytes) = compare_with_forward(&pendulum, &start, 6.0, 11, Some(budget));
        assert!(steps > 100, "{steps} steps");
        assert!(
            bytes <= (budget / 2).saturating_add(8 * steps.next_power_of_two()),
            "{bytes} bytes for a budget of {budget}"
        );
    }
    let mut ladder = unit_ladder(8);
    for (j, cell) in ladder.cells.iter_mut().enumerate() {
        cell.l = 1.0 + 0.3 * (j as f64).sin();
    }
    let start = ladder_at_rest(&ladder, &pulse(8));
    let ny = 3 * ladder.sizes().nq + ladder.sizes().nc;
    let (steps, bytes) = compare_with_forward(&ladder, &start, 6.0, 12, Some(40 * (8 * ny + 40)));
    assert!(steps > 20, "{steps} steps");
    assert!(bytes <= 20 * (8 * ny + 40) + 8 * steps.next_power_of_two());
    let budget = Radau::new(&ladder, tight()).expect("valid").record_within(0.0, &start, 1.0, 100);
    let error = budget.expect_err("a budget below sixteen states");
    assert!(error.to_string().contains("at least"), "{error}");
    // Sixteen states: eight checkpoints of a run of hundreds of steps, and room in the sweep
    // for one whole step and four starts, which halve a stretch at most four times.
    let recording = Radau::new(&pendulum, tight())
        .expect("valid")
        .record_within(0.0, &start_of_pendulum(&pendulum), 6.0, 16 * state)
        .expect("recorded within sixteen states");
    let terminal = |_: f64, y: &State<Pendulum>, out: &mut State<Pendulum>| {
        out.clone_from(y);
        0.5 * y.q.norm_squared()
    };
    let error = recording.gradient(&pendulum, &Objective::terminal(&terminal)).expect_err("too little room");
    assert!(
        matches!(&error, SimError::InvalidOption { what: "budget", reason } if reason.contains("too small")),
        "{error}"
    );
}

/// Costs at sample times, `G = Σ_k c_kᵀ (q, v)(t_k)` with random `c_k` over 41 samples from the
/// start to the end, equal the forward sensitivities of the same run sampled at the same times
/// on the collocation polynomial (what `interpolate_sensitivity` samples; the state's samples
/// taken from it too, `DenseOutput::Collocation`), to 1e-10 of the largest; with every step
/// kept and with the run recorded within a budget. Returns the worst relative difference.
fn check_samples_against_forward<M: Parameters + dirac::Hybrid>(
    model: &M,
    start: &State<M>,
    t_end: f64,
    budget: Option<usize>,
) -> f64
where
    DefaultAllocator: Storage<M>,
{
    let names = model.coordinate_names();
    let wrt = everything(model);
    let options = RadauOptions {
        exact_stages: budget.is_some(),
        dense_output: dirac::DenseOutput::Collocation,
        ..tight()
    };
    let times: Vec<f64> = (0..=40).map(|k| t_end * k as f64 / 40.0).collect();
    let mut radau = Radau::new(model, options).expect("valid").with_sensitivities(&wrt).expect("valid");
    let solution =
        radau.solve_with_sensitivities(0.0, start, t_end, &Sampling::Times(times.clone())).expect("solves");
    let recording = record(&mut Radau::new(model, options).expect("valid"), start, t_end, budget);
    assert_eq!(recording.steps(), solution.stats.steps, "the same run");
    let n = names.len();
    let mut rng = Rng::new(17);
    let c: Vec<f64> = (0..times.len() * 2 * n).map(|_| rng.uniform(-1.0, 1.0)).collect();
    let cost = |k: usize, _: f64, y: &State<M>, out: &mut State<M>| {
        let ck = &c[k * 2 * n..(k + 1) * 2 * n];
        out.q.copy_from_slice(&ck[..n]);
        out.v.copy_from_slice(&ck[n..]);
        (0..n).map(|i| ck[i] * y.q[i] + ck[n + i] * y.v[i]).sum()
    };
    let gradient = recording.gradient(model, &Objective::samples(&times, &cost)).expect("a gradient");
    let coordinates: Vec<_> =
        names.iter().map(|name| model.coordinate(name).expect("a coordinate")).collect();
    let mut worst = 0.0f64;
    let mut pairs = Vec::new();
    for (j, w) in wrt.wrt().iter().enumerate() {
        let name = &solution.sensitivity_names()[j];
        let mut forward = 0.0;
        for (i, &coordinate) in coordinates.iter().enumerate() {
            let dq = solution.dq(coordinate, name).expect("a sensitivity");
            let dv = solution.dv(coordinate, name).expect("a sensitivity");
            for k in 0..times.len() {
                forward += c[k * 2 * n + i] * dq[k] + c[k * 2 * n + n + i] * dv[k];
            }
        }
        let adjoint = match *w {
            Wrt::Parameter(k) => gradient.parameters[k],
            Wrt::InitialPosition(i) => gradient.positions[i],
            Wrt::InitialVelocity(i) => gradient.velocities[i],
        };
        pairs.push((name.clone(), forward, adjoint));
    }
    let scale = pairs.iter().fold(1e-3f64, |m, (_, f, _)| m.max(f.abs()));
    for (name, f, a) in &pairs {
        worst = worst.max((f - a).abs() / scale);
        assert!((f - a).abs() <= 1e-10 * scale, "∂G/∂{name}: forward {f}, adjoint {a} (scale {scale})");
    }
    let value: f64 = (0..times.len())
        .map(|k| {
            let at = |i: usize| (solution.q(coordinates[i])[k], solution.v(coordinates[i])[k]);
            (0..n).map(|i| c[k * 2 * n + i] * at(i).0 + c[k * 2 * n + n + i] * at(i).1).sum::<f64>()
        })
        .sum();
    assert!(
        (gradient.value - value).abs() <= 1e-10 * value.abs().max(1.0),
        "G {} against {value}",
        gradient.value
    );
    worst
}

#[test]
fn sampled_costs_equal_forward_sensitivities_at_the_samples() {
    let pendulum = Pendulum { m: 1.3, g: 9.81, l: 0.7 };
    let q = VecQ::<Pendulum>::new(0.7 * 0.8f64.sin(), -0.7 * 0.8f64.cos());
    let start =
        consistent_state(&pendulum, 0.0, &q, &VecQ::<Pendulum>::new(0.2, 0.1), Consistency::default())
            .expect("a consistent start");
    let whole = check_samples_against_forward(&pendulum, &start, 2.0, None);
    let within = check_samples_against_forward(&pendulum, &start, 2.0, Some(40 * 72));
    let mut ladder = unit_ladder(8);
    for (j, cell) in ladder.cells.iter_mut().enumerate() {
        cell.l = 1.0 + 0.3 * (j as f64).sin();
    }
    let start = ladder_at_rest(&ladder, &pulse(8));
    let sparse = check_samples_against_forward(&ladder, &start, 3.0, None);
    eprintln!("sampled costs: pendulum {whole:.1e}, within a budget {within:.1e}, ladder {sparse:.1e}");
}

/// A running cost: the gradient of `∫ ½ |q|² dt + x(T)` of the pendulum against central
/// differences of whole runs (each recomputing the objective by the same quadrature) in every
/// parameter and initial velocity, to the tolerance.
#[test]
fn adjoint_gradients_of_a_running_cost_match_central_differences() {
    let options = RadauOptions { rtol: 1e-11, atol: 1e-13, ..RadauOptions::default() };
    let start_of = |p: &Pendulum, v0: VecQ<Pendulum>| {
        let q = VecQ::<Pendulum>::new(p.l * 0.8f64.sin(), -p.l * 0.8f64.cos());
        consistent_state(p, 0.0, &q, &v0, Consistency::default()).expect("a consistent start")
    };
    // Each closure writes only what its cost depends on: `out` arrives zeroed.
    let running = |_: f64, y: &State<Pendulum>, out: &mut State<Pendulum>| {
        out.q.copy_from(&y.q);
        0.5 * y.q.norm_squared()
    };
    let terminal = |_: f64, y: &State<Pendulum>, out: &mut State<Pendulum>| {
        out.q[0] = 1.0;
        y.q[0]
    };
    let objective = Objective::terminal(&terminal).with_running(&running);
    let run = |p: &Pendulum, v0: VecQ<Pendulum>| {
        let mut radau = Radau::new(p, options).expect("valid");
        let recording = radau.record(0.0, &start_of(p, v0), 1.5).expect("integrates");
        recording.gradient(p, &objective).expect("a gradient")
    };
    let pendulum = Pendulum { m: 1.3, g: 9.81, l: 0.7 };
    let v0 = VecQ::<Pendulum>::new(0.2, 0.1);
    let gradient = run(&pendulum, v0);
    for k in 0..pendulum.parameter_count() {
        let theta = pendulum.parameter_value(k);
        let step = 1e-4 * theta;
        let at = |value: f64| {
            let mut moved = pendulum.clone();
            moved.set_parameter_value(k, value);
            run(&moved, v0).value
        };
        let fd = (at(theta + step) - at(theta - step)) / (2.0 * step);
        let name = &pendulum.parameter_names()[k];
        // Read by the parameter's name, as a user would.
        let adjoint = gradient.parameter(name).expect("a parameter of the model");
        assert!(
            (adjoint - fd).abs() <= 1e-6 * fd.abs().max(1.0),
            "∂G/∂{name}: adjoint {adjoint}, central difference {fd}"
        );
    }
    assert_eq!(gradient.parameter("no such parameter"), None);
    let names: Vec<&str> = gradient.parameters_by_name().map(|(name, _)| name).collect();
    assert_eq!(names, ["m", "g", "l"]);
    for i in 0..2 {
        let step = 1e-5;
        let at = |delta: f64| {
            let mut v = v0;
            v[i] += delta;
            run(&pendulum, v).value
        };
        let fd = (at(step) - at(-step)) / (2.0 * step);
        assert!(
            (gradient.velocities[i] - fd).abs() <= 1e-6 * fd.abs().max(1.0),
            "∂G/∂v0[{i}]: adjoint {}, central difference {fd}",
            gradient.velocities[i]
        );
    }
}

/// What the sweep cannot differentiate is refused by name before any work: a run with the
/// projection onto the constraints on, and a model with a contact (whose impacts `solve` would
/// apply and the sweep would not differentiate: integrating through the floor instead would
/// be a wrong answer).
/// The adjoint gradient of `cᵀ y(T)` over a run through impacts equals `cᵀ s(T)` of the
/// forward sensitivities carried through the same impacts by a second run with the same steps
/// (the forward by the saltation matrix, the sweep by its transpose), to `1e-10` of the
/// largest. Returns the worst relative difference and the number of impacts.
fn check_through_impacts<M: Parameters + dirac::Hybrid>(
    model: &M,
    start: &State<M>,
    t_end: f64,
    seed: u64,
) -> (f64, usize)
where
    DefaultAllocator: Storage<M>,
{
    let (worst, solution) = adjoint_against_forward(model, start, t_end, seed);
    (worst, solution.impacts().len())
}

/// The worst relative difference between the adjoint gradient of a random `cᵀ y(T)` and the
/// forward sensitivities' of a second run with the same steps, and that run's solution.
fn adjoint_against_forward<M: Parameters + dirac::Hybrid>(
    model: &M,
    start: &State<M>,
    t_end: f64,
    seed: u64,
) -> (f64, Solution<M, dirac::RadauStats>)
where
    DefaultAllocator: Storage<M>,
{
    let wrt = everything(model);
    let mut radau = Radau::new(model, tight()).expect("valid").with_sensitivities(&wrt).expect("valid");
    let solution =
        radau.solve_with_sensitivities(0.0, start, t_end, &Sampling::Times(vec![t_end])).expect("integrates");
    let recording = Radau::new(model, tight()).expect("valid").record(0.0, start, t_end).expect("records");
    assert_eq!(recording.steps(), solution.stats.steps, "the same steps");
    let (_, worst) = terminal_against_forward(model, &radau, &wrt, &recording, &random_weights(model, seed));
    (worst, solution)
}

/// As [`check_through_impacts`], across the model's switching surfaces: the worst relative
/// difference and the number of crossings (the solution's events).
fn check_through_crossings<M: Parameters + dirac::Hybrid>(
    model: &M,
    start: &State<M>,
    t_end: f64,
    seed: u64,
) -> (f64, usize)
where
    DefaultAllocator: Storage<M>,
{
    let (worst, solution) = adjoint_against_forward(model, start, t_end, seed);
    (worst, solution.events().len())
}

/// Through impacts: a ball pulled by a sine (its flight not a parabola) bouncing on its floor,
/// a bar striking the floor with both ends, a pendulum on a rod against its wall.
#[test]
fn adjoint_gradients_through_impacts_equal_forward_sensitivities() {
    let ball = LiftedBall { m: 1.0, g: 9.81, e: 0.8, f0: 3.0, om: 5.0 };
    let mut start = State::<LiftedBall>::zeros();
    start.set_q(LiftedBall::Y, 1.0);
    let (worst, impacts) = check_through_impacts(&ball, &start, 2.0, 21);
    eprintln!("lifted ball: {impacts} impacts, worst relative difference {worst:e}");
    assert!(impacts >= 2);

    let bar = Bar { m: 1.0, j: 0.2, g: 9.81, l: 1.0, e: 0.5 };
    let q = VecQ::<Bar>::new(0.0, 0.6, 0.3);
    let v = VecQ::<Bar>::new(0.2, -1.0, 0.5);
    let start = consistent_state(&bar, 0.0, &q, &v, Consistency::default()).expect("a start");
    let (worst, impacts) = check_through_impacts(&bar, &start, 0.6, 22);
    eprintln!("bar: {impacts} impacts, worst relative difference {worst:e}");
    assert!(impacts >= 2);

    let (l, theta0, theta_w) = (1.3, 1.2f64, 0.4f64);
    let pendulum = PendulumAndWall { m: 0.7, g: 9.81, l, e: 0.6, w: l * theta_w.sin() };
    let q = VecQ::<PendulumAndWall>::new(l * theta0.sin(), -l * theta0.cos());
    let v = VecQ::<PendulumAndWall>::new(-0.3, 0.0);
    let start = consistent_state(&pendulum, 0.0, &q, &v, Consistency::default()).expect("a start");
    let (worst, impacts) = check_through_impacts(&pendulum, &start, 2.0, 23);
    eprintln!("pendulum against its wall: {impacts} impacts, worst relative difference {worst:e}");
    assert!(impacts >= 2);
}

/// Across switching surfaces: the adjoint gradient of `cᵀ y(T)` equals `cᵀ s(T)` of the
/// forward sensitivities carried across the same crossings (the forward by the jump
/// `I + (f⁻ − f⁺) ∂t*/∂x`, the sweep by its transpose), to `1e-10` of the largest. A spring
/// with Coulomb friction (a surface on the velocity, crossed where the motion turns) and a
/// brake past a point (one on the position); a pendulum on a rod whose damper engages past a
/// point; the zoo's model with every non-smooth function.
#[test]
fn adjoint_gradients_across_switching_surfaces_equal_forward_sensitivities() {
    let spring = CoulombSpring { m: 1.0, k: 4.0, mu: 0.05, a: 0.1, f: 0.2 };
    let mut start = State::<CoulombSpring>::zeros();
    start.v[0] = 1.0;
    start.p[0] = 1.0;
    let (worst, crossings) = check_through_crossings(&spring, &start, 2.5, 31);
    eprintln!("Coulomb spring: {crossings} crossings, worst relative difference {worst:e}");
    assert!(crossings >= 3, "{crossings}");

    let (l, theta0) = (1.0, 1.0f64);
    let pendulum = DampedPastW { m: 0.7, g: 9.81, l, w: 0.3, c: 0.8 };
    let q = VecQ::<DampedPastW>::new(-l * theta0.sin(), -l * theta0.cos());
    let start = consistent_state(&pendulum, 0.0, &q, &VecQ::<DampedPastW>::zeros(), Consistency::default())
        .expect("a start");
    let (worst, crossings) = check_through_crossings(&pendulum, &start, 3.0, 32);
    eprintln!("pendulum with a damper past w: {crossings} crossings, worst relative difference {worst:e}");
    assert!(crossings >= 2, "{crossings}");

    let right = CoulombSpring { m: 2.0, k: 3.0, mu: 0.1, a: -0.2, f: 0.4 };
    let pair = CoulombPair { left: spring.clone(), right, c: 0.3 };
    let mut start = State::<CoulombPair>::zeros();
    let v = VecQ::<CoulombPair>::new(0.7, 1.0);
    start = consistent_state(&pair, 0.0, &start.q, &v, Consistency::default()).expect("a start");
    let (worst, crossings) = check_through_crossings(&pair, &start, 2.5, 34);
    eprintln!("two Coulomb springs linked: {crossings} crossings, worst relative difference {worst:e}");
    assert!(crossings >= 3, "{crossings}");

    let model = NonSmooth { m: 1.2, k: 2.0, gap: 0.3, c: 0.4, fmax: 0.5, mu: 0.05 };
    let q = VecQ::<NonSmooth>::new(0.9, -0.4);
    let v = VecQ::<NonSmooth>::new(0.2, 0.7);
    let start = consistent_state(&model, 0.0, &q, &v, Consistency::default()).expect("a start");
    let (worst, crossings) = check_through_crossings(&model, &start, 3.0, 33);
    eprintln!("every non-smooth function: {crossings} crossings, worst relative difference {worst:e}");
    assert!(crossings >= 4, "{crossings}");
}

/// Across laws' switches: the adjoint gradient of `cᵀ y(T)` equals `cᵀ s(T)` of the forward
/// sensitivities carried across the same switches (the jump of the rate from the old mode to
/// the new, `I + (f⁻ − f⁺) ∂t*/∂x`, the sweep by its transpose), to `1e-10` of the largest. The
/// friction belt, which sticks and slips twice (a release's time follows from the law's force,
/// a multiplier); a half-wave rectifier's ideal diode, which conducts and blocks (its current,
/// a multiplier); a capacitor charged through an ideal switch; the belt's block with its
/// friction as a part of an interconnection.
#[test]
fn adjoint_gradients_across_laws_equal_forward_sensitivities() {
    use crate::every_method::switching::{Block, BlockOnSpring, HalfWave, SwitchedCharge, WallSpring};
    let belt = FrictionBelt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 };
    let (worst, switches) = check_through_crossings(&belt, &State::<FrictionBelt>::zeros(), 6.5, 41);
    eprintln!("friction belt: {switches} switches, worst relative difference {worst:e}");
    assert!(switches >= 4, "{switches}");

    let rectifier = HalfWave { u: 1.0, w: 1.0, c: 2.0, r: 1.0 };
    let (worst, switches) = check_through_crossings(&rectifier, &State::<HalfWave>::zeros(), 9.0, 42);
    eprintln!("half-wave rectifier: {switches} switches, worst relative difference {worst:e}");
    assert!(switches >= 3, "{switches}");

    let charge = SwitchedCharge { u: 1.0, w: 1.0, c: 1.0, r: 1.0 };
    let zero = VecQ::<SwitchedCharge>::zeros();
    let start = consistent_state(&charge, 0.0, &zero, &zero, Consistency::default()).expect("a start");
    let (worst, switches) = check_through_crossings(&charge, &start, 9.0, 43);
    eprintln!("switched charge: {switches} switches, worst relative difference {worst:e}");
    assert!(switches >= 3, "{switches}");

    let (m, k, vb, n, mu_s, mu_k) = (1.0, 4.0, 0.5, 9.81, 0.4, 0.25);
    let composite = BlockOnSpring { block: Block { m, vb, n, mu_s, mu_k }, spring: WallSpring { k } };
    let zero = VecQ::<BlockOnSpring>::zeros();
    let start = consistent_state(&composite, 0.0, &zero, &zero, Consistency::default()).expect("a start");
    let (worst, switches) = check_through_crossings(&composite, &start, 6.5, 44);
    eprintln!(
        "block on a spring (interconnection): {switches} switches, worst relative difference {worst:e}"
    );
    assert!(switches >= 4, "{switches}");
}

/// A spring's force held at `u_k` over `[t_k, t_{k+1})` (`record_held`): the gradient with
/// respect to every sample, and to the parameters, of `G = x(T)`, against the closed form. From
/// rest, `x(T) = Σ_k (u_k/k) (cos ω(T − t_{k+1}) − cos ω(T − t_k))`, `ω = √(k/m)`, `t_K = T`:
/// `∂G/∂u_k` is its coefficient, and `∂G/∂k`, `∂G/∂m` and `∂G/∂f` (the input's field, whose
/// derivative is a shift of every sample) are central differences (step 1e-6) of it.
#[test]
fn adjoint_gradients_with_respect_to_held_inputs_match_the_closed_form() {
    let spring = ForcedSpring { m: 1.3, k: 4.0, f: 0.0 };
    let times = [0.0, 0.5, 1.0, 1.5];
    let samples = [0.3, -1.0, 0.7, 2.0];
    let t_end = 2.0;
    let exact = |s: &ForcedSpring, u: &[f64]| {
        let w = (s.k / s.m).sqrt();
        let after = |k: usize| times.get(k + 1).copied().unwrap_or(t_end);
        (0..times.len())
            .map(|k| u[k] / s.k * ((w * (t_end - after(k))).cos() - (w * (t_end - times[k])).cos()))
            .sum::<f64>()
    };
    let mut model = spring.clone();
    let recording = Radau::new(&mut model, RadauOptions::tolerances(1e-11, 1e-13))
        .expect("valid")
        .record_held(0.0, &State::<ForcedSpring>::zeros(), t_end, &times, &[(ForcedSpring::F, &samples)])
        .expect("records");
    let terminal = |_: f64, y: &State<ForcedSpring>, out: &mut State<ForcedSpring>| {
        out.q[0] = 1.0;
        y.q[0]
    };
    let objective = Objective::terminal(&terminal);
    let gradient = recording.gradient_held(&spring, &objective).expect("a gradient");
    assert!((gradient.value - exact(&spring, &samples)).abs() < 1e-9, "x(T) = {}", gradient.value);
    for k in 0..times.len() {
        let mut unit = [0.0; 4];
        unit[k] = 1.0;
        let want = exact(&spring, &unit);
        let got = gradient.inputs[0][k];
        eprintln!("∂x(T)/∂u_{k}: {got} against {want}");
        assert!((got - want).abs() < 1e-8, "∂x(T)/∂u_{k}: {got} against {want}");
    }
    for (k, name) in spring.parameter_names().iter().enumerate() {
        let h = 1e-6;
        let (mut plus, mut minus) = (spring.clone(), spring.clone());
        plus.set_parameter_value(k, spring.parameter_value(k) + h);
        minus.set_parameter_value(k, spring.parameter_value(k) - h);
        // The input's own field is a parameter too: its derivative is a shift of every sample's.
        let shifted = |d: f64| samples.map(|u| u + d);
        let want = if name == "f" {
            (exact(&spring, &shifted(h)) - exact(&spring, &shifted(-h))) / (2.0 * h)
        } else {
            (exact(&plus, &samples) - exact(&minus, &samples)) / (2.0 * h)
        };
        let got = gradient.parameters[k];
        eprintln!("∂x(T)/∂{name}: {got} against {want}");
        assert!((got - want).abs() < 1e-7 * want.abs().max(1.0), "∂x(T)/∂{name}: {got} against {want}");
    }
    // The plain gradient refuses the run, which it would sweep with the last samples' inputs.
    let error = recording.gradient(&spring, &objective).expect_err("held inputs");
    assert!(matches!(&error, SimError::InvalidOption { what: "adjoint", .. }), "{error}");
    // Samples that do not start at t0, and an integrator that cannot set inputs.
    let error = Radau::new(&mut model, RadauOptions::default())
        .expect("valid")
        .record_held(
            0.0,
            &State::<ForcedSpring>::zeros(),
            t_end,
            &[0.1, 1.0],
            &[(ForcedSpring::F, &[1.0, 2.0])],
        )
        .expect_err("the samples start late");
    assert!(matches!(&error, SimError::InvalidOption { what: "held inputs", .. }), "{error}");
    let error = Radau::new(&spring, RadauOptions::default())
        .expect("valid")
        .record_held(0.0, &State::<ForcedSpring>::zeros(), t_end, &times, &[(ForcedSpring::F, &samples)])
        .expect_err("a shared model");
    assert!(matches!(&error, SimError::SharedModel { .. }), "{error}");
    // An input in the mass matrix would make the momentum jump at each change.
    let mut adjustable = AdjustableMass { m: 1.0, dm: 0.0, k: 4.0 };
    let mut start = State::<AdjustableMass>::zeros();
    start.q[0] = 0.5;
    let error = Radau::new(&mut adjustable, RadauOptions::default())
        .expect("valid")
        .record_held(0.0, &start, 1.0, &[0.0, 0.5], &[(AdjustableMass::DM, &[0.1, 0.2])])
        .expect_err("an input in the momenta");
    assert!(
        matches!(&error, SimError::InvalidOption { what: "held inputs", reason } if reason.contains("`dm`")),
        "{error}"
    );
}

/// The Coulomb spring's exact motion at `t`: harmonic between crossings, under the constant
/// force `−μ sgn v − f [x > a]` of each phase, from `x = 0` at speed `v0`; each crossing of
/// `x = a` or `v = 0` found by bisection on the closed form to round-off.
fn coulomb_spring_exact(s: &CoulombSpring, v0: f64, t_end: f64) -> (f64, f64) {
    let w = (s.k / s.m).sqrt();
    let flow = |x: f64, v: f64, force: f64, t: f64| {
        let c = force / s.k;
        (
            c + (x - c) * (w * t).cos() + v / w * (w * t).sin(),
            -(x - c) * w * (w * t).sin() + v * (w * t).cos(),
        )
    };
    let (mut t, mut x, mut v) = (0.0, 0.0, v0);
    let (mut moving, mut past) = (v.signum(), if x > s.a { 1.0 } else { -1.0 });
    loop {
        let force = -s.mu * moving - if past > 0.0 { s.f } else { 0.0 };
        // Signed so that both are positive until their surface is crossed.
        let gaps = |tau: f64| {
            let (xs, vs) = flow(x, v, force, tau);
            ((xs - s.a) * past, vs * moving)
        };
        let grid = 4000;
        let dt = (t_end - t) / f64::from(grid);
        let crossing = (1..=grid).find_map(|i| {
            let (g, h) = gaps(f64::from(i) * dt);
            (g < 0.0 || h < 0.0).then(|| (f64::from(i - 1) * dt, f64::from(i) * dt, g < 0.0))
        });
        let Some((mut lo, mut hi, position)) = crossing else { return flow(x, v, force, t_end - t) };
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            let (g, h) = gaps(mid);
            if (if position { g } else { h }) > 0.0 { lo = mid } else { hi = mid }
        }
        let tau = 0.5 * (lo + hi);
        (x, v) = flow(x, v, force, tau);
        t += tau;
        if position { past = -past } else { moving = -moving }
    }
}

/// The forward sensitivities across switching surfaces against central differences (step
/// 1e-6) of the exact motion (`coulomb_spring_exact`): the Coulomb spring at `t = 2.5`,
/// through four crossings of its friction's surface and its brake's. (Differences of whole
/// simulations are no reference here: the solves' own errors, about the tolerance, are not
/// smooth in the parameters where a crossing moves.)
#[test]
fn sensitivities_across_switching_surfaces_match_the_exact_motion() {
    let spring = CoulombSpring { m: 1.0, k: 4.0, mu: 0.05, a: 0.1, f: 0.2 };
    let v0 = 1.0;
    let mut start = State::<CoulombSpring>::zeros();
    (start.v[0], start.p[0]) = (v0, spring.m * v0);
    let t_end = 2.5;
    let wrt = Sensitivities::all_parameters(&spring).initial_velocity(CoulombSpring::X);
    let solution = Radau::new(&spring, RadauOptions::tolerances(1e-11, 1e-13))
        .expect("valid")
        .with_sensitivities(&wrt)
        .expect("valid")
        .solve_with_sensitivities(0.0, &start, t_end, &Sampling::Times(vec![t_end]))
        .expect("integrates");
    assert_eq!(solution.events().len(), 4, "four crossings");
    let mut failures = 0;
    for name in ["m", "k", "mu", "a", "f", "v(t0)"] {
        let h = 1e-6;
        let (mut plus, mut minus) = (spring.clone(), spring.clone());
        let (mut up, mut down) = (v0, v0);
        match name {
            "m" => (plus.m, minus.m) = (spring.m + h, spring.m - h),
            "k" => (plus.k, minus.k) = (spring.k + h, spring.k - h),
            "mu" => (plus.mu, minus.mu) = (spring.mu + h, spring.mu - h),
            "a" => (plus.a, minus.a) = (spring.a + h, spring.a - h),
            "f" => (plus.f, minus.f) = (spring.f + h, spring.f - h),
            _ => (up, down) = (v0 + h, v0 - h),
        }
        let (xp, vp) = coulomb_spring_exact(&plus, up, t_end);
        let (xm, vm) = coulomb_spring_exact(&minus, down, t_end);
        let (dx, dv) = ((xp - xm) / (2.0 * h), (vp - vm) / (2.0 * h));
        let got_x = solution.dq(CoulombSpring::X, name).expect("a sensitivity")[0];
        let got_v = solution.dv(CoulombSpring::X, name).expect("a sensitivity")[0];
        eprintln!("∂x/∂{name}: {got_x} against {dx}; ∂v/∂{name}: {got_v} against {dv}");
        failures += usize::from((got_x - dx).abs() > 1e-7 * dx.abs().max(1.0));
        failures += usize::from((got_v - dv).abs() > 1e-7 * dv.abs().max(1.0));
    }
    assert_eq!(failures, 0, "sensitivities off the exact motion's");
}

#[test]
fn adjoints_out_of_reach_are_refused_with_the_reason() {
    let pendulum = unit_pendulum();
    let options = RadauOptions { projection: true, ..RadauOptions::default() };
    let error = Radau::new(&pendulum, options)
        .expect("valid")
        .record(0.0, &horizontal_start(&pendulum), 1.0)
        .expect_err("projection has no derivative");
    assert!(
        matches!(&error, SimError::InvalidOption { what: "adjoint", reason } if reason.contains("projection")),
        "{error}"
    );
    // Sample times that are not a rising sequence within the run, or a cost that is not finite.
    let recording = Radau::new(&pendulum, RadauOptions::default())
        .expect("valid")
        .record(0.0, &horizontal_start(&pendulum), 1.0)
        .expect("integrates");
    let cost = |_: usize, _: f64, y: &State<Pendulum>, out: &mut State<Pendulum>| {
        out.clone_from(y);
        0.5 * y.q.norm_squared()
    };
    for times in [vec![0.2, f64::NAN], vec![0.5, 0.2], vec![0.5, 1.5]] {
        let error = recording.gradient(&pendulum, &Objective::samples(&times, &cost)).expect_err("refused");
        assert!(
            matches!(&error, SimError::InvalidOption { what: "samples", .. }),
            "samples at {times:?}: {error}"
        );
    }
    let blows_up = |_: f64, _: &State<Pendulum>, out: &mut State<Pendulum>| {
        out.components_mut().for_each(|x| *x = f64::NAN);
        0.0
    };
    let error = recording.gradient(&pendulum, &Objective::terminal(&blows_up)).expect_err("not finite");
    assert!(matches!(&error, SimError::NonFinite { .. }), "{error}");
    // Within a budget, impacts are not crossed yet; nor is a running cost over a run with
    // impacts, whose cut steps would count past them.
    let ball = BouncingBall { m: 1.0, g: 9.81, e: 0.8 };
    let mut start = State::<BouncingBall>::zeros();
    start.set_q(BouncingBall::Y, 1.0);
    let error = Radau::new(&ball, RadauOptions::default())
        .expect("valid")
        .record_within(0.0, &start, 2.0, 100_000)
        .expect_err("impacts are not crossed within a budget");
    assert!(
        matches!(&error, SimError::InvalidOption { what: "adjoint", reason } if reason.contains("floor")),
        "{error}"
    );
    let spring = CoulombSpring { m: 1.0, k: 4.0, mu: 0.05, a: 0.1, f: 0.2 };
    let mut moving = State::<CoulombSpring>::zeros();
    (moving.v[0], moving.p[0]) = (0.5, 0.5);
    let error = Radau::new(&spring, RadauOptions::default())
        .expect("valid")
        .record_within(0.0, &moving, 2.0, 100_000)
        .expect_err("switching surfaces are not crossed within a budget");
    assert!(
        matches!(&error, SimError::InvalidOption { what: "adjoint", reason } if reason.contains("switching")),
        "{error}"
    );
    let belt = FrictionBelt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 };
    let error = Radau::new(&belt, RadauOptions::default())
        .expect("valid")
        .record_within(0.0, &State::<FrictionBelt>::zeros(), 2.0, 100_000)
        .expect_err("laws are not crossed within a budget");
    assert!(
        matches!(&error, SimError::InvalidOption { what: "adjoint", reason } if reason.contains("laws")),
        "{error}"
    );
    let recording =
        Radau::new(&ball, RadauOptions::default()).expect("valid").record(0.0, &start, 2.0).expect("records");
    let running = |_: f64, y: &State<BouncingBall>, out: &mut State<BouncingBall>| {
        out.clone_from(y);
        0.5 * y.q.norm_squared()
    };
    let error = recording.gradient(&ball, &Objective::running(&running)).expect_err("a running cost");
    assert!(matches!(&error, SimError::InvalidOption { what: "adjoint", .. }), "{error}");
}
