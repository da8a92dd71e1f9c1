//! Generated blocks of the pendulum (holonomic) and the rolling disk (nonholonomic) against
//! derivations by hand, at seeded random states.

use dirac::State;
use dirac::prelude::*;

use crate::util::Rng;
use crate::zoo::{Pendulum, RollingDisk};

fn assert_close(got: f64, want: f64, what: &str) {
    assert!((got - want).abs() <= 1e-13 * want.abs().max(1.0), "{what}: generated {got}, by hand {want}");
}

/// L = ½ m (vx² + vy²) − m g y, φ = x² + y² − l²: by hand, ∂L/∂q = (0, −m g), ∂L/∂v = m v,
/// L_vv = m I, A = (2x, 2y), ∂(Av)/∂q = (2 vx, 2 vy), ∂(Aᵀλ)/∂q = 2 λ I.
#[test]
fn pendulum_blocks() {
    let model = Pendulum { m: 1.3, g: 9.81, l: 0.7 };
    let mut rng = Rng::new(31);
    for _ in 0..20 {
        let mut s = State::<Pendulum>::zeros();
        s.set_q(Pendulum::X, rng.uniform(-1.0, 1.0)).set_q(Pendulum::Y, rng.uniform(-1.0, 1.0));
        s.set_v(Pendulum::X, rng.uniform(-1.0, 1.0)).set_v(Pendulum::Y, rng.uniform(-1.0, 1.0));
        s.set_lambda(Pendulum::ROD, rng.uniform(-1.0, 1.0));
        let (x, y) = (s.q(Pendulum::X), s.q(Pendulum::Y));
        let (vx, vy) = (s.v(Pendulum::X), s.v(Pendulum::Y));
        let lambda = s.lambda(Pendulum::ROD);
        let m = model.m;

        let mut jb = JacobianBlocks::<Pendulum>::zeros();
        model.jacobian_blocks(0.0, &s.q, &s.v, &s.lambda, &mut jb);
        let mut rb = ResidualBlocks::<Pendulum>::zeros();
        model.residual_blocks(0.0, &s.q, &s.v, &s.lambda, &mut rb);
        let mut phi = VecH::<Pendulum>::zeros();
        model.holonomic(0.0, &s.q, &mut phi);

        assert_close(rb.momentum_rate[0], 2.0 * x * lambda, "pdot_x");
        assert_close(rb.momentum_rate[1], -m * model.g + 2.0 * y * lambda, "pdot_y");
        assert_close(rb.dl_dv[0], m * vx, "p_x");
        assert_close(rb.dl_dv[1], m * vy, "p_y");
        assert_close(rb.constraint_velocity[0], 2.0 * x * vx + 2.0 * y * vy, "A v");
        assert_close(phi[0], x * x + y * y - model.l * model.l, "phi");
        assert_close(jb.a[(0, 0)], 2.0 * x, "A_x");
        assert_close(jb.a[(0, 1)], 2.0 * y, "A_y");
        assert_close(jb.dav_dq[(0, 0)], 2.0 * vx, "d(Av)/dx");
        assert_close(jb.dav_dq[(0, 1)], 2.0 * vy, "d(Av)/dy");
        let expected_k = [[2.0 * lambda, 0.0], [0.0, 2.0 * lambda]];
        let expected_lvv = [[m, 0.0], [0.0, m]];
        for i in 0..2 {
            for j in 0..2 {
                assert_close(jb.dpdot_dq[(i, j)], expected_k[i][j], "K");
                assert_close(jb.l_vv[(i, j)], expected_lvv[i][j], "L_vv");
                assert_close(jb.dpdot_dv[(i, j)], 0.0, "D");
                assert_close(jb.l_vq[(i, j)], 0.0, "L_vq");
            }
        }
    }
}

/// q = (x, y, θ, φ), constraints ẋ − r cos φ θ̇ = 0 and ẏ − r sin φ θ̇ = 0. By hand:
/// A = [[1, 0, −r cos φ, 0], [0, 1, −r sin φ, 0]], ∂(Av)/∂φ = (r sin φ θ̇, −r cos φ θ̇),
/// Aᵀλ = (λ1, λ2, −r (cos φ λ1 + sin φ λ2), 0) with ∂/∂φ of the third entry r (sin φ λ1 − cos φ λ2).
#[test]
fn rolling_disk_blocks() {
    let model = RollingDisk { m: 2.0, r: 0.3, i_roll: 0.09, i_turn: 0.045 };
    let mut rng = Rng::new(32);
    for _ in 0..20 {
        let mut s = State::<RollingDisk>::zeros();
        for i in 0..4 {
            s.q[i] = rng.uniform(-3.0, 3.0);
            s.v[i] = rng.uniform(-1.0, 1.0);
        }
        s.set_lambda(RollingDisk::ROLL_X, rng.uniform(-1.0, 1.0));
        s.set_lambda(RollingDisk::ROLL_Y, rng.uniform(-1.0, 1.0));
        let (phi, v_theta) = (s.q(RollingDisk::PHI), s.v(RollingDisk::THETA));
        let (l1, l2) = (s.lambda(RollingDisk::ROLL_X), s.lambda(RollingDisk::ROLL_Y));
        let r = model.r;

        let mut jb = JacobianBlocks::<RollingDisk>::zeros();
        model.jacobian_blocks(0.0, &s.q, &s.v, &s.lambda, &mut jb);
        let a = [[1.0, 0.0, -r * phi.cos(), 0.0], [0.0, 1.0, -r * phi.sin(), 0.0]];
        let dav = [[0.0, 0.0, 0.0, r * phi.sin() * v_theta], [0.0, 0.0, 0.0, -r * phi.cos() * v_theta]];
        for j in 0..2 {
            for i in 0..4 {
                assert_close(jb.a[(j, i)], a[j][i], "A");
                assert_close(jb.dav_dq[(j, i)], dav[j][i], "d(Av)/dq");
            }
        }
        let mut k = [[0.0; 4]; 4];
        k[2][3] = r * (phi.sin() * l1 - phi.cos() * l2);
        let lvv = [model.m, model.m, model.i_roll, model.i_turn];
        for (i, row) in k.iter().enumerate() {
            for (j, &kij) in row.iter().enumerate() {
                assert_close(jb.dpdot_dq[(i, j)], kij, "K = d(A^T lambda)/dq");
                assert_close(jb.l_vv[(i, j)], if i == j { lvv[i] } else { 0.0 }, "L_vv");
            }
        }
        let mut rb = ResidualBlocks::<RollingDisk>::zeros();
        model.residual_blocks(0.0, &s.q, &s.v, &s.lambda, &mut rb);
        let rate = [l1, l2, -r * (phi.cos() * l1 + phi.sin() * l2), 0.0];
        for (i, &r) in rate.iter().enumerate() {
            assert_close(rb.momentum_rate[i], r, "A^T lambda");
        }
    }
}
