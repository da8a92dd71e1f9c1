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
    /// `∂(D₁, D₂)/∂z`, `2n × (2n + n_u)`.
    pub jacobian: DMatrix<f64>,
    /// The weighted Hessian at a point, one value per entry of the model's pattern.
    pub point_hessian: Vec<f64>,
    /// The interval's Hessian in `z`, full and symmetric.
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
            jacobian: DMatrix::zeros(2 * n, 2 * n + nu),
            point_hessian: vec![0.0; model.weighted_hessian_pattern().len()],
            hessian: DMatrix::zeros(2 * n + nu, 2 * n + nu),
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

    /// `∂(D₁, D₂)/∂z` of the interval from `a` to `b` at `t` into [`Interval::jacobian`].
    pub fn jacobian(&mut self, model: &M, t: f64, a: &[f64], b: &[f64], h: f64) {
        self.jacobian.fill(0.0);
        for (map, t) in [(START, t), (END, t + h)] {
            self.place(map, a, b, h);
            self.lagrangian_blocks(model, t);
            // L_q at its own end of the interval, in D₁ at the start and D₂ at the end.
            let row = if map.alpha == 1.0 { 0 } else { self.n };
            self.pull_lq(map, row, 0.5 * h, h);
            // P in both, with opposite signs.
            self.pull_lv(map, 0, -0.5, h);
            self.pull_lv(map, self.n, 0.5, h);
        }
        self.place(MIDDLE, a, b, h);
        self.force_blocks(model, t + 0.5 * h);
        self.pull_force(MIDDLE, 0, 0.5 * h, h);
        self.pull_force(MIDDLE, self.n, 0.5 * h, h);
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
    /// with respect to `q`, `v` and `u` are `gq(i, j)`, `gv(i, j)` and `gu(i, j)`.
    #[allow(clippy::too_many_arguments)]
    fn pull(
        jacobian: &mut DMatrix<f64>,
        (n, nu): (usize, usize),
        map: Map,
        row: usize,
        s: f64,
        h: f64,
        gq: impl Fn(usize, usize) -> f64,
        gv: impl Fn(usize, usize) -> f64,
        gu: impl Fn(usize, usize) -> f64,
    ) {
        let gamma = map.gamma / h;
        for i in 0..n {
            for j in 0..n {
                let (dq, dv) = (gq(i, j), gv(i, j));
                jacobian[(row + i, j)] += s * (map.alpha * dq - gamma * dv);
                jacobian[(row + i, n + j)] += s * (map.beta * dq + gamma * dv);
            }
            for k in 0..nu {
                jacobian[(row + i, 2 * n + k)] += s * gu(i, k);
            }
        }
    }

    fn pull_lq(&mut self, map: Map, row: usize, s: f64, h: f64) {
        let (n, l_qq, l_vq, l_qu) = (self.n, &self.l_qq, &self.l_vq, &self.dpdot_du);
        let gq = |i, j| l_qq[(i, j)];
        let gv = |i, j| l_vq[(j, i)];
        let gu = |i, k| l_qu[k * n + i];
        Self::pull(&mut self.jacobian, (n, self.nu), map, row, s, h, gq, gv, gu);
    }

    /// Adds `s ∂L_v/∂z` (at the point placed) to rows `row..row + n`.
    pub fn pull_lv(&mut self, map: Map, row: usize, s: f64, h: f64) {
        let (n, l_vq, l_vv, l_vu) = (self.n, &self.l_vq, &self.l_vv, &self.l_vu);
        let gq = |i, j| l_vq[(i, j)];
        let gv = |i, j| l_vv[(i, j)];
        let gu = |i, k| l_vu[k * n + i];
        Self::pull(&mut self.jacobian, (n, self.nu), map, row, s, h, gq, gv, gu);
    }

    fn pull_force(&mut self, map: Map, row: usize, s: f64, h: f64) {
        let (n, f_q, f_v, f_u) = (self.n, &self.f_q, &self.f_v, &self.f_u);
        let gq = |i, j| f_q[(i, j)];
        let gv = |i, j| f_v[(i, j)];
        let gu = |i, k| f_u[k * n + i];
        Self::pull(&mut self.jacobian, (n, self.nu), map, row, s, h, gq, gv, gu);
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
