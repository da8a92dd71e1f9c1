//! What writing a mechanism as rigid bodies and joints costs against the same mechanism
//! reduced by hand to its joint angles, in one process: the double pendulum of
//! `tests/zoo/bodies.rs`, two boxes on two hinges swinging for 2 s under gravity.
//!
//! - bodies: two `RigidBody` parts (12 coordinates each, six rows for `RᵀR = I`) and ten
//!   holonomic rows of joints: 24 coordinates and 22 rows;
//! - joints reduced: the same bodies with their two joints named (`joint(th1 => w1) =
//!   revolute(..)`) under `#[dirac(reduce)]`, which compiles them to the two joint angles;
//! - by hand: the two angles, with the Lagrangian in their sines and cosines.
//!
//! Radau and Explicit at rtol = atol = 1e-8 (Radau projecting onto the constraints), the
//! variational integrator at h = 1e-3; each pair alternated `ROUNDS` times, the medians'
//! ratio printed with the steps of each and how far each ends from a tight reference of the
//! hand-reduced model.
//!
//! Run: `cargo bench -p dirac-benches --bench bodies`.

#![allow(missing_docs)]

use std::hint::black_box;
use std::time::Instant;

use dirac::State;
use dirac::prelude::*;

use dirac_benches::zoo;

use zoo::bodies::{
    PlanarDoublePendulum, ReducedDoublePendulum, SpatialDoublePendulum, double_pendulums, spatial_start,
};

const ROUNDS: usize = 11;
const END: f64 = 2.0;
const TH: [f64; 2] = [0.9, -0.4];
const W: [f64; 2] = [0.3, 1.1];

fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// The angles at the end: from `R e3 = (sin θ, 0, cos θ)` for the bodies.
fn body_angles(s: &State<SpatialDoublePendulum>) -> [f64; 2] {
    [s.q[5].atan2(s.q[11]), s.q[17].atan2(s.q[23])]
}

fn compare(
    method: &str,
    label: &str,
    reference: [f64; 2],
    bodies: &dyn Fn() -> (usize, [f64; 2]),
    by_hand: &dyn Fn() -> (usize, [f64; 2]),
) {
    let (mut ta, mut tb) = (Vec::new(), Vec::new());
    let (mut a, mut b) = ((0, [0.0; 2]), (0, [0.0; 2]));
    for _ in 0..ROUNDS {
        let start = Instant::now();
        a = black_box(bodies());
        ta.push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        b = black_box(by_hand());
        tb.push(start.elapsed().as_secs_f64());
    }
    let error = |x: [f64; 2]| (x[0] - reference[0]).abs().max((x[1] - reference[1]).abs());
    let (ma, mb) = (median(ta), median(tb));
    println!(
        "{method:11} {label:7} {:9.1} µs ({:5} steps, off by {:.1e}) | by hand {:8.1} µs ({:5} steps, off by {:.1e}) | ratio {:6.2}",
        ma * 1e6,
        a.0,
        error(a.1),
        mb * 1e6,
        b.0,
        error(b.1),
        ma / mb
    );
}

fn main() {
    let (spatial, planar) = double_pendulums();
    let start = spatial_start(&spatial, TH, W);
    let mut state = State::<PlanarDoublePendulum>::zeros();
    state.q[0] = TH[0];
    state.q[1] = TH[1];
    state.v[0] = W[0];
    state.v[1] = W[1];
    let hand_start =
        consistent_state(&planar, 0.0, &state.q, &state.v, Consistency::default()).expect("a start");
    let last = Sampling::Times(vec![END]);
    let tight = Radau::new(&planar, RadauOptions::tolerances(1e-13, 1e-13))
        .expect("valid")
        .solve(0.0, &hand_start, END, &last)
        .expect("it swings");
    let end = tight.last().expect("a sample");
    let reference = [end.q[0], end.q[1]];
    let (rtol, atol, h) = (1e-8, 1e-8, 1e-3);
    let projected = RadauOptions { projection: true, ..RadauOptions::tolerances(rtol, atol) };
    // The hand model's runs, the baseline of every row.
    let hand_radau = || {
        let mut radau = Radau::new(&planar, RadauOptions::tolerances(rtol, atol)).expect("valid");
        let s = radau.solve(0.0, &hand_start, END, &last).expect("integrates");
        let e = s.last().expect("a sample");
        (radau.stats().steps, [e.q[0], e.q[1]])
    };
    let hand_explicit = || {
        let mut explicit = Explicit::new(&planar, ExplicitOptions::tolerances(rtol, atol)).expect("valid");
        let s = explicit.solve(0.0, &hand_start, END, &last).expect("integrates");
        let e = s.last().expect("a sample");
        (explicit.stats().steps, [e.q[0], e.q[1]])
    };
    let hand_variational = || {
        let mut variational = Variational::new(&planar, h, VariationalOptions::default()).expect("valid");
        let s = variational.solve(0.0, &hand_start, END, &last).expect("integrates");
        let e = s.last().expect("a sample");
        (variational.stats().steps, [e.q[0], e.q[1]])
    };
    compare(
        "Radau",
        "bodies",
        reference,
        &|| {
            let mut radau = Radau::new(&spatial, projected).expect("valid");
            let s = radau.solve(0.0, &start, END, &last).expect("integrates");
            (radau.stats().steps, body_angles(&s.last().expect("a sample")))
        },
        &hand_radau,
    );
    compare(
        "Explicit",
        "bodies",
        reference,
        &|| {
            let mut explicit =
                Explicit::new(&spatial, ExplicitOptions::tolerances(rtol, atol)).expect("valid");
            let s = explicit.solve(0.0, &start, END, &last).expect("integrates");
            (explicit.stats().steps, body_angles(&s.last().expect("a sample")))
        },
        &hand_explicit,
    );
    compare(
        "Variational",
        "bodies",
        reference,
        &|| {
            let mut variational =
                Variational::new(&spatial, h, VariationalOptions::default()).expect("valid");
            let s = variational.solve(0.0, &start, END, &last).expect("integrates");
            (variational.stats().steps, body_angles(&s.last().expect("a sample")))
        },
        &hand_variational,
    );
    // The same bodies in joint coordinates: link 2's angle is the sum of the two joints'.
    let reduced = ReducedDoublePendulum::new(&spatial);
    let mut q = VecQ::<ReducedDoublePendulum>::zeros();
    let mut v = VecQ::<ReducedDoublePendulum>::zeros();
    (q[0], q[1], v[0], v[1]) = (TH[0], TH[1] - TH[0], W[0], W[1] - W[0]);
    let reduced_start = consistent_state(&reduced, 0.0, &q, &v, Consistency::default()).expect("a start");
    let angles = |s: &State<ReducedDoublePendulum>| [s.q[0], s.q[0] + s.q[1]];
    compare(
        "Radau",
        "reduced",
        reference,
        &|| {
            let mut radau = Radau::new(&reduced, RadauOptions::tolerances(rtol, atol)).expect("valid");
            let s = radau.solve(0.0, &reduced_start, END, &last).expect("integrates");
            (radau.stats().steps, angles(&s.last().expect("a sample")))
        },
        &hand_radau,
    );
    compare(
        "Explicit",
        "reduced",
        reference,
        &|| {
            let mut explicit =
                Explicit::new(&reduced, ExplicitOptions::tolerances(rtol, atol)).expect("valid");
            let s = explicit.solve(0.0, &reduced_start, END, &last).expect("integrates");
            (explicit.stats().steps, angles(&s.last().expect("a sample")))
        },
        &hand_explicit,
    );
    compare(
        "Variational",
        "reduced",
        reference,
        &|| {
            let mut variational =
                Variational::new(&reduced, h, VariationalOptions::default()).expect("valid");
            let s = variational.solve(0.0, &reduced_start, END, &last).expect("integrates");
            (variational.stats().steps, angles(&s.last().expect("a sample")))
        },
        &hand_variational,
    );
}
