//! Coulomb's isotropic friction cone: `friction(slip, kinetic = mu * floor) = (vx, vy)` pushes
//! against the slip in the plane of its two tangent velocities with `μ λ_floor`, holds while
//! the force that holds it stays within `μ λ_floor`, and slips against that force where it
//! reaches it. The references are closed forms and quadratures of the puck's motion, and the
//! invariants of a top: its spin about its axis (friction at the tip has no moment about it),
//! its energy less the friction's work, and, once its tip holds, the Lagrange top's integrals
//! and the turning points of its nutation, computed from them here.

use dirac::prelude::*;
use dirac::{Coordinate, SimError, State};

use crate::contact_friction::start;
use crate::every_method::{Fineness, Method};
use crate::util::check_jacobian_by_differences;
use crate::zoo::{FlatPuck, GroundTop, Puck, TowingPuck};

const G: f64 = 9.81;

/// What a run leaves to check: its times, a coordinate's samples and its events by name.
struct Run {
    t: Vec<f64>,
    x: Vec<f64>,
    y: Vec<f64>,
    events: Vec<(String, f64)>,
    last: Vec<f64>,
}

/// Solves `model` from `start` to `t_end` with `method` (Radau and Explicit at tolerance
/// `tol`, the variational integrator at step `h`).
fn run<M: Hybrid>(
    model: &M,
    start: &State<M>,
    t_end: f64,
    (method, tol, h): (Method, f64, f64),
    (x, y): (Coordinate<M>, Coordinate<M>),
) -> Result<Run, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let fineness = Fineness::new(tol, tol, h);
    macro_rules! solve {
        ($integrator:expr) => {{
            let solution = $integrator?.solve(0.0, start, t_end, &Sampling::Steps)?;
            let events =
                solution.events().iter().map(|e| (solution.event_name(e).to_string(), e.t)).collect();
            let last = solution.last().expect("a sample").v.as_slice().to_vec();
            Ok(Run {
                t: solution.t().to_vec(),
                x: solution.q(x).to_vec(),
                y: solution.q(y).to_vec(),
                events,
                last,
            })
        }};
    }
    match method {
        Method::Radau => solve!(Radau::new(model, fineness.radau())),
        Method::Explicit => solve!(Explicit::new(model, fineness.explicit())),
        Method::Variational => solve!(Variational::new(model, fineness.h, fineness.variational())),
    }
}

const METHODS: [Method; 3] = [Method::Radau, Method::Explicit, Method::Variational];

#[test]
fn a_puck_slides_to_a_stop_along_its_slip() {
    // Thrown at 3 m/s along 0.5 rad: the friction force μ m g stays against the slip, so it stops
    // at `v0 / (μ g)` after `v0² / (2 μ g)` along its line, and holds there.
    let (mu, v0, angle) = (0.4, 3.0, 0.5f64);
    let puck = Puck { m: 2.0, g: G, mu, push: 0.0, angle: 0.0, side: 0.0 };
    let start = start(&puck, &[], &[v0 * angle.cos(), v0 * angle.sin()]);
    let direction = [start.q[Puck::SLIP_MODE_1.index()], start.q[Puck::SLIP_MODE_2.index()]];
    assert!(
        (direction[0] - angle.cos()).abs() < 1e-15 && (direction[1] - angle.sin()).abs() < 1e-15,
        "it slips along its velocity: {direction:?}"
    );
    let stops = v0 / (mu * G);
    for method in METHODS {
        let run = run(&puck, &start, 2.0, (method, 1e-10, 1e-3), (Puck::X, Puck::Y)).expect("solves");
        assert_eq!(run.events.len(), 1, "{method:?}: {:?}", run.events);
        assert_eq!(run.events[0].0, "slip_stops");
        // The stop is read where the slip has turned back by 2e-9 (the derive's margin, above
        // round-off where slips start), 2e-9 / (μ g) = 5.1e-10 s after it. Measured: 5.1e-10
        // (Radau, Explicit, Variational).
        let late = 2e-9 / (mu * G);
        assert!((run.events[0].1 - stops - late).abs() < 1e-12, "{method:?}: stops at {}", run.events[0].1);
        for (k, &t) in run.t.iter().enumerate() {
            let tc = t.min(stops);
            let s = v0 * tc - 0.5 * mu * G * tc * tc;
            let (x, y) = (run.x[k], run.y[k]);
            // Measured: 1.1e-15 (Radau), 2.6e-14 (Explicit, Variational at h = 1e-3).
            assert!(
                (x - s * angle.cos()).abs().max((y - s * angle.sin()).abs()) < 1e-12,
                "{method:?} at {t}: ({x}, {y}) against {s} along the line"
            );
        }
        assert!(run.last.iter().all(|v| v.abs() < 1e-12), "{method:?}: held at rest, {:?}", run.last);
    }
}

#[test]
fn a_pushed_puck_slips_along_the_push_where_it_reaches_the_bound() {
    // Pushed from rest with `c t` along 0.7 rad: held until `c t_s = μ m g`, then it slips along
    // the push, `m s'' = c (t − t_s)`, so `s = c (t − t_s)³ / (6 m)`.
    let (m, mu, c, angle) = (2.0, 0.4, 10.0, 0.7f64);
    let puck = Puck { m, g: G, mu, push: c, angle, side: 0.0 };
    let start = start(&puck, &[], &[]);
    assert_eq!(start.q[Puck::SLIP_MODE_1.index()], 0.0, "stuck");
    let slips = mu * m * G / c;
    for (method, bound) in [(Method::Radau, 1e-10), (Method::Variational, 1e-6)] {
        let run = run(&puck, &start, 2.0, (method, 1e-11, 1e-3), (Puck::X, Puck::Y)).expect("solves");
        assert_eq!(run.events.len(), 1, "{method:?}: {:?}", run.events);
        assert_eq!(run.events[0].0, "slip_slips");
        assert!((run.events[0].1 - slips).abs() < 1e-9, "{method:?}: slips at {}", run.events[0].1);
        // Measured: 2.1e-15 (Radau); 3.9e-7 (Variational at h = 1e-3, second order: 3.9e-9 at
        // 1e-4, with the slip's direction evaluated at the step's own velocity; held at the
        // start's, its stiffness across the slip kicked the velocity by 2e-4).
        for (k, &t) in run.t.iter().enumerate() {
            let s = if t > slips { c * (t - slips).powi(3) / (6.0 * m) } else { 0.0 };
            let (x, y) = (run.x[k], run.y[k]);
            assert!(
                (x - s * angle.cos()).abs().max((y - s * angle.sin()).abs()) < bound,
                "{method:?} at {t}: ({x}, {y}) against {s} along the push"
            );
        }
    }
    // A slip that starts from rest is stiff across it (Coulomb's force turns with the slip's
    // direction at a rate that grows as the slip is slow): Explicit says so and stops.
    let err = run(&puck, &start, 2.0, (Method::Explicit, 1e-10, 1e-3), (Puck::X, Puck::Y)).err();
    assert!(matches!(err, Some(SimError::Unstable { .. })), "{:?}", err.map(|e| e.to_string()));
}

/// The stop of a puck thrown at 3 m/s along x with a side force of half the friction along
/// y, from `tests/references/cone_curve.py` (mpmath quadratures of the motion's closed form
/// in the velocity's angle, 30 digits): time, x and y. They equal [`curve_stop`]'s.
const CURVE_STOP: [f64; 3] = [1.019_367_991_845_056, 1.223_241_590_214_067, 0.382_262_996_941_896];

/// Where a puck thrown at `v0` along x stops under the side force `k μ m g` along y (`k < 1`):
/// time and position, the closed forms that `tests/references/cone_curve.py` finds equal to
/// its quadratures to 30 digits at k = 1/2, 1/3 and 1/4.
fn curve_stop(v0: f64, mu: f64, g: f64, k: f64) -> [f64; 3] {
    let (k2, mg) = (k * k, mu * g);
    [v0 / (mg * (1.0 - k2)), 2.0 * v0 * v0 / (mg * (4.0 - k2)), k * v0 * v0 / (4.0 * mg * (1.0 - k2))]
}

#[test]
fn a_side_force_curves_the_slip_to_a_stop() {
    let closed = curve_stop(3.0, 0.4, G, 0.5);
    assert!(closed.iter().zip(CURVE_STOP).all(|(c, q)| (c - q).abs() < 1e-15), "{closed:?}");
    let (m, mu) = (2.0, 0.4);
    let puck = Puck { m, g: G, mu, push: 0.0, angle: 0.0, side: 0.5 * mu * m * G };
    let flat = FlatPuck { m, g: G, mu, side: 0.5 * mu * m * G };
    let starts = (start(&puck, &[], &[3.0]), start(&flat, &[], &[3.0]));
    // Radau and Explicit at tolerance 1e-11, the variational integrator at step 1e-4.
    for method in METHODS {
        let fineness = (method, 1e-11, 1e-4);
        let runs = [
            ("on its contact force", run(&puck, &starts.0, 1.5, fineness, (Puck::X, Puck::Y))),
            ("of the state", run(&flat, &starts.1, 1.5, fineness, (FlatPuck::X, FlatPuck::Y))),
        ];
        for (which, run) in runs {
            let run = run.unwrap_or_else(|e| panic!("{method:?}, {which}: {e}"));
            // The slip turns towards the side force: the runtime freezes its direction again
            // each time it has turned by 60°, and its last `slip_stops` is the stop.
            let stop = run.events.iter().rev().find(|(name, _)| name == "slip_stops").expect("it stops").1;
            let (x, y) = (run.x[run.x.len() - 1], run.y[run.y.len() - 1]);
            // Measured: Radau 2.3e-10 in time (the force turns to the frozen direction within
            // 1e-9 m/s of rest), 6.4e-12 in position; Explicit 2.5e-10 and 1.0e-12; Variational
            // at h = 1e-4 2.8e-9 and 5.4e-10.
            let (dt, dx, dy) = (stop - CURVE_STOP[0], x - CURVE_STOP[1], y - CURVE_STOP[2]);
            let bound = if method == Method::Variational { 1e-8 } else { 1e-9 };
            assert!(dt.abs() < 1e-8, "{method:?}, {which}: stops at {stop} ({dt:e} off)");
            assert!(dx.abs().max(dy.abs()) < bound, "{method:?}, {which}: stops at ({x}, {y})");
            assert!(run.last.iter().all(|v| v.abs() < 1e-12), "{method:?}, {which}: held, {:?}", run.last);
        }
    }
}

#[test]
fn a_puck_at_rest_holds_within_the_cone_and_slips_along_the_force_beyond_it() {
    let (m, mu) = (2.0, 0.4);
    // A side force within μ m g: held, the law's force is the side force turned back.
    let held = FlatPuck { m, g: G, mu, side: 0.9 * mu * m * G };
    let state = start(&held, &[], &[]);
    assert_eq!((state.q[FlatPuck::SLIP_MODE_1.index()], state.q[FlatPuck::SLIP_MODE_2.index()]), (0.0, 0.0));
    let force = [state.lambda[FlatPuck::SLIP_1.index()], state.lambda[FlatPuck::SLIP_2.index()]];
    assert!(force[0].abs() < 1e-12 && (force[1] + 0.9 * mu * m * G).abs() < 1e-12, "{force:?}");
    // Beyond it: slipping along the side force from the start.
    let pushed = FlatPuck { side: 1.1 * mu * m * G, ..held };
    let state = start(&pushed, &[], &[]);
    let direction = [state.q[FlatPuck::SLIP_MODE_1.index()], state.q[FlatPuck::SLIP_MODE_2.index()]];
    // Solved from the accelerations (a round mass: along the force), to their round-off.
    assert!(direction[0].abs() < 1e-13 && (direction[1] - 1.0).abs() < 1e-15, "{direction:?}");
    // No friction and nothing pushing: held and slipping are one motion; the start picks one
    // (it slips, any way) rather than a direction of zero over zero.
    let free = FlatPuck { mu: 0.0, side: 0.0, ..held };
    let state = start(&free, &[], &[]);
    assert!(state.q.iter().chain(state.v.iter()).all(|x| x.is_finite()), "{:?}", state.q);
    assert_eq!(state.q[FlatPuck::SLIP_MODE_1.index()].hypot(state.q[FlatPuck::SLIP_MODE_2.index()]), 1.0);
}

#[test]
fn a_puck_heavier_along_x_starts_to_slip_where_its_slip_and_friction_agree() {
    // Pushed to twice its bound, its start is 0.27 rad off the push. Measured: 1.2e-13 off m
    // at the start; 2.6e-12 (Radau), 3.3e-15 (Explicit) off the line.
    let m = towed_from_rest(2.0);
    let push = [0.8f64.cos(), 0.8f64.sin()];
    assert!((m[0] * push[0] + m[1] * push[1]).acos() > 0.15, "m {m:?} is off the push {push:?}");
}

#[test]
fn a_puck_pushed_just_past_its_bound_starts_to_slip_where_its_slip_and_friction_agree() {
    // At 1.1 times its bound the friction turns the start's acceleration ten times as much as
    // it is off its direction: m <- ġ(m) / |ġ(m)| flips between m and -m there, and the
    // directions are solved for by Newton's method instead. Measured: 2.0e-13 off m at the
    // start; 3.6e-14 (Radau), 7.0e-14 (Explicit) off the line.
    towed_from_rest(1.1);
}

/// Starts a [`TowingPuck`] from rest under a push of size `push` at 0.8 rad, past its bound 1,
/// and checks that it slips on the closed-form line. Returns the line's direction.
///
/// From rest under a push F past the bound B, the slip starts along the unit m for which the
/// acceleration M⁻¹ (F − B m) is along m itself: (k M + B) m = F with k > 0, so it moves on the
/// straight line s m, s = k t² / 2. Against the push (m = F / |F|) is that only for a round M;
/// here M = diag(3, 1). k solved here by bisection on |(k M + B)⁻¹ F| = 1, which falls with k.
fn towed_from_rest(push: f64) -> [f64; 2] {
    let (mx, my, bound) = (3.0, 1.0, 1.0);
    let (fx, fy) = (push * 0.8f64.cos(), push * 0.8f64.sin());
    let puck = TowingPuck { mx, my, fx, fy, bound };
    let along = |k: f64| [fx / (k * mx + bound), fy / (k * my + bound)];
    let (mut low, mut high) = (0.0, 10.0);
    for _ in 0..200 {
        let k = 0.5 * (low + high);
        if norm(along(k)) > 1.0 { low = k } else { high = k }
    }
    let k = 0.5 * (low + high);
    let m = along(k);
    let state = start(&puck, &[], &[]);
    let direction = [state.q[TowingPuck::SLIP_MODE_1.index()], state.q[TowingPuck::SLIP_MODE_2.index()]];
    let off = (direction[0] - m[0]).abs().max((direction[1] - m[1]).abs());
    eprintln!("push {push}: starts {off:.1e} off m");
    assert!(off < 1e-9, "{direction:?} against {m:?}");
    for method in [Method::Radau, Method::Explicit] {
        let run = run(&puck, &state, 1.0, (method, 1e-10, 1e-3), (TowingPuck::X, TowingPuck::Y));
        let run = run.expect("solves");
        assert!(run.events.is_empty(), "{method:?}: no turn, no stop: {:?}", run.events);
        let mut largest: f64 = 0.0;
        for (i, &t) in run.t.iter().enumerate() {
            let s = 0.5 * k * t * t;
            let error = (run.x[i] - s * m[0]).abs().max((run.y[i] - s * m[1]).abs());
            assert!(error < 1e-9, "{method:?} at {t}: ({}, {}) against {s} along {m:?}", run.x[i], run.y[i]);
            largest = largest.max(error);
        }
        eprintln!("push {push}, {method:?}: {largest:.1e} m off the line s m at most");
    }
    m
}

fn norm(x: [f64; 2]) -> f64 {
    x[0].hypot(x[1])
}

/// Sensitivities across a cone's switches (its turns and its stop) against central differences
/// of the closed form of the curved slip's stop, [`curve_stop`]; refused for a cone on a
/// contact force, as for any friction on one.
#[test]
fn sensitivities_across_a_cones_turns_and_stop_match_the_closed_form() {
    let (m, mu, v0) = (2.0, 0.4, 3.0);
    let puck = FlatPuck { m, g: G, mu, side: 0.5 * mu * m * G };
    let start = start(&puck, &[], &[v0]);
    let wrt = Sensitivities::all_parameters(&puck);
    let solution = Radau::new(&puck, RadauOptions::tolerances(1e-12, 1e-12))
        .expect("valid")
        .with_sensitivities(&wrt)
        .expect("an associated cone")
        .solve_with_sensitivities(0.0, &start, 1.5, &Sampling::Times(vec![1.5]))
        .expect("integrates across the switches");
    let exact = |p: &FlatPuck| curve_stop(v0, p.mu, p.g, p.side / (p.mu * p.m * p.g));
    for (k, name) in puck.parameter_names().iter().enumerate() {
        let h = 1e-6;
        let (mut plus, mut minus) = (puck.clone(), puck.clone());
        plus.set_parameter_value(k, puck.parameter_value(k) + h);
        minus.set_parameter_value(k, puck.parameter_value(k) - h);
        for (c, coordinate) in [(1, FlatPuck::X), (2, FlatPuck::Y)] {
            let want = (exact(&plus)[c] - exact(&minus)[c]) / (2.0 * h);
            let got = solution.dq(coordinate, name).expect("a sensitivity")[0];
            assert!(
                (got - want).abs() < 1e-6 * want.abs().max(1.0),
                "∂{coordinate:?}/∂{name}: {got} against {want}"
            );
        }
    }
    let pushed = Puck { m, g: G, mu, push: 0.0, angle: 0.0, side: 0.5 * mu * m * G };
    let wrt = Sensitivities::all_parameters(&pushed);
    let err = Radau::new(&pushed, RadauOptions::default()).expect("valid").with_sensitivities(&wrt).err();
    assert!(
        matches!(err, Some(SimError::Unsupported { capability: dirac::Capability::ContactFriction, .. })),
        "{:?}",
        err.map(|e| e.to_string())
    );
}

/// The invariants of a top whose tip slips and then holds on the floor, run by Radau.
#[test]
fn a_top_on_the_ground_slips_then_spins_on_its_tip() {
    let top = GroundTop { m: 0.5, g: G, l: 0.04, a: 1.5e-4, c: 2e-4, mu: 0.3 };
    let theta0 = 0.3f64;
    // Spinning at 200 rad/s, tilted, its centre thrown sideways: the tip slips at first.
    let start =
        start(&top, &[0.0, 0.0, top.l * theta0.cos(), 0.0, theta0, 0.0], &[0.3, 0.0, 0.0, 0.0, 0.0, 200.0]);
    assert_eq!(start.q[GroundTop::TIP_MODE_1.index()], 1.0, "slipping along x");
    let solution = Radau::new(&top, RadauOptions::tolerances(1e-11, 1e-11))
        .expect("valid")
        .solve(0.0, &start, 1.0, &Sampling::Every(1e-5))
        .expect("solves");
    let stops: Vec<f64> = solution.event_times("tip_stops").expect("declared");
    assert_eq!(stops.len(), 1, "it slips, then holds: {:?}", solution.events());
    assert!(solution.event_times("tip_slips").expect("declared").is_empty());
    let t = solution.t();
    let (theta, w_theta) = (solution.q(GroundTop::THETA), solution.v(GroundTop::THETA));
    let (w_psi, w_phi) = (solution.v(GroundTop::PSI), solution.v(GroundTop::PHI));
    let spin: Vec<f64> = (0..t.len()).map(|k| w_phi[k] + w_psi[k] * theta[k].cos()).collect();
    // The friction at the tip, on the axis, has no moment about it. Measured: 8.5e-14.
    let drift = spin.iter().map(|w| (w - spin[0]).abs()).fold(0.0, f64::max);
    assert!(drift < 1e-11, "the spin drifts by {drift:e}");
    // The energy falls by the friction's work (in the constraint power), trapezoid-summed over
    // the samples. Measured: 2.0e-10 of 4.21 J (the quadrature's, at the kink of the stop).
    let (energy, power) = (solution.energy(), solution.constraint_power());
    let mut work = 0.0;
    for k in 1..t.len() {
        work += 0.5 * (power[k] + power[k - 1]) * (t[k] - t[k - 1]);
        let balance = energy[k] - energy[0] - work;
        assert!(
            balance.abs() < 1e-8,
            "at {}: energy {} less the work {work} is off by {balance:e}",
            t[k],
            energy[k]
        );
    }
    assert!(work < -1e-3, "the slip dissipates: {work}");
    // Held, it is the Lagrange top about its tip: energy, the angular momentum about the
    // vertical through the tip `I₁ ψ̇ sin²θ + c ω₃ cos θ` (`I₁ = a + m l²`) and the spin keep
    // their values, and `u = cos θ` moves between the roots of
    // `(1 − u²)(α − β u) − (b − a' u)²` in [−1, 1].
    let k0 = t.iter().position(|&x| x > stops[0] + 1e-4).expect("held for a while");
    let i1 = top.a + top.m * top.l * top.l;
    let about_tip = |k: usize| i1 * w_psi[k] * theta[k].sin().powi(2) + top.c * spin[k] * theta[k].cos();
    let lz = about_tip(k0);
    for k in k0..t.len() {
        // Measured: 3.5e-14 and 9.7e-13.
        assert!((about_tip(k) - lz).abs() < 1e-11, "at {}: {} against {lz}", t[k], about_tip(k));
        assert!((energy[k] - energy[k0]).abs() < 1e-10, "at {}: energy {}", t[k], energy[k]);
    }
    let held_energy = 0.5 * i1 * (w_theta[k0].powi(2) + (w_psi[k0] * theta[k0].sin()).powi(2))
        + 0.5 * top.c * spin[k0].powi(2)
        + top.m * G * top.l * theta[k0].cos();
    let alpha = (2.0 * held_energy - top.c * spin[k0].powi(2)) / i1;
    let beta = 2.0 * top.m * G * top.l / i1;
    let (b, a) = (lz / i1, top.c * spin[k0] / i1);
    let f = |u: f64| (1.0 - u * u) * (alpha - beta * u) - (b - a * u).powi(2);
    let roots = crate::util::roots_in(&f, -1.0, 1.0, 100_000);
    assert_eq!(roots.len(), 2, "two turning points: {roots:?}");
    let (theta_low, theta_high) = (roots[1].acos(), roots[0].acos());
    let low = theta[k0..].iter().copied().fold(f64::INFINITY, f64::min);
    let high = theta[k0..].iter().copied().fold(f64::NEG_INFINITY, f64::max);
    // Measured: 3.2e-11 and 1.5e-11 (the samples every 1e-5 s pass within that of the turns).
    assert!(
        (low - theta_low).abs() < 1e-8 && (high - theta_high).abs() < 1e-8,
        "θ in [{low}, {high}], turning points {theta_low}, {theta_high}"
    );
    // Held within the cone all along, and pressed onto the floor.
    let (t1, t2, n) = (
        solution.lambda(GroundTop::TIP_1),
        solution.lambda(GroundTop::TIP_2),
        solution.lambda(GroundTop::FLOOR),
    );
    for k in k0..t.len() {
        assert!(
            n[k] > 0.0 && t1[k].hypot(t2[k]) < top.mu * n[k],
            "at {}: ({}, {}) against {}",
            t[k],
            t1[k],
            t2[k],
            n[k]
        );
    }
}

/// The cones' derivatives, in every mode: the generated Jacobian against central differences of
/// the residual, and `∂((B − A)ᵀλ)/∂v` against differences of `(B − A)ᵀλ`.
#[test]
fn the_cone_derivatives_are_the_differences() {
    let puck = Puck { m: 2.0, g: G, mu: 0.4, push: 1.0, angle: 0.3, side: 0.5 };
    let top = GroundTop { m: 0.5, g: G, l: 0.04, a: 1.5e-4, c: 2e-4, mu: 0.3 };
    check_jacobian_by_differences(&puck, 11, 4);
    check_jacobian_by_differences(&FlatPuck { m: 2.0, g: G, mu: 0.4, side: 0.5 }, 12, 4);
    check_jacobian_by_differences(&top, 13, 4);
    const { assert!(<GroundTop as LagrangeDirac>::SLIP_TURNS && !<FlatPuck as LagrangeDirac>::NON_ASSOCIATED) };
    let n = 8;
    let q = VecQ::<GroundTop>::from_column_slice(&[0.1, -0.2, 0.03, 0.4, 0.3, 1.0, 0.6, 0.8]);
    let v = VecQ::<GroundTop>::from_column_slice(&[0.3, -0.1, 0.02, 2.0, -1.0, 150.0, 0.0, 0.0]);
    let lambda = VecC::<GroundTop>::from_column_slice(&[4.0, 0.5, -0.7]);
    let pushed = |v: &VecQ<GroundTop>| {
        let mut slip = MatCQ::<GroundTop>::zeros();
        top.slip_rows(0.0, &q, v, &mut slip);
        slip.transpose() * lambda
    };
    let mut exact = MatQQ::<GroundTop>::zeros();
    top.slip_dv(0.0, &q, &v, &lambda, &mut exact);
    for j in 0..n {
        let h = 1e-6 * v[j].abs().max(1.0);
        let (mut plus, mut minus) = (v, v);
        plus[j] += h;
        minus[j] -= h;
        let difference = (pushed(&plus) - pushed(&minus)) / (2.0 * h);
        for i in 0..n {
            let tol = 1e-6 * exact[(i, j)].abs().max(1.0);
            assert!(
                (exact[(i, j)] - difference[i]).abs() < tol,
                "∂/∂v{j} of row {i}: {} against {}",
                exact[(i, j)],
                difference[i]
            );
        }
    }
}
