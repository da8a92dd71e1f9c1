//! URDF robots that touch the ground (`#[dirac(urdf = …, floating, ground(restitution = e))]`):
//! each point of their `<collision>` shapes that can touch the plane `z = 0` a unilateral
//! constraint. The references are free fall's closed form and the laws a frictionless ground
//! keeps: it pushes only along `z`, so the momentum along `x` and `y` and the angular momentum
//! about the vertical are kept, and an elastic impact keeps the energy. With
//! `ground(friction = mu)`, Coulomb's cone acts where a point rests: a sliding ball's closed
//! form (it rolls from `t = 2 v0 / (7 μ g)` at `5/7 v0`) and a brick's on its face (it stops
//! after `v0² / (2 μ g)`).

use dirac::State;
use dirac::nalgebra::{Matrix3, Vector3};
use dirac::prelude::*;

use crate::every_method::{Fineness, Method};
use crate::zoo::robots::{
    Brick, GroundBall, RollingBall, RollingBallWithContacts, SlidingBrick, SlidingBrickWithContacts,
};

const G: f64 = 9.81;

/// The index of coordinate `name` of `M`.
fn coordinate<M: LagrangeDirac>(name: &str) -> usize
where
    DefaultAllocator: Storage<M>,
{
    M::NAMES
        .coordinate_names()
        .iter()
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("no coordinate {name}"))
}

/// The rotation `exp(ŵ)`.
fn rotation(w: Vector3<f64>) -> Matrix3<f64> {
    dirac::nalgebra::Rotation3::new(w).into_inner()
}

/// The largest change of `out(name)` along a solution, relative to its largest size (or 1).
fn drift<M: LagrangeDirac, S>(solution: &Solution<M, S>, name: &str) -> f64
where
    DefaultAllocator: Storage<M>,
{
    let column = solution.column(&format!("out({name})")).expect("a momentum");
    let scale = column.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
    column.iter().fold(0.0_f64, |m, x| m.max((x - column[0]).abs())) / scale
}

/// A spinning ball dropped from `z0 = 1` while it moves along `x`: the ground's force passes
/// through its centre, so it touches down at `T_n = t1 (1 + 2 (e + … + eⁿ⁻¹))`,
/// `t1 = √(2 (z0 − r) / g)`, rises to `r + e² (z0 − r)` between the first two, moves along `x`
/// at its initial speed and keeps its spin.
#[test]
fn a_ball_read_from_a_urdf_bounces_on_the_ground_as_free_fall_says() {
    let (z0, r, e) = (1.0, 0.1, 0.5);
    let ball = GroundBall { e };
    assert_eq!(ball.unilateral_names(), ["ball_ground"]);
    let r0 = rotation(Vector3::new(0.2, -0.4, 0.1));
    let rows = std::array::from_fn(|i| std::array::from_fn(|j| r0[(i, j)]));
    let mut start = State::<GroundBall>::zeros();
    start
        .place_free_body("root_joint", [0.0, 0.0, z0], rows, [0.3, 0.0, 0.0], [1.0, 2.0, 3.0])
        .expect("free");
    let start = consistent_state(&ball, 0.0, &start.q, &start.v, Consistency::default()).expect("consistent");
    let t1 = (2.0 * (z0 - r) / G).sqrt();
    let touchdowns = [t1, t1 * (1.0 + 2.0 * e), t1 * (1.0 + 2.0 * e + 2.0 * e * e)];
    let apex = t1 * (1.0 + e);
    // Short of the fourth touchdown, `t1 (1 + 2 (e + e² + e³))`, and of the bounces' limit.
    let end = 1.15;
    let (x, z) = (coordinate::<GroundBall>("root_joint_x"), coordinate::<GroundBall>("root_joint_z"));
    each_integrator!(&ball, Fineness::new(1e-12, 1e-12, 1e-3), |method, integrator| {
        let solution = integrator
            .solve(0.0, &start, end, &Sampling::Times(vec![apex, end]))
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let times = solution.event_times("ball_ground").expect("the contact");
        let late = touchdowns.iter().zip(&times).fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        let height = (solution.state(0).expect("the apex").q[z] - (r + e * e * (z0 - r))).abs();
        let end_state = solution.state(1).expect("the end");
        let along = (end_state.q[x] - 0.3 * end).abs();
        let kept = ["linear_momentum_x", "linear_momentum_y", "angular_momentum_z"]
            .map(|name| drift(&solution, name))
            .into_iter()
            .fold(0.0_f64, f64::max);
        eprintln!(
            "{}: touchdowns {late:.1e} s off, apex {height:.1e} off, x {along:.1e} off, momenta kept to {kept:.1e}",
            method.name()
        );
        assert!(times.len() >= 3, "{method:?}: {} touchdowns", times.len());
        // The variational integrator steps h = 1e-3, finds a touchdown on its grid's
        // interpolant and restarts from there, which moves the momenta it otherwise keeps to
        // round-off (measured 2.4e-8); the adaptive methods' dense output is exact on parabolas.
        let (bound, momenta) = if method == Method::Variational { (1e-5, 1e-7) } else { (1e-9, 1e-9) };
        assert!(late < bound && height < bound && along < bound, "{method:?}");
        assert!(kept < momenta, "{method:?}: {kept:e}");
    });
}

/// A brick with a capsule on top, dropped turned so that one corner touches first, bounces
/// elastically on its corners: energy and the momenta the frictionless ground does not push
/// on are kept through every impact, and no corner or capsule end goes below the ground.
#[test]
fn a_brick_bounces_on_its_corners_keeping_energy_and_horizontal_momenta() {
    assert_eq!(Brick.unilateral_names().len(), 10, "eight corners and the capsule's two ends");
    let r0 = rotation(Vector3::new(0.5, 0.3, 0.2));
    let rows = std::array::from_fn(|i| std::array::from_fn(|j| r0[(i, j)]));
    let mut start = State::<Brick>::zeros();
    start
        .place_free_body("root_joint", [0.1, -0.2, 0.5], rows, [0.4, -0.2, 0.0], [0.5, -1.0, 2.0])
        .expect("free");
    let start =
        consistent_state(&Brick, 0.0, &start.q, &start.v, Consistency::default()).expect("consistent");
    let times: Vec<f64> = (1..=100).map(|k| 0.01 * f64::from(k)).collect();
    let radau = Radau::new(&Brick, RadauOptions::tolerances(1e-11, 1e-11))
        .expect("options")
        .solve(0.0, &start, 1.0, &Sampling::Times(times.clone()))
        .expect("Radau");
    check_brick(Method::Radau, &radau);
    let explicit = Explicit::new(&Brick, ExplicitOptions::tolerances(1e-11, 1e-11))
        .expect("options")
        .solve(0.0, &start, 1.0, &Sampling::Times(times))
        .expect("Explicit");
    check_brick(Method::Explicit, &explicit);
}

/// The brick's impacts, energy, momenta and lowest point along `solution`.
fn check_brick<S>(method: Method, solution: &Solution<Brick, S>) {
    let impacts: usize = Brick
        .unilateral_names()
        .iter()
        .map(|name| solution.event_times(name).expect("a contact").len())
        .sum();
    let energy = solution.energy();
    let lost = energy.iter().fold(0.0_f64, |m, x| m.max((x - energy[0]).abs())) / energy[0].abs();
    let kept = ["linear_momentum_x", "linear_momentum_y", "angular_momentum_z"]
        .map(|name| drift(solution, name))
        .into_iter()
        .fold(0.0_f64, f64::max);
    let mut lowest = f64::INFINITY;
    let mut gaps = vec![0.0; 10];
    for k in 0..solution.len() {
        let state = solution.state(k).expect("a sample");
        Brick.unilateral(0.0, &state.q, &mut gaps);
        lowest = gaps.iter().copied().fold(lowest, f64::min);
    }
    eprintln!(
        "{}: {impacts} impacts in 1 s, energy kept to {lost:.1e}, momenta to {kept:.1e}, lowest point {lowest:.1e}",
        method.name()
    );
    assert!(impacts >= 2, "{method:?}: {impacts} impacts");
    assert!(lost < 1e-8 && kept < 1e-9, "{method:?}: {lost:e} {kept:e}");
    assert!(lowest > -1e-9, "{method:?}: {lowest:e}");
}

/// A ball of radius `r` put on the ground sliding at `v0` without spin: the friction `μ m g`
/// slows it, and its torque `r μ m g` about the centre spins it up at `5 μ g / (2 r)` (moment
/// `2/5 m r²`), until the point on the ground stops, `v0 − μ g t = 5/2 μ g t`: at
/// `t_r = 2 v0 / (7 μ g)`, after `x_r = v0 t_r − μ g t_r² / 2`, it rolls on at `5/7 v0`, the
/// cone stuck and its force zero. Under every integrator.
#[test]
fn a_ball_sliding_on_the_ground_rolls_on_at_five_sevenths_of_its_speed() {
    let (v0, r, mu) = (2.0, 0.1, 0.3);
    let mut ball = RollingBall { mu }.with_contacts();
    let declared: Vec<String> = ball.event_declarations().into_iter().map(|(name, _)| name).collect();
    assert_eq!(declared, ["ball_ground_slip_stops", "ball_ground_slip_slips"]);
    assert!(ball.set_contact_closed(0, true), "the companion rests its contact");
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mut start = State::<RollingBallWithContacts>::zeros();
    start.place_free_body("root_joint", [0.0, 0.0, r], identity, [v0, 0.0, 0.0], [0.0; 3]).expect("free");
    let start = consistent_state(&ball, 0.0, &start.q, &start.v, Consistency::default()).expect("consistent");
    let t_r = 2.0 * v0 / (7.0 * mu * G);
    let x_r = v0 * t_r - 0.5 * mu * G * t_r * t_r;
    let end = 1.0;
    let x = coordinate::<RollingBallWithContacts>("root_joint_x");
    each_integrator!(&mut ball, Fineness::new(1e-11, 1e-11, 1e-4), |method, integrator| {
        let mut events = Events::new().contacts(integrator.model());
        let solution = integrator
            .solve_with_events(0.0, &start, end, &Sampling::Times(vec![t_r, end]), &mut events, |_, _| {
                std::ops::ControlFlow::Continue(())
            })
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let stops = solution.event_times("ball_ground_slip_stops").expect("the cone");
        let rolling = solution.state(0).expect("t_r");
        let last = solution.state(1).expect("the end");
        let late = (stops[0] - t_r).abs();
        let at = (rolling.q[x] - x_r).abs();
        let speed = (last.v[x] - 5.0 / 7.0 * v0).abs();
        let along = (last.q[x] - (x_r + 5.0 / 7.0 * v0 * (end - t_r))).abs();
        eprintln!(
            "{}: rolls {late:.1e} s off t_r, {at:.1e} m off x_r, at {speed:.1e} m/s off 5/7 v0, {along:.1e} m off at the end",
            method.name()
        );
        assert_eq!(stops.len(), 1, "{method:?}: it sticks once and rolls on: {stops:?}");
        assert!(solution.event_times("ball_ground opens").expect("a resting contact").is_empty());
        // The stop is read where the slip has turned back by 2e-9 (the derive's margin), 1.9e-10 s
        // after t_r here (2e-9 over the slip's deceleration 7/2 μ g); the variational sample at t_r
        // is then read inside the step that ends at the stop, second order in h = 1e-4 (3.3e-9
        // measured; Radau 7.2e-13, Explicit 2.7e-13).
        let at_bound = if method == Method::Variational { 1e-8 } else { 1e-9 };
        assert!(late < 1e-9 && at < at_bound && speed < 1e-9, "{method:?}");
        // The variational steps are second order in h = 1e-4 along the roll (5.0e-7 measured,
        // 5.0e-5 at h = 1e-3); the adaptive methods meet their tolerance.
        let bound = if method == Method::Variational { 1e-6 } else { 1e-9 };
        assert!(along < bound, "{method:?}: {along:e}");
    });
}

/// A brick lying on its face, thrown along the ground at `v0` in the direction 0.4 rad: four
/// corners rest, their normal forces redundant (four rows, three freedoms: the least-norm
/// ones), each under its own cone. All four slip along the throw, so the friction `μ m g`
/// slows the brick uniformly (its pressure's centre moves ahead of the centre of mass, on the
/// line of the slip, and the brick does not turn): all four stop together at `v0 / (μ g)`,
/// after `v0² / (2 μ g)`, and the brick stays there.
#[test]
fn a_brick_thrown_along_the_ground_on_its_face_stops_after_v0_squared_over_two_mu_g() {
    // The brick's companion takes more than a test thread's stack.
    let worker = std::thread::Builder::new().stack_size(64 << 20).spawn(brick_stops).expect("a thread");
    worker.join().expect("the brick stops");
}

fn brick_stops() {
    let (v0, mu, angle) = (1.0f64, 0.4, 0.4f64);
    let mut brick = SlidingBrick { mu }.with_contacts();
    // Its box (0.4 × 0.2 × 0.1, centred 0.05 ahead of the link's origin) lies flat with the
    // link's origin 0.05 above the ground: corners 1 to 4 are its lower face's.
    for j in 0..4 {
        assert!(brick.set_contact_closed(j, true));
    }
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mut start = State::<SlidingBrickWithContacts>::zeros();
    let throw = [v0 * angle.cos(), v0 * angle.sin(), 0.0];
    start.place_free_body("root_joint", [0.0, 0.0, 0.05], identity, throw, [0.0; 3]).expect("free");
    let start =
        consistent_state(&brick, 0.0, &start.q, &start.v, Consistency::default()).expect("consistent");
    let weight = 2.5 * G;
    let pressed: f64 = (0..4).map(|j| start.lambda[brick.contact_row(j).expect("a row")]).sum();
    assert!(
        (pressed - weight).abs() < 1e-9 * weight,
        "the corners carry {pressed}, the brick weighs {weight}"
    );
    let (t_s, d) = (v0 / (mu * G), v0 * v0 / (2.0 * mu * G));
    let (x, y) = (
        coordinate::<SlidingBrickWithContacts>("root_joint_x"),
        coordinate::<SlidingBrickWithContacts>("root_joint_y"),
    );
    each_integrator!(&mut brick, Fineness::new(1e-11, 1e-11, 1e-4), |method, integrator| {
        let mut events = Events::new().contacts(integrator.model());
        let solution = integrator
            .solve_with_events(0.0, &start, 1.0, &Sampling::Times(vec![0.5, 1.0]), &mut events, |_, _| {
                std::ops::ControlFlow::Continue(())
            })
            .unwrap_or_else(|error| panic!("{method:?}: {error}"));
        let stops: Vec<f64> = (1..=4)
            .flat_map(|k| solution.event_times(&format!("brick_ground{k}_slip_stops")).expect("a cone"))
            .collect();
        let late = (stops[0] - t_s).abs();
        let [half, last] = [0, 1].map(|k| solution.state(k).expect("a sample"));
        let off = (last.q[x] - d * angle.cos()).hypot(last.q[y] - d * angle.sin());
        let moved = (last.q[x] - half.q[x]).hypot(last.q[y] - half.q[y]);
        eprintln!(
            "{}: stops {late:.1e} s off v0/(mu g), {off:.1e} m off v0²/(2 mu g), moves {moved:.1e} m after",
            method.name()
        );
        // One stop event sticks all four: the others' slips have stopped with it.
        assert_eq!(stops.len(), 1, "{method:?}: {stops:?}");
        assert!(late < 1e-9 && off < 1e-9, "{method:?}");
        assert!(moved < 1e-12, "{method:?}: it creeps {moved:e} m at rest");
    });
}

/// The brick of the test above thrown along the ground on its face while it spins about the
/// vertical: its four corners slip apart, each under its own cone, so how their redundant
/// normal forces share the weight changes the friction's torque and so the motion, and the
/// rows with their friction (`B`) are not redundant where the contacts' rows (`A`) are. The
/// consistent start shares the load as the deflated factorisations do (no part along
/// `ker Aᵀ`); the corners then carry the weight, the reference independent of the share (the
/// start took a solution of the nearly singular system as written before, whose corners
/// carried 38.8 N of the brick's 24.5 N). The integrators do not yet share it so (their
/// deflation measures the rows `B`): each refuses the motion by name, where it would otherwise
/// step a load shared at round-off.
#[test]
fn a_spinning_brick_on_its_face_starts_with_the_weight_shared_and_is_refused_by_name() {
    let worker = std::thread::Builder::new().stack_size(64 << 20).spawn(spinning_brick).expect("a thread");
    worker.join().expect("the brick starts");
}

fn spinning_brick() {
    let (v0, spin, mu) = (1.0f64, 6.0, 0.4);
    let mut brick = SlidingBrick { mu }.with_contacts();
    for j in 0..4 {
        assert!(brick.set_contact_closed(j, true));
    }
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mut start = State::<SlidingBrickWithContacts>::zeros();
    start
        .place_free_body("root_joint", [0.0, 0.0, 0.05], identity, [v0, 0.0, 0.0], [0.0, 0.0, spin])
        .expect("free");
    let start =
        consistent_state(&brick, 0.0, &start.q, &start.v, Consistency::default()).expect("consistent");
    let weight = 2.5 * G;
    let pressed: f64 = (0..4).map(|j| start.lambda[brick.contact_row(j).expect("a row")]).sum();
    assert!(
        (pressed - weight).abs() < 1e-9 * weight,
        "the corners carry {pressed}, the brick weighs {weight}"
    );
    let refusal = |method: &str, error: Option<SimError>| {
        let message =
            error.map(|error| error.to_string()).unwrap_or_else(|| panic!("{method}: the run went on"));
        assert!(
            message.contains("brick_ground1_force") && message.contains("are dependent at this state"),
            "{method}: {message}"
        );
    };
    let mut radau = Radau::new(&mut brick, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid options");
    let mut events = Events::new().contacts(radau.model());
    refusal(
        "Radau",
        radau
            .solve_with_events(0.0, &start, 0.1, &Sampling::Steps, &mut events, |_, _| {
                std::ops::ControlFlow::Continue(())
            })
            .err(),
    );
    let mut explicit =
        Explicit::new(&mut brick, ExplicitOptions::tolerances(1e-10, 1e-10)).expect("valid options");
    let mut events = Events::new().contacts(explicit.model());
    refusal(
        "Explicit",
        explicit
            .solve_with_events(0.0, &start, 0.1, &Sampling::Steps, &mut events, |_, _| {
                std::ops::ControlFlow::Continue(())
            })
            .err(),
    );
}
