//! One round of the optimal control benchmark's dirac side (benches/peers/optimal.sh runs it
//! alternately with CasADi's, benches/peers/optimal.py): a problem transcribed by DMOC and
//! solved by IPOPT, for each number of intervals given, one CSV line each:
//! `dirac,problem,N,cost,iterations,solve seconds,evaluation seconds,transcription seconds`.
//! The problems: `cartpole`, the cart-pole's swing-up (2 s from hanging to upright at rest,
//! |x| <= 1.5 m, |f| <= 20 N); `chain8`, the 8-link chain with a torque at each joint raised
//! from hanging at rest to every link at 0.5 rad at rest in 2 s. Both cost the integral of the
//! squared inputs over 2.
//!
//!   cargo bench -p dirac-benches --bench optimal -- cartpole 50 100

use std::f64::consts::PI;
use std::time::Instant;

use dirac::VecQ;
use dirac::optimal::ipopt::IpoptOptions;
use dirac::optimal::{Dmoc, Problem};
use dirac::{DenseModel, InputsOutputs, Storage};
use dirac_benches::zoo::{CartPole, Chain8, cart_pole};

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
            other => {
                eprintln!("no problem `{other}`: cartpole or chain8");
                std::process::exit(2);
            }
        }
    }
}

fn run<M>(name: &str, n: usize, problem: Problem<M>, started: Instant)
where
    M: DenseModel + InputsOutputs,
    dirac::nalgebra::DefaultAllocator: Storage<M>,
{
    {
        let mut dmoc = match Dmoc::new(problem) {
            Ok(dmoc) => dmoc,
            Err(e) => {
                eprintln!("N = {n}: {e}");
                std::process::exit(1);
            }
        };
        let transcription = started.elapsed();
        match dmoc.solve(&IpoptOptions::default()) {
            Ok(o) => println!(
                "dirac,{name},{n},{:.12e},{},{:.6e},{:.6e},{:.6e}",
                o.cost,
                o.iterations,
                o.wall.as_secs_f64(),
                o.evaluation.as_secs_f64(),
                transcription.as_secs_f64()
            ),
            Err(e) => {
                eprintln!("N = {n}: {e}");
                std::process::exit(1);
            }
        }
    }
}
