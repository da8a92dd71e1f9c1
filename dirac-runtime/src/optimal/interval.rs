//! One interval of the DMOC transcription: the discrete Euler-Lagrange terms `D₁L_d + F⁻`
//! and `D₂L_d + F⁺` of the variational integrator's discrete Lagrangian, their Jacobian with
//! respect to the interval's variables `z = (q_k, q_{k+1}, u_k)`, and the Hessian of their
//! weighted sum, from the model's generated blocks.
//!
//! With `v = (q_{k+1} − q_k)/h`, the trapezoidal `L_d = h/2 [L(q_k, v) + L(q_{k+1}, v)]` and
//! the forces at the midpoint (as [`Variational`](crate::Variational) steps):
//!
//! ```text
//! D₁ = h/2 L_q(q_k, v) − P + h/2 F(q̄, v, u)       P = ½ [L_v(q_k, v) + L_v(q_{k+1}, v)]
//! D₂ = h/2 L_q(q_{k+1}, v) + P + h/2 F(q̄, v, u)    q̄ = (q_k + q_{k+1})/2
//! ```
//!
//! Each term is a block of the model (`L_q`, `L_v` or `F`) at one of three points `x = (q, v, u)`,
//! each an affine function of `z`: its derivatives are the blocks' own, pulled back through
//! that map.
//!
//! With a free final time the step `h` is a variable too (the last entry of `z`). A point's
//! weighted sum is then `S = h A(x) + B(x)` (the `L_q` and force terms carry `h`, the momenta
//! do not) at `x(z, h)` whose velocity `(q_{k+1} − q_k)/h` moves with `h`
//! (`∂x/∂h = X_h = (0, −v/h, 0)`). With `W = ∇²S` and `G = ∇S` at the point:
//!
//! ```text
//! ∂²S/∂z∂h = (∇A + W X_h)ᵀ X_z − (1/h) G_vᵀ X_z,v
//! ∂²S/∂h²  = 2 ∇A·X_h + X_hᵀ W X_h + G·X_hh          X_hh = (0, 2v/h², 0)
//! ```

use nalgebra::{DMatrix, DefaultAllocator};

use crate::model::{DenseModel, InputsOutputs, MatQQ};
use crate::shape::dims::{Storage, VecC, VecQ};

/// Where a block is evaluated: `q = α q_k + β q_{k+1}` (or a given position), `v` the
/// interval's velocity (or a given one), `u = u_k`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Map {
    pub alpha: f64,
    pub beta: f64,
    /// `1/h` if the velocity is the interval's, 0 if it is given.
    pub gamma: f64,
}

pub(crate) const START: Map = Map { alpha: 1.0, beta: 0.0, gamma: 1.0 };
pub(crate) const END: Map = Map { alpha: 0.0, beta: 1.0, gamma: 1.0 };
pub(crate) const MIDDLE: Map = Map { alpha: 0.5, beta: 0.5, gamma: 1.0 };

impl Map {
    /// The entries `(z index, factor)` of `∂x_r/∂z` for entry `r` of `x = (q, v, u)`.
    pub fn column(self, r: usize, n: usize, h: f64) -> [(usize, f64); 2] {
        let gamma = self.gamma / h;
        match r {
            r if r < n => [(r, self.alpha), (n + r, self.beta)],
            r if r < 2 * n => [(r - n, -gamma), (r, gamma)],
            r => [(r, 1.0), (r, 0.0)],
        }
    }
}

/// The work space of one interval's evaluations: the model's blocks at a point, and the
/// interval's Jacobian and Hessian.
pub(crate) struct Interval<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    pub q: VecQ<M>,
    pub v: VecQ<M>,
    pub lambda: VecC<M>,
    pub out: VecQ<M>,
    pub wq: VecQ<M>,
    pub wv: VecQ<M>,
    pub wf: VecQ<M>,
    l_qq: MatQQ<M>,
    l_vq: MatQQ<M>,
    l_vv: MatQQ<M>,
    f_q: MatQQ<M>,
    f_v: MatQQ<M>,
    dpdot_du: Vec<f64>,
    f_u: Vec<f64>,
    l_vu: Vec<f64>,
    /// `∇A`, `G` and `W X_h` at a point, over `x = (q, v, u)` (free final time).
    grad_a: Vec<f64>,
    grad_s: Vec<f64>,
    w_xh: Vec<f64>,
    /// `∂(D₁, D₂)/∂z`, `2n × (2n + n_u + 1)`; the last column is `∂/∂h` (free final time).
    pub jacobian: DMatrix<f64>,
    /// The weighted Hessian at a point, one value per entry of the model's pattern.
    pub point_hessian: Vec<f64>,
    /// The interval's Hessian in `z = (q_k, q_{k+1}, u_k, h)`, full and symmetric.
    pub hessian: DMatrix<f64>,
    n: usize,
    nu: usize,
}

impl<M> Interval<M>
where
    M: DenseModel + InputsOutputs,
    DefaultAllocator: Storage<M>,
{
    pub fn new(model: &M) -> Self {
        let (n, nu) = (model.sizes().nq, M::NAMES.input_count());
        let zq = VecQ::<M>::zeros;
        let zm = MatQQ::<M>::zeros;
        Interval {
            q: zq(),
            v: zq(),
            lambda: VecC::<M>::zeros(),
            out: zq(),
            wq: zq(),
            wv: zq(),
            wf: zq(),
            l_qq: zm(),
            l_vq: zm(),
            l_vv: zm(),
            f_q: zm(),
            f_v: zm(),
            dpdot_du: vec![0.0; n * nu],
            f_u: vec![0.0; n * nu],
            l_vu: vec![0.0; n * nu],
            grad_a: vec![0.0; 2 * n + nu],
            grad_s: vec![0.0; 2 * n + nu],
            w_xh: vec![0.0; 2 * n + nu],
            jacobian: DMatrix::zeros(2 * n, 2 * n + nu + 1),
            point_hessian: vec![0.0; model.weighted_hessian_pattern().len()],
            hessian: DMatrix::zeros(2 * n + nu + 1, 2 * n + nu + 1),
            n,
            nu,
        }
    }

    /// Sets `q` and `v` to the point `map` of the interval from `a` to `b` (`v = (b − a)/h`).
    pub fn place(&mut self, map: Map, a: &[f64], b: &[f64], h: f64) {
        for i in 0..self.n {
            self.q[i] = map.alpha * a[i] + map.beta * b[i];
            self.v[i] = (b[i] - a[i]) / h;
        }
    }

    /// `(D₁, D₂)` of the interval from `a` to `b` at `t`, into `d1` and `d2`, with the model's
    /// inputs already set to `u_k`.
    #[allow(clippy::too_many_arguments, clippy::needless_range_loop)]
    pub fn residual(
        &mut self,
        model: &M,
        t: f64,
        a: &[f64],
        b: &[f64],
        h: f64,
        d1: &mut [f64],
        d2: &mut [f64],
    ) {
        let n = self.n;
        self.place(START, a, b, h);
        model.dl_dq(t, &self.q, &self.v, &mut self.out);
        for i in 0..n {
            d1[i] = 0.5 * h * self.out[i];
        }
        model.dl_dv(t, &self.q, &self.v, &mut self.out);
        for i in 0..n {
            d1[i] -= 0.5 * self.out[i];
            d2[i] = 0.5 * self.out[i];
        }
        self.place(END, a, b, h);
        model.dl_dq(t + h, &self.q, &self.v, &mut self.out);
        for i in 0..n {
            d2[i] += 0.5 * h * self.out[i];
        }
        model.dl_dv(t + h, &self.q, &self.v, &mut self.out);
        for i in 0..n {
            d1[i] -= 0.5 * self.out[i];
            d2[i] += 0.5 * self.out[i];
        }
        self.place(MIDDLE, a, b, h);
        model.force(t + 0.5 * h, &self.q, &self.v, &mut self.out);
        for i in 0..n {
            d1[i] += 0.5 * h * self.out[i];
            d2[i] += 0.5 * h * self.out[i];
        }
    }

    /// `∂(D₁, D₂)/∂z` of the interval from `a` to `b` at `t` into [`Interval::jacobian`], with
    /// the column `∂/∂h` if the step is `free`.
    #[allow(clippy::too_many_arguments)]
    pub fn jacobian(&mut self, model: &M, t: f64, a: &[f64], b: &[f64], h: f64, free: bool) {
        self.jacobian.fill(0.0);
        let (n, step) = (self.n, 2 * self.n + self.nu);
        for (map, t) in [(START, t), (END, t + h)] {
            self.place(map, a, b, h);
            self.lagrangian_blocks(model, t);
            // L_q at its own end of the interval, in D₁ at the start and D₂ at the end.
            let row = if map.alpha == 1.0 { 0 } else { n };
            self.pull_lq(map, row, 0.5 * h, h);
            // P in both, with opposite signs.
            self.pull_lv(map, 0, -0.5, h);
            self.pull_lv(map, n, 0.5, h);
            if free {
                // `h/2 L_q`'s own factor.
                model.dl_dq(t, &self.q, &self.v, &mut self.out);
                for i in 0..n {
                    self.jacobian[(row + i, step)] += 0.5 * self.out[i];
                }
            }
        }
        self.place(MIDDLE, a, b, h);
        self.force_blocks(model, t + 0.5 * h);
        self.pull_force(MIDDLE, 0, 0.5 * h, h);
        self.pull_force(MIDDLE, n, 0.5 * h, h);
        if free {
            model.force(t + 0.5 * h, &self.q, &self.v, &mut self.out);
            for i in 0..n {
                self.jacobian[(i, step)] += 0.5 * self.out[i];
                self.jacobian[(n + i, step)] += 0.5 * self.out[i];
            }
        }
    }

    /// `L_qq`, `L_vq`, `L_vv`, `∂L_q/∂u` (in `dpdot_du`) and `L_vu` at the point placed.
    fn lagrangian_blocks(&mut self, model: &M, t: f64) {
        model.l_qq(t, &self.q, &self.v, &mut self.l_qq);
        model.l_vq(t, &self.q, &self.v, &mut self.l_vq);
        model.l_vv(t, &self.q, &self.v, &mut self.l_vv);
        model.dpdot_du(t, &self.q, &self.v, &self.lambda, &mut self.dpdot_du);
        model.force_du(t, &self.q, &self.v, &mut self.f_u);
        for (l, f) in self.dpdot_du.iter_mut().zip(&self.f_u) {
            *l -= f;
        }
        model.l_vu(t, &self.q, &self.v, &mut self.l_vu);
    }

    /// `∂L_v/∂x` at the point placed, for the momenta at a given state (the start's and the
    /// end's conditions).
    pub fn momentum_jacobian(&mut self, model: &M, t: f64) {
        self.lagrangian_blocks(model, t);
    }

    /// `F_q`, `F_v` and `F_u` at the point placed.
    fn force_blocks(&mut self, model: &M, t: f64) {
        model.force_dq(t, &self.q, &self.v, &mut self.f_q);
        model.force_dv(t, &self.q, &self.v, &mut self.f_v);
        model.force_du(t, &self.q, &self.v, &mut self.f_u);
    }

    /// Adds `s ∂G/∂z` to rows `row..row + n` of the Jacobian for a block `G` whose derivatives
    /// with respect to `q`, `v` and `u` are `gq(i, j)`, `gv(i, j)` and `gu(i, j)`, and to the
    /// column `∂/∂h` what the point's velocity `v` moving with `h` brings.
    #[allow(clippy::too_many_arguments)]
    fn pull(
        jacobian: &mut DMatrix<f64>,
        (n, nu): (usize, usize),
        map: Map,
        row: usize,
        s: f64,
        h: f64,
        v: &[f64],
        gq: impl Fn(usize, usize) -> f64,
        gv: impl Fn(usize, usize) -> f64,
        gu: impl Fn(usize, usize) -> f64,
    ) {
        let gamma = map.gamma / h;
        for i in 0..n {
            let mut along_h = 0.0;
            for j in 0..n {
                let (dq, dv) = (gq(i, j), gv(i, j));
                jacobian[(row + i, j)] += s * (map.alpha * dq - gamma * dv);
                jacobian[(row + i, n + j)] += s * (map.beta * dq + gamma * dv);
                along_h -= dv * v[j];
            }
            for k in 0..nu {
                jacobian[(row + i, 2 * n + k)] += s * gu(i, k);
            }
            jacobian[(row + i, 2 * n + nu)] += s * gamma * along_h;
        }
    }

    fn pull_lq(&mut self, map: Map, row: usize, s: f64, h: f64) {
        let (n, l_qq, l_vq, l_qu) = (self.n, &self.l_qq, &self.l_vq, &self.dpdot_du);
        let gq = |i, j| l_qq[(i, j)];
        let gv = |i, j| l_vq[(j, i)];
        let gu = |i, k| l_qu[k * n + i];
        Self::pull(&mut self.jacobian, (n, self.nu), map, row, s, h, self.v.as_slice(), gq, gv, gu);
    }

    /// Adds `s ∂L_v/∂z` (at the point placed) to rows `row..row + n`.
    pub fn pull_lv(&mut self, map: Map, row: usize, s: f64, h: f64) {
        let (n, l_vq, l_vv, l_vu) = (self.n, &self.l_vq, &self.l_vv, &self.l_vu);
        let gq = |i, j| l_vq[(i, j)];
        let gv = |i, j| l_vv[(i, j)];
        let gu = |i, k| l_vu[k * n + i];
        Self::pull(&mut self.jacobian, (n, self.nu), map, row, s, h, self.v.as_slice(), gq, gv, gu);
    }

    fn pull_force(&mut self, map: Map, row: usize, s: f64, h: f64) {
        let (n, f_q, f_v, f_u) = (self.n, &self.f_q, &self.f_v, &self.f_u);
        let gq = |i, j| f_q[(i, j)];
        let gv = |i, j| f_v[(i, j)];
        let gu = |i, k| f_u[k * n + i];
        Self::pull(&mut self.jacobian, (n, self.nu), map, row, s, h, self.v.as_slice(), gq, gv, gu);
    }

    /// Adds the weighted Hessian at the point placed (weights in `wq`, `wv`, `wf`), pulled
    /// back through `map`, to [`Interval::hessian`].
    pub fn add_point_hessian(&mut self, model: &M, t: f64, map: Map, h: f64) {
        let Interval { q, v, wq, wv, wf, point_hessian, .. } = self;
        model.weighted_hessian(t, q, v, wq, wv, wf, point_hessian);
        let pattern = model.weighted_hessian_pattern();
        for (&(r, c), &value) in pattern.iter().zip(self.point_hessian.iter()) {
            add_pulled(&mut self.hessian, map, self.n, h, r, c, value);
        }
    }

    /// Adds the row and column `h` of the Hessian of the point's weighted sum to
    /// [`Interval::hessian`] (free final time), after [`Interval::add_point_hessian`] at the
    /// same point and weights has left `W` in [`Interval::point_hessian`]. The point's
    /// velocity must be the interval's (`map.gamma = 1`).
    #[allow(clippy::needless_range_loop)]
    pub fn add_step_hessian(&mut self, model: &M, t: f64, map: Map, h: f64) {
        let (n, nu) = (self.n, self.nu);
        let (dx, step) = (2 * n + nu, 2 * n + nu);
        self.lagrangian_blocks(model, t);
        self.force_blocks(model, t);
        // `∇A` (the terms weighted by `wq` and `wf`, which carry `h`, divided by it) and
        // `G = h ∇A + ∇(wv·L_v)`; `dpdot_du` now holds `∂L_q/∂u`.
        for r in 0..n {
            let (mut a_q, mut a_v, mut b_q, mut b_v) = (0.0, 0.0, 0.0, 0.0);
            for i in 0..n {
                let (wq, wv, wf) = (self.wq[i], self.wv[i], self.wf[i]);
                a_q += wq * self.l_qq[(i, r)] + wf * self.f_q[(i, r)];
                a_v += wq * self.l_vq[(r, i)] + wf * self.f_v[(i, r)];
                b_q += wv * self.l_vq[(i, r)];
                b_v += wv * self.l_vv[(i, r)];
            }
            self.grad_a[r] = a_q / h;
            self.grad_a[n + r] = a_v / h;
            self.grad_s[r] = a_q + b_q;
            self.grad_s[n + r] = a_v + b_v;
        }
        for k in 0..nu {
            let (mut a, mut b) = (0.0, 0.0);
            for i in 0..n {
                a += self.wq[i] * self.dpdot_du[k * n + i] + self.wf[i] * self.f_u[k * n + i];
                b += self.wv[i] * self.l_vu[k * n + i];
            }
            self.grad_a[2 * n + k] = a / h;
            self.grad_s[2 * n + k] = a + b;
        }
        // `X_h` is `−v/h` in the velocity entries; `W X_h` from `W`'s pattern.
        let x_h =
            |r: usize, v: &VecQ<M>| if (n..2 * n).contains(&r) { -map.gamma * v[r - n] / h } else { 0.0 };
        self.w_xh.fill(0.0);
        for (&(r, c), &value) in model.weighted_hessian_pattern().iter().zip(self.point_hessian.iter()) {
            self.w_xh[r] += value * x_h(c, &self.v);
            if r != c {
                self.w_xh[c] += value * x_h(r, &self.v);
            }
        }
        let mut hh = 0.0;
        for r in 0..dx {
            let xh = x_h(r, &self.v);
            hh += 2.0 * self.grad_a[r] * xh + xh * self.w_xh[r];
            let mut coefficient = self.grad_a[r] + self.w_xh[r];
            if (n..2 * n).contains(&r) {
                coefficient -= self.grad_s[r] / h;
                hh += self.grad_s[r] * 2.0 * map.gamma * self.v[r - n] / (h * h);
            }
            for (a, pa) in map.column(r, n, h) {
                let x = coefficient * pa;
                if x != 0.0 {
                    self.hessian[(a, step)] += x;
                    self.hessian[(step, a)] += x;
                }
            }
        }
        self.hessian[(step, step)] += hh;
    }
}

/// Adds `value (e_r e_cᵀ + e_c e_rᵀ)` (once if `r = c`) of an `x`-space Hessian, pulled back
/// through `map`, to the symmetric `hessian` in `z`.
pub(crate) fn add_pulled(
    hessian: &mut DMatrix<f64>,
    map: Map,
    n: usize,
    h: f64,
    r: usize,
    c: usize,
    value: f64,
) {
    for (a, pa) in map.column(r, n, h) {
        for (b, pb) in map.column(c, n, h) {
            let x = value * pa * pb;
            if x == 0.0 {
                continue;
            }
            hessian[(a, b)] += x;
            if r != c {
                hessian[(b, a)] += x;
            }
        }
    }
}
