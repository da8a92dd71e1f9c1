//! Systems assembled from `dirac::components` alone, with each integrator, against closed forms
//! and hand-reduced equations derived in each test. The parts follow the connector convention:
//! a pin's coordinate is its node's flux (its velocity the voltage), a flange's its position or
//! angle, and a connection makes the velocities equal and the through quantities (current,
//! torque) sum to zero: Kirchhoff's current law and Newton's third law at every node, with no
//! equation written for them.

use dirac::Drive;
use dirac::State;
use dirac::components::electrical::{Capacitor, Ground, Inductor, Resistor, StepVoltage, VoltageSource};
use dirac::components::electromechanical::Emf;
use dirac::components::rotational::{self as rot, Clutch, IdealGear, Inertia, Torque};
use dirac::nalgebra::{Matrix2, Matrix4, Vector2, Vector4};
use dirac::prelude::*;
use dirac::sources::{Hold, Table};

use super::{Fineness, Method};

/// The index of the coordinate named `name` in model `M`.
fn index<M: Named>(name: &str) -> usize {
    let names = M::NAMES.coordinate_names();
    names.iter().position(|n| n == name).unwrap_or_else(|| panic!("no `{name}` in {names:?}"))
}

/// A series RLC circuit switched onto a constant source at `t = 0`: five parts, five
/// connections, no hand-written Lagrangian.
#[derive(Interconnection, Clone, Debug)]
#[dirac(
    connect(source.p, r.p),
    connect(r.n, l.p),
    connect(l.n, c.p),
    connect(c.n, ground.p),
    connect(source.n, ground.p)
)]
pub struct SeriesRlc {
    pub source: VoltageSource,
    pub r: Resistor,
    pub l: Inductor,
    pub c: Capacitor,
    pub ground: Ground,
}

/// The series RLC's step response with each integrator, from rest. Closed form (underdamped,
/// `α = R/2L < ω₀ = 1/√(LC)`): the capacitor's voltage `U (1 − e^{−αt} (cos ω_d t + α/ω_d sin
/// ω_d t))`, `ω_d = √(ω₀² − α²)`, and the current through every part the same,
/// `C d(vc)/dt = U/(L ω_d) e^{−αt} sin ω_d t`. Measured at t = 1, 3, 10 (voltage, current):
/// Explicit at rtol 1e-10 within 6e-11 and 1.2e-10; Radau 1e-12 at t = 1 and 10, 5.9e-9 and
/// 5.0e-9 at t = 3, a sample inside a step, where its dense output has the stage order;
/// Variational at h = 1e-3 within 2.6e-8 and 1.1e-7.
#[test]
fn a_series_rlc_from_parts_against_its_closed_form() {
    let (u, r, l, c) = (1.0, 0.5, 1.0, 1.0);
    let circuit = SeriesRlc {
        source: VoltageSource { u },
        r: Resistor { r },
        l: Inductor { l },
        c: Capacitor { c },
        ground: Ground {},
    };
    let (alpha, w0) = (r / (2.0 * l), 1.0 / (l * c).sqrt());
    let wd = (w0 * w0 - alpha * alpha).sqrt();
    let vc = |t: f64| u * (1.0 - (-alpha * t).exp() * ((wd * t).cos() + alpha / wd * (wd * t).sin()));
    let current = |t: f64| u / (l * wd) * (-alpha * t).exp() * (wd * t).sin();
    let zero = VecQ::<SeriesRlc>::zeros();
    let start = consistent_state(&circuit, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
    let times = vec![1.0, 3.0, 10.0];
    each_integrator!(&circuit, Fineness::new(1e-10, 1e-12, 1e-3), |method, integrator| {
        let solution = integrator
            .solve(0.0, &start, 10.0, &Sampling::Times(times.clone()))
            .unwrap_or_else(|e| panic!("{method:?}: {e}"));
        let bound = match method {
            Method::Variational => 1e-7,
            Method::Radau => 3e-8,
            Method::Explicit => 1e-9,
        };
        let voltages = solution.output(SeriesRlc::c_output(Capacitor::V));
        // The resistor's and the inductor's currents, each from its own law: the same current,
        // as the connections say.
        let through_r = solution.output(SeriesRlc::r_output(Resistor::I));
        let through_l = solution.output(SeriesRlc::l_output(Inductor::I));
        for (k, &t) in times.iter().enumerate() {
            assert!(
                (voltages[k] - vc(t)).abs() < bound,
                "{method:?} at {t}: vc {}, closed form {}",
                voltages[k],
                vc(t)
            );
            for i in [through_r[k], through_l[k]] {
                assert!(
                    (i - current(t)).abs() < 3.0 * bound,
                    "{method:?} at {t}: i {i}, closed form {}",
                    current(t)
                );
            }
        }
    });
}

/// The series RLC reduced when it compiles: the connections merge, the ground is zero, and
/// three node fluxes remain with the source's row.
#[derive(Interconnection, Clone, Debug)]
#[dirac(reduce)]
#[dirac(
    connect(source.p, r.p),
    connect(r.n, l.p),
    connect(l.n, c.p),
    connect(c.n, ground.p),
    connect(source.n, ground.p)
)]
pub struct SeriesRlcReduced {
    pub source: VoltageSource,
    pub r: Resistor,
    pub l: Inductor,
    pub c: Capacitor,
    pub ground: Ground,
}

/// The reduced series RLC's step response with each integrator, against the same closed form
/// and bounds as the unreduced circuit's above, read by the parts' output names; the
/// variational integrator's currents (second order in h = 1e-3) within 1e-6, measured 3.1e-7
/// at t = 1.
#[test]
fn a_reduced_series_rlc_against_its_closed_form() {
    // The source's node leaves with its row: the resistor reads its voltage, the input.
    assert_eq!(SeriesRlcReduced::NAMES.coordinate_names(), ["r.n", "l.n"]);
    assert!(SeriesRlcReduced::NAMES.constraint_names().is_empty());
    let (u, r, l, c) = (1.0, 0.5, 1.0, 1.0);
    let circuit = SeriesRlcReduced {
        source: VoltageSource { u },
        r: Resistor { r },
        l: Inductor { l },
        c: Capacitor { c },
        ground: Ground {},
    };
    let (alpha, w0) = (r / (2.0 * l), 1.0 / (l * c).sqrt());
    let wd = (w0 * w0 - alpha * alpha).sqrt();
    let vc = |t: f64| u * (1.0 - (-alpha * t).exp() * ((wd * t).cos() + alpha / wd * (wd * t).sin()));
    let current = |t: f64| u / (l * wd) * (-alpha * t).exp() * (wd * t).sin();
    let zero = VecQ::<SeriesRlcReduced>::zeros();
    let start = consistent_state(&circuit, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
    let times = vec![1.0, 3.0, 10.0];
    each_integrator!(&circuit, Fineness::new(1e-10, 1e-12, 1e-3), |method, integrator| {
        let solution = integrator
            .solve(0.0, &start, 10.0, &Sampling::Times(times.clone()))
            .unwrap_or_else(|e| panic!("{method:?}: {e}"));
        let bound = match method {
            Method::Variational => 1e-7,
            Method::Radau => 3e-8,
            Method::Explicit => 1e-9,
        };
        let output = |name: &str| solution.column(&format!("out({name})")).expect("an output").to_vec();
        // The source's current flows into its pin `p` (the through quantity's convention): the
        // loop's current leaves it there, so it reads minus the loop's.
        let (voltages, through_r, through_l, into_source) =
            (output("c.v"), output("r.i"), output("l.i"), output("source.i"));
        for (k, &t) in times.iter().enumerate() {
            assert!(
                (voltages[k] - vc(t)).abs() < bound,
                "{method:?} at {t}: vc {}, closed form {}",
                voltages[k],
                vc(t)
            );
            let current_bound = if method == Method::Variational { 1e-6 } else { 3.0 * bound };
            for i in [through_r[k], through_l[k], -into_source[k]] {
                assert!(
                    (i - current(t)).abs() < current_bound,
                    "{method:?} at {t}: i {i}, closed form {}",
                    current(t)
                );
            }
        }
    });
}

/// The series RLC driven by a table of voltages, held or interpolated, with each integrator:
/// the drive sets the source's input at every evaluation and the steps end at the table's
/// samples ([`Drive::stop_at`]). Reference, computed here independently of the integrators:
/// on each interval between samples the source's voltage is `u + s (t − t_k)`, and the state
/// `(vc, i, u, s)` of `C vc' = i`, `L i' = u − R i − vc`, `u' = s`, `s' = 0` moves by the
/// matrix exponential of that linear system over the interval; the capacitor's voltage and
/// the current carry over each sample, the voltage and its slope start afresh from the table.
/// Measured (rtol 1e-10, h = 1e-3; the largest error over the samples, some inside steps):
/// held, Radau 9.7e-9, Explicit 1.9e-11, Variational 1.9e-7; interpolated, Radau 2.2e-9,
/// Explicit 3.2e-11, Variational 1.6e-7. The source's voltage prescribes a velocity: where the
/// held voltage jumps, the velocities jump with it; where the interpolated one moves, Explicit
/// takes its rate from the drive.
#[test]
fn a_series_rlc_driven_by_a_table_against_its_exact_solution() {
    let (r, l, c) = (0.5, 1.0, 1.0);
    let times = vec![0.0, 0.7, 1.5, 2.2, 3.1, 4.0];
    let volts = vec![1.0, -0.5, 2.0, 0.3, -1.0, 0.5];
    let t_end = 5.0;
    let samples = vec![0.35, 0.7, 2.0, 3.1, 3.6, 5.0];
    for hold in [Hold::Zero, Hold::Linear] {
        let table = Table::new(times.clone(), volts.clone(), hold).expect("a valid table");
        // The exact solution at `t`, interval by interval.
        let a = Matrix4::new(
            0.0,
            1.0 / c,
            0.0,
            0.0, //
            -1.0 / l,
            -r / l,
            1.0 / l,
            0.0, //
            0.0,
            0.0,
            0.0,
            1.0, //
            0.0,
            0.0,
            0.0,
            0.0,
        );
        let exact = |t: f64| {
            let (mut x, mut from) = (Vector4::zeros(), 0.0);
            for (k, &tk) in times.iter().enumerate() {
                let next = times.get(k + 1).copied().unwrap_or(f64::INFINITY);
                let slope = match (hold, times.get(k + 1)) {
                    (Hold::Linear, Some(&tn)) => (volts[k + 1] - volts[k]) / (tn - tk),
                    _ => 0.0,
                };
                x = (a * (tk - from)).exp() * x;
                (x[2], x[3], from) = (volts[k], slope, tk);
                if t <= next {
                    break;
                }
            }
            (a * (t - from)).exp() * x
        };
        let mut circuit = SeriesRlc {
            source: VoltageSource { u: table.at(0.0) },
            r: Resistor { r },
            l: Inductor { l },
            c: Capacitor { c },
            ground: Ground {},
        };
        let zero = VecQ::<SeriesRlc>::zeros();
        let start = consistent_state(&circuit, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
        let u = SeriesRlc::source_input(VoltageSource::U);
        let mut source = |t: f64, _: &State<SeriesRlc>, m: &mut SeriesRlc| m.set_input(u, table.at(t));
        each_integrator!(&mut circuit, Fineness::new(1e-10, 1e-12, 1e-3), |method, integrator| {
            // The closure is borrowed by each integrator in turn.
            integrator.drive(&mut source).expect("an exclusive model");
            integrator.stop_at(table.times()).expect("finite times");
            let solution = integrator
                .solve(0.0, &start, t_end, &Sampling::Times(samples.clone()))
                .unwrap_or_else(|e| panic!("{method:?}: {e}"));
            let vc = solution.output(SeriesRlc::c_output(Capacitor::V));
            let current = solution.output(SeriesRlc::l_output(Inductor::I));
            let bound = match method {
                Method::Variational => 1e-6,
                Method::Radau => 3e-8,
                Method::Explicit => 1e-9,
            };
            for (k, &t) in samples.iter().enumerate() {
                let x = exact(t);
                let error = (vc[k] - x[0]).abs().max((current[k] - x[1]).abs());
                assert!(
                    error < bound,
                    "{method:?}, {hold:?} at {t}: vc {} i {} against {x}",
                    vc[k],
                    current[k]
                );
            }
            // Every stop inside the span is a step's end.
            let steps = integrator.solve(0.0, &start, t_end, &Sampling::Steps).expect("integrates");
            for stop in &times[1..] {
                assert!(steps.t().contains(stop), "{method:?}: no step ends at {stop}");
            }
        });
    }
}

/// A DC motor (armature resistance and inductance, EMF, rotor) driving a load through a
/// gearbox, the load's bearing a viscous damper to a fixed housing: ten parts.
#[derive(Interconnection, Clone, Debug)]
#[dirac(
    connect(source.p, r.p),
    connect(r.n, l.p),
    connect(l.n, emf.p),
    connect(emf.n, ground.p),
    connect(source.n, ground.p),
    connect(emf.phi, rotor.phi),
    connect(rotor.phi, gear.a),
    connect(gear.b, load.phi),
    connect(load.phi, bearing.b),
    connect(bearing.a, housing.phi)
)]
pub struct GearedMotor {
    pub source: StepVoltage,
    pub r: Resistor,
    pub l: Inductor,
    pub emf: Emf,
    pub ground: Ground,
    pub rotor: Inertia,
    pub gear: IdealGear,
    pub load: Inertia,
    pub bearing: rot::Damper,
    pub housing: rot::Fixed,
}

/// The geared motor's step response against the hand-reduced linear ODE in the armature
/// current `i` and the motor speed `ω`: `L di/dt = V − R i − k ω`,
/// `(J_m + J_l/n²) dω/dt = k i − (d/n²) ω` (the load's inertia and damping seen through the
/// gear of ratio `n`), solved exactly by the matrix exponential: `x(t) = x∞ + e^{At}(x₀ − x∞)`.
/// Its steady state: `ω∞ = V / (k + R d/(k n²))`, `i∞ = d ω∞/(k n²)`.
#[test]
fn a_geared_dc_motor_against_its_reduced_equations() {
    let (volts, r, l, k, jm, jl, d, n) = (12.0, 1.0, 0.05, 0.5, 0.01, 0.05, 0.1, 4.0);
    let drive = GearedMotor {
        source: StepVoltage { offset: 0.0, height: volts, start: 0.0 },
        r: Resistor { r },
        l: Inductor { l },
        emf: Emf { k },
        ground: Ground {},
        rotor: Inertia { j: jm },
        gear: IdealGear { ratio: n },
        load: Inertia { j: jl },
        bearing: rot::Damper { d },
        housing: rot::Fixed { phi0: 0.0 },
    };
    let j = jm + jl / (n * n);
    let a = Matrix2::new(-r / l, -k / l, k / j, -d / (n * n * j));
    let w_inf = volts / (k + r * d / (k * n * n));
    let steady = Vector2::new(d * w_inf / (k * n * n), w_inf);
    let reduced = |t: f64| steady + (a * t).exp() * (Vector2::zeros() - steady);
    let zero = VecQ::<GearedMotor>::zeros();
    let start = consistent_state(&drive, 0.0, &zero, &zero, Consistency::default()).expect("at rest");
    let (rotor, load) = (index::<GearedMotor>("rotor.phi"), index::<GearedMotor>("load.phi"));
    // At 2 s the motor is steady to e^{-40} (its time constants are 0.05 s): Explicit, which
    // would go on to the stability limit of its steps there, stops with the others.
    let times = vec![0.02, 0.1, 0.5, 1.0, 2.0];
    each_integrator!(&drive, Fineness::new(1e-10, 1e-12, 1e-4), |method, integrator| {
        let solution = integrator
            .solve(0.0, &start, 2.0, &Sampling::Times(times.clone()))
            .unwrap_or_else(|e| panic!("{method:?}: {e}"));
        let current = solution.output(GearedMotor::l_output(Inductor::I));
        let bound = if method == Method::Variational { 1e-5 } else { 1e-7 };
        for (s, &t) in times.iter().enumerate() {
            let state = solution.state(s).expect("a sample");
            let expected = reduced(t);
            let (i, w) = (current[s], state.v[rotor]);
            assert!(
                (i - expected[0]).abs() < bound * volts,
                "{method:?} at {t}: i {i}, reduced {}",
                expected[0]
            );
            assert!(
                (w - expected[1]).abs() < bound * w_inf,
                "{method:?} at {t}: ω {w}, reduced {}",
                expected[1]
            );
            assert!((state.v[load] * n - w).abs() < 1e-8 * w_inf, "{method:?}: the gear's ratio");
        }
        let last = times.len() - 1;
        assert!((solution.state(last).expect("a sample").v[rotor] - w_inf).abs() < bound * w_inf);
    });
}

/// Two inertias joined by a friction clutch, the first driven by a constant torque.
#[derive(Interconnection, Clone, Debug)]
#[dirac(connect(motor.phi, first.phi), connect(first.phi, clutch.a), connect(clutch.b, second.phi))]
pub struct Drivetrain {
    pub motor: Torque,
    pub first: Inertia,
    pub clutch: Clutch,
    pub second: Inertia,
}

/// The clutch slips, then engages: from `ω₁ = ω₀`, `ω₂ = 0`, slipping under the kinetic torque
/// `T_k`, `j₁ ω₁' = τ − T_k` and `j₂ ω₂' = T_k` until the speeds meet at
/// `t* = ω₀ / (T_k/j₂ − (τ − T_k)/j₁)`; then the clutch sticks, since the torque that holds the
/// second inertia, `j₂ τ/(j₁ + j₂)`, is within the stiction `T_s`, and both accelerate at
/// `τ/(j₁ + j₂)`. With the values below, `t* = 2` and the common speed there is 2.
#[test]
fn a_clutch_slips_then_engages() {
    let (j1, j2, tau, tk, ts, w0) = (1.0, 2.0, 1.5, 2.0, 3.0, 3.0);
    let drivetrain = Drivetrain {
        motor: Torque { tau },
        first: Inertia { j: j1 },
        clutch: Clutch { kinetic: tk, stiction: ts, engaged: 1.0 },
        second: Inertia { j: j2 },
    };
    let t_star = w0 / (tk / j2 - (tau - tk) / j1);
    let w_star = tk / j2 * t_star;
    let speeds = |t: f64| {
        if t < t_star {
            (w0 + (tau - tk) / j1 * t, tk / j2 * t)
        } else {
            let w = w_star + tau / (j1 + j2) * (t - t_star);
            (w, w)
        }
    };
    let mut v = VecQ::<Drivetrain>::zeros();
    for name in ["motor.phi", "first.phi", "clutch.a"] {
        v[index::<Drivetrain>(name)] = w0;
    }
    let start = consistent_state(&drivetrain, 0.0, &VecQ::<Drivetrain>::zeros(), &v, Consistency::default())
        .expect("slipping");
    let (first, second) = (index::<Drivetrain>("first.phi"), index::<Drivetrain>("second.phi"));
    let times = vec![1.0, 1.9, 2.1, 3.0, 5.0];
    each_integrator!(&drivetrain, Fineness::new(1e-10, 1e-12, 1e-3), |method, integrator| {
        let solution = integrator
            .solve(0.0, &start, 5.0, &Sampling::Times(times.clone()))
            .unwrap_or_else(|e| panic!("{method:?}: {e}"));
        let transmitted = solution.output(Drivetrain::clutch_output(Clutch::TAU));
        let bound = if method == Method::Variational { 1e-6 } else { 1e-8 };
        for (s, &t) in times.iter().enumerate() {
            let state = solution.state(s).expect("a sample");
            let (w1, w2) = speeds(t);
            assert!(
                (state.v[first] - w1).abs() < bound,
                "{method:?} at {t}: ω₁ {} against {w1}",
                state.v[first]
            );
            assert!(
                (state.v[second] - w2).abs() < bound,
                "{method:?} at {t}: ω₂ {} against {w2}",
                state.v[second]
            );
            // On the first inertia the clutch puts −T_k while slipping and minus the holding
            // torque once stuck (its `tau`, the torque on what is at `a`).
            let expected = if t < t_star { -tk } else { -j2 * tau / (j1 + j2) };
            assert!(
                (transmitted[s] - expected).abs() < 1e-6,
                "{method:?} at {t}: the clutch passes {} against {expected}",
                transmitted[s]
            );
        }
    });
}
