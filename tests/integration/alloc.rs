//! No heap allocation inside an integration step: a counting global allocator (the test
//! binary's) observes the allocations of this thread while an integrator's steps run, after
//! set-up. Counts are per thread, so the other tests running beside these do not disturb them.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use dirac::prelude::*;
use dirac::{Drive, Input, State};

use crate::fmi::driven_pendulum;
use crate::zoo::{self, *};

struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
    /// The bytes this thread holds, and the most it held since [`peak_from_here`] last reset it.
    static LIVE: Cell<isize> = const { Cell::new(0) };
    static PEAK: Cell<isize> = const { Cell::new(0) };
}

fn grow(bytes: isize) {
    let live = LIVE.with(|c| {
        c.set(c.get() + bytes);
        c.get()
    });
    PEAK.with(|c| c.set(c.get().max(live)));
}

/// Starts watching the most bytes held from now on, and returns the bytes held now.
fn peak_from_here() -> isize {
    let live = LIVE.with(Cell::get);
    PEAK.with(|c| c.set(live));
    live
}

fn peak() -> isize {
    PEAK.with(Cell::get)
}

// SAFETY: every call is forwarded unchanged to the system allocator; counting touches only a
// const-initialised thread-local cell, which does not allocate.
#[allow(unsafe_code)]
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.with(|c| c.set(c.get() + 1));
        grow(layout.size() as isize);
        // SAFETY: forwarded with the caller's layout.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        grow(-(layout.size() as isize));
        // SAFETY: `ptr` was allocated by `System` with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.with(|c| c.set(c.get() + 1));
        grow(new_size as isize - layout.size() as isize);
        // SAFETY: forwarded unchanged.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

/// Steps `radau` 200 times after 5 warm-up steps and returns the allocations during the 200.
fn allocations_in_steps<M: LagrangeDirac>(model: &M, start: &State<M>, t_end: f64) -> usize
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut radau = Radau::new(model, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid options");
    radau.start(0.0, start, t_end).expect("starts");
    for _ in 0..5 {
        radau.step().expect("steps");
    }
    let before = allocations();
    for _ in 0..200 {
        if radau.finished() {
            break;
        }
        radau.step().expect("steps");
    }
    allocations() - before
}

#[test]
fn radau_steps_do_not_allocate() {
    let p = unit_pendulum();
    let s = horizontal_start(&p);
    assert_eq!(allocations_in_steps(&p, &s, 100.0), 0, "pendulum");

    let chain = paper_chain();
    let s = paper_chain_start(&chain);
    assert_eq!(allocations_in_steps(&chain, &s, 100.0), 0, "interconnected chain");

    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let v = VecQ::<RollingDisk>::new(0.6, 0.0, 2.0, 1.0);
    let s = consistent_state(&disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
        .expect("consistent");
    assert_eq!(allocations_in_steps(&disk, &s, 100.0), 0, "rolling disk");

    // The counter does count: a heap allocation on this thread is seen.
    let before = allocations();
    let boxed = std::hint::black_box(Box::new([0u8; 64]));
    drop(boxed);
    assert_eq!(allocations() - before, 1);
}

/// The allocations of a whole `solve_with_progress` (reports every step) to `t_end`, sampled at
/// the end only, with `integrator`, and the number of reports.
fn allocations_with_progress<I: Integrator<Pendulum>>(
    integrator: &mut I,
    start: &State<Pendulum>,
    t_end: f64,
) -> (usize, usize) {
    let sampling = Sampling::Times(vec![t_end]);
    let mut reports = 0;
    let before = allocations();
    let solution = integrator
        .solve_with_progress(0.0, start, t_end, &sampling, std::time::Duration::ZERO, |progress| {
            reports += 1;
            std::hint::black_box(progress.fraction());
        })
        .expect("solves");
    let counted = allocations() - before;
    drop(solution);
    (counted, reports)
}

/// Progress reported after every step costs no allocation per step: a run ten times as long,
/// with ten times the reports, allocates as often (the solution's storage and the start's).
#[test]
fn progress_reports_do_not_allocate() {
    let p = unit_pendulum();
    let s = horizontal_start(&p);
    let mut radau = Radau::new(&p, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid options");
    allocations_with_progress(&mut radau, &s, 1.0);
    let (short, few) = allocations_with_progress(&mut radau, &s, 1.0);
    let (long, many) = allocations_with_progress(&mut radau, &s, 10.0);
    assert!(many > 5 * few, "{few} and {many} reports");
    assert_eq!(short, long, "Radau: {few} reports with {short} allocations, {many} with {long}");

    let mut explicit = Explicit::new(&p, ExplicitOptions::default()).expect("valid options");
    allocations_with_progress(&mut explicit, &s, 1.0);
    let (short, few) = allocations_with_progress(&mut explicit, &s, 1.0);
    let (long, many) = allocations_with_progress(&mut explicit, &s, 10.0);
    assert!(many > 5 * few, "{few} and {many} reports");
    assert_eq!(short, long, "explicit: {few} reports with {short} allocations, {many} with {long}");
}

/// Steps the variational integrator 200 times after 5 warm-up steps; allocations during them.
fn allocations_in_variational_steps<M: LagrangeDirac>(
    model: &M,
    start: &State<M>,
    options: VariationalOptions,
) -> usize
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut vi = Variational::new(model, 0.01, options).expect("valid options");
    vi.start(0.0, start, 100.0).expect("starts");
    for _ in 0..5 {
        vi.step().expect("steps");
    }
    let before = allocations();
    for _ in 0..200 {
        vi.step().expect("steps");
    }
    allocations() - before
}

#[test]
fn variational_steps_do_not_allocate() {
    let general = VariationalOptions { use_structure: false, ..VariationalOptions::default() };
    let p = unit_pendulum();
    let s = horizontal_start(&p);
    assert_eq!(
        allocations_in_variational_steps(&p, &s, VariationalOptions::default()),
        0,
        "pendulum, separable path"
    );
    assert_eq!(allocations_in_variational_steps(&p, &s, general), 0, "pendulum, general path");

    let chain = paper_chain();
    let s = paper_chain_start(&chain);
    assert_eq!(
        allocations_in_variational_steps(&chain, &s, VariationalOptions::default()),
        0,
        "interconnected chain"
    );
}

/// Velocities no inertia fixes but the forces do (the motor's current): Explicit settles them
/// at every stage and in its dense output, the variational step at its end, Radau needs
/// nothing more. The recorder's dissipated power is an output like any other.
#[test]
fn steps_with_velocities_fixed_by_forces_do_not_allocate() {
    let motor = AcMotor { r: 1.5, k: 0.8, j: 0.2, b: 0.1, u0: 12.0, om: 3.0 };
    let s = consistent_state(
        &motor,
        0.0,
        &VecQ::<AcMotor>::zeros(),
        &VecQ::<AcMotor>::zeros(),
        Consistency::default(),
    )
    .expect("consistent");
    assert_eq!(allocations_in_steps(&motor, &s, 100.0), 0, "Radau");
    assert_eq!(allocations_in_explicit_steps(&motor, &s, 100.0), 0, "Explicit");
    let general = VariationalOptions { use_structure: false, ..VariationalOptions::default() };
    assert_eq!(allocations_in_variational_steps(&motor, &s, VariationalOptions::default()), 0, "Variational");
    assert_eq!(allocations_in_variational_steps(&motor, &s, general), 0, "Variational, general path");
}

/// Switching surfaces located and the integration restarted at each, as a plain solve does,
/// under the three integrators: neither the search nor the restart allocates.
#[test]
fn restarting_at_switching_surfaces_does_not_allocate() {
    let servo = SaturatedServo { m: 1.0, kp: 4.0, kd: 1.5, r: 1.0, fmax: 1.0 };
    let start = State::<SaturatedServo>::zeros();
    fn run<I: Integrator<SaturatedServo>>(
        mut integrator: I,
        start: &State<SaturatedServo>,
    ) -> (usize, usize) {
        let mut events = dirac::Events::new().switches();
        integrator.start(0.0, start, 6.0).expect("starts");
        events.begin(integrator.model(), 0.0, start).expect("begins");
        let mut at = start.clone();
        let before = allocations();
        let mut switches = 0;
        while !integrator.finished() {
            integrator.step().expect("steps");
            while let Some(event) = events.locate(&mut integrator).expect("locates") {
                switches += 1;
                at.clone_from(events.state());
                integrator.restart_at(event.t, &at).expect("restarts");
                events.resume(integrator.model(), event.t, &at).expect("resumes");
            }
        }
        (allocations() - before, switches)
    }
    let radau = Radau::new(&servo, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let explicit = Explicit::new(&servo, ExplicitOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let variational = Variational::new(&servo, 1e-3, VariationalOptions::default()).expect("valid");
    for (name, (allocated, switches)) in [
        ("Radau", run(radau, &start)),
        ("Explicit", run(explicit, &start)),
        ("Variational", run(variational, &start)),
    ] {
        assert_eq!(allocated, 0, "{name}");
        assert!(switches >= 3, "{name}: {switches} switches located");
    }
}

/// A friction law watched as a plain solve watches it (`Events::switches`): the steps, the
/// search for its events and the sampling of its engage function within each step allocate
/// nothing, under the three integrators, up to the first switch (the slip from rest stops at
/// `t₁ = asin(vb/(ω x_e))/ω`, `x_e = μk N/k`). (The switch itself projects the state onto the
/// new mode on the heap, once per switch, as a reset does.)
#[test]
fn watching_friction_laws_does_not_allocate() {
    let belt = FrictionBelt { m: 1.0, k: 4.0, vb: 0.5, n: 9.81, mu_s: 0.4, mu_k: 0.25 };
    let zero = VecQ::<FrictionBelt>::zeros();
    let start = dirac::consistent_state(&belt, 0.0, &zero, &zero, Default::default()).expect("slipping");
    let t1 = (0.5f64 / (2.0 * 0.25 * 9.81 / 4.0)).asin() / 2.0;
    let radau = Radau::new(&belt, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let explicit = Explicit::new(&belt, ExplicitOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let variational = Variational::new(&belt, 1e-3, VariationalOptions::default()).expect("valid");
    for (name, (allocated, stops)) in [
        ("Radau", to_the_first_switch(radau, &start, "grip_stops")),
        ("Explicit", to_the_first_switch(explicit, &start, "grip_stops")),
        ("Variational", to_the_first_switch(variational, &start, "grip_stops")),
    ] {
        assert_eq!(allocated, 0, "{name}");
        let stops = stops.expect("the slip stops");
        assert!((stops - t1).abs() < 1e-6, "{name}: stops at {stops}, closed form {t1}");
    }
}

/// Friction on a contact force (`kinetic = mu * floor`): the steps of every integrator read
/// the slip rows `B − A` beside the constraint rows, and the stop is located, without
/// allocating. The block slides on the flat from 3 m/s and stops at `v0 / (μ g)` = 0.76 s.
#[test]
fn stepping_friction_on_a_contact_force_does_not_allocate() {
    let block = SlopeBlock { m: 2.0, g: 9.81, slope: 0.0, mu: 0.4, push: 0.0 };
    let mut v = VecQ::<SlopeBlock>::zeros();
    v[SlopeBlock::X.index()] = 3.0;
    let start = dirac::consistent_state(&block, 0.0, &VecQ::<SlopeBlock>::zeros(), &v, Default::default())
        .expect("slipping");
    let radau = Radau::new(&block, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let explicit = Explicit::new(&block, ExplicitOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let variational = Variational::new(&block, 1e-3, VariationalOptions::default()).expect("valid");
    for (name, (allocated, stops)) in [
        ("Radau", to_the_first_switch(radau, &start, "slide_stops")),
        ("Explicit", to_the_first_switch(explicit, &start, "slide_stops")),
        ("Variational", to_the_first_switch(variational, &start, "slide_stops")),
    ] {
        assert_eq!(allocated, 0, "{name}");
        let stops = stops.expect("the slip stops");
        assert!((stops - 3.0 / (0.4 * 9.81)).abs() < 1e-6, "{name}: stops at {stops}");
    }
}

/// Steps `integrator` from `start` until its laws' first switch, which must be the event
/// `expected`: the allocations in the steps and the location, and the switch's time.
fn to_the_first_switch<M: dirac::Hybrid, I: Integrator<M>>(
    mut integrator: I,
    start: &State<M>,
    expected: &str,
) -> (usize, Option<f64>)
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut events = dirac::Events::new().switches();
    integrator.start(0.0, start, 1.0).expect("starts");
    events.begin(integrator.model(), 0.0, start).expect("begins");
    let before = allocations();
    while !integrator.finished() {
        integrator.step().expect("steps");
        if let Some(event) = events.locate(&mut integrator).expect("locates") {
            assert_eq!(events.name(&event), expected);
            return (allocations() - before, Some(event.t));
        }
    }
    (allocations() - before, None)
}

/// A friction cone on a contact force (its slip rows turn with the velocity, so each
/// variational step evaluates them at the step's velocity): a puck thrown along 0.5 rad steps to
/// its stop without allocating, under every integrator.
#[test]
fn stepping_a_friction_cone_does_not_allocate() {
    use crate::zoo::Puck;
    let puck = Puck { m: 2.0, g: 9.81, mu: 0.4, push: 0.0, angle: 0.0, side: 0.0 };
    let mut v = VecQ::<Puck>::zeros();
    v[Puck::X.index()] = 3.0 * 0.5f64.cos();
    v[Puck::Y.index()] = 3.0 * 0.5f64.sin();
    let start = dirac::consistent_state(&puck, 0.0, &VecQ::<Puck>::zeros(), &v, Default::default())
        .expect("slipping");
    let radau = Radau::new(&puck, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let explicit = Explicit::new(&puck, ExplicitOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let variational = Variational::new(&puck, 1e-3, VariationalOptions::default()).expect("valid");
    for (name, (allocated, stops)) in [
        ("Radau", to_the_first_switch(radau, &start, "slip_stops")),
        ("Explicit", to_the_first_switch(explicit, &start, "slip_stops")),
        ("Variational", to_the_first_switch(variational, &start, "slip_stops")),
    ] {
        assert_eq!(allocated, 0, "{name}");
        let stops = stops.expect("the slip stops");
        assert!((stops - 3.0 / (0.4 * 9.81)).abs() < 1e-6, "{name}: stops at {stops}");
    }
}

/// A friction cone at a contact that rests (the URDF ball's `ground(friction = mu)`, its rows
/// and events on only while the contact is closed): the ball slides to its roll without
/// allocating, under every integrator.
#[test]
fn stepping_a_cone_at_a_resting_contact_does_not_allocate() {
    use crate::zoo::robots::{RollingBall, RollingBallWithContacts};
    let mut ball = RollingBall { mu: 0.3 }.with_contacts();
    assert!(ball.set_contact_closed(0, true));
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mut start = State::<RollingBallWithContacts>::zeros();
    start.place_free_body("root_joint", [0.0, 0.0, 0.1], identity, [2.0, 0.0, 0.0], [0.0; 3]).expect("free");
    let start = dirac::consistent_state(&ball, 0.0, &start.q, &start.v, Default::default()).expect("sliding");
    let radau = Radau::new(&ball, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let explicit = Explicit::new(&ball, ExplicitOptions::tolerances(1e-10, 1e-10)).expect("valid");
    let variational = Variational::new(&ball, 1e-3, VariationalOptions::default()).expect("valid");
    let rolls = 2.0 * 2.0 / (7.0 * 0.3 * 9.81);
    for (name, (allocated, stops)) in [
        ("Radau", to_the_first_switch(radau, &start, "ball_ground_slip_stops")),
        ("Explicit", to_the_first_switch(explicit, &start, "ball_ground_slip_stops")),
        ("Variational", to_the_first_switch(variational, &start, "ball_ground_slip_stops")),
    ] {
        assert_eq!(allocated, 0, "{name}");
        let stops = stops.expect("the slip stops");
        assert!((stops - rolls).abs() < 1e-6, "{name}: rolls from {stops}");
    }
}

/// The sparse path: a model made of an array of 200 cells, stored sparse and factored by a
/// sparse LU, under both integrators.
/// Steps the explicit integrator 200 times after 5 warm-up steps, reading the state within
/// each step as a recorder does, and returns the allocations during the 200.
fn allocations_in_explicit_steps<M: LagrangeDirac>(model: &M, start: &State<M>, t_end: f64) -> usize
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut explicit =
        Explicit::new(model, ExplicitOptions::tolerances(1e-10, 1e-10)).expect("valid options");
    explicit.start(0.0, start, t_end).expect("starts");
    for _ in 0..5 {
        explicit.step().expect("steps");
    }
    let mut within = start.clone();
    let before = allocations();
    for _ in 0..200 {
        if explicit.finished() {
            break;
        }
        let h = explicit.step().expect("steps");
        explicit.interpolate(explicit.t() - 0.5 * h, &mut within);
    }
    allocations() - before
}

/// Holonomic (the pendulum, on the separable m × m path, and the 8-link pendulum, on the
/// saddle-point path), nonholonomic (the rolling disk), interconnected and degenerate (the
/// paper's chain) and array models (the LC ladder, sparse).
/// Redundant rows (the Bennett linkage's five cut rows on three angles): every method's
/// deflated factorisations, their projections of right-hand sides and Radau's return of the
/// multipliers to least norm work in place.
#[test]
fn steps_of_models_with_redundant_rows_do_not_allocate() {
    let (model, start) = crate::redundant::bennett_start();
    // Radau with its projection, which rows redundant only on the loop need (off it they
    // contradict each other).
    let options = RadauOptions { projection: true, ..RadauOptions::tolerances(1e-10, 1e-10) };
    let mut radau = Radau::new(&model, options).expect("valid options");
    radau.start(0.0, &start, 100.0).expect("starts");
    for _ in 0..5 {
        radau.step().expect("steps");
    }
    let before = allocations();
    for _ in 0..200 {
        radau.step().expect("steps");
    }
    assert_eq!(allocations() - before, 0, "Radau");
    assert_eq!(allocations_in_explicit_steps(&model, &start, 100.0), 0, "Explicit");
    assert_eq!(
        allocations_in_variational_steps(&model, &start, VariationalOptions::default()),
        0,
        "separable"
    );
    let general = VariationalOptions { use_structure: false, ..VariationalOptions::default() };
    assert_eq!(allocations_in_variational_steps(&model, &start, general), 0, "general");
}

#[test]
fn explicit_steps_do_not_allocate() {
    let p = unit_pendulum();
    assert_eq!(allocations_in_explicit_steps(&p, &horizontal_start(&p), 100.0), 0, "pendulum");
    let chain = paper_chain();
    assert_eq!(allocations_in_explicit_steps(&chain, &paper_chain_start(&chain), 100.0), 0, "chain");
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let v = VecQ::<RollingDisk>::from([0.6, 0.0, 2.0, 1.0]);
    let s = consistent_state(&disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
        .expect("consistent");
    assert_eq!(allocations_in_explicit_steps(&disk, &s, 100.0), 0, "rolling disk");
    let eight = Pendulum8 { m: 0.5, l: 0.25, g: 9.81 };
    let q = VecQ::<Pendulum8>::from_fn(|i, _| 0.3 + 0.05 * i as f64);
    let s = consistent_state(&eight, 0.0, &q, &VecQ::<Pendulum8>::zeros(), Consistency::default())
        .expect("consistent");
    assert_eq!(allocations_in_explicit_steps(&eight, &s, 100.0), 0, "8-link pendulum");
    let ladder = unit_ladder(50);
    let x: Vec<f64> = (0..50).map(|j| (-((j as f64 - 20.0) / 5.0).powi(2)).exp()).collect();
    assert_eq!(allocations_in_explicit_steps(&ladder, &ladder_at_rest(&ladder, &x), 100.0), 0, "ladder");
}

#[test]
fn steps_of_models_made_of_arrays_do_not_allocate() {
    let ladder = unit_ladder(200);
    let x: Vec<f64> = (0..200).map(|j| (-((j as f64 - 60.0) / 5.0).powi(2)).exp()).collect();
    let s = ladder_at_rest(&ladder, &x);
    assert_eq!(allocations_in_steps(&ladder, &s, 100.0), 0, "Radau, ladder");
    assert_eq!(
        allocations_in_variational_steps(&ladder, &s, VariationalOptions::default()),
        0,
        "variational, ladder"
    );
}

/// Inputs set between steps: each `set_input` restarts the integrator (checks, new Jacobian,
/// new grid); a 100-step feedback loop on the forced spring and on the composite of two, with
/// each integrator, allocates nothing.
fn allocations_with_inputs<M: InputsOutputs, I: Integrator<M>>(
    integrator: &mut I,
    start: &State<M>,
    input: Input<M>,
) -> usize
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    integrator.start(0.0, start, 100.0).expect("starts");
    for _ in 0..5 {
        integrator.step().expect("steps");
    }
    let before = allocations();
    for _ in 0..100 {
        let x = integrator.state().q[0];
        integrator.set_input(input, -3.0 * x).expect("an exclusive model");
        integrator.step().expect("steps");
    }
    allocations() - before
}

#[test]
fn steps_with_inputs_set_between_them_do_not_allocate() {
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let q = VecQ::<ForcedSpring>::from([1.0]);
    let s = consistent_state(&spring, 0.0, &q, &VecQ::<ForcedSpring>::zeros(), Consistency::default())
        .expect("consistent");
    let mut radau = Radau::new(&mut spring, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    assert_eq!(allocations_with_inputs(&mut radau, &s, ForcedSpring::F), 0, "Radau, spring");
    let mut vi = Variational::new(&mut spring, 0.01, VariationalOptions::default()).expect("valid");
    assert_eq!(allocations_with_inputs(&mut vi, &s, ForcedSpring::F), 0, "variational, spring");
    let mut explicit = Explicit::new(&mut spring, ExplicitOptions::default()).expect("valid");
    assert_eq!(allocations_with_inputs(&mut explicit, &s, ForcedSpring::F), 0, "explicit, spring");

    let spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let mut pair = ForcedPair { left: spring.clone(), right: spring };
    let q = VecQ::<ForcedPair>::from([1.0, 1.0]);
    let s = consistent_state(&pair, 0.0, &q, &VecQ::<ForcedPair>::zeros(), Consistency::default())
        .expect("consistent");
    let right_f = ForcedPair::right_input(ForcedSpring::F);
    let mut radau = Radau::new(&mut pair, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    assert_eq!(allocations_with_inputs(&mut radau, &s, right_f), 0, "Radau, composite");
    let mut vi = Variational::new(&mut pair, 0.01, VariationalOptions::default()).expect("valid");
    assert_eq!(allocations_with_inputs(&mut vi, &s, right_f), 0, "variational, composite");
}

/// Inputs driven inside the steps: a source of time and a continuous feedback with its
/// finite-difference Jacobian, on Radau.
#[test]
fn steps_with_driven_inputs_do_not_allocate() {
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let q = VecQ::<ForcedSpring>::from([1.0]);
    let s = consistent_state(&spring, 0.0, &q, &VecQ::<ForcedSpring>::zeros(), Consistency::default())
        .expect("consistent");
    let mut law = |t: f64, state: &State<ForcedSpring>, model: &mut ForcedSpring| {
        model.f = 0.3 * t.sin() - 5.0 * state.q[0] - 0.8 * state.v[0];
    };
    let mut law_jacobian =
        |_: f64, _: &State<ForcedSpring>, out: &mut [f64]| out.copy_from_slice(&[-5.0, -0.8]);
    for given in [false, true] {
        let mut radau = Radau::new(&mut spring, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
        if given {
            radau.drive_feedback_with(&mut law, &mut law_jacobian).expect("a dense model");
        } else {
            radau.drive_feedback(&mut law).expect("a dense model");
        }
        radau.start(0.0, &s, 100.0).expect("starts");
        for _ in 0..5 {
            radau.step().expect("steps");
        }
        let before = allocations();
        for _ in 0..200 {
            radau.step().expect("steps");
        }
        assert_eq!(allocations() - before, 0, "feedback Jacobian given: {given}");
    }
}

/// A series RLC made of library parts, its source's voltage an input that prescribes a velocity.
#[derive(Interconnection, Clone, Debug)]
#[dirac(
    connect(source.p, r.p),
    connect(r.n, l.p),
    connect(l.n, c.p),
    connect(c.n, ground.p),
    connect(source.n, ground.p)
)]
struct TableRlc {
    source: dirac::components::electrical::VoltageSource,
    r: dirac::components::electrical::Resistor,
    l: dirac::components::electrical::Inductor,
    c: dirac::components::electrical::Capacitor,
    ground: dirac::components::electrical::Ground,
}

/// Inputs driven from tables, held and interpolated, with the steps ending at every sample
/// (a stop every 0.05 s): each method, through many stops, where the velocity the source
/// prescribes jumps (held) or moves (interpolated).
#[test]
fn steps_driven_from_tables_through_stops_do_not_allocate() {
    use dirac::components::electrical::{Capacitor, Ground, Inductor, Resistor, VoltageSource};
    use dirac::sources::{Hold, Table};
    fn run<'m, I: Integrator<TableRlc> + Drive<'m, TableRlc>>(
        mut integrator: I,
        source: &'m mut dyn FnMut(f64, &State<TableRlc>, &mut TableRlc),
        table: &Table,
        start: &State<TableRlc>,
    ) -> usize {
        integrator.drive(source).expect("exclusive");
        integrator.stop_at(table.times()).expect("finite");
        integrator.start(0.0, start, 100.0).expect("starts");
        for _ in 0..5 {
            integrator.step().expect("steps");
        }
        let mut within = start.clone();
        let before = allocations();
        for _ in 0..400 {
            let h = integrator.step().expect("steps");
            integrator.interpolate(integrator.t() - 0.5 * h, &mut within);
        }
        assert!(integrator.t() > 1.0, "through stops: {}", integrator.t());
        allocations() - before
    }
    for hold in [Hold::Zero, Hold::Linear] {
        let times: Vec<f64> = (0..2000).map(|k| 0.05 * k as f64).collect();
        let volts: Vec<f64> = times.iter().map(|t| (3.0 * t).sin()).collect();
        let table = Table::new(times, volts, hold).expect("valid");
        let mut rlc = TableRlc {
            source: VoltageSource { u: 0.0 },
            r: Resistor { r: 0.5 },
            l: Inductor { l: 1.0 },
            c: Capacitor { c: 1.0 },
            ground: Ground {},
        };
        let zero = VecQ::<TableRlc>::zeros();
        let start = consistent_state(&rlc, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
        let u = TableRlc::source_input(VoltageSource::U);
        let mut source = |t: f64, _: &State<TableRlc>, m: &mut TableRlc| m.set_input(u, table.at(t));
        let radau = Radau::new(&mut rlc, RadauOptions::tolerances(1e-8, 1e-10)).expect("valid");
        assert_eq!(run(radau, &mut source, &table, &start), 0, "Radau, {hold:?}");
        let explicit = Explicit::new(&mut rlc, ExplicitOptions::tolerances(1e-8, 1e-10)).expect("valid");
        assert_eq!(run(explicit, &mut source, &table, &start), 0, "Explicit, {hold:?}");
        let variational = Variational::new(&mut rlc, 1e-2, VariationalOptions::default()).expect("valid");
        assert_eq!(run(variational, &mut source, &table, &start), 0, "Variational, {hold:?}");
    }
}

/// Prescribed motion: constraints that depend on time (holonomic and affine velocity rows, in
/// a primitive and in an interconnection, and an array of them) under both integrators, with
/// Radau projecting after each step.
#[test]
fn steps_with_prescribed_motion_do_not_allocate() {
    let general = VariationalOptions { use_structure: false, ..VariationalOptions::default() };
    let crank = SliderCrank { m1: 1.0, m2: 2.0, m3: 0.5, r: 0.3, l: 1.0, g: 9.81, c: 0.8, w: 6.0 };
    let q = VecQ::<SliderCrank>::new(0.0, 0.0, 1.3);
    let s = consistent_state(&crank, 0.0, &q, &VecQ::<SliderCrank>::zeros(), Consistency::default())
        .expect("consistent");
    assert_eq!(allocations_in_steps(&crank, &s, 100.0), 0, "Radau, slider crank");
    assert_eq!(allocations_in_variational_steps(&crank, &s, general), 0, "variational, slider crank");
    let mut radau =
        Radau::new(&crank, RadauOptions { projection: true, ..RadauOptions::tolerances(1e-10, 1e-10) })
            .expect("valid options");
    radau.start(0.0, &s, 100.0).expect("starts");
    radau.step().expect("steps");
    let before = allocations();
    for _ in 0..200 {
        radau.step().expect("steps");
    }
    assert_eq!(allocations() - before, 0, "Radau with projection, slider crank");

    let bead = BeadOnRod { m: 1.0, w: 0.2 };
    let q = VecQ::<BeadOnRod>::new(1.0, 0.0);
    let s = consistent_state(&bead, 0.0, &q, &VecQ::<BeadOnRod>::zeros(), Consistency::default())
        .expect("consistent");
    assert_eq!(
        allocations_in_variational_steps(&bead, &s, VariationalOptions::default()),
        0,
        "variational, bead on a rod, separable path"
    );

    let disk = DiskOnBelt { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045, belt: 0.5 };
    let v = VecQ::<DiskOnBelt>::new(1.1, 0.0, 2.0, 1.0);
    let s = consistent_state(&disk, 0.0, &VecQ::<DiskOnBelt>::zeros(), &v, Consistency::default())
        .expect("consistent");
    assert_eq!(allocations_in_steps(&disk, &s, 100.0), 0, "Radau, disk on a belt");
    assert_eq!(
        allocations_in_variational_steps(&disk, &s, VariationalOptions::default()),
        0,
        "variational, disk on a belt"
    );

    let pair = ShakenPair { left: FreeMass { m: 1.0 }, right: FreeMass { m: 3.0 }, a: 0.2, w: 4.0 };
    let q = VecQ::<ShakenPair>::new(0.0, 1.0);
    let s = consistent_state(&pair, 0.0, &q, &VecQ::<ShakenPair>::zeros(), Consistency::default())
        .expect("consistent");
    assert_eq!(allocations_in_steps(&pair, &s, 100.0), 0, "Radau, shaken pair");

    let row = ShakenRow { cells: (0..50).map(|_| FreeMass { m: 1.0 }).collect(), a: 0.1, w: 3.0 };
    let q = VecQ::<ShakenRow>::from_fn(50, |i, _| i as f64);
    let s = consistent_state(&row, 0.0, &q, &VecQ::<ShakenRow>::zeros(50), Consistency::default())
        .expect("consistent");
    assert_eq!(allocations_in_steps(&row, &s, 100.0), 0, "Radau, shaken row of 50");
    assert_eq!(
        allocations_in_variational_steps(&row, &s, VariationalOptions::default()),
        0,
        "variational, shaken row of 50"
    );
}

/// Steps `integrator` from `start` and locates the crossings of `x = 0` and `v = 0` after each
/// step (every kind: several per period), returning the allocations after set-up and the
/// number of events located.
fn allocations_locating_events<I: Integrator<Oscillator>>(
    mut integrator: I,
    start: &State<Oscillator>,
) -> (usize, usize) {
    let mut events = dirac::Events::new()
        .on("x", dirac::Crossing::Either, |_, s: &State<Oscillator>, _| s.q(Oscillator::X))
        .on("v", dirac::Crossing::Falling, |_, s: &State<Oscillator>, _| s.v(Oscillator::X));
    integrator.start(0.0, start, 40.0).expect("starts");
    events.begin(integrator.model(), 0.0, start).expect("begins");
    let before = allocations();
    let mut located = 0;
    while !integrator.finished() {
        integrator.step().expect("steps");
        while let Some(event) = events.locate(&mut integrator).expect("locates") {
            located += 1;
            assert!(event.t <= integrator.t());
        }
    }
    (allocations() - before, located)
}

#[test]
fn locating_events_does_not_allocate() {
    let model = Oscillator { m: 1.0, k: 1.0 };
    let mut start = State::<Oscillator>::zeros();
    start.set_q(Oscillator::X, 1.0);
    let radau = Radau::new(&model, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid options");
    let (allocations, located) = allocations_locating_events(radau, &start);
    assert_eq!(allocations, 0, "Radau with events");
    // x = cos t over 40: 13 zeros of x, 6 falling zeros of v (at t = 2kπ, k ≥ 1).
    assert_eq!(located, 13 + 6);
    let variational = Variational::new(&model, 1e-2, VariationalOptions::default()).expect("valid step");
    let (allocations, located) = allocations_locating_events(variational, &start);
    assert_eq!(allocations, 0, "variational with events");
    assert_eq!(located, 13 + 6);
    let explicit = Explicit::new(&model, ExplicitOptions::tolerances(1e-10, 1e-10)).expect("valid options");
    let (allocations, located) = allocations_locating_events(explicit, &start);
    assert_eq!(allocations, 0, "explicit with events");
    assert_eq!(located, 13 + 6);
}

/// Location on a driven input sets the inputs at every time it evaluates at: the drive's
/// calls allocate nothing either.
#[test]
fn locating_events_on_driven_inputs_does_not_allocate() {
    let mut spring = ForcedSpring { m: 1.0, k: 4.0, f: 0.0 };
    let start = State::<ForcedSpring>::zeros();
    let mut source = |t: f64, _: &State<ForcedSpring>, m: &mut ForcedSpring| m.f = (1.3 * t).sin();
    let mut events = dirac::Events::new().on(
        "half",
        dirac::Crossing::Either,
        |_, _: &State<ForcedSpring>, m: &ForcedSpring| m.f - 0.5,
    );
    let mut radau = Radau::new(&mut spring, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid options");
    radau.drive(&mut source).expect("held exclusively");
    radau.start(0.0, &start, 20.0).expect("starts");
    events.begin(radau.model(), 0.0, &start).expect("begins");
    let before = allocations();
    let mut located = 0;
    while !radau.finished() {
        radau.step().expect("steps");
        while events.locate(&mut radau).expect("locates").is_some() {
            located += 1;
        }
    }
    assert_eq!(allocations() - before, 0);
    // sin(1.3 t) = ½ twice per period 2π/1.3 over 20: at 0.40 + 4.83 k and 2.01 + 4.83 k.
    assert_eq!(located, 9);
}

/// An elastic wall at `x = ½` for the oscillator, handled by hand: the velocity reversed at
/// each impact and the integrator restarted there, on its grid. The variational integrator
/// takes a step of its own to each trial time (its discrete flow); neither that nor the
/// restart allocates.
#[test]
fn restarting_at_impacts_does_not_allocate() {
    let model = Oscillator { m: 1.0, k: 1.0 };
    // x = sin t until the wall.
    let mut start = State::<Oscillator>::zeros();
    start.set_v(Oscillator::X, 1.0).set_p(Oscillator::X, 1.0);
    let mut events =
        dirac::Events::new()
            .on("wall", dirac::Crossing::Falling, |_, s: &State<Oscillator>, _| 0.5 - s.q(Oscillator::X));
    let mut variational = Variational::new(&model, 1e-2, VariationalOptions::default()).expect("valid step");
    variational.start(0.0, &start, 40.0).expect("starts");
    let mut reflected = start.clone();
    events.begin(variational.model(), 0.0, &start).expect("begins");
    let before = allocations();
    let mut impacts = 0;
    while !variational.finished() {
        variational.step().expect("steps");
        while let Some(event) = events.locate(&mut variational).expect("locates") {
            impacts += 1;
            reflected.clone_from(events.state());
            let (v, p) = (reflected.v(Oscillator::X), reflected.p(Oscillator::X));
            reflected.set_v(Oscillator::X, -v).set_p(Oscillator::X, -p);
            variational.restart_at(event.t, &reflected).expect("restarts");
            events.resume(variational.model(), event.t, &reflected).expect("resumes");
        }
    }
    assert_eq!(allocations() - before, 0);
    // x = sin t reaches the wall at π/6; reflected there, it comes back after the rest of its
    // period, 2π − 2π/3: 10 impacts by t = 40.
    let period = 4.0 * std::f64::consts::FRAC_PI_3;
    assert_eq!(impacts, ((40.0 - std::f64::consts::FRAC_PI_6) / period).floor() as usize + 1);
}

/// The event functions of declared contacts evaluate the model's unilateral constraints into
/// storage made when they are added: watching them allocates nothing. (The impact law at an
/// event solves a small system on the heap, once per impact, as a reset does.)
#[test]
fn watching_contacts_does_not_allocate() {
    let ball = BouncingBall { m: 1.0, g: 9.81, e: 0.5 };
    let mut start = State::<BouncingBall>::zeros();
    start.set_q(BouncingBall::Y, 1.0);
    let mut events = dirac::Events::new().contacts(&ball);
    let mut radau = Radau::new(&ball, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid options");
    radau.start(0.0, &start, 1.0).expect("starts");
    events.begin(radau.model(), 0.0, &start).expect("begins");
    let mut located = Vec::with_capacity(4);
    let before = allocations();
    // Up to the touchdown (past it, without the impact that `solve_with_events` applies, the
    // contact would close).
    while !radau.finished() && located.is_empty() {
        radau.step().expect("steps");
        if let Some(event) = events.locate(&mut radau).expect("locates") {
            located.push(event.t);
        }
    }
    assert_eq!(allocations() - before, 0);
    // The touchdown at √(2 h / g).
    assert_eq!(located.len(), 1);
    assert!((located[0] - (2.0 / 9.81f64).sqrt()).abs() < 1e-10);
}

/// A solve with forward sensitivities through impacts, switching surfaces or laws' switches
/// allocates per crossing (the saltation matrix's small dense systems) and per sample, never
/// per step: at two tolerances, which take different numbers of steps through the same
/// crossings to the same samples, it allocates as often.
#[test]
fn sensitivity_steps_through_impacts_and_switches_do_not_allocate() {
    // Pulled by a sine, so that its flight is not a parabola, which Radau would solve exactly
    // at any tolerance.
    let ball = LiftedBall { m: 1.0, g: 9.81, e: 0.8, f0: 3.0, om: 5.0 };
    let mut start = State::<LiftedBall>::zeros();
    start.set_q(LiftedBall::Y, 1.0);
    let wrt = Sensitivities::all_parameters(&ball).initial_position(LiftedBall::Y);
    let crossings = allocations_through_crossings(&ball, &start, &wrt);
    assert!(crossings >= 2, "{crossings} impacts");
    // Coulomb friction and a brake past a point: switching surfaces on a velocity and a position.
    let spring = CoulombSpring { m: 1.0, k: 4.0, mu: 0.05, a: 0.1, f: 0.2 };
    let mut start = State::<CoulombSpring>::zeros();
    (start.v[0], start.p[0]) = (1.0, 1.0);
    let wrt = Sensitivities::all_parameters(&spring).initial_velocity(CoulombSpring::X);
    let crossings = allocations_through_crossings(&spring, &start, &wrt);
    assert!(crossings >= 3, "{crossings} crossings");
    // A friction law that sticks (at t = 0.46) and slips again (at t = 1.21, where its force,
    // a multiplier, reaches its bound).
    let belt = FrictionBelt { m: 1.0, k: 4.0, vb: 0.2, n: 2.0, mu_s: 0.4, mu_k: 0.25 };
    let wrt = Sensitivities::all_parameters(&belt).initial_position(FrictionBelt::X);
    let switches = allocations_through_crossings(&belt, &State::<FrictionBelt>::zeros(), &wrt);
    assert!(switches >= 2, "{switches} switches");
}

/// Runs `model` from `start` to `t = 2` with the sensitivities `wrt` at a loose and a tight
/// tolerance and asserts that both allocate as often; the number of crossings (impacts and
/// events).
fn allocations_through_crossings<M: Parameters + dirac::Hybrid>(
    model: &M,
    start: &State<M>,
    wrt: &Sensitivities<M>,
) -> usize
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let run = |tolerance: f64| {
        let before = allocations();
        let solution = Radau::new(model, RadauOptions::tolerances(tolerance, tolerance))
            .expect("valid options")
            .with_sensitivities(wrt)
            .expect("valid")
            .solve_with_sensitivities(0.0, start, 2.0, &Sampling::Times(vec![0.5, 1.0, 1.5, 2.0]))
            .expect("integrates");
        let allocated = allocations() - before;
        (allocated, solution.stats.steps, solution.impacts().len() + solution.events().len())
    };
    // A first run makes what the process keeps from then on.
    run(1e-11);
    let (loose, few, crossings) = run(1e-6);
    let (tight, many, same) = run(1e-11);
    assert_eq!(crossings, same);
    assert!(many > few + 20, "{few} and {many} steps");
    assert_eq!(loose, tight, "{few} steps allocate {loose} times, {many} steps {tight} times");
    crossings
}

/// An adjoint sweep back through impacts, switching surfaces or laws' switches allocates per
/// crossing (the transposed jump's small dense products), never per backward step: sweeps over
/// runs at two tolerances, with different numbers of steps through the same crossings,
/// allocate as often.
#[test]
fn backward_steps_through_impacts_and_switches_do_not_allocate() {
    let ball = LiftedBall { m: 1.0, g: 9.81, e: 0.8, f0: 3.0, om: 5.0 };
    let mut start = State::<LiftedBall>::zeros();
    start.set_q(LiftedBall::Y, 1.0);
    sweeps_through_crossings(&ball, &start);
    let spring = CoulombSpring { m: 1.0, k: 4.0, mu: 0.05, a: 0.1, f: 0.2 };
    let mut start = State::<CoulombSpring>::zeros();
    (start.v[0], start.p[0]) = (1.0, 1.0);
    sweeps_through_crossings(&spring, &start);
    let belt = FrictionBelt { m: 1.0, k: 4.0, vb: 0.2, n: 2.0, mu_s: 0.4, mu_k: 0.25 };
    sweeps_through_crossings(&belt, &State::<FrictionBelt>::zeros());
}

/// An adjoint sweep over a run that held its inputs between samples (`record_held`) allocates
/// per sweep (a copy of the model for each sample), never per backward step: sweeps over runs
/// at two tolerances allocate as often.
#[test]
fn backward_steps_with_held_inputs_do_not_allocate() {
    let spring = ForcedSpring { m: 1.3, k: 4.0, f: 0.0 };
    let (times, samples) = ([0.0, 0.5, 1.0, 1.5], [0.3, -1.0, 0.7, 2.0]);
    let terminal = |_: f64, y: &State<ForcedSpring>, out: &mut State<ForcedSpring>| {
        out.clone_from(y);
        0.5 * (y.q.norm_squared() + y.v.norm_squared())
    };
    let objective = dirac::adjoint::Objective::terminal(&terminal);
    let sweep = |tolerance: f64| {
        let mut model = spring.clone();
        let recording = Radau::new(&mut model, RadauOptions::tolerances(tolerance, tolerance))
            .expect("valid options")
            .record_held(0.0, &State::<ForcedSpring>::zeros(), 2.0, &times, &[(ForcedSpring::F, &samples)])
            .expect("records");
        let before = allocations();
        let gradient = recording.gradient_held(&spring, &objective).expect("a gradient");
        assert!(gradient.inputs[0].iter().all(|g| g.is_finite()));
        (allocations() - before, recording.steps())
    };
    same_allocations_at_two_tolerances(sweep);
}

/// A reduced composite records the series it recovers (eliminated coordinates, multipliers,
/// port efforts) at each sample, solving for the accelerations there: without allocating. The
/// reduced motor run sampled at 40 and at 80 times, at a loose and at a tight tolerance,
/// allocates as often each time (a sample's columns are reserved with the run).
#[test]
fn recording_the_series_a_reduced_model_recovers_does_not_allocate() {
    let model = crate::reduction::Reduced::new();
    assert!(!model.recovered_names().is_empty() && crate::reduction::Reduced::RECOVERED_READS_ACCELERATIONS);
    let zero = VecQ::<crate::reduction::Reduced>::zeros();
    let start = consistent_state(&model, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
    let run = |tolerance: f64, samples: usize| {
        let times: Vec<f64> = (1..=samples).map(|k| 0.4 * k as f64 / samples as f64).collect();
        let mut radau = Radau::new(&model, RadauOptions::tolerances(tolerance, tolerance)).expect("valid");
        let before = allocations();
        let solution = radau.solve(0.0, &start, 0.4, &Sampling::Times(times)).expect("integrates");
        let counted = allocations() - before;
        assert!(solution.column("lambda(connect6)").expect("recovered").iter().all(|x| x.is_finite()));
        (counted, solution.stats.steps)
    };
    run(1e-6, 40);
    let (loose, few) = run(1e-6, 40);
    let (tight, many) = run(1e-11, 40);
    let (denser, _) = run(1e-11, 80);
    assert!(many > few + 20, "{few} and {many} steps");
    assert_eq!(loose, tight, "{few} steps allocate {loose} times, {many} steps {tight} times");
    assert_eq!(tight, denser, "40 samples allocate {tight} times, 80 samples {denser} times");
}

/// Runs `sweep(tolerance)` (the allocations it counted, and the steps of its run) once to warm
/// up, then at a loose and a tight tolerance, and asserts that the tight run took more than
/// twenty more steps and that both allocated as often.
fn same_allocations_at_two_tolerances(sweep: impl Fn(f64) -> (usize, usize)) {
    sweep(1e-11);
    let (loose, few) = sweep(1e-6);
    let (tight, many) = sweep(1e-11);
    assert!(many > few + 20, "{few} and {many} steps");
    assert_eq!(loose, tight, "{few} steps allocate {loose} times, {many} steps {tight} times");
}

/// Sweeps back over runs of `model` from `start` to `t = 2` at a loose and a tight tolerance,
/// and asserts that both allocate as often.
fn sweeps_through_crossings<M: Parameters + dirac::Hybrid>(model: &M, start: &State<M>)
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let terminal = |_: f64, y: &State<M>, out: &mut State<M>| {
        out.clone_from(y);
        0.5 * (y.q.norm_squared() + y.v.norm_squared())
    };
    let objective = dirac::adjoint::Objective::terminal(&terminal);
    let sweep = |tolerance: f64| {
        let recording = Radau::new(model, RadauOptions::tolerances(tolerance, tolerance))
            .expect("valid options")
            .record(0.0, start, 2.0)
            .expect("records");
        let before = allocations();
        let gradient = recording.gradient(model, &objective).expect("a gradient");
        assert!(gradient.parameters.iter().all(|g| g.is_finite()));
        (allocations() - before, recording.steps())
    };
    same_allocations_at_two_tolerances(sweep);
}

/// A companion whose contacts can rest watches its closed contacts' forces for their release:
/// evaluating them allocates nothing either. The ball rests on its floor from the start.
#[test]
fn watching_resting_contacts_does_not_allocate() {
    let mut ball = BouncingBall { m: 1.0, g: 9.81, e: 0.5 }.with_contacts();
    assert!(ball.set_contact_closed(0, true));
    let start =
        dirac::consistent_state(&ball, 0.0, &Default::default(), &Default::default(), Default::default())
            .expect("consistent");
    let mut events = dirac::Events::new().contacts(&ball);
    let mut radau = Radau::new(&ball, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid options");
    radau.start(0.0, &start, 1.0).expect("starts");
    events.begin(radau.model(), 0.0, &start).expect("begins");
    let before = allocations();
    let mut located = 0;
    while !radau.finished() {
        radau.step().expect("steps");
        while events.locate(&mut radau).expect("locates").is_some() {
            located += 1;
        }
    }
    assert_eq!(allocations() - before, 0);
    // Held by the floor, the ball neither strikes it nor leaves it.
    assert_eq!(located, 0);
    assert!(radau.state().q(BouncingBallWithContacts::Y).abs() < 1e-12);
}

/// Steps a Radau integration with forward sensitivities (`wrt`) 200 times after 5 warm-up
/// steps, reading each sensitivity and interpolating it within the step, and returns the
/// allocations during the 200 and how many of them solved the sensitivities with the stages'
/// coupled system.
fn allocations_with_sensitivities<M: Parameters>(
    model: &M,
    start: &State<M>,
    wrt: &Sensitivities<M>,
    error_control: bool,
) -> (usize, usize)
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let wrt = wrt.clone().error_control(error_control);
    let options = RadauOptions::tolerances(1e-10, 1e-10);
    let mut radau = Radau::new(model, options).expect("valid").with_sensitivities(&wrt).expect("valid");
    radau.start(0.0, start, 100.0).expect("starts");
    let mut s = State::<M>::with_sizes(model.sizes());
    for _ in 0..5 {
        radau.step().expect("steps");
    }
    let coupled = radau.stats().coupled_sensitivity_steps;
    let before = allocations();
    for _ in 0..200 {
        let h = radau.step().expect("steps");
        for j in 0..wrt.len() {
            assert!(radau.sensitivity(j, &mut s));
            assert!(radau.interpolate_sensitivity(j, radau.t() - 0.5 * h, &mut s));
        }
    }
    let allocated = allocations() - before;
    (allocated, radau.stats().coupled_sensitivity_steps - coupled)
}

#[test]
fn steps_with_sensitivities_do_not_allocate() {
    let p = unit_pendulum();
    let wrt = Sensitivities::all_parameters(&p).initial_position(Pendulum::X).initial_velocity(Pendulum::Y);
    for error_control in [false, true] {
        let (n, coupled) = allocations_with_sensitivities(&p, &horizontal_start(&p), &wrt, error_control);
        assert_eq!(n, 0, "pendulum, error control {error_control}");
        // The path for small nonlinear models was among those counted.
        assert!(coupled > 0, "pendulum: no step solved the stages' coupled system");
    }
    let chain = paper_chain();
    let wrt = Sensitivities::all_parameters(&chain).initial_position(Chain::left(Primitive1::X1));
    let (n, _) = allocations_with_sensitivities(&chain, &paper_chain_start(&chain), &wrt, true);
    assert_eq!(n, 0, "interconnected chain");
    let disk = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let v = VecQ::<RollingDisk>::new(0.6, 0.0, 2.0, 1.0);
    let start = consistent_state(&disk, 0.0, &VecQ::<RollingDisk>::zeros(), &v, Consistency::default())
        .expect("consistent");
    let wrt = Sensitivities::all_parameters(&disk);
    let (n, coupled) = allocations_with_sensitivities(&disk, &start, &wrt, false);
    assert_eq!(n, 0, "rolling disk");
    assert!(coupled > 0, "rolling disk: no step solved the stages' coupled system");
    // A model made of an array of cells: stored sparse and factored by a sparse LU.
    let ladder = unit_ladder(20);
    let start = ladder_at_rest(&ladder, &pulse(20));
    let wrt = Sensitivities::new(&ladder)
        .initial_position(ladder.cells(5, zoo::Cell::B))
        .initial_velocity(ladder.cells(6, zoo::Cell::A));
    for error_control in [false, true] {
        let (n, _) = allocations_with_sensitivities(&ladder, &start, &wrt, error_control);
        assert_eq!(n, 0, "ladder (sparse), error control {error_control}");
    }
    // The same ladder as a network assembled at run time, with respect to two of its parts'
    // parameters: each part writes its derivatives in place.
    let network = network_ladder(20);
    let mut at = State::<dirac::network::Network>::with_sizes(network.sizes());
    at.q.copy_from_slice(start.q.as_slice());
    at.v.copy_from_slice(start.v.as_slice());
    at.p.copy_from_slice(start.p.as_slice());
    at.lambda.copy_from_slice(start.lambda.as_slice());
    let names = network.parameter_names();
    let wrt = Sensitivities::new(&network).parameters(&[&names[0], &names[7]]).expect("parameters");
    for error_control in [false, true] {
        let (n, _) = allocations_with_sensitivities(&network, &at, &wrt, error_control);
        assert_eq!(n, 0, "network ladder, error control {error_control}");
    }
}

/// A run of `model` recorded whole, or within `budget` bytes.
fn record<M: Parameters + dirac::Hybrid>(
    model: &M,
    options: RadauOptions,
    start: &State<M>,
    t_end: f64,
    budget: Option<usize>,
) -> dirac::adjoint::Recording<M>
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut radau = Radau::new(model, options).expect("valid");
    match budget {
        None => radau.record(0.0, start, t_end),
        Some(bytes) => radau.record_within(0.0, start, t_end, bytes),
    }
    .expect("integrates")
}

/// The allocations of an adjoint sweep over a run of `model` from `start` to `t_end`: its
/// set-up only, if its backward steps allocate nothing. Returns them with the number of steps.
fn allocations_in_adjoint_sweep<M: Parameters + dirac::Hybrid>(
    model: &M,
    start: &State<M>,
    t_end: f64,
    budget: Option<usize>,
) -> (usize, usize)
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let recording = record(model, RadauOptions::tolerances(1e-8, 1e-8), start, t_end, budget);
    let terminal = |_: f64, y: &State<M>, out: &mut State<M>| {
        out.clone_from(y);
        0.5 * (y.q.norm_squared() + y.v.norm_squared() + y.p.norm_squared() + y.lambda.norm_squared())
    };
    let running = |_: f64, y: &State<M>, out: &mut State<M>| {
        out.clone_from(y);
        out.lambda.fill(0.0);
        0.5 * (y.q.norm_squared() + y.v.norm_squared() + y.p.norm_squared())
    };
    let objective = dirac::adjoint::Objective::terminal(&terminal).with_running(&running);
    let before = allocations();
    let gradient = recording.gradient(model, &objective).expect("a gradient");
    let allocated = allocations() - before;
    assert!(gradient.parameters.iter().all(|g| g.is_finite()));
    (allocated, recording.steps())
}

/// The backward steps of an adjoint sweep allocate nothing: a sweep over many more steps
/// allocates exactly as much as one over a few (its set-up), on a model stored dense and on
/// one made of an array of cells, stored sparse; and with the run recorded within a budget,
/// where the sweep also solves the steps between checkpoints again (replayed steps included).
/// The sweep's room for replayed starts is the budget's share or the run's steps, whichever is
/// less, and each of the ladder's starts is an allocation: its budgets leave room for fewer
/// starts (about 18 and 9) than the short run's 46 steps, so both runs set up the same room.
#[test]
fn backward_steps_of_an_adjoint_sweep_do_not_allocate() {
    let p = unit_pendulum();
    let start = horizontal_start(&p);
    for budget in [None, Some(100_000)] {
        let (short, few) = allocations_in_adjoint_sweep(&p, &start, 0.2, budget);
        let (long, many) = allocations_in_adjoint_sweep(&p, &start, 20.0, budget);
        assert!(many > 10 * few, "{few} and {many} steps");
        assert_eq!(short, long, "pendulum: {few} steps allocate {short} times, {many} steps {long} times");
    }
    let ladder = unit_ladder(10);
    let start = ladder_at_rest(&ladder, &pulse(10));
    for budget in [None, Some(40_000), Some(20_000)] {
        let (short, few) = allocations_in_adjoint_sweep(&ladder, &start, 5.0, budget);
        let (long, many) = allocations_in_adjoint_sweep(&ladder, &start, 100.0, budget);
        assert!(many > 5 * few, "{few} and {many} steps");
        assert_eq!(short, long, "ladder: {few} steps allocate {short} times, {many} steps {long} times");
    }
}

/// The most bytes held above the start while a run of the ladder `model` to `t_end` is
/// recorded (within `budget`, if given) and the gradient of `½ |y(T)|²` taken; and the steps.
fn peak_bytes_of_a_gradient<M: Parameters + dirac::Hybrid>(
    model: &M,
    start: &State<M>,
    t_end: f64,
    budget: Option<usize>,
) -> (isize, usize)
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let base = peak_from_here();
    let recording = record(model, RadauOptions::tolerances(1e-10, 1e-10), start, t_end, budget);
    let terminal = |_: f64, y: &State<M>, out: &mut State<M>| {
        out.clone_from(y);
        0.5 * (y.q.norm_squared() + y.v.norm_squared() + y.p.norm_squared() + y.lambda.norm_squared())
    };
    let gradient =
        recording.gradient(model, &dirac::adjoint::Objective::terminal(&terminal)).expect("a gradient");
    assert!(gradient.parameters.iter().all(|g| g.is_finite()));
    (peak() - base, recording.steps())
}

/// The memory of an adjoint gradient recorded within a budget, measured by the allocator: a
/// twenty times longer run of a 50-cell ladder holds at most the budget and its steps' sizes
/// more than a short one (the set-up, the same for both, is what the short one holds), while
/// a recording that keeps every step grows by its stages, `4 (3n + m)` numbers a step.
#[test]
fn checkpoints_hold_the_memory_of_an_adjoint_gradient_within_the_budget() {
    let ladder = unit_ladder(50);
    let start = ladder_at_rest(&ladder, &pulse(50));
    let budget = 100_000;
    let (short, few) = peak_bytes_of_a_gradient(&ladder, &start, 5.0, Some(budget));
    let (long, many) = peak_bytes_of_a_gradient(&ladder, &start, 100.0, Some(budget));
    let (whole, steps) = peak_bytes_of_a_gradient(&ladder, &start, 100.0, None);
    assert_eq!(steps, many);
    let step_sizes = 16 * many as isize;
    eprintln!(
        "checkpointed: {few} steps {short} bytes, {many} steps {long} bytes (budget {budget}); \
         every step kept: {whole} bytes"
    );
    assert!(many > 5 * few, "{few} and {many} steps");
    assert!(long - short <= budget as isize + step_sizes, "{short} bytes for {few} steps, {long} for {many}");
    let sizes = ladder.sizes();
    let stages = 4 * 8 * (3 * sizes.nq + sizes.nc) as isize;
    assert!(whole - short >= (many as isize) * stages / 2, "every step kept: {whole} bytes");
}

/// An FMU's communication steps through its C functions (`dirac::fmi::abi`, what
/// `export_fmu!` exports): set the input, step, read outputs, positions and the multiplier.
/// After the first step, which builds the integrator, 100 such rounds allocate nothing.
#[test]
fn fmu_communication_steps_do_not_allocate() {
    use driven_pendulum::DrivenPendulum;
    let read = ["time", "energy", "height", "x", "y", "vx", "vy", "lambda(rod)"];
    assert_eq!(
        allocations_in_fmu_steps::<DrivenPendulum>("f", &read),
        0,
        "allocations in 100 communication steps"
    );
}

/// A netlist's RC ladder of 100 cells as a run-time network, exported as an FMU whose input is
/// its source's current (an input in a force: a voltage source's, in a constraint, makes the
/// state jump at each change, which is set-up work).
struct NetlistLadder;

impl dirac::fmi::Fmu for NetlistLadder {
    type Model = dirac::network::Network;
    const IDENTIFIER: &'static str = "ladder";

    fn model(
        _resources: Option<&std::path::Path>,
    ) -> Result<dirac::fmi::Start<dirac::network::Network>, dirac::fmi::BoxError> {
        use std::fmt::Write as _;
        let mut text = String::from("an RC ladder\nI1 0 n0 DC 1\nR0 n0 0 1\n");
        for k in 1..=100 {
            let _ = writeln!(text, "R{k} n{} n{k} 1\nC{k} n{k} 0 1", k - 1);
        }
        let circuit = dirac::spice::parse(&text)?.circuit()?;
        let (q, v) = circuit.start_values();
        Ok(dirac::fmi::Start { model: circuit.network, q, v })
    }
}

/// The same through a run-time network of 202 parts (a netlist's, made by the FMU's
/// [`Fmu::model`](dirac::fmi::Fmu::model)): its steps, on the sparse path, allocate nothing.
#[test]
fn communication_steps_of_a_network_fmu_do_not_allocate() {
    let read = ["time", "c100.v", "c100.charge", "i1.v", "r100.n"];
    assert_eq!(
        allocations_in_fmu_steps::<NetlistLadder>("i1.i", &read),
        0,
        "allocations in 100 communication steps"
    );
}

/// Allocations in 100 communication steps of FMU `F` through its C functions, after a first,
/// each setting `input`, stepping by 0.01 and reading the variables `read`.
#[allow(unsafe_code)]
fn allocations_in_fmu_steps<F: dirac::fmi::Fmu>(input: &str, read: &[&str]) -> usize
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<F::Model>,
{
    use std::ffi::CString;
    use std::ptr::null_mut;

    let start = F::model(None).expect("the model is made");
    let xml = dirac::fmi::describe::<F>(None, dirac::fmi::Version::Fmi3).expect("described");
    let token = xml.split("instantiationToken=\"").nth(1).and_then(|t| t.split('"').next()).expect("a token");
    let (name, token) = (CString::new("alloc").expect("no NUL"), CString::new(token).expect("no NUL"));
    let abi = |status: i32| assert_eq!(status, 0, "an FMI call failed");
    let vr = |name: &str| {
        dirac::fmi::value_reference(&start.model, name).unwrap_or_else(|| {
            let part = name.split('.').next().unwrap_or(name);
            let names: Vec<&str> = xml
                .split("<Float64 name=\"")
                .skip(1)
                .filter_map(|r| r.split('"').next())
                .filter(|n| n.contains(part))
                .collect();
            panic!("{name} is no variable of the FMU; those that name {part} are {names:?}")
        })
    };
    let (u, read): (u32, Vec<u32>) = (vr(input), read.iter().map(|n| vr(n)).collect());
    let mut values = vec![0.0; read.len()];
    // SAFETY: the calls follow FMI: one instance, used and freed here, with valid pointers and
    // lengths.
    unsafe {
        use dirac::fmi::abi;
        let instance = abi::instantiate_co_simulation::<F>(
            name.as_ptr(),
            token.as_ptr(),
            std::ptr::null(),
            false,
            null_mut(),
            None,
        );
        assert!(!instance.is_null());
        abi(abi::enter_initialization_mode::<F>(instance, true, 1e-8, 0.0, false, 0.0));
        abi(abi::exit_initialization_mode::<F>(instance));
        let mut round = |k: usize| {
            let t = 0.01 * k as f64;
            let value = [2.0 * (3.0 * t).sin()];
            abi(abi::set_float64::<F>(instance, &u, 1, value.as_ptr(), 1));
            abi(abi::do_step::<F>(instance, t, 0.01, null_mut(), null_mut(), null_mut(), null_mut()));
            abi(abi::get_float64::<F>(instance, read.as_ptr(), read.len(), values.as_mut_ptr(), read.len()));
        };
        round(0);
        let before = allocations();
        for k in 1..=100 {
            round(k);
        }
        let n = allocations() - before;
        assert!((values[0] - 1.01).abs() < 1e-12, "t = {}", values[0]);
        abi::free_instance::<F>(instance);
        n
    }
}

/// Rigid bodies on joints (holonomic rows of an interconnection): every method's steps, and
/// Radau's projection of the steps' ends and of the samples between them.
#[test]
fn steps_of_bodies_on_joints_do_not_allocate() {
    let (pendulum, _) = zoo::bodies::double_pendulums();
    let s = zoo::bodies::spatial_start(&pendulum, [0.9, -0.4], [0.3, 1.1]);
    assert_eq!(allocations_in_steps(&pendulum, &s, 100.0), 0, "Radau, bodies on joints");
    assert_eq!(allocations_in_explicit_steps(&pendulum, &s, 100.0), 0, "Explicit, bodies on joints");
    assert_eq!(
        allocations_in_variational_steps(&pendulum, &s, VariationalOptions::default()),
        0,
        "variational, bodies on joints"
    );
    let mut radau =
        Radau::new(&pendulum, RadauOptions { projection: true, ..RadauOptions::tolerances(1e-10, 1e-10) })
            .expect("valid options");
    radau.start(0.0, &s, 100.0).expect("starts");
    radau.step().expect("steps");
    let mut sample = s.clone();
    let before = allocations();
    for _ in 0..100 {
        let t0 = radau.t();
        radau.step().expect("steps");
        radau.interpolate(0.5 * (t0 + radau.t()), &mut sample);
    }
    assert_eq!(allocations() - before, 0, "Radau with projection, steps and samples, bodies on joints");
}

#[test]
fn steps_of_a_robot_from_its_urdf_do_not_allocate() {
    use zoo::robots::{Panda, SWING_START};
    let q = VecQ::<Panda>::from_column_slice(&SWING_START);
    let s =
        consistent_state(&Panda, 0.0, &q, &VecQ::<Panda>::zeros(), Consistency::default()).expect("a start");
    assert_eq!(allocations_in_steps(&Panda, &s, 100.0), 0, "Radau, the Panda");
    assert_eq!(allocations_in_explicit_steps(&Panda, &s, 100.0), 0, "Explicit, the Panda");
    assert_eq!(
        allocations_in_variational_steps(&Panda, &s, VariationalOptions::default()),
        0,
        "variational, the Panda"
    );
}

/// A network assembled at run time with 10⁴ parts (a ground and 9 999 ladder cells: 19 999
/// coordinates, 10 000 rows) steps without allocating, with Radau and Explicit: each part's
/// kernel works on the stack, the network writes in place.
#[test]
fn steps_of_a_network_of_ten_thousand_parts_do_not_allocate() {
    let n = 9_999;
    let (ladder, network) = (unit_ladder(n), network_ladder(n));
    let x: Vec<f64> = (0..n).map(|j| (-((j as f64 - 3000.0) / 5.0).powi(2)).exp()).collect();
    let s = ladder_at_rest(&ladder, &x);
    let mut start = State::<dirac::network::Network>::with_sizes(network.sizes());
    start.q.copy_from_slice(s.q.as_slice());
    start.v.copy_from_slice(s.v.as_slice());
    start.p.copy_from_slice(s.p.as_slice());
    start.lambda.copy_from_slice(s.lambda.as_slice());
    let mut radau = Radau::new(&network, RadauOptions::tolerances(1e-8, 1e-8)).expect("valid options");
    radau.start(0.0, &start, 100.0).expect("starts");
    for _ in 0..3 {
        radau.step().expect("steps");
    }
    let before = allocations();
    for _ in 0..10 {
        radau.step().expect("steps");
    }
    assert_eq!(allocations() - before, 0, "Radau, a network of 10⁴ parts");
    let mut explicit =
        Explicit::new(&network, ExplicitOptions::tolerances(1e-8, 1e-8)).expect("valid options");
    explicit.start(0.0, &start, 100.0).expect("starts");
    for _ in 0..3 {
        explicit.step().expect("steps");
    }
    let before = allocations();
    for _ in 0..10 {
        explicit.step().expect("steps");
    }
    assert_eq!(allocations() - before, 0, "Explicit, a network of 10⁴ parts");
}

/// A SPICE netlist's network, its nodes joined and its reference grounded (an LC ladder of
/// 5 000 nodes from a pulse: 10⁴ parts, 5 000 unknowns), steps without allocating: the joined
/// coordinates add up in place and the grounded entries are cleared in place.
#[test]
fn steps_of_a_netlist_with_joined_nodes_do_not_allocate() {
    let n = 5_000;
    let mut text = String::from("an LC ladder\n");
    for k in 1..=n {
        let from = if k == 1 { "0".to_string() } else { format!("n{}", k - 1) };
        text += &format!("L{k} {from} n{k} 1\nC{k} n{k} 0 1\n");
    }
    text += ".ic";
    for k in 1..=n {
        text += &format!(" v(n{k})={:e}", (-((k as f64 - 1500.0) / 5.0).powi(2)).exp());
    }
    text += "\n.tran 1 10 uic\n.end\n";
    let circuit = dirac::spice::parse(&text).expect("reads").circuit().expect("a circuit");
    assert_eq!(circuit.network.sizes().nq, n);
    let start = circuit.start().expect("consistent");
    assert_eq!(allocations_in_steps(&circuit.network, &start, 1e3), 0, "Radau, a netlist of 10⁴ parts");
}

/// Sources that follow waveforms set their inputs at every evaluation, and steps end at the
/// waveforms' corners: neither allocates.
#[test]
fn steps_of_a_netlist_driven_by_waveforms_do_not_allocate() {
    let mut text = String::from("an RC ladder driven by a pulse train and a piecewise-linear current\n");
    text += "V1 n0 0 PULSE(0 1 0.1 0.05 0.05 0.2 0.5)\nI1 0 n3 PWL(0 0 0.3 1m 0.7 -1m 2 0)\n";
    text += "V2 m 0 SIN(0 1 2 0.25)\nR0 m n5 1\n";
    for k in 1..=200 {
        text += &format!("R{k} n{} n{k} 1\nC{k} n{k} 0 1m\n", k - 1);
    }
    text += ".tran 0.01 2\n.end\n";
    let circuit = dirac::spice::parse(&text).expect("reads").circuit().expect("a circuit");
    assert!(circuit.is_driven() && circuit.corners().len() > 10);
    let start = circuit.start().expect("consistent");
    let mut network = circuit.network.clone();
    let mut drive = circuit.drive();
    let mut radau = Radau::new(&mut network, RadauOptions::tolerances(1e-8, 1e-8)).expect("valid options");
    radau.drive(&mut drive).expect("held exclusively");
    radau.stop_at(circuit.corners()).expect("finite corners");
    radau.start(0.0, &start, 2.0).expect("starts");
    for _ in 0..5 {
        radau.step().expect("steps");
    }
    let before = allocations();
    let mut steps = 0;
    while !radau.finished() {
        radau.step().expect("steps");
        steps += 1;
    }
    assert_eq!(allocations() - before, 0, "Radau, a netlist driven by waveforms, {steps} steps");
    assert!(steps > circuit.corners().len(), "{steps} steps past {} corners", circuit.corners().len());
}

/// A netlist with an ideal diode (a half-wave rectifier feeding an RC ladder: 10⁴ parts),
/// watched as a plain solve watches its laws (`Events::switches_in`, the events read from the
/// network's parts): the steps, the search for the diode's events and the evaluation of the
/// parts' event functions allocate nothing, up to the first switch (the diode blocks once the
/// sine turns down). The switch itself projects the state onto the new mode on the heap, as
/// for a derived model.
#[test]
fn watching_an_ideal_diode_in_a_netlist_does_not_allocate() {
    let n = 5_000;
    let mut text = String::from("a rectifier into an RC ladder\n.model di D(ideal)\nV1 in 0 SIN(0 1 0.5)\n");
    text += "D1 in n0 di\nC0 n0 0 1\n";
    for k in 1..n {
        text += &format!("R{k} n{} n{k} 1\nC{k} n{k} 0 1\n", k - 1);
    }
    text += ".tran 0.01 2\n.end\n";
    let circuit = dirac::spice::parse(&text).expect("reads").circuit().expect("a circuit");
    assert!(circuit.network.part_names().len() >= 10_000);
    let start = circuit.start().expect("consistent");
    let mut events = dirac::Events::new().switches_in(&circuit.network);
    let mut radau =
        Radau::new(&circuit.network, RadauOptions::tolerances(1e-8, 1e-8)).expect("valid options");
    // Twice from the start: the first run analyses the sparse matrices' structure (the step's
    // and the dense output's), once; the second is counted.
    let mut run = |counted: bool| {
        radau.start(0.0, &start, 2.0).expect("starts");
        events.begin(radau.model(), 0.0, &start).expect("begins");
        let before = allocations();
        let mut steps = 0;
        let blocked = loop {
            assert!(!radau.finished(), "the diode blocks before the end");
            radau.step().expect("steps");
            steps += 1;
            if let Some(event) = events.locate(&mut radau).expect("locates") {
                assert_eq!(events.name(&event), "d1.diode_blocks");
                break event.t;
            }
        };
        if counted {
            assert_eq!(allocations() - before, 0, "Radau with an ideal diode's events, {steps} steps");
        }
        blocked
    };
    let (first, blocked) = (run(false), run(true));
    // The first run's factorisations differ from the second's by round-off (its first one
    // analyses the structure), which the step control can turn into other steps: the two
    // agree to the run's accuracy, not bit for bit (at rtol 1e-12 the diode blocks at
    // 0.571999, and at this tolerance 3.5e-6 from it).
    assert!((first - blocked).abs() < 1e-5, "{first} and {blocked}");
    assert!(blocked > 0.25 && blocked < 1.0, "blocks at {blocked}");
}

#[test]
fn a_warm_started_interior_point_solve_does_not_allocate() {
    use dirac::optimal::interior::{InteriorOptions, InteriorPoint};
    use dirac::optimal::{Collocation, Dmoc, Problem};
    // The swing-up (final state given, so every equation of the transcription is evaluated),
    // solved once cold; then the plan's inputs are disturbed and the solve is warm started
    // from there, as a receding horizon's next sample is: the solver's work space and the
    // transcription's were sized when they were made.
    let problem = Problem::new(zoo::cart_pole(), 2.0, 30)
        .final_state(VecQ::<CartPole>::from([0.0, std::f64::consts::PI]), VecQ::<CartPole>::zeros())
        .position_bounds(CartPole::X, -1.5, 1.5)
        .input_bounds(CartPole::F, -20.0, 20.0);
    let mut dmoc = Dmoc::new(problem).expect("well-formed");
    let mut solver = InteriorPoint::new(&dmoc).expect("equations only");
    let options = InteriorOptions::default();
    assert!(solver.solve(&mut dmoc, &options).solved);
    let (x, _) = solver.point_mut();
    let inputs = 31 * 2;
    for u in &mut x[inputs..] {
        *u *= 0.9;
    }
    let before = allocations();
    let result = solver.resolve(&mut dmoc, &options);
    let during = allocations() - before;
    assert!(result.solved && result.iterations > 0, "the warm start solves again: {result:?}");
    assert_eq!(during, 0, "a warm-started solve allocated {during} times");

    // The same on the Radau IIA collocation of the problem: points of (q, v), then inputs.
    let mut collocation = Collocation::new(dmoc.problem().clone()).expect("well-formed");
    let mut solver = InteriorPoint::new(&collocation).expect("equations only");
    assert!(solver.solve(&mut collocation, &options).solved);
    let (x, _) = solver.point_mut();
    let inputs = (3 * 30 + 1) * 4;
    for u in &mut x[inputs..] {
        *u *= 0.9;
    }
    let before = allocations();
    let result = solver.resolve(&mut collocation, &options);
    let during = allocations() - before;
    assert!(result.solved && result.iterations > 0, "the warm start solves again: {result:?}");
    assert_eq!(during, 0, "a warm-started collocation solve allocated {during} times");

    // With a free final time: the steps are variables, and every evaluation reads them; with a
    // bounded velocity, each interval has its row and its variable too.
    let free = dmoc.problem().clone().free_final_time(1.0, 4.0).time_weight(10.0).velocity_bounds(
        CartPole::X,
        -2.5,
        2.5,
    );
    let mut dmoc = Dmoc::new(free).expect("well-formed");
    let mut solver = InteriorPoint::new(&dmoc).expect("equations only");
    assert!(solver.solve(&mut dmoc, &options).solved);
    let (x, _) = solver.point_mut();
    let inputs = 31 * 2;
    for u in &mut x[inputs..inputs + 30] {
        *u *= 0.9;
    }
    let before = allocations();
    let result = solver.resolve(&mut dmoc, &options);
    let during = allocations() - before;
    assert!(result.solved && result.iterations > 0, "the warm start solves again: {result:?}");
    assert_eq!(during, 0, "a warm-started free-final-time solve allocated {during} times");

    let mut collocation = Collocation::new(dmoc.problem().clone()).expect("well-formed");
    let mut solver = InteriorPoint::new(&collocation).expect("equations only");
    assert!(solver.solve(&mut collocation, &options).solved);
    let (x, _) = solver.point_mut();
    let inputs = (3 * 30 + 1) * 4;
    for u in &mut x[inputs..inputs + 30] {
        *u *= 0.9;
    }
    let before = allocations();
    let result = solver.resolve(&mut collocation, &options);
    let during = allocations() - before;
    assert!(result.solved && result.iterations > 0, "the warm start solves again: {result:?}");
    assert_eq!(during, 0, "a warm-started free-final-time collocation solve allocated {during} times");
}
