//! The block-wise methods agree with the flat residual and Jacobian (each is its own generated
//! schedule), the identities between blocks hold, and matrices are written sparsely.

use dirac::State;
use dirac::Storage;
use dirac::nalgebra::{DMatrix, DefaultAllocator};
use dirac::prelude::*;

use crate::util::{Rng, random_y};
use crate::zoo::*;

fn close(a: &DMatrix<f64>, b: &DMatrix<f64>, what: &str) {
    let scale = a.amax().max(b.amax()).max(1.0);
    assert!((a - b).amax() <= 1e-12 * scale, "{what}: {a} vs {b}");
}

fn dyn_of<R: dirac::nalgebra::Dim, C: dirac::nalgebra::Dim, S: dirac::nalgebra::RawStorage<f64, R, C>>(
    m: &dirac::nalgebra::Matrix<f64, R, C, S>,
) -> DMatrix<f64> {
    DMatrix::from_fn(m.nrows(), m.ncols(), |i, j| m[(i, j)])
}

/// Checks every block against the flat forms at seeded random states.
pub(crate) fn check_blocks<M: DenseModel>(model: &M, seed: u64)
where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (M::NQ, M::NC);
    let mut rng = Rng::new(seed);
    for _ in 0..10 {
        let t = rng.uniform(0.0, 2.0);
        let y = random_y(model, &mut rng);
        let s = State::<M>::from_y(M::SIZES, &y);
        let f = dyn_of(&model.residual_vector(t, &y));
        let jac = dyn_of(&model.jacobian_matrix(t, &y));

        let mut rb = ResidualBlocks::<M>::zeros();
        model.residual_blocks(t, &s.q, &s.v, &s.lambda, &mut rb);
        close(&dyn_of(&rb.momentum_rate), &f.rows(2 * n, n).into(), "momentum rate = f_p");
        close(&dyn_of(&(s.p.clone() - &rb.dl_dv)), &f.rows(n, n).into(), "p - dL/dv = f_v");
        close(&dyn_of(&rb.constraint_velocity), &f.rows(3 * n, m).into(), "A v = f_lambda");
        close(&dyn_of(&s.v), &f.rows(0, n).into(), "f_q = v");

        let (mut dl_dq, mut dl_dv, mut force) = (VecQ::<M>::zeros(), VecQ::<M>::zeros(), VecQ::<M>::zeros());
        model.dl_dq(t, &s.q, &s.v, &mut dl_dq);
        model.dl_dv(t, &s.q, &s.v, &mut dl_dv);
        model.force(t, &s.q, &s.v, &mut force);
        let mut a = MatCQ::<M>::zeros();
        model.constraint_matrix(t, &s.q, &mut a);
        let mut b = VecC::<M>::zeros();
        model.constraint_rate(t, &s.q, &mut b);
        close(&dyn_of(&(&a * &s.v + &b)), &dyn_of(&rb.constraint_velocity), "A v + b");
        let rate = dl_dq + force + a.transpose() * &s.lambda;
        close(&dyn_of(&rate), &dyn_of(&rb.momentum_rate), "dL/dq + F + A^T lambda");
        close(&dyn_of(&dl_dv), &dyn_of(&rb.dl_dv), "dl_dv");

        let mut jb = JacobianBlocks::<M>::zeros();
        model.jacobian_blocks(t, &s.q, &s.v, &s.lambda, &mut jb);
        let block =
            |r: usize, c: usize, nr: usize, nc: usize| -> DMatrix<f64> { jac.view((r, c), (nr, nc)).into() };
        close(&dyn_of(&jb.dpdot_dq), &block(2 * n, 0, n, n), "K = df_p/dq");
        close(&dyn_of(&jb.dpdot_dv), &block(2 * n, n, n, n), "D = df_p/dv");
        close(&-dyn_of(&jb.l_vq), &block(n, 0, n, n), "-L_vq = df_v/dq");
        close(&-dyn_of(&jb.l_vv), &block(n, n, n, n), "-L_vv = df_v/dv");
        close(&dyn_of(&jb.a), &block(3 * n, n, m, n), "A = df_lambda/dv");
        close(&dyn_of(&jb.dav_dq), &block(3 * n, 0, m, n), "d(Av)/dq = df_lambda/dq");
        close(&dyn_of(&jb.a.transpose()), &block(2 * n, 3 * n, n, m), "A^T = df_p/dlambda");
        close(&DMatrix::identity(n, n), &block(0, n, n, n), "df_q/dv = I");
        close(&DMatrix::identity(n, n), &block(n, 2 * n, n, n), "df_v/dp = I");
        close(&dyn_of(&a), &dyn_of(&jb.a), "constraint_matrix = A");

        let mats = individual_blocks(model, t, &s);
        close(
            &(mats.l_qq + mats.f_q + mats.datl_dq),
            &dyn_of(&jb.dpdot_dq),
            "L_qq + F_q + d(A^T lambda)/dq = K",
        );
        close(&(mats.l_vq.transpose() + mats.f_v), &dyn_of(&jb.dpdot_dv), "L_qv + F_v = D");
        close(&mats.l_vv, &dyn_of(&jb.l_vv), "l_vv");
        close(&mats.l_vq, &dyn_of(&jb.l_vq), "l_vq");
        close(&mats.dav_dq, &dyn_of(&jb.dav_dq), "dav_dq");
        check_holonomic_rows(model, t, &s.q, &a, &b);
        check_l_vt(model, t, &s);
        check_dav_dt(model, t, &s);
    }
}

struct Individual {
    l_qq: DMatrix<f64>,
    l_vq: DMatrix<f64>,
    l_vv: DMatrix<f64>,
    f_q: DMatrix<f64>,
    f_v: DMatrix<f64>,
    datl_dq: DMatrix<f64>,
    dav_dq: DMatrix<f64>,
}

fn individual_blocks<M: DenseModel>(model: &M, t: f64, s: &State<M>) -> Individual
where
    DefaultAllocator: Storage<M>,
{
    let qq = |f: &dyn Fn(&mut MatQQ<M>)| {
        let mut out = MatQQ::<M>::zeros();
        f(&mut out);
        dyn_of(&out)
    };
    let mut dav_dq = MatCQ::<M>::zeros();
    model.dav_dq(t, &s.q, &s.v, &mut dav_dq);
    Individual {
        l_qq: qq(&|o| model.l_qq(t, &s.q, &s.v, o)),
        l_vq: qq(&|o| model.l_vq(t, &s.q, &s.v, o)),
        l_vv: qq(&|o| model.l_vv(t, &s.q, &s.v, o)),
        f_q: qq(&|o| model.force_dq(t, &s.q, &s.v, o)),
        f_v: qq(&|o| model.force_dv(t, &s.q, &s.v, o)),
        datl_dq: qq(&|o| model.datl_dq(t, &s.q, &s.lambda, o)),
        dav_dq: dyn_of(&dav_dq),
    }
}

/// `∂(∂L/∂v)/∂t` against central differences of `dl_dv` in time.
fn check_l_vt<M: DenseModel>(model: &M, t: f64, s: &State<M>)
where
    DefaultAllocator: Storage<M>,
{
    let h = 1e-6;
    let (mut plus, mut minus, mut exact) = (VecQ::<M>::zeros(), VecQ::<M>::zeros(), VecQ::<M>::zeros());
    model.dl_dv(t + h, &s.q, &s.v, &mut plus);
    model.dl_dv(t - h, &s.q, &s.v, &mut minus);
    model.l_vt(t, &s.q, &s.v, &mut exact);
    for i in 0..M::NQ {
        let fd = (plus[i] - minus[i]) / (2.0 * h);
        assert!(
            (fd - exact[i]).abs() <= 1e-6 * exact[i].abs().max(1.0),
            "d(dL/dv_{i})/dt: {} vs {fd}",
            exact[i]
        );
    }
}

/// The first rows of A are ∂φ/∂q and the first entries of b are ∂φ/∂t: checked against
/// central differences of `holonomic`.
fn check_holonomic_rows<M: DenseModel>(model: &M, t: f64, q: &VecQ<M>, a: &MatCQ<M>, b: &VecC<M>)
where
    DefaultAllocator: Storage<M>,
{
    let h = 1e-6;
    for i in 0..M::NQ {
        let (mut plus, mut minus) = (q.clone(), q.clone());
        plus[i] += h;
        minus[i] -= h;
        let (mut phi_p, mut phi_m) = (VecH::<M>::zeros(), VecH::<M>::zeros());
        model.holonomic(t, &plus, &mut phi_p);
        model.holonomic(t, &minus, &mut phi_m);
        for j in 0..M::NH {
            let fd = (phi_p[j] - phi_m[j]) / (2.0 * h);
            assert!((fd - a[(j, i)]).abs() <= 1e-6 * a[(j, i)].abs().max(1.0), "dphi{j}/dq{i}");
        }
    }
    let (mut phi_p, mut phi_m) = (VecH::<M>::zeros(), VecH::<M>::zeros());
    model.holonomic(t + h, q, &mut phi_p);
    model.holonomic(t - h, q, &mut phi_m);
    for j in 0..M::NH {
        let fd = (phi_p[j] - phi_m[j]) / (2.0 * h);
        assert!((fd - b[j]).abs() <= 1e-6 * b[j].abs().max(1.0), "dphi{j}/dt: {} vs {fd}", b[j]);
    }
}

/// `∂(A v + b)/∂t` against central differences in time of `A(q, t) v + b(q, t)`.
fn check_dav_dt<M: DenseModel>(model: &M, t: f64, s: &State<M>)
where
    DefaultAllocator: Storage<M>,
{
    let h = 1e-6;
    let at = |t: f64| {
        let (mut a, mut b) = (MatCQ::<M>::zeros(), VecC::<M>::zeros());
        model.constraint_matrix(t, &s.q, &mut a);
        model.constraint_rate(t, &s.q, &mut b);
        a * &s.v + b
    };
    let (plus, minus) = (at(t + h), at(t - h));
    let mut exact = VecC::<M>::zeros();
    model.dav_dt(t, &s.q, &s.v, &mut exact);
    for j in 0..M::NC {
        let fd = (plus[j] - minus[j]) / (2.0 * h);
        assert!(
            (fd - exact[j]).abs() <= 1e-6 * exact[j].abs().max(1.0),
            "d(Av + b)_{j}/dt: {} vs {fd}",
            exact[j]
        );
    }
}

#[test]
fn blocks_agree_with_flat_forms_for_every_model() {
    check_blocks(&Primitive1 { m1: 1.0, m2: 2.0, k1: 4.0, k2: 5.0 }, 11);
    check_blocks(&Primitive2 { m3: 3.0, k3: 6.0 }, 12);
    check_blocks(&MassSpringChain { m1: 1.0, m2: 2.0, m3: 3.0, k1: 4.0, k2: 5.0, k3: 6.0 }, 13);
    check_blocks(&Pendulum { m: 1.3, g: 9.81, l: 0.7 }, 14);
    check_blocks(&RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 }, 15);
    check_blocks(&DrivenOscillator { m: 1.0, k: 2.0, c: 0.3, a: 0.5, w: 1.7 }, 16);
    check_blocks(&LcCircuit { ind: 1.0, cap: 1.0 }, 17);
    check_blocks(&Pendulum8 { m: 0.5, l: 0.25, g: 9.81 }, 18);
    check_blocks(&AllFunctions { m: 1.5, k: 0.7 }, 19);
    // Rheonomic constraints: b = ∂φ/∂t and ∂(A v + b)/∂t against differences in time.
    check_blocks(&ShakenPendulum { m: 1.3, g: 9.81, l: 0.7, a: 0.2, w: 3.0 }, 20);
    check_blocks(&DraggedMass { m: 1.5, k: 2.0, c: 0.4 }, 21);
    check_blocks(&BeadOnRod { m: 0.8, w: 2.5 }, 22);
    check_blocks(&DiskOnBelt { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045, belt: 0.7 }, 23);
    check_blocks(
        &DiskOnAcceleratingBelt { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045, u0: 0.7, c: 0.2 },
        24,
    );
    check_blocks(&SliderCrank { m1: 1.0, m2: 2.0, m3: 0.5, r: 0.3, l: 1.0, g: 9.81, c: 0.2, w: 4.0 }, 25);
    let coupled =
        CoupledByOneForm { wheel: Wheel { j: 0.2, k_theta: 3.0 }, cart: Cart { m: 1.5, k: 2.0 }, c: 0.7 };
    check_blocks(&coupled, 20);
    let chain = paper_chain();
    check_blocks(&chain, 21);
    let frame = MovingFrame { m: 1.2, k: 3.0, u0: 0.7, w: 2.1 };
    check_blocks(&frame, 22);
    check_blocks(
        &FramedPair { first: frame.clone(), second: MovingFrame { m: 0.8, k: 1.0, u0: -0.4, w: 0.9 } },
        23,
    );
}

/// `∂(∂L/∂v)/∂t` is not zero for the moving frame, so the check above has something to check:
/// `∂L/∂v = m (v + u0 cos(w t))`, so `∂(∂L/∂v)/∂t = −m u0 w sin(w t)`.
#[test]
fn time_derivative_of_the_momenta_by_hand() {
    let frame = MovingFrame { m: 1.2, k: 3.0, u0: 0.7, w: 2.1 };
    let (q, v) = (VecQ::<MovingFrame>::new(0.3), VecQ::<MovingFrame>::new(-0.5));
    let mut out = VecQ::<MovingFrame>::zeros();
    frame.l_vt(0.4, &q, &v, &mut out);
    let by_hand = -1.2 * 0.7 * 2.1 * (2.1f64 * 0.4).sin();
    assert!((out[0] - by_hand).abs() < 1e-14, "{} vs {by_hand}", out[0]);
}

/// Structural zeros are never written: entries that stay zero in a zeroed buffer keep a
/// sentinel in a pre-filled one, and every other entry is overwritten.
#[test]
fn jacobian_writes_only_structural_nonzeros() {
    let chain = MassSpringChain { m1: 1.0, m2: 2.0, m3: 3.0, k1: 4.0, k2: 5.0, k3: 6.0 };
    let mut rng = Rng::new(21);
    let y = random_y(&chain, &mut rng);
    let zeroed = chain.jacobian_matrix(0.0, &y);
    let mut sentinel = MatYY::<MassSpringChain>::repeat(7.0);
    chain.jacobian(0.0, &y, &mut sentinel);
    let mut untouched = 0;
    for (z, s) in zeroed.iter().zip(sentinel.iter()) {
        if *z == 0.0 {
            assert_eq!(*s, 7.0, "a structural zero was written");
            untouched += 1;
        } else {
            assert_eq!(z, s);
        }
    }
    // 9×9 flat Jacobian of a 3-mass chain: 3 (q̇ = v) + 3 (−L_vv) + 3 (I in p) + 7 (tridiagonal K).
    assert_eq!(untouched, 81 - 16);
}

/// `E = ⟨p, v⟩ − L` and `⟨F, v⟩` from the default methods, against the formulas by hand.
#[test]
fn energy_and_power() {
    let osc = DrivenOscillator { m: 1.5, k: 2.0, c: 0.3, a: 0.5, w: 1.7 };
    let (t, x, v) = (0.4, 0.3, -0.8);
    let (q, vv, p) = (
        VecQ::<DrivenOscillator>::new(x),
        VecQ::<DrivenOscillator>::new(v),
        VecQ::<DrivenOscillator>::new(osc.m * v),
    );
    let energy = osc.energy(t, &q, &vv, &p);
    assert!((energy - (0.5 * osc.m * v * v + 0.5 * osc.k * x * x)).abs() < 1e-14);
    let power = osc.power(t, &q, &vv);
    assert!((power - (-osc.c * v + osc.a * (osc.w * t).sin()) * v).abs() < 1e-14);
}
