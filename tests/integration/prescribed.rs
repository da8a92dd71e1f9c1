//! Prescribed motion: constraints that depend on time, `φ(q, t) = 0` and
//! `A(q, t) v + b(q, t) = 0`. Every reference is computed here, independently of dirac: a
//! closed form, or (for the shaken pendulum) the angle-form equation of motion integrated by
//! classical Runge-Kutta at a step small enough that its error is below round-off. The power
//! balance `dE/dt = ⟨F, v⟩ − ∂L/∂t − ⟨λ, b⟩` is checked by integrating the recorded powers.

use std::f64::consts::PI;

use dirac::State;
use dirac::prelude::*;

use crate::zoo::{
    BeadOnRod, DiskOnAcceleratingBelt, DiskOnBelt, DraggedMass, FreeMass, ShakenPair, ShakenPendulum,
    ShakenRow, SliderCrank,
};

/// `∫ f dt` over samples `f` at equal spacing `dt`, by Simpson's rule (an even number of
/// intervals).
fn simpson(f: &[f64], dt: f64) -> f64 {
    let n = f.len() - 1;
    assert!(n >= 2 && n.is_multiple_of(2), "Simpson's rule needs an even number of intervals, not {n}");
    let inner: f64 = (1..n).map(|i| if i % 2 == 1 { 4.0 * f[i] } else { 2.0 * f[i] }).sum();
    (f[0] + inner + f[n]) * dt / 3.0
}

/// The energy gained over a solution against the work its forces and constraints did, both
/// from the recorded series sampled every `dt`: `|ΔE − ∫ (⟨F, v⟩ + P_c) dt|`, relative to the
/// largest of `|ΔE|` and the integrals of the absolute powers.
fn balance_error<M: LagrangeDirac, S>(solution: &Solution<M, S>, dt: f64) -> f64
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let e = solution.energy();
    let total: Vec<f64> =
        solution.power().iter().zip(solution.constraint_power()).map(|(f, c)| f + c).collect();
    let absolute: Vec<f64> = total.iter().map(|p| p.abs()).collect();
    let gained = e[e.len() - 1] - e[0];
    let scale = gained.abs().max(simpson(&absolute, dt));
    (gained - simpson(&total, dt)).abs() / scale
}

// ---- A pendulum with a shaken pivot ----------------------------------------------------------

/// The angle `θ` from the downward vertical of a pendulum whose pivot moves as `a sin(ω t)`:
/// `l θ̈ = −g sin θ − ẍ_p cos θ` with `ẍ_p = −a ω² sin(ω t)`, by classical Runge-Kutta with
/// step `h`, at each of `times`.
fn shaken_angle(p: &ShakenPendulum, theta0: f64, times: &[f64], h: f64) -> Vec<(f64, f64)> {
    let rhs = |t: f64, (th, om): (f64, f64)| {
        let xpp = -p.a * p.w * p.w * (p.w * t).sin();
        (om, (-p.g * th.sin() - xpp * th.cos()) / p.l)
    };
    let (mut t, mut y) = (0.0, (theta0, 0.0));
    let mut out = Vec::new();
    for &target in times {
        while t < target - 1e-12 {
            let dt = h.min(target - t);
            let k1 = rhs(t, y);
            let k2 = rhs(t + dt / 2.0, (y.0 + dt / 2.0 * k1.0, y.1 + dt / 2.0 * k1.1));
            let k3 = rhs(t + dt / 2.0, (y.0 + dt / 2.0 * k2.0, y.1 + dt / 2.0 * k2.1));
            let k4 = rhs(t + dt, (y.0 + dt * k3.0, y.1 + dt * k3.1));
            y.0 += dt / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
            y.1 += dt / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
            t += dt;
        }
        out.push(y);
    }
    out
}

fn shaken() -> ShakenPendulum {
    ShakenPendulum { m: 1.2, g: 9.81, l: 0.8, a: 0.15, w: 5.0 }
}

/// The bob hanging at angle `θ0` at rest relative to the pivot, which moves at `a ω` at t = 0.
fn shaken_start(p: &ShakenPendulum, theta0: f64) -> State<ShakenPendulum> {
    let q = VecQ::<ShakenPendulum>::from([p.l * theta0.sin(), -p.l * theta0.cos()]);
    let v = VecQ::<ShakenPendulum>::from([p.a * p.w, 0.0]);
    let s = consistent_state(p, 0.0, &q, &v, Consistency::default()).expect("consistent");
    // Already consistent: the projection must leave it as it is.
    assert!((s.v[0] - p.a * p.w).abs() < 1e-14 && s.v[1].abs() < 1e-14, "v0 = {:?}", s.v);
    s
}

#[test]
fn a_pendulum_with_a_shaken_pivot_follows_its_angle_equation() {
    let p = shaken();
    let theta0 = 0.4;
    let times: Vec<f64> = (1..=8).map(|i| 0.5 * i as f64).collect();
    let reference = shaken_angle(&p, theta0, &times, 1e-4);
    let tol = 1e-11;
    let mut radau = Radau::new(&p, RadauOptions::tolerances(tol, tol)).expect("valid");
    let solution = radau
        .solve(0.0, &shaken_start(&p, theta0), 4.0, &Sampling::Times(times.clone()))
        .expect("integrates");
    let (xs, ys) = (solution.q(ShakenPendulum::X), solution.q(ShakenPendulum::Y));
    for (k, (&t, &(theta, _))) in times.iter().zip(&reference).enumerate() {
        let (x, y) = (p.a * (p.w * t).sin() + p.l * theta.sin(), -p.l * theta.cos());
        let error = (xs[k] - x).abs().max((ys[k] - y).abs());
        assert!(error < 1e-8, "t = {t}: bob at ({}, {}) against ({x}, {y})", xs[k], ys[k]);
    }
    // The rod stays its length about the moving pivot.
    assert!(solution.holonomic_residual().iter().all(|r| *r < 1e-9));
}

#[test]
fn the_variational_integrator_converges_at_second_order_on_the_shaken_pendulum() {
    let p = shaken();
    let theta0 = 0.4;
    let (&(theta, _), t_end) = (&shaken_angle(&p, theta0, &[1.0], 1e-4)[0], 1.0);
    let (x, y) = (p.a * (p.w * t_end).sin() + p.l * theta.sin(), -p.l * theta.cos());
    let error = |h: f64| {
        let mut vi = Variational::new(&p, h, VariationalOptions::default()).expect("valid");
        vi.start(0.0, &shaken_start(&p, theta0), t_end).expect("starts");
        while !vi.finished() {
            vi.step().expect("steps");
        }
        let s = vi.state();
        let mut phi = VecH::<ShakenPendulum>::zeros();
        p.holonomic(vi.t(), &s.q, &mut phi);
        assert!(phi.amax() < 1e-12, "the rod's constraint holds at the step points: {}", phi.amax());
        (s.q[0] - x).abs().max((s.q[1] - y).abs())
    };
    let (coarse, fine) = (error(2e-3), error(1e-3));
    let order = (coarse / fine).log2();
    assert!((order - 2.0).abs() < 0.15, "order {order:.3} (errors {coarse:e}, {fine:e})");
    assert!(fine < 1e-4, "error {fine:e} at h = 1e-3");
}

#[test]
fn the_shaken_pendulum_closes_its_power_balance() {
    let p = shaken();
    let dt = 1e-3;
    let tol = 1e-11;
    let mut radau = Radau::new(&p, RadauOptions::tolerances(tol, tol)).expect("valid");
    let solution = radau.solve(0.0, &shaken_start(&p, 0.4), 4.0, &Sampling::Every(dt)).expect("integrates");
    assert_eq!(solution.len(), 4001);
    // The pivot does work: the energy is not conserved, but balanced by −⟨λ, b⟩.
    let e = solution.energy();
    let swing = e.iter().fold(0.0f64, |m, x| m.max((x - e[0]).abs()));
    assert!(swing > 0.1, "the shaken pivot changes the energy by {swing}");
    let error = balance_error(&solution, dt);
    assert!(error < 1e-8, "power balance error {error:e}");
}

// ---- A mass dragged through a spring ---------------------------------------------------------

/// `x(t) = c t − (c/ω) sin ωt` from rest at 0, ω² = k/m.
fn dragged_exact(d: &DraggedMass, t: f64) -> (f64, f64) {
    let w = (d.k / d.m).sqrt();
    (d.c * t - d.c / w * (w * t).sin(), d.c - d.c * (w * t).cos())
}

fn dragged_start(d: &DraggedMass) -> State<DraggedMass> {
    // Both at rest: the projection gives the dragged end, which has no inertia, its speed c
    // and leaves the mass at rest.
    let (q, v) = (VecQ::<DraggedMass>::zeros(), VecQ::<DraggedMass>::zeros());
    let s = consistent_state(d, 0.0, &q, &v, Consistency::default()).expect("consistent");
    assert!((s.v[1] - d.c).abs() < 1e-12 && s.v[0].abs() < 1e-9, "v0 = {:?}", s.v);
    s
}

#[test]
fn a_mass_dragged_through_a_spring_follows_the_exact_solution() {
    let d = DraggedMass { m: 1.5, k: 6.0, c: 0.8 };
    let times: Vec<f64> = (1..=10).map(|i| i as f64).collect();
    let tol = 1e-11;
    let mut radau = Radau::new(&d, RadauOptions::tolerances(tol, tol)).expect("valid");
    let solution =
        radau.solve(0.0, &dragged_start(&d), 10.0, &Sampling::Times(times.clone())).expect("integrates");
    for (k, &t) in times.iter().enumerate() {
        let (x, v) = dragged_exact(&d, t);
        let (xs, vs) = (solution.q(DraggedMass::X), solution.v(DraggedMass::X));
        assert!((xs[k] - x).abs() < 1e-8, "x({t}) = {} against {x}", xs[k]);
        assert!((vs[k] - v).abs() < 1e-8, "v({t}) = {} against {v}", vs[k]);
        assert!((solution.q(DraggedMass::E)[k] - d.c * t).abs() < 1e-10, "the end is at c t");
        // The multiplier is the pull on the end: p_e = 0 gives λ = k (e − x).
        let pull = d.k * (d.c * t - x);
        let lambda = solution.lambda(DraggedMass::DRAG)[k];
        assert!((lambda - pull).abs() < 1e-7, "λ({t}) = {lambda} against k (ct − x) = {pull}");
        // Its power −⟨λ, b⟩ = λ c is the power of that pull.
        assert!((solution.constraint_power()[k] - pull * d.c).abs() < 1e-7);
    }
}

#[test]
fn the_variational_integrator_drags_the_mass_at_second_order() {
    let d = DraggedMass { m: 1.5, k: 6.0, c: 0.8 };
    let (x, _) = dragged_exact(&d, 2.0);
    let error = |h: f64| {
        let mut vi = Variational::new(&d, h, VariationalOptions::default()).expect("valid");
        vi.start(0.0, &dragged_start(&d), 2.0).expect("starts");
        while !vi.finished() {
            vi.step().expect("steps");
        }
        assert!((vi.state().q[1] - 2.0 * d.c).abs() < 1e-12, "the end is at c t");
        (vi.state().q[0] - x).abs()
    };
    let (coarse, fine) = (error(1e-2), error(5e-3));
    let order = (coarse / fine).log2();
    assert!((order - 2.0).abs() < 0.15, "order {order:.3} (errors {coarse:e}, {fine:e})");
}

// ---- A bead on a rotating rod ----------------------------------------------------------------

#[test]
fn a_bead_on_a_rotating_rod_slides_out_as_cosh() {
    // r(t) = r0 cosh(ωt) along the rod at angle ωt; E = ½ m r0² ω² cosh(2ωt), so the rod puts
    // in the power m r0² ω³ sinh(2ωt).
    let bead = BeadOnRod { m: 0.7, w: 1.3 };
    let (r0, m, w) = (0.5, bead.m, bead.w);
    // Started at rest: the projection gives it the rod's velocity ω r0 across the rod.
    let q = VecQ::<BeadOnRod>::from([r0, 0.0]);
    let start = consistent_state(&bead, 0.0, &q, &VecQ::<BeadOnRod>::zeros(), Consistency::default())
        .expect("consistent");
    assert!(start.v[0].abs() < 1e-14 && (start.v[1] - w * r0).abs() < 1e-14, "v0 = {:?}", start.v);
    let tol = 1e-11;
    let dt = 2e-3;
    let mut radau = Radau::new(&bead, RadauOptions::tolerances(tol, tol)).expect("valid");
    let solution = radau.solve(0.0, &start, 2.0, &Sampling::Every(dt)).expect("integrates");
    let (xs, ys) = (solution.q(BeadOnRod::X), solution.q(BeadOnRod::Y));
    for (k, &t) in solution.t().iter().enumerate() {
        let r = r0 * (w * t).cosh();
        let (x, y) = (r * (w * t).cos(), r * (w * t).sin());
        assert!((xs[k] - x).abs().max((ys[k] - y).abs()) < 1e-8 * r, "t = {t}");
        let energy = 0.5 * m * r0 * r0 * w * w * (2.0 * w * t).cosh();
        assert!((solution.energy()[k] - energy).abs() < 1e-8 * energy, "E({t})");
        let power = m * r0 * r0 * w.powi(3) * (2.0 * w * t).sinh();
        assert!((solution.constraint_power()[k] - power).abs() < 1e-7 * (1.0 + power), "P({t})");
    }
    assert!(balance_error(&solution, dt) < 1e-9);

    // The variational integrator, at second order.
    let error = |h: f64| {
        let mut vi = Variational::new(&bead, h, VariationalOptions::default()).expect("valid");
        vi.start(0.0, &start, 2.0).expect("starts");
        while !vi.finished() {
            vi.step().expect("steps");
        }
        let r = (vi.state().q[0].powi(2) + vi.state().q[1].powi(2)).sqrt();
        (r - r0 * (2.0 * w).cosh()).abs()
    };
    let order = (error(1e-2) / error(5e-3)).log2();
    assert!((order - 2.0).abs() < 0.15, "order {order:.3}");
}

// ---- A disk rolling on a moving belt ---------------------------------------------------------

/// On a belt at constant speed `u`, the belt's frame is inertial: the disk rolls there at a
/// constant rate `ω` and turns at a constant rate `Ω`, on a circle of radius `r ω / Ω` that
/// the belt carries along.
fn disk_exact(d: &DiskOnBelt, (omega, turn, phi0): (f64, f64, f64), t: f64) -> [f64; 4] {
    let phi = phi0 + turn * t;
    let radius = d.r * omega / turn;
    [d.belt * t + radius * (phi.sin() - phi0.sin()), -radius * (phi.cos() - phi0.cos()), omega * t, phi]
}

fn disk_start<M: DenseModel>(model: &M, r: f64, belt: f64, (omega, turn, phi0): (f64, f64, f64)) -> State<M>
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let mut q = VecQ::<M>::zeros();
    q[3] = phi0;
    let mut v = VecQ::<M>::zeros();
    v[0] = belt + r * omega * phi0.cos();
    v[1] = r * omega * phi0.sin();
    v[2] = omega;
    v[3] = turn;
    consistent_state(model, 0.0, &q, &v, Consistency::default()).expect("consistent")
}

#[test]
fn a_disk_on_a_moving_belt_rolls_on_a_carried_circle() {
    let d = DiskOnBelt { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045, belt: 0.6 };
    let motion = (2.0, 0.9, 0.3);
    let start = disk_start(&d, d.r, d.belt, motion);
    let tol = 1e-11;
    let dt = 5e-3;
    let mut radau = Radau::new(&d, RadauOptions::tolerances(tol, tol)).expect("valid");
    let solution = radau.solve(0.0, &start, 5.0, &Sampling::Every(dt)).expect("integrates");
    let keys = [DiskOnBelt::X, DiskOnBelt::Y, DiskOnBelt::THETA, DiskOnBelt::PHI];
    for (k, &t) in solution.t().iter().enumerate() {
        let exact = disk_exact(&d, motion, t);
        for (key, x) in keys.iter().zip(exact) {
            assert!((solution.q(*key)[k] - x).abs() < 1e-8, "{key:?} at t = {t}");
        }
        // The belt does work on the disk, −⟨λ, b⟩ = λ_x u, where λ_x = m ẍ = −m r ω Ω sin φ.
        let (omega, turn, _) = motion;
        let power = -d.m * d.r * omega * turn * exact[3].sin() * d.belt;
        // Radau's multipliers are of lower order than its positions (index 2), and these are
        // interpolated between steps: 1e-6 of the power's amplitude.
        let amplitude = d.m * d.r * omega * turn * d.belt;
        let error = (solution.constraint_power()[k] - power).abs();
        assert!(error < 1e-6 * amplitude, "P({t}) = {} against {power}", solution.constraint_power()[k]);
    }
    assert!(balance_error(&solution, dt) < 1e-9);
    assert!(solution.constraint_residual().iter().all(|r| *r < 1e-9));

    // The variational integrator keeps the affine constraints at its midpoints and converges.
    let error = |h: f64| {
        let mut vi = Variational::new(&d, h, VariationalOptions::default()).expect("valid");
        vi.start(0.0, &start, 5.0).expect("starts");
        while !vi.finished() {
            vi.step().expect("steps");
        }
        let exact = disk_exact(&d, motion, 5.0);
        (0..4).map(|i| (vi.state().q[i] - exact[i]).abs()).fold(0.0, f64::max)
    };
    let (coarse, fine) = (error(1e-2), error(5e-3));
    assert!(fine < 1e-4, "error {fine:e}");
    let order = (coarse / fine).log2();
    assert!((order - 2.0).abs() < 0.2, "order {order:.3} (errors {coarse:e}, {fine:e})");
}

#[test]
fn a_belt_driven_through_an_input_matches_one_written_with_t() {
    // belt = u0 + c t, once as an input set by a drive inside Radau's steps, once in the
    // constraint itself.
    let (u0, c) = (0.6, 0.25);
    let by_t = DiskOnAcceleratingBelt { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045, u0, c };
    let mut by_input = DiskOnBelt { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045, belt: u0 };
    let motion = (2.0, 0.9, 0.3);
    let times: Vec<f64> = (1..=4).map(|i| i as f64).collect();
    let tol = 1e-11;
    let start = disk_start(&by_t, by_t.r, u0, motion);
    let mut radau = Radau::new(&by_t, RadauOptions::tolerances(tol, tol)).expect("valid");
    let written = radau.solve(0.0, &start, 4.0, &Sampling::Times(times.clone())).expect("integrates");
    let start = disk_start(&by_input, by_input.r, u0, motion);
    let mut source = |t: f64, _: &State<DiskOnBelt>, model: &mut DiskOnBelt| model.belt = u0 + c * t;
    let mut radau = Radau::new(&mut by_input, RadauOptions::tolerances(tol, tol)).expect("valid");
    radau.drive(&mut source).expect("an exclusive model");
    let driven = radau.solve(0.0, &start, 4.0, &Sampling::Times(times)).expect("integrates");
    for (a, b) in [
        (DiskOnAcceleratingBelt::X, DiskOnBelt::X),
        (DiskOnAcceleratingBelt::Y, DiskOnBelt::Y),
        (DiskOnAcceleratingBelt::THETA, DiskOnBelt::THETA),
    ] {
        for (x, y) in written.q(a).iter().zip(driven.q(b)) {
            assert!((x - y).abs() < 1e-8, "{a:?}: {x} against {y}");
        }
    }
    // The accelerating belt drags the disk along x.
    assert!(written.q(DiskOnAcceleratingBelt::X)[3] > u0 * 4.0);
}

// ---- A slider crank driven at constant crank speed ---------------------------------------------

fn crank() -> SliderCrank {
    SliderCrank { m1: 1.0, m2: 2.0, m3: 0.5, r: 0.3, l: 1.0, g: 9.81, c: 0.8, w: 2.0 * PI }
}

/// The crank at angle 0 and turning at ω, the rod along the axis, the slider at r + l.
fn crank_start(s: &SliderCrank) -> State<SliderCrank> {
    let q = VecQ::<SliderCrank>::from([0.0, 0.0, s.r + s.l]);
    consistent_state(s, 0.0, &q, &VecQ::<SliderCrank>::zeros(), Consistency::default()).expect("consistent")
}

/// The slider's position, `r cos ωt + √(l² − r² sin² ωt)`.
fn slider_exact(s: &SliderCrank, t: f64) -> f64 {
    let (sin, cos) = (s.w * t).sin_cos();
    s.r * cos + (s.l * s.l - s.r * s.r * sin * sin).sqrt()
}

#[test]
fn a_slider_crank_with_a_prescribed_crank_closes_its_power_balance_under_radau() {
    let s = crank();
    let start = crank_start(&s);
    assert!((start.v[0] - s.w).abs() < 1e-12, "the crank starts at ω: {}", start.v[0]);
    // Samples close enough that Simpson's rule adds nothing: the balance's error is then that
    // of the multipliers interpolated between steps (1.3e-8 with samples every 1e-3).
    let (tol, dt) = (1e-10, 5e-4);
    let mut radau = Radau::new(&s, RadauOptions::tolerances(tol, tol)).expect("valid");
    let solution = radau.solve(0.0, &start, 2.0, &Sampling::Every(dt)).expect("integrates");
    // Samples between steps come from the collocation polynomial, accurate to the tolerance
    // only up to a constant; at the step points the constraints hold much more tightly.
    let between = solution.holonomic_residual().iter().fold(0.0f64, |m, x| m.max(*x));
    assert!(between < 1e-8, "|φ| up to {between:e} between steps");
    let mut radau = Radau::new(&s, RadauOptions::tolerances(tol, tol)).expect("valid");
    let steps = radau.solve(0.0, &start, 2.0, &Sampling::Steps).expect("integrates");
    let at_steps = steps.holonomic_residual().iter().fold(0.0f64, |m, x| m.max(*x));
    assert!(at_steps < 1e-11, "|φ| up to {at_steps:e} at the steps");
    // The drive's torque does work against gravity, inertia and the damper.
    // 1.9e-9 with the first step HINIT chooses, below 1e-9 from a first step of 1e-6 of the
    // span: where the samples fall in the steps moves the multipliers' interpolation error.
    let error = balance_error(&solution, dt);
    assert!(error < 5e-9, "power balance error {error:e}");
    let drive = solution.lambda(SliderCrank::DRIVE);
    assert!(drive.iter().any(|x| x.abs() > 1.0), "the drive carries a torque");
}

#[test]
fn a_slider_crank_with_a_prescribed_crank_closes_its_power_balance_under_the_variational_integrator() {
    let s = crank();
    let start = crank_start(&s);
    let h = 1e-3;
    let mut vi = Variational::new(&s, h, VariationalOptions::default()).expect("valid");
    let solution = vi.solve(0.0, &start, 2.0, &Sampling::Steps).expect("integrates");
    assert_eq!(solution.len(), 2001);
    for (k, &t) in solution.t().iter().enumerate() {
        let x = solution.q(SliderCrank::X)[k];
        assert!((x - slider_exact(&s, t)).abs() < 1e-10, "slider at t = {t}");
    }
    assert!(solution.holonomic_residual().iter().all(|r| *r < 1e-12));
    assert!(solution.constraint_residual().iter().all(|r| *r < 1e-10));
    // The positions and velocities at the step points are exact (the crank prescribes the whole
    // motion); the multipliers are second-order accurate, so the balance closes to O(h²).
    let error = balance_error(&solution, h);
    assert!(error < 2e-6, "power balance error {error:e}");
    let coarse = {
        let mut vi = Variational::new(&s, 2.0 * h, VariationalOptions::default()).expect("valid");
        balance_error(&vi.solve(0.0, &start, 2.0, &Sampling::Steps).expect("integrates"), 2.0 * h)
    };
    let order = (coarse / error).log2();
    assert!((order - 2.0).abs() < 0.2, "the balance closes at order {order:.3}");
}

// ---- Prescribed relative motion in an interconnection ------------------------------------------

/// Masses `m_i` whose neighbours' relative velocities are `u(t) = a ω cos(ω t)`, started with
/// no momentum: `v_i = v_0 + i u` with `Σ m_i v_i = 0`, so `x_i(t) = x_i(0) + c_i a sin(ω t)`
/// with `c_i = i − Σ_k k m_k / Σ_k m_k`.
fn shaken_positions(masses: &[f64], x0: &[f64], (a, w): (f64, f64), t: f64) -> Vec<f64> {
    let total: f64 = masses.iter().sum();
    let centre: f64 = masses.iter().enumerate().map(|(k, m)| k as f64 * m).sum::<f64>() / total;
    x0.iter().enumerate().map(|(i, x)| x + (i as f64 - centre) * a * (w * t).sin()).collect()
}

#[test]
fn an_interconnection_may_prescribe_a_relative_velocity() {
    let pair = ShakenPair { left: FreeMass { m: 1.0 }, right: FreeMass { m: 3.0 }, a: 0.2, w: 4.0 };
    assert_eq!(pair.constraint_names(), ["shake"]);
    let equations = ShakenPair::equations().text;
    assert!(equations.contains("0 = right.v - left.v - a*w*cos(w*t)"), "{equations}");
    let q = VecQ::<ShakenPair>::from([0.0, 1.0]);
    // From rest, the projection gives the masses the prescribed relative velocity a ω with no
    // momentum: the change that costs the least kinetic energy.
    let start = consistent_state(&pair, 0.0, &q, &VecQ::<ShakenPair>::zeros(), Consistency::default())
        .expect("consistent");
    // (To 1e-9: the projection regularises the mass matrix by 1e-10 of its size.)
    let (relative, momentum) = (start.v[1] - start.v[0], start.v[0] + 3.0 * start.v[1]);
    assert!((relative - 0.8).abs() < 1e-14 && momentum.abs() < 1e-9, "v0 = {:?}", start.v);
    let tol = 1e-11;
    let dt = 2e-3;
    let mut radau = Radau::new(&pair, RadauOptions::tolerances(tol, tol)).expect("valid");
    let solution = radau.solve(0.0, &start, 2.0, &Sampling::Every(dt)).expect("integrates");
    for (k, &t) in solution.t().iter().enumerate() {
        let x = shaken_positions(&[1.0, 3.0], &[0.0, 1.0], (0.2, 4.0), t);
        let (left, right) = (ShakenPair::left(FreeMass::X), ShakenPair::right(FreeMass::X));
        // Samples between steps, from the collocation polynomial: 1e-8.
        assert!((solution.q(left)[k] - x[0]).abs() < 1e-8, "left at t = {t}");
        assert!((solution.q(right)[k] - x[1]).abs() < 1e-8, "right at t = {t}");
    }
    // The shaker is the only source: the energy follows its power, which is also the power of
    // the interconnection forces.
    // (From the interpolated multipliers, 1.5e-9.)
    let error = balance_error(&solution, dt);
    assert!(error < 1e-8, "balance error {error:e}");
    for (p, c) in solution.interconnection_power().iter().zip(solution.constraint_power()) {
        assert!((p - c).abs() < 1e-8 * (1.0 + c.abs()), "{p} against {c}");
    }
    // The variational integrator, on the same interconnection.
    let mut vi = Variational::new(&pair, 1e-3, VariationalOptions::default()).expect("valid");
    vi.start(0.0, &start, 2.0).expect("starts");
    while !vi.finished() {
        vi.step().expect("steps");
    }
    let x = shaken_positions(&[1.0, 3.0], &[0.0, 1.0], (0.2, 4.0), 2.0);
    assert!((vi.state().q[0] - x[0]).abs() < 1e-6 && (vi.state().q[1] - x[1]).abs() < 1e-6);
}

#[test]
fn an_array_of_subsystems_may_prescribe_relative_velocities() {
    let masses = [1.0, 2.0, 0.5, 1.5, 1.0];
    let row = ShakenRow { cells: masses.iter().map(|&m| FreeMass { m }).collect(), a: 0.1, w: 3.0 };
    assert_eq!(row.constraint_names().len(), 4);
    let x0: Vec<f64> = (0..5).map(|i| i as f64).collect();
    let q = VecQ::<ShakenRow>::from_vec(x0.clone());
    let start = consistent_state(&row, 0.0, &q, &VecQ::<ShakenRow>::zeros(5), Consistency::default())
        .expect("consistent");
    let tol = 1e-11;
    let mut radau = Radau::new(&row, RadauOptions::tolerances(tol, tol)).expect("valid");
    let times = vec![0.5, 1.0, 1.5, 2.0];
    let solution = radau.solve(0.0, &start, 2.0, &Sampling::Times(times.clone())).expect("integrates");
    // Samples inside a step come from its collocation polynomial, not held to the tolerance:
    // the worst error at t = 0.5 and 1.5 ranges from 1.9e-10 to 1.3e-9 as the first step
    // ranges from 2e-6 to 1e-2 and moves the steps; at t = 1 and 2 it stays below 2e-11.
    for (k, &t) in times.iter().enumerate() {
        let x = shaken_positions(&masses, &x0, (0.1, 3.0), t);
        for (i, xi) in x.iter().enumerate() {
            let key = row.cells(i, FreeMass::X);
            assert!((solution.q(key)[k] - xi).abs() < 5e-9, "cells[{i}] at t = {t}");
        }
    }
}

// ---- Bad prescriptions end in typed errors -----------------------------------------------------

/// A prescription that stops being defined: `x = √(1 − t)` has no value after t = 1.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v), lagrangian = 0.5 * m * v * v)]
#[dirac(holonomic(track) = x - sqrt(1.0 - t))]
struct EndingTrack {
    m: f64,
}

/// A point on the unit circle prescribed to be at x = 2 + t: out of reach.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => v, y => w), lagrangian = 0.5 * m * (v * v + w * w))]
#[dirac(holonomic(ring) = x * x + y * y - 1.0, holonomic(reach) = x - 2.0 - t)]
struct OutOfReach {
    m: f64,
}

#[test]
fn bad_prescriptions_end_in_typed_errors() {
    // Started where the track has a value and run past its end: an error naming the time and
    // the cause, not a panic, a hang or a NaN solution.
    let track = EndingTrack { m: 1.0 };
    let start = consistent_state(
        &track,
        0.0,
        &VecQ::<EndingTrack>::from([1.0]),
        &VecQ::<EndingTrack>::zeros(),
        Consistency::default(),
    )
    .expect("consistent at t = 0");
    assert!((start.v[0] + 0.5).abs() < 1e-12, "v = d√(1 − t)/dt = −1/2 at t = 0");
    let mut radau = Radau::new(&track, RadauOptions::tolerances(1e-8, 1e-8)).expect("valid");
    let error = radau.solve(0.0, &start, 2.0, &Sampling::Steps).expect_err("the track ends at t = 1");
    let message = error.to_string();
    // Radau's Newton iteration meets the NaN of √(1 − t) past t = 1 in the track's equation.
    assert!(matches!(error, SimError::NonFinite { .. }) && message.contains("track"), "{message}");
    let mut vi = Variational::new(&track, 1e-2, VariationalOptions::default()).expect("valid");
    let error = vi.solve(0.0, &start, 2.0, &Sampling::Steps).expect_err("the track ends at t = 1");
    assert!(matches!(error, SimError::NonFinite { t, .. } if t <= 1.0 + 1e-12), "{error}");

    // Past t = 1 there is no consistent state at all.
    let error = consistent_state(
        &track,
        1.5,
        &VecQ::<EndingTrack>::from([0.0]),
        &VecQ::<EndingTrack>::zeros(),
        Consistency::default(),
    )
    .expect_err("no track at t = 1.5");
    assert!(matches!(error, SimError::NonFinite { .. }), "{error}");
    assert!(error.to_string().contains("track"), "{error}");

    // A belt whose speed jumps between steps would need an impulse: the change is refused with
    // the constraint it moved, and the model can be put back and the run continued.
    let mut disk = DiskOnBelt { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045, belt: 0.6 };
    let start = disk_start(&disk, disk.r, disk.belt, (2.0, 0.9, 0.3));
    let mut radau = Radau::new(&mut disk, RadauOptions::tolerances(1e-10, 1e-10)).expect("valid");
    radau.start(0.0, &start, 1.0).expect("starts");
    radau.step().expect("steps");
    let error = radau.set_input(DiskOnBelt::BELT, 0.9).expect_err("the belt cannot jump");
    assert!(
        matches!(&error, SimError::ConstraintMoved { equation, .. } if equation.contains("roll_x")),
        "{error}"
    );
    radau.set_input(DiskOnBelt::BELT, 0.6).expect("the belt back at its speed");
    while !radau.finished() {
        radau.step().expect("steps");
    }
    // Through a sampled controller the same jump is an impulse: at each sample the disk's
    // velocities jump to the consistent ones nearest in the kinetic-energy norm, on the belt's
    // new speed, and the run goes on.
    let mut jumpy = |t: f64, _: &State<DiskOnBelt>, model: &mut DiskOnBelt| model.belt = 0.6 + t;
    let solution = radau
        .solve_sampled(0.0, &start, 1.0, 0.25, &Sampling::Steps, &mut jumpy)
        .expect("the belt's jumps move the disk by impulses");
    let worst = solution.constraint_residual().iter().copied().fold(0.0, f64::max);
    assert!(worst < 1e-8, "the rolling constraints after the jumps: {worst}");
    // Each jump is recorded twice at its sample, before and after.
    let at = |t: f64| solution.t().iter().filter(|&&s| s == t).count();
    assert_eq!((at(0.25), at(0.5), at(0.75)), (2, 2, 2));
    assert_eq!(disk.belt, 0.6 + 0.75);
    disk.belt = 0.6;
    // And through the model handed out for a change, then a restart, with either integrator.
    let mut vi = Variational::new(&mut disk, 1e-2, VariationalOptions::default()).expect("valid");
    vi.start(0.0, &start, 1.0).expect("starts");
    vi.step().expect("steps");
    vi.model_mut().expect("exclusive").belt = 0.9;
    let error = vi.restart_until(1.0).expect_err("the belt cannot jump");
    assert!(matches!(error, SimError::ConstraintMoved { .. }), "{error}");
    vi.model_mut().expect("exclusive").belt = 0.6;
    vi.restart_until(1.0).expect("the belt back at its speed");

    // A prescription out of reach: the consistent initialisation says which constraint it
    // cannot meet.
    let reach = OutOfReach { m: 1.0 };
    let q = VecQ::<OutOfReach>::new(1.0, 0.0);
    let error = consistent_state(&reach, 0.0, &q, &VecQ::<OutOfReach>::zeros(), Consistency::default())
        .expect_err("x = 2 is off the unit circle");
    assert!(matches!(error, SimError::InconsistentInitialState { .. }), "{error}");
}

/// Two free masses, the right one's velocity set by the left one's position: the part
/// without velocities, `−x_l`, is read from a coordinate of a subsystem.
#[derive(Interconnection, Clone, Debug)]
#[dirac(constraint(follow) = right.v - left.x)]
struct Follower {
    left: FreeMass,
    right: FreeMass,
}

/// Two free masses moving together: nothing prescribed.
#[derive(Interconnection, Clone, Debug)]
#[dirac(constraint(tie) = right.v - left.v)]
struct Tied {
    left: FreeMass,
    right: FreeMass,
}

/// A composite of a prescribed model and a free one.
#[derive(Interconnection, Clone, Debug)]
#[dirac(constraint(tie) = mass.v - bead.vx)]
struct BeadAndMass {
    bead: BeadOnRod,
    mass: FreeMass,
}

#[test]
fn models_say_whether_they_prescribe_motion() {
    // Decided when they compile, from the constraints' parts without velocities.
    const { assert!(ShakenPendulum::PRESCRIBED && DraggedMass::PRESCRIBED && BeadOnRod::PRESCRIBED) };
    const { assert!(DiskOnBelt::PRESCRIBED && SliderCrank::PRESCRIBED) };
    const {
        assert!(
            !crate::zoo::Pendulum::PRESCRIBED
                && !crate::zoo::RollingDisk::PRESCRIBED
                && !FreeMass::PRESCRIBED
        )
    };
    const {
        assert!(
            ShakenPair::PRESCRIBED
                && ShakenRow::PRESCRIBED
                && Follower::PRESCRIBED
                && BeadAndMass::PRESCRIBED
        )
    };
    const { assert!(!Tied::PRESCRIBED && !crate::zoo::Chain::PRESCRIBED && !crate::zoo::Ladder::PRESCRIBED) };
    // The follower's rate is −x_l, from the position of the left mass.
    let follower = Follower { left: FreeMass { m: 1.0 }, right: FreeMass { m: 1.0 } };
    let mut b = VecC::<Follower>::zeros();
    follower.constraint_rate(0.0, &VecQ::<Follower>::new(0.7, 3.0), &mut b);
    assert_eq!(b[0], -0.7);
}

#[test]
fn a_consistent_state_depends_on_the_start_time() {
    // The bead put on the rod at t0 = 0.5, where the rod points at ω t0, at rest: the projection
    // gives it the rod's velocity there, and it slides out as r0 cosh(ω (t − t0)).
    let bead = BeadOnRod { m: 0.7, w: 1.3 };
    let (r0, w, t0) = (0.5, bead.w, 0.5);
    let q = VecQ::<BeadOnRod>::new(r0 * (w * t0).cos(), r0 * (w * t0).sin());
    let start = consistent_state(&bead, t0, &q, &VecQ::<BeadOnRod>::zeros(), Consistency::default())
        .expect("consistent");
    let across = VecQ::<BeadOnRod>::new(-(w * t0).sin(), (w * t0).cos()) * (w * r0);
    assert!((start.v - across).amax() < 1e-14, "v0 = {:?}", start.v);
    // Started at t = 0 instead, the same positions are off the rod.
    let error = consistent_state(&bead, 0.0, &q, &VecQ::<BeadOnRod>::zeros(), Consistency::default())
        .map(|s| (s.q - q).amax());
    assert!(matches!(error, Ok(moved) if moved > 0.1), "{error:?}");
    let mut radau = Radau::new(&bead, RadauOptions::tolerances(1e-11, 1e-11)).expect("valid");
    let solution = radau.solve(t0, &start, 2.0, &Sampling::Times(vec![1.0, 2.0])).expect("integrates");
    // t = 2 ends the last step; t = 1 falls inside one and is read from its collocation
    // polynomial, whose error is not held to the tolerance: from 8e-11 to 1.5e-9 relative as
    // the first step ranges from 1e-6 to 1e-2 and moves the steps around t = 1.
    for (k, t, bound) in [(0, 1.0, 5e-9), (1, 2.0, 1e-10)] {
        let (x, y) = (solution.q(BeadOnRod::X)[k], solution.q(BeadOnRod::Y)[k]);
        let r = r0 * (w * (t - t0)).cosh();
        assert!((x.hypot(y) - r).abs() < bound * r, "r({t}) = {} against {r}", x.hypot(y));
        assert!((y.atan2(x) - w * t).abs() < 1e-9, "on the rod at t = {t}");
    }
}

#[test]
fn absurd_rates_of_prescription_end_in_typed_errors() {
    let q = VecQ::<BeadOnRod>::new(0.5, 0.0);
    let start = |bead: &BeadOnRod| {
        consistent_state(bead, 0.0, &q, &VecQ::<BeadOnRod>::zeros(), Consistency::default())
    };
    // A NaN rate is named as a parameter.
    let error = start(&BeadOnRod { m: 1.0, w: f64::NAN }).expect_err("NaN rate");
    assert!(
        matches!(&error, SimError::InvalidParameter { .. }) && error.to_string().contains("`w`"),
        "{error}"
    );
    // A rate whose time derivative overflows: named at the start.
    let error = start(&BeadOnRod { m: 1.0, w: 1e300 }).expect_err("ω² overflows");
    assert!(
        matches!(&error, SimError::NonFinite { .. }) && error.to_string().contains("∂(A v + b)/∂t"),
        "{error}"
    );
    // A rod at rest is no prescription: the bead stays where it is.
    let still = BeadOnRod { m: 1.0, w: 0.0 };
    let s = start(&still).expect("consistent");
    let mut radau = Radau::new(&still, RadauOptions::tolerances(1e-8, 1e-8)).expect("valid");
    let solution = radau.solve(0.0, &s, 1.0, &Sampling::Steps).expect("integrates");
    assert!(solution.q(BeadOnRod::X).iter().all(|x| (x - 0.5).abs() < 1e-12));
    // A rod turned at 10¹² rad/s: a typed failure of either integrator at the start, not a hang
    // or a result.
    let fast = BeadOnRod { m: 1.0, w: 1e12 };
    let s = start(&fast).expect("consistent at t = 0");
    let mut radau = Radau::new(&fast, RadauOptions::tolerances(1e-8, 1e-8)).expect("valid");
    let error = radau.solve(0.0, &s, 1.0, &Sampling::Steps).expect_err("too fast to follow");
    assert!(matches!(error, SimError::NewtonDiverged { .. } | SimError::StepSizeTooSmall { .. }), "{error}");
    let mut vi = Variational::new(&fast, 1e-3, VariationalOptions::default()).expect("valid");
    let error = vi.solve(0.0, &s, 1.0, &Sampling::Steps).expect_err("too fast for the step");
    assert!(matches!(error, SimError::NewtonDiverged { .. } | SimError::Unstable { .. }), "{error}");
}
