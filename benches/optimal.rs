//! One round of the optimal control benchmark's dirac side (benches/peers/optimal.sh runs it
//! alternately with CasADi's, benches/peers/optimal.py): a problem transcribed by DMOC and
//! solved by IPOPT (`dirac` rows) and by the pure-Rust interior point (`interior` rows), for
//! each number of intervals given, one CSV line each:
//! `tool,problem,N,cost,iterations,solve seconds,evaluation seconds,transcription seconds`.
//! The problems: `cartpole`, the cart-pole's swing-up (2 s from hanging to upright at rest,
//! |x| <= 1.5 m, |f| <= 20 N); `chain8`, the 8-link chain with a torque at each joint raised
//! from hanging at rest to every link at 0.5 rad at rest in 2 s. Both cost the integral of the
//! squared inputs over 2. `acrobot`: two 1 kg, 1 m links with a torque only at the elbow,
//! swung up from hanging at rest to upright at rest in 3 s, inputs unbounded. `panda`: the
//! Panda's arm from its URDF file with a torque at each joint, from one pose to another at rest
//! in 2 s, within the file's joint limits and efforts, costing the squared torques and ten
//! times the squared joint velocities over 2.
//!
//! With `TRANSCRIPTION=collocation` in the environment, each problem is transcribed by Radau IIA
//! collocation (`optimal::Collocation`) instead of DMOC.
//!
//! `mpc` is the receding horizon instead: the cart-pole, simulated by Radau from 0.5 rad off
//! upright, under a 100 Hz MPC (1 s horizon on N intervals, |f| <= 20 N, |x| <= 1.5 m) on the
//! interior point, warm started; then IPOPT solving the same samples' problems, each from the
//! last IPOPT optimum as its guess. One line per solver:
//! `mpc,solver,N,samples,median ms,p90 ms,max ms,max iterations,failures,final |theta - pi|`.
//!
//!   cargo bench -p dirac-benches --bench optimal -- cartpole 50 100
//!   cargo bench -p dirac-benches --bench optimal -- mpc 20

use std::f64::consts::PI;
use std::time::Instant;

use dirac::optimal::interior::{InteriorOptions, InteriorPoint};
use dirac::optimal::ipopt::IpoptOptions;
use dirac::optimal::{Collocation, Dmoc, Mpc, OptimalError, Optimum, Problem, Transcription};
use dirac::prelude::*;
use dirac::{DenseModel, InputsOutputs, State, Storage, VecQ};
use dirac_benches::zoo::robots::panda_point_to_point;
use dirac_benches::zoo::{Acrobot, CartPole, Chain8, acrobot, cart_pole, cart_pole_balance};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let name = args.iter().find(|a| a.parse::<usize>().is_err()).map_or("cartpole", String::as_str);
    let sizes: Vec<usize> = args.iter().filter_map(|a| a.parse().ok()).collect();
    let sizes = if sizes.is_empty() { vec![50, 100] } else { sizes };
    for n in sizes {
        let started = Instant::now();
        match name {
            "cartpole" => {
                let problem = Problem::new(cart_pole(), 2.0, n)
                    .final_state(VecQ::<CartPole>::from([0.0, PI]), VecQ::<CartPole>::zeros())
                    .position_bounds(CartPole::X, -1.5, 1.5)
                    .input_bounds(CartPole::F, -20.0, 20.0);
                run(name, n, problem, started);
            }
            "chain8" => {
                let chain = Chain8 {
                    m: 0.2,
                    l: 0.25,
                    g: 9.81,
                    u1: 0.0,
                    u2: 0.0,
                    u3: 0.0,
                    u4: 0.0,
                    u5: 0.0,
                    u6: 0.0,
                    u7: 0.0,
                    u8: 0.0,
                };
                let problem = Problem::new(chain, 2.0, n)
                    .final_state(VecQ::<Chain8>::from_element(0.5), VecQ::<Chain8>::zeros());
                run(name, n, problem, started);
            }
            "acrobot" => {
                let problem = Problem::new(acrobot(), 3.0, n)
                    .final_state(VecQ::<Acrobot>::from([PI, PI]), VecQ::<Acrobot>::zeros());
                run(name, n, problem, started);
            }
            "panda" => run(name, n, panda_point_to_point(n), started),
            "mpc" => mpc(n),
            other => {
                eprintln!("no problem `{other}`: cartpole, chain8, acrobot, panda or mpc");
                std::process::exit(2);
            }
        }
    }
}

fn run<M>(name: &str, n: usize, problem: Problem<M>, started: Instant)
where
    M: DenseModel + InputsOutputs + Clone,
    dirac::nalgebra::DefaultAllocator: Storage<M>,
{
    let collocated = std::env::var("TRANSCRIPTION").is_ok_and(|t| t == "collocation");
    for tool in ["dirac", "interior"] {
        let started = if tool == "dirac" { started } else { Instant::now() };
        let optimum = match collocated {
            true => {
                let collocation = Collocation::new(problem.clone()).unwrap_or_else(|e| fail(n, tool, e));
                solve(name, n, tool, collocation, started)
            }
            false => {
                let dmoc = Dmoc::new(problem.clone()).unwrap_or_else(|e| fail(n, tool, e));
                solve(name, n, tool, dmoc, started)
            }
        };
        let (o, transcription) = match optimum {
            (Ok(o), transcription) => (o, transcription),
            // The interior point has no restoration phase: its failures are reported and the
            // round goes on with IPOPT's rows.
            (Err(error), _) if tool == "interior" => {
                eprintln!("{name} N = {n}, {tool}: {error}");
                continue;
            }
            (Err(error), _) => fail(n, tool, error),
        };
        println!(
            "{tool},{name},{n},{:.12e},{},{:.6e},{:.6e},{:.6e}",
            o.cost,
            o.iterations,
            o.wall.as_secs_f64(),
            o.evaluation.as_secs_f64(),
            transcription.as_secs_f64()
        );
    }
}

/// Solves a transcription made since `started` with `tool`: the result, and how long the
/// transcription took to make.
fn solve<T: Transcription>(
    name: &str,
    n: usize,
    tool: &str,
    mut transcription: T,
    started: Instant,
) -> (Result<Optimum, OptimalError>, std::time::Duration) {
    let made = started.elapsed();
    let optimum = match tool {
        "dirac" => transcription.solve(&IpoptOptions::default()),
        _ => {
            if let Ok(solver) = InteriorPoint::new(&transcription) {
                eprintln!(
                    "{name} N = {n}: {} variables, {} Jacobian and {} Hessian entries; the KKT's half bandwidth is {}",
                    transcription.variables(),
                    transcription.jacobian_pattern().len(),
                    transcription.hessian_pattern().len(),
                    solver.bandwidth()
                );
            }
            transcription.solve_interior(&InteriorOptions::default())
        }
    };
    (optimum, made)
}

fn fail(n: usize, tool: &str, error: OptimalError) -> ! {
    eprintln!("N = {n}, {tool}: {error}");
    std::process::exit(1);
}

/// The 100 Hz receding horizon on the cart-pole, solved by the interior point in the loop and
/// by IPOPT on the same samples afterwards.
fn mpc(n: usize) {
    let upright = PI;
    let problem = cart_pole_balance(n);
    let mut controller = Mpc::new(problem.clone(), InteriorOptions::default()).expect("well-formed");
    let mut plant = cart_pole();
    let q = VecQ::<CartPole>::from([0.0, upright - 0.5]);
    let start = consistent_state(&plant, 0.0, &q, &VecQ::<CartPole>::zeros(), Consistency::default())
        .expect("consistent");
    let mut measured: Vec<(f64, State<CartPole>)> = Vec::new();
    let mut radau = Radau::new(&mut plant, RadauOptions::default()).expect("valid");
    let solution = radau
        .run(0.0, &start, 4.0)
        .every(0.01, |t, state, plant: &mut CartPole| {
            measured.push((t, state.clone()));
            controller.apply(t, state, plant);
        })
        .solve()
        .expect("the closed loop runs");
    let theta = solution.q(CartPole::THETA);
    let error = (theta[theta.len() - 1] - upright).abs();
    let samples = controller.samples();
    let times: Vec<f64> = samples.iter().map(|s| s.solve.as_secs_f64()).collect();
    let iterations = samples.iter().map(|s| s.iterations).max().unwrap_or(0);
    let failures = samples.iter().filter(|s| s.status != "Solve_Succeeded").count();
    report("interior", n, &times, iterations, failures, error);

    // IPOPT on the same states, each from the last optimum (IPOPT's set-up counted, as it is
    // paid at every sample).
    let mut times = Vec::with_capacity(measured.len());
    let (mut iterations, mut failures) = (0, 0);
    // The last optimum's positions and inputs.
    let mut guess: Option<Guess> = None;
    let options = IpoptOptions::default();
    for (t, state) in &measured {
        let started = Instant::now();
        let mut p = problem.clone().starting_at(*t).start(state.q, state.v);
        if let Some((positions, inputs)) = guess.take() {
            p = p.guess(positions, inputs);
        }
        match Dmoc::new(p).expect("well-formed").solve(&options) {
            Ok(o) => {
                iterations = iterations.max(o.iterations);
                guess = Some((o.positions, o.inputs));
            }
            Err(_) => failures += 1,
        }
        times.push(started.elapsed().as_secs_f64());
    }
    report("ipopt", n, &times, iterations, failures, f64::NAN);
}

/// Positions at the nodes and inputs on the intervals.
type Guess = (Vec<Vec<f64>>, Vec<Vec<f64>>);

fn report(solver: &str, n: usize, times: &[f64], iterations: usize, failures: usize, error: f64) {
    let mut sorted = times.to_vec();
    sorted.sort_by(f64::total_cmp);
    let at = |q: f64| 1e3 * sorted[((sorted.len() - 1) as f64 * q).round() as usize];
    println!(
        "mpc,{solver},{n},{},{:.4},{:.4},{:.4},{iterations},{failures},{error:.3e}",
        sorted.len(),
        at(0.5),
        at(0.9),
        at(1.0)
    );
}
