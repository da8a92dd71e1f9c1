//! Consistent initial states: from positions and velocities a user chooses, the nearest state
//! that satisfies every algebraic equation of the implicit Lagrange-d'Alembert equations.
//!
//! 1. positions are projected onto `φ(q) = 0` (Gauss-Newton, minimal-norm corrections);
//! 2. velocities are projected onto `A(q) v = 0`, minimising the kinetic-energy norm of the
//!    change, `½ Δvᵀ L_vv Δv`, so that velocities without inertia (a degenerate Lagrangian's)
//!    take up the correction and the others keep the values given;
//! 3. momenta are set by the Legendre map `p = ∂L/∂v`;
//! 4. multipliers (and accelerations) solve the differentiated constraints
//!    `[L_vv −Aᵀ; A 0] [v̇; λ] = [∂L/∂q + F − L_vq v − ∂²L/∂v∂t; −∂(Av)/∂q v]`.
//!
//! Set-up code: it allocates, unlike a step.

use nalgebra::{DMatrix, DVector, DefaultAllocator};

use crate::dims::{MatCQ, MatQQ, Storage, VecH, VecQ};
use crate::error::SimError;
use crate::model::LagrangeDirac;
use crate::state::State;

/// Tolerance and iteration budget of the projections.
#[derive(Clone, Copy, Debug)]
pub struct Consistency {
    /// Largest accepted constraint residual, relative to the size of `q` (or `v`).
    pub tolerance: f64,
    /// Gauss-Newton iterations allowed for `φ(q) = 0`.
    pub max_iterations: usize,
}

impl Default for Consistency {
    fn default() -> Self {
        Consistency { tolerance: 1e-13, max_iterations: 50 }
    }
}

fn dense<R: nalgebra::Dim, C: nalgebra::Dim, S: nalgebra::RawStorage<f64, R, C>>(
    m: &nalgebra::Matrix<f64, R, C, S>,
) -> DMatrix<f64> {
    DMatrix::from_fn(m.nrows(), m.ncols(), |i, j| m[(i, j)])
}

/// The consistent state nearest to positions `q` and velocities `v` at time `t`.
pub fn consistent_state<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
    options: Consistency,
) -> Result<State<M>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let mut s = State::<M>::zeros();
    s.q.copy_from(q);
    s.v.copy_from(v);
    if let Some(j) = s.q.iter().chain(s.v.iter()).position(|x| !x.is_finite()) {
        let names = if j < M::NQ { M::coordinate_names() } else { M::velocity_names() };
        return Err(SimError::NonFinite { t, component: names[j % M::NQ].clone() });
    }
    project_positions(model, &mut s.q, options)?;
    project_velocities(model, t, &s.q, &mut s.v, options)?;
    model.dl_dv(t, &s.q, &s.v, &mut s.p);
    s.lambda.copy_from_slice(multipliers(model, t, &s.q, &s.v)?.as_slice());
    Ok(s)
}

fn project_positions<M: LagrangeDirac>(
    model: &M,
    q: &mut VecQ<M>,
    options: Consistency,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let h = M::NH;
    if h == 0 {
        return Ok(());
    }
    let mut phi = VecH::<M>::zeros();
    let mut a = MatCQ::<M>::zeros();
    for iteration in 0..=options.max_iterations {
        model.holonomic(q, &mut phi);
        let scale = 1.0 + q.amax();
        if phi.amax() <= options.tolerance * scale {
            return Ok(());
        }
        if iteration == options.max_iterations || !phi.iter().all(|x| x.is_finite()) {
            break;
        }
        a.fill(0.0);
        model.constraint_matrix(q, &mut a);
        let ah = dense(&a).rows(0, h).into_owned();
        let correction = min_norm_solve(&ah, &DVector::from_column_slice(phi.as_slice()));
        for i in 0..M::NQ {
            q[i] -= correction[i];
        }
    }
    let (j, residual) =
        phi.iter().enumerate().fold((0, 0.0f64), |b, (j, x)| if x.abs() > b.1 { (j, x.abs()) } else { b });
    Err(SimError::InconsistentInitialState {
        equation: format!("holonomic constraint `{}`", M::constraint_names()[j]),
        residual,
        iterations: options.max_iterations,
    })
}

/// The minimal-norm `x` with `A x = b` (least squares if there is none).
fn min_norm_solve(a: &DMatrix<f64>, b: &DVector<f64>) -> DVector<f64> {
    a.clone().svd(true, true).solve(b, 1e-14 * a.amax().max(1e-300)).expect("SVD with both factors computed")
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
    let (n, m) = (M::NQ, M::NC);
    if m == 0 {
        return Ok(());
    }
    let mut a = MatCQ::<M>::zeros();
    model.constraint_matrix(q, &mut a);
    let a = dense(&a);
    let av = &a * DVector::from_column_slice(v.as_slice());
    if av.amax() <= options.tolerance * (1.0 + v.amax()) {
        return Ok(());
    }
    let mut lvv = MatQQ::<M>::zeros();
    model.l_vv(t, q, v, &mut lvv);
    let w = dense(&lvv);
    // A small multiple of I keeps the problem well posed where L_vv is singular off ker A.
    let reg = 1e-10 * w.amax().max(1.0);
    let mut kkt = DMatrix::zeros(n + m, n + m);
    kkt.view_mut((0, 0), (n, n)).copy_from(&(w + DMatrix::identity(n, n) * reg));
    kkt.view_mut((0, n), (n, m)).copy_from(&a.transpose());
    kkt.view_mut((n, 0), (m, n)).copy_from(&a);
    let mut rhs = DVector::zeros(n + m);
    rhs.rows_mut(n, m).copy_from(&(-av));
    let x = min_norm_solve(&kkt, &rhs);
    for i in 0..n {
        v[i] += x[i];
    }
    let after = &a * DVector::from_column_slice(v.as_slice());
    if after.amax() > 1e3 * options.tolerance * (1.0 + v.amax()) {
        let (j, residual) = after
            .iter()
            .enumerate()
            .fold((0, 0.0f64), |b, (j, x)| if x.abs() > b.1 { (j, x.abs()) } else { b });
        return Err(SimError::InconsistentInitialState {
            equation: format!("velocity constraint `{}`", M::constraint_names()[j]),
            residual,
            iterations: 1,
        });
    }
    Ok(())
}

/// λ from the differentiated constraints, with the accelerations as by-product.
fn multipliers<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
) -> Result<DVector<f64>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (M::NQ, M::NC);
    let (mut dl_dq, mut force) = (VecQ::<M>::zeros(), VecQ::<M>::zeros());
    model.dl_dq(t, q, v, &mut dl_dq);
    model.force(t, q, v, &mut force);
    let (mut lvv, mut lvq) = (MatQQ::<M>::zeros(), MatQQ::<M>::zeros());
    model.l_vv(t, q, v, &mut lvv);
    model.l_vq(t, q, v, &mut lvq);
    let (mut a, mut g) = (MatCQ::<M>::zeros(), MatCQ::<M>::zeros());
    model.constraint_matrix(q, &mut a);
    model.dav_dq(q, v, &mut g);
    let mut lvt = VecQ::<M>::zeros();
    model.l_vt(t, q, v, &mut lvt);

    let mut kkt = DMatrix::zeros(n + m, n + m);
    kkt.view_mut((0, 0), (n, n)).copy_from(&dense(&lvv));
    kkt.view_mut((0, n), (n, m)).copy_from(&(-dense(&a).transpose()));
    kkt.view_mut((n, 0), (m, n)).copy_from(&dense(&a));
    let mut rhs = DVector::zeros(n + m);
    let top = dl_dq + force - lvq * v - lvt;
    rhs.rows_mut(0, n).copy_from(&dense(&top));
    rhs.rows_mut(n, m).copy_from(&(-(dense(&g) * DVector::from_column_slice(v.as_slice()))));
    let svd = kkt.clone().svd(true, true);
    let smallest_at = svd.singular_values.imin();
    let smallest = svd.singular_values[smallest_at];
    let largest = svd.singular_values.max().max(1e-300);
    if smallest <= 1e-12 * largest {
        let names = M::coordinate_names();
        let v_t = svd.v_t.as_ref().expect("V computed");
        let null = v_t.row(smallest_at);
        let worst = (0..n).max_by(|&i, &j| null[i].abs().total_cmp(&null[j].abs())).unwrap_or(0);
        return Err(SimError::InconsistentInitialState {
            equation: format!(
                "momentum balance of `{}`: no inertia and no constraint determine its motion",
                names.get(worst).cloned().unwrap_or_default()
            ),
            residual: smallest / largest,
            iterations: 0,
        });
    }
    let x = svd.solve(&rhs, 0.0).expect("SVD with both factors computed");
    Ok(x.rows(n, m).into_owned())
}
