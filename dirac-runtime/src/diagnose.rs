//! Finding the true cause of a failure, for the messages of typed errors: which parameter or
//! state component is not finite, which algebraic equation a state violates, and why a
//! consistency or Newton matrix is singular (a coordinate without inertia or constraint, a
//! vanishing or dependent constraint). Failure paths only: these functions allocate.

use nalgebra::{DMatrix, DefaultAllocator, SVD};

use crate::dims::{MatCQ, MatQQ, Storage, VecH, VecQ};
use crate::error::SimError;
use crate::layout::Layout;
use crate::model::LagrangeDirac;
use crate::state::State;

/// A copy of a stack matrix on the heap.
pub(crate) fn dense<R: nalgebra::Dim, C: nalgebra::Dim, S: nalgebra::RawStorage<f64, R, C>>(
    m: &nalgebra::Matrix<f64, R, C, S>,
) -> DMatrix<f64> {
    DMatrix::from_fn(m.nrows(), m.ncols(), |i, j| m[(i, j)])
}

/// The singular value decomposition of `a` with a bounded number of iterations: `None` if it
/// did not converge (it always does for finite input; the bound keeps NaN from looping).
pub(crate) fn svd(a: &DMatrix<f64>) -> Option<SVD<f64, nalgebra::Dyn, nalgebra::Dyn>> {
    if !a.iter().all(|x| x.is_finite()) {
        return None;
    }
    // nalgebra's default tolerance, with a bound on the iterations.
    SVD::try_new(a.clone(), true, true, 5.0 * f64::EPSILON, 10_000)
}

/// A typed error naming the first component of `state` that is NaN or infinite.
pub fn check_finite_state<M: LagrangeDirac>(t: f64, state: &State<M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    match state.components().position(|x| !x.is_finite()) {
        Some(i) => Err(SimError::NonFinite { t, component: Layout::<M>::describe(i) }),
        None => Ok(()),
    }
}

/// The first entry of a block that is NaN or infinite, named: `∂L/∂q of `y``.
pub(crate) fn non_finite_entry<M: LagrangeDirac>(
    t: f64,
    what: &str,
    values: &[f64],
    per_coordinate: bool,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let Some(k) = values.iter().position(|x| !x.is_finite()) else {
        return Ok(());
    };
    let component = if per_coordinate && M::NQ > 0 {
        format!("{what} at coordinate `{}`", M::coordinate_names()[k % M::NQ])
    } else {
        what.to_owned()
    };
    Err(SimError::NonFinite { t, component })
}

/// The algebraic equation that `state` violates the most beyond `tolerance` (relative to the
/// size of the terms it is made of: `|A| (1 + |q|)` for `φ(q) = 0`, `|A| (1 + |v|)` for
/// `A(q) v = 0`, `1 + |p| + |∂L/∂v|` for the Legendre map `p = ∂L/∂v`), with its residual.
pub fn violated_equation<M: LagrangeDirac>(
    model: &M,
    t: f64,
    state: &State<M>,
    tolerance: f64,
) -> Option<(String, f64)>
where
    DefaultAllocator: Storage<M>,
{
    let names = M::constraint_names();
    let mut phi = VecH::<M>::zeros();
    model.holonomic(&state.q, &mut phi);
    let mut a = MatCQ::<M>::zeros();
    model.constraint_matrix(&state.q, &mut a);
    // Residuals against the size of the terms they are made of: φ / |A| is a distance in q.
    let size_a = a.amax();
    let q_scale = size_a * (1.0 + state.q.amax());
    if let Some((j, r)) = worst(phi.iter().copied()).filter(|(_, r)| *r > tolerance * q_scale) {
        return Some((format!("holonomic constraint `{}`", names[j]), r));
    }
    let av = a * &state.v;
    let v_scale = size_a * (1.0 + state.v.amax());
    if let Some((j, r)) = worst(av.iter().copied()).filter(|(_, r)| *r > tolerance * v_scale) {
        return Some((format!("velocity constraint `{}`", names[j]), r));
    }
    let mut dl_dv = VecQ::<M>::zeros();
    model.dl_dv(t, &state.q, &state.v, &mut dl_dv);
    let p_scale = 1.0 + state.p.amax().max(dl_dv.amax());
    let gap = &state.p - &dl_dv;
    if let Some((i, r)) = worst(gap.iter().copied()).filter(|(_, r)| *r > tolerance * p_scale) {
        return Some((format!("Legendre map p = ∂L/∂v of `{}`", M::coordinate_names()[i]), r));
    }
    None
}

/// The index and size of the largest entry in absolute value.
fn worst(values: impl Iterator<Item = f64>) -> Option<(usize, f64)> {
    values.map(f64::abs).enumerate().fold(None, |best, (i, x)| match best {
        Some((_, b)) if b >= x => best,
        _ => Some((i, x)),
    })
}

/// Why the saddle-point matrix `[L_vv Aᵀ; A 0]` of `model` at `(t, q, v)` is singular: the
/// unknowns its null space moves, read as the cause. For the messages of consistency and
/// Newton failures.
pub fn singular_cause<M: LagrangeDirac>(model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>) -> String
where
    DefaultAllocator: Storage<M>,
{
    let (mut lvv, mut a) = (MatQQ::<M>::zeros(), MatCQ::<M>::zeros());
    model.l_vv(t, q, v, &mut lvv);
    model.constraint_matrix(q, &mut a);
    cause_of(&dense(&lvv), &dense(&a))
}

/// [`singular_cause`] for the blocks themselves.
pub(crate) fn cause_of<M: LagrangeDirac>(lvv: &DMatrix<f64>, a: &DMatrix<f64>) -> String
where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (M::NQ, M::NC);
    let mut kkt = DMatrix::zeros(n + m, n + m);
    kkt.view_mut((0, 0), (n, n)).copy_from(lvv);
    kkt.view_mut((0, n), (n, m)).copy_from(&a.transpose());
    kkt.view_mut((n, 0), (m, n)).copy_from(a);
    let Some(svd) = svd(&kkt) else {
        return "the matrix holds values that are not finite".to_owned();
    };
    let v_t = svd.v_t.as_ref().expect("V computed");
    let null = v_t.row(svd.singular_values.imin()).transpose();
    let (dv, dl) = (null.rows(0, n), null.rows(n, m));
    let largest = null.amax().max(f64::MIN_POSITIVE);
    let picked = |x: &nalgebra::DVectorView<'_, f64>, names: &[String]| -> Vec<String> {
        x.iter()
            .enumerate()
            .filter(|(_, z)| z.abs() > 0.3 * largest)
            .map(|(i, _)| format!("`{}`", names[i]))
            .collect()
    };
    if dl.amax() >= dv.amax() {
        let constraints = picked(&dl, &M::constraint_names());
        if constraints.len() == 1 {
            let j = dl.iamax();
            if a.row(j).amax() <= 1e-12 * a.amax().max(1e-300) || a.row(j).amax() == 0.0 {
                return format!(
                    "the one-form of constraint {} is zero at this state (its ∂φ/∂q or A(q) row vanishes), \
                     so its multiplier is not determined",
                    constraints[0]
                );
            }
            return format!(
                "the multiplier of constraint {} is not determined at this state",
                constraints[0]
            );
        }
        return format!(
            "the constraints {} are dependent at this state (their one-forms are linearly dependent), \
             so their multipliers are not determined",
            constraints.join(", ")
        );
    }
    let coordinates = picked(&dv, &M::coordinate_names());
    format!(
        "the velocity of {} is not determined: along this motion there is no inertia (L_vv) and no \
         constraint",
        coordinates.join(", ")
    )
}
