//! Work-precision data of dirac's integrators, as CSV `problem,tol,error,seconds,steps`,
//! seconds the median of 21 solves, each building the integrator and integrating to the end:
//!
//! - pendulum: error at t = 1 against the published values of DESIGN.md §3;
//! - chain: the paper's torn chain, largest error of x1, x2, x3 at t = 20 against the exact
//!   modal solution;
//! - pendulum8: the 8-link pendulum of the zoo (m = 0.5, l = 0.25, released at rest from
//!   θ_i = 0.3 + 0.05 i), largest error of the angles at t = 2 against a reference printed by
//!   `reference` (Radau at rtol 1e-13), which diffsol's Tsit45 and BDF reproduce to 1e-11.
//!
//! `benches/peers/run.sh` runs it beside SUNDIALS IDA and diffsol on the same problems.
//!
//! Run: `cargo bench -p dirac-benches --bench work_precision -- radau|explicit [only=PROBLEM]`; with
//! `reference`, prints the
//! chain's exact x1, x2, x3 at t = 20 and the 8-link pendulum's angles at t = 2.

#![allow(missing_docs)]

use dirac_benches::zoo;

#[path = "support/median.rs"]
mod median;

use dirac::State;
use dirac::nalgebra::{Matrix3, SymmetricEigen, Vector3};
use dirac::prelude::*;
use dirac::{ExplicitStats, RadauStats};
use median::median_seconds;
use zoo::*;

/// x(t) of M ẍ = −K x from x(0) = (0.1, 0, 0) at rest, by the eigensystem of M^{-1/2} K M^{-1/2}.
fn chain_exact(t: f64) -> Vector3<f64> {
    let (m, k) = ([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]);
    let kk = Matrix3::new(k[0] + k[1], -k[1], 0.0, -k[1], k[1] + k[2], -k[2], 0.0, -k[2], k[2]);
    let l = Matrix3::from_diagonal(&Vector3::new(m[0], m[1], m[2]).map(|x: f64| 1.0 / x.sqrt()));
    let eig = SymmetricEigen::new(l * kk * l);
    let u0 = l.try_inverse().expect("diagonal") * Vector3::new(0.1, 0.0, 0.0);
    let mut u = Vector3::zeros();
    for i in 0..3 {
        let phi = eig.eigenvectors.column(i);
        u += phi * (phi.dot(&u0) * (eig.eigenvalues[i].sqrt() * t).cos());
    }
    l * u
}

const PENDULUM8_END: f64 = 2.0;

fn pendulum8() -> Pendulum8 {
    Pendulum8 { m: 0.5, l: 0.25, g: 9.81 }
}

fn pendulum8_start(model: &Pendulum8) -> State<Pendulum8> {
    let q = VecQ::<Pendulum8>::from_fn(|i, _| 0.3 + 0.05 * i as f64);
    consistent_state(model, 0.0, &q, &VecQ::<Pendulum8>::zeros(), Consistency::default()).expect("consistent")
}

/// The 8-link pendulum's angles at the end time, from Radau at a tolerance far below the
/// benchmark's.
fn pendulum8_reference() -> VecQ<Pendulum8> {
    let model = pendulum8();
    let mut radau = Radau::new(&model, RadauOptions::tolerances(1e-13, 1e-13)).expect("valid");
    let end = Sampling::Times(vec![PENDULUM8_END]);
    let sol = radau.solve(0.0, &pendulum8_start(&model), PENDULUM8_END, &end).expect("integrates");
    sol.state(0).expect("a sample").q
}

/// One integrator's solve to `t_end`: the state there and the steps taken.
trait Method {
    fn solve<M: DenseModel>(model: &M, start: &State<M>, t_end: f64, tol: f64) -> (State<M>, usize)
    where
        DefaultAllocator: Storage<M>;
}

struct RadauMethod;
struct ExplicitMethod;

impl Method for RadauMethod {
    fn solve<M: DenseModel>(model: &M, start: &State<M>, t_end: f64, tol: f64) -> (State<M>, usize)
    where
        DefaultAllocator: Storage<M>,
    {
        let mut radau = Radau::new(model, RadauOptions::tolerances(tol, tol)).expect("valid");
        let sol = radau.solve(0.0, start, t_end, &Sampling::Times(vec![t_end])).expect("integrates");
        let stats: RadauStats = sol.stats;
        (sol.state(0).expect("a sample"), stats.steps)
    }
}

impl Method for ExplicitMethod {
    fn solve<M: DenseModel>(model: &M, start: &State<M>, t_end: f64, tol: f64) -> (State<M>, usize)
    where
        DefaultAllocator: Storage<M>,
    {
        let mut explicit = Explicit::new(model, ExplicitOptions::tolerances(tol, tol)).expect("valid");
        let sol = explicit.solve(0.0, start, t_end, &Sampling::Times(vec![t_end])).expect("integrates");
        let stats: ExplicitStats = sol.stats;
        (sol.state(0).expect("a sample"), stats.steps)
    }
}

/// Prints one CSV row per tolerance: the error `error(state)` of the solve and its median time.
fn rows<I: Method, M: DenseModel>(
    problem: &str,
    model: &M,
    start: &State<M>,
    t_end: f64,
    error: impl Fn(&State<M>) -> f64,
) where
    DefaultAllocator: Storage<M>,
{
    if std::env::args().skip(1).any(|a| a.starts_with("only=") && a != format!("only={problem}")) {
        return;
    }
    for tol in [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10] {
        let mut achieved = 0.0;
        let (seconds, steps) = median_seconds(|| {
            let (end, steps) = I::solve(model, start, t_end, tol);
            achieved = error(&end);
            steps
        });
        println!("{problem},{tol},{achieved:.3e},{seconds:.6e},{steps}");
    }
}

fn run<I: Method>() {
    println!("problem,tol,error,seconds,steps");
    let p = unit_pendulum();
    rows::<I, _>("pendulum", &p, &horizontal_start(&p), 1.0, |s| {
        let (x, y) = (s.q(Pendulum::X), s.q(Pendulum::Y));
        f64::max((x + 0.986_291_751_131_875_3).abs(), (y + 0.165_010_853_125_541_17).abs())
    });
    let chain = paper_chain();
    let exact = chain_exact(20.0);
    let masses = [Chain::left(Primitive1::X1), Chain::left(Primitive1::X2), Chain::right(Primitive2::X3)];
    rows::<I, _>("chain", &chain, &paper_chain_start(&chain), 20.0, |s| {
        masses.iter().enumerate().map(|(i, c)| (s.q(*c) - exact[i]).abs()).fold(0.0, f64::max)
    });
    let model = pendulum8();
    let reference = std::cell::OnceCell::new();
    rows::<I, _>("pendulum8", &model, &pendulum8_start(&model), PENDULUM8_END, |s| {
        (s.q - reference.get_or_init(pendulum8_reference)).amax()
    });
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "reference") {
        let x = chain_exact(20.0);
        let angles = pendulum8_reference();
        let all: Vec<String> = x.iter().chain(angles.iter()).map(|v| format!("{v:.17e}")).collect();
        println!("{}", all.join(" "));
    } else if args.iter().any(|a| a == "explicit") {
        run::<ExplicitMethod>();
    } else {
        run::<RadauMethod>();
    }
}
