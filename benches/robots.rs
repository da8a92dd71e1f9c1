//! The Panda arm read from its URDF (`tests/robots/panda/panda_arm.urdf`), for the comparison
//! with Pinocchio and MuJoCo in `benches/peers/robots.sh`, which runs this bench twice:
//!
//! - `cargo bench -p dirac-benches --bench robots -- evaluate`: seconds per call of what an implicit step
//!   evaluates (the flat residual and Jacobian; the residual and Jacobian blocks the condensed
//!   Newton solver uses), each the median of 15 batches, as `name,seconds` lines;
//! - `cargo bench -p dirac-benches --bench robots -- swing DIR`: the 1 s free swing from rest under gravity by
//!   Explicit and Radau over a range of tolerances, as CSV `problem,tol,error,seconds,steps`:
//!   the error is the largest joint-angle error at the samples of the reference
//!   `DIR/arm_swing.csv` (Pinocchio's dynamics integrated by SciPy's DOP853 at 1e-12, written
//!   by `benches/peers/robots.py`), the seconds the median of 5 solves.

#![allow(missing_docs)]

use std::hint::black_box;
use std::time::Instant;

use dirac::State;
use dirac::prelude::*;

use dirac_benches::zoo;

use zoo::robots::{PandaArm, SWING_START};

fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn per_call(mut f: impl FnMut()) -> f64 {
    const CALLS: u32 = 20_000;
    let batches = (0..15)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..CALLS {
                f();
            }
            start.elapsed().as_secs_f64() / f64::from(CALLS)
        })
        .collect();
    median(batches)
}

fn start() -> State<PandaArm> {
    let q = VecQ::<PandaArm>::from_column_slice(&SWING_START[..7]);
    consistent_state(&PandaArm, 0.0, &q, &VecQ::<PandaArm>::zeros(), Consistency::default()).expect("a start")
}

fn evaluate() {
    // A state away from rest, so that every velocity term is exercised.
    let mut s = start();
    for (k, v) in s.v.iter_mut().enumerate() {
        *v = 0.3 * (k as f64 + 1.0).sin();
    }
    s.p = {
        let mut p = VecQ::<PandaArm>::zeros();
        PandaArm.dl_dv(0.0, &s.q, &s.v, &mut p);
        p
    };
    let y = s.to_y();
    let mut f = PandaArm.residual_vector(0.0, &y);
    let mut jac = PandaArm.jacobian_matrix(0.0, &y);
    let flat = per_call(|| {
        PandaArm.residual(0.0, black_box(&y), black_box(&mut f));
        PandaArm.jacobian(0.0, black_box(&y), black_box(&mut jac));
    });
    let mut rb = ResidualBlocks::<PandaArm>::zeros();
    let mut jb = JacobianBlocks::<PandaArm, dirac::algebra::Dense>::with_shape(&PandaArm.shape());
    let blocks = per_call(|| {
        PandaArm.residual_blocks(0.0, black_box(&s.q), black_box(&s.v), &s.lambda, black_box(&mut rb));
        PandaArm.jacobian_blocks(0.0, black_box(&s.q), black_box(&s.v), &s.lambda, black_box(&mut jb));
    });
    let mass = per_call(|| {
        black_box(dirac::joint_space::mass_matrix(&PandaArm, 0.0, black_box(&s.q)));
    });
    let bias = per_call(|| {
        black_box(dirac::joint_space::bias_torques(&PandaArm, 0.0, black_box(&s.q), black_box(&s.v)));
    });
    let tau = VecQ::<PandaArm>::from_fn(|i, _| 0.5 * i as f64 - 1.0);
    let forward = per_call(|| {
        black_box(dirac::joint_space::forward_dynamics(
            &PandaArm,
            0.0,
            black_box(&s.q),
            black_box(&s.v),
            black_box(&tau),
        ));
    });
    println!("residual_and_jacobian,{flat:.4e}");
    println!("residual_and_jacobian_blocks,{blocks:.4e}");
    println!("mass_matrix,{mass:.4e}");
    println!("bias_torques,{bias:.4e}");
    println!("forward_dynamics,{forward:.4e}");
}

/// The largest joint-angle error at the reference's samples.
fn error<S>(rows: &[Vec<f64>], solution: &Solution<PandaArm, S>) -> f64 {
    let mut worst = 0.0_f64;
    for (k, row) in rows.iter().enumerate() {
        for j in 0..7 {
            worst = worst.max((solution.q(Coordinate::unchecked(j))[k] - row[1 + j]).abs());
        }
    }
    worst
}

fn swing(dir: &str) {
    let text = std::fs::read_to_string(format!("{dir}/arm_swing.csv")).expect("the reference");
    let rows: Vec<Vec<f64>> =
        text.lines().skip(1).map(|l| l.split(',').map(|x| x.parse().expect("a number")).collect()).collect();
    let times: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    let start = start();
    println!("problem,tol,error,seconds,steps");
    for tol in [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12] {
        let sampling = Sampling::Times(times.clone());
        let mut explicit = Explicit::new(&PandaArm, ExplicitOptions::tolerances(tol, tol)).expect("options");
        let mut radau = Radau::new(&PandaArm, RadauOptions::tolerances(tol, tol)).expect("options");
        let (mut te, mut tr) = (Vec::new(), Vec::new());
        let (mut se, mut sr) = (None, None);
        for _ in 0..5 {
            let clock = Instant::now();
            se = Some(black_box(explicit.solve(0.0, &start, 1.0, &sampling).expect("the swing")));
            te.push(clock.elapsed().as_secs_f64());
            let clock = Instant::now();
            sr = Some(black_box(radau.solve(0.0, &start, 1.0, &sampling).expect("the swing")));
            tr.push(clock.elapsed().as_secs_f64());
        }
        let (se, sr) = (se.expect("solved"), sr.expect("solved"));
        println!("explicit,{tol:e},{:.3e},{:.4e},{}", error(&rows, &se), median(te), explicit.stats().steps);
        println!("radau,{tol:e},{:.3e},{:.4e},{}", error(&rows, &sr), median(tr), radau.stats().steps);
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).filter(|a| a != "--bench").collect();
    match args.first().map(String::as_str) {
        Some("swing") => swing(args.get(1).map_or("target/peers/robots", String::as_str)),
        _ => evaluate(),
    }
}
