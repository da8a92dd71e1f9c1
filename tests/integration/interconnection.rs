//! Interconnected models against hand-written monolithic equivalents, at consistent states.
//!
//! A state of a composite is consistent when the interconnection constraints hold (`v2 = v̄2`)
//! and its multipliers satisfy the consistency conditions. For the paper's chain, p̄2 ≡ 0 gives
//! ṗ̄2 = 0, so μ = k3 (x3 − x̄2) (DESIGN.md §1.3); for the gear, the constraint's time
//! derivative gives μ (derived in `rack_and_pinion_is_the_geared_model`). The references are
//! the monolithic models' generated equations, or formulas derived by hand.

use dirac::Fixed;
use dirac::State;
use dirac::prelude::*;

use crate::util::Rng;
use crate::zoo::*;

fn chain() -> Chain {
    paper_chain()
}

fn monolithic() -> MassSpringChain {
    MassSpringChain { m1: 1.0, m2: 2.0, m3: 3.0, k1: 4.0, k2: 5.0, k3: 6.0 }
}

fn assert_close(got: f64, want: f64, what: &str) {
    assert!((got - want).abs() <= 1e-12 * want.abs().max(1.0), "{what}: composite {got}, reference {want}");
}

/// A consistent state of the torn chain for positions x and velocities v of the three masses.
fn consistent_chain_state(x: [f64; 3], v: [f64; 3]) -> State<Chain> {
    let mut s = State::<Chain>::zeros();
    let coordinates = [
        (Chain::left(Primitive1::X1), 0),
        (Chain::left(Primitive1::X2), 1),
        (Chain::right(Primitive2::X2BAR), 1),
        (Chain::right(Primitive2::X3), 2),
    ];
    for (c, i) in coordinates {
        s.set_q(c, x[i]).set_v(c, v[i]);
    }
    s.set_lambda(Chain::CONNECT0, chain().right.k3 * (x[2] - x[1]));
    s
}

#[test]
fn chain_reduces_to_the_monolithic_chain() {
    let (torn, whole) = (chain(), monolithic());
    let mut rng = Rng::new(51);
    for _ in 0..50 {
        let x = [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)];
        let v = [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)];
        let s = consistent_chain_state(x, v);
        let mut rb = ResidualBlocks::<Chain>::zeros();
        torn.residual_blocks(0.0, &s.q, &s.v, &s.lambda, &mut rb);

        let mut m = State::<MassSpringChain>::zeros();
        m.q.copy_from_slice(&x);
        m.v.copy_from_slice(&v);
        let mut mb = ResidualBlocks::<MassSpringChain>::zeros();
        whole.residual_blocks(0.0, &m.q, &m.v, &m.lambda, &mut mb);

        let rate = |c: Coordinate<Chain>| rb.momentum_rate[c.index()];
        assert_close(rate(Chain::left(Primitive1::X1)), mb.momentum_rate[0], "pdot_1");
        assert_close(rate(Chain::left(Primitive1::X2)), mb.momentum_rate[1], "pdot_2");
        assert_close(rate(Chain::right(Primitive2::X2BAR)), 0.0, "pdot_2bar (consistency)");
        assert_close(rate(Chain::right(Primitive2::X3)), mb.momentum_rate[2], "pdot_3");
        // The momenta: p2 of the composite carries m2 v2, p̄2 = 0.
        assert_close(rb.dl_dv[Chain::left(Primitive1::X2).index()], mb.dl_dv[1], "p_2");
        assert_close(rb.dl_dv[Chain::right(Primitive2::X2BAR).index()], 0.0, "p_2bar");
        assert_eq!(rb.constraint_velocity[Chain::CONNECT0.index()], 0.0, "v2 = v2bar");
    }
}

/// Interconnection forces by name: f̄2 = −k3 (x3 − x̄2) and f2 = −f̄2, and no power flows
/// through the interconnection (Tellegen).
#[test]
fn port_efforts_by_name_and_tellegen() {
    let torn = chain();
    let mut rng = Rng::new(52);
    for _ in 0..20 {
        let x = [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)];
        let v = [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)];
        let s = consistent_chain_state(x, v);
        let mut f = VecQ::<Chain>::zeros();
        torn.interconnection_forces(0.0, &s.q, &s.lambda, &mut f);
        let (f2, f2bar) = (f[Chain::LEFT_X2.index()], f[Chain::RIGHT_X2BAR.index()]);
        assert_close(f2bar, -torn.right.k3 * (x[2] - x[1]), "f2bar = -k3 (x3 - x2bar)");
        assert_close(f2, -f2bar, "f2 + f2bar = 0");
        assert_eq!(f[Chain::left(Primitive1::X1).index()], 0.0);
        assert!(torn.interconnection_power(0.0, &s.q, &s.v, &s.lambda).abs() < 1e-15, "Tellegen");
        // Off the constraint, the power is μ (v2 − v̄2).
        let mut off = s.clone();
        off.set_v(Chain::RIGHT_X2BAR, v[1] + 0.5);
        let mu = s.lambda(Chain::CONNECT0);
        assert_close(
            torn.interconnection_power(0.0, &off.q, &off.v, &off.lambda),
            -0.5 * mu,
            "power off the constraint",
        );
    }
}

#[test]
fn composite_names() {
    let chain = paper_chain();
    assert_eq!(chain.coordinate_names(), ["left.x1", "left.x2", "right.x2bar", "right.x3"]);
    assert_eq!(chain.velocity_names(), ["left.v1", "left.v2", "right.v2bar", "right.v3"]);
    assert_eq!(chain.constraint_names(), ["connect0"]);
    assert_eq!(chain.ports(), [Chain::LEFT_X2, Chain::RIGHT_X2BAR]);
    assert_eq!(chain.coordinate("right.x3"), Some(Chain::right(Primitive2::X3)));
    assert_eq!(Chain::LEFT_X2.name(), "left.x2");
    assert_eq!((Chain::NQ, Chain::NC, Chain::NH), (4, 1, 0));
    assert_eq!(Chain5::NAMES.constraint_names(), ["body.head.connect0", "body.connect0", "connect0"]);
    let position = Chain5::NAMES.constraint_names().iter().position(|c| c == "body.head.connect0");
    assert_eq!(position, Some(Chain5::body_constraint(Chain4::head_constraint(Chain3::CONNECT0)).index()));
    assert_eq!(Chain5::NAMES.coordinate_names()[7], "end.x");
    let text = Chain::equations().text;
    assert!(text.contains("0 = v[left.x2] - v[right.x2bar]    (connect0, multiplier mu_connect0)"), "{text}");
    assert!(text.contains("dp_x2bar/dt = k3*(x3 - x2bar) + f_x2bar"), "{text}");
}

/// Three levels, ((P1 ⋈ Tail) ⋈ Tail) ⋈ Tail, against the monolithic 5-mass chain. Each tail's
/// x̄ has no momentum, so its connection carries μ = k (x − x̄) of that tail's spring.
#[test]
fn three_level_hierarchy_is_the_five_mass_chain() {
    let (m, k) = ([1.0, 2.0, 3.0, 1.5, 0.5], [4.0, 5.0, 6.0, 2.0, 3.0]);
    let tail = |i: usize| Tail { m: m[i], k: k[i] };
    let head = Chain3 { left: Primitive1 { m1: m[0], m2: m[1], k1: k[0], k2: k[1] }, right: tail(2) };
    let model = Chain5 { body: Chain4 { head, tail: tail(3) }, end: tail(4) };
    let whole = MassSpringChain5 {
        m1: m[0],
        m2: m[1],
        m3: m[2],
        m4: m[3],
        m5: m[4],
        k1: k[0],
        k2: k[1],
        k3: k[2],
        k4: k[3],
        k5: k[4],
    };
    let masses = [
        Chain5::body(Chain4::head(Chain3::left(Primitive1::X1))),
        Chain5::body(Chain4::head(Chain3::left(Primitive1::X2))),
        Chain5::body(Chain4::head(Chain3::right(Tail::X))),
        Chain5::body(Chain4::tail(Tail::X)),
        Chain5::end(Tail::X),
    ];
    let bars = [
        (Chain5::body(Chain4::head(Chain3::right(Tail::XBAR))), 1),
        (Chain5::body(Chain4::tail(Tail::XBAR)), 2),
        (Chain5::end(Tail::XBAR), 3),
    ];
    let rows = [
        Chain5::body_constraint(Chain4::head_constraint(Chain3::CONNECT0)),
        Chain5::body_constraint(Chain4::CONNECT0),
        Chain5::CONNECT0,
    ];
    let mut rng = Rng::new(53);
    for _ in 0..30 {
        let x: Vec<f64> = (0..5).map(|_| rng.uniform(-1.0, 1.0)).collect();
        let v: Vec<f64> = (0..5).map(|_| rng.uniform(-1.0, 1.0)).collect();
        let mut s = State::<Chain5>::zeros();
        for (i, c) in masses.iter().enumerate() {
            s.set_q(*c, x[i]).set_v(*c, v[i]);
        }
        for (j, (c, at)) in bars.iter().enumerate() {
            s.set_q(*c, x[*at]).set_v(*c, v[*at]);
            s.set_lambda(rows[j], k[j + 2] * (x[at + 1] - x[*at]));
        }
        let mut rb = ResidualBlocks::<Chain5>::zeros();
        model.residual_blocks(0.0, &s.q, &s.v, &s.lambda, &mut rb);
        let mut w = State::<MassSpringChain5>::zeros();
        w.q.copy_from_slice(&x);
        w.v.copy_from_slice(&v);
        let mut wb = ResidualBlocks::<MassSpringChain5>::zeros();
        whole.residual_blocks(0.0, &w.q, &w.v, &w.lambda, &mut wb);
        for (i, c) in masses.iter().enumerate() {
            assert_close(rb.momentum_rate[c.index()], wb.momentum_rate[i], "pdot of a mass");
        }
        for (c, _) in bars {
            assert_close(rb.momentum_rate[c.index()], 0.0, "pdot of a port coordinate (consistency)");
        }
        assert!(rb.constraint_velocity.amax() == 0.0, "every connection holds");
        assert!(model.interconnection_power(0.0, &s.q, &s.v, &s.lambda).abs() < 1e-14, "Tellegen");
    }
}

/// Rack and pinion against the hand-substituted model in θ alone. With J θ̈ = −kθ θ + r μ and
/// m ẍ = −k x − μ, the derivative of the constraint r θ̇ = ẋ gives
/// μ = (r kθ θ / J − k x / m) / (r² / J + 1 / m); then θ̈ must equal the geared model's.
#[test]
fn rack_and_pinion_is_the_geared_model() {
    let (j, k_theta, m, k, r) = (0.2, 3.0, 1.5, 2.0, 0.3);
    let model = RackAndPinion { wheel: Wheel { j, k_theta }, cart: Cart { m, k }, r };
    let by_hand = GearedByHand { j, k_theta, m, k, r };
    let mut rng = Rng::new(54);
    for _ in 0..30 {
        let (theta, omega) = (rng.uniform(-2.0, 2.0), rng.uniform(-1.0, 1.0));
        let (x, v_x) = (r * theta, r * omega);
        let mu = (r * k_theta * theta / j - k * x / m) / (r * r / j + 1.0 / m);
        let mut s = State::<RackAndPinion>::zeros();
        let (th, cx) = (RackAndPinion::wheel(Wheel::THETA), RackAndPinion::cart(Cart::X));
        s.set_q(th, theta).set_v(th, omega).set_q(cx, x).set_v(cx, v_x);
        s.set_lambda(RackAndPinion::GEAR, mu);
        let mut rb = ResidualBlocks::<RackAndPinion>::zeros();
        model.residual_blocks(0.0, &s.q, &s.v, &s.lambda, &mut rb);
        assert_close(rb.constraint_velocity[RackAndPinion::GEAR.index()], 0.0, "r v_theta - v_x");
        let theta_dd = rb.momentum_rate[th.index()] / j;
        let x_dd = rb.momentum_rate[cx.index()] / m;
        assert_close(x_dd, r * theta_dd, "the cart follows the wheel");

        let mut hb = ResidualBlocks::<GearedByHand>::zeros();
        let (hq, hv) = (VecQ::<GearedByHand>::new(theta), VecQ::<GearedByHand>::new(omega));
        by_hand.residual_blocks(0.0, &hq, &hv, &VecC::<GearedByHand>::zeros(), &mut hb);
        assert_close(theta_dd, hb.momentum_rate[0] / (j + m * r * r), "theta'' of the geared model");
        // The interconnection forces are Ωᵀμ = (r μ, −μ), and they do no work.
        let mut f = VecQ::<RackAndPinion>::zeros();
        model.interconnection_forces(0.0, &s.q, &s.lambda, &mut f);
        assert_close(f[th.index()], r * mu, "torque on the wheel");
        assert_close(f[cx.index()], -mu, "force on the cart");
        assert!(model.interconnection_power(0.0, &s.q, &s.v, &s.lambda).abs() < 1e-14);
    }
}

/// The solution's (X, dE|TP + F̃) lies in D_ΔC = (D_ΔQ1 × D_ΔQ2) ⋈ D_int (eqs. 2, 4–6), built
/// from the primitives' own structures and the interconnection one-form, and that structure is
/// the composite's own. A pair with a wrong ṗ does not lie in it.
#[test]
fn solutions_lie_in_the_interconnected_dirac_structure() {
    let torn = chain();
    let mut rng = Rng::new(55);
    for _ in 0..10 {
        let x = [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)];
        let v = [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)];
        let s = consistent_chain_state(x, v);
        let q1 = VecQ::<Primitive1>::new(x[0], x[1]);
        let q2 = VecQ::<Primitive2>::new(x[1], x[2]);
        let d1 = DiracStructure::of_model(&torn.left, 0.0, &q1);
        let d2 = DiracStructure::of_model(&torn.right, 0.0, &q2);
        let omega = dirac::nalgebra::DMatrix::from_row_slice(1, 4, &[0.0, 1.0, -1.0, 0.0]);
        let dc = d1.product(&d2).interconnect(&omega);
        assert_eq!(dc, DiracStructure::of_model(&torn, 0.0, &s.q));

        let mut rb = ResidualBlocks::<Chain>::zeros();
        torn.residual_blocks(0.0, &s.q, &s.v, &s.lambda, &mut rb);
        let (mut dl_dq, mut force) = (VecQ::<Chain>::zeros(), VecQ::<Chain>::zeros());
        torn.dl_dq(0.0, &s.q, &s.v, &mut dl_dq);
        torn.force(0.0, &s.q, &s.v, &mut force);
        // X = (q̇, ṗ) with ṗ the solution's momentum rate, which includes the constraint forces
        // Ωᵀμ; α = (−∂L/∂q − F, v). Membership asks β + ṗ = Ωᵀμ to lie in range(Aᵀ).
        let pdot_solution: Vec<f64> = rb.momentum_rate.iter().copied().collect();
        let beta: Vec<f64> = (-(dl_dq + force)).iter().copied().collect();
        let qdot: Vec<f64> = s.v.iter().copied().collect();
        assert!(dc.membership(&qdot, &pdot_solution, &beta, &qdot).max() < 1e-12);
        let mut wrong = pdot_solution.clone();
        wrong[0] += 0.1;
        assert!(dc.membership(&qdot, &wrong, &beta, &qdot).annihilator > 0.05);
        let mut sliding = qdot.clone();
        sliding[2] += 0.1;
        assert!(dc.membership(&sliding, &pdot_solution, &beta, &sliding).distribution > 0.05);
    }
}
