//! Finding the true cause of a failure, for the messages of typed errors: which parameter or
//! state component is not finite, which algebraic equation a state violates, and why a
//! consistency or Newton matrix is singular (a coordinate without inertia or constraint, a
//! vanishing or dependent constraint). Failure paths only: these functions allocate.

use nalgebra::{DMatrix, DefaultAllocator, SVD};

use crate::algebra::{Algebra, dense_cq, dense_qq};
use crate::analysis::floors::floor_of;
use crate::error::SimError;
use crate::model::state::State;
use crate::model::{LagrangeDirac, MatCQ};
use crate::shape::dims::{Sizes, Storage, VecC, VecH, VecQ};
use crate::shape::layout::{Layout, Slot, Unknown, Unknowns};

/// The most unknowns `n + m` for which failures are analysed with dense matrices.
pub(crate) const DENSE_ANALYSIS: usize = 2000;
/// Above this many unknowns a sparse model whose saddle-point matrix factors (every velocity
/// fixed by inertia or constraints) is started by the sparse path.
pub(crate) const SPARSE_ANALYSIS: usize = 200;

/// The singular value decomposition of `a` with a bounded number of iterations: `None` if it
/// did not converge (it always does for finite input; the bound keeps NaN from looping).
pub(crate) fn svd(a: &DMatrix<f64>) -> Option<SVD<f64, nalgebra::Dyn, nalgebra::Dyn>> {
    if !a.iter().all(|x| x.is_finite()) {
        return None;
    }
    // nalgebra's default tolerance, with a bound on the iterations.
    SVD::try_new(a.clone(), true, true, 5.0 * f64::EPSILON, 10_000)
}

/// Slot `i` of `model`'s state in words, for messages: "coordinate `x`", "momentum of `x`".
pub fn describe_slot<M: LagrangeDirac>(model: &M, i: usize) -> String
where
    DefaultAllocator: Storage<M>,
{
    match Layout::new(model.sizes()).slot(i) {
        Slot::Position(k) => format!("coordinate `{}`", model.coordinate_names()[k]),
        Slot::Velocity(k) => format!("velocity `{}`", model.velocity_names()[k]),
        Slot::Momentum(k) => format!("momentum of `{}`", model.coordinate_names()[k]),
        Slot::Multiplier(k) => format!("multiplier `{}`", model.constraint_names()[k]),
    }
}

/// A typed error naming the first component of `state` that is NaN or infinite.
pub fn check_finite_state<M: LagrangeDirac>(model: &M, t: f64, state: &State<M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    match state.components().position(|x| !x.is_finite()) {
        Some(i) => Err(SimError::NonFinite { t, component: describe_slot(model, i) }),
        None => Ok(()),
    }
}

/// The first entry of a vector that is NaN or infinite, named: `∂L/∂q at coordinate `y``
/// when `per_coordinate` (a vector over the coordinates), else just `what`.
pub(crate) fn non_finite_entry<M: LagrangeDirac>(
    model: &M,
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
    let component = if per_coordinate {
        format!("{what} at coordinate `{}`", model.coordinate_names()[k])
    } else {
        what.to_owned()
    };
    Err(SimError::NonFinite { t, component })
}

/// The first entry of an `n × n` block that is NaN or infinite, named by its row's
/// coordinate: `the mass matrix L_vv at coordinate `y``.
pub(crate) fn non_finite_qq<M: LagrangeDirac>(
    model: &M,
    t: f64,
    what: &str,
    block: &<M::Algebra as Algebra<M>>::Qq,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let mut row = None;
    M::Algebra::qq_entries(block, |i, _, x| {
        if row.is_none() && !x.is_finite() {
            row = Some(i);
        }
    });
    match row {
        None => Ok(()),
        Some(i) => Err(SimError::NonFinite {
            t,
            component: format!("{what} at coordinate `{}`", model.coordinate_names()[i]),
        }),
    }
}

/// The algebraic equation that `state` violates the most beyond `tolerance` (relative to the
/// size of the terms it is made of, row by row: `Σ_i |A_ji| (|q_i| + ρ |q|∞)` for `φ(q, t) = 0`,
/// `Σ_i |A_ji| (|v_i| + ρ |v|∞) + |b_j|` for `A(q, t) v + b(q, t) = 0`, `|p_i| + ρ |p|∞` for
/// the Legendre map `p = ∂L/∂v`, with `ρ` a small fraction: a test that does not depend on the
/// units), with its residual.
pub fn violated_equation<M: LagrangeDirac>(
    model: &M,
    t: f64,
    state: &State<M>,
    tolerance: f64,
) -> Option<(String, f64)>
where
    DefaultAllocator: Storage<M>,
{
    let (holonomic, velocity) = constraint_residuals(model, t, state);
    if let Some((j, r, _)) = holonomic.filter(|w| w.2 > tolerance || w.2.is_nan()) {
        return Some((format!("holonomic constraint `{}`", model.constraint_names()[j]), r));
    }
    if let Some((j, r, _)) = velocity.filter(|w| w.2 > tolerance || w.2.is_nan()) {
        return Some((format!("velocity constraint `{}`", model.constraint_names()[j]), r));
    }
    violated_legendre_map(model, t, state, tolerance)
}

/// The largest residual of `φ(q, t) = 0` and of `A(q, t) v + b(q, t) = 0` at `state`, each as
/// its row, the residual, and the residual relative to the size of the terms it is made of
/// (see [`violated_equation`]). Allocates nothing for a dense model.
fn constraint_residuals<M: LagrangeDirac>(
    model: &M,
    t: f64,
    state: &State<M>,
) -> (Option<Worst>, Option<Worst>)
where
    DefaultAllocator: Storage<M>,
{
    constraint_residuals_in(model, t, state, &mut CheckRoom::new(model))
}

/// [`constraint_residuals`] in room made beforehand: allocates nothing.
fn constraint_residuals_in<M: LagrangeDirac>(
    model: &M,
    t: f64,
    state: &State<M>,
    room: &mut CheckRoom<M>,
) -> (Option<Worst>, Option<Worst>)
where
    DefaultAllocator: Storage<M>,
{
    let CheckRoom { phi, a, av, sizes_h, sizes_c, .. } = room;
    model.holonomic(t, &state.q, phi);
    model.constraint_matrix(t, &state.q, a);
    model.constraint_rate(t, &state.q, av);
    // Each row against the size of its own terms (in units of the row's own), the positions
    // and velocities below a fraction of the largest measured against that fraction.
    let (q_floor, v_floor) = (floor_of(state.q.amax()), floor_of(state.v.amax()));
    let nh = sizes_h.len();
    sizes_h.fill(0.0);
    sizes_c.iter_mut().zip(av.iter()).for_each(|(s, b)| *s = b.abs());
    M::Algebra::cq_entries(a, |row, column, value| {
        if row < nh {
            sizes_h[row] += value.abs() * (state.q[column].abs() + q_floor);
        }
        sizes_c[row] += value.abs() * (state.v[column].abs() + v_floor);
    });
    M::Algebra::cq_mul(a, 1.0, state.v.as_slice(), av.as_mut_slice());
    (relative_worst(phi.as_slice(), sizes_h.as_slice()), relative_worst(av.as_slice(), sizes_c.as_slice()))
}

/// The residual furthest beyond its row's size (a NaN first), as its row, the residual and
/// their ratio (infinite where the size is zero and the residual is not).
fn relative_worst(residuals: &[f64], sizes: &[f64]) -> Option<Worst> {
    let mut best: Option<Worst> = None;
    for (j, (&r, &size)) in residuals.iter().zip(sizes).enumerate() {
        let r = r.abs();
        let ratio = if r.is_nan() {
            f64::NAN
        } else if r == 0.0 {
            0.0
        } else if size == 0.0 {
            f64::INFINITY
        } else {
            r / size
        };
        match best {
            Some((_, _, b)) if b.is_nan() || (!ratio.is_nan() && b >= ratio) => {}
            _ => best = Some((j, r, ratio)),
        }
    }
    best
}

/// The vectors and the constraint matrix the checks of a restart evaluate into, made once with
/// an integrator, so that a restart of a model stored on the heap allocates nothing.
pub(crate) struct CheckRoom<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    phi: VecH<M>,
    a: MatCQ<M>,
    av: VecC<M>,
    dl_dv: VecQ<M>,
    /// The sizes of the holonomic and of the velocity rows' terms.
    sizes_h: VecH<M>,
    sizes_c: VecC<M>,
}

impl<M: LagrangeDirac> CheckRoom<M>
where
    DefaultAllocator: Storage<M>,
{
    pub(crate) fn new(model: &M) -> CheckRoom<M> {
        let sizes = model.sizes();
        CheckRoom {
            phi: sizes.zeros_h::<M>(),
            a: M::Algebra::zeros_cq(&model.shape()),
            av: sizes.zeros_c::<M>(),
            dl_dv: sizes.zeros_q::<M>(),
            sizes_h: sizes.zeros_h::<M>(),
            sizes_c: sizes.zeros_c::<M>(),
        }
    }
}

/// A constraint's row, its residual, and the residual relative to its terms' size.
type Worst = (usize, f64, f64);

/// The constraint that `state` violates the most relative to the size of its terms (as in
/// [`violated_equation`]); `None` for a model without constraints.
pub(crate) fn worst_constraint<M: LagrangeDirac>(
    model: &M,
    t: f64,
    state: &State<M>,
    room: &mut CheckRoom<M>,
) -> Option<Worst>
where
    DefaultAllocator: Storage<M>,
{
    if model.sizes().nc == 0 {
        return None;
    }
    match constraint_residuals_in(model, t, state, room) {
        (Some(h), Some(v)) => Some(if h.2.is_nan() || h.2 >= v.2 { h } else { v }),
        (h, v) => h.or(v),
    }
}

/// An error if a change of the model between steps moved a constraint off the state: its
/// violation relative to its terms' size went from `before` to beyond `1e-8 + 2 before`. A
/// prescribed motion (a constraint that depends on an input or a parameter) cannot jump.
pub(crate) fn check_constraints_kept<M: LagrangeDirac>(
    model: &M,
    t: f64,
    state: &State<M>,
    before: f64,
    room: &mut CheckRoom<M>,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    match worst_constraint(model, t, state, room) {
        Some((j, residual, relative)) if relative.is_nan() || relative > 1e-8 + 2.0 * before => {
            let kind = if j < model.sizes().nh { "holonomic" } else { "velocity" };
            let equation = format!("{kind} constraint `{}`", model.constraint_names()[j]);
            Err(SimError::ConstraintMoved { t, equation, residual })
        }
        _ => Ok(()),
    }
}

/// The momentum `p = ∂L/∂v` that `state` violates most beyond `tolerance` (relative to the
/// momenta's size), and by how much: what a change of the model while it runs may break.
pub fn violated_legendre_map<M: LagrangeDirac>(
    model: &M,
    t: f64,
    state: &State<M>,
    tolerance: f64,
) -> Option<(String, f64)>
where
    DefaultAllocator: Storage<M>,
{
    violated_legendre_map_in(model, t, state, (tolerance, |_, _| 0.0), &mut CheckRoom::new(model))
}

/// [`violated_legendre_map`] in room made beforehand: allocates nothing unless it finds one.
/// Momentum `i` of value `p` may also miss by `slack(i, p)`: the accuracy to which the
/// integrator that reached `state` solved the map (its Newton iteration's error weight).
pub(crate) fn violated_legendre_map_in<M: LagrangeDirac>(
    model: &M,
    t: f64,
    state: &State<M>,
    (tolerance, slack): (f64, impl Fn(usize, f64) -> f64),
    room: &mut CheckRoom<M>,
) -> Option<(String, f64)>
where
    DefaultAllocator: Storage<M>,
{
    let dl_dv = &mut room.dl_dv;
    model.dl_dv(t, &state.q, &state.v, dl_dv);
    // Each momentum against its own size, those below a fraction of the largest against that.
    let floor = floor_of(state.p.amax().max(dl_dv.amax()));
    let beyond = state.p.iter().zip(dl_dv.iter()).enumerate().find_map(|(i, (p, l))| {
        let r = (p - l).abs();
        (r.is_nan() || r > tolerance * (p.abs().max(l.abs()) + floor) + slack(i, *p)).then_some((i, r))
    });
    if let Some((i, r)) = beyond {
        let name = &model.coordinate_names()[i];
        return Some((
            format!(
                "the momentum of `{name}` does not match its velocity (the Legendre map p = ∂L/∂v of `{name}`)"
            ),
            r,
        ));
    }
    None
}

/// Why the saddle-point matrix `[L_vv Aᵀ; A 0]` of `model` at `(t, q, v)` is singular: the
/// unknowns its null space moves, read as the cause. For the messages of consistency and
/// Newton failures.
pub fn singular_cause<M: LagrangeDirac>(model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>) -> String
where
    DefaultAllocator: Storage<M>,
{
    let (sizes, shape) = (model.sizes(), model.shape());
    let Sizes { nq: n, nc: m, .. } = sizes;
    if n + m > DENSE_ANALYSIS {
        return format!(
            "the model has {} unknowns, too many to analyse the cause; look for a coordinate without \
             inertia or constraint, or dependent constraints",
            n + m
        );
    }
    let (mut lvv, mut a) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_cq(&shape));
    model.l_vv(t, q, v, &mut lvv);
    model.constraint_matrix(t, q, &mut a);
    cause_of(model, &dense_qq::<M, M::Algebra>(&lvv, n), &dense_cq::<M, M::Algebra>(&a, m, n))
}

/// [`singular_cause`] for the blocks themselves.
pub(crate) fn cause_of<M: LagrangeDirac>(model: &M, lvv: &DMatrix<f64>, a: &DMatrix<f64>) -> String
where
    DefaultAllocator: Storage<M>,
{
    let (n, m) = (lvv.nrows(), a.nrows());
    // In the model's own units, so that the null space's largest entries are the unknowns it
    // moves, whatever their units.
    let units = crate::analysis::units::Units::of(lvv, a);
    let a_scaled = units.a(a);
    let mut kkt = DMatrix::zeros(n + m, n + m);
    kkt.view_mut((0, 0), (n, n)).copy_from(&units.lvv(lvv));
    kkt.view_mut((0, n), (n, m)).copy_from(&a_scaled.transpose());
    kkt.view_mut((n, 0), (m, n)).copy_from(&a_scaled);
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
        let constraints = picked(&dl, &model.constraint_names());
        if constraints.len() == 1 {
            let j = dl.iamax();
            if a.row(j).amax() <= 1e-12 * a.amax().max(1e-300) || a.row(j).amax() == 0.0 {
                return format!(
                    "the row of constraint {} is zero at this state (its ∂φ/∂q or A(q) row, the constraint's \
                     one-form, vanishes), so its force (multiplier) is not determined",
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
    let coordinates = picked(&dv, &model.coordinate_names());
    format!(
        "the velocity of {} is not determined: along this motion there is no inertia (L_vv), no \
         constraint, and no force or dissipation that depends on it (∂F/∂v)",
        coordinates.join(", ")
    )
}

/// The unknown of a condensed system `(x_v, x_λ)` (or of a variational stage, `(v, Λ)`) at
/// `column`, for the message of a singular matrix: "no pivot for the velocity `vx`".
pub fn pivot_name<M: LagrangeDirac>(model: &M, column: usize) -> String
where
    DefaultAllocator: Storage<M>,
{
    match Unknowns::new(model.sizes()).unknown(column) {
        Unknown::Velocity(i) => format!("no pivot for the velocity `{}`", model.velocity_names()[i]),
        Unknown::Multiplier(j) => format!("no pivot for the multiplier `{}`", model.constraint_names()[j]),
    }
}

/// An error if the inertia `L_vv` at `(t, q, v)` is not positive semi-definite: along some
/// motion the kinetic energy is negative (a negative mass or capacitance), which no physical
/// model has. A degenerate inertia (zero along some motion) passes.
///
/// A dense model's is decided on its eigenvalues in the model's own units ([`Units`]: unit
/// inertia wherever there is some), so that a small inertia is not taken for round-off: an
/// eigenvalue below `−1e-9` of the largest is negative. A sparse model's, on its diagonal and
/// its 2 × 2 principal minors (`L_ii ≥ 0`, `L_ij² ≤ L_ii L_jj`), which catch a negative part
/// in a network at a cost linear in its size.
pub(crate) fn check_inertia<M: LagrangeDirac>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (sizes, shape) = (model.sizes(), model.shape());
    let n = sizes.nq;
    let mut lvv = M::Algebra::zeros_qq(&shape);
    model.l_vv(t, q, v, &mut lvv);
    if M::Algebra::qq_values(&lvv).iter().any(|x| !x.is_finite()) {
        return Ok(());
    }
    let names = model.coordinate_names();
    let negative = |coordinates: Vec<usize>, detail: String| SimError::NegativeInertia {
        t,
        coordinates: coordinates.iter().map(|&i| format!("`{}`", names[i])).collect::<Vec<_>>().join(", "),
        detail,
    };
    if M::Algebra::dense_qq(&lvv).is_none() {
        let mut diagonal = vec![0.0; n];
        M::Algebra::qq_entries(&lvv, |row, column, value| {
            if row == column {
                diagonal[row] += value;
            }
        });
        if let Some(i) = (0..n).find(|&i| diagonal[i] < 0.0) {
            return Err(negative(vec![i], format!("∂²L/∂v² has {:e} on its diagonal there", diagonal[i])));
        }
        let mut found = None;
        M::Algebra::qq_entries(&lvv, |row, column, value| {
            if row < column
                && found.is_none()
                && value * value > (1.0 + 1e-9) * diagonal[row] * diagonal[column]
            {
                found = Some((row, column));
            }
        });
        return match found {
            Some((i, j)) => {
                Err(negative(vec![i, j], "a 2 × 2 principal minor of ∂²L/∂v² is negative".into()))
            }
            None => Ok(()),
        };
    }
    let mut a = M::Algebra::zeros_cq(&shape);
    model.constraint_matrix(t, q, &mut a);
    let (lvv, a) = (dense_qq::<M, M::Algebra>(&lvv, n), dense_cq::<M, M::Algebra>(&a, sizes.nc, n));
    if !a.iter().all(|x| x.is_finite()) || n == 0 {
        return Ok(());
    }
    let units = crate::analysis::units::Units::of(&lvv, &a);
    let scaled = units.lvv(&lvv);
    let scaled = (&scaled + scaled.transpose()) * 0.5;
    let eigen = nalgebra::SymmetricEigen::new(scaled);
    let (k, least) = eigen.eigenvalues.argmin();
    let largest = eigen.eigenvalues.amax().max(1.0);
    if least >= -1e-9 * largest {
        return Ok(());
    }
    let direction = eigen.eigenvectors.column(k);
    let biggest = direction.amax();
    let moved: Vec<usize> = (0..n).filter(|&i| direction[i].abs() > 0.3 * biggest).collect();
    Err(negative(
        moved,
        format!("an eigenvalue of {least:.3e} in the model's own units, where its inertia is 1"),
    ))
}
