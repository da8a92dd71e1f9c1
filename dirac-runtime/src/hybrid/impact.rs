//! An impact at unilateral constraints as a map of the state just before it, with its
//! derivative: what carries a sensitivity or an adjoint across the impact, and what a
//! saltation matrix (the linearised jump of a hybrid orbit) is made of.
//!
//! The impact law (see the contacts' module) is linear in the unknowns `u = (Δv, μ, Λ)`, the
//! velocity change, the model's constraint impulses and the contacts' impulses, for the
//! contacts `J` that the impact pushes (`Λ_j > 0`):
//!
//! ```text
//! [H  −Aᵀ  −Cᵀ] [Δv]   [      0      ]      H = ∂²L/∂v², A the model's constraint rows,
//! [A   0    0 ] [μ ] = [      0      ]      C the rows a_j = ∂φ_j/∂q of the contacts in J,
//! [C   0    0 ] [Λ ]   [−(1 + E) C v⁻]      E their restitutions;
//! ```
//!
//! `v⁺ = v⁻ + Δv`. Differentiating it along a change `dx` of `q`, `v⁻`, `t` or a parameter,
//! `K du = −(dK) u + dr`, which takes `∂(H Δv)/∂x`, `∂(Aᵀμ)/∂x`, `∂(A Δv)/∂x` (from the
//! model's own blocks, `H Δv` being `∂L/∂v(v⁺) − ∂L/∂v(v⁻)` for a Lagrangian quadratic in the
//! velocities, which the impact law assumes) and the contacts' second derivatives, which the
//! derive emits ([`Hybrid::unilateral_derivatives`](crate::model::Hybrid::unilateral_derivatives)).

use nalgebra::{DMatrix, DVector, DefaultAllocator};

use crate::algebra::Algebra;
use crate::error::SimError;
use crate::hybrid::contacts::Contacts;
use crate::model::blocks::ResidualBlocks;
use crate::model::state::State;
use crate::model::{Hybrid, Parameters};
use crate::shape::dims::{Storage, VecQ};

/// An impact and its derivative ([`impact_map`]): the velocities after it and how they move
/// with the positions, the velocities before it, the time and the parameters.
#[derive(Clone, Debug)]
pub struct ImpactMap {
    /// The velocities after the impact, `v⁺`.
    pub velocity: DVector<f64>,
    /// Each closing contact (its index among the unilateral constraints) with its impulse
    /// `Λ ≥ 0`: zero for one that was not approaching or that the others opened.
    pub impulses: Vec<(usize, f64)>,
    /// `∂v⁺/∂q`, `n × n`.
    pub dq: DMatrix<f64>,
    /// `∂v⁺/∂v⁻`, `n × n`.
    pub dv: DMatrix<f64>,
    /// `∂v⁺/∂t` (a moving contact or constraint).
    pub dt: DVector<f64>,
    /// `∂v⁺/∂θ`, `n × P`, a column per parameter in the model's order.
    pub dtheta: DMatrix<f64>,
}

/// The impact of `model`'s unilateral constraints `closing` (their indices) at time `t`, at
/// positions `q`, on velocities `v` (before it), by the same law as a simulation's impacts,
/// with its derivative with respect to `q`, `v`, `t` and every parameter.
///
/// Refused with [`SimError::InvalidOption`] for a model whose derive does not emit its
/// contacts' second derivatives (an interconnection); the impact's own errors (a restitution
/// outside `[0, 1]`, an impact that moves nothing) as a simulation reports them; and
/// [`SimError::NotDetermined`] where the law's linear system is singular there, so that its
/// derivative does not exist (redundant constraint rows).
///
/// The guide's section on contacts has a worked example (`dirac::guide`).
pub fn impact_map<M: Hybrid + Parameters>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
    closing: &[usize],
) -> Result<ImpactMap, SimError>
where
    DefaultAllocator: Storage<M>,
{
    if model.unilateral_derivatives_len() == 0 {
        return Err(SimError::InvalidOption {
            what: "impact",
            reason: "the model's contacts have no generated second derivatives (an interconnection's \
                     do not yet): declare the unilateral constraints on a model of its own"
                .into(),
        });
    }
    let sizes = model.sizes();
    let (n, m, k) = (sizes.nq, sizes.nc, model.unilateral_names().len());
    if let Some(j) = closing.iter().find(|&&j| j >= k) {
        return Err(SimError::InvalidOption {
            what: "impact",
            reason: format!("there is no unilateral constraint {j}: the model has {k}"),
        });
    }
    let params = model.parameter_count();
    let mut state = State::<M>::with_sizes(sizes);
    state.q.copy_from(q);
    state.v.copy_from(v);
    let impacts = Contacts::new(model).impact(model, t, &mut state, closing)?;
    let active: Vec<(usize, f64)> = impacts.impulses.iter().copied().filter(|&(_, l)| l > 0.0).collect();
    let mut map = ImpactMap {
        velocity: DVector::from_column_slice(state.v.as_slice()),
        impulses: impacts.impulses,
        dq: DMatrix::zeros(n, n),
        dv: DMatrix::identity(n, n),
        dt: DVector::zeros(n),
        dtheta: DMatrix::zeros(n, params),
    };
    if active.is_empty() {
        return Ok(map);
    }
    let law = Law::new(model, t, q, v, &state.v, &active, k)?;
    let r = active.len();
    let size = n + m + r;

    // Along q_c.
    let dense_qq = |fill: &dyn Fn(&mut crate::model::MatQQ<M>)| dense_qq(model, fill);
    let dense_cq = |fill: &dyn Fn(&mut crate::model::MatCQ<M>)| dense_cq(model, fill);
    let (v_minus, v_plus) = (v, &state.v);
    let mu = law.mu::<M>(sizes);
    let momenta: DMatrix<f64> =
        &dense_qq(&|b| model.l_vq(t, q, v_plus, b)) - &dense_qq(&|b| model.l_vq(t, q, v_minus, b));
    let forces: DMatrix<f64> = dense_qq(&|b| model.datl_dq(t, q, &mu, b));
    let rows: DMatrix<f64> =
        &dense_cq(&|b| model.dav_dq(t, q, v_plus, b)) - &dense_cq(&|b| model.dav_dq(t, q, v_minus, b));
    let mut rhs = DVector::zeros(size);
    for c in 0..n {
        rhs.fill(0.0);
        for i in 0..n {
            let contacts: f64 = law.hessian_column(c).map(|(lambda, h)| lambda * h[i]).sum();
            rhs[i] = -(momenta[(i, c)] - forces[(i, c)] - contacts);
        }
        for i in 0..m {
            rhs[n + i] = -rows[(i, c)];
        }
        for (s, row) in law.contacts.iter().enumerate() {
            let hessian = |x: &[f64]| (0..n).map(|i| row.hessian[i + c * n] * x[i]).sum::<f64>();
            rhs[n + m + s] = -row.de_dq[c] * row.approach
                - (1.0 + row.e) * (hessian(v_minus.as_slice()) + row.moving_dq[c])
                - hessian(law.dv.as_slice());
        }
        law.solve(&mut rhs)?;
        map.dq.column_mut(c).copy_from(&rhs.rows(0, n));
    }

    // Along v⁻_c: only the contacts' law moves.
    for c in 0..n {
        rhs.fill(0.0);
        for (s, row) in law.contacts.iter().enumerate() {
            rhs[n + m + s] = -(1.0 + row.e) * row.a[c];
        }
        law.solve(&mut rhs)?;
        for i in 0..n {
            map.dv[(i, c)] += rhs[i];
        }
    }

    // Along t: ∂A/∂t column by column from ∂(A v + b)/∂t at the unit velocities.
    let rate = |w: &VecQ<M>| {
        let mut out = sizes.zeros_c::<M>();
        model.dav_dt(t, q, w, &mut out);
        out
    };
    let mut unit = sizes.zeros_q::<M>();
    let still = rate(&unit);
    let mut moving_forces = DVector::<f64>::zeros(n);
    for i in 0..n {
        unit[i] = 1.0;
        moving_forces[i] = (rate(&unit) - &still).dot(&mu);
        unit[i] = 0.0;
    }
    let momenta_t = {
        let (mut plus, mut minus) = (sizes.zeros_q::<M>(), sizes.zeros_q::<M>());
        model.l_vt(t, q, v_plus, &mut plus);
        model.l_vt(t, q, v_minus, &mut minus);
        plus - minus
    };
    let rows_t = rate(v_plus) - rate(v_minus);
    let blocks = law.derivatives(0);
    rhs.fill(0.0);
    for i in 0..n {
        let contacts: f64 = blocks.iter().map(|(lambda, d)| lambda * d.a[i]).sum();
        rhs[i] = -(momenta_t[i] - moving_forces[i] - contacts);
    }
    for i in 0..m {
        rhs[n + i] = -rows_t[i];
    }
    law.contact_rows(&blocks, v_minus.as_slice(), &mut rhs, n + m);
    law.solve(&mut rhs)?;
    map.dt.copy_from(&rhs.rows(0, n));

    // Along each parameter: the model's blocks at (v⁺, 0), (v⁻, 0) and (v⁻, μ).
    if params > 0 {
        let zero = sizes.zeros_c::<M>();
        let each = |w: &VecQ<M>, lambda: &crate::shape::dims::VecC<M>| {
            let mut out: Vec<ResidualBlocks<M>> =
                (0..params).map(|_| ResidualBlocks::with_sizes(&sizes)).collect();
            model.residual_blocks_dtheta_all(t, q, w, lambda, &mut out);
            out
        };
        let (plus, minus, pushed) = (each(v_plus, &zero), each(v_minus, &zero), each(v_minus, &mu));
        for p in 0..params {
            let blocks = law.derivatives(p + 1);
            rhs.fill(0.0);
            for i in 0..n {
                let contacts: f64 = blocks.iter().map(|(lambda, d)| lambda * d.a[i]).sum();
                let forces = pushed[p].momentum_rate[i] - minus[p].momentum_rate[i];
                rhs[i] = -(plus[p].dl_dv[i] - minus[p].dl_dv[i] - forces - contacts);
            }
            for i in 0..m {
                rhs[n + i] = -(plus[p].constraint_velocity[i] - minus[p].constraint_velocity[i]);
            }
            law.contact_rows(&blocks, v_minus.as_slice(), &mut rhs, n + m);
            law.solve(&mut rhs)?;
            map.dtheta.column_mut(p).copy_from(&rhs.rows(0, n));
        }
    }
    Ok(map)
}

/// An `n × n` block of `model`, written by `fill`, as a dense matrix.
fn dense_qq<M: Hybrid>(model: &M, fill: &dyn Fn(&mut crate::model::MatQQ<M>)) -> DMatrix<f64>
where
    DefaultAllocator: Storage<M>,
{
    let n = model.sizes().nq;
    let mut block = <M::Algebra as Algebra<M>>::zeros_qq(&model.shape());
    fill(&mut block);
    let mut out = DMatrix::zeros(n, n);
    <M::Algebra as Algebra<M>>::qq_entries(&block, |i, j, x| out[(i, j)] += x);
    out
}

/// An `m × n` block of `model`, written by `fill`, as a dense matrix.
fn dense_cq<M: Hybrid>(model: &M, fill: &dyn Fn(&mut crate::model::MatCQ<M>)) -> DMatrix<f64>
where
    DefaultAllocator: Storage<M>,
{
    let sizes = model.sizes();
    let mut block = <M::Algebra as Algebra<M>>::zeros_cq(&model.shape());
    fill(&mut block);
    let mut out = DMatrix::zeros(sizes.nc, sizes.nq);
    <M::Algebra as Algebra<M>>::cq_entries(&block, |i, j, x| out[(i, j)] += x);
    out
}

/// One pushed contact's part of the law: its row, restitution and approach speed, and what
/// its derivative needs.
struct ContactRow {
    a: Vec<f64>,
    e: f64,
    /// The normal speed before the impact, `a v⁻ + ∂φ/∂t < 0`.
    approach: f64,
    /// `∂²φ/∂t∂q`: how a moving contact's speed changes with the positions.
    moving_dq: Vec<f64>,
    lambda: f64,
    /// `∂²φ/∂q²`, column-major.
    hessian: Vec<f64>,
    de_dq: Vec<f64>,
}

/// The derivatives of one contact's `a`, `e` and `∂φ/∂t` along `t` or a parameter.
struct Along {
    a: Vec<f64>,
    e: f64,
    moving: f64,
}

/// The impact law's linear system at the impact, factored, with its solution.
struct Law {
    t: f64,
    n: usize,
    k: usize,
    params: usize,
    contacts: Vec<ContactRow>,
    /// Which unilateral constraint each of `contacts` is.
    index: Vec<usize>,
    /// The contacts' derivatives as the model emits them.
    derivatives: Vec<f64>,
    lu: nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
    dv: DVector<f64>,
    mu: DVector<f64>,
}

impl Law {
    fn new<M: Hybrid + Parameters>(
        model: &M,
        t: f64,
        q: &VecQ<M>,
        v_minus: &VecQ<M>,
        v_plus: &VecQ<M>,
        active: &[(usize, f64)],
        k: usize,
    ) -> Result<Law, SimError>
    where
        DefaultAllocator: Storage<M>,
    {
        let sizes = model.sizes();
        let (n, m, params) = (sizes.nq, sizes.nc, model.parameter_count());
        let mut rows = vec![0.0; k * n];
        let mut restitution = vec![0.0; k];
        model.unilateral_dq(t, q, &mut rows);
        model.restitution(t, q, &mut restitution);
        let mut derivatives = vec![0.0; model.unilateral_derivatives_len()];
        model.unilateral_derivatives(t, q, &mut derivatives);
        // Along t: ∂φ/∂t, then ∂a/∂t = ∂²φ/∂t∂q.
        let along_t = k * n * n + k * n;
        let contacts: Vec<ContactRow> = active
            .iter()
            .map(|&(j, lambda)| {
                let a: Vec<f64> = (0..n).map(|c| rows[j + c * k]).collect();
                let approach =
                    a.iter().zip(v_minus.iter()).map(|(x, y)| x * y).sum::<f64>() + derivatives[along_t + j];
                ContactRow {
                    approach,
                    moving_dq: (0..n).map(|c| derivatives[along_t + k + j + c * k]).collect(),
                    e: restitution[j],
                    lambda,
                    hessian: derivatives[j * n * n..(j + 1) * n * n].to_vec(),
                    de_dq: (0..n).map(|c| derivatives[k * n * n + j + c * k]).collect(),
                    a,
                }
            })
            .collect();
        let r = contacts.len();
        let shape = model.shape();
        let mut h = <M::Algebra as Algebra<M>>::zeros_qq(&shape);
        model.l_vv(t, q, v_minus, &mut h);
        let mut cm = <M::Algebra as Algebra<M>>::zeros_cq(&shape);
        model.constraint_matrix(t, q, &mut cm);
        let size = n + m + r;
        let mut matrix = DMatrix::<f64>::zeros(size, size);
        <M::Algebra as Algebra<M>>::qq_entries(&h, |i, j, x| matrix[(i, j)] += x);
        <M::Algebra as Algebra<M>>::cq_entries(&cm, |i, j, x| {
            matrix[(j, n + i)] -= x;
            matrix[(n + i, j)] += x;
        });
        for (s, row) in contacts.iter().enumerate() {
            for (c, &x) in row.a.iter().enumerate() {
                matrix[(c, n + m + s)] -= x;
                matrix[(n + m + s, c)] += x;
            }
        }
        let lu = matrix.lu();
        let mut u = DVector::zeros(size);
        for (s, row) in contacts.iter().enumerate() {
            u[n + m + s] = -(1.0 + row.e) * row.approach;
        }
        if !lu.solve_mut(&mut u) || u.iter().any(|x| !x.is_finite()) {
            return Err(singular(t));
        }
        // The law's velocity change is the impact's, to round-off; the impact's own is used.
        let dv = DVector::from_iterator(n, v_plus.iter().zip(v_minus.iter()).map(|(p, m)| p - m));
        let mu = u.rows(n, m).into_owned();
        let index = active.iter().map(|&(j, _)| j).collect();
        Ok(Law { t, n, k, params, contacts, index, derivatives, lu, dv, mu })
    }

    fn mu<M: Hybrid>(&self, sizes: crate::shape::dims::Sizes) -> crate::shape::dims::VecC<M>
    where
        DefaultAllocator: Storage<M>,
    {
        let mut mu = sizes.zeros_c::<M>();
        mu.iter_mut().zip(self.mu.iter()).for_each(|(x, &y)| *x = y);
        mu
    }

    /// Each pushed contact's impulse with column `c` of its Hessian.
    fn hessian_column(&self, c: usize) -> impl Iterator<Item = (f64, &[f64])> {
        let n = self.n;
        self.contacts.iter().map(move |row| (row.lambda, &row.hessian[c * n..(c + 1) * n]))
    }

    /// Each pushed contact's impulse with its derivatives along `x` (0 for `t`, `1 + p` for
    /// parameter `p`).
    fn derivatives(&self, x: usize) -> Vec<(f64, Along)> {
        let (n, k) = (self.n, self.k);
        let block = 2 * k + k * n;
        let base = k * n * n + k * n + x * block;
        let second = k * n * n + k * n + (self.params + 1) * block + x * k;
        self.contacts
            .iter()
            .zip(&self.index)
            .map(|(row, &j)| {
                let a = (0..n).map(|c| self.derivatives[base + k + j + c * k]).collect();
                let e = self.derivatives[base + k + k * n + j];
                (row.lambda, Along { a, e, moving: self.derivatives[second + j] })
            })
            .collect()
    }

    /// The contacts' rows of the right-hand side along `x`, from `offset`:
    /// `−∂e/∂x c − (1 + e) (∂a/∂x v⁻ + ∂²φ/∂t∂x) − ∂a/∂x Δv`, `c` the normal speed before.
    fn contact_rows(&self, along: &[(f64, Along)], v_minus: &[f64], rhs: &mut DVector<f64>, offset: usize) {
        for (s, (row, (_, d))) in self.contacts.iter().zip(along).enumerate() {
            let dot = |x: &[f64]| d.a.iter().zip(x).map(|(a, b)| a * b).sum::<f64>();
            rhs[offset + s] =
                -d.e * row.approach - (1.0 + row.e) * (dot(v_minus) + d.moving) - dot(self.dv.as_slice());
        }
    }

    fn solve(&self, rhs: &mut DVector<f64>) -> Result<(), SimError> {
        if self.lu.solve_mut(rhs) && rhs.iter().all(|x| x.is_finite()) {
            Ok(())
        } else {
            Err(singular(self.t))
        }
    }
}

fn singular(t: f64) -> SimError {
    SimError::NotDetermined {
        t,
        cause: "the impact law's linear system (the mass matrix bordered by the constraint and contact \
                rows) is singular: redundant rows leave the impulses undetermined, so the impact has no \
                derivative"
            .into(),
    }
}

/// The saltation matrix of an impact ([`saltation`]): how a small change of the state just
/// before it, and of the parameters, carries to the state just after it, the impact's time
/// moving with them.
#[derive(Clone, Debug)]
pub struct Saltation {
    /// `δ(q, v)⁺ = S δ(q, v)⁻`, `2n × 2n`, positions first: a change of the state before the
    /// impact, at the impact's time, to the change of the state after it at that time.
    pub matrix: DMatrix<f64>,
    /// The change of the state after the impact per unit change of each parameter, the state
    /// before it held: `2n × P`.
    pub parameters: DMatrix<f64>,
    /// `∂t*/∂(q, v)⁻`: how the impact's time moves with the state before it (`2n`).
    pub time: DVector<f64>,
    /// `∂t*/∂θ`: how it moves with each parameter (`P`).
    pub time_parameters: DVector<f64>,
    /// The impact itself and its derivative at fixed time.
    pub impact: ImpactMap,
}

/// The saltation matrix of the impact at which unilateral constraint `contact` closes, at time
/// `t`, positions `q` and velocities `v` just before it, with the contacts `closing` (which
/// holds `contact`) taking part: the linearised jump of the motion across the impact,
///
/// ```text
/// S = DΦ + (DΦ f⁻ + ∂Φ/∂t − f⁺) ∂t*/∂x,    ∂t*/∂x = −(a, 0) / (a v⁻ + ∂φ/∂t),
/// ```
///
/// `Φ` the impact ([`impact_map`]), `f = (v, v̇)` the motion just before and just after it
/// (the accelerations from the equations of motion with the constraints at acceleration
/// level), `a = ∂φ/∂q` the contact's one-form. The parameters' columns are
/// `∂Φ/∂θ + (DΦ f⁻ + ∂Φ/∂t − f⁺) ∂t*/∂θ`, with `∂t*/∂θ = −∂φ/∂θ / (a v⁻ + ∂φ/∂t)`. What
/// carries a sensitivity across an impact, and the factor an impact contributes to the
/// monodromy matrix of a periodic hybrid orbit (a hopping or walking gait's stability).
///
/// Refused as [`impact_map`] is, and with [`SimError::InvalidOption`] where `contact` is not
/// among `closing` or is not approaching (the motion does not cross it there).
///
/// The guide's section on contacts works the bouncing ball's out (`dirac::guide`).
pub fn saltation<M: Hybrid + Parameters>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
    contact: usize,
    closing: &[usize],
) -> Result<Saltation, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let names = model.unilateral_names();
    if !closing.contains(&contact) {
        return Err(SimError::InvalidOption {
            what: "saltation",
            reason: format!(
                "the contact whose closing times the impact ({contact}) is not among the closing ones {closing:?}"
            ),
        });
    }
    let impact = impact_map(model, t, q, v, closing)?;
    let sizes = model.sizes();
    let (n, k, params) = (sizes.nq, names.len(), model.parameter_count());
    let mut rows = vec![0.0; k * n];
    model.unilateral_dq(t, q, &mut rows);
    let mut derivatives = vec![0.0; model.unilateral_derivatives_len()];
    model.unilateral_derivatives(t, q, &mut derivatives);
    let block = 2 * k + k * n;
    let along = |x: usize| derivatives[k * n * n + k * n + x * block + contact];
    let a: Vec<f64> = (0..n).map(|c| rows[contact + c * k]).collect();
    let speed = a.iter().zip(v.iter()).map(|(a, v)| a * v).sum::<f64>() + along(0);
    if speed >= 0.0 || speed.is_nan() {
        return Err(SimError::InvalidOption {
            what: "saltation",
            reason: format!(
                "the contact `{}` is not approaching (its normal speed is {speed:e}): the motion does not \
                 cross it there, so no impact is timed by it",
                names[contact]
            ),
        });
    }
    let mut after = sizes.zeros_q::<M>();
    after.iter_mut().zip(impact.velocity.iter()).for_each(|(x, &y)| *x = y);
    let (before_rate, after_rate) = (accelerations(model, t, q, v)?, accelerations(model, t, q, &after)?);

    // DΦ on (q, v): positions kept, velocities by the impact.
    let mut d_phi = DMatrix::<f64>::identity(2 * n, 2 * n);
    d_phi.view_mut((n, 0), (n, n)).copy_from(&impact.dq);
    d_phi.view_mut((n, n), (n, n)).copy_from(&impact.dv);
    let mut f_before = DVector::<f64>::zeros(2 * n);
    f_before.rows_mut(0, n).copy_from_slice(v.as_slice());
    f_before.rows_mut(n, n).copy_from(&before_rate);
    let mut f_after = DVector::<f64>::zeros(2 * n);
    f_after.rows_mut(0, n).copy_from(&impact.velocity);
    f_after.rows_mut(n, n).copy_from(&after_rate);
    // The jump's change per unit delay of the impact.
    let mut delay = &d_phi * &f_before - f_after;
    for i in 0..n {
        delay[n + i] += impact.dt[i];
    }
    let mut time = DVector::<f64>::zeros(2 * n);
    for (c, &x) in a.iter().enumerate() {
        time[c] = -x / speed;
    }
    let time_parameters = DVector::from_iterator(params, (0..params).map(|p| -along(p + 1) / speed));
    let matrix = d_phi + &delay * time.transpose();
    let mut parameters = DMatrix::<f64>::zeros(2 * n, params);
    parameters.view_mut((n, 0), (n, params)).copy_from(&impact.dtheta);
    parameters += &delay * time_parameters.transpose();
    Ok(Saltation { matrix, parameters, time, time_parameters, impact })
}

/// `v̇` at `(t, q, v)`: the equations of motion with the constraints at acceleration level,
/// `[L_vv −Bᵀ; A 0] (v̇, λ) = (∂L/∂q + F − L_vt − L_vq v, −∂(A v + b)/∂q v − ∂(A v + b)/∂t)`
/// (`B = A` but where slipping friction cones put their kinetic force on a contact's row, see
/// [`LagrangeDirac::slip_rows`](crate::model::LagrangeDirac::slip_rows)).
pub(crate) fn accelerations<M: Hybrid>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
) -> Result<DVector<f64>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    Ok(motion_at(model, t, q, v)?.accelerations)
}

/// The motion at `(t, q, v)` from the equations of motion with the constraints at acceleration
/// level (see [`accelerations`]): the accelerations, the multipliers, and the factorised matrix
/// `[L_vv −Bᵀ; A 0]` of the system that gave them.
pub(crate) struct Motion {
    pub accelerations: DVector<f64>,
    pub multipliers: DVector<f64>,
    pub system: nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
    /// The rows of the system that are the force balance of a coordinate without mass,
    /// differentiated along the motion (see [`massless_rows`]).
    pub massless: Vec<usize>,
}

/// [`Motion`] at `(t, q, v)`.
pub(crate) fn motion_at<M: Hybrid>(model: &M, t: f64, q: &VecQ<M>, v: &VecQ<M>) -> Result<Motion, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let sizes = model.sizes();
    let (n, m) = (sizes.nq, sizes.nc);
    let h = dense_qq(model, &|b| model.l_vv(t, q, v, b));
    let lvq = dense_qq(model, &|b| model.l_vq(t, q, v, b));
    let a = dense_cq(model, &|b| model.constraint_matrix(t, q, b));
    let dav = dense_cq(model, &|b| model.dav_dq(t, q, v, b));
    let (mut dl, mut force, mut lvt) = (sizes.zeros_q::<M>(), sizes.zeros_q::<M>(), sizes.zeros_q::<M>());
    model.dl_dq(t, q, v, &mut dl);
    model.force(t, q, v, &mut force);
    model.l_vt(t, q, v, &mut lvt);
    let mut rate = sizes.zeros_c::<M>();
    model.dav_dt(t, q, v, &mut rate);
    let velocities = DVector::from_column_slice(v.as_slice());
    // The rows' forces are `Bᵀλ`: with the friction that slipping cones' contact forces drive,
    // `B = A + (B − A)`.
    let pushing = match M::NON_ASSOCIATED {
        true => &a + dense_cq(model, &|b| model.slip_rows(t, q, v, b)),
        false => a.clone(),
    };
    let mut matrix = DMatrix::<f64>::zeros(n + m, n + m);
    matrix.view_mut((0, 0), (n, n)).copy_from(&h);
    matrix.view_mut((0, n), (n, m)).copy_from(&(-pushing.transpose()));
    matrix.view_mut((n, 0), (m, n)).copy_from(&a);
    let mut rhs = DVector::<f64>::zeros(n + m);
    let top = &lvq * &velocities;
    for i in 0..n {
        rhs[i] = dl[i] + force[i] - lvt[i] - top[i];
    }
    let bottom = &dav * &velocities;
    for i in 0..m {
        rhs[n + i] = -bottom[i] - rate[i];
    }
    let massless = massless_rows(&h, &lvq, &a);
    if !massless.is_empty() {
        free_massless_rows(model, (t, q, v), &massless, &mut matrix, &mut rhs);
    }
    let system = matrix.clone().lu();
    let mut solution = rhs.clone();
    if !system.solve_mut(&mut solution) || solution.iter().any(|x| !x.is_finite()) {
        // Redundant rows (a box's four corners on the ground): the multipliers without part
        // along `ker Aᵀ`, as the integrators' deflation takes them.
        let ones = vec![1.0; m];
        solution = crate::analysis::init::deflated_solve(&matrix, &rhs, n, &a.transpose(), &ones)
            .ok_or_else(|| SimError::NotDetermined {
                t,
                cause: "the accelerations: the mass matrix bordered by the constraint rows is singular there"
                    .into(),
            })?;
    }
    let rhs = solution;
    Ok(Motion {
        accelerations: rhs.rows(0, n).into_owned(),
        multipliers: rhs.rows(n, m).into_owned(),
        system,
        massless,
    })
}

/// The coordinates without mass or momentum (their rows of `L_vv` and `L_vq` zero) that no
/// constraint row reaches (their columns of `A` zero): their velocities are fixed by a force
/// balance, `r_i(t, q, v) = ∂L/∂q_i + F_i = 0`, which says nothing of their accelerations.
fn massless_rows(h: &DMatrix<f64>, lvq: &DMatrix<f64>, a: &DMatrix<f64>) -> Vec<usize> {
    (0..h.nrows())
        .filter(|&i| {
            h.row(i).iter().all(|&x| x == 0.0)
                && lvq.row(i).iter().all(|&x| x == 0.0)
                && a.column(i).iter().all(|&x| x == 0.0)
        })
        .collect()
}

/// Replaces each row `i` of `massless` in the acceleration-level system by the force balance
/// differentiated along the motion, `∂r_i/∂v v̇ = −(∂r_i/∂t + ∂r_i/∂q v)`, with
/// `r = ∂L/∂q + F`: `∂r_i/∂v` from the generated `L_qv` and `∂F/∂v`, the rest a central
/// difference along `(1, v)` in `(t, q)`, Richardson-extrapolated.
fn free_massless_rows<M: Hybrid>(
    model: &M,
    (t, q, v): (f64, &VecQ<M>, &VecQ<M>),
    massless: &[usize],
    matrix: &mut DMatrix<f64>,
    rhs: &mut DVector<f64>,
) where
    DefaultAllocator: Storage<M>,
{
    let sizes = model.sizes();
    let n = sizes.nq;
    let lvq = dense_qq(model, &|b| model.l_vq(t, q, v, b));
    let fv = dense_qq(model, &|b| model.force_dv(t, q, v, b));
    let (mut dl, mut force, mut moved) = (sizes.zeros_q::<M>(), sizes.zeros_q::<M>(), q.clone());
    let size = q.iter().chain(v.iter()).fold(1.0f64, |s, x| s.max(x.abs()));
    let step = 1e-4 * size / (1.0 + v.amax());
    let mut balance = |d: f64| -> DVector<f64> {
        moved.iter_mut().zip(q.iter().zip(v.iter())).for_each(|(x, (q, v))| *x = q + d * v);
        model.dl_dq(t + d, &moved, v, &mut dl);
        model.force(t + d, &moved, v, &mut force);
        DVector::from_iterator(n, dl.iter().zip(force.iter()).map(|(a, b)| a + b))
    };
    let near = (balance(step) - balance(-step)) / (2.0 * step);
    let far = (balance(2.0 * step) - balance(-2.0 * step)) / (4.0 * step);
    let along = (near * 4.0 - far) / 3.0;
    for &i in massless {
        matrix.row_mut(i).fill(0.0);
        for j in 0..n {
            // `∂(∂L/∂q_i)/∂v_j` is `L_vq[j][i]`.
            matrix[(i, j)] = lvq[(j, i)] + fv[(i, j)];
        }
        rhs[i] = -along[i];
    }
}
