//! What a declared law costs against the same law written by hand, in one process: stick-slip
//! of a mass on a belt (`m = 1, k = 4, vb = 0.5, N = 9.81, μs = 0.4, μk = 0.25`, t = 20, about
//! five stick-slip periods) as `friction(grip, …) = v − vb` solved by a plain `solve`, and as
//! fields, a slack coordinate and two declared events switched by the action of a
//! `solve_with_events` (the pattern the guide describes for laws of one's own). Both runs are
//! the same equations in each mode; they differ in how the mode is held (a coordinate, or
//! fields) and switched (by the solve, or by the action).
//!
//! Each integrator (Radau and Explicit at rtol 1e-8, the variational one at h = 1e-3) runs
//! the two alternately, `ROUNDS` times each; the medians' ratio is printed, with the samples
//! and switches of each, so that the work compared is seen to be the same.
//!
//! Run: `cargo bench -p dirac-benches --bench laws`.

#![allow(missing_docs)]

use std::hint::black_box;
use std::ops::ControlFlow;
use std::time::Instant;

use dirac::State;
use dirac::prelude::*;

/// Friction as the law.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(friction(grip, kinetic = mu_k * n, stiction = mu_s * n) = v - vb)]
pub struct WithLaw {
    pub m: f64,
    pub k: f64,
    pub vb: f64,
    pub n: f64,
    pub mu_s: f64,
    pub mu_k: f64,
}

/// Friction by hand: `stuck` switches the row `stick` on, `side` holds the slip's sign.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v, s => vs))]
#[dirac(lagrangian = 0.5 * m * v * v + 0.5 * vs * vs - 0.5 * k * x * x)]
#[dirac(constraint(stick) = stuck * (v - vb) + (1.0 - stuck) * vs)]
#[dirac(force(x) = -(1.0 - stuck) * mu_k * n * side)]
#[dirac(event(sticks, falling) = (1.0 - stuck) * side * (v - vb) + stuck)]
#[dirac(event(release, falling) = stuck * (mu_s * n - stick.abs()) + (1.0 - stuck))]
pub struct ByHand {
    pub m: f64,
    pub k: f64,
    pub vb: f64,
    pub n: f64,
    pub mu_s: f64,
    pub mu_k: f64,
    pub stuck: f64,
    pub side: f64,
}

const T_END: f64 = 20.0;
const ROUNDS: usize = 15;

fn law() -> WithLaw {
    WithLaw { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 }
}

/// Stuck on the belt at the start, as the law's start chooses for `x = 0`, `v = vb`.
fn by_hand() -> ByHand {
    ByHand { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25, stuck: 1.0, side: 1.0 }
}

/// The law by a plain solve: samples and events.
fn run_law<I: Integrator<WithLaw>>(integrator: &mut I, start: &State<WithLaw>) -> (usize, usize) {
    let solution = integrator.solve(0.0, start, T_END, &Sampling::Steps).expect("integrates");
    (solution.len(), solution.events().len())
}

/// The hand-written law: its action sticks the mass if the spring's pull is within the bound,
/// and otherwise reverses the slip; a release frees it on the side the stick force pushed.
fn run_by_hand<I: Integrator<ByHand>>(integrator: &mut I, start: &State<ByHand>) -> (usize, usize) {
    *integrator.model_mut().expect("held exclusively") = by_hand();
    let mut events = Events::new().declared();
    let solution = integrator
        .solve_with_events(0.0, start, T_END, &Sampling::Steps, &mut events, |event, at| {
            let (pull, force) = (at.model().k * at.state().q(ByHand::X), at.state().lambda(ByHand::STICK));
            let model = at.model_mut().expect("held exclusively");
            let bound = model.mu_s * model.n;
            if model.stuck == 1.0 && event.index == 1 {
                model.stuck = 0.0;
                model.side = -force.signum();
            } else if model.stuck == 0.0 && event.index == 0 {
                if pull.abs() < bound * (1.0 - 1e-6) {
                    model.stuck = 1.0;
                    at.state_mut();
                } else {
                    model.side = -model.side;
                }
            }
            ControlFlow::Continue(())
        })
        .expect("integrates");
    (solution.len(), solution.events().len())
}

fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// Times `a` and `b` alternately and prints their medians' ratio.
fn compare(name: &str, mut a: impl FnMut() -> (usize, usize), mut b: impl FnMut() -> (usize, usize)) {
    let (mut ta, mut tb) = (Vec::new(), Vec::new());
    let (mut wa, mut wb) = ((0, 0), (0, 0));
    for _ in 0..ROUNDS {
        let clock = Instant::now();
        wa = black_box(a());
        ta.push(clock.elapsed().as_secs_f64());
        let clock = Instant::now();
        wb = black_box(b());
        tb.push(clock.elapsed().as_secs_f64());
    }
    let (ma, mb) = (median(ta), median(tb));
    println!(
        "{name:<12} law {:>9.1} µs ({} samples, {} events)   by hand {:>9.1} µs ({} samples, {} events)   law/by hand {:.2}",
        ma * 1e6,
        wa.0,
        wa.1,
        mb * 1e6,
        wb.0,
        wb.1,
        ma / mb
    );
}

fn main() {
    // `laws CASE REPEATS` runs one case alone (`radau-law`, `radau-hand`, `explicit-law`,
    // `explicit-hand`), for an exact count of its instructions under callgrind
    // (`benches/laws.sh`).
    let mut args = std::env::args().skip(1).filter(|a| a != "--bench");
    if let Some(case) = args.next() {
        let repeats: usize = args.next().and_then(|r| r.parse().ok()).unwrap_or(1);
        return alone(&case, repeats);
    }
    let (with_law, mut hand) = (law(), by_hand());
    let zero = VecQ::<WithLaw>::zeros();
    let mut v0 = VecQ::<WithLaw>::zeros();
    v0[0] = 0.5;
    let law_start = consistent_state(&with_law, 0.0, &zero, &v0, Consistency::default()).expect("stuck");
    let mut v0 = VecQ::<ByHand>::zeros();
    v0[0] = 0.5;
    let hand_start =
        consistent_state(&hand, 0.0, &VecQ::<ByHand>::zeros(), &v0, Consistency::default()).expect("stuck");

    let tolerances = RadauOptions::tolerances(1e-8, 1e-10);
    let mut radau_law = Radau::new(&with_law, tolerances).expect("valid");
    let mut radau_hand = Radau::new(&mut hand, tolerances).expect("valid");
    compare("Radau", || run_law(&mut radau_law, &law_start), || run_by_hand(&mut radau_hand, &hand_start));
    drop(radau_hand);

    let tolerances = ExplicitOptions::tolerances(1e-8, 1e-10);
    let mut explicit_law = Explicit::new(&with_law, tolerances).expect("valid");
    let mut explicit_hand = Explicit::new(&mut hand, tolerances).expect("valid");
    compare(
        "Explicit",
        || run_law(&mut explicit_law, &law_start),
        || run_by_hand(&mut explicit_hand, &hand_start),
    );
    drop(explicit_hand);

    let mut variational_law =
        Variational::new(&with_law, 1e-3, VariationalOptions::default()).expect("valid");
    let mut variational_hand =
        Variational::new(&mut hand, 1e-3, VariationalOptions::default()).expect("valid");
    compare(
        "Variational",
        || run_law(&mut variational_law, &law_start),
        || run_by_hand(&mut variational_hand, &hand_start),
    );
}

/// Runs `case` `repeats` times and prints the samples it recorded.
fn alone(case: &str, repeats: usize) {
    let (with_law, mut hand) = (law(), by_hand());
    let mut v0 = VecQ::<WithLaw>::zeros();
    v0[0] = 0.5;
    let law_start = consistent_state(&with_law, 0.0, &VecQ::<WithLaw>::zeros(), &v0, Consistency::default())
        .expect("stuck");
    let mut v0 = VecQ::<ByHand>::zeros();
    v0[0] = 0.5;
    let hand_start =
        consistent_state(&hand, 0.0, &VecQ::<ByHand>::zeros(), &v0, Consistency::default()).expect("stuck");
    let mut samples = 0;
    for _ in 0..repeats {
        samples += match case {
            "radau-law" => {
                run_law(
                    &mut Radau::new(&with_law, RadauOptions::tolerances(1e-8, 1e-10)).expect("valid"),
                    &law_start,
                )
                .0
            }
            "radau-hand" => {
                run_by_hand(
                    &mut Radau::new(&mut hand, RadauOptions::tolerances(1e-8, 1e-10)).expect("valid"),
                    &hand_start,
                )
                .0
            }
            "explicit-law" => {
                run_law(
                    &mut Explicit::new(&with_law, ExplicitOptions::tolerances(1e-8, 1e-10)).expect("valid"),
                    &law_start,
                )
                .0
            }
            "explicit-hand" => {
                run_by_hand(
                    &mut Explicit::new(&mut hand, ExplicitOptions::tolerances(1e-8, 1e-10)).expect("valid"),
                    &hand_start,
                )
                .0
            }
            _ => {
                eprintln!(
                    "usage: laws [CASE REPEATS], CASE one of radau-law, radau-hand, explicit-law, explicit-hand"
                );
                std::process::exit(2);
            }
        };
    }
    println!("{samples}");
}
