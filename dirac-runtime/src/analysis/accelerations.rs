//! The accelerations and multipliers at `(t, q, v)`: the differentiated equations of motion
//! with the constraints at acceleration level,
//!
//! ```text
//! [ L_vv  −Aᵀ ] [ v̇ ]   [ ∂L/∂q + F − L_vt − L_vq v ]
//! [ A      0  ] [ λ ] = [ −∂(A v + b)/∂q v − ∂(A v + b)/∂t ]
//! ```
//!
//! one saddle-point solve per evaluation, with the storage the model's algebra gives (on the
//! stack for a dense model). The system is regular exactly when `L_vv` is positive definite
//! on the constraint distribution, which a degenerate Lagrangian whose massless coordinates
//! are held by constraints (the paper's torn chain) satisfies: its algebraic velocities are
//! eliminated here.
//!
//! Two shortcuts for separable models (constant `L_vv`, [`LagrangeDirac::SEPARABLE`]): with a
//! nonsingular mass matrix `M` (dense models), `M` is factored once and each evaluation solves
//! the `m × m` system `A M⁻¹ Aᵀ λ = …` (as RATTLE does); otherwise the factorisation of the
//! saddle-point system is kept while `A` does not change (linear constraints, or none).
//!
//! The factorisation of the last evaluation also projects a nearby state onto the
//! constraints ([`Accelerations::project`]), by corrections orthogonal in the metric `L_vv`.

use nalgebra::{DefaultAllocator, OMatrix};

use crate::algebra::lu::{Deflation, Lu};
use crate::algebra::mass::Mass;
use crate::algebra::{Algebra, Saddle, SaddleTerms, amax};
use crate::analysis::free::FreeVelocities;
use crate::analysis::init_saddle::SaddleOf;
use crate::error::SimError;
use crate::model::blocks::ResidualBlocks;
use crate::model::{LagrangeDirac, MatCQ, MatQQ, configuration};
use crate::shape::dims::{Dimensions, MatKK, Sizes, Storage, VecC, VecH, VecK, VecQ};
use crate::shape::layout::{Layout, Unknowns};

/// The `m × m` path of a separable dense model with a nonsingular mass matrix: `M` factored,
/// `B = M⁻¹ Aᵀ` and `S = A B` factored for the constraint rows of the last factorisation.
struct Schur<M: Dimensions>
where
    DefaultAllocator: Storage<M>,
{
    mass: Mass<M>,
    a: OMatrix<f64, M::Nc, M::Nq>,
    b: OMatrix<f64, M::Nq, M::Nc>,
    s: Lu<f64, M::Nc>,
    deflation: Deflation<f64, M::Nc>,
    top: VecQ<M>,
    bottom: VecC<M>,
}

/// Writes row `i` of `inverse · x` to the `i`-th slot `out` yields, for the `k × k` inverse
/// stored by columns (`k = x.len()`). Each sum runs over `j` in order: bit for bit what the
/// column-by-column accumulation gives.
fn inverse_product<'a>(inverse: &[f64], x: &[f64], out: impl Iterator<Item = &'a mut f64>) {
    let k = x.len();
    for (i, out) in out.enumerate().take(k) {
        let mut sum = 0.0;
        for (j, xj) in x.iter().enumerate() {
            sum += inverse[j * k + i] * xj;
        }
        *out = sum;
    }
}

/// What a projection did.
#[derive(Clone, Copy)]
pub(crate) struct Projection {
    /// Whether the positions or velocities moved.
    pub moved: bool,
    /// Whether they reached the constraints.
    pub reached: bool,
}

/// The storage of an evaluation.
pub(crate) struct Accelerations<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    sizes: Sizes,
    lvv: MatQQ<M>,
    lvq: MatQQ<M>,
    a: MatCQ<M>,
    dav: MatCQ<M>,
    /// `B − A` of a [`LagrangeDirac::NON_ASSOCIATED`] model, and of its factored system.
    slip: MatCQ<M>,
    factored_slip: MatCQ<M>,
    /// The constraint rows and `L_vv` of the factored system, whose factorisation is kept
    /// while they stay the same (every evaluation of a model with a constant mass matrix and
    /// constant constraint rows, such as a circuit of linear parts).
    factored_a: MatCQ<M>,
    factored_lvv: MatQQ<M>,
    /// Evaluations in a row that found the matrix changed since it was factored: past a few,
    /// it changes with the state (a pendulum's constraint rows) and is no longer compared.
    changed: u32,
    factored: bool,
    saddle: SaddleOf<M>,
    /// The inverse of a dense saddle-point matrix whose factorisation was kept for a second
    /// evaluation (constant mass matrix and constraint rows): its product is
    /// independent multiply-adds where the triangular solves are a chain of dependent ones.
    inverse: Option<MatKK<M>>,
    inverse_ready: bool,
    product: VecK<M>,
    /// The separable shortcut, once the mass matrix is known to allow it; `checked` once it
    /// was looked for.
    schur: Option<Schur<M>>,
    checked: bool,
    blocks: ResidualBlocks<M>,
    zero_lambda: VecC<M>,
    lvt: VecQ<M>,
    rate: VecC<M>,
    /// The rate at which driven inputs move the constraints' prescribed part, `∂b/∂u · u̇`,
    /// added to the model's own `∂(A v + b)/∂t` (zero unless a drive sets such inputs).
    pub input_rate: VecC<M>,
    phi: VecH<M>,
    /// The constraint rows and rates at a projected state.
    a_projected: MatCQ<M>,
    residual: VecC<M>,
    x: VecK<M>,
    /// Factorisations done, for the statistics.
    pub factorizations: usize,
    /// The velocities no inertia or constraint fixes, solved from the forces at every
    /// evaluation ([`Accelerations::prepare`] finds them).
    free: Option<FreeVelocities<M>>,
}

impl<M: LagrangeDirac> Accelerations<M>
where
    DefaultAllocator: Storage<M>,
{
    pub fn new(model: &M) -> Self {
        let (sizes, shape) = (model.sizes(), model.shape());
        let a = M::Algebra::zeros_cq(&shape);
        let dense = M::Algebra::dense_cq(&a).is_some();
        Accelerations {
            sizes,
            lvv: M::Algebra::zeros_qq(&shape),
            factored_lvv: M::Algebra::zeros_qq(&shape),
            changed: 0,
            lvq: M::Algebra::zeros_qq(&shape),
            a_projected: a.clone(),
            factored_a: a.clone(),
            slip: a.clone(),
            factored_slip: a.clone(),
            a,
            dav: M::Algebra::zeros_cq(&shape),
            factored: false,
            saddle: M::Algebra::saddle(&shape),
            inverse: dense.then(|| {
                let k = <M::Nk as nalgebra::Dim>::from_usize(sizes.nq + sizes.nc);
                MatKK::<M>::zeros_generic(k, k)
            }),
            inverse_ready: false,
            product: sizes.zeros_k::<M>(),
            schur: None,
            checked: false,
            blocks: ResidualBlocks::with_sizes(&sizes),
            zero_lambda: sizes.zeros_c::<M>(),
            lvt: sizes.zeros_q::<M>(),
            rate: sizes.zeros_c::<M>(),
            input_rate: sizes.zeros_c::<M>(),
            phi: sizes.zeros_h::<M>(),
            residual: sizes.zeros_c::<M>(),
            x: sizes.zeros_k::<M>(),
            factorizations: 0,
            free: None,
        }
    }

    /// Finds the velocities that only the forces fix at a start `(t, q, v)` (set-up: it
    /// allocates), so that every evaluation solves them from the momentum balance.
    pub fn prepare(&mut self, model: &M, t: f64, (q, v): (&VecQ<M>, &VecQ<M>)) -> Result<(), SimError> {
        self.free = FreeVelocities::find(model, t, (q, v), "Explicit")?;
        Ok(())
    }

    /// Forgets the velocities found by [`Accelerations::prepare`].
    pub fn unprepare(&mut self) {
        self.free = None;
    }

    /// Whether the model has velocities that only the forces fix (found by
    /// [`Accelerations::prepare`]).
    pub fn has_free(&self) -> bool {
        self.free.is_some()
    }

    /// Puts the velocities that only the forces fix onto their momentum balance at `(t, q)`;
    /// false where that fails (a singular matrix, no convergence). Nothing to do for a model
    /// without such velocities.
    #[inline]
    pub fn settle(&mut self, model: &M, t: f64, q: &VecQ<M>, v: &mut VecQ<M>) -> bool {
        match &mut self.free {
            Some(free) => free.settle(model, t, q, v),
            None => true,
        }
    }

    /// Whether the model's blocks are dense (its factorisations allocate nothing, ever).
    pub fn is_dense(&self) -> bool {
        M::Algebra::dense_qq(&self.lvv).is_some()
    }

    /// `∂L/∂v` at the point of the last evaluation: the momenta there.
    pub fn momenta(&self) -> &VecQ<M> {
        &self.blocks.dl_dv
    }

    /// Measures the constraint rows' redundancy again at the next factorisation: the model
    /// changed (a contact closed or opened).
    pub fn remeasure(&mut self) {
        self.saddle.remeasure();
        if let Some(schur) = &mut self.schur {
            schur.deflation.remeasure();
        }
    }

    /// Forgets the factorisation and the mass matrix: the model may have changed.
    pub fn forget(&mut self) {
        self.remeasure();
        self.factored = false;
        self.changed = 0;
        self.inverse_ready = false;
        self.checked = false;
        self.schur = None;
    }

    /// Looks once for the separable shortcut: a constant, nonsingular mass matrix of a dense
    /// model.
    fn look_for_mass(&mut self, model: &M, t: f64, (q, v): (&VecQ<M>, &VecQ<M>)) {
        self.checked = true;
        // The shortcut's `A M⁻¹ Aᵀ` is symmetric; a balance on `Bᵀλ` is not.
        if !M::SEPARABLE || M::NON_ASSOCIATED {
            return;
        }
        model.l_vv(t, q, v, &mut self.lvv);
        let Some(mass) = M::Algebra::dense_qq(&self.lvv).and_then(|matrix| Mass::new(&self.sizes, matrix))
        else {
            return;
        };
        let m = self.sizes.nc;
        self.schur = Some(Schur {
            mass,
            a: OMatrix::<f64, M::Nc, M::Nq>::zeros_generic(
                <M::Nc as nalgebra::Dim>::from_usize(m),
                <M::Nq as nalgebra::Dim>::from_usize(self.sizes.nq),
            ),
            b: OMatrix::<f64, M::Nq, M::Nc>::zeros_generic(
                <M::Nq as nalgebra::Dim>::from_usize(self.sizes.nq),
                <M::Nc as nalgebra::Dim>::from_usize(m),
            ),
            s: Lu::new(m),
            deflation: Deflation::new(m),
            top: self.sizes.zeros_q::<M>(),
            bottom: self.sizes.zeros_c::<M>(),
        });
    }

    /// Writes `v̇` and `λ` at `(t, q, v)`; false where the system is singular.
    pub fn evaluate(
        &mut self,
        model: &M,
        t: f64,
        (q, v): (&VecQ<M>, &VecQ<M>),
        acceleration: &mut VecQ<M>,
        lambda: &mut VecC<M>,
    ) -> bool {
        let Sizes { nq: n, nc: m, .. } = self.sizes;
        if !self.checked {
            self.look_for_mass(model, t, (q, v));
        }
        // A robot's tree gives the balance and the mass matrix by its recursions; its momenta
        // are then `M v`.
        let tree = model.tree_dynamics(t, q, v, &mut self.blocks.momentum_rate, &mut self.lvv);
        if tree {
            self.blocks.dl_dv.fill(0.0);
            M::Algebra::qq_mul(&self.lvv, 1.0, v.as_slice(), self.blocks.dl_dv.as_mut_slice());
        } else {
            model.residual_blocks(t, q, v, &self.zero_lambda, &mut self.blocks);
        }
        let x = self.x.as_mut_slice();
        x[..n].copy_from_slice(self.blocks.momentum_rate.as_slice());
        if !tree && !M::SEPARABLE {
            model.l_vt(t, q, v, &mut self.lvt);
            for (x, l) in x[..n].iter_mut().zip(self.lvt.iter()) {
                *x -= l;
            }
            model.l_vq(t, q, v, &mut self.lvq);
            M::Algebra::qq_mul(&self.lvq, -1.0, v.as_slice(), &mut x[..n]);
            // A mass matrix that moves with the state is needed by every evaluation (to compare
            // with the factored one, or to factor). Evaluated here, beside the other blocks and
            // from this one place, the compiler inlines it and shares its trigonometry with
            // theirs; a second call site (in the comparison and in `factor`) kept it out of line
            // and cost the 8-link pendulum 21% more instructions a solve.
            model.l_vv(t, q, v, &mut self.lvv);
        }
        // Constraint rows that depend on parameters alone are those of the factorisation held:
        // with no rates and no `∂(A v)/∂q`, the constraints' right-hand side is zero.
        let constant = M::CONSTANT_CONSTRAINTS && !M::NON_ASSOCIATED && self.factored;
        if m > 0 && constant {
            x[n..].fill(0.0);
        } else if m > 0 {
            model.constraint_matrix(t, q, &mut self.a);
            if M::NON_ASSOCIATED {
                model.slip_rows(t, q, v, &mut self.slip);
            }
            model.dav_dq(t, q, v, &mut self.dav);
            model.dav_dt(t, q, v, &mut self.rate);
            for ((x, r), u) in x[n..].iter_mut().zip(self.rate.iter()).zip(self.input_rate.iter()) {
                *x = -r - u;
            }
            M::Algebra::cq_mul(&self.dav, -1.0, v.as_slice(), &mut x[n..]);
        }
        // The factorisation holds while the matrix's entries stay the same: `L_vv` (constant
        // in a separable model, compared otherwise) and the constraint rows.
        let compare = self.changed < 4;
        let keep = self.factored
            && compare
            && (constant || M::Algebra::cq_values(&self.a) == M::Algebra::cq_values(&self.factored_a))
            && (!M::NON_ASSOCIATED
                || M::Algebra::cq_values(&self.slip) == M::Algebra::cq_values(&self.factored_slip))
            && (M::SEPARABLE
                || M::Algebra::qq_values(&self.lvv) == M::Algebra::qq_values(&self.factored_lvv));
        if keep {
            self.changed = 0;
        } else {
            if self.factored && compare {
                self.changed += 1;
            }
            self.factored = self.factor(model, t, (q, v));
            if !self.factored {
                return false;
            }
            if self.changed < 4 {
                M::Algebra::cq_values_mut(&mut self.factored_a)
                    .copy_from_slice(M::Algebra::cq_values(&self.a));
                if M::NON_ASSOCIATED {
                    M::Algebra::cq_values_mut(&mut self.factored_slip)
                        .copy_from_slice(M::Algebra::cq_values(&self.slip));
                }
                if self.schur.is_none() {
                    M::Algebra::qq_values_mut(&mut self.factored_lvv)
                        .copy_from_slice(M::Algebra::qq_values(&self.lvv));
                }
            }
        }
        if keep && !self.inverse_ready && self.schur.is_none() {
            self.invert();
        }
        if self.schur.is_none()
            && self.inverse_ready
            && let Some(inverse) = &self.inverse
        {
            // Written straight into the results, without a round trip through `x`.
            let k = <M::Nk as nalgebra::Dim>::try_to_usize().unwrap_or(n + m);
            let out = acceleration.iter_mut().chain(lambda.iter_mut());
            inverse_product(&inverse.as_slice()[..k * k], &self.x.as_slice()[..k], out);
            return true;
        }
        self.solve();
        let x = self.x.as_slice();
        acceleration.as_mut_slice().copy_from_slice(&x[..n]);
        lambda.as_mut_slice().copy_from_slice(&x[n..]);
        true
    }

    /// Forms the inverse of the factored saddle-point matrix, column by column, where it is
    /// dense.
    fn invert(&mut self) {
        let Some(inverse) = &mut self.inverse else {
            return;
        };
        let k = self.sizes.nq + self.sizes.nc;
        for j in 0..k {
            let column = self.product.as_mut_slice();
            column.fill(0.0);
            column[j] = 1.0;
            self.saddle.solve(column);
            inverse.column_mut(j).copy_from(&self.product);
        }
        self.inverse_ready = true;
    }

    /// Factors the system for the constraint rows in `a` and `L_vv` at `(t, q, v)` (evaluated
    /// here for a separable model, whose `L_vv` is constant; by `evaluate` otherwise).
    fn factor(&mut self, model: &M, t: f64, (q, v): (&VecQ<M>, &VecQ<M>)) -> bool {
        self.factorizations += 1;
        self.inverse_ready = false;
        if let Some(schur) = &mut self.schur {
            if self.sizes.nc == 0 {
                return true;
            }
            let a = M::Algebra::dense_cq(&self.a).expect("the shortcut is taken for dense models only");
            schur.a.copy_from(a);
            schur.b = schur.mass.solve_transpose(a);
            schur.a.mul_to(&schur.b, schur.s.matrix_mut());
            let rows = &schur.a;
            return schur.s.factor_schur(&mut schur.deflation, (rows.ncols(), |i, k| rows[(k, i)])).is_ok();
        }
        if M::SEPARABLE {
            model.l_vv(t, q, v, &mut self.lvv);
        }
        // Along the velocities the forces fix, `L_vv` vanishes; `N Nᵀ` there makes the matrix
        // regular and sets their accelerations to `Nᵀ` of the balance, zero once settled. Each
        // case assembles from a term list of constant length, so that its loops unroll (one
        // list of either length cost the 8-link pendulum 2% more instructions a solve).
        let right = [(-1.0, &self.a), (-1.0, &self.slip)];
        let right = if M::NON_ASSOCIATED { &right[..] } else { &right[..1] };
        let bottom = [(1.0, 1.0, &self.a)];
        match &self.free {
            Some(free) => self.saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
                top: &[(1.0, &self.lvv), (1.0, &free.projector)],
                top_transposed: &[],
                identity: 0.0,
                right,
                bottom: &bottom,
                corner: (0.0, 0.0),
            }),
            None => self.saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
                top: &[(1.0, &self.lvv)],
                top_transposed: &[],
                identity: 0.0,
                right,
                bottom: &bottom,
                corner: (0.0, 0.0),
            }),
        }
        self.saddle.factor().is_ok()
    }

    /// Replaces `x = (top, bottom)` by the solution `(v̇, λ)` with the factorisation held.
    fn solve(&mut self) {
        let Some(schur) = &mut self.schur else {
            match &self.inverse {
                Some(inverse) if self.inverse_ready => {
                    // The size as a constant where the model fixes it, so that the loops unroll.
                    let k = <M::Nk as nalgebra::Dim>::try_to_usize().unwrap_or(self.sizes.nq + self.sizes.nc);
                    let (inverse, x) = (&inverse.as_slice()[..k * k], &mut self.x.as_mut_slice()[..k]);
                    let product = &mut self.product.as_mut_slice()[..k];
                    inverse_product(inverse, x, product.iter_mut());
                    x.copy_from_slice(product);
                }
                _ => self.saddle.solve(self.x.as_mut_slice()),
            }
            return;
        };
        let Sizes { nq: n, nc: m, .. } = self.sizes;
        let x = self.x.as_mut_slice();
        // v̇ = M⁻¹ (top + Aᵀ λ) with A M⁻¹ Aᵀ λ = bottom − A M⁻¹ top; index loops over the
        // column-major storage, which for these small blocks cost less than nalgebra's
        // general products.
        let top = schur.top.as_mut_slice();
        top.copy_from_slice(&x[..n]);
        schur.mass.solve(&mut schur.top);
        if m > 0 {
            let (top, a, b) = (schur.top.as_slice(), schur.a.as_slice(), schur.b.as_slice());
            let bottom = schur.bottom.as_mut_slice();
            bottom.copy_from_slice(&x[n..]);
            for (j, t) in top.iter().enumerate() {
                for (r, y) in bottom.iter_mut().enumerate() {
                    *y -= a[r + j * m] * t;
                }
            }
            schur.deflation.project(schur.bottom.as_mut_slice());
            schur.s.solve(&mut schur.bottom);
            let lambda = schur.bottom.as_slice();
            x[..n].copy_from_slice(top);
            for (j, l) in lambda.iter().enumerate() {
                for (i, y) in x[..n].iter_mut().enumerate() {
                    *y += b[i + j * n] * l;
                }
            }
            x[n..].copy_from_slice(lambda);
        } else {
            x[..n].copy_from_slice(schur.top.as_slice());
        }
    }

    /// A first step size for an integration from `(t, q, v)` with accelerations `a0`, as
    /// DOPRI5's `HINIT` chooses it on the motion's ODE `q̇ = v`, `v̇ = a(t, q, v)`: the size of
    /// the state and of its derivative (an explicit Euler step's error of about 1% of the
    /// tolerance), and the derivative's change over such a step, which bounds the step by
    /// `(0.01 / |y''|)^exponent`, `exponent` one over the order of the error the step size
    /// controls; at most `max`. `scale(i, y)` weighs component `i` of `(q, v)` (`v` from `nq`)
    /// of value `y`. The Euler step's positions, velocities, accelerations and multipliers go to
    /// `scratch`; one evaluation, at that step's end.
    pub fn initial_step(
        &mut self,
        model: &M,
        (t, q, v, a0): (f64, &VecQ<M>, &VecQ<M>, &VecQ<M>),
        scale: impl Fn(usize, f64) -> f64,
        (exponent, max): (f64, f64),
        scratch: (&mut VecQ<M>, &mut VecQ<M>, &mut VecQ<M>, &mut VecC<M>),
    ) -> f64 {
        let Layout { v: v_at, .. } = Layout::new(self.sizes);
        let n = self.sizes.nq;
        let (q1, v1, a1, lambda) = scratch;
        let (mut dy, mut df) = (0.0, 0.0);
        for i in 0..n {
            let (sq, sv) = (scale(i, q[i]), scale(v_at + i, v[i]));
            dy += (q[i] / sq).powi(2) + (v[i] / sv).powi(2);
            df += (v[i] / sq).powi(2) + (a0[i] / sv).powi(2);
        }
        let mut h = if dy <= 1e-10 || df <= 1e-10 { 1e-6 } else { 0.01 * (dy / df).sqrt() };
        h = h.min(max);
        // An explicit Euler step of that size, and the derivative there.
        configuration::advance::<M>(q, h, v, q1);
        v1.copy_from(v);
        v1.axpy(h, a0, 1.0);
        if !self.settle(model, t + h, q1, v1) || !self.evaluate(model, t + h, (q1, v1), a1, lambda) {
            return h;
        }
        let mut d2 = 0.0;
        for i in 0..n {
            d2 +=
                ((v1[i] - v[i]) / scale(i, q[i])).powi(2) + ((a1[i] - a0[i]) / scale(v_at + i, v[i])).powi(2);
        }
        let d2 = d2.sqrt() / h;
        let d12 = d2.max(df.sqrt());
        let h1 =
            if d12 <= 1e-15 || !d12.is_finite() { (h * 1e-3).max(1e-6) } else { (0.01 / d12).powf(exponent) };
        (100.0 * h).min(h1).min(max)
    }

    /// Puts `(q, v)` at time `t` onto the constraints with the factorisation of the last
    /// evaluation: positions onto `φ(q, t) = 0` by simplified
    /// Newton, corrections `Δq` with `L_vv Δq ∈ range Aᵀ` and `A Δq = (−φ, 0)` (moving along
    /// the other constraints); then velocities onto `A(q, t) v + b(q, t) = 0` likewise.
    /// Iterations stop at round-off, at most four each. Says whether `(q, v)` moved, and
    /// whether it reached the constraints (to 1e-10 of their scale): a step too long for the
    /// simplified Newton iteration leaves them unreached.
    /// The last evaluation must have been at this `q` and `t` (its constraint rows are reused
    /// while the positions stay).
    pub fn project(&mut self, model: &M, t: f64, q: &mut VecQ<M>, v: &mut VecQ<M>) -> Projection {
        let (unknowns, nh) = (Unknowns::new(self.sizes), self.sizes.nh);
        let m = unknowns.m;
        let mut done = Projection { moved: false, reached: true };
        if m == 0 || !self.factored {
            return done;
        }
        for k in 0..=4 {
            if nh == 0 {
                break;
            }
            model.holonomic(t, q, &mut self.phi);
            let (r, size) = (amax(self.phi.as_slice()), 1.0 + amax(q.as_slice()));
            if r <= 1e-15 * size {
                break;
            }
            if k == 4 {
                done.reached = r <= 1e-10 * size;
                break;
            }
            let x = self.x.as_mut_slice();
            x.fill(0.0);
            for (x, phi) in unknowns.split_mut(x).1[..nh].iter_mut().zip(self.phi.iter()) {
                *x = -phi;
            }
            self.solve();
            done.moved = true;
            configuration::advance_in_place::<M>(q, 1.0, unknowns.split(self.x.as_slice()).0);
        }
        // The constraint rows at `q`: the last evaluation's, unless the positions moved.
        let positions_moved = done.moved;
        if positions_moved {
            model.constraint_matrix(t, q, &mut self.a_projected);
        }
        let scale = amax(M::Algebra::cq_values(if positions_moved { &self.a_projected } else { &self.a }))
            * amax(v.as_slice());
        for k in 0..=4 {
            self.residual.fill(0.0);
            if M::PRESCRIBED {
                model.constraint_rate(t, q, &mut self.residual);
            }
            let rows = if positions_moved { &self.a_projected } else { &self.a };
            M::Algebra::cq_mul(rows, 1.0, v.as_slice(), self.residual.as_mut_slice());
            let r = amax(self.residual.as_slice());
            if r <= 1e-15 * scale || r == 0.0 {
                break;
            }
            if k == 4 || !r.is_finite() {
                done.reached &= r <= 1e-10 * scale;
                break;
            }
            let x = self.x.as_mut_slice();
            x.fill(0.0);
            for (x, r) in unknowns.split_mut(x).1.iter_mut().zip(self.residual.iter()) {
                *x = -r;
            }
            self.solve();
            done.moved = true;
            for (v, dv) in v.iter_mut().zip(unknowns.split(self.x.as_slice()).0) {
                *v += dv;
            }
        }
        done
    }
}
