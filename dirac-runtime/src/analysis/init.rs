//! Consistent initial states: from positions and velocities a user chooses, the nearest state
//! that satisfies every algebraic equation of the implicit Lagrange-d'Alembert equations.
//!
//! 1. positions are projected onto `φ(q, t) = 0` (Gauss-Newton, minimal-norm corrections);
//! 2. velocities are projected onto `A(q, t) v + b(q, t) = 0`, minimising the kinetic-energy
//!    norm of the change, `½ Δvᵀ L_vv Δv`, so that velocities without inertia (a degenerate
//!    Lagrangian's) take up the correction and the others keep the values given;
//! 3. velocities that neither inertia nor constraints fix (the directions `N` of
//!    `ker L_vv ∩ ker A`: a capacitor's current, a massless node between dampers) solve the
//!    momentum balance projected on them, `Nᵀ (∂L/∂q + F − L_vq v − ∂²L/∂v∂t) = 0`, an
//!    equation in `v` without `v̇` (`Nᵀ L_vv = 0`, `Nᵀ Aᵀ = 0`), by Newton's method with the
//!    matrix `Nᵀ (L_qv − L_vq + F_v) N` (dissipation `−R_vv` is part of `F_v`);
//! 4. momenta are set by the Legendre map `p = ∂L/∂v`;
//! 5. multipliers (and accelerations) solve the differentiated constraints
//!    `[L_vv −Aᵀ; A 0] [v̇; λ] = [∂L/∂q + F − L_vq v − ∂²L/∂v∂t; −∂(Av + b)/∂q v − ∂(Av + b)/∂t]`.
//!
//! Every quantity is checked to be finite before it is used, so a NaN parameter or an
//! overflowing state ends in a typed error that names it, never in a hung decomposition or a
//! NaN multiplier returned as success. Set-up code: it allocates, unlike a step.

use nalgebra::{DMatrix, DVector, DefaultAllocator};

use crate::algebra::{Algebra, dense_cq, dense_qq};
use crate::analysis::diagnose::{
    DENSE_ANALYSIS, SPARSE_ANALYSIS, cause_of, check_finite_state, check_inertia, non_finite_entry,
    non_finite_qq, svd,
};
use crate::analysis::floors::{floor_of, within};
use crate::analysis::init_saddle::{self, rates};
use crate::analysis::units::Units;
use crate::error::SimError;
use crate::model::configuration;
use crate::model::state::State;
use crate::model::{LagrangeDirac, check_parameters};
use crate::shape::dims::{Sizes, Storage, VecQ};
use crate::shape::layout::{Layout, Slot};

/// Tolerance and iteration budget of the projections.
#[derive(Clone, Copy, Debug)]
pub struct Consistency {
    /// How far positions (velocities) may remain from the constraints, relative to their size
    /// `1 + |q|` (`1 + |v|`): a residual `φ(q, t)` (`A(q, t) v + b`) is accepted up to this times
    /// `|A(q)| (1 + |q|)` (`|A(q)| (1 + |v|)`).
    pub tolerance: f64,
    /// Gauss-Newton iterations allowed for `φ(q, t) = 0`.
    pub max_iterations: usize,
}

impl Default for Consistency {
    fn default() -> Self {
        Consistency { tolerance: 1e-13, max_iterations: 50 }
    }
}

/// The consistent state nearest to positions `q` and velocities `v` at time `t`, every law's
/// mode as `q` holds it ([`consistent_state`](crate::consistent_state) chooses them).
pub(crate) fn project<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
    options: Consistency,
) -> Result<State<M>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    if !(options.tolerance > 0.0 && options.tolerance.is_finite()) {
        return Err(SimError::InvalidTolerance { what: "consistency tolerance", value: options.tolerance });
    }
    if !t.is_finite() {
        return Err(SimError::InvalidTimeSpan { reason: format!("the initial time {t} is not finite") });
    }
    check_parameters(model)?;
    let sizes = model.sizes();
    let mut s = State::<M>::with_sizes(sizes);
    s.q.copy_from(q);
    s.v.copy_from(v);
    if let Some(j) = s.q.iter().chain(s.v.iter()).position(|x| !x.is_finite()) {
        // `(q, v)` is the start of the flat state: its layout names the slot.
        let (names, i) = match Layout::new(sizes).slot(j) {
            Slot::Position(i) => (model.coordinate_names(), i),
            Slot::Velocity(i) => (model.velocity_names(), i),
            slot => unreachable!("slot {j} of (q, v) is a position or a velocity, not {slot:?}"),
        };
        return Err(SimError::NonFinite { t, component: names[i].clone() });
    }
    // Large models and sparse ones beyond a few hundred unknowns take the saddle path: sparse
    // factorisations, linear in the size of a network, where the dense analysis costs a
    // singular value decomposition, cubic in it.
    let size = sizes.nq + sizes.nc;
    let sparse = M::Algebra::dense_qq(&M::Algebra::zeros_qq(&model.shape())).is_none();
    let saddle_path = size > DENSE_ANALYSIS || (sparse && size > SPARSE_ANALYSIS);
    check_inertia(model, t, &s.q, &s.v)?;
    let free = if saddle_path {
        let budget = (options.tolerance, options.max_iterations);
        init_saddle::project_positions(model, t, &mut s.q, budget)?;
        init_saddle::project_velocities(model, t, &s.q, &mut s.v, options.tolerance)?;
        usize::from(init_saddle::free_velocities(model, t, &s.q, &mut s.v, budget)?)
    } else {
        project_positions(model, t, &mut s.q, options)?;
        project_velocities(model, t, &s.q, &mut s.v, options)?;
        algebraic_velocities(model, t, &s.q, &mut s.v, options)?
    };
    model.dl_dv(t, &s.q, &s.v, &mut s.p);
    non_finite_entry(model, t, "the momentum p = ∂L/∂v", s.p.as_slice(), true)?;
    s.lambda.copy_from_slice(multipliers(model, t, &s.q, &s.v, free, saddle_path)?.as_slice());
    check_finite_state(model, t, &s)?;
    Ok(s)
}

fn project_positions<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &mut VecQ<M>,
    options: Consistency,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let Sizes { nq: n, nc: m, nh: h } = model.sizes();
    if h == 0 {
        return Ok(());
    }
    let mut phi = model.sizes().zeros_h::<M>();
    let mut a = M::Algebra::zeros_cq(&model.shape());
    for iteration in 0..=options.max_iterations {
        model.holonomic(t, q, &mut phi);
        non_finite_entry(model, t, "a holonomic constraint φ(q)", phi.as_slice(), false)
            .map_err(|_| holonomic_not_finite(model, t, phi.as_slice()))?;
        model.constraint_matrix(t, q, &mut a);
        let ah = dense_cq::<M, M::Algebra>(&a, m, n).rows(0, h).into_owned();
        if !ah.iter().all(|x| x.is_finite()) {
            return Err(SimError::NonFinite {
                t, component: "a holonomic constraint's row ∂φ/∂q".into()
            });
        }
        // φ / |∂φ/∂q| is how far the positions are from the constraint, to first order; each
        // row against the size of its terms linear in the positions.
        let floor = floor_of(q.amax());
        let sizes =
            DVector::from_fn(h, |j, _| (0..n).map(|i| ah[(j, i)].abs() * (q[i].abs() + floor)).sum::<f64>());
        if within(phi.as_slice(), sizes.as_slice(), options.tolerance) {
            return Ok(());
        }
        if iteration == options.max_iterations {
            break;
        }
        let correction = min_norm_solve(&ah, &DVector::from_column_slice(phi.as_slice()));
        configuration::advance_in_place::<M>(q, -1.0, correction.as_slice());
        if let Some(i) = q.iter().position(|x| !x.is_finite()) {
            let component =
                format!("coordinate `{}` while projecting onto the constraints", model.coordinate_names()[i]);
            return Err(SimError::NonFinite { t, component });
        }
    }
    let (j, residual) =
        phi.iter().enumerate().fold((0, 0.0f64), |b, (j, x)| if x.abs() > b.1 { (j, x.abs()) } else { b });
    Err(SimError::InconsistentInitialState {
        equation: format!("holonomic constraint `{}`", model.constraint_names()[j]),
        residual,
        iterations: options.max_iterations,
    })
}

fn holonomic_not_finite<M: LagrangeDirac>(model: &M, t: f64, phi: &[f64]) -> SimError
where
    DefaultAllocator: Storage<M>,
{
    let j = phi.iter().position(|x| !x.is_finite()).unwrap_or(0);
    SimError::NonFinite { t, component: format!("holonomic constraint `{}`", model.constraint_names()[j]) }
}

/// The minimal-norm `x` with `A x = b` (least squares if there is none); finite input only.
fn min_norm_solve(a: &DMatrix<f64>, b: &DVector<f64>) -> DVector<f64> {
    match svd(a) {
        Some(svd) => svd.solve(b, 1e-14 * a.amax().max(1e-300)).expect("SVD with both factors computed"),
        None => DVector::from_element(a.ncols(), f64::NAN),
    }
}

fn project_velocities<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &mut VecQ<M>,
    options: Consistency,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let Sizes { nq: n, nc: m, .. } = model.sizes();
    if m == 0 {
        return Ok(());
    }
    let shape = model.shape();
    let mut a = M::Algebra::zeros_cq(&shape);
    model.constraint_matrix(t, q, &mut a);
    non_finite_entry(model, t, "the constraint rows A(q)", M::Algebra::cq_values(&a), false)?;
    let a = dense_cq::<M, M::Algebra>(&a, m, n);
    let mut b = model.sizes().zeros_c::<M>();
    model.constraint_rate(t, q, &mut b);
    non_finite_entry(model, t, "the constraint rates b(q, t)", b.as_slice(), false)?;
    let b = DVector::from_column_slice(b.as_slice());
    let v_now = DVector::from_column_slice(v.as_slice());
    let av = &a * &v_now + &b;
    non_finite_entry(model, t, "the constraint velocities A(q, t) v + b(q, t)", av.as_slice(), false)?;
    if worst_row(&a, &v_now, &b, options.tolerance).is_none() {
        return Ok(());
    }
    let mut lvv = M::Algebra::zeros_qq(&shape);
    model.l_vv(t, q, v, &mut lvv);
    non_finite_qq(model, t, "the mass matrix L_vv", &lvv)?;
    // The change of least kinetic energy, in the model's own units, where `L'` has a unit
    // diagonal wherever there is inertia; along velocities that neither inertia nor the
    // constraints fix, the least change (the minimal-norm solution). Refined once against the
    // rows' residual, with the same factors.
    let units = Units::of(&dense_qq::<M, M::Algebra>(&lvv, n), &a);
    let a_scaled = units.a(&a);
    let mut kkt = DMatrix::zeros(n + m, n + m);
    kkt.view_mut((0, 0), (n, n)).copy_from(&units.lvv(&dense_qq::<M, M::Algebra>(&lvv, n)));
    kkt.view_mut((0, n), (n, m)).copy_from(&a_scaled.transpose());
    kkt.view_mut((n, 0), (m, n)).copy_from(&a_scaled);
    let Some(svd) = svd(&kkt) else {
        return Err(SimError::NonFinite { t, component: "the mass matrix or the constraint rows".into() });
    };
    let cut = 1e-12 * svd.singular_values.max();
    let mut av = av;
    for _ in 0..2 {
        let rhs = DVector::from_fn(n + m, |k, _| if k < n { 0.0 } else { -units.row[k - n] * av[k - n] });
        let x = svd.solve(&rhs, cut).expect("SVD with both factors computed");
        for i in 0..n {
            v[i] += units.velocity[i] * x[i];
        }
        av = &a * DVector::from_column_slice(v.as_slice()) + &b;
    }
    let projected = DVector::from_column_slice(v.as_slice());
    let Some((j, residual)) = worst_row(&a, &projected, &b, 1e3 * options.tolerance) else {
        return Ok(());
    };
    // What the projection leaves of a velocity it brought to rest is the round-off of the
    // velocities it started from (in the model's own units), measured against which a row of
    // a state at rest (a box stuck to the ground) misses by its own round-off: a zero.
    let largest = (0..n).map(|i| (v_now[i] / units.velocity[i]).abs()).fold(0.0, f64::max);
    let mut rest = projected;
    for i in 0..n {
        if (rest[i] / units.velocity[i]).abs() <= 64.0 * f64::EPSILON * largest {
            rest[i] = 0.0;
        }
    }
    if worst_row(&a, &rest, &b, 1e3 * options.tolerance).is_none() {
        v.as_mut_slice().copy_from_slice(rest.as_slice());
        return Ok(());
    }
    Err(SimError::InconsistentInitialState {
        equation: format!("velocity constraint `{}`", model.constraint_names()[j]),
        residual,
        iterations: 1,
    })
}

/// The row of `A v + b = 0` furthest beyond `tolerance` times the size of its own terms,
/// `Σ_i |A_ji| (|v_i| + FLOOR |v|∞) + |b_j|` (a test that does not depend on the units of the velocities or of
/// the rows), with its residual; `None` if every row is within it.
fn worst_row(a: &DMatrix<f64>, v: &DVector<f64>, b: &DVector<f64>, tolerance: f64) -> Option<(usize, f64)> {
    let mut worst: Option<(usize, f64, f64)> = None;
    let floor = floor_of(v.amax());
    for j in 0..a.nrows() {
        let (mut sum, mut size) = (b[j], b[j].abs());
        for i in 0..a.ncols() {
            sum += a[(j, i)] * v[i];
            size += a[(j, i)].abs() * (v[i].abs() + floor);
        }
        let excess = sum.abs() / size;
        if sum.is_nan() || sum.abs() > tolerance * size && worst.is_none_or(|(_, _, e)| excess > e) {
            worst = Some((j, sum.abs(), if sum.is_nan() { f64::INFINITY } else { excess }));
        }
    }
    worst.map(|(j, residual, _)| (j, residual))
}

/// λ from the differentiated constraints, with the accelerations as by-product: by the
/// sparse saddle-point system on the `saddle_path`, else densely.
fn multipliers<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
    free: usize,
    saddle_path: bool,
) -> Result<DVector<f64>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let Sizes { nq: n, nc: m, .. } = model.sizes();
    let (top, bottom) = rates(model, t, q, v)?;
    let shape = model.shape();
    let (mut lvv, mut a) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_cq(&shape));
    model.l_vv(t, q, v, &mut lvv);
    non_finite_qq(model, t, "the mass matrix L_vv", &lvv)?;
    model.constraint_matrix(t, q, &mut a);
    non_finite_entry(model, t, "the constraint rows A(q)", M::Algebra::cq_values(&a), false)?;
    // Friction that pushes with a contact force makes the balance's rows `B = A + (B − A)`:
    // solved densely.
    let saddle_path = saddle_path && !M::NON_ASSOCIATED;
    let lambda = if saddle_path && free > 0 {
        DVector::from_vec(init_saddle::free_multipliers(model, t, (q, v), (&top, &bottom))?)
    } else if saddle_path {
        DVector::from_vec(init_saddle::multipliers(model, t, (q, v), (&top, &bottom))?)
    } else {
        let a = dense_cq::<M, M::Algebra>(&a, m, n);
        let b = if M::NON_ASSOCIATED {
            let mut slip = M::Algebra::zeros_cq(&shape);
            model.slip_rows(t, q, v, &mut slip);
            non_finite_entry(model, t, "the slip rows B − A", M::Algebra::cq_values(&slip), false)?;
            Some(&a + dense_cq::<M, M::Algebra>(&slip, m, n))
        } else {
            None
        };
        dense_multipliers(
            model,
            t,
            &dense_qq::<M, M::Algebra>(&lvv, n),
            (&a, b.as_ref()),
            (&top, &bottom),
            free,
        )?
    };
    if let Some(j) = lambda.iter().position(|x| !x.is_finite()) {
        let component = format!("multiplier `{}`", model.constraint_names()[j]);
        return Err(SimError::NonFinite { t, component });
    }
    Ok(lambda)
}

/// λ from the dense saddle-point system, by a singular value decomposition that names the
/// cause when it is singular. Its null space may hold the `free` directions of
/// `ker L_vv ∩ ker A` in `v̇` (velocities the forces fix): they leave `λ` unique, and the
/// minimal-norm solution takes it. The balance reads the constraint forces `Bᵀλ`, with `B`
/// the second of `(a, b)` where friction pushes with a contact force, `A` otherwise.
fn dense_multipliers<M: LagrangeDirac>(
    model: &M,
    t: f64,
    lvv: &DMatrix<f64>,
    (a, b): (&DMatrix<f64>, Option<&DMatrix<f64>>),
    (top, bottom): (&[f64], &[f64]),
    free: usize,
) -> Result<DVector<f64>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (lvv.nrows(), a.nrows());
    // In the model's own units, so that a small inertia counts as inertia.
    let units = Units::of(lvv, a);
    let a_scaled = units.a(a);
    let b = b.unwrap_or(a);
    let b_scaled = units.a(b);
    let mut kkt = DMatrix::zeros(n + m, n + m);
    kkt.view_mut((0, 0), (n, n)).copy_from(&units.lvv(lvv));
    kkt.view_mut((0, n), (n, m)).copy_from(&(-b_scaled.transpose()));
    kkt.view_mut((n, 0), (m, n)).copy_from(&a_scaled);
    let mut rhs = DVector::zeros(n + m);
    for i in 0..n {
        rhs[i] = units.velocity[i] * top[i];
    }
    for j in 0..m {
        rhs[n + j] = units.row[j] * bottom[j];
    }
    let singular = || SimError::NotDetermined { t, cause: cause_of(model, lvv, a) };
    let Some(svd) = svd(&kkt) else {
        return Err(singular());
    };
    let largest = svd.singular_values.max().max(1e-300);
    let null = svd.singular_values.iter().filter(|&&x| x <= 1e-12 * largest).count();
    // Redundant rows (`ker Aᵀ`, in the rows' units) leave the multipliers' part along them
    // undetermined, as the free directions leave the accelerations'.
    let redundant = if m == 0 { None } else { null_space(&b_scaled.transpose(), 1e-10) };
    // A row that is zero by itself (its one-form vanishes here) is undetermined, not redundant.
    let vanishing =
        redundant.as_ref().is_some_and(|z| z.row_iter().any(|row| row.norm_squared() > 1.0 - 1e-9));
    let dependent = if vanishing { 0 } else { redundant.as_ref().map_or(0, |z| z.ncols()) };
    // Friction on redundant contact forces (a box's corners on the ground, slipping apart): how
    // they share the load changes the friction and so the accelerations, and `B`'s rows need
    // not be redundant where `A`'s are. They share it without part along `ker Aᵀ`, as a
    // deflated factorisation does.
    let sharing = null > free + dependent
        && !std::ptr::eq(a, b)
        && null_space(&a_scaled.transpose(), 1e-10)
            .is_some_and(|z| z.ncols() > 0 && z.row_iter().all(|row| row.norm_squared() <= 1.0 - 1e-9));
    let lambda = if sharing {
        let x = deflated_solve(&kkt, &rhs, n, &a.transpose(), units.row.as_slice()).ok_or_else(singular)?;
        return Ok(DVector::from_fn(m, |j, _| units.row[j] * x[n + j]));
    } else if null <= free + dependent {
        let x = svd.solve(&rhs, 1e-12 * largest).expect("SVD with both factors computed");
        DVector::from_fn(m, |j, _| units.row[j] * x[n + j])
    } else {
        // Singular in the model's own units is singular in the units it is written in too,
        // unless the scaling made it so: a velocity whose inertia the constraints hold to a
        // sliver (a floating base's rotation rates near a turn about an axis) scaled to a unit
        // one. Where the system as written is regular, it decides.
        let mut written = DMatrix::zeros(n + m, n + m);
        written.view_mut((0, 0), (n, n)).copy_from(lvv);
        written.view_mut((0, n), (n, m)).copy_from(&(-b.transpose()));
        written.view_mut((n, 0), (m, n)).copy_from(a);
        let rhs = DVector::from_fn(n + m, |i, _| if i < n { top[i] } else { bottom[i - n] });
        let svd = crate::analysis::diagnose::svd(&written).ok_or_else(singular)?;
        let largest = svd.singular_values.max().max(1e-300);
        if svd.singular_values.iter().filter(|&&x| x <= 1e-12 * largest).count() > free + dependent {
            return Err(singular());
        }
        let x = svd.solve(&rhs, 1e-12 * largest).expect("SVD with both factors computed");
        x.rows(n, m).into_owned()
    };
    if dependent == 0 {
        return Ok(lambda);
    }
    // The multipliers of least norm in the model's units with the same force `Bᵀ λ`: what the
    // integrators' deflated factorisations keep (`algebra::lu::Deflation`).
    let force = b.transpose() * &lambda;
    let aligned = crate::analysis::diagnose::svd(&b.transpose()).ok_or_else(singular)?;
    aligned.solve(&force, 1e-10 * aligned.singular_values.max()).map_err(|_| singular())
}

/// The solution `x = (v̇, λ')` of the acceleration-level system `kkt x = rhs` (`n`
/// velocities, then the multipliers scaled by `row`, `λ = row ∘ λ'`) whose multipliers have
/// no part along `ker Aᵀ` (`at` is `Aᵀ`, `n × m`), in the model's units: where the rows are
/// redundant, the one solution the integrators' deflation keeps. `None` where the equations
/// have no solution or more than one even so.
pub(crate) fn deflated_solve(
    kkt: &DMatrix<f64>,
    rhs: &DVector<f64>,
    n: usize,
    at: &DMatrix<f64>,
    row: &[f64],
) -> Option<DVector<f64>> {
    let size = kkt.ncols();
    let kernel = null_space(at, 1e-10)?;
    let d = kernel.ncols();
    let mut stacked = DMatrix::zeros(size + d, size);
    stacked.view_mut((0, 0), (size, size)).copy_from(kkt);
    let scale = kkt.amax().max(f64::MIN_POSITIVE);
    for k in 0..d {
        for (j, r) in row.iter().enumerate() {
            stacked[(size + k, n + j)] = scale * kernel[(j, k)] * r;
        }
    }
    let mut right = DVector::zeros(size + d);
    right.rows_mut(0, size).copy_from(rhs);
    let decomposition = crate::analysis::diagnose::svd(&stacked)?;
    let largest = decomposition.singular_values.max();
    if decomposition.singular_values.iter().any(|&x| x <= 1e-12 * largest) {
        return None;
    }
    let x = decomposition.solve(&right, 1e-12 * largest).ok()?;
    let residual = (kkt * &x - rhs).amax();
    (residual <= 1e-9 * (scale * x.amax() + rhs.amax())).then_some(x)
}

/// A basis (by columns) of `ker L_vv ∩ ker A`: the velocities that neither inertia nor
/// constraints fix. The kernels are taken in the model's own units ([`Units`]), so that a small
/// inertia is inertia whatever the units: first `Z` spanning `ker A'`, then the kernel of
/// `Zᵀ L' Z`, orthonormal there; the columns are those directions in the model's units,
/// `D_v N'` (not orthonormal in them).
pub(crate) fn free_directions(lvv: &DMatrix<f64>, a: &DMatrix<f64>) -> Option<DMatrix<f64>> {
    let n = lvv.nrows();
    let units = Units::of(lvv, a);
    let (lvv, a) = (units.lvv(lvv), units.a(a));
    let z = if a.nrows() == 0 { DMatrix::identity(n, n) } else { null_space(&a, 1e-10)? };
    if z.ncols() == 0 {
        return Some(z);
    }
    let scaled = if lvv.amax() == 0.0 {
        z
    } else {
        // `L'` has a unit diagonal where there is inertia: its kernel is relative to 1.
        let reduced = z.transpose() * &lvv * &z;
        z * null_space(&reduced, 1e-10)?
    };
    // Entries of round-off size are zeros: in the model's units they would be multiplied by
    // the large scales of small inertias, and move velocities the constraints hold.
    let mut scaled = scaled;
    for mut column in scaled.column_iter_mut() {
        let largest = column.amax();
        column.apply(|x| {
            if x.abs() <= 64.0 * f64::EPSILON * largest {
                *x = 0.0;
            }
        });
    }
    Some(DMatrix::from_fn(n, scaled.ncols(), |i, k| units.velocity[i] * scaled[(i, k)]))
}

/// An orthonormal basis (by columns) of the null space of `a`: the right singular vectors
/// whose singular values are at most `relative` times the largest (all of them when `a` is
/// zero).
fn null_space(a: &DMatrix<f64>, relative: f64) -> Option<DMatrix<f64>> {
    let n = a.ncols();
    // A square matrix, so that the decomposition has a right singular vector per column.
    let rows = a.nrows().max(n);
    let mut square = DMatrix::zeros(rows, n);
    square.view_mut((0, 0), (a.nrows(), n)).copy_from(a);
    let svd = svd(&square)?;
    let v_t = svd.v_t.as_ref().expect("V computed");
    let largest = svd.singular_values.max();
    let columns: Vec<_> = (0..n)
        .filter(|&k| svd.singular_values[k] <= relative * largest)
        .map(|k| v_t.row(k).transpose())
        .collect();
    Some(if columns.is_empty() { DMatrix::zeros(n, 0) } else { DMatrix::from_columns(&columns) })
}

/// `Nᵀ (L_qv − L_vq + F_v) N`: how the momentum balance along the free directions `N`
/// changes with the velocities along them (the terms with third derivatives of `L` left out;
/// they change Newton's rate, not its solution).
pub(crate) fn free_matrix<M: LagrangeDirac>(
    model: &M,
    t: f64,
    (q, v): (&VecQ<M>, &VecQ<M>),
    free: &DMatrix<f64>,
) -> DMatrix<f64>
where
    DefaultAllocator: Storage<M>,
{
    free.transpose() * balance_dv(model, t, (q, v)) * free
}

/// `D = L_qv − L_vq + F_v`, dense: how the momentum balance moves with the velocities.
fn balance_dv<M: LagrangeDirac>(model: &M, t: f64, (q, v): (&VecQ<M>, &VecQ<M>)) -> DMatrix<f64>
where
    DefaultAllocator: Storage<M>,
{
    let (n, shape) = (model.sizes().nq, model.shape());
    let (mut lvq, mut fv) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_qq(&shape));
    model.l_vq(t, q, v, &mut lvq);
    model.force_dv(t, q, v, &mut fv);
    let lvq = dense_qq::<M, M::Algebra>(&lvq, n);
    lvq.transpose() - &lvq + dense_qq::<M, M::Algebra>(&fv, n)
}

/// Solves for the velocities along the free directions `N` of `ker L_vv ∩ ker A` the momentum
/// balance projected on them (step 3 of the module's list); returns the number of such
/// directions. A singular `Nᵀ (L_qv − L_vq + F_v) N` leaves some of them undetermined: the
/// error names their coordinates.
fn algebraic_velocities<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &mut VecQ<M>,
    options: Consistency,
) -> Result<usize, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let Sizes { nq: n, nc: m, .. } = model.sizes();
    let shape = model.shape();
    let (mut lvv, mut a) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_cq(&shape));
    model.l_vv(t, q, v, &mut lvv);
    non_finite_qq(model, t, "the mass matrix L_vv", &lvv)?;
    model.constraint_matrix(t, q, &mut a);
    let (lvv, a) = (dense_qq::<M, M::Algebra>(&lvv, n), dense_cq::<M, M::Algebra>(&a, m, n));
    let Some(free) = free_directions(&lvv, &a) else {
        return Err(SimError::NonFinite { t, component: "the mass matrix or the constraint rows".into() });
    };
    let k = free.ncols();
    if k == 0 {
        return Ok(0);
    }
    let mut residual = f64::NAN;
    for _ in 0..options.max_iterations {
        // The matrix first: where it is singular, some velocity is not determined, whatever
        // the balance's residual.
        let d = balance_dv(model, t, (q, v));
        let j = free.transpose() * &d * &free;
        let Some(svd) = svd(&j) else {
            return Err(SimError::NonFinite {
                t,
                component: "∂F/∂v along the velocities without inertia".into(),
            });
        };
        let largest = svd.singular_values.max();
        if svd.singular_values.min() <= 1e-12 * largest || largest == 0.0 {
            let v_t = svd.v_t.as_ref().expect("V computed");
            let direction = &free * v_t.row(svd.singular_values.imin()).transpose();
            return Err(SimError::NotDetermined { t, cause: undetermined_velocities(model, &direction) });
        }
        let (top, _) = rates(model, t, q, v)?;
        let top = DVector::from_vec(top);
        let r = free.transpose() * &top;
        // The size of the terms each projected balance is made of (the forces cancel there:
        // a source's current against its resistor's), for a test relative to them:
        // `|N|ᵀ (|balance| + |F| + |D| |v|)`, the last the size of each velocity's force.
        let mut force = model.sizes().zeros_q::<M>();
        model.force(t, q, v, &mut force);
        let flows = d.abs() * DVector::from_iterator(n, v.iter().map(|x| x.abs()));
        let floor = floor_of(top.amax().max(force.amax()).max(flows.amax()));
        let terms = DVector::from_fn(n, |i, _| top[i].abs() + force[i].abs() + flows[i] + floor);
        let scale = free.abs().transpose() * terms;
        residual = r.amax();
        if r.iter().zip(scale.iter()).all(|(r, s)| r.abs() <= 1e2 * options.tolerance * s) {
            return Ok(k);
        }
        let y = svd.solve(&r, 0.0).expect("SVD with both factors computed");
        let step = &free * y;
        for i in 0..n {
            v[i] -= step[i];
        }
        if let Some(i) = v.iter().position(|x| !x.is_finite()) {
            let component = format!("velocity `{}` of the momentum balance", model.velocity_names()[i]);
            return Err(SimError::NonFinite { t, component });
        }
    }
    let worst = free.column_iter().map(|c| c.iamax()).next().unwrap_or(0);
    Err(SimError::InconsistentInitialState {
        equation: format!(
            "the momentum balance of `{}` (its velocity has no inertia and is fixed by the forces)",
            model.coordinate_names()[worst]
        ),
        residual,
        iterations: options.max_iterations,
    })
}

/// The message for a direction of velocities that nothing determines.
pub(crate) fn undetermined_velocities<M: LagrangeDirac>(model: &M, direction: &DVector<f64>) -> String
where
    DefaultAllocator: Storage<M>,
{
    let largest = direction.amax();
    let names = model.coordinate_names();
    let picked: Vec<String> = (direction.iter().enumerate())
        .filter(|(_, z)| z.abs() > 0.3 * largest)
        .map(|(i, _)| format!("`{}`", names[i]))
        .collect();
    format!(
        "the velocity of {} is not determined: along this motion there is no inertia (L_vv), no \
         constraint, and no force or dissipation that depends on it (∂F/∂v)",
        picked.join(", ")
    )
}

#[cfg(test)]
mod tests {
    use nalgebra::{DMatrix, DVector};

    use super::deflated_solve;

    /// A unit mass in the plane held at `y = 0` by two identical rows (a box's two corners on
    /// the ground, seen from the side), friction on each row's force pushing along `x`
    /// (`B = A + (B − A)`: `0.3 λ_1` and `−0.2 λ_2`), under gravity `g`. The rows leave
    /// `λ_1 + λ_2 = g` and nothing else; without part along `ker Aᵀ = (1, −1)` the two share
    /// it, `λ_1 = λ_2 = g/2`, and `ẍ = 0.3 g/2 − 0.2 g/2 = 0.05 g`: worked by hand.
    #[test]
    fn redundant_rows_with_friction_share_their_load_evenly() {
        let g = 9.81;
        let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, 1.0]);
        let b = DMatrix::from_row_slice(2, 2, &[0.3, 1.0, -0.2, 1.0]);
        let mut kkt = DMatrix::zeros(4, 4);
        kkt.view_mut((0, 0), (2, 2)).fill_with_identity();
        kkt.view_mut((0, 2), (2, 2)).copy_from(&(-b.transpose()));
        kkt.view_mut((2, 0), (2, 2)).copy_from(&a);
        let rhs = DVector::from_row_slice(&[0.0, -g, 0.0, 0.0]);
        assert!(kkt.clone().lu().solve(&rhs).is_none_or(|x| !x.iter().all(|x: &f64| x.is_finite())));
        let x = deflated_solve(&kkt, &rhs, 2, &a.transpose(), &[1.0, 1.0]).expect("a solution");
        let expected = [0.05 * g, 0.0, g / 2.0, g / 2.0];
        for (x, e) in x.iter().zip(expected) {
            assert!((x - e).abs() < 1e-12 * g, "{x} against {e}");
        }
        // Scaled multipliers (`λ = row ∘ λ'`) share the load in the model's units all the same.
        let row = [2.0, 0.5];
        let mut scaled = kkt.clone();
        for (j, r) in row.iter().enumerate() {
            for i in 0..2 {
                scaled[(i, 2 + j)] *= r;
            }
        }
        let x = deflated_solve(&scaled, &rhs, 2, &a.transpose(), &row).expect("a solution");
        assert!((row[0] * x[2] - g / 2.0).abs() < 1e-12 * g && (row[1] * x[3] - g / 2.0).abs() < 1e-12 * g);
    }
}
