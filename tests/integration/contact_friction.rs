//! Coulomb friction on a contact force: `friction(slide, kinetic = mu * floor) = vx`, whose
//! kinetic force names the row `floor` and so pushes with `μ λ_floor`. The momentum balance
//! then reads `Bᵀλ` with `B = A + (B − A)` (`LagrangeDirac::slip_rows`), and every
//! integrator steps it. The references are the closed forms of a block and a ball on a slope,
//! under constant forces in each mode: `g (sin θ − μ cos θ)` sliding, rest where
//! `μ ≥ tan θ`, the stopping distance `v0² / (2 μ g)` on the flat, `5/7 g sin θ` rolling.

use dirac::prelude::*;
use dirac::{Coordinate, State};

use crate::every_method::Fineness;
use crate::util::check_jacobian_by_differences;
use crate::zoo::{SlopeBall, SlopeBlock};

const G: f64 = 9.81;

/// The consistent start of `model` at positions and velocities `(q, v)`, its laws' modes chosen
/// from them.
pub(crate) fn start<M: Hybrid>(model: &M, q: &[f64], v: &[f64]) -> State<M>
where
    DefaultAllocator: Storage<M>,
{
    let (mut q0, mut v0) = (model.sizes().zeros_q::<M>(), model.sizes().zeros_q::<M>());
    q0.as_mut_slice()[..q.len()].copy_from_slice(q);
    v0.as_mut_slice()[..v.len()].copy_from_slice(v);
    consistent_state(model, 0.0, &q0, &v0, Consistency::default()).expect("a consistent start")
}

/// Solves `model` from `start` to `t_end` with every integrator (Radau and Explicit at
/// tolerance `tol`, the variational integrator at step 1e-3), and hands each solution to
/// `check` with the method's name.
fn every_method<M: Hybrid>(
    model: &M,
    start: &State<M>,
    t_end: f64,
    tol: f64,
    mut check: impl FnMut(&str, &[f64], &dyn Fn(Coordinate<M>) -> Vec<f64>, &[(String, f64)]),
) where
    DefaultAllocator: Storage<M>,
{
    each_integrator!(model, Fineness::new(tol, tol, 1e-3), |method, integrator| {
        let solution = integrator
            .solve(0.0, start, t_end, &Sampling::Steps)
            .unwrap_or_else(|e| panic!("{method:?}: {e}"));
        let events: Vec<(String, f64)> =
            solution.events().iter().map(|e| (solution.event_name(e).to_string(), e.t)).collect();
        check(&format!("{method:?}"), solution.t(), &|i| solution.q(i).to_vec(), &events);
    });
}

#[test]
fn a_block_slides_down_a_slope_at_g_sin_less_mu_g_cos() {
    let block = SlopeBlock { m: 2.0, g: G, slope: 0.5, mu: 0.3, push: 0.0 };
    let a = G * (0.5f64.sin() - 0.3 * 0.5f64.cos());
    let start = start(&block, &[], &[]);
    // From rest the pull down the slope exceeds what friction holds: it slips downhill.
    assert_eq!(start.q[SlopeBlock::SLIDE_MODE.index()], 1.0);
    // The contact force is the weight's normal part, m g cos θ.
    assert!((start.lambda[SlopeBlock::FLOOR.index()] - 2.0 * G * 0.5f64.cos()).abs() < 1e-12);
    every_method(&block, &start, 2.0, 1e-10, |method, t, q, events| {
        assert!(events.is_empty(), "{method}: {events:?}");
        let x = q(SlopeBlock::X);
        // Measured: 8.9e-16 (Radau), 3.7e-14 (Explicit), 4.9e-14 (Variational) at t = 2.
        for (t, x) in t.iter().zip(&x) {
            assert!((x - 0.5 * a * t * t).abs() < 1e-10 * (1.0 + x.abs()), "{method} at {t}: {x}");
        }
    });
}

#[test]
fn a_block_that_friction_holds_stays_at_rest() {
    // μ = 0.5 > tan 0.3 = 0.31.
    let block = SlopeBlock { m: 2.0, g: G, slope: 0.3, mu: 0.5, push: 0.0 };
    let start = start(&block, &[], &[]);
    assert_eq!(start.q[SlopeBlock::SLIDE_MODE.index()], 0.0, "stuck");
    // Stuck, the law's multiplier is the friction force that holds the weight's pull.
    assert!((start.lambda[SlopeBlock::SLIDE.index()].abs() - 2.0 * G * 0.3f64.sin()).abs() < 1e-12);
    every_method(&block, &start, 10.0, 1e-10, |method, _, q, events| {
        assert!(events.is_empty(), "{method}: {events:?}");
        let drift = q(SlopeBlock::X).iter().fold(0.0f64, |m, x| m.max(x.abs()));
        assert!(drift < 1e-12, "{method}: drifts {drift:e} in 10 s");
    });
}

#[test]
fn a_block_sliding_on_the_flat_stops_at_v0_squared_over_two_mu_g() {
    let (v0, mu) = (3.0, 0.4);
    let block = SlopeBlock { m: 2.0, g: G, slope: 0.0, mu, push: 0.0 };
    let start = start(&block, &[], &[v0]);
    let (distance, stops) = (v0 * v0 / (2.0 * mu * G), v0 / (mu * G));
    every_method(&block, &start, 2.0, 1e-12, |method, t, q, events| {
        assert_eq!(events.len(), 1, "{method}: {events:?}");
        assert_eq!(events[0].0, "slide_stops");
        assert!(
            (events[0].1 - stops).abs() < 1e-10,
            "{method}: stops at {}, closed form {stops}",
            events[0].1
        );
        let (x, mode) = (q(SlopeBlock::X), q(SlopeBlock::SLIDE_MODE));
        // Measured: 2.2e-16 (Radau), 2.4e-15 (Explicit), 6.2e-14 (Variational).
        let last = x[x.len() - 1];
        assert!((last - distance).abs() < 1e-8 * distance, "{method}: {last} against {distance}");
        // Stuck, the mode is 0 and its slack, free, drifts by round-off (2e-49 measured).
        for ((t, x), mode) in t.iter().zip(&x).zip(&mode) {
            if *t > stops + 1e-9 {
                assert!(
                    (x - last).abs() < 1e-12 && mode.abs() < 1e-12,
                    "{method} at {t}: x {x}, mode {mode}"
                );
            }
        }
    });
}

/// The friction's power is the constraints' (`⟨(B − A)ᵀλ, v⟩`, the balance's constraint
/// forces being `Bᵀλ`): `−μ m g v` while the block slides on the flat, and the energy it takes
/// out by the stop is all the kinetic energy, `½ m v0²`.
#[test]
fn the_friction_takes_out_the_energy_as_constraint_power() {
    let (m, v0, mu) = (2.0, 3.0, 0.4);
    let block = SlopeBlock { m, g: G, slope: 0.0, mu, push: 0.0 };
    let start = start(&block, &[], &[v0]);
    let solution = Radau::new(&block, RadauOptions::tolerances(1e-12, 1e-12))
        .expect("valid options")
        .solve(0.0, &start, 1.0, &Sampling::Every(0.05))
        .expect("solves");
    let (t, v, power, energy) =
        (solution.t(), solution.v(SlopeBlock::X), solution.constraint_power(), solution.energy());
    for ((t, v), power) in t.iter().zip(v).zip(power) {
        let closed = -mu * m * G * v;
        assert!((power - closed).abs() < 1e-9, "at {t}: constraint power {power}, closed form {closed}");
    }
    let taken = energy[0] - energy[energy.len() - 1];
    assert!((taken - 0.5 * m * v0 * v0).abs() < 1e-9, "{taken} taken out, ½ m v0² = {}", 0.5 * m * v0 * v0);
}

#[test]
fn a_pushed_block_slips_where_the_push_reaches_what_friction_holds() {
    // On the flat, pushed with `c t`: it slips at `t_s = μ m g / c` and then `m ẍ = c (t − t_s)`.
    let (m, mu, c) = (2.0, 0.4, 5.0);
    let block = SlopeBlock { m, g: G, slope: 0.0, mu, push: c };
    let start = start(&block, &[], &[]);
    assert_eq!(start.q[SlopeBlock::SLIDE_MODE.index()], 0.0, "stuck");
    let slips = mu * m * G / c;
    let t_end = slips + 1.0;
    every_method(&block, &start, t_end, 1e-11, |method, t, q, events| {
        assert_eq!(events.len(), 1, "{method}: {events:?}");
        assert_eq!(events[0].0, "slide_slips");
        assert!(
            (events[0].1 - slips).abs() < 1e-8,
            "{method}: slips at {}, closed form {slips}",
            events[0].1
        );
        let x = q(SlopeBlock::X);
        let (t, x) = (t[t.len() - 1], x[x.len() - 1]);
        let closed = c * (t - slips).powi(3) / (6.0 * m);
        // The variational integrator's error on a cubic motion, `h² x''' t / 12` with
        // `x''' = c / m`: 2e-7 here.
        let bound = if method == "Variational" { 1e-6 } else { 1e-8 };
        assert!((x - closed).abs() < bound, "{method}: x({t}) = {x}, closed form {closed}");
    });
}

#[test]
fn a_ball_that_friction_holds_rolls_down_at_five_sevenths_g_sin() {
    // Rolling needs the friction force 2/7 m g sin θ, within μ m g cos θ for μ ≥ 2/7 tan θ.
    let (r, slope) = (0.1, 0.4);
    let ball = SlopeBall { m: 1.5, g: G, r, slope, mu: 0.5 };
    let start = start(&ball, &[], &[]);
    assert_eq!(start.q[SlopeBall::TOUCH_MODE.index()], 0.0, "rolling");
    let a = 5.0 / 7.0 * G * slope.sin();
    every_method(&ball, &start, 2.0, 1e-10, |method, t, q, events| {
        assert!(events.is_empty(), "{method}: {events:?}");
        let (x, phi) = (q(SlopeBall::X), q(SlopeBall::PHI));
        for ((t, x), phi) in t.iter().zip(&x).zip(&phi) {
            let closed = 0.5 * a * t * t;
            assert!((x - closed).abs() < 1e-9 * (1.0 + closed), "{method} at {t}: {x} against {closed}");
            assert!((r * phi - x).abs() < 1e-9 * (1.0 + closed), "{method} at {t}: it slips");
        }
    });
}

#[test]
fn a_ball_on_a_slippery_slope_slides_and_spins_up() {
    // μ = 0.05 < 2/7 tan 0.6: it slips; friction μ m g cos θ slows the slide and spins the ball
    // up at μ m g cos θ r / I = 5 μ g cos θ / (2 r).
    let (r, slope, mu) = (0.1, 0.6, 0.05);
    let ball = SlopeBall { m: 1.5, g: G, r, slope, mu };
    let start = start(&ball, &[], &[]);
    assert_eq!(start.q[SlopeBall::TOUCH_MODE.index()], 1.0, "slipping downhill");
    let a = G * (slope.sin() - mu * slope.cos());
    let alpha = 5.0 * mu * G * slope.cos() / (2.0 * r);
    every_method(&ball, &start, 1.0, 1e-10, |method, t, q, events| {
        assert!(events.is_empty(), "{method}: {events:?}");
        let (x, phi) = (q(SlopeBall::X), q(SlopeBall::PHI));
        for ((t, x), phi) in t.iter().zip(&x).zip(&phi) {
            let (closed_x, closed_phi) = (0.5 * a * t * t, 0.5 * alpha * t * t);
            assert!(
                (x - closed_x).abs() < 1e-9 * (1.0 + closed_x),
                "{method} at {t}: x {x} against {closed_x}"
            );
            assert!(
                (phi - closed_phi).abs() < 1e-9 * (1.0 + closed_phi),
                "{method} at {t}: phi {phi} against {closed_phi}"
            );
        }
    });
}

/// The generated Jacobian carries `Bᵀ` in the multipliers' columns of the momentum balance:
/// checked against central differences of the residual, and `B − A` against that column less
/// the constraint rows.
#[test]
fn the_slip_rows_are_the_differences_of_the_balance() {
    check_jacobian_by_differences(&SlopeBlock { m: 2.0, g: G, slope: 0.3, mu: 0.4, push: 1.0 }, 7, 4);
    check_jacobian_by_differences(&SlopeBall { m: 1.5, g: G, r: 0.1, slope: 0.4, mu: 0.3 }, 8, 4);
    let ball = SlopeBall { m: 1.5, g: G, r: 0.1, slope: 0.4, mu: 0.3 };
    const { assert!(<SlopeBall as LagrangeDirac>::NON_ASSOCIATED) };
    let n = 4;
    for mode in [-1.0, 0.0, 1.0] {
        let mut y = ball.sizes().zeros_y::<SlopeBall>();
        y[SlopeBall::TOUCH_MODE.index()] = mode;
        y[0] = 0.3;
        let jac = ball.jacobian_matrix(0.0, &y);
        let q = VecQ::<SlopeBall>::from_column_slice(&y.as_slice()[..n]);
        let (mut a, mut slip) = (MatCQ::<SlopeBall>::zeros(), MatCQ::<SlopeBall>::zeros());
        ball.constraint_matrix(0.0, &q, &mut a);
        ball.slip_rows(0.0, &q, &q, &mut slip);
        for j in 0..2 {
            for i in 0..n {
                let column = jac[(2 * n + i, 3 * n + j)];
                assert_eq!(column, a[(j, i)] + slip[(j, i)], "mode {mode}: ∂ṗ_{i}/∂λ_{j}");
            }
        }
        // Slipping, the contact force's row drives the friction along the slip: −μ s ∂g/∂v.
        let expected = [-0.3 * mode, 0.0, 0.3 * mode * 0.1, 0.0];
        for (i, e) in expected.iter().enumerate() {
            assert_eq!(slip[(SlopeBall::FLOOR.index(), i)], *e, "mode {mode}, coordinate {i}");
        }
    }
}

#[test]
fn friction_on_a_contact_force_is_refused_where_it_is_not_carried() {
    let block = SlopeBlock { m: 2.0, g: G, slope: 0.5, mu: 0.3, push: 0.0 };
    let unsupported =
        |method| SimError::Unsupported { method, capability: dirac::Capability::ContactFriction };
    let rest = start(&SlopeBlock { slope: 0.0, ..block.clone() }, &[], &[]);
    let err = dirac::linearize(&block, 0.0, &rest).err();
    assert_eq!(err.map(|e| e.to_string()), Some(unsupported("linearize").to_string()));
    let wrt = Sensitivities::new(&block).parameters(&["mu"]).expect("a parameter");
    let err = Radau::new(&block, RadauOptions::default()).expect("valid").with_sensitivities(&wrt).err();
    assert_eq!(err.map(|e| e.to_string()), Some(unsupported("Radau's sensitivities").to_string()));
    let mut network = dirac::network::Network::builder();
    let err = network.add("block", block).err().map(|e| e.to_string());
    assert_eq!(
        err.as_deref(),
        Some(
            "part `block` has friction that pushes with a contact force (`kinetic = mu * floor`), which a \
             run-time network does not resolve yet"
        )
    );
}

/// Friction takes power out: a negative coefficient (or a contact force that pulls) would make
/// the slip push the block on, and a consistent start (and every switch) refuses it by name.
#[test]
fn friction_that_would_push_is_refused_by_name() {
    let block = SlopeBlock { m: 2.0, g: G, slope: 0.0, mu: -0.4, push: 0.0 };
    let mut v = block.sizes().zeros_q::<SlopeBlock>();
    v[SlopeBlock::X.index()] = 3.0;
    let err =
        consistent_state(&block, 0.0, &block.sizes().zeros_q::<SlopeBlock>(), &v, Consistency::default())
            .err()
            .map(|e| e.to_string());
    let message = err.expect("refused");
    assert!(
        message.contains("contact force of `floor` puts") && message.contains("must not be negative"),
        "{message}"
    );
}
