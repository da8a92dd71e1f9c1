//! Small-model runs whose instructions `benches/small_models.sh` counts under callgrind, to
//! compare two commits exactly on a shared, noisy machine: `small_models CASE REPEATS` runs one
//! case `REPEATS` times and prints a checksum (the steps taken, or a final coordinate).
//!
//! Cases: Radau on the paper's chain (t = 20, tol 1e-8/1e-10), on the Cartesian pendulum
//! (t = 10, tol 1e-8) and on the 8-link pendulum (t = 10, tol 1e-8/1e-10); 2000 variational
//! steps of h = 0.01 on the pendulum (separable path and, with `use_structure: false`, general
//! path) and on the chain (general path); Explicit on the chain (t = 20, tol 1e-8/1e-10) and on
//! the Cartesian pendulum (t = 10, tol 1e-8) and on the 8-link pendulum (the work-precision
//! problem: t = 2, tol 1e-6); Radau and Explicit on the saturated servo (t = 4, tol
//! 1e-8/1e-10: its switching surfaces located in the solve).

#![allow(missing_docs)]

use dirac_benches::zoo;

use dirac::State;
use dirac::prelude::*;
use zoo::*;

fn radau<M: DenseModel>(model: &M, start: &State<M>, t_end: f64, rtol: f64, atol: f64) -> f64
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut radau = Radau::new(model, RadauOptions::tolerances(rtol, atol)).expect("valid");
    let solution = radau.solve(0.0, start, t_end, &Sampling::Times(vec![t_end])).expect("integrates");
    solution.stats.steps as f64
}

fn explicit<M: DenseModel>(model: &M, start: &State<M>, t_end: f64, rtol: f64, atol: f64) -> f64
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut explicit = Explicit::new(model, ExplicitOptions::tolerances(rtol, atol)).expect("valid");
    let solution = explicit.solve(0.0, start, t_end, &Sampling::Times(vec![t_end])).expect("integrates");
    solution.stats.steps as f64
}

fn variational<M: DenseModel>(model: &M, start: &State<M>, options: VariationalOptions) -> f64
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut vi = Variational::new(model, 0.01, options).expect("valid");
    vi.start(0.0, start, 20.0).expect("starts");
    for _ in 0..2000 {
        vi.step().expect("steps");
    }
    vi.state().q[0]
}

fn main() {
    let mut args = std::env::args().skip(1);
    let case = args.next().unwrap_or_default();
    let repeats: usize = args.next().and_then(|r| r.parse().ok()).unwrap_or(1);

    let chain = paper_chain();
    let mut q = VecQ::<Chain>::zeros();
    q[0] = 0.1;
    let chain_start = consistent_state(&chain, 0.0, &q, &VecQ::<Chain>::zeros(), Consistency::default())
        .expect("consistent");
    let p8 = Pendulum8 { m: 0.5, l: 0.25, g: 9.81 };
    let q8 = VecQ::<Pendulum8>::from_fn(|i, _| 0.3 + 0.05 * i as f64);
    let p8_start = consistent_state(&p8, 0.0, &q8, &VecQ::<Pendulum8>::zeros(), Consistency::default())
        .expect("consistent");
    let pendulum = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let (q0, v0) = (VecQ::<Pendulum>::from([0.6, -0.8]), VecQ::<Pendulum>::from([0.8, 0.6]));
    let pendulum_start =
        consistent_state(&pendulum, 0.0, &q0, &v0, Consistency::default()).expect("consistent");
    let general = VariationalOptions { use_structure: false, ..VariationalOptions::default() };
    let servo = SaturatedServo { m: 1.0, kp: 4.0, kd: 1.5, r: 1.0, fmax: 1.0 };
    let servo_start = State::<SaturatedServo>::zeros();

    let mut checksum = 0.0;
    for _ in 0..repeats {
        checksum += match case.as_str() {
            "radau-chain" => radau(&chain, &chain_start, 20.0, 1e-8, 1e-10),
            "radau-pendulum" => radau(&pendulum, &pendulum_start, 10.0, 1e-8, 1e-8),
            "radau-pendulum8" => radau(&p8, &p8_start, 10.0, 1e-8, 1e-10),
            "variational-pendulum" => variational(&pendulum, &pendulum_start, VariationalOptions::default()),
            "variational-pendulum-general" => variational(&pendulum, &pendulum_start, general),
            "variational-chain" => variational(&chain, &chain_start, general),
            "explicit-chain" => explicit(&chain, &chain_start, 20.0, 1e-8, 1e-10),
            "explicit-pendulum" => explicit(&pendulum, &pendulum_start, 10.0, 1e-8, 1e-8),
            "explicit-pendulum8" => explicit(&p8, &p8_start, 2.0, 1e-6, 1e-6),
            "radau-servo" => radau(&servo, &servo_start, 4.0, 1e-8, 1e-10),
            "explicit-servo" => explicit(&servo, &servo_start, 4.0, 1e-8, 1e-10),
            _ => {
                eprintln!(
                    "usage: small_models CASE [REPEATS], CASE one of radau-chain, radau-pendulum, \
                     radau-pendulum8, variational-pendulum, variational-pendulum-general, variational-chain, \
                     explicit-chain, explicit-pendulum, explicit-pendulum8, radau-servo, explicit-servo"
                );
                std::process::exit(2);
            }
        };
    }
    println!("{checksum}");
}
