//! Values sampled between the steps (Radau's and Explicit's) against closed forms: as
//! accurate as the steps' ends.
//!
//! References: the Kepler orbit from Kepler's equation solved by Newton's method to round-off
//! (`zoo::kepler_exact`), and the bead on a turning rod `r = r0 cosh ωt` (`zoo::bead_exact`).
//! Neither goes through dirac.

use dirac::DenseOutput;
use dirac::State;
use dirac::prelude::*;

use crate::zoo::{BeadOnRod, Kepler, bead_exact, kepler_exact};

/// The largest error of positions, velocities and momenta (over `mass`) at the steps' ends,
/// and at 19 points inside every step, against `exact`.
fn errors<M: LagrangeDirac>(
    model: &M,
    (start, t_end): (&State<M>, f64),
    options: RadauOptions,
    mass: f64,
    exact: impl Fn(f64) -> [f64; 4],
) -> (f64, f64)
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let radau = Radau::new(model, options).expect("valid");
    errors_of(radau, (start, t_end), 20, mass, exact)
}

/// [`errors`] for any integrator, at `parts − 1` points inside every step.
fn errors_of<M: LagrangeDirac>(
    mut integrator: impl Integrator<M>,
    (start, t_end): (&State<M>, f64),
    parts: u32,
    mass: f64,
    exact: impl Fn(f64) -> [f64; 4],
) -> (f64, f64)
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let error = |t: f64, s: &State<M>| {
        let x = exact(t);
        let got = [s.q[0], s.q[1], s.v[0], s.v[1], s.p[0] / mass, s.p[1] / mass];
        got.iter().zip([x[0], x[1], x[2], x[3], x[2], x[3]]).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
    };
    integrator.start(0.0, start, t_end).expect("starts");
    let (mut at_ends, mut between) = (0.0f64, 0.0f64);
    let mut out = start.clone();
    while !integrator.finished() {
        let t0 = integrator.t();
        integrator.step().expect("steps");
        let t1 = integrator.t();
        at_ends = at_ends.max(error(t1, integrator.state()));
        for k in 1..parts {
            let t = t0 + (t1 - t0) * f64::from(k) / f64::from(parts);
            integrator.interpolate(t, &mut out);
            between = between.max(error(t, &out));
        }
    }
    (at_ends, between)
}

fn kepler() -> (Kepler, State<Kepler>) {
    let x = kepler_exact(0.6, 0.0);
    let (q, v) = (VecQ::<Kepler>::from([x[0], x[1]]), VecQ::<Kepler>::from([x[2], x[3]]));
    let start = consistent_state(&Kepler {}, 0.0, &q, &v, Consistency::default()).expect("consistent");
    (Kepler {}, start)
}

fn bead() -> (BeadOnRod, State<BeadOnRod>) {
    let bead = BeadOnRod { m: 0.7, w: 1.3 };
    let q = VecQ::<BeadOnRod>::from([0.5, 0.0]);
    let start = consistent_state(&bead, 0.0, &q, &VecQ::<BeadOnRod>::zeros(), Consistency::default())
        .expect("consistent");
    (bead, start)
}

#[test]
fn samples_between_steps_are_as_accurate_as_the_steps_ends() {
    let (kepler, kepler_start) = kepler();
    let (bead, bead_start) = bead();
    for k in 4..=12 {
        let tol = 10f64.powi(-k);
        let options = RadauOptions::tolerances(tol, tol);
        // Over one orbit's first sixth, where the global error has not yet grown past the local
        // errors inside a step, and over the whole orbit.
        for span in [1.0, 2.0 * std::f64::consts::PI] {
            let (ends, between) =
                errors(&kepler, (&kepler_start, span), options, 1.0, |t| kepler_exact(0.6, t));
            assert!(
                between <= 3.0 * ends,
                "Kepler to {span} at {tol:e}: {between:e} between steps, {ends:e} at their ends"
            );
        }
        let (ends, between) =
            errors(&bead, (&bead_start, 2.0), options, bead.m, |t| bead_exact(bead.w, 0.5, t));
        assert!(between <= 3.0 * ends, "bead at {tol:e}: {between:e} between steps, {ends:e} at their ends");
    }
}

/// The bead at every tolerance from 1e-4 to 1e-12, a hundred points inside every step, in
/// both integrators with dense output. Measured: at most 1.8× the steps' ends (Radau at 1e-12)
/// and 1.7× (Explicit at 1e-11 and 1e-12).
#[test]
fn samples_on_the_bead_are_within_three_times_the_steps_ends_in_both_integrators() {
    let (bead, bead_start) = bead();
    let exact = |t| bead_exact(bead.w, 0.5, t);
    for k in 4..=12 {
        let tol = 10f64.powi(-k);
        let radau = Radau::new(&bead, RadauOptions::tolerances(tol, tol)).expect("valid");
        let (ends, between) = errors_of(radau, (&bead_start, 2.0), 100, bead.m, exact);
        assert!(between <= 3.0 * ends, "Radau at {tol:e}: {between:e} between steps, {ends:e} at their ends");
        let explicit = Explicit::new(&bead, ExplicitOptions::tolerances(tol, tol)).expect("valid");
        let (ends, between) = errors_of(explicit, (&bead_start, 2.0), 100, bead.m, exact);
        assert!(
            between <= 3.0 * ends,
            "Explicit at {tol:e}: {between:e} between steps, {ends:e} at their ends"
        );
    }
}

#[test]
fn the_collocation_polynomial_alone_is_what_the_correction_improves_on() {
    // The check above can fail: RADAU5's own dense output misses it by far at tight tolerances.
    let (bead, bead_start) = bead();
    let options =
        RadauOptions { dense_output: DenseOutput::Collocation, ..RadauOptions::tolerances(1e-11, 1e-11) };
    let (ends, between) = errors(&bead, (&bead_start, 2.0), options, bead.m, |t| bead_exact(bead.w, 0.5, t));
    assert!(between > 20.0 * ends, "{between:e} between steps, {ends:e} at their ends");
}

#[test]
fn sampled_solutions_carry_the_accuracy() {
    // Through `solve` and `Sampling::Every`, as a plot or a CSV samples it. At this tolerance
    // the steps' ends are within 8e-11 of the closed form; before the correction, samples
    // between them were off by up to 4e-9.
    let (bead, bead_start) = bead();
    let solution = Radau::new(&bead, RadauOptions::tolerances(1e-11, 1e-11))
        .expect("valid")
        .solve(0.0, &bead_start, 2.0, &Sampling::Every(1e-3))
        .expect("integrates");
    for (k, &t) in solution.t().iter().enumerate() {
        let x = bead_exact(bead.w, 0.5, t);
        let got = [solution.q(BeadOnRod::X)[k], solution.q(BeadOnRod::Y)[k], solution.v(BeadOnRod::X)[k]];
        for (a, b) in got.iter().zip(x) {
            assert!((a - b).abs() < 3e-10, "t = {t}: {a} against {b}");
        }
    }
}
