//! Redundant constraint rows: closed loops whose rows take away fewer freedoms than they
//! count, and a constraint written twice. They run under every integrator with the rows kept
//! to round-off and multipliers that are consistent: of least norm where the method solves for
//! them afresh (a consistent start, Explicit, Variational), with the same force `Aᵀ λ` in
//! Radau (whose multipliers' part that exerts no force is set back to zero at each new
//! Jacobian). References: Bennett's closed-form relation of the angles of his linkage, the
//! four-bar's loop closed by two circles, the least-norm multipliers from nalgebra's
//! pseudo-inverse of `Aᵀ`, and a closed form for the rows written twice.

// The derives' accessors and constants of these models are not all read here.
#![allow(dead_code)]

use dirac::State;
use dirac::components::bodies::RigidBody;
use dirac::nalgebra::DMatrix;
use dirac::prelude::*;

use crate::every_method::{Fineness, Method};
use crate::joints::{FOUR_BAR, closed_loop, loop_rates, rod};

fn largest(xs: impl IntoIterator<Item = f64>) -> f64 {
    xs.into_iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// The least-norm multipliers with the force `Aᵀ λ` of `lambda`, by the pseudo-inverse of `Aᵀ`
/// (nalgebra's SVD), for rows `a` (dense, `m × n`).
fn least_norm(a: &DMatrix<f64>, lambda: &[f64]) -> Vec<f64> {
    let force = a.transpose() * DMatrix::from_column_slice(lambda.len(), 1, lambda);
    let pinv = a.transpose().pseudo_inverse(1e-10 * a.amax()).expect("an SVD");
    (pinv * force).iter().copied().collect()
}

/// The Bennett linkage: four links joined by four hinges in a spatial loop, links 1 and 3 of
/// length `a1` and twist `α1`, links 2 and 4 of length `a2` and twist `α2`, with
/// `a1 / sin α1 = a2 / sin α2`. Generic four-hinge loops are rigid; this one moves with one
/// freedom. Written in the angles `th1..th3` of the first three hinges (Denavit-Hartenberg:
/// each link `Rz(θ) Tx(a) Rx(α)`), the frame after the third hinge carried as definitions; the
/// fourth hinge is its five rows: the frame's origin at the fourth link's far end `(−a4, 0, 0)`
/// (three rows) and its `z` axis along the ground's view of the fourth hinge
/// `(0, sin α4, cos α4)` (two rows). Five rows on three angles for one freedom: three of them
/// are redundant everywhere on the loop. Flywheels of inertia `j1..j3` on the hinges and a
/// spring on the first move it.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(th1 => w1, th2 => w2, th3 => w3))]
#[dirac(
    define(c1) = th1.cos(),
    define(s1) = th1.sin(),
    define(c2) = th2.cos(),
    define(s2) = th2.sin(),
    define(c3) = th3.cos(),
    define(s3) = th3.sin(),
    define(ra11) = c1,
    define(ra12) = -s1 * ca1,
    define(ra13) = s1 * sa1,
    define(ra21) = s1,
    define(ra22) = c1 * ca1,
    define(ra23) = -c1 * sa1,
    define(ra32) = sa1,
    define(ra33) = ca1,
    define(rb11) = ra11 * c2 + ra12 * s2,
    define(rb12) = ra11 * (-s2 * ca2) + ra12 * (c2 * ca2) + ra13 * sa2,
    define(rb13) = ra11 * (s2 * sa2) + ra12 * (-c2 * sa2) + ra13 * ca2,
    define(rb21) = ra21 * c2 + ra22 * s2,
    define(rb22) = ra21 * (-s2 * ca2) + ra22 * (c2 * ca2) + ra23 * sa2,
    define(rb23) = ra21 * (s2 * sa2) + ra22 * (-c2 * sa2) + ra23 * ca2,
    define(rb31) = ra32 * s2,
    define(rb32) = ra32 * (c2 * ca2) + ra33 * sa2,
    define(rb33) = ra32 * (-c2 * sa2) + ra33 * ca2,
    define(ox1) = a1 * c1,
    define(oy1) = a1 * s1,
    define(ox2) = ox1 + a2 * (ra11 * c2 + ra12 * s2),
    define(oy2) = oy1 + a2 * (ra21 * c2 + ra22 * s2),
    define(oz2) = a2 * (ra32 * s2),
    define(ox3) = ox2 + a3 * (rb11 * c3 + rb12 * s3),
    define(oy3) = oy2 + a3 * (rb21 * c3 + rb22 * s3),
    define(oz3) = oz2 + a3 * (rb31 * c3 + rb32 * s3),
    define(zx3) = rb11 * s3 * sa3 - rb12 * c3 * sa3 + rb13 * ca3,
    define(zy3) = rb21 * s3 * sa3 - rb22 * c3 * sa3 + rb23 * ca3
)]
#[dirac(lagrangian = 0.5 * (j1 * w1 * w1 + j2 * w2 * w2 + j3 * w3 * w3) - 0.5 * k * (th1 - rest).powi(2))]
#[dirac(holonomic(cut_x) = ox3 + a4, holonomic(cut_y) = oy3, holonomic(cut_z) = oz3)]
#[dirac(holonomic(axis_x) = zx3, holonomic(axis_y) = zy3 - sa4)]
pub struct Bennett {
    pub a1: f64,
    pub a2: f64,
    pub a3: f64,
    pub a4: f64,
    pub sa1: f64,
    pub ca1: f64,
    pub sa2: f64,
    pub ca2: f64,
    pub sa3: f64,
    pub ca3: f64,
    pub sa4: f64,
    pub j1: f64,
    pub j2: f64,
    pub j3: f64,
    pub k: f64,
    pub rest: f64,
}

/// The linkage with twists of 30° and 60° and the constant of its relation of angles,
/// `tan(θ1/2) tan(θ2/2) = sin((α2 + α1)/2) / sin((α2 − α1)/2)`, with `θ3 = −θ1` (Bennett 1903).
fn bennett() -> (Bennett, f64) {
    let (al1, al2) = (std::f64::consts::FRAC_PI_6, std::f64::consts::FRAC_PI_3);
    let (a1, a2) = (1.0, al2.sin() / al1.sin());
    let model = Bennett {
        a1,
        a2,
        a3: a1,
        a4: a2,
        sa1: al1.sin(),
        ca1: al1.cos(),
        sa2: al2.sin(),
        ca2: al2.cos(),
        sa3: al1.sin(),
        ca3: al1.cos(),
        sa4: al2.sin(),
        j1: 1.0,
        j2: 0.5,
        j3: 0.8,
        k: 2.0,
        rest: 1.2,
    };
    (model, ((al2 + al1) / 2.0).sin() / ((al2 - al1) / 2.0).sin())
}

/// On the loop: `θ2` from the relation, `θ3 = −θ1`, the rates by differentiating both.
fn on_the_loop(k: f64, (th1, w1): (f64, f64)) -> (VecQ<Bennett>, VecQ<Bennett>) {
    let u = k / (th1 / 2.0).tan();
    let th2 = 2.0 * u.atan();
    let w2 = -k / ((th1 / 2.0).sin().powi(2) * (1.0 + u * u)) * w1;
    (VecQ::<Bennett>::new(th1, th2, -th1), VecQ::<Bennett>::new(w1, w2, -w1))
}

/// The linkage and a consistent start on its loop, the first hinge at 0.6 rad turning at 0.7
/// rad/s.
pub(crate) fn bennett_start() -> (Bennett, State<Bennett>) {
    let (model, k) = bennett();
    let (q, v) = on_the_loop(k, (0.6, 0.7));
    let start = consistent_state(&model, 0.0, &q, &v, Consistency::default()).expect("a start");
    (model, start)
}

#[test]
fn the_bennett_linkage_with_its_five_cut_rows_moves_as_bennetts_relation_says() {
    let (model, k) = bennett();
    assert_eq!(Bennett::NAMES.constraint_names().len(), 5);
    let (q, v) = on_the_loop(k, (0.6, 0.7));
    let start = consistent_state(&model, 0.0, &q, &v, Consistency::default()).expect("a start");
    // The start is on the loop already; its multipliers are those of least norm.
    assert!((start.q - q).amax() < 1e-14 && (start.v - v).amax() < 1e-14);
    let rows = |q: &VecQ<Bennett>| {
        let mut a = dirac::nalgebra::SMatrix::<f64, 5, 3>::zeros();
        model.constraint_matrix(0.0, q, &mut a);
        DMatrix::from_column_slice(5, 3, a.as_slice())
    };
    let least = least_norm(&rows(&start.q), start.lambda.as_slice());
    assert!(largest(start.lambda.iter().zip(&least).map(|(a, b)| a - b)) < 1e-12, "{}", start.lambda);
    let relation = |s: &State<Bennett>| {
        let (t1, t2, t3) = (s.q[0], s.q[1], s.q[2]);
        (t1 + t3).abs().max(((t1 / 2.0).tan() * (t2 / 2.0).tan() - k).abs())
    };
    let times: Vec<f64> = (1..=20).map(|k| 0.25 * k as f64).collect();
    let mut ends = Vec::new();
    each_integrator!(&model, Fineness::new(1e-10, 1e-10, 1e-3).projected(), |method, integrator| {
        let solution = integrator.solve(0.0, &start, 5.0, &Sampling::Times(times.clone())).expect("it moves");
        let kept = largest((0..times.len()).map(|k| relation(&solution.state(k).expect("a sample"))));
        let drift = largest(solution.holonomic_residual().iter().copied());
        let end = solution.state(times.len() - 1).expect("a sample");
        let a = rows(&end.q);
        let least = least_norm(&a, end.lambda.as_slice());
        let off = largest(end.lambda.iter().zip(&least).map(|(a, b)| a - b));
        println!(
            "{}: Bennett's relation {kept:.1e}, rows {drift:.1e}, multipliers from least norm {off:.1e}",
            method.name()
        );
        assert!(kept < 1e-12 && drift < 1e-12, "{}: {kept:e} {drift:e}", method.name());
        // Explicit's are of least norm at the sample; the variational integrator's act through
        // the rows at its steps' points, of least norm there (to 1e-7 of those at the sample).
        match method {
            Method::Explicit => assert!(off < 1e-10, "{}: {} against {least:?}", method.name(), end.lambda),
            Method::Variational => assert!(off < 1e-6, "{}: {} against {least:?}", method.name(), end.lambda),
            Method::Radau => {}
        }
        ends.push((method, end, a));
    });
    // The three agree on the motion (Variational to its step's order), and Radau's multipliers
    // on the force they exert.
    let (explicit, radau) = (&ends[1].1, &ends[0].1);
    assert!((radau.q - explicit.q).amax() < 1e-8, "{} against {}", radau.q, explicit.q);
    assert!((ends[2].1.q - explicit.q).amax() < 1e-5);
    let a = &ends[1].2;
    let force = a.transpose() * DMatrix::from_column_slice(5, 1, (radau.lambda - explicit.lambda).as_slice());
    assert!(force.amax() < 1e-7, "{force}");
}

/// A planar four-bar of bodies about `y`, as `joints::FourBar` without `reduce`: its three
/// bodies' 36 coordinates and 38 rows (each hinge's five, each body's six), of which three
/// are redundant: the loop's rows across the plane.
#[derive(Interconnection, Clone, Debug)]
#[dirac(large)]
#[dirac(joint(th1 => w1) = revolute(y, world, crank at [0.0, 0.0, h1]))]
#[dirac(joint(th2 => w2) = revolute(y, crank at [0.0, 0.0, -h1], coupler at [0.0, 0.0, h2]))]
#[dirac(joint(th3 => w3) = revolute(y, world at [d, 0.0, 0.0], rocker at [0.0, 0.0, h3]))]
#[dirac(joint(th4 => w4) = revolute(y, coupler at [0.0, 0.0, -h2], rocker at [0.0, 0.0, -h3]))]
pub struct FourBarOfBodies {
    pub crank: RigidBody,
    pub coupler: RigidBody,
    pub rocker: RigidBody,
    pub h1: f64,
    pub h2: f64,
    pub h3: f64,
    pub d: f64,
}

/// Writes a body turned by `p` about `y` at rate `w`, its centre at `c` moving at `cv`, into
/// its twelve coordinates (centre, then the rotation by rows) and their rates.
fn place(q: &mut [f64], v: &mut [f64], (p, w): (f64, f64), (c, cv): ([f64; 3], [f64; 3])) {
    let (s, k) = p.sin_cos();
    q[..3].copy_from_slice(&c);
    v[..3].copy_from_slice(&cv);
    q[3..12].copy_from_slice(&[k, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, k]);
    v[3..12].copy_from_slice(&[-s * w, 0.0, k * w, 0.0, 0.0, 0.0, -k * w, 0.0, -s * w]);
}

#[test]
fn a_four_bar_with_its_redundant_rows_closes_as_the_circles_say() {
    // Its integrators hold more than the default thread's stack.
    let worker = std::thread::Builder::new().stack_size(256 << 20).spawn(four_bar_with_redundant_rows);
    worker.expect("a thread").join().expect("no panic");
}

fn four_bar_with_redundant_rows() {
    assert_eq!(
        (FourBarOfBodies::NAMES.coordinate_names().len(), FourBarOfBodies::NAMES.constraint_names().len()),
        (36, 38)
    );
    let [h1, h2, h3, d] = FOUR_BAR;
    let model =
        FourBarOfBodies { crank: rod(0.5, h1), coupler: rod(0.8, h2), rocker: rod(0.6, h3), h1, h2, h3, d };
    let (p1, w1) = (0.3, 1.5);
    let (p2, p3) = closed_loop(FOUR_BAR, p1);
    let (w2, w3) = loop_rates(FOUR_BAR, (p1, p2, p3), w1);
    let (mut q, mut v) = (VecQ::<FourBarOfBodies>::zeros(), VecQ::<FourBarOfBodies>::zeros());
    let (q, v) = (q.as_mut_slice(), v.as_mut_slice());
    let (s1, c1, s2, c2, s3, c3) = (p1.sin(), p1.cos(), p2.sin(), p2.cos(), p3.sin(), p3.cos());
    // The crank hangs from the origin (its centre h1 below along its axis), the coupler from
    // the crank's lower end A, the rocker from (d, 0, 0).
    let (a, av) = ([-2.0 * h1 * s1, 0.0, -2.0 * h1 * c1], [-2.0 * h1 * c1 * w1, 0.0, 2.0 * h1 * s1 * w1]);
    place(
        &mut q[..12],
        &mut v[..12],
        (p1, w1),
        ([-h1 * s1, 0.0, -h1 * c1], [-h1 * c1 * w1, 0.0, h1 * s1 * w1]),
    );
    let coupler = ([a[0] - h2 * s2, 0.0, a[2] - h2 * c2], [av[0] - h2 * c2 * w2, 0.0, av[2] + h2 * s2 * w2]);
    place(&mut q[12..24], &mut v[12..24], (p2, w2), coupler);
    place(
        &mut q[24..],
        &mut v[24..],
        (p3, w3),
        ([d - h3 * s3, 0.0, -h3 * c3], [-h3 * c3 * w3, 0.0, h3 * s3 * w3]),
    );
    let (q, v) =
        (VecQ::<FourBarOfBodies>::from_column_slice(q), VecQ::<FourBarOfBodies>::from_column_slice(v));
    let start = consistent_state(&model, 0.0, &q, &v, Consistency::default()).expect("a start");
    assert!((start.q - q).amax() < 1e-12 && (start.v - v).amax() < 1e-12);
    // Each body's angle about `y` from its rotation's first row, `(cos p, 0, sin p)`.
    let angle = |s: &State<FourBarOfBodies>, body: usize| s.q[12 * body + 5].atan2(s.q[12 * body + 3]);
    let times: Vec<f64> = (1..=10).map(|k| 0.2 * k as f64).collect();
    let mut cranks = Vec::new();
    each_integrator!(&model, Fineness::new(1e-10, 1e-10, 1e-4).projected(), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 2.0, &Sampling::Times(times.clone())).expect("it swings");
        let mut closure = 0.0f64;
        for k in 0..times.len() {
            let s = solution.state(k).expect("a sample");
            let (p2, p3) = closed_loop(FOUR_BAR, angle(&s, 0));
            closure = closure.max((p2 - angle(&s, 1)).abs()).max((p3 - angle(&s, 2)).abs());
        }
        let drift = largest(solution.holonomic_residual().iter().copied());
        println!(
            "{}: four-bar of 38 rows against the closed loop {closure:.1e}, rows {drift:.1e}",
            method.name()
        );
        assert!(closure < 1e-12 && drift < 1e-12, "{}: {closure:e} {drift:e}", method.name());
        cranks.push(angle(&solution.state(times.len() - 1).expect("a sample"), 0));
    });
    assert!((cranks[0] - cranks[1]).abs() < 1e-8 && (cranks[2] - cranks[1]).abs() < 1e-6, "{cranks:?}");
}

/// Two masses on a line held at a fixed distance twice, `v + w = 0` and `2 v + 2 w = 0`, the
/// first pushed by a constant force `k`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v, y => w))]
#[dirac(lagrangian = 0.5 * m * (v * v + w * w) - k * x)]
#[dirac(constraint(tie) = v + w, constraint(tie_again) = 2.0 * v + 2.0 * w)]
pub struct TiedTwice {
    pub m: f64,
    pub k: f64,
}

#[test]
fn a_constraint_written_twice_runs_with_the_multipliers_of_least_norm() {
    let model = TiedTwice { m: 2.0, k: 3.0 };
    let start = consistent_state(
        &model,
        0.0,
        &VecQ::<TiedTwice>::zeros(),
        &VecQ::<TiedTwice>::zeros(),
        Consistency::default(),
    )
    .expect("a start");
    // The pair accelerates at `∓k/(2m)`; the rows push with `λ1 + 2 λ2 = k/2`, whose least-norm
    // split is `(1, 2) k / 10`.
    let (m, k) = (model.m, model.k);
    let least = [k / 10.0, 2.0 * k / 10.0];
    assert!(largest(start.lambda.iter().zip(&least).map(|(a, b)| a - b)) < 1e-14, "{}", start.lambda);
    each_integrator!(&model, Fineness::new(1e-10, 1e-10, 1e-2), |method, integrator| {
        let solution = integrator.solve(0.0, &start, 1.0, &Sampling::Times(vec![1.0])).expect("it moves");
        let end = solution.state(0).expect("a sample");
        let a = k / (2.0 * m);
        let exact = [-0.5 * a, 0.5 * a, -a, a];
        let apart = largest([end.q[0], end.q[1], end.v[0], end.v[1]].iter().zip(&exact).map(|(x, e)| x - e));
        let off = largest(end.lambda.iter().zip(&least).map(|(x, e)| x - e));
        println!("{}: tied twice against the closed form {apart:.1e}, multipliers {off:.1e}", method.name());
        assert!(apart < 1e-12 && off < 1e-12, "{}: {end:?}", method.name());
    });
}

/// One velocity held at 0 and at 1: rows that cannot both hold.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v))]
#[dirac(lagrangian = 0.5 * m * v * v)]
#[dirac(constraint(stop) = v, constraint(go) = v - 1.0)]
pub struct Contradictory {
    pub m: f64,
}

#[test]
fn rows_that_contradict_each_other_are_an_error_naming_one_of_them() {
    let model = Contradictory { m: 1.0 };
    let zero = VecQ::<Contradictory>::zeros();
    match consistent_state(&model, 0.0, &zero, &zero, Consistency::default()) {
        Err(SimError::InconsistentInitialState { equation, .. }) => {
            assert!(equation.contains("stop") || equation.contains("go"), "{equation}")
        }
        other => panic!("{other:?}"),
    }
    each_integrator!(&model, Fineness::new(1e-8, 1e-8, 1e-2), |method, integrator| {
        match integrator.solve(0.0, &State::<Contradictory>::zeros(), 1.0, &Sampling::Steps) {
            Err(SimError::StateNotConsistent { equation, .. }) => {
                assert!(equation.contains("`go`"), "{equation}")
            }
            Err(other) => panic!("{}: {other:?}", method.name()),
            Ok(_) => panic!("{}: rows that contradict each other ran", method.name()),
        }
    });
}
