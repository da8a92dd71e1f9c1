//! Robots read from URDF files, against Pinocchio on the same file: the joint-space mass
//! matrix, gravity and bias torques at random states, and a free swing integrated by SciPy's
//! DOP853 on Pinocchio's dynamics. The references are computed by
//! `tests/references/robots.py` (`bash tests/references/robots.sh`), independently of dirac.

use dirac::joint_space;
use std::ops::ControlFlow;

use dirac::Events;
use dirac::State;
use dirac::prelude::*;

use crate::every_method::{Fineness, Method};
use crate::util::{check_csc_against_dense, check_jacobian_by_differences};
use crate::zoo::robots::{FloatingPanda, Panda, PandaStops, PandaStopsWithContacts, SWING_START};

fn table(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines.next().expect("a header").split(',').map(str::to_owned).collect();
    let rows = lines.map(|l| l.split(',').map(|x| x.parse().expect("a number")).collect()).collect();
    (header, rows)
}

/// The largest entry of `a − b`, relative to the largest entry of `b` (or 1 if that is less).
fn relative_error(a: impl IntoIterator<Item = f64>, b: &[f64]) -> f64 {
    let scale = b.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
    a.into_iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs())) / scale
}

#[test]
fn the_panda_has_the_joints_and_links_of_its_urdf() {
    let names: Vec<String> = Panda::NAMES.coordinate_names().to_vec();
    let mut expected: Vec<String> = (1..=7).map(|k| format!("panda_joint{k}")).collect();
    expected.extend(["panda_finger_joint1".to_owned(), "panda_finger_joint2".to_owned()]);
    assert_eq!(names, expected);
    assert_eq!(Panda.constraint_names(), ["panda_finger_joint2_mimic"]);
    assert_eq!(Panda.ports().len(), 9, "every joint is a port");
    let outputs = Panda::NAMES.output_names();
    for link in
        ["panda_link0", "panda_link1", "panda_link7", "panda_hand", "panda_hand_tcp", "panda_leftfinger"]
    {
        for axis in ["x", "y", "z", "r11", "r23", "r33"] {
            assert!(outputs.iter().any(|o| *o == format!("{link}_{axis}")), "{link}_{axis} in {outputs:?}");
        }
    }
}

/// Each link's pose, the root's too, against Pinocchio's `oMf` at ten random joint positions
/// (`tests/references/panda_frames.csv`, computed by `tests/references/robots.py`): origins and
/// rotations read by name from the model's outputs.
#[test]
fn the_panda_gives_every_links_position_and_rotation_as_pinocchio_does() {
    let (header, rows) = table(include_str!("../references/panda_frames.csv"));
    assert_eq!(header.len(), 9 + 6 * 12);
    assert_eq!(rows.len(), 10);
    let names = Panda::NAMES.output_names();
    let mut outputs = vec![0.0; names.len()];
    let mut worst = 0.0_f64;
    for row in &rows {
        let q = VecQ::<Panda>::from_column_slice(&row[0..9]);
        let (v, lambda) = (VecQ::<Panda>::zeros(), VecC::<Panda>::zeros());
        Panda.outputs(0.0, &q, &v, &lambda, &mut outputs);
        for (column, reference) in header.iter().zip(row).skip(9) {
            let k = names.iter().position(|n| n == column).unwrap_or_else(|| panic!("no output {column}"));
            worst = worst.max((outputs[k] - reference).abs());
        }
    }
    eprintln!("Panda's link poses against Pinocchio: {worst:.1e}");
    assert!(worst < 1e-14, "{worst:e}");
}

#[test]
fn the_panda_has_pinocchios_mass_matrix_gravity_and_bias_torques() {
    let (header, rows) = table(include_str!("../references/panda_dynamics.csv"));
    assert_eq!(header.len(), 9 + 9 + 81 + 9 + 9);
    assert_eq!(rows.len(), 20);
    let (mut worst_m, mut worst_g, mut worst_b) = (0.0_f64, 0.0_f64, 0.0_f64);
    for row in &rows {
        let q = VecQ::<Panda>::from_column_slice(&row[0..9]);
        let v = VecQ::<Panda>::from_column_slice(&row[9..18]);
        let mass = joint_space::mass_matrix(&Panda, 0.0, &q);
        let gravity = joint_space::gravity_torques(&Panda, 0.0, &q);
        let bias = joint_space::bias_torques(&Panda, 0.0, &q, &v);
        // Row-major in the file; nalgebra iterates column-major, so compare the transpose.
        worst_m = worst_m.max(relative_error(mass.transpose().iter().copied(), &row[18..99]));
        worst_g = worst_g.max(relative_error(gravity.iter().copied(), &row[99..108]));
        worst_b = worst_b.max(relative_error(bias.iter().copied(), &row[108..117]));
    }
    eprintln!(
        "Panda against Pinocchio: mass matrix {worst_m:.1e}, gravity {worst_g:.1e}, bias {worst_b:.1e}"
    );
    assert!(worst_m < 1e-12 && worst_g < 1e-12 && worst_b < 1e-12, "{worst_m:e} {worst_g:e} {worst_b:e}");
}

/// Pinocchio's articulated-body algorithm (`aba`) at 20 random states under random torques
/// (`tests/references/panda_aba.csv`, computed by `tests/references/robots.py --aba`): the
/// accelerations of the Panda's generated recursion.
#[test]
fn the_pandas_forward_dynamics_are_pinocchios_aba() {
    const { assert!(<Panda as joint_space::JointSpace>::RECURSIVE) };
    let (header, rows) = table(include_str!("../references/panda_aba.csv"));
    assert_eq!((header.len(), rows.len()), (4 * 9, 20));
    let mut worst = 0.0_f64;
    for row in &rows {
        let [q, v, tau] = [0, 9, 18].map(|k| VecQ::<Panda>::from_column_slice(&row[k..k + 9]));
        let a = joint_space::forward_dynamics(&Panda, 0.0, &q, &v, &tau).expect("a regular mass matrix");
        worst = worst.max(relative_error(a.iter().copied(), &row[27..36]));
    }
    eprintln!("Panda's forward dynamics against Pinocchio's aba: {worst:.1e}");
    assert!(worst < 1e-12, "{worst:e}");
}

/// A deterministic stream of numbers in `[-1, 1)`.
fn uniform(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    ((*seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
}

/// The recursions generated for a robot's tree against the same quantities read off the
/// model's blocks, `joint_space::blocks` (from the Lagrangian the derive differentiated), at 20
/// random states; the accelerations of the articulated-body recursion against `M a + b = τ`
/// from the blocks. Returns the largest relative differences (mass, gravity, bias, `M a + b − τ`).
fn recursions_against_blocks<M: DenseModel>(model: &M) -> [f64; 5]
where
    dirac::__private::DefaultAllocator: dirac::__private::Storage<M>,
{
    let mut seed = 45_u64;
    let mut worst = [0.0_f64; 5];
    for _ in 0..20 {
        let [q, v, tau] = [2.0, 2.0, 5.0].map(|scale| VecQ::<M>::from_fn(|_, _| scale * uniform(&mut seed)));
        let mass = joint_space::mass_matrix(model, 0.0, &q);
        let gravity = joint_space::gravity_torques(model, 0.0, &q);
        let bias = joint_space::bias_torques(model, 0.0, &q, &v);
        let a = joint_space::forward_dynamics(model, 0.0, &q, &v, &tau).expect("a regular mass matrix");
        let mut from_blocks = mass.clone();
        joint_space::blocks::mass_matrix(model, 0.0, &q, &mut from_blocks);
        let (mut g, mut b) = (gravity.clone(), bias.clone());
        joint_space::blocks::gravity_torques(model, 0.0, &q, &mut g);
        joint_space::blocks::bias_torques(model, 0.0, &q, &v, &mut b);
        let balance = &from_blocks * a + &b;
        let relative = |x: f64, scale: f64| x / scale.max(1.0);
        worst[0] = worst[0].max(relative((&mass - &from_blocks).amax(), from_blocks.amax()));
        worst[1] = worst[1].max(relative((&gravity - &g).amax(), g.amax()));
        worst[2] = worst[2].max(relative((&bias - &b).amax(), b.amax()));
        worst[3] = worst[3].max(relative((balance - &tau).amax(), tau.amax()));
        // What the accelerations read: `∂L/∂q + F − L_vt − L_vq v` and `L_vv`.
        let (mut rate, mut l_vv) = (VecQ::<M>::zeros(), dirac::MatQQ::<M>::zeros());
        assert!(model.tree_dynamics(0.0, &q, &v, &mut rate, &mut l_vv), "a tree's recursions");
        let (mut dl_dq, mut force, mut l_vt) = (VecQ::<M>::zeros(), VecQ::<M>::zeros(), VecQ::<M>::zeros());
        let mut l_vq = dirac::MatQQ::<M>::zeros();
        model.dl_dq(0.0, &q, &v, &mut dl_dq);
        model.force(0.0, &q, &v, &mut force);
        model.l_vt(0.0, &q, &v, &mut l_vt);
        model.l_vq(0.0, &q, &v, &mut l_vq);
        let expected = dl_dq + force - l_vt - l_vq * &v;
        worst[4] = worst[4]
            .max(relative((rate - &expected).amax(), expected.amax()))
            .max(relative((l_vv - &from_blocks).amax(), from_blocks.amax()));
    }
    worst
}

/// The puck of `tests/robots/free/puck.urdf` (a planar joint normal to z) under a gravity that
/// is a parameter and pulls along no axis.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(urdf = "../tests/robots/free/puck.urdf", gravity = [g * tilt.sin(), -g * tilt.cos(), -0.5 * g])]
struct TiltedPuck {
    g: f64,
    tilt: f64,
}

/// The Panda (its finger mimicking the other through a row the recursions leave alone), its
/// companion with its stops' slack coordinates (each of unit mass, beside the tree), and the
/// puck, whose planar joint is two slides and a turn, under a gravity that is a parameter
/// pointing along no axis. A robot that floats keeps the blocks (its base's embedded rotation
/// is no joint of the recursions).
#[test]
fn the_recursions_of_a_robots_tree_are_its_lagrangians() {
    use dirac::joint_space::JointSpace;
    const { assert!(Panda::RECURSIVE && PandaStopsWithContacts::RECURSIVE && TiltedPuck::RECURSIVE) };
    const { assert!(!FloatingPanda::RECURSIVE) };
    let (mut rate, mut l_vv) = (VecQ::<FloatingPanda>::zeros(), dirac::MatQQ::<FloatingPanda>::zeros());
    let q = VecQ::<FloatingPanda>::zeros();
    assert!(!FloatingPanda.tree_dynamics(0.0, &q, &q, &mut rate, &mut l_vv), "no recursions: the blocks");
    for (name, worst, bound) in [
        ("Panda", recursions_against_blocks(&Panda), 1e-13),
        ("Panda with its stops' slacks", recursions_against_blocks(&PandaStops.with_contacts()), 1e-13),
        ("puck", recursions_against_blocks(&TiltedPuck { g: 9.0, tilt: 0.3 }), 1e-13),
    ] {
        eprintln!(
            "{name}: recursions against the blocks: mass {:.1e}, gravity {:.1e}, bias {:.1e}, M a + b − τ {:.1e}, \
             balance and L_vv the accelerations read {:.1e}",
            worst[0], worst[1], worst[2], worst[3], worst[4]
        );
        assert!(worst.iter().all(|w| *w < bound), "{name}: {worst:?}");
    }
}

#[test]
fn the_panda_has_the_derivatives_its_differences_say() {
    check_jacobian_by_differences(&Panda, 38, 5);
    crate::blocks::check_blocks(&Panda, 39);
}

/// The Panda's second derivatives are large enough that it compiles them once, in its Jacobian
/// blocks, and reads `L_qq`, the flat Jacobian (checked above against differences of the flat
/// residual, which is compiled on its own) and the compressed columns from there. `L_qq` is
/// checked here against central differences of `∂L/∂q`, which is also compiled on its own.
#[test]
fn the_second_derivatives_a_large_model_reads_from_its_blocks_are_its_differences() {
    check_csc_against_dense(&Panda, 40, 3);
    let mut rng = crate::util::Rng::new(41);
    for _ in 0..5 {
        let y = crate::util::random_y(&Panda, &mut rng);
        let s = State::<Panda>::from_y(Panda.sizes(), &y);
        let mut l_qq = MatQQ::<Panda>::zeros();
        Panda.l_qq(0.0, &s.q, &s.v, &mut l_qq);
        let dl_dq = |q: &VecQ<Panda>| {
            let mut out = VecQ::<Panda>::zeros();
            Panda.dl_dq(0.0, q, &s.v, &mut out);
            out
        };
        let n = Panda.sizes().nq;
        for c in 0..n {
            let h = 1e-6;
            let (mut plus, mut minus) = (s.q, s.q);
            plus[c] += h;
            minus[c] -= h;
            let column = (dl_dq(&plus) - dl_dq(&minus)) / (2.0 * h);
            for r in 0..n {
                let (exact, approx) = (l_qq[(r, c)], column[r]);
                assert!(
                    (exact - approx).abs() <= 1e-6 * exact.abs().max(1.0),
                    "L_qq[{r}, {c}]: {exact} against {approx}"
                );
            }
        }
    }
}

/// The swing's start, its fingers made consistent with the mimic row.
fn swing_start() -> State<Panda> {
    let q = VecQ::<Panda>::from_column_slice(&SWING_START);
    consistent_state(&Panda, 0.0, &q, &VecQ::<Panda>::zeros(), Consistency::default())
        .expect("a consistent start")
}

/// Radau and Explicit at rtol = atol = 1e-10 and the variational integrator at h = 2e-4,
/// against the reference's samples every 0.1 s. Radau without its `projection`: the mimic row
/// is linear, and its projection of velocities (the smallest correction in the Euclidean norm,
/// not the mass-weighted one) would perturb the arm's momenta through the fingers' coupling.
#[test]
fn the_panda_swings_as_pinocchio_and_dop853_say_in_every_method() {
    let (header, rows) = table(include_str!("../references/panda_swing.csv"));
    assert_eq!(header.len(), 1 + 18);
    let times: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    let start = swing_start();
    each_integrator!(&Panda, Fineness::new(1e-10, 1e-10, 2e-4), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 1.0, &Sampling::Times(times.clone())).expect("the swing");
        let mut worst = 0.0_f64;
        for (k, row) in rows.iter().enumerate() {
            for j in 0..9 {
                let c = Coordinate::<Panda>::unchecked(j);
                worst = worst.max((solution.q(c)[k] - row[1 + j]).abs());
            }
        }
        // Measured: Radau 1.7e-9, Explicit 1.7e-10, Variational (second order) 1.2e-3.
        let bound = match method {
            Method::Radau => 1e-8,
            Method::Explicit => 1e-9,
            Method::Variational => 2e-3,
        };
        eprintln!("{}: Panda swing, max |q - q_ref| over 1 s: {worst:.2e}", method.name());
        assert!(worst < bound, "{}: {worst:e}", method.name());
        let residual = solution.holonomic_residual().iter().fold(0.0_f64, |m, r| m.max(r.abs()));
        assert!(residual < 1e-12, "{}: the mimic row drifts by {residual:e}", method.name());
    });
}

/// The elbow thrown at its upper stop (−0.0698 rad, from the URDF) at 3 rad/s: with
/// restitution 0 it strikes the stop and rests against it (the companion closes the contact;
/// its force holds the elbow) or leaves it as the arm's motion pulls, and never passes it.
#[test]
fn the_panda_with_joint_limits_strikes_its_stops_and_never_passes_them() {
    let names = PandaStops::NAMES.unilateral_names();
    assert_eq!(names.len(), 2 * 8, "two stops on each of seven arm joints and the first finger: {names:?}");
    let upper = -0.0698;
    let mut model = PandaStops.with_contacts();
    let joint = |name: &str| model.coordinate(name).expect("a joint").index();
    let mut q = VecQ::<PandaStopsWithContacts>::zeros();
    for (name, angle) in Panda::NAMES.coordinate_names().iter().zip(SWING_START) {
        q[joint(name)] = angle;
    }
    let elbow = joint("panda_joint4");
    q[elbow] = -0.3;
    let mut v = VecQ::<PandaStopsWithContacts>::zeros();
    v[elbow] = 3.0;
    let start = consistent_state(&model, 0.0, &q, &v, Consistency::default()).expect("a start");
    macro_rules! throw {
        ($name:literal, $integrator:expr) => {{
            let mut integrator = $integrator;
            let mut events = Events::new().contacts(integrator.model());
            let solution = integrator
                .solve_with_events(0.0, &start, 0.5, &Sampling::Every(1e-3), &mut events, |_, _| {
                    ControlFlow::Continue(())
                })
                .expect("the throw");
            let elbow = solution.q(Coordinate::<PandaStopsWithContacts>::unchecked(elbow));
            let highest = elbow.iter().fold(f64::MIN, |m, x| m.max(*x));
            let strikes = solution.impacts_at("panda_joint4_upper").expect("a stop's name");
            let force = solution.column("lambda(panda_joint4_upper_force)").expect("the stop's force");
            let struck = strikes.first().map_or(f64::INFINITY, |s| s.t);
            let (before, after): (Vec<_>, Vec<_>) =
                solution.t().iter().zip(force).partition(|(t, _)| **t < struck);
            assert!(before.iter().all(|(_, f)| f.abs() < 1e-9), "{}: a force on the open stop", $name);
            let held = after.iter().filter(|(_, f)| f.abs() > 1e-6).count();
            eprintln!(
                "{}: elbow at most {highest:.9} rad, {} strike(s) at {struck:.4} s, held by the stop at {held} of the {} samples after",
                $name,
                strikes.len(),
                after.len()
            );
            assert_eq!(strikes.len(), 1, "{}: one strike", $name);
            assert!(strikes[0].t > 0.05 && strikes[0].t < 0.1, "{}: struck at {}", $name, strikes[0].t);
            assert!(highest <= upper + 1e-9, "{}: the elbow passed its stop: {highest}", $name);
        }};
    }
    throw!("Radau", Radau::new(&mut model, RadauOptions::tolerances(1e-9, 1e-9)).expect("options"));
    throw!("Explicit", Explicit::new(&mut model, ExplicitOptions::tolerances(1e-9, 1e-9)).expect("options"));
}
