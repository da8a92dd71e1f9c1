//! The paper's primitive systems 1 and 2 (Yoshimura, Jacobs & Marsden, §VI.C): the generated
//! momentum equations equal eqs. (9) and (10), with the port efforts f2, f̄2 external (zero
//! until interconnected), checked at seeded random states. The references are the equations
//! as printed in the paper.

use dirac::State;
use dirac::prelude::*;

use crate::util::Rng;
use crate::zoo::{Primitive1, Primitive2};

fn assert_close(got: f64, want: f64, what: &str) {
    assert!((got - want).abs() <= 1e-13 * want.abs().max(1.0), "{what}: generated {got}, paper {want}");
}

/// Eq. (9): ṗ1 = −k1 x1 − k2 (x1 − x2), ṗ2 = k2 (x1 − x2) + f2, with p1 = m1 v1, p2 = m2 v2.
#[test]
fn primitive_system_1_is_eq_9() {
    let sys = Primitive1 { m1: 1.0, m2: 2.0, k1: 4.0, k2: 5.0 };
    let mut rng = Rng::new(41);
    for _ in 0..50 {
        let mut s = State::<Primitive1>::zeros();
        s.set_q(Primitive1::X1, rng.uniform(-1.0, 1.0)).set_q(Primitive1::X2, rng.uniform(-1.0, 1.0));
        s.set_v(Primitive1::X1, rng.uniform(-1.0, 1.0)).set_v(Primitive1::X2, rng.uniform(-1.0, 1.0));
        let (x1, x2) = (s.q(Primitive1::X1), s.q(Primitive1::X2));
        let mut rb = ResidualBlocks::<Primitive1>::zeros();
        sys.residual_blocks(0.0, &s.q, &s.v, &s.lambda, &mut rb);
        assert_close(rb.momentum_rate[0], -sys.k1 * x1 - sys.k2 * (x1 - x2), "pdot_1");
        assert_close(rb.momentum_rate[1], sys.k2 * (x1 - x2), "pdot_2 (f2 = 0)");
        assert_close(rb.dl_dv[0], sys.m1 * s.v(Primitive1::X1), "p_1");
        assert_close(rb.dl_dv[1], sys.m2 * s.v(Primitive1::X2), "p_2");
    }
    assert_eq!(sys.ports(), [Primitive1::X2]);
}

/// Eq. (10): ṗ̄2 = k3 (x3 − x̄2) + f̄2, ṗ3 = −k3 (x3 − x̄2), with p̄2 = 0 (degenerate) and p3 = m3 v3.
#[test]
fn primitive_system_2_is_eq_10() {
    let sys = Primitive2 { m3: 3.0, k3: 6.0 };
    let mut rng = Rng::new(42);
    for _ in 0..50 {
        let mut s = State::<Primitive2>::zeros();
        s.set_q(Primitive2::X2BAR, rng.uniform(-1.0, 1.0)).set_q(Primitive2::X3, rng.uniform(-1.0, 1.0));
        s.set_v(Primitive2::X2BAR, rng.uniform(-1.0, 1.0)).set_v(Primitive2::X3, rng.uniform(-1.0, 1.0));
        let (x2bar, x3) = (s.q(Primitive2::X2BAR), s.q(Primitive2::X3));
        let mut rb = ResidualBlocks::<Primitive2>::zeros();
        sys.residual_blocks(0.0, &s.q, &s.v, &s.lambda, &mut rb);
        assert_close(rb.momentum_rate[0], sys.k3 * (x3 - x2bar), "pdot_2bar (f2bar = 0)");
        assert_close(rb.momentum_rate[1], -sys.k3 * (x3 - x2bar), "pdot_3");
        assert_close(rb.dl_dv[0], 0.0, "p_2bar");
        assert_close(rb.dl_dv[1], sys.m3 * s.v(Primitive2::X3), "p_3");
    }
    let mut lvv = MatQQ::<Primitive2>::zeros();
    sys.l_vv(0.0, &VecQ::<Primitive2>::zeros(), &VecQ::<Primitive2>::zeros(), &mut lvv);
    assert_eq!(lvv.determinant(), 0.0, "L2 is degenerate: no kinetic term in v2bar");
}

/// The equations printed for people show eqs. (9) and (10), with the port efforts.
#[test]
fn printed_equations_show_the_port_efforts() {
    let text = Primitive1::equations().text;
    assert!(text.contains("dp_x1/dt = -k1*x1 + k2*(x2 - x1)"), "{text}");
    assert!(text.contains("dp_x2/dt = -k2*(x2 - x1) + f_x2"), "{text}");
    assert!(text.contains("p_x2 = m2*v2"), "{text}");
    let text = Primitive2::equations().text;
    assert!(text.contains("dp_x2bar/dt = k3*(x3 - x2bar) + f_x2bar"), "{text}");
    assert!(text.contains("p_x2bar = 0"), "{text}");
    let latex = Primitive2::equations().latex;
    assert!(
        latex.contains(
            "\\dot{p}_{\\bar{x}_{2}} &= k_{3} \\left(x_{3} - \\bar{x}_{2}\\right) + f_{\\bar{x}_{2}}"
        ),
        "{latex}"
    );
}
