//! For every model in the zoo: the generated flat Jacobian equals central differences of the
//! generated residual (the reference), at seeded random states.

use crate::util::{check_csc_against_dense, check_jacobian_by_differences};
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
