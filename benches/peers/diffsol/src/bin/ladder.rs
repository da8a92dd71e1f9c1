//! diffsol 0.18 on the LC ladder of `benches/peers/ladder.sh`, with its sparse backend (faer's
//! sparse matrices and sparse LU): BDF and ESDIRK34 with `FaerSparseLU`, and Tsit45.
//!
//! diffsol gets the form a diffsol user would write: the node fluxes `x_j` (`x_0 = 0` at
//! ground) obey `C ẍ = −(1/L) T x` with `T` tridiagonal, so the state is `y = (x, ẋ)`, `2N`
//! unknowns, against the `7N + 4` of the index-2 DAE that dirac's Radau and IDA integrate.
//! The right-hand side and its Jacobian-vector product are hand-written; diffsol finds the
//! Jacobian's sparsity by probing (once, when the problem is built, outside the timing).
//!
//! It reads the start and the reference that `benches/ladder_peers.rs setup DIR` wrote: the
//! node fluxes at rest are `y0[nodes[j]]`, the exact fluxes at t = 10 are `ref.txt`. Prints CSV
//! `problem,tol,error,seconds,steps` for the method named by the first argument, the error the
//! largest nodal flux error at t = 10 and seconds the median of 3 solves, each creating the
//! solver and integrating to t = 10.
//!
//! Usage: `ladder bdf|esdirk34|tsit45 DIR`.

use std::path::Path;
use std::time::Instant;

use diffsol::{FaerSparseLU, FaerSparseMat, OdeBuilder, OdeEquationsImplicit, OdeSolverMethod, OdeSolverStopReason, Vector};

type M = FaerSparseMat<f64>;

const T_END: f64 = 10.0;
/// The unit cells of the zoo's `unit_ladder`.
const L: f64 = 1.0;
const C: f64 = 1.0;

fn read(dir: &Path, name: &str) -> Vec<f64> {
    let path = dir.join(name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    text.split_whitespace().map(|v| v.parse().expect("a number")).collect()
}

/// `out = −T x / (L C)`: 2 on the diagonal (1 in the last row, the open end), −1 beside it.
fn minus_t(x: &[f64], out: &mut [f64]) {
    let n = x.len();
    for j in 0..n {
        let left = if j == 0 { 0.0 } else { x[j - 1] };
        let (diagonal, right) = if j + 1 == n { (1.0, 0.0) } else { (2.0, x[j + 1]) };
        out[j] = -(diagonal * x[j] - left - right) / (L * C);
    }
}

fn rhs(y: &[f64], _p: &[f64], _t: f64, f: &mut [f64]) {
    let n = y.len() / 2;
    f[..n].copy_from_slice(&y[n..]);
    minus_t(&y[..n], &mut f[n..]);
}

fn jac_mul(_y: &[f64], _p: &[f64], _t: f64, w: &[f64], jw: &mut [f64]) {
    let n = w.len() / 2;
    jw[..n].copy_from_slice(&w[n..]);
    minus_t(&w[..n], &mut jw[n..]);
}

/// Integrates `solver` to `T_END`; returns the node fluxes there and the number of steps.
fn run<'a, Eqn, S>(mut solver: S, n: usize) -> (Vec<f64>, usize)
where
    Eqn: OdeEquationsImplicit<T = f64> + 'a,
    S: OdeSolverMethod<'a, Eqn>,
{
    solver.set_stop_time(T_END).expect("stop time after start");
    while !matches!(solver.step().expect("diffsol step"), OdeSolverStopReason::TstopReached) {}
    let y = solver.state().y;
    ((0..n).map(|i| y.get_index(i)).collect(), solver.get_statistics().number_of_steps)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 3 {
        eprintln!("usage: ladder bdf|esdirk34|tsit45 DIR");
        std::process::exit(2);
    }
    let (method, dir) = (args[1].as_str(), Path::new(&args[2]));
    let y0 = read(dir, "y0.txt");
    let nodes: Vec<usize> = read(dir, "nodes.txt").into_iter().map(|i| i as usize).collect();
    let reference = read(dir, "ref.txt");
    let n = nodes.len();
    let x0: Vec<f64> = nodes.iter().map(|&i| y0[i]).collect();
    println!("problem,tol,error,seconds,steps");
    for tol in [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10] {
        let problem = OdeBuilder::<M>::new()
            .rtol(tol)
            .atol(vec![tol; 2 * n])
            .rhs_implicit(rhs, jac_mul)
            .init(
                |_p, _t, y| {
                    y[..n].copy_from_slice(&x0);
                    y[n..].fill(0.0);
                },
                2 * n,
            )
            .build()
            .expect("ladder problem");
        let (mut times, mut error, mut steps) = (Vec::new(), 0.0, 0);
        for _ in 0..3 {
            let clock = Instant::now();
            let (x, s) = match method {
                "bdf" => run(problem.bdf::<FaerSparseLU<f64>>().expect("bdf"), n),
                "esdirk34" => run(problem.esdirk34::<FaerSparseLU<f64>>().expect("esdirk34"), n),
                "tsit45" => run(problem.tsit45().expect("tsit45"), n),
                other => panic!("unknown method {other}; expected bdf, esdirk34 or tsit45"),
            };
            times.push(clock.elapsed().as_secs_f64());
            error = x.iter().zip(&reference).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            steps = s;
        }
        times.sort_by(f64::total_cmp);
        println!("ladder,{tol:e},{error:.3e},{:.6e},{steps}", times[1]);
    }
}
