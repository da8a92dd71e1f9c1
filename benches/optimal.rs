//! One round of the optimal control benchmark's dirac side (benches/peers/optimal.sh runs it
//! alternately with CasADi's, benches/peers/optimal.py): the cart-pole swing-up transcribed by
//! DMOC and solved by IPOPT, for each number of intervals given, one CSV line each:
//! `dirac,N,cost,iterations,solve seconds,evaluation seconds,transcription seconds`.
//!
//!   cargo bench -p dirac-benches --bench optimal -- 50 100

use std::f64::consts::PI;
use std::time::Instant;

use dirac::VecQ;
use dirac::optimal::ipopt::IpoptOptions;
use dirac::optimal::{Dmoc, Problem};
use dirac_benches::zoo::{CartPole, cart_pole};

fn main() {
    let sizes: Vec<usize> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let sizes = if sizes.is_empty() { vec![50, 100] } else { sizes };
    for n in sizes {
        let started = Instant::now();
        let problem = Problem::new(cart_pole(), 2.0, n)
            .final_state(VecQ::<CartPole>::from([0.0, PI]), VecQ::<CartPole>::zeros())
            .position_bounds(CartPole::X, -1.5, 1.5)
            .input_bounds(CartPole::F, -20.0, 20.0);
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
                "dirac,{n},{:.12e},{},{:.6e},{:.6e},{:.6e}",
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
