//! Dense output: the collocation polynomial of the last accepted step, for the starting values
//! of the next step's Newton iteration and for sampling the multipliers between steps, and its
//! correction by the step's ends ([`Start`]) for sampling the rest as accurately as the steps'
//! ends are.

use std::cell::{Cell, RefCell};

use nalgebra::DefaultAllocator;

use super::tableau::{C1, C2, TI};
use crate::algebra::Algebra;
use crate::algebra::{Saddle, SaddleTerms};
use crate::model::LagrangeDirac;
use crate::model::MatCQ;
use crate::model::state::State;
use crate::shape::dims::{Sizes, Storage, VecC, VecK, VecQ, VecY};
use crate::shape::layout::Layout;

/// The last step's collocation polynomial, as Newton divided differences at `s = c − 1`.
pub(crate) struct Dense<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    cont: [VecY<M>; 3],
    /// The size of the last accepted step.
    pub h: f64,
}

impl<M: LagrangeDirac> Dense<M>
where
    DefaultAllocator: Storage<M>,
{
    pub fn new(sizes: Sizes) -> Self {
        Dense { cont: [sizes.zeros_y::<M>(), sizes.zeros_y::<M>(), sizes.zeros_y::<M>()], h: 0.0 }
    }

    /// Takes the polynomial of a step of size `h` with stage increments `z`.
    // Indexing vectors of a size known to the compiler beats nalgebra's strided iterators.
    #[allow(clippy::needless_range_loop)]
    pub fn update(&mut self, z: &[VecY<M>; 3], h: f64) {
        // Reciprocals of constants, folded by the compiler: the loop multiplies.
        let (c1m1, c2m1, c1mc2) = (1.0 / (C1 - 1.0), 1.0 / (C2 - 1.0), 1.0 / (C1 - C2));
        let (c1, c2) = (1.0 / C1, 1.0 / C2);
        for i in 0..z[0].len() {
            let (z1, z2, z3) = (z[0][i], z[1][i], z[2][i]);
            let d1 = (z2 - z3) * c2m1;
            let ak = (z1 - z2) * c1mc2;
            let acont3 = (ak - z1 * c1) * c2;
            let d2 = (ak - d1) * c1m1;
            self.cont[0][i] = d1;
            self.cont[1][i] = d2;
            self.cont[2][i] = d2 - acont3;
        }
        self.h = h;
    }

    /// The polynomial's increment over the step's end value at `s` step sizes from the end.
    pub fn increment(&self, i: usize, s: f64) -> f64 {
        let (s1, s2) = (C1 - 1.0, C2 - 1.0);
        let d = &self.cont;
        s * (d[0][i] + (s - s2) * (d[1][i] + (s - s1) * d[2][i]))
    }

    /// The polynomial's derivative in step sizes at `s` step sizes from the end.
    pub fn slope(&self, i: usize, s: f64) -> f64 {
        let (s1, s2) = (C1 - 1.0, C2 - 1.0);
        let d = &self.cont;
        let inner = d[1][i] + (s - s1) * d[2][i];
        d[0][i] + (s - s2) * inner + s * (inner + (s - s2) * d[2][i])
    }

    /// The state at `t` within the last step, which ended at `t_end` in `y`.
    pub fn interpolate(&self, y: &VecY<M>, t_end: f64, t: f64, out: &mut State<M>) {
        let s = (t - t_end) / self.h;
        for (i, x) in out.components_mut().enumerate() {
            *x = y[i] + self.increment(i, s);
        }
    }

    /// Starting values of the stages of a next step of size `h`, the polynomial extrapolated to
    /// its nodes, and their transforms `w = (T⁻¹ ⊗ I) z`, in one pass over the components.
    // Indexing vectors of a size known to the compiler beats nalgebra's strided iterators.
    #[allow(clippy::needless_range_loop)]
    pub fn extrapolate_transformed(&self, h: f64, z: &mut [VecY<M>; 3], w: &mut [VecY<M>; 3]) {
        let s = [C1 * h / self.h, C2 * h / self.h, h / self.h];
        for i in 0..z[0].len() {
            let x = s.map(|s| self.increment(i, s));
            for k in 0..3 {
                z[k][i] = x[k];
                w[k][i] = TI[k][0] * x[0] + TI[k][1] * x[1] + TI[k][2] * x[2];
            }
        }
    }
}

/// The start of the last accepted step, value and rate, for a continuous extension of higher
/// order than the collocation polynomial's.
///
/// The collocation polynomial `u` has the stage order, `O(h⁴)`, inside a step, while the
/// step's end is `O(h⁶)` (superconvergence): at tight tolerances samples between steps came out
/// a hundred times less accurate than the steps' ends. Inside a step
/// `u − y = K(θ) h⁴ y⁽⁴⁾ + O(h⁵)` with `K(θ) = −⅙ ∫₀^θ (σ − c₁)(σ − c₂)(σ − 1) dσ` (`u′`
/// interpolates `y′` at the nodes), and the cubic Hermite polynomial `H` through the step's
/// ends has `H − y = −θ²(1 − θ)²/24 · h⁴ y⁽⁴⁾ + O(h⁵)`. Their difference,
/// `θ(1 − θ)²/60 · h⁴ y⁽⁴⁾`, measures `h⁴ y⁽⁴⁾` (at `θ = ⅓`, where it is largest), and
/// `u − K(θ) h⁴ y⁽⁴⁾` is `O(h⁵)`, as accurate as the steps' ends after a few steps. The
/// positions (whose rates are the velocities) and the momenta (`ṗ = f_p`) are corrected so;
/// the velocities come from them through the Legendre map ([`Legendre`]) or else as the
/// corrected positions' derivative; the multipliers, whose order at the steps' ends is the
/// stage order anyway, keep the collocation polynomial. A (quintic Hermite) extension through
/// the last three steps' ends measured no better and is not kept: it needs a history that
/// every event and restart cuts, and a short step before a long one amplifies its errors.
pub(crate) struct Start<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// `y` at the start of the last accepted step.
    y: VecY<M>,
    /// `f(t, y)` there.
    f: VecY<M>,
    /// Whether a step was accepted since the integration (re)started.
    known: bool,
    /// Whether `measured` belongs to an earlier step.
    stale: Cell<bool>,
    /// `h⁴ y⁽⁴⁾` of the positions and momenta in the last step, once a sample asked for it.
    measured: RefCell<VecY<M>>,
}

impl<M: LagrangeDirac> Start<M>
where
    DefaultAllocator: Storage<M>,
{
    pub fn new(sizes: Sizes) -> Self {
        let measured = RefCell::new(sizes.zeros_y::<M>());
        Start {
            y: sizes.zeros_y::<M>(),
            f: sizes.zeros_y::<M>(),
            known: false,
            stale: Cell::new(true),
            measured,
        }
    }

    /// Forgets the last step: a new integration, or a restart after a jump.
    pub fn forget(&mut self) {
        self.known = false;
    }

    /// Records the start `y`, `f` of a step about to be accepted.
    pub fn push(&mut self, y: &VecY<M>, f: &VecY<M>) {
        self.y.copy_from(y);
        self.f.copy_from(f);
        self.known = true;
        self.stale.set(true);
    }

    /// Overwrites the positions, momenta and velocities of `out`, the state at `t` within the
    /// last step (of size `h`, ending at `t_end` in `y_end` with rates `f_end`, its collocation
    /// polynomial `dense`), with the corrected extension. Says whether it did (not before a
    /// step is accepted).
    pub fn refine(
        &self,
        dense: &Dense<M>,
        (y_end, f_end): (&VecY<M>, &VecY<M>),
        (t_end, h): (f64, f64),
        t: f64,
        out: &mut State<M>,
    ) -> bool {
        if !self.known || h <= 0.0 {
            return false;
        }
        let l = Layout::new(out.sizes());
        // Time in steps from the end, and from the start.
        let s = (t - t_end) / h;
        let theta = 1.0 + s;
        let k = -(theta * (theta * (theta * (theta / 4.0 - 0.6) + 0.45) - 0.1)) / 6.0;
        let dk = -(theta * (theta * (theta - 1.8) + 0.9) - 0.1) / 6.0;
        if self.stale.replace(false) {
            self.measure(dense, (y_end, f_end), h, &l, &mut self.measured.borrow_mut());
        }
        let d = self.measured.borrow();
        for i in 0..out.q.len() {
            let (q, p) = (l.q + i, l.p + i);
            out.q[i] = y_end[q] + dense.increment(q, s) - k * d[q];
            out.v[i] = (dense.slope(q, s) - dk * d[q]) / h;
            out.p[i] -= k * d[p];
        }
        true
    }

    /// `h⁴ y⁽⁴⁾` of the positions and momenta from `u − H` at θ = ⅓, where the cubic Hermite
    /// basis is 20/27 and 4/27 for the start's value and rate, 7/27 and −2/27 for the end's.
    fn measure(
        &self,
        dense: &Dense<M>,
        (y_end, f_end): (&VecY<M>, &VecY<M>),
        h: f64,
        l: &Layout,
        d: &mut VecY<M>,
    ) {
        let (third, scale) = (-2.0 / 3.0, 60.0 * 27.0 / 4.0);
        let (y0, f0) = (&self.y, &self.f);
        let at = |x: usize, d0: f64, d1: f64| {
            let u = y_end[x] + dense.increment(x, third);
            (u - (20.0 * y0[x] + 4.0 * d0 + 7.0 * y_end[x] - 2.0 * d1) / 27.0) * scale
        };
        for i in 0..l.v - l.q {
            let (q, v, p) = (l.q + i, l.v + i, l.p + i);
            d[q] = at(q, h * y0[v], h * y_end[v]);
            d[p] = at(p, h * f0[p], h * f_end[p]);
        }
    }
}

/// Velocities from the corrected positions and momenta through the Legendre map
/// `p = ∂L/∂v(t, q, v)` and the constraints `A(q, t) v + b(q, t) = 0`.
///
/// The derivative of the corrected positions is less accurate: the positions at the steps' ends
/// carry each step's local error, `O(h⁶)`, and a derivative divides it by `h`; at tight
/// tolerances that alone made velocities between steps ten times less accurate than at the ends.
/// Two simplified Newton iterations (one for a model without constraints whose `L_vv` is
/// constant) on `p − ∂L/∂v = 0`, `A v + b = 0` with the matrix `[L_vv Aᵀ; A 0]` (the mass
/// matrix of the last Jacobian, the constraints at the step's end; factored once per step, when
/// first sampled) give velocities as accurate as the positions and momenta they come from, on
/// the constraints. Where that matrix is singular (a velocity fixed by neither inertia nor
/// constraints) the whole state keeps the collocation polynomial, whose velocities and momenta
/// agree at the stages.
pub(crate) struct Legendre<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    work: RefCell<LegendreWork<M>>,
}

struct LegendreWork<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// Whether the matrix was factored for the last step, and whether it is nonsingular.
    factored: Option<bool>,
    saddle: <M::Algebra as Algebra<M>>::Saddle<f64>,
    a: MatCQ<M>,
    b: VecC<M>,
    x: VecK<M>,
    dl_dv: VecQ<M>,
}

impl<M: LagrangeDirac> Legendre<M>
where
    DefaultAllocator: Storage<M>,
{
    pub fn new(model: &M) -> Self {
        let (sizes, shape) = (model.sizes(), model.shape());
        Legendre {
            work: RefCell::new(LegendreWork {
                factored: None,
                saddle: M::Algebra::saddle(&shape),
                a: M::Algebra::zeros_cq(&shape),
                b: sizes.zeros_c::<M>(),
                x: sizes.zeros_k::<M>(),
                dl_dv: sizes.zeros_q::<M>(),
            }),
        }
    }

    /// A step was accepted: the matrix is factored anew at its next sample.
    pub fn forget(&mut self) {
        self.work.get_mut().factored = None;
    }

    /// Whether the velocities can be corrected in the last step: `[L_vv Aᵀ; A 0]`, with the
    /// mass matrix `l_vv` of the last Jacobian and the constraints at the step's end
    /// `(t_end, q_end)`, factored at the step's first sample, is nonsingular.
    pub fn ready(
        &self,
        model: &M,
        l_vv: &<M::Algebra as Algebra<M>>::Qq,
        (t_end, q_end): (f64, &VecQ<M>),
    ) -> bool {
        let work = &mut *self.work.borrow_mut();
        if work.factored.is_none() {
            if !work.b.is_empty() {
                model.constraint_matrix(t_end, q_end, &mut work.a);
            }
            work.saddle.assemble(&SaddleTerms {
                top: &[(1.0, l_vv)],
                top_transposed: &[],
                identity: 0.0,
                right: &[(1.0, &work.a)],
                bottom: &[(1.0, 1.0, &work.a)],
                corner: (0.0, 0.0),
            });
            work.factored = Some(work.saddle.factor().is_ok());
        }
        work.factored == Some(true)
    }

    /// Corrects the velocities of `out` at `t` so that they match its positions and momenta
    /// and satisfy the constraints, with the matrix [`Legendre::ready`] factored.
    // Indexing keeps the unknowns, the momenta and the velocities side by side.
    #[allow(clippy::needless_range_loop)]
    pub fn correct(&self, model: &M, t: f64, out: &mut State<M>) {
        let work = &mut *self.work.borrow_mut();
        let n = out.q.len();
        let constrained = !work.b.is_empty();
        // The constraints at the sample, `A(q) v + b`: q does not change in the iterations.
        if constrained {
            model.constraint_matrix(t, &out.q, &mut work.a);
            if M::PRESCRIBED {
                model.constraint_rate(t, &out.q, &mut work.b);
            } else {
                work.b.fill(0.0);
            }
        }
        let iterations = if M::SEPARABLE && !constrained { 1 } else { 2 };
        for _ in 0..iterations {
            model.dl_dv(t, &out.q, &out.v, &mut work.dl_dv);
            let x = work.x.as_mut_slice();
            for i in 0..n {
                x[i] = out.p[i] - work.dl_dv[i];
            }
            if constrained {
                x[n..].copy_from_slice(work.b.as_slice());
                M::Algebra::cq_mul(&work.a, 1.0, out.v.as_slice(), &mut x[n..]);
                for r in &mut x[n..] {
                    *r = -*r;
                }
            }
            work.saddle.solve(x);
            for i in 0..n {
                out.v[i] += x[i];
            }
        }
        // With constraints the two conditions are more than the velocities can meet: the
        // solve keeps `A v + b = 0` and leaves `Aᵀ μ` of the Legendre map, the share of the
        // momenta's error across the constraints. The momenta follow the velocities, so that the
        // sample is consistent, as the steps' ends are.
        if constrained {
            model.dl_dv(t, &out.q, &out.v, &mut out.p);
        }
    }
}
