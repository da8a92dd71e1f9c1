//! The general path of a variational step: a Newton iteration on the `(n + m)` system of each
//! stage, for any Lagrangian (configuration-dependent or degenerate mass matrices included),
//! with the blocks stored and the systems solved as the model's algebra says.

use nalgebra::DefaultAllocator;

use super::work::{StageBlocks, Step, assemble_legendre};
use crate::algebra::{Algebra, Saddle, SaddleTerms};
use crate::analysis::free::FreeVelocities;
use crate::error::SimError;
use crate::model::LagrangeDirac;
use crate::model::MatCQ;
use crate::model::configuration;
use crate::shape::dims::{Sizes, Storage, VecC, VecH, VecQ};
use crate::shape::layout::Unknowns;

/// Which unknowns a Newton update applies to.
#[derive(Clone, Copy)]
enum Stage {
    /// `(v, Λ)`.
    One,
    /// `(w, Γ)`: the new velocities and the stage-2 impulse.
    Two,
}

/// Both stages.
pub(crate) fn general_step<M: LagrangeDirac>(s: &mut Step<'_, M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    s.work.last_update = f64::INFINITY;
    stage_one(s)?;
    s.work.last_update = f64::INFINITY;
    stage_two(s)
}

/// Stage 1: the new positions, through `(v, Λ)`.
// Indexing keeps the several vectors of one component side by side.
#[allow(clippy::needless_range_loop)]
fn stage_one<M: LagrangeDirac>(s: &mut Step<'_, M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let unknowns = Unknowns::new(s.work.sizes.typed::<M>());
    let (n, h) = (unknowns.n, s.h);
    let (t0, t1, tm) = (s.t, s.t + h, s.t + 0.5 * h);
    let model = s.model;
    for iteration in 0..s.options.max_iterations {
        let w = &mut s.work;
        let (q, v, x) = (&s.state.q, &w.v, &mut w.vectors);
        configuration::advance::<M>(q, h, v, &mut x.q1);
        configuration::advance::<M>(q, 0.5 * h, v, &mut x.qm);
        model.dl_dv(t0, q, v, &mut x.lv0);
        model.dl_dv(t1, &x.q1, v, &mut x.lv1);
        model.dl_dq(t0, q, v, &mut x.lq);
        model.force(tm, &x.qm, v, &mut x.f);
        if M::SLIP_TURNS {
            // Friction that turns with the slip pushes against the step's own slip: held at
            // the start's velocity, its stiffness across the slip would be explicit.
            model.slip_rows(t0, q, v, &mut w.slip0);
        }
        // The constraint impulse A(q_k)ᵀ Λ (B(q_k)ᵀ Λ where friction pushes with a contact
        // force), held in `target` (unused in this stage).
        x.target.fill(0.0);
        M::Algebra::cq_tr_mul(&w.a0, 1.0, w.big_lambda.as_slice(), x.target.as_mut_slice());
        if M::NON_ASSOCIATED {
            M::Algebra::cq_tr_mul(&w.slip0, 1.0, w.big_lambda.as_slice(), x.target.as_mut_slice());
        }
        let r = x.r.as_mut_slice();
        for i in 0..n {
            r[i] = 0.5 * (x.lv0[i] + x.lv1[i]) - 0.5 * h * (x.lq[i] + x.f[i]) - x.target[i] - s.state.p[i];
        }
        if let Some(free) = &w.free {
            midpoint_rows(model, free, (tm, h), (&x.qm, v), (&x.lq, &mut x.target, &mut x.f), &mut r[..n]);
        }
        let b = &mut w.blocks;
        model.l_vv(t0, q, v, &mut b.lvv0);
        model.l_vv(t1, &x.q1, v, &mut b.lvv1);
        model.l_vq(t0, q, v, &mut b.lvq0);
        model.l_vq(t1, &x.q1, v, &mut b.lvq1);
        model.force_dq(tm, &x.qm, v, &mut b.fq);
        model.force_dv(tm, &x.qm, v, &mut b.fv);
        if M::SLIP_TURNS {
            model.slip_dv(t0, q, v, &w.big_lambda, &mut b.sv);
        }
        model.constraint_matrix(t1, &x.q1, &mut b.a1);
        model.constraint_matrix(tm, &x.qm, &mut b.am);
        model.dav_dq(tm, &x.qm, v, &mut b.gm);
        let at = StagePoints { t: t0, h, q1: &x.q1, qm: &x.qm };
        stage_one_constraints(
            model,
            &w.sizes.typed::<M>(),
            at,
            (&mut x.phi, &mut x.rate),
            &b.am,
            v,
            unknowns.split_mut(r).1,
        );
        assemble_stage_one::<M>(&mut w.saddle, b, (&w.a0, &w.slip0), h);
        if newton_update(s, Stage::One, iteration)? {
            return Ok(());
        }
    }
    Err(s.diverged())
}

/// Along the velocities only the forces fix, the stage-1 row is the momentum balance at the
/// midpoint, `−(h/2) Nᵀ (∂L/∂q + F − L_vq v)` there (the discrete Lagrange-d'Alembert force
/// fixes the step velocity, as the implicit midpoint rule does): `∂L/∂q`, in the row at the
/// step's start (`lq`), moves to its midpoint. With `∂L/∂q` at the start the rows were the
/// explicit Euler method's, first order. `lm` and `d` are scratch.
#[cold]
#[inline(never)]
fn midpoint_rows<M: LagrangeDirac>(
    model: &M,
    free: &FreeVelocities<M>,
    (tm, h): (f64, f64),
    (qm, v): (&VecQ<M>, &VecQ<M>),
    (lq, lm, d): (&VecQ<M>, &mut VecQ<M>, &mut VecQ<M>),
    r: &mut [f64],
) where
    DefaultAllocator: Storage<M>,
{
    model.dl_dq(tm, qm, v, lm);
    for (d, (lq, lm)) in d.iter_mut().zip(lq.iter().zip(lm.iter())) {
        *d = 0.5 * h * (lq - lm);
    }
    free.add_along(r, d.as_slice());
}

/// The stage-1 matrix: `∂/∂v` of the momentum residual (top) and of the constraints (bottom).
fn assemble_stage_one<M: LagrangeDirac>(
    saddle: &mut <M::Algebra as Algebra<M>>::Saddle<f64>,
    b: &mut StageBlocks<M>,
    (a0, slip0): (&MatCQ<M>, &MatCQ<M>),
    h: f64,
) where
    DefaultAllocator: Storage<M>,
{
    // ½ (L_vv(q_k) + L_vv(q_{k+1}) + h L_vq(q_{k+1})) − (h/2)(L_vq(q_k)ᵀ + F_v + (h/2) F_q)
    // − ∂(B(q_k, v)ᵀ Λ)/∂v where the slip turns with the velocity.
    let terms = [
        (0.5, &b.lvv0),
        (0.5, &b.lvv1),
        (0.5 * h, &b.lvq1),
        (-0.5 * h, &b.fv),
        (-0.25 * h * h, &b.fq),
        (-1.0, &b.sv),
    ];
    let terms = if M::SLIP_TURNS { &terms[..] } else { &terms[..5] };
    let forces = [(-1.0, a0), (-1.0, slip0)];
    let rest = SaddleTerms {
        top: &[],
        top_transposed: &[(-0.5 * h, &b.lvq0)],
        identity: 0.0,
        right: if M::NON_ASSOCIATED { &forces[..] } else { &forces[..1] },
        // Holonomic rows: A(q_{k+1}); the others: A(q_{k+½}) + (h/2) ∂(A v)/∂q there.
        bottom: &[(1.0, 0.0, &b.a1), (0.0, 1.0, &b.am), (0.0, 0.5 * h, &b.gm)],
        corner: (0.0, 0.0),
    };
    if M::Algebra::dense_qq(&b.sum).is_some() {
        // Dense blocks store every entry in the same order: the top terms sum value by value,
        // in plain loops over equal slices that vectorise whatever else the step inlines.
        let sum = M::Algebra::qq_values_mut(&mut b.sum);
        sum.fill(0.0);
        for (c, x) in terms {
            for (y, x) in sum.iter_mut().zip(M::Algebra::qq_values(x)) {
                *y += c * x;
            }
        }
        saddle.assemble(&SaddleTerms { top: &[(1.0, &b.sum)], ..rest });
    } else {
        saddle.assemble(&SaddleTerms { top: terms, ..rest });
    }
}

/// Where stage 1 evaluates the constraints: the end point and the midpoint of a step of size
/// `h` from `t`.
#[derive(Clone, Copy)]
pub(crate) struct StagePoints<'a, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    pub t: f64,
    pub h: f64,
    pub q1: &'a VecQ<M>,
    pub qm: &'a VecQ<M>,
}

/// `φ(q_{k+1}, t_{k+1})/h` for holonomic rows, `A(q_{k+½}, t_{k+½}) v + b(q_{k+½}, t_{k+½})`
/// for the others, into `out`; `am` holds `A(q_{k+½}, t_{k+½})`.
pub(crate) fn stage_one_constraints<M: LagrangeDirac>(
    model: &M,
    sizes: &Sizes,
    at: StagePoints<'_, M>,
    (phi, rate): (&mut VecH<M>, &mut VecC<M>),
    am: &MatCQ<M>,
    v: &VecQ<M>,
    out: &mut [f64],
) where
    DefaultAllocator: Storage<M>,
{
    if sizes.nc == 0 {
        return;
    }
    if M::PRESCRIBED {
        model.constraint_rate(at.t + 0.5 * at.h, at.qm, rate);
        out.copy_from_slice(rate.as_slice());
    } else {
        out.fill(0.0);
    }
    M::Algebra::cq_mul(am, 1.0, v.as_slice(), out);
    model.holonomic(at.t + at.h, at.q1, phi);
    for j in 0..sizes.nh {
        out[j] = phi[j] / at.h;
    }
}

/// Stage 2: the new momenta and velocities, through `(w, Γ)`.
#[allow(clippy::needless_range_loop)]
fn stage_two<M: LagrangeDirac>(s: &mut Step<'_, M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let unknowns = Unknowns::new(s.work.sizes.typed::<M>());
    let (n, h) = (unknowns.n, s.h);
    let (t0, t1, tm) = (s.t, s.t + h, s.t + 0.5 * h);
    let model = s.model;
    {
        let w = &mut s.work;
        let (q, v, x) = (&s.state.q, &w.v, &mut w.vectors);
        configuration::advance::<M>(q, h, v, &mut x.q1);
        configuration::advance::<M>(q, 0.5 * h, v, &mut x.qm);
        model.dl_dv(t0, q, v, &mut x.lv0);
        model.dl_dv(t1, &x.q1, v, &mut x.lv1);
        model.dl_dq(t1, &x.q1, v, &mut x.lq);
        model.force(tm, &x.qm, v, &mut x.f);
        w.work += h * x.f.dot(v);
        for i in 0..n {
            x.target[i] = 0.5 * (x.lv0[i] + x.lv1[i]) + 0.5 * h * (x.lq[i] + x.f[i]);
        }
        model.constraint_matrix(t1, &x.q1, &mut w.blocks.a1);
        if M::NON_ASSOCIATED {
            model.slip_rows(t1, &x.q1, v, &mut w.slip1);
        }
        if M::PRESCRIBED {
            model.constraint_rate(t1, &x.q1, &mut x.rate);
        }
        s.state.v.copy_from(v);
    }
    for iteration in 0..s.options.max_iterations {
        let w = &mut s.work;
        let (x, b) = (&mut w.vectors, &mut w.blocks);
        let wv = &s.state.v;
        model.dl_dv(t1, &x.q1, wv, &mut x.lv1);
        // The constraint impulse A(q_{k+1})ᵀ Γ, held in `lv0` (not needed after `target`).
        x.lv0.fill(0.0);
        M::Algebra::cq_tr_mul(&b.a1, 1.0, w.gamma.as_slice(), x.lv0.as_mut_slice());
        if M::NON_ASSOCIATED {
            M::Algebra::cq_tr_mul(&w.slip1, 1.0, w.gamma.as_slice(), x.lv0.as_mut_slice());
        }
        let (r_v, r_lambda) = unknowns.split_mut(x.r.as_mut_slice());
        for (i, r) in r_v.iter_mut().enumerate() {
            *r = x.lv1[i] - x.lv0[i] - x.target[i];
        }
        if M::PRESCRIBED {
            r_lambda.copy_from_slice(x.rate.as_slice());
        } else {
            r_lambda.fill(0.0);
        }
        M::Algebra::cq_mul(&b.a1, 1.0, wv.as_slice(), r_lambda);
        model.l_vv(t1, &x.q1, wv, &mut b.lvv1);
        // Along the velocities only the forces fix, the Legendre map does not depend on them:
        // `N Nᵀ` completes the matrix, their rows are dropped here, and they are solved from
        // the momentum balance at the step's end once the others have converged.
        if let Some(free) = &w.free {
            free.remove(r_v);
        }
        assemble_legendre::<M>(&mut w.saddle, (&b.lvv1, &b.a1, &w.slip1), w.free.as_ref());
        if newton_update(s, Stage::Two, iteration)? {
            let w = &mut s.work;
            if let Some(free) = &mut w.free
                && !free.settle(model, t1, &w.vectors.q1, &mut s.state.v)
            {
                return Err(s.diverged());
            }
            if M::NON_ASSOCIATED {
                friction_work(s);
            }
            let x = &s.work.vectors;
            model.dl_dv(t1, &x.q1, &s.state.v, &mut s.state.p);
            return Ok(());
        }
    }
    Err(s.diverged())
}

/// The work of the friction the step's impulses drive, `⟨(B − A)ᵀΛ, v⟩ + ⟨(B − A)ᵀΓ, v⟩`
/// (`B − A` at the step's start and end), into the work the energy check allows for.
fn friction_work<M: LagrangeDirac>(s: &mut Step<'_, M>)
where
    DefaultAllocator: Storage<M>,
{
    let w = &mut s.work;
    let rate = &mut w.vectors.rate;
    for (slip, impulse) in [(&w.slip0, &w.big_lambda), (&w.slip1, &w.gamma)] {
        rate.fill(0.0);
        M::Algebra::cq_mul(slip, 1.0, w.v.as_slice(), rate.as_mut_slice());
        w.work += rate.dot(impulse);
    }
}

/// Factors the assembled stage matrix, applies the Newton update in `work.vectors.r` to the
/// stage's unknowns and says whether the iteration has converged.
#[inline(always)]
fn newton_update<M: LagrangeDirac>(
    s: &mut Step<'_, M>,
    stage: Stage,
    iteration: usize,
) -> Result<bool, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let unknowns = Unknowns::new(s.work.sizes.typed::<M>());
    s.stats.factorizations += 1;
    if let Err(singular) = s.work.saddle.factor() {
        return Err(s.singular(singular.column));
    }
    let r = s.work.vectors.r.as_mut_slice();
    s.work.saddle.solve(r);
    s.stats.newton_iterations += 1;
    let (x, mult) = match stage {
        Stage::One => (&mut s.work.v, &mut s.work.big_lambda),
        Stage::Two => (&mut s.state.v, &mut s.work.gamma),
    };
    let tolerance = s.options.tolerance;
    let mut converged = true;
    let mut finite = true;
    let (r_v, r_lambda) = unknowns.split(r);
    let scale = &s.work.scale;
    for (i, r) in r_v.iter().enumerate() {
        x[i] -= r;
        converged &= r.abs() <= tolerance * (scale[i] + x[i].abs());
        finite &= r.is_finite();
    }
    for (j, r) in r_lambda.iter().enumerate() {
        mult[j] -= r;
        converged &= r.abs() <= tolerance * (1.0 + mult[j].abs());
        finite &= r.is_finite();
    }
    // An iteration still short of the tolerance after three updates has stalled at round-off
    // when every update is below 1e3 times it: a badly scaled model (masses of 1e-5 against
    // lengths of 1e-2, Andrews' squeezer) never reaches 1e-12. Checked only then, so that the
    // iterations that converge pay nothing for it.
    if !converged && iteration >= 3 && finite {
        let loose = |r: &[f64], x: &[f64], scale: &dyn Fn(usize) -> f64| {
            r.iter().zip(x).enumerate().all(|(i, (r, x))| r.abs() <= 1e3 * tolerance * (scale(i) + x.abs()))
        };
        converged = loose(r_v, x.as_slice(), &|i| scale[i]) && loose(r_lambda, mult.as_slice(), &|_| 1.0);
    }
    if !finite {
        return Err(SimError::NonFinite {
            t: s.t,
            component: "a Newton update of the variational step".into(),
        });
    }
    Ok(converged)
}
