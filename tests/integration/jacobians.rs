//! For every model in the zoo: the generated flat Jacobian equals central differences of the
//! generated residual (the reference), at seeded random states.

use dirac::State;
use dirac::Storage;
use dirac::nalgebra::DefaultAllocator;
use dirac::prelude::*;

use crate::util::{Rng, check_csc_against_dense, check_jacobian_by_differences, random_y};
use crate::zoo::*;

#[test]
fn primitive_systems_and_chain() {
    check_jacobian_by_differences(&Primitive1 { m1: 1.0, m2: 2.0, k1: 4.0, k2: 5.0 }, 1, 20);
    check_jacobian_by_differences(&Primitive2 { m3: 3.0, k3: 6.0 }, 2, 20);
    let chain = MassSpringChain { m1: 1.0, m2: 2.0, m3: 3.0, k1: 4.0, k2: 5.0, k3: 6.0 };
    check_jacobian_by_differences(&chain, 3, 20);
}

#[test]
fn pendulum_and_rolling_disk() {
    check_jacobian_by_differences(&Pendulum { m: 1.3, g: 9.81, l: 0.7 }, 4, 20);
    check_jacobian_by_differences(&RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 }, 5, 20);
}

#[test]
fn forced_and_degenerate_models() {
    check_jacobian_by_differences(&DrivenOscillator { m: 1.0, k: 2.0, c: 0.3, a: 0.5, w: 1.7 }, 6, 20);
    check_jacobian_by_differences(&LcCircuit { ind: 1.0, cap: 1.0 }, 7, 20);
}

#[test]
fn models_with_prescribed_motion() {
    check_jacobian_by_differences(&ShakenPendulum { m: 1.3, g: 9.81, l: 0.7, a: 0.2, w: 3.0 }, 70, 20);
    check_jacobian_by_differences(&DraggedMass { m: 1.5, k: 2.0, c: 0.4 }, 71, 20);
    check_jacobian_by_differences(&BeadOnRod { m: 0.8, w: 2.5 }, 72, 20);
    check_jacobian_by_differences(
        &DiskOnBelt { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045, belt: 0.7 },
        73,
        20,
    );
    let crank = SliderCrank { m1: 1.0, m2: 2.0, m3: 0.5, r: 0.3, l: 1.0, g: 9.81, c: 0.2, w: 4.0 };
    check_jacobian_by_differences(&crank, 74, 20);
    check_csc_against_dense(&crank, 75, 5);
}

#[test]
fn eight_link_pendulum() {
    check_jacobian_by_differences(&Pendulum8 { m: 0.5, l: 0.25, g: 9.81 }, 8, 5);
}

#[test]
fn every_supported_function() {
    check_jacobian_by_differences(&AllFunctions { m: 1.5, k: 0.7 }, 9, 40);
}

/// Away from their switching surfaces (random states are that with probability 1 − 1e-5),
/// the branches' derivatives are the function's.
#[test]
fn non_smooth_functions_and_conditionals() {
    let model = NonSmooth { m: 1.2, k: 2.0, gap: 0.3, c: 0.4, fmax: 0.5, mu: 0.25 };
    check_jacobian_by_differences(&model, 10, 60);
}

#[test]
fn interconnected_models() {
    let chain = paper_chain();
    check_jacobian_by_differences(&chain, 61, 10);
    let gear = RackAndPinion { wheel: Wheel { j: 0.2, k_theta: 3.0 }, cart: Cart { m: 1.5, k: 2.0 }, r: 0.3 };
    check_jacobian_by_differences(&gear, 62, 10);
    let coupled =
        CoupledByOneForm { wheel: Wheel { j: 0.2, k_theta: 3.0 }, cart: Cart { m: 1.5, k: 2.0 }, c: 0.7 };
    check_jacobian_by_differences(&coupled, 63, 20);
    let tail = Tail { m: 1.0, k: 2.0 };
    let head = Chain3 { left: Primitive1 { m1: 1.0, m2: 2.0, k1: 4.0, k2: 5.0 }, right: tail.clone() };
    let five = Chain5 { body: Chain4 { head, tail: tail.clone() }, end: tail };
    check_jacobian_by_differences(&five, 64, 5);
}

/// The compressed-sparse-column output of every derived model against its dense Jacobian.
#[test]
fn sparse_jacobians_match_the_dense_ones() {
    check_csc_against_dense(&Primitive1 { m1: 1.0, m2: 2.0, k1: 4.0, k2: 5.0 }, 11, 5);
    check_csc_against_dense(&MassSpringChain { m1: 1.0, m2: 2.0, m3: 3.0, k1: 4.0, k2: 5.0, k3: 6.0 }, 12, 5);
    check_csc_against_dense(&Pendulum { m: 1.3, g: 9.81, l: 0.7 }, 13, 5);
    check_csc_against_dense(&RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 }, 14, 5);
    check_csc_against_dense(&DrivenOscillator { m: 1.0, k: 2.0, c: 0.3, a: 0.5, w: 1.7 }, 15, 5);
    check_csc_against_dense(&LcCircuit { ind: 1.0, cap: 1.0 }, 16, 5);
    check_csc_against_dense(&Pendulum8 { m: 0.5, l: 0.25, g: 9.81 }, 17, 3);
    check_csc_against_dense(&AllFunctions { m: 1.5, k: 0.7 }, 18, 5);
}

/// The event functions' gradients (`Hybrid::event_derivatives`: with respect to positions,
/// velocities, multipliers, time and every parameter) against central differences of the
/// generated event functions, at seeded random states: a model switching on a velocity and a
/// position, one with a constraint, the zoo's model with every non-smooth function, and an
/// interconnection of two models with switching surfaces (each part's rows placed at its
/// coordinates and its parameters' offset).
#[test]
fn event_gradients_match_central_differences() {
    let spring = CoulombSpring { m: 1.0, k: 4.0, mu: 0.05, a: 0.1, f: 0.2 };
    check_event_gradients(&spring, 90);
    check_event_gradients(&DampedPastW { m: 0.7, g: 9.81, l: 1.0, w: 0.3, c: 0.8 }, 91);
    check_event_gradients(&NonSmooth { m: 1.2, k: 2.0, gap: 0.3, c: 0.4, fmax: 0.5, mu: 0.25 }, 92);
    let right = CoulombSpring { m: 2.0, k: 3.0, mu: 0.1, a: -0.2, f: 0.4 };
    check_event_gradients(&CoulombPair { left: spring, right, c: 0.3 }, 93);
}

fn check_event_gradients<M: dirac::Hybrid + Parameters + Clone>(model: &M, seed: u64)
where
    DefaultAllocator: Storage<M>,
{
    let sizes = model.sizes();
    let (n, m, params) = (sizes.nq, sizes.nc, model.parameter_count());
    let count = model.event_declarations().len();
    let width = 2 * n + m + 1 + params;
    assert!(count > 0);
    assert_eq!(model.event_derivatives_len(), count * width, "generated for every event");
    let mut rng = Rng::new(seed);
    let mut values = vec![0.0; count];
    let (mut plus, mut minus) = (vec![0.0; count], vec![0.0; count]);
    let mut gradient = vec![0.0; count * width];
    for _ in 0..10 {
        let state = State::<M>::from_y(sizes, &random_y(model, &mut rng));
        let t = rng.uniform(0.0, 2.0);
        model.event_derivatives(t, &state.q, &state.v, &state.lambda, &mut gradient);
        model.events(t, &state.q, &state.v, &state.lambda, &mut values);
        let h = 1e-6;
        // Column `x` by central differences of the events along `nudge(x, ±h)`.
        let mut column = |x: usize, nudge: &mut dyn FnMut(f64, &mut [f64])| {
            nudge(h, &mut plus);
            nudge(-h, &mut minus);
            for e in 0..count {
                let (fd, got) = ((plus[e] - minus[e]) / (2.0 * h), gradient[e * width + x]);
                assert!(
                    (fd - got).abs() <= 1e-6 * fd.abs().max(1.0),
                    "event {e}, column {x}: {got} against {fd}"
                );
            }
        };
        for i in 0..n {
            column(i, &mut |d, out| {
                let mut q = state.q.clone();
                q[i] += d;
                model.events(t, &q, &state.v, &state.lambda, out);
            });
            column(n + i, &mut |d, out| {
                let mut v = state.v.clone();
                v[i] += d;
                model.events(t, &state.q, &v, &state.lambda, out);
            });
        }
        for r in 0..m {
            column(2 * n + r, &mut |d, out| {
                let mut lambda = state.lambda.clone();
                lambda[r] += d;
                model.events(t, &state.q, &state.v, &lambda, out);
            });
        }
        column(2 * n + m, &mut |d, out| model.events(t + d, &state.q, &state.v, &state.lambda, out));
        for k in 0..params {
            column(2 * n + m + 1 + k, &mut |d, out| {
                let mut changed = model.clone();
                changed.set_parameter_value(k, model.parameter_value(k) + d);
                changed.events(t, &state.q, &state.v, &state.lambda, out);
            });
        }
    }
}
