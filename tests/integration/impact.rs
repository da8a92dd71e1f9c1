//! An impact as a map of the state before it (`dirac::impact::impact_map`), and its derivative.
//!
//! Reference: central differences of the impact itself, the same law solved at positions,
//! velocities, time and parameters moved by `±h` (`h = 1e-6` of the value's scale, error
//! `O(h²)` plus round-off `O(ε/h)`, about 1e-9), on models whose every term of the derivative
//! is exercised: a mass matrix that varies with the positions, a moving constraint whose rows
//! do, a curved and moving contact, restitutions that are products of parameters, and two
//! contacts closing at once.

use dirac::Events;
use dirac::impact::{ImpactMap, impact_map, saltation};
use dirac::nalgebra::{DMatrix, DVector, DefaultAllocator};
use dirac::prelude::*;
use dirac::{Hybrid, Storage};

use crate::zoo::*;

/// A mass `m` on a spring of rest length `l` swinging in polar coordinates `(th, r)`, its
/// mass matrix varying with `r`; a bead `z` of mass `mz` held by a link that stretches
/// (`z = r cos th (1 + c t)`: its row varies with the positions and time); a wall that
/// accelerates (`r sin th ≤ d + s t²`) with restitution `e0 e1`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(th => w, r => vr, z => vz))]
#[dirac(lagrangian = 0.5 * m * (vr * vr + r * r * w * w) + 0.5 * mz * vz * vz + m * g * r * th.cos()
    - 0.5 * k * (r - l) * (r - l))]
#[dirac(holonomic(link) = z - r * th.cos() * (1.0 + c * t))]
#[dirac(unilateral(wall, restitution = e0 * e1) = d + s * t * t - r * th.sin())]
pub struct Swinger {
    pub m: f64,
    pub mz: f64,
    pub g: f64,
    pub k: f64,
    pub l: f64,
    pub c: f64,
    pub e0: f64,
    pub e1: f64,
    pub d: f64,
    pub s: f64,
}

/// The worst difference, relative to the largest entry of each block, between `map`'s
/// derivative and central differences of the impact.
fn worst_against_differences<M: Hybrid + Parameters + Clone>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
    closing: &[usize],
    map: &ImpactMap,
) -> f64
where
    DefaultAllocator: Storage<M>,
{
    let n = model.sizes().nq;
    let after = |model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>| {
        impact_map(model, t, q, v, closing).expect("an impact").velocity
    };
    let mut worst = 0.0f64;
    let mut compare = |exact: Vec<f64>, plus: DVector<f64>, minus: DVector<f64>, h: f64| {
        let differences = (plus - minus) / (2.0 * h);
        let scale = exact.iter().fold(1.0f64, |s, x| s.max(x.abs()));
        for (a, b) in exact.iter().zip(differences.iter()) {
            worst = worst.max((a - b).abs() / scale);
        }
    };
    for c in 0..n {
        let h = 1e-6 * q[c].abs().max(1.0);
        let (mut up, mut down) = (q.clone(), q.clone());
        up[c] += h;
        down[c] -= h;
        compare(
            map.dq.column(c).iter().copied().collect(),
            after(model, t, &up, v),
            after(model, t, &down, v),
            h,
        );
        let h = 1e-6 * v[c].abs().max(1.0);
        let (mut up, mut down) = (v.clone(), v.clone());
        up[c] += h;
        down[c] -= h;
        compare(
            map.dv.column(c).iter().copied().collect(),
            after(model, t, q, &up),
            after(model, t, q, &down),
            h,
        );
    }
    let h = 1e-6;
    compare(map.dt.iter().copied().collect(), after(model, t + h, q, v), after(model, t - h, q, v), h);
    for p in 0..model.parameter_count() {
        let value = model.parameter_value(p);
        let h = 1e-6 * value.abs().max(1.0);
        let (mut up, mut down) = (model.clone(), model.clone());
        up.set_parameter_value(p, value + h);
        down.set_parameter_value(p, value - h);
        compare(
            map.dtheta.column(p).iter().copied().collect(),
            after(&up, t, q, v),
            after(&down, t, q, v),
            h,
        );
    }
    worst
}

#[test]
fn the_derivative_of_an_impact_equals_central_differences_of_it() {
    let swinger =
        Swinger { m: 1.3, mz: 0.4, g: 9.81, k: 20.0, l: 1.0, c: 0.3, e0: 0.9, e1: 0.7, d: 0.5, s: 0.2 };
    let (th, r, t) = (0.4f64, 1.1f64, 0.25);
    let (w, vr, c) = (1.5, 0.3, 0.3);
    let q = VecQ::<Swinger>::new(th, r, r * th.cos() * (1.0 + c * t));
    let vz = (1.0 + c * t) * (vr * th.cos() - r * th.sin() * w) + c * r * th.cos();
    let v = VecQ::<Swinger>::new(w, vr, vz);
    let map = impact_map(&swinger, t, &q, &v, &[0]).expect("an impact");
    assert!(map.impulses[0].1 > 0.0, "the wall pushes: {:?}", map.impulses);
    // The law holds: the wall's normal speed reversed and scaled, the link's rate kept.
    let a = [-r * th.cos(), -th.sin(), 0.0];
    let normal = |v: &[f64]| a.iter().zip(v).map(|(a, v)| a * v).sum::<f64>() + 2.0 * 0.2 * t;
    let (before, after) = (normal(v.as_slice()), normal(map.velocity.as_slice()));
    assert!((after + 0.63 * before).abs() < 1e-12, "normal speed {before} before, {after} after");
    let worst = worst_against_differences(&swinger, t, &q, &v, &[0], &map);
    eprintln!("swinger: worst relative difference {worst:e}");
    assert!(worst < 1e-7, "worst relative difference {worst:e}");
    // Every block is exercised: none of them vanishes.
    for (name, block) in [("q", &map.dq), ("v", &map.dv), ("θ", &map.dtheta)] {
        assert!(block.norm() > 1e-3, "∂v⁺/∂{name} = {block}");
    }
    assert!(map.dt.norm() > 1e-3, "∂v⁺/∂t = {}", map.dt);

    // The pendulum against its wall: a rod and a contact.
    let pendulum = PendulumAndWall { m: 1.2, g: 9.81, l: 0.8, e: 0.6, w: 0.3 };
    let angle = 0.5f64;
    let q = VecQ::<PendulumAndWall>::new(0.8 * angle.sin(), -0.8 * angle.cos());
    let v = VecQ::<PendulumAndWall>::new(-2.0 * angle.cos(), -2.0 * angle.sin());
    let map = impact_map(&pendulum, 0.0, &q, &v, &[0]).expect("an impact");
    let worst = worst_against_differences(&pendulum, 0.0, &q, &v, &[0], &map);
    eprintln!("pendulum: worst relative difference {worst:e}");
    assert!(worst < 1e-7, "pendulum: worst relative difference {worst:e}");

    // A bar falling flat and turning, so that both ends strike at once, with different speeds.
    let bar = Bar { m: 1.0, j: 0.2, g: 9.81, l: 1.0, e: 0.5 };
    let q = VecQ::<Bar>::new(0.0, 0.0, 0.0);
    let v = VecQ::<Bar>::new(0.3, -1.0, 0.4);
    let map = impact_map(&bar, 0.0, &q, &v, &[0, 1]).expect("an impact");
    assert!(map.impulses.iter().all(|&(_, l)| l > 0.0), "both ends pushed: {:?}", map.impulses);
    let worst = worst_against_differences(&bar, 0.0, &q, &v, &[0, 1], &map);
    eprintln!("bar: worst relative difference {worst:e}");
    assert!(worst < 1e-7, "bar: worst relative difference {worst:e}");
}

/// An interconnection's contacts have no generated second derivatives: refused by name.
#[test]
fn the_derivative_of_an_interconnections_impact_is_refused() {
    let loaded = LoadedBall { ball: PortedBall { m: 1.0, g: 9.81, e: 0.8 }, load: Load { m: 0.5 } };
    let sizes = loaded.sizes();
    let mut v = sizes.zeros_q::<LoadedBall>();
    v.fill(-1.0);
    let error = impact_map(&loaded, 0.0, &sizes.zeros_q::<LoadedBall>(), &v, &[0])
        .expect_err("no second derivatives");
    assert!(matches!(&error, SimError::InvalidOption { what: "impact", .. }), "{error}");
}

/// Bad input ends in a typed error naming the cause: a contact the model does not have, one
/// not among the closing ones, one that is not approaching, velocities that are not finite.
#[test]
fn impacts_of_bad_input_are_refused_by_name() {
    let ball = BouncingBall { m: 1.0, g: 9.81, e: 0.8 };
    let (q, down, up) =
        (VecQ::<BouncingBall>::new(0.0), VecQ::<BouncingBall>::new(-2.0), VecQ::<BouncingBall>::new(2.0));
    let error = impact_map(&ball, 0.0, &q, &down, &[3]).expect_err("no contact 3");
    assert!(matches!(&error, SimError::InvalidOption { what: "impact", .. }), "{error}");
    let error = saltation(&ball, 0.0, &q, &down, 3, &[3]).expect_err("no contact 3");
    assert!(matches!(&error, SimError::InvalidOption { what: "impact", .. }), "{error}");
    let error = saltation(&ball, 0.0, &q, &down, 0, &[]).expect_err("not closing");
    assert!(matches!(&error, SimError::InvalidOption { what: "saltation", .. }), "{error}");
    let error = saltation(&ball, 0.0, &q, &up, 0, &[0]).expect_err("leaving the floor");
    assert!(matches!(&error, SimError::InvalidOption { what: "saltation", .. }), "{error}");
    let error = impact_map(&ball, 0.0, &q, &VecQ::<BouncingBall>::new(f64::NAN), &[0]).expect_err("NaN");
    assert!(matches!(&error, SimError::NonFinite { .. }), "{error}");
}

/// The bar in free flight (`x`, `y` ballistic, `th` turning steadily) at time `t` from
/// `(q0, v0)`: its flow is known in closed form, and so is the flow's derivative over `τ`,
/// `[[I, τ I], [0, I]]`.
fn bar_in_flight(q0: &[f64; 3], v0: &[f64; 3], t: f64) -> ([f64; 3], [f64; 3]) {
    let q = [q0[0] + v0[0] * t, q0[1] + v0[1] * t - 0.5 * 9.81 * t * t, q0[2] + v0[2] * t];
    (q, [v0[0], v0[1] - 9.81 * t, v0[2]])
}

fn free_flight(tau: f64) -> DMatrix<f64> {
    let mut flow = DMatrix::identity(6, 6);
    for i in 0..3 {
        flow[(i, 3 + i)] = tau;
    }
    flow
}

/// The bar's state at `t_end` from `(q0, v0)` at 0, simulated through its impacts, and the
/// impacts (contact, time).
fn bar_at(bar: &Bar, q0: &[f64], v0: &[f64], t_end: f64) -> (DVector<f64>, Vec<(usize, f64)>) {
    let q = VecQ::<Bar>::from_column_slice(q0);
    let v = VecQ::<Bar>::from_column_slice(v0);
    let start = consistent_state(bar, 0.0, &q, &v, Consistency::default()).expect("a start");
    let mut radau = Radau::new(bar, RadauOptions::tolerances(1e-13, 1e-13)).expect("valid");
    let solution = radau
        .solve_with_events(0.0, &start, t_end, &Sampling::Steps, &mut Events::new().contacts(bar), |_, _| {
            std::ops::ControlFlow::Continue(())
        })
        .expect("integrates");
    let end = solution.last().expect("samples");
    let impacts = solution.impacts().iter().map(|impact| (impact.contact, impact.t)).collect();
    (DVector::from_iterator(6, end.q.iter().chain(end.v.iter()).copied()), impacts)
}

/// The saltation matrix of a bar's end striking the floor, carried by the bar's free flight
/// before and after (closed form), equals the derivative of whole simulations through the
/// impact by central differences (their events located on the dense output, the impact's
/// time moving with the start), with respect to the starting state and to the parameters
/// the flight does not depend on (mass, inertia, length, restitution).
#[test]
fn the_saltation_matrix_carries_changes_of_a_simulation_across_its_impact() {
    let bar = Bar { m: 1.0, j: 0.2, g: 9.81, l: 1.0, e: 0.5 };
    let (q0, v0) = ([0.0, 0.6, 0.3], [0.2, -1.0, 0.5]);
    // The left end strikes first, once, before `t_end`.
    let t_end = 0.27;
    let (_, impacts) = bar_at(&bar, &q0, &v0, t_end);
    assert!(matches!(impacts[..], [(0, _)]), "the left end strikes once: {impacts:?}");
    let strike = impacts[0].1;
    let (q, v) = bar_in_flight(&q0, &v0, strike);
    let (q, v) = (VecQ::<Bar>::from_column_slice(&q), VecQ::<Bar>::from_column_slice(&v));
    let jump = saltation(&bar, strike, &q, &v, 0, &[0]).expect("an impact");
    let through = free_flight(t_end - strike) * &jump.matrix * free_flight(strike);
    let mut worst = 0.0f64;
    let scale = through.amax();
    for c in 0..6 {
        let h = 1e-5;
        let (mut up, mut down) = ([q0, v0].concat(), [q0, v0].concat());
        up[c] += h;
        down[c] -= h;
        let (plus, _) = bar_at(&bar, &up[..3], &up[3..], t_end);
        let (minus, _) = bar_at(&bar, &down[..3], &down[3..], t_end);
        let differences = (plus - minus) / (2.0 * h);
        worst = worst.max((differences - through.column(c)).amax() / scale);
    }
    eprintln!("bar through its impact, state: worst relative difference {worst:e}");
    assert!(worst < 1e-8, "worst relative difference {worst:e}");
    let carried = free_flight(t_end - strike) * &jump.parameters;
    for p in [0, 1, 3, 4] {
        let value = bar.parameter_value(p);
        let h = 1e-5 * value;
        let (mut up, mut down) = (bar.clone(), bar.clone());
        up.set_parameter_value(p, value + h);
        down.set_parameter_value(p, value - h);
        let differences = (bar_at(&up, &q0, &v0, t_end).0 - bar_at(&down, &q0, &v0, t_end).0) / (2.0 * h);
        let error = (&differences - carried.column(p)).amax() / differences.amax().max(1.0);
        eprintln!("bar through its impact, parameter {p}: relative difference {error:e}");
        assert!(error < 1e-8, "parameter {p}: {differences} against {}", carried.column(p));
    }

    // Forward sensitivities carried through the same impact by the solve.
    let mut wrt = Sensitivities::all_parameters(&bar);
    for c in [Bar::X, Bar::Y, Bar::TH] {
        wrt = wrt.initial_position(c).initial_velocity(c);
    }
    let q = VecQ::<Bar>::from_column_slice(&q0);
    let v = VecQ::<Bar>::from_column_slice(&v0);
    let start = consistent_state(&bar, 0.0, &q, &v, Consistency::default()).expect("a start");
    let solution = Radau::new(&bar, RadauOptions::tolerances(1e-12, 1e-12))
        .expect("valid")
        .with_sensitivities(&wrt)
        .expect("valid")
        .solve_with_sensitivities(0.0, &start, t_end, &Sampling::Times(vec![t_end]))
        .expect("integrates through the impact");
    let state = ["x", "y", "th", "vx", "vy", "w"];
    let mut worst = 0.0f64;
    for (c, initial) in state.iter().enumerate() {
        for (i, quantity) in state.iter().enumerate() {
            let got = solution.sensitivity(quantity, &format!("{initial}(t0)")).expect("a sensitivity")[0];
            worst = worst.max((got - through[(i, c)]).abs() / scale);
        }
    }
    for (p, name) in [(0, "m"), (1, "j"), (3, "l"), (4, "e")] {
        for (i, quantity) in state.iter().enumerate() {
            let got = solution.sensitivity(quantity, name).expect("a sensitivity")[0];
            worst = worst.max((got - carried[(i, p)]).abs() / carried.column(p).amax().max(1.0));
        }
    }
    eprintln!("bar through its impact, forward sensitivities: worst relative difference {worst:e}");
    assert!(worst < 1e-8, "forward sensitivities: worst relative difference {worst:e}");
}
