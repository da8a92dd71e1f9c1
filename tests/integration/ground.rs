//! URDF robots that touch the ground (`#[dirac(urdf = …, floating, ground(restitution = e))]`):
//! each point of their `<collision>` shapes that can touch the plane `z = 0` a unilateral
//! constraint. The references are free fall's closed form and the laws a frictionless ground
//! keeps: it pushes only along `z`, so the momentum along `x` and `y` and the angular momentum
//! about the vertical are kept, and an elastic impact keeps the energy.

use dirac::State;
use dirac::nalgebra::{Matrix3, Vector3};
use dirac::prelude::*;

use crate::every_method::{Fineness, Method};
use crate::zoo::robots::{Brick, GroundBall};

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
