//! `#[dirac(reduce)]`: a composite flattened into one model when it compiles, its aliases
//! eliminated. The reference of every comparison is the same composite without `reduce`,
//! which these tests' neighbours check against independent solutions (the motor in
//! `linearization.rs`, the parts in `components.rs`): reduced and unreduced must move alike.

// The derives' accessors and constants of these composites are not all read here.
#![allow(dead_code)]

use dirac::components::electrical::{Ground, Inductor, Resistor, VoltageSource};
use dirac::components::electromechanical::Emf;
use dirac::components::rotational::{Damper, Fixed, IdealGear, Inertia};
use dirac::prelude::*;

macro_rules! motor_drive {
    ($(#[$attr:meta])* $name:ident) => {
        /// A DC motor with a gearbox and a load on a viscous bearing, from ten parts.
        #[derive(Interconnection, Clone, Debug)]
        $(#[$attr])*
        #[dirac(
            connect(source.p, r.p), connect(r.n, l.p), connect(l.n, emf.p), connect(emf.n, ground.p),
            connect(source.n, ground.p), connect(emf.phi, rotor.phi), connect(rotor.phi, gear.a),
            connect(gear.b, load.phi), connect(load.phi, bearing.b), connect(bearing.a, housing.phi)
        )]
        pub struct $name {
            pub source: VoltageSource,
            pub r: Resistor,
            pub l: Inductor,
            pub emf: Emf,
            pub ground: Ground,
            pub rotor: Inertia,
            pub gear: IdealGear,
            pub load: Inertia,
            pub bearing: Damper,
            pub housing: Fixed,
        }

        impl $name {
            pub(crate) fn new() -> $name {
                $name {
                    source: VoltageSource { u: 12.0 },
                    r: Resistor { r: 1.0 },
                    l: Inductor { l: 0.05 },
                    emf: Emf { k: 0.5 },
                    ground: Ground {},
                    rotor: Inertia { j: 0.01 },
                    gear: IdealGear { ratio: 4.0 },
                    load: Inertia { j: 0.05 },
                    bearing: Damper { d: 0.1 },
                    housing: Fixed { phi0: 0.0 },
                }
            }
        }
    };
}

motor_drive!(Parts);
motor_drive!(
    #[dirac(reduce)]
    Reduced
);

/// A run from rest, sampled at `times`, at tight tolerances.
macro_rules! run {
    ($ty:ty, $model:expr, $times:expr) => {{
        let (model, times): (&$ty, &[f64]) = (&$model, &$times);
        let zero = VecQ::<$ty>::zeros();
        let start = consistent_state(model, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
        let mut radau = Radau::new(model, RadauOptions::tolerances(1e-11, 1e-11)).expect("valid");
        let end = *times.last().expect("a time");
        radau.solve(0.0, &start, end, &Sampling::Times(times.to_vec())).expect("integrates")
    }};
}

#[test]
fn the_motor_from_ten_parts_reduces_to_two_coordinates_and_no_row() {
    assert_eq!(Reduced::NAMES.coordinate_names(), ["r.n", "gear.b"]);
    assert!(Reduced::NAMES.constraint_names().is_empty());
    assert_eq!((VecQ::<Reduced>::zeros().len(), VecC::<Reduced>::zeros().len()), (2, 0));
    assert_eq!((VecQ::<Parts>::zeros().len(), VecC::<Parts>::zeros().len()), (17, 15));
    // The node between the resistor and the inductor has no inertia: its velocity (the node's
    // voltage) is solved in closed form from the resistor's current, `v = u − r i`.
    assert_eq!(Reduced::SOLVED_VELOCITIES, [0]);
    // The connections merge, the ground and the housing become numbers, the gear a ratio, the
    // EMF's node `k` times the rotor's angle; the source's node, which only the resistor
    // reads through its voltage, leaves with the source's row: its voltage is the input.
    let eliminated = Reduced::ELIMINATED;
    assert_eq!(eliminated.len(), 15);
    assert!(eliminated.contains(&("source.p", "∫ source.u dt")), "{eliminated:?}");
    assert!(eliminated.contains(&("r.p", "source.p")));
    assert!(eliminated.contains(&("housing.phi", "bearing.a")));
    assert!(eliminated.contains(&("source.n", "0")));
    assert!(eliminated.contains(&("bearing.a", "housing.phi0")));
    assert!(
        eliminated
            .iter()
            .any(|(name, by)| *name == "emf.phi" && by.contains("gear.ratio") && by.contains("gear.b"))
    );
    assert!(
        eliminated.iter().any(|(name, by)| *name == "l.n" && by.contains("emf.k") && by.contains("gear.b"))
    );
    // Its parameters and outputs keep the parts' dotted names.
    let parameters = Reduced::new().parameter_names();
    for name in
        ["source.u", "r.r", "l.l", "emf.k", "rotor.j", "gear.ratio", "load.j", "bearing.d", "housing.phi0"]
    {
        assert!(parameters.iter().any(|p| p == name), "no parameter `{name}` in {parameters:?}");
    }
}

#[test]
fn the_reduced_motor_moves_as_the_ten_parts_do() {
    let times: Vec<f64> = (1..=8).map(|k| 0.05 * k as f64).collect();
    let (parts, reduced) = (Parts::new(), Reduced::new());
    let (full, flat) = (run!(Parts, parts, times), run!(Reduced, reduced, times));
    let rotor = Parts::NAMES.coordinate_names().iter().position(|n| n == "rotor.phi").expect("the rotor");
    let load = Reduced::NAMES.coordinate_names().iter().position(|n| n == "gear.b").expect("the load");
    for (i, t) in times.iter().enumerate() {
        let (a, b) = (full.state(i).expect("a sample"), flat.state(i).expect("a sample"));
        // The rotor turns `ratio` times the load.
        // Both at rtol = atol = 1e-11: they agree to the integrators' global error.
        let (w, w_reduced) = (a.v[rotor], 4.0 * b.v[load]);
        assert!((w - w_reduced).abs() < 1e-8 * (1.0 + w.abs()), "t = {t}: {w} against {w_reduced}");
        assert!((a.q[rotor] - 4.0 * b.q[load]).abs() < 1e-8 * (1.0 + a.q[rotor].abs()));
    }
    // Every output the parts record, the reduced model records alike: currents, voltages,
    // the power the source supplies (a multiplier), the bearing's torque.
    let names = reduced.output_names();
    let mut compared = 0;
    for name in names.iter().filter(|n| parts.output_names().contains(n)) {
        let column = format!("out({name})");
        let (a, b) = (full.column(&column).expect("an output"), flat.column(&column).expect("an output"));
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() < 1e-7 * (1.0 + x.abs()), "{name}: {x} against {y}");
        }
        compared += 1;
    }
    assert!(compared >= 10, "only {compared} outputs in common: {names:?}");
    assert!(names.iter().any(|n| n == "source.i") && names.iter().any(|n| n == "l.i"));
}

/// The series of `model` at `(t, q, v)` alone: the state made consistent (its multipliers and
/// momenta solved there) and recorded as a run's first sample.
macro_rules! sample_at {
    ($ty:ty, $model:expr, $t:expr, $q:expr, $v:expr) => {{
        let (model, t): (&$ty, f64) = (&$model, $t);
        let start = consistent_state(model, t, &$q, &$v, Consistency::default()).expect("consistent");
        let mut radau = Radau::new(model, RadauOptions::tolerances(1e-11, 1e-11)).expect("valid");
        radau.solve(t, &start, t + 1e-3, &Sampling::Times(vec![t])).expect("integrates")
    }};
}

/// Compares every series the reduced model `$b` recovers with the same series of the unreduced
/// model `$a` at the same states: each sample of a run of `$a` at `times`, read in `$b`'s
/// coordinates by name, made consistent in both and recorded there (so they agree to
/// rounding, not to the integrators' error). At every port, the effort times the port's
/// velocity agrees too, and the powers of all ports sum to zero (connections are lossless).
/// The numbers of series and of port efforts compared.
macro_rules! assert_recovered {
    (($ta:ty, $a:expr), ($tb:ty, $b:expr), $times:expr) => {{
        let (a, b, times): (&$ta, &$tb, &[f64]) = (&$a, &$b, &$times);
        let full = run!($ta, a.clone(), times);
        let (coordinates, velocities) = (a.coordinate_names(), a.velocity_names());
        let (mut compared, mut efforts) = (0, 0);
        for (i, &t) in times.iter().enumerate() {
            let state = full.state(i).expect("a sample");
            let (mut q, mut v) = (VecQ::<$tb>::zeros(), VecQ::<$tb>::zeros());
            for (k, name) in b.coordinate_names().iter().enumerate() {
                let j = coordinates.iter().position(|c| c == name).expect("a coordinate of both");
                (q[k], v[k]) = (state.q[j], state.v[j]);
            }
            let unreduced = sample_at!($ta, *a, t, state.q, state.v);
            let reduced = sample_at!($tb, *b, t, q, v);
            let mut port_power = 0.0;
            for name in b.recovered_names() {
                let (Some(x), Some(y)) = (unreduced.column(name), reduced.column(name)) else {
                    panic!("`{name}` is not a series of both");
                };
                let (x, y) = (x[0], y[0]);
                assert!((x - y).abs() <= 1e-10 * (1.0 + x.abs()), "t = {t}: `{name}` {y} against {x}");
                compared += 1;
                if let Some(port) = name.strip_prefix("f(").and_then(|n| n.strip_suffix(')')) {
                    let k = coordinates.iter().position(|c| c == port).expect("a port of both");
                    let speed = (unreduced.column(&velocities[k]), reduced.column(&velocities[k]));
                    let (Some(vx), Some(vy)) = speed else {
                        panic!("`{}` is not a series of both", velocities[k])
                    };
                    let (px, py) = (x * vx[0], y * vy[0]);
                    assert!(
                        (px - py).abs() <= 1e-10 * (1.0 + px.abs()),
                        "t = {t}: power at `{port}` {py} against {px}"
                    );
                    port_power += py;
                    efforts += 1;
                }
            }
            assert!(port_power.abs() < 1e-9, "t = {t}: the connections take {port_power} W");
        }
        (compared, efforts)
    }};
}

/// What the reduction takes out of the state is still recorded under the composite's names:
/// each eliminated coordinate, velocity and momentum, each eliminated connection's and part
/// row's multiplier (those of coordinates with inertia read the accelerations), the
/// interconnection force at every port, and each part's dissipated power. Reference: the same
/// ten parts unreduced, at the same states (`assert_recovered`).
#[test]
fn the_forces_and_port_powers_of_eliminated_connections_are_the_unreduced_models() {
    let reduced = Reduced::new();
    let recovered = reduced.recovered_names();
    let expected =
        ["rotor.phi", "rotor.w", "p(rotor.phi)", "lambda(connect6)", "lambda(gear.gear)", "f(gear.a)"];
    for name in expected.into_iter().chain(["out(r.dissipated_power)", "out(bearing.dissipated_power)"]) {
        assert!(recovered.contains(&name), "`{name}` is not recovered: {recovered:?}");
    }
    let times: Vec<f64> = (1..=6).map(|k| 0.06 * k as f64).collect();
    // The files a solution writes hold them too, as its columns are.
    let solution = run!(Reduced, reduced, times);
    let mut csv = Vec::new();
    solution.write_csv(&mut csv).expect("written");
    let csv = String::from_utf8(csv).expect("text");
    let (header, first) = (csv.lines().next().expect("a header"), csv.lines().nth(1).expect("a row"));
    let at = header.split(',').position(|n| n == "lambda(connect6)").expect("in the header");
    let written: f64 = first.split(',').nth(at).expect("a value").parse().expect("a number");
    assert_eq!(written, solution.column("lambda(connect6)").expect("recovered")[0]);
    let (compared, efforts) = assert_recovered!((Parts, Parts::new()), (Reduced, reduced), times);
    // Ten connections join 17 ports (the ground, the rotor and the load in two each).
    assert_eq!(efforts, 6 * 17, "the efforts at the ports the connections join, at 6 times");
    assert!(compared > 6 * 60, "only {compared} series compared");
}

/// An oscillator whose recovered series divides by its position (the hidden attribute the
/// reduction emits, written here by hand): `m a / x = −k` wherever `x ≠ 0`, and 0/0 at rest.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
#[dirac(__recover("stiffness") = -m * __dt_v / x)]
pub struct Divided {
    pub m: f64,
    pub k: f64,
}

/// A recovered series that is not finite at a sample ends the run with an error naming it and
/// when, as an output does; where it is finite it is recorded (reference: `m ẍ = −k x`).
#[test]
fn a_recovered_series_that_is_not_finite_is_an_error_naming_it() {
    let model = Divided { m: 2.0, k: 3.0 };
    let run = |x: f64| {
        let (q, v) = (VecQ::<Divided>::from_element(x), VecQ::<Divided>::zeros());
        let start = consistent_state(&model, 0.0, &q, &v, Consistency::default()).expect("consistent");
        Radau::new(&model, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid").solve(
            0.0,
            &start,
            0.5,
            &Sampling::Every(0.25),
        )
    };
    let solution = run(1.0).expect("finite away from x = 0");
    for k in solution.column("stiffness").expect("recovered") {
        assert!((k - 3.0).abs() < 1e-12, "{k}");
    }
    let error = run(0.0).expect_err("0/0 at rest");
    assert!(matches!(error, SimError::NonFinite { t, .. } if t == 0.0), "{error:?}");
    assert!(error.to_string().contains("the recovered series `stiffness`"), "{error}");
}

#[test]
fn a_reduced_parameter_is_set_by_its_dotted_name_and_reaches_the_field() {
    let mut reduced = Reduced::new();
    let k = reduced.parameter_names().iter().position(|n| n == "gear.ratio").expect("the gear's ratio");
    reduced.set_parameter_value(k, 2.0);
    assert_eq!(reduced.gear.ratio, 2.0);
    assert_eq!(reduced.parameter_value(k), 2.0);
    // The reduced model runs with it: the rotor now turns twice the load.
    let mut parts = Parts::new();
    parts.gear.ratio = 2.0;
    let (full, flat) = (run!(Parts, parts, [0.2]), run!(Reduced, reduced, [0.2]));
    let rotor = Parts::NAMES.coordinate_names().iter().position(|n| n == "rotor.phi").expect("the rotor");
    let load = Reduced::NAMES.coordinate_names().iter().position(|n| n == "gear.b").expect("the load");
    let (a, b) = (full.state(0).expect("a sample"), flat.state(0).expect("a sample"));
    assert!((a.v[rotor] - 2.0 * b.v[load]).abs() < 1e-8);
}

/// The motor alone, reduced, its terminals left open: a part of a larger reduced composite.
#[derive(Interconnection, Clone, Debug)]
#[dirac(reduce)]
#[dirac(
    connect(r.n, l.p), connect(l.n, emf.p), connect(emf.phi, rotor.phi), connect(rotor.phi, gear.a),
    connect(gear.b, load.phi), connect(load.phi, bearing.b), connect(bearing.a, housing.phi)
)]
pub struct Motor {
    pub r: Resistor,
    pub l: Inductor,
    pub emf: Emf,
    pub rotor: Inertia,
    pub gear: IdealGear,
    pub load: Inertia,
    pub bearing: Damper,
    pub housing: Fixed,
}

/// The same motor, not reduced.
#[derive(Interconnection, Clone, Debug)]
#[dirac(
    connect(r.n, l.p), connect(l.n, emf.p), connect(emf.phi, rotor.phi), connect(rotor.phi, gear.a),
    connect(gear.b, load.phi), connect(load.phi, bearing.b), connect(bearing.a, housing.phi)
)]
pub struct PlainMotor {
    pub r: Resistor,
    pub l: Inductor,
    pub emf: Emf,
    pub rotor: Inertia,
    pub gear: IdealGear,
    pub load: Inertia,
    pub bearing: Damper,
    pub housing: Fixed,
}

/// A reduced motor driven by a source, reduced again.
#[derive(Interconnection, Clone, Debug)]
#[dirac(reduce)]
#[dirac(connect(source.p, motor.r.p), connect(source.n, ground.p), connect(motor.emf.n, ground.p))]
pub struct Driven {
    pub source: VoltageSource,
    pub ground: Ground,
    pub motor: Motor,
}

/// A motor that is not reduced, driven and reduced around it.
#[derive(Interconnection, Clone, Debug)]
#[dirac(reduce)]
#[dirac(connect(source.p, motor.r.p), connect(source.n, ground.p), connect(motor.emf.n, ground.p))]
pub struct DrivenPlain {
    pub source: VoltageSource,
    pub ground: Ground,
    pub motor: PlainMotor,
}

fn motor() -> Motor {
    let p = Parts::new();
    Motor {
        r: p.r,
        l: p.l,
        emf: p.emf,
        rotor: p.rotor,
        gear: p.gear,
        load: p.load,
        bearing: p.bearing,
        housing: p.housing,
    }
}

#[test]
fn reduced_composites_nest_and_reduce_to_the_same_model() {
    let driven = Driven { source: VoltageSource { u: 12.0 }, ground: Ground {}, motor: motor() };
    let m = motor();
    let plain = PlainMotor {
        r: m.r,
        l: m.l,
        emf: m.emf,
        rotor: m.rotor,
        gear: m.gear,
        load: m.load,
        bearing: m.bearing,
        housing: m.housing,
    };
    let around = DrivenPlain { source: VoltageSource { u: 12.0 }, ground: Ground {}, motor: plain };
    assert_eq!(Driven::NAMES.coordinate_names(), ["motor.r.n", "motor.gear.b"]);
    assert_eq!(DrivenPlain::NAMES.coordinate_names(), ["motor.r.n", "motor.gear.b"]);
    let parameters = driven.parameter_names();
    assert!(parameters.iter().any(|p| p == "motor.gear.ratio"), "{parameters:?}");
    let times = [0.1, 0.3];
    let (flat, nested, around) =
        (run!(Reduced, Reduced::new(), times), run!(Driven, driven, times), run!(DrivenPlain, around, times));
    for i in 0..times.len() {
        let f = flat.state(i).expect("a sample");
        let (a, b) = (nested.state(i).expect("a sample"), around.state(i).expect("a sample"));
        // The load's speed and the node flux between resistor and inductor, in the same
        // places in all three.
        for (v, q) in [(a.v[1], a.q[0]), (b.v[1], b.q[0])] {
            assert!((f.v[1] - v).abs() < 1e-8, "{} against {v}", f.v[1]);
            assert!((f.q[0] - q).abs() < 1e-8);
        }
    }
    // A parameter set by its path reaches the nested field.
    let mut driven = driven;
    let k = driven.parameter_names().iter().position(|n| n == "motor.l.l").expect("the inductance");
    driven.set_parameter_value(k, 0.1);
    assert_eq!(driven.motor.l.l, 0.1);
}

/// The motor and its source, neither reduced: the reference of the nested reductions' series.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(source.p, motor.r.p), connect(source.n, ground.p), connect(motor.emf.n, ground.p))]
pub struct DrivenUnreduced {
    pub source: VoltageSource,
    pub ground: Ground,
    pub motor: PlainMotor,
}

/// A reduced composite nested in a reduced one recovers its own connections under their
/// nested names (`lambda(motor.connect3)`), its ports' efforts and its parts' dissipated
/// powers, as the two composites unreduced record them, at the same states
/// (`assert_recovered`).
#[test]
fn nested_reductions_recover_the_inner_connections_under_their_nested_names() {
    let m = motor();
    let plain = PlainMotor {
        r: m.r.clone(),
        l: m.l.clone(),
        emf: m.emf.clone(),
        rotor: m.rotor.clone(),
        gear: m.gear.clone(),
        load: m.load.clone(),
        bearing: m.bearing.clone(),
        housing: m.housing.clone(),
    };
    let unreduced = DrivenUnreduced { source: VoltageSource { u: 12.0 }, ground: Ground {}, motor: plain };
    let driven = Driven { source: VoltageSource { u: 12.0 }, ground: Ground {}, motor: m };
    let recovered = driven.recovered_names();
    let expected = ["lambda(motor.connect3)", "lambda(connect0)", "f(motor.gear.a)", "motor.rotor.w"];
    for name in expected.into_iter().chain(["out(motor.r.dissipated_power)"]) {
        assert!(recovered.contains(&name), "`{name}` is not recovered: {recovered:?}");
    }
    let times = [0.05, 0.2];
    let (compared, efforts) = assert_recovered!((DrivenUnreduced, unreduced), (Driven, driven), times);
    assert_eq!(efforts, 2 * 17, "the efforts at the ports the connections join, at 2 times");
    assert!(compared > 2 * 60, "only {compared} series compared");
}

/// A cart on a wheel that rolls without slipping: the composite's own row, `x = r θ` at the
/// velocity level, is solved for the cart.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v_x), port(x), lagrangian = 0.5 * m * v_x * v_x - 0.5 * k * x * x)]
pub struct Cart {
    pub m: f64,
    pub k: f64,
}

#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(theta => v_theta), port(theta), lagrangian = 0.5 * j * v_theta * v_theta)]
pub struct Wheel {
    pub j: f64,
}

macro_rules! rolling {
    ($(#[$attr:meta])* $name:ident) => {
        #[derive(Interconnection, Clone, Debug)]
        $(#[$attr])*
        #[dirac(constraint(roll) = radius * wheel.v_theta - cart.v_x)]
        pub struct $name {
            pub cart: Cart,
            pub wheel: Wheel,
            pub radius: f64,
        }
    };
}

rolling!(Rolling);
rolling!(
    #[dirac(reduce)]
    RollingReduced
);

#[test]
fn a_composites_own_row_is_solved_and_the_motion_is_the_closed_forms() {
    assert_eq!(RollingReduced::NAMES.coordinate_names(), ["wheel.theta"]);
    let (m, k, j, radius) = (2.0, 3.0, 0.5, 0.4);
    let reduced = RollingReduced { cart: Cart { m, k }, wheel: Wheel { j }, radius };
    // θ̈ (m r² + j) = −k r² θ: a harmonic oscillator of ω² = k r² / (m r² + j).
    let omega = (k * radius * radius / (m * radius * radius + j)).sqrt();
    let mut q = VecQ::<RollingReduced>::zeros();
    q[0] = 1.0;
    let zero = VecQ::<RollingReduced>::zeros();
    let start = consistent_state(&reduced, 0.0, &q, &zero, Consistency::default()).expect("a start");
    let mut radau = Radau::new(&reduced, RadauOptions::tolerances(1e-11, 1e-11)).expect("valid");
    let times = vec![0.5, 1.0, 2.0];
    let solution = radau.solve(0.0, &start, 2.0, &Sampling::Times(times.clone())).expect("integrates");
    for (i, t) in times.iter().enumerate() {
        let theta = solution.state(i).expect("a sample").q[0];
        assert!((theta - (omega * t).cos()).abs() < 1e-8, "t = {t}: {theta} against {}", (omega * t).cos());
    }
    // The unreduced composite started alike moves alike.
    let plain = Rolling { cart: Cart { m, k }, wheel: Wheel { j }, radius };
    let mut q = VecQ::<Rolling>::zeros();
    q[0] = radius;
    q[1] = 1.0;
    let zero = VecQ::<Rolling>::zeros();
    let start = consistent_state(&plain, 0.0, &q, &zero, Consistency::default()).expect("a start");
    let mut radau = Radau::new(&plain, RadauOptions::tolerances(1e-11, 1e-11)).expect("valid");
    let full = radau.solve(0.0, &start, 2.0, &Sampling::Times(times.clone())).expect("integrates");
    for i in 0..times.len() {
        let (a, b) = (full.state(i).expect("a sample"), solution.state(i).expect("a sample"));
        assert!((a.q[1] - b.q[0]).abs() < 1e-8 && (a.q[0] - radius * b.q[0]).abs() < 1e-8);
    }
}

macro_rules! speed_driven {
    ($(#[$attr:meta])* $name:ident) => {
        /// A rotor spun up through a damper by a prescribed speed.
        #[derive(Interconnection, Clone, Debug)]
        $(#[$attr])*
        #[dirac(connect(drive.phi, damper.a), connect(damper.b, rotor.phi))]
        pub struct $name {
            pub drive: dirac::components::rotational::Speed,
            pub damper: Damper,
            pub rotor: Inertia,
        }

        impl $name {
            fn new() -> $name {
                $name {
                    drive: dirac::components::rotational::Speed { w_ref: 2.0 },
                    damper: Damper { d: 0.5 },
                    rotor: Inertia { j: 0.25 },
                }
            }
        }
    };
}

speed_driven!(SpeedDriven);
speed_driven!(
    #[dirac(reduce)]
    SpeedDrivenReduced
);

/// A prescribed speed on a flange that only a damper reads (through its speed) leaves the
/// model with its row: one coordinate remains, the rotor's. Reference: `j ω' = d (w_ref − ω)`
/// from rest, so `ω = w_ref (1 − e^{−d t / j})`, and the drive supplies `d (w_ref − ω) w_ref`;
/// the unreduced composite records the same power.
#[test]
fn a_prescribed_speed_leaves_the_model_and_its_power_is_read_from_the_damper() {
    assert_eq!(SpeedDrivenReduced::NAMES.coordinate_names(), ["damper.b"]);
    assert!(SpeedDrivenReduced::NAMES.constraint_names().is_empty());
    assert!(SpeedDrivenReduced::ELIMINATED.contains(&("drive.phi", "∫ drive.w_ref dt")));
    let times: Vec<f64> = (1..=5).map(|k| 0.2 * k as f64).collect();
    let (full, flat) = (
        run!(SpeedDriven, SpeedDriven::new(), times),
        run!(SpeedDrivenReduced, SpeedDrivenReduced::new(), times),
    );
    let (w_ref, d, j) = (2.0, 0.5, 0.25);
    let (unreduced, reduced) = (
        full.column("out(drive.supplied)").expect("an output"),
        flat.column("out(drive.supplied)").expect("an output"),
    );
    for (i, &t) in times.iter().enumerate() {
        let omega = w_ref * (1.0 - (-d * t / j).exp());
        let state = flat.state(i).expect("a sample");
        assert!((state.v[0] - omega).abs() < 1e-9, "t = {t}: ω {} against {omega}", state.v[0]);
        let power = d * (w_ref - omega) * w_ref;
        assert!((reduced[i].abs() - power).abs() < 1e-8, "t = {t}: {} against {power}", reduced[i]);
        assert!((reduced[i] - unreduced[i]).abs() < 1e-8, "t = {t}: {} against {}", reduced[i], unreduced[i]);
    }
}
