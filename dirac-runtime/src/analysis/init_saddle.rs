//! The projections and multipliers of a consistent start for large models, through the
//! model's own saddle-point solver (sparse for models made of arrays): the same problems as
//! the dense path in [`init`](crate::analysis::init), whose singular value decompositions cost `(n + m)³`.
//!
//! 1. `φ(q, t) = 0` by Gauss-Newton with the minimal-norm correction `Δq = A_hᵀ y`,
//!    `[I A_hᵀ; A_h 0] [Δq; y] = [0; φ]`;
//! 2. `A(q, t) v + b(q, t) = 0` with the least change in the kinetic-energy norm,
//!    `[L_vv + εI Aᵀ; A 0] [Δv; y] = [0; −A v]`;
//! 3. the multipliers, `[L_vv −Aᵀ; A 0] [v̇; λ] = [∂L/∂q + F − L_vq v − ∂²L/∂v∂t; −∂(Av)/∂q v]`.

use nalgebra::DefaultAllocator;

use crate::algebra::lu::Singular;
use crate::algebra::{Algebra, Saddle, SaddleTerms, amax};
use crate::analysis::diagnose::{non_finite_entry, non_finite_qq, singular_cause};
use crate::analysis::floors::{FLOOR, floor_of, within};
use crate::error::SimError;
use crate::model::LagrangeDirac;
use crate::model::configuration;
use crate::shape::dims::{Sizes, Storage, VecQ};
use crate::shape::layout::{Unknown, Unknowns};

pub(crate) type SaddleOf<M> = <<M as LagrangeDirac>::Algebra as Algebra<M>>::Saddle<f64>;

/// Why a consistency system is singular: the unknown without a pivot, and what the model's
/// structure says.
pub(crate) fn not_determined<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
    s: Singular,
) -> SimError
where
    DefaultAllocator: Storage<M>,
{
    let unknown = match Unknowns::new(model.sizes()).unknown(s.column) {
        Unknown::Velocity(i) => format!("velocity `{}`", model.velocity_names()[i]),
        Unknown::Multiplier(j) => format!("the multiplier of `{}`", model.constraint_names()[j]),
    };
    SimError::NotDetermined {
        t,
        cause: format!("nothing determines {unknown}; {}", singular_cause(model, t, q, v)),
    }
}

/// `[I A_hᵀ; A_h 0]`: the system of the smallest position correction onto the holonomic
/// constraints (the other constraints' rows hold only a unit diagonal).
pub(crate) fn assemble_positions<M: LagrangeDirac>(
    saddle: &mut SaddleOf<M>,
    a: &<M::Algebra as Algebra<M>>::Cq,
) where
    DefaultAllocator: Storage<M>,
{
    saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
        top: &[],
        top_transposed: &[],
        identity: 1.0,
        right: &[(1.0, a)],
        bottom: &[(1.0, 0.0, a)],
        corner: (0.0, 1.0),
    });
}

/// `[L_vv + εI Aᵀ; A 0]`: the system of the velocity correction of least kinetic energy onto
/// the velocity constraints.
pub(crate) fn assemble_velocities<M: LagrangeDirac>(
    saddle: &mut SaddleOf<M>,
    l_vv: &<M::Algebra as Algebra<M>>::Qq,
    a: &<M::Algebra as Algebra<M>>::Cq,
) where
    DefaultAllocator: Storage<M>,
{
    saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
        top: &[(1.0, l_vv)],
        top_transposed: &[],
        // A small multiple of I keeps the problem well posed where L_vv is singular off ker A:
        // small beside the least inertia, so that every velocity with some keeps its weight.
        identity: 1e-10 * least_inertia::<M>(l_vv).unwrap_or(1.0),
        right: &[(1.0, a)],
        bottom: &[(1.0, 1.0, a)],
        corner: (0.0, 0.0),
    });
}

/// Whether the model is sparse and its saddle-point matrix `[L_vv Aᵀ; A 0]` at `(t, q, v)`
/// factors without regularisation: then inertia and constraints fix every velocity, there is
/// no direction of `ker L_vv ∩ ker A` for the forces to fix, and the sparse path starts it.
pub(crate) fn velocities_determined<M: LagrangeDirac>(model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>) -> bool
where
    DefaultAllocator: Storage<M>,
{
    let shape = model.shape();
    let (mut lvv, mut a) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_cq(&shape));
    if M::Algebra::dense_qq(&lvv).is_some() {
        return false;
    }
    model.l_vv(t, q, v, &mut lvv);
    model.constraint_matrix(t, q, &mut a);
    let finite = |x: &[f64]| x.iter().all(|x| x.is_finite());
    if !finite(M::Algebra::qq_values(&lvv)) || !finite(M::Algebra::cq_values(&a)) {
        return false;
    }
    let mut saddle: SaddleOf<M> = M::Algebra::saddle(&shape);
    saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
        top: &[(1.0, &lvv)],
        top_transposed: &[],
        identity: 0.0,
        right: &[(1.0, &a)],
        bottom: &[(1.0, 1.0, &a)],
        corner: (0.0, 0.0),
    });
    saddle.factor().is_ok()
}

/// Projects `q` onto `φ(q, t) = 0`.
pub(crate) fn project_positions<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &mut VecQ<M>,
    (tolerance, max_iterations): (f64, usize),
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (sizes, shape) = (model.sizes(), model.shape());
    let Sizes { nq: n, nc: m, nh: h } = sizes;
    if h == 0 {
        return Ok(());
    }
    let mut saddle: SaddleOf<M> = M::Algebra::saddle(&shape);
    let (mut phi, mut a) = (sizes.zeros_h::<M>(), M::Algebra::zeros_cq(&shape));
    let (mut x, at_rest) = (vec![0.0; n + m], sizes.zeros_q::<M>());
    let mut sizes = vec![0.0; h];
    for iteration in 0..=max_iterations {
        model.holonomic(t, q, &mut phi);
        non_finite_entry(model, t, "a holonomic constraint φ(q)", phi.as_slice(), false)?;
        model.constraint_matrix(t, q, &mut a);
        non_finite_entry(model, t, "the constraint rows A(q)", M::Algebra::cq_values(&a), false)?;
        // Each row against the size of its terms linear in the positions.
        sizes.fill(0.0);
        let floor = floor_of(q.amax());
        M::Algebra::cq_entries(&a, |row, column, value| {
            if row < h {
                sizes[row] += value.abs() * (q[column].abs() + floor);
            }
        });
        if within(phi.as_slice(), &sizes, tolerance) {
            return Ok(());
        }
        if iteration == max_iterations {
            let j = phi.iamax();
            return Err(SimError::InconsistentInitialState {
                equation: format!("holonomic constraint `{}`", model.constraint_names()[j]),
                residual: phi[j].abs(),
                iterations: max_iterations,
            });
        }
        assemble_positions(&mut saddle, &a);
        saddle.factor().map_err(|s| not_determined(model, t, q, &at_rest, s))?;
        x.fill(0.0);
        x[n..n + h].copy_from_slice(phi.as_slice());
        saddle.solve(&mut x);
        configuration::advance_in_place::<M>(q, -1.0, &x[..n]);
        non_finite_entry(model, t, "a coordinate while projecting onto the constraints", q.as_slice(), true)?;
    }
    unreachable!("the last iteration returns")
}

/// Projects `v` onto `A(q, t) v + b(q, t) = 0`.
pub(crate) fn project_velocities<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &mut VecQ<M>,
    tolerance: f64,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (sizes, shape) = (model.sizes(), model.shape());
    let Sizes { nq: n, nc: m, .. } = sizes;
    if m == 0 {
        return Ok(());
    }
    let mut a = M::Algebra::zeros_cq(&shape);
    model.constraint_matrix(t, q, &mut a);
    non_finite_entry(model, t, "the constraint rows A(q)", M::Algebra::cq_values(&a), false)?;
    let mut b = sizes.zeros_c::<M>();
    model.constraint_rate(t, q, &mut b);
    non_finite_entry(model, t, "the constraint rates b(q, t)", b.as_slice(), false)?;
    let mut av = b.as_slice().to_vec();
    M::Algebra::cq_mul(&a, 1.0, v.as_slice(), &mut av);
    // Each row against the size of its own terms, `Σ_i |A_ji| (|v_i| + FLOOR |v|∞) + |b_j|`.
    let row_sizes = |v: &VecQ<M>| {
        let mut sizes: Vec<f64> = b.iter().map(|x| x.abs()).collect();
        let floor = floor_of(v.amax());
        M::Algebra::cq_entries(&a, |row, column, value| {
            sizes[row] += value.abs() * (v[column].abs() + floor)
        });
        sizes
    };
    if within(&av, &row_sizes(v), tolerance) {
        return Ok(());
    }
    let mut lvv = M::Algebra::zeros_qq(&shape);
    model.l_vv(t, q, v, &mut lvv);
    non_finite_entry(model, t, "the mass matrix L_vv", M::Algebra::qq_values(&lvv), false)?;
    let mut saddle: SaddleOf<M> = M::Algebra::saddle(&shape);
    assemble_velocities(&mut saddle, &lvv, &a);
    saddle.factor().map_err(|s| not_determined(model, t, q, v, s))?;
    // Solved, then refined once against the rows' residual with the same factors.
    let mut x = vec![0.0; n + m];
    for _ in 0..2 {
        x[..n].fill(0.0);
        for (xr, avr) in x[n..].iter_mut().zip(&av) {
            *xr = -avr;
        }
        saddle.solve(&mut x);
        for i in 0..n {
            v[i] += x[i];
        }
        av.copy_from_slice(b.as_slice());
        M::Algebra::cq_mul(&a, 1.0, v.as_slice(), &mut av);
    }
    let sizes = row_sizes(v);
    let excess = |j: usize| if av[j].is_nan() { f64::INFINITY } else { av[j].abs() / sizes[j] };
    let j = (0..m).fold(0, |b, j| if excess(j) > excess(b) { j } else { b });
    if !within(&av[j..=j], &sizes[j..=j], 1e3 * tolerance) {
        return Err(SimError::InconsistentInitialState {
            equation: format!("velocity constraint `{}`", model.constraint_names()[j]),
            residual: av[j].abs(),
            iterations: 1,
        });
    }
    Ok(())
}

/// The multipliers at a consistent `(t, q, v)`, from the momentum balance and the
/// differentiated constraints with right-hand sides `top` and `bottom`.
pub(crate) fn multipliers<M: LagrangeDirac>(
    model: &M,
    t: f64,
    (q, v): (&VecQ<M>, &VecQ<M>),
    (top, bottom): (&[f64], &[f64]),
) -> Result<Vec<f64>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (sizes, shape) = (model.sizes(), model.shape());
    let Sizes { nq: n, nc: m, .. } = sizes;
    let (mut lvv, mut a) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_cq(&shape));
    model.l_vv(t, q, v, &mut lvv);
    model.constraint_matrix(t, q, &mut a);
    let mut saddle: SaddleOf<M> = M::Algebra::saddle(&shape);
    saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
        top: &[(1.0, &lvv)],
        top_transposed: &[],
        identity: 0.0,
        right: &[(-1.0, &a)],
        bottom: &[(1.0, 1.0, &a)],
        corner: (0.0, 0.0),
    });
    saddle.factor().map_err(|s| not_determined(model, t, q, v, s))?;
    let mut x = Vec::with_capacity(n + m);
    x.extend_from_slice(top);
    x.extend_from_slice(bottom);
    saddle.solve(&mut x);
    Ok(x.split_off(n))
}

/// The smallest positive diagonal entry of `L_vv` (the least inertia of a velocity that has
/// some), `None` if no velocity has inertia.
fn least_inertia<M: LagrangeDirac>(lvv: &<M::Algebra as Algebra<M>>::Qq) -> Option<f64>
where
    DefaultAllocator: Storage<M>,
{
    let mut least: Option<f64> = None;
    M::Algebra::qq_entries(lvv, |row, column, value| {
        if row == column && value > 0.0 && least.is_none_or(|l| value < l) {
            least = Some(value);
        }
    });
    least
}

/// The blocks of `(t, q, v)` the free velocities' iteration needs.
struct Blocks<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    lvv: <M::Algebra as Algebra<M>>::Qq,
    lvq: <M::Algebra as Algebra<M>>::Qq,
    fv: <M::Algebra as Algebra<M>>::Qq,
    a: <M::Algebra as Algebra<M>>::Cq,
}

impl<M: LagrangeDirac> Blocks<M>
where
    DefaultAllocator: Storage<M>,
{
    fn at(model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>) -> Result<Self, SimError> {
        let shape = model.shape();
        let mut blocks = Blocks {
            lvv: M::Algebra::zeros_qq(&shape),
            lvq: M::Algebra::zeros_qq(&shape),
            fv: M::Algebra::zeros_qq(&shape),
            a: M::Algebra::zeros_cq(&shape),
        };
        model.l_vv(t, q, v, &mut blocks.lvv);
        model.l_vq(t, q, v, &mut blocks.lvq);
        model.force_dv(t, q, v, &mut blocks.fv);
        model.constraint_matrix(t, q, &mut blocks.a);
        for (what, values) in [
            ("the mass matrix L_vv", M::Algebra::qq_values(&blocks.lvv)),
            ("L_vq", M::Algebra::qq_values(&blocks.lvq)),
            ("∂F/∂v", M::Algebra::qq_values(&blocks.fv)),
            ("the constraint rows A(q)", M::Algebra::cq_values(&blocks.a)),
        ] {
            non_finite_entry(model, t, what, values, false)?;
        }
        Ok(blocks)
    }

    /// `[σ L_vv − J  −Aᵀ; A 0]` with `J = L_qv − L_vq + F_v`, how the momentum balance
    /// `∂L/∂q + F − L_vq v − ∂²L/∂v∂t` changes with the velocities (the terms with third
    /// derivatives of `L` left out: they change Newton's rate, not its solution).
    fn shifted(&self, saddle: &mut SaddleOf<M>, sigma: f64) {
        saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
            top: &[(sigma, &self.lvv), (-1.0, &self.fv), (1.0, &self.lvq)],
            top_transposed: &[(-1.0, &self.lvq)],
            identity: 0.0,
            right: &[(-1.0, &self.a)],
            bottom: &[(1.0, 1.0, &self.a)],
            corner: (0.0, 0.0),
        });
    }

    /// The shift `σ` under which `σ L_vv` outweighs `J` a million times on every velocity with
    /// inertia, relative to the model's own sizes (0 without inertia).
    fn shift(&self) -> f64 {
        let j = amax(M::Algebra::qq_values(&self.fv)) + 2.0 * amax(M::Algebra::qq_values(&self.lvq));
        least_inertia::<M>(&self.lvv).map_or(0.0, |l| 1e6 * j.max(f64::MIN_POSITIVE) / l)
    }
}

/// The velocities that neither inertia nor constraints fix (the directions `N` of
/// `ker L_vv ∩ ker A`: a node without capacitance, a massless link between dampers), solved
/// from the momentum balance projected on them, `Nᵀ (∂L/∂q + F − L_vq v − ∂²L/∂v∂t) = 0`,
/// without forming `N`: true if there were any.
///
/// A Newton step on `[σ L_vv − J  −Aᵀ; A 0] [δ; λ] = [balance; −(A v + b)]` moves the free
/// velocities by Newton's step of the projected balance (`Nᵀ L_vv = 0`, `Nᵀ Aᵀ = 0`) and the
/// others by `O(1/σ)`, which the least-kinetic-energy projection `[L_vv + εI Aᵀ; A 0]` then
/// takes back out, so that the velocities with inertia keep their values. Both systems are
/// sparse: the cost is a few factorisations, linear in the size of a network.
pub(crate) fn free_velocities<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &mut VecQ<M>,
    (tolerance, max_iterations): (f64, usize),
) -> Result<bool, SimError>
where
    DefaultAllocator: Storage<M>,
{
    if velocities_determined(model, t, q, v) {
        return Ok(false);
    }
    let (sizes, shape) = (model.sizes(), model.shape());
    let Sizes { nq: n, nc: m, .. } = sizes;
    let (mut shifted, mut projection): (SaddleOf<M>, SaddleOf<M>) =
        (M::Algebra::saddle(&shape), M::Algebra::saddle(&shape));
    let (mut x, mut y, mut b) = (vec![0.0; n + m], vec![0.0; n + m], sizes.zeros_c::<M>());
    let mut step = 0.0;
    for _ in 0..max_iterations.max(2) {
        let blocks = Blocks::at(model, t, q, v)?;
        blocks.shifted(&mut shifted, blocks.shift());
        shifted.factor().map_err(|s| not_determined(model, t, q, v, s))?;
        let (balance, _) = rates(model, t, q, v)?;
        x[..n].copy_from_slice(&balance);
        model.constraint_rate(t, q, &mut b);
        for (xr, br) in x[n..].iter_mut().zip(b.iter()) {
            *xr = -br;
        }
        M::Algebra::cq_mul(&blocks.a, -1.0, v.as_slice(), &mut x[n..]);
        shifted.solve(&mut x);
        // The step's part with inertia: the velocities `y` of least kinetic energy with the
        // step's momenta `L_vv δ` and constraint velocities `A δ`.
        assemble_velocities(&mut projection, &blocks.lvv, &blocks.a);
        projection.factor().map_err(|s| not_determined(model, t, q, v, s))?;
        y.fill(0.0);
        M::Algebra::qq_mul(&blocks.lvv, 1.0, &x[..n], &mut y[..n]);
        M::Algebra::cq_mul(&blocks.a, 1.0, &x[..n], &mut y[n..]);
        projection.solve(&mut y);
        step = 0.0f64;
        for i in 0..n {
            let d = x[i] - y[i];
            v[i] += d;
            step = step.max(d.abs());
        }
        non_finite_entry(model, t, "a velocity without inertia", v.as_slice(), true)?;
        if step <= 1e2 * tolerance * floor_of(v.amax()) / FLOOR {
            return Ok(true);
        }
    }
    Err(SimError::InconsistentInitialState {
        equation: "the momentum balance along the velocities without inertia (fixed by the forces)".into(),
        residual: step,
        iterations: max_iterations,
    })
}

/// The multipliers at a consistent `(t, q, v)` of a model with velocities that only the forces
/// fix: `[L_vv −Aᵀ; A 0] [v̇; λ] = [top; bottom]` determines `λ` but not `v̇` along them, so it
/// is solved with the shifted matrix `[σ L_vv − J  −Aᵀ; A 0]` (for `[L_vv − J/σ  −Aᵀ/σ; …]`,
/// nonsingular), refined against the unshifted system until `λ` settles.
pub(crate) fn free_multipliers<M: LagrangeDirac>(
    model: &M,
    t: f64,
    (q, v): (&VecQ<M>, &VecQ<M>),
    (top, bottom): (&[f64], &[f64]),
) -> Result<Vec<f64>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let Sizes { nq: n, nc: m, .. } = model.sizes();
    let blocks = Blocks::at(model, t, q, v)?;
    let sigma = blocks.shift().max(1.0);
    let mut shifted: SaddleOf<M> = M::Algebra::saddle(&model.shape());
    blocks.shifted(&mut shifted, sigma);
    shifted.factor().map_err(|s| not_determined(model, t, q, v, s))?;
    let (mut solution, mut r) = (vec![0.0; n + m], vec![0.0; n + m]);
    let size = amax(top).max(amax(bottom));
    for _ in 0..20 {
        // The unshifted system's residual at the present (v̇, λ).
        r[..n].copy_from_slice(top);
        r[n..].copy_from_slice(bottom);
        M::Algebra::qq_mul(&blocks.lvv, -1.0, &solution[..n], &mut r[..n]);
        M::Algebra::cq_tr_mul(&blocks.a, 1.0, &solution[n..], &mut r[..n]);
        M::Algebra::cq_mul(&blocks.a, -1.0, &solution[..n], &mut r[n..]);
        if amax(&r) <= 1e-14 * size || size == 0.0 {
            break;
        }
        // σ times the momentum rows, λ in units of σ λ.
        for x in &mut r[..n] {
            *x *= sigma;
        }
        shifted.solve(&mut r);
        let change = amax(&r[n..]) / sigma;
        for (s, d) in solution[..n].iter_mut().zip(&r[..n]) {
            *s += d;
        }
        for (s, d) in solution[n..].iter_mut().zip(&r[n..]) {
            *s += d / sigma;
        }
        if change <= 1e-15 * amax(&solution[n..]) {
            break;
        }
    }
    Ok(solution.split_off(n))
}

/// The right-hand sides of the multipliers' system at `(t, q, v)`: the momentum balance
/// without constraint forces and the differentiated constraints, each checked to be finite.
pub(crate) fn rates<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
) -> Result<(Vec<f64>, Vec<f64>), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (sizes, shape) = (model.sizes(), model.shape());
    let (mut dl_dq, mut force, mut lvt) = (sizes.zeros_q::<M>(), sizes.zeros_q::<M>(), sizes.zeros_q::<M>());
    model.dl_dq(t, q, v, &mut dl_dq);
    non_finite_entry(model, t, "∂L/∂q", dl_dq.as_slice(), true)?;
    model.force(t, q, v, &mut force);
    non_finite_entry(model, t, "the force", force.as_slice(), true)?;
    model.l_vt(t, q, v, &mut lvt);
    non_finite_entry(model, t, "∂²L/∂v∂t", lvt.as_slice(), true)?;
    let mut lvq = M::Algebra::zeros_qq(&shape);
    model.l_vq(t, q, v, &mut lvq);
    non_finite_qq(model, t, "L_vq", &lvq)?;
    let mut g = M::Algebra::zeros_cq(&shape);
    model.dav_dq(t, q, v, &mut g);
    non_finite_entry(model, t, "∂(A v + b)/∂q", M::Algebra::cq_values(&g), false)?;
    let mut rate = sizes.zeros_c::<M>();
    model.dav_dt(t, q, v, &mut rate);
    non_finite_entry(model, t, "∂(A v + b)/∂t", rate.as_slice(), false)?;
    let mut top = dl_dq + force - lvt;
    M::Algebra::qq_mul(&lvq, -1.0, v.as_slice(), top.as_mut_slice());
    non_finite_entry(model, t, "the momentum balance", top.as_slice(), true)?;
    let mut bottom: Vec<f64> = rate.iter().map(|x| -x).collect();
    M::Algebra::cq_mul(&g, -1.0, v.as_slice(), &mut bottom);
    non_finite_entry(model, t, "the constraint accelerations", &bottom, false)?;
    Ok((top.as_slice().to_vec(), bottom))
}
