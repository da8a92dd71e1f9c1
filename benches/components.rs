//! What assembling a system from `dirac::components` costs against the same system written as
//! one hand-reduced model, in one process: a DC motor with a rigid gearbox and a load on a
//! viscous bearing, driven by 12 V from rest for 2 s (about 40 time constants).
//!
//! - parts: ten parts (source, resistor, inductor, EMF, ground, rotor, gear, load, bearing,
//!   housing) and ten connections: 17 coordinates, node fluxes and flange angles, and 22
//!   constraint rows, most of them connections, whose multipliers are the currents and torques;
//! - by hand: the armature charge and the motor angle, `L = ½ l i² + ½ (j_m + j_l/n²) ω² −
//!   k q ω` with the forces `V − R i` and `−(b/n²) ω` (the `motor_load` example's way).
//!
//! - reduced: the ten parts with `#[dirac(reduce)]`: 2 coordinates and no row.
//! - by hand in fluxes: the motor written by hand in the coordinates the reduction keeps, the
//!   flux of the node between resistor and inductor and the load's angle,
//!   `L = −(φ − k n θ)²/2l + ½ (n² j_m + j_l) ω²` with the forces `(V − e)/R` and `−b ω`: the
//!   same equations as the reduced model's, so the same steps, and the time ratio is the cost
//!   of the code alone.
//!
//! All at rtol = atol = 1e-8, with Radau and Explicit, alternated `ROUNDS` times each (parts,
//! reduced, by hand in fluxes, by hand in the charge in every round); the medians' ratios to
//! both hand models are printed with the steps of each and the final rotor speeds, which agree.
//!
//! Run: `cargo bench -p dirac-benches --bench components`.

#![allow(missing_docs)]

use std::hint::black_box;
use std::time::Instant;

use dirac::components::electrical::{Ground, Inductor, Resistor, VoltageSource};
use dirac::components::electromechanical::Emf;
use dirac::components::rotational::{Damper, Fixed, IdealGear, Inertia};
use dirac::prelude::*;

const ROUNDS: usize = 15;
const VOLTS: f64 = 12.0;
const R: f64 = 1.0;
const L: f64 = 0.05;
const K: f64 = 0.5;
const JM: f64 = 0.01;
const JL: f64 = 0.05;
const B: f64 = 0.1;
const N: f64 = 4.0;

#[derive(Interconnection, Clone, Debug)]
#[dirac(
    connect(source.p, r.p), connect(r.n, l.p), connect(l.n, emf.p), connect(emf.n, ground.p),
    connect(source.n, ground.p), connect(emf.phi, rotor.phi), connect(rotor.phi, gear.a),
    connect(gear.b, load.phi), connect(load.phi, bearing.b), connect(bearing.a, housing.phi)
)]
pub struct Parts {
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

/// The same ten parts, reduced when the program compiles (`#[dirac(reduce)]`): the
/// connections, the ground, the fixed housing, the gear and the EMF are solved for, leaving
/// the node fluxes `source.p` and `r.n`, the load angle `gear.b` and the source's row.
#[derive(Interconnection, Clone, Debug)]
#[dirac(reduce)]
#[dirac(
    connect(source.p, r.p), connect(r.n, l.p), connect(l.n, emf.p), connect(emf.n, ground.p),
    connect(source.n, ground.p), connect(emf.phi, rotor.phi), connect(rotor.phi, gear.a),
    connect(gear.b, load.phi), connect(load.phi, bearing.b), connect(bearing.a, housing.phi)
)]
pub struct Reduced {
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

/// The same motor reduced by hand to its charge and angle.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(q => i, theta => w))]
#[dirac(lagrangian = 0.5 * l * i * i + 0.5 * (jm + jl / (n * n)) * w * w - k * q * w)]
#[dirac(force(q) = volts - r * i, force(theta) = -b / (n * n) * w)]
pub struct ByHand {
    pub l: f64,
    pub r: f64,
    pub k: f64,
    pub jm: f64,
    pub jl: f64,
    pub b: f64,
    pub n: f64,
    pub volts: f64,
}

/// The same motor by hand in the reduced model's coordinates: the node flux `phi` (its
/// velocity `e` the node's voltage, no inertia) and the load's angle.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(phi => e, theta => w))]
#[dirac(lagrangian = -(phi - k * n * theta) * (phi - k * n * theta) / (2.0 * l) + 0.5 * (jm * n * n + jl) * w * w)]
#[dirac(force(phi) = (volts - e) / r, force(theta) = -b * w)]
pub struct ByHandInFluxes {
    pub l: f64,
    pub r: f64,
    pub k: f64,
    pub jm: f64,
    pub jl: f64,
    pub b: f64,
    pub n: f64,
    pub volts: f64,
}

fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// One run: its steps and the final rotor speed.
type Run<'a> = &'a dyn Fn() -> (usize, f64);

/// Times the runs alternately, round by round, and prints each median with its ratios to the
/// last two runs' (the hand models': in fluxes, then in the charge), and what each computed.
fn compare(method: &str, runs: &[(&str, Run<'_>)]) {
    let mut times = vec![Vec::new(); runs.len()];
    let mut results = vec![(0, 0.0); runs.len()];
    for _ in 0..ROUNDS {
        for (k, (_, run)) in runs.iter().enumerate() {
            let start = Instant::now();
            results[k] = black_box(run());
            times[k].push(start.elapsed().as_secs_f64());
        }
    }
    let medians: Vec<f64> = times.into_iter().map(median).collect();
    let (fluxes, charge) = (medians[runs.len() - 2], medians[runs.len() - 1]);
    for (k, (name, _)) in runs.iter().enumerate() {
        println!(
            "{method:9} {name:9} {:9.1} µs ({:4} steps, rotor ω = {:.9}) | ratio to by hand in fluxes {:.2}, in the charge {:.2}",
            medians[k] * 1e6,
            results[k].0,
            results[k].1,
            medians[k] / fluxes,
            medians[k] / charge
        );
    }
}

fn main() {
    let parts = Parts {
        source: VoltageSource { u: VOLTS },
        r: Resistor { r: R },
        l: Inductor { l: L },
        emf: Emf { k: K },
        ground: Ground {},
        rotor: Inertia { j: JM },
        gear: IdealGear { ratio: N },
        load: Inertia { j: JL },
        bearing: Damper { d: B },
        housing: Fixed { phi0: 0.0 },
    };
    let zero = VecQ::<Parts>::zeros();
    let start = consistent_state(&parts, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
    let rotor = Parts::NAMES.coordinate_names().iter().position(|n| n == "rotor.phi").expect("the rotor");
    let reduced = Reduced {
        source: parts.source.clone(),
        r: parts.r.clone(),
        l: parts.l.clone(),
        emf: parts.emf.clone(),
        ground: Ground {},
        rotor: parts.rotor.clone(),
        gear: parts.gear.clone(),
        load: parts.load.clone(),
        bearing: parts.bearing.clone(),
        housing: parts.housing.clone(),
    };
    let zero_reduced = VecQ::<Reduced>::zeros();
    let start_reduced = consistent_state(&reduced, 0.0, &zero_reduced, &zero_reduced, Consistency::default())
        .expect("at rest");
    // The rotor turns `ratio` times the load, whose angle the reduced model keeps.
    let load = Reduced::NAMES.coordinate_names().iter().position(|n| n == "gear.b").expect("the load");
    let hand = ByHand { l: L, r: R, k: K, jm: JM, jl: JL, b: B, n: N, volts: VOLTS };
    let zero_hand = VecQ::<ByHand>::zeros();
    let start_hand =
        consistent_state(&hand, 0.0, &zero_hand, &zero_hand, Consistency::default()).expect("at rest");
    let fluxes = ByHandInFluxes { l: L, r: R, k: K, jm: JM, jl: JL, b: B, n: N, volts: VOLTS };
    let zero_fluxes = VecQ::<ByHandInFluxes>::zeros();
    let start_fluxes =
        consistent_state(&fluxes, 0.0, &zero_fluxes, &zero_fluxes, Consistency::default()).expect("at rest");
    let (rtol, atol, end) = (1e-8, 1e-8, 2.0);
    let last = Sampling::Times(vec![end]);
    compare(
        "Radau",
        &[
            ("parts", &|| {
                let mut radau = Radau::new(&parts, RadauOptions::tolerances(rtol, atol)).expect("valid");
                let s = radau.solve(0.0, &start, end, &last).expect("integrates");
                (radau.stats().steps, s.last().expect("a sample").v[rotor])
            }),
            ("reduced", &|| {
                let mut radau = Radau::new(&reduced, RadauOptions::tolerances(rtol, atol)).expect("valid");
                let s = radau.solve(0.0, &start_reduced, end, &last).expect("integrates");
                (radau.stats().steps, N * s.last().expect("a sample").v[load])
            }),
            ("in fluxes", &|| {
                let mut radau = Radau::new(&fluxes, RadauOptions::tolerances(rtol, atol)).expect("valid");
                let s = radau.solve(0.0, &start_fluxes, end, &last).expect("integrates");
                (radau.stats().steps, N * s.last().expect("a sample").v[1])
            }),
            ("by hand", &|| {
                let mut radau = Radau::new(&hand, RadauOptions::tolerances(rtol, atol)).expect("valid");
                let s = radau.solve(0.0, &start_hand, end, &last).expect("integrates");
                (radau.stats().steps, s.last().expect("a sample").v[1])
            }),
        ],
    );
    compare(
        "Explicit",
        &[
            ("parts", &|| {
                let mut explicit =
                    Explicit::new(&parts, ExplicitOptions::tolerances(rtol, atol)).expect("valid");
                let s = explicit.solve(0.0, &start, end, &last).expect("integrates");
                (explicit.stats().steps, s.last().expect("a sample").v[rotor])
            }),
            ("reduced", &|| {
                let mut explicit =
                    Explicit::new(&reduced, ExplicitOptions::tolerances(rtol, atol)).expect("valid");
                let s = explicit.solve(0.0, &start_reduced, end, &last).expect("integrates");
                (explicit.stats().steps, N * s.last().expect("a sample").v[load])
            }),
            ("in fluxes", &|| {
                let mut explicit =
                    Explicit::new(&fluxes, ExplicitOptions::tolerances(rtol, atol)).expect("valid");
                let s = explicit.solve(0.0, &start_fluxes, end, &last).expect("integrates");
                (explicit.stats().steps, N * s.last().expect("a sample").v[1])
            }),
            ("by hand", &|| {
                let mut explicit =
                    Explicit::new(&hand, ExplicitOptions::tolerances(rtol, atol)).expect("valid");
                let s = explicit.solve(0.0, &start_hand, end, &last).expect("integrates");
                (explicit.stats().steps, s.last().expect("a sample").v[1])
            }),
        ],
    );
}
