//! Impacts at unilateral constraints `φ_u(q, t) ≥ 0` (`#[dirac(unilateral(name) = φ)]`), by
//! Newton's law of restitution along the constraints' own one-forms.
//!
//! When contacts `J` close at once with normal velocities `c_j = a_j v⁻ + ∂φ_j/∂t < 0`
//! (`a_j = ∂φ_j/∂q`; `∂φ_j/∂t` the speed of a moving contact), the momentum jumps along their
//! one-forms, `p⁺ = p⁻ + Σ_j a_jᵀ Λ_j`, while the model's own constraints keep holding,
//! `A v⁺ + b = 0`, and each contact's normal velocity is reversed and scaled by its
//! restitution, `a_j v⁺ + ∂φ_j/∂t = −e_j c_j`. For a Lagrangian quadratic in the
//! velocities (`Δp = L_vv Δv`, every mechanical one) this is linear:
//!
//! ```text
//! [L_vv  −Aᵀ] [X_j]   [a_jᵀ]          velocity change per unit impulse on contact j,
//! [A      0 ] [ · ] = [ 0  ]          with the model's constraints kept;
//!
//! W Λ = −(1 + e) c,   W_ij = a_i X_j  (the inverse effective mass of the contacts),
//! v⁺ = v⁻ + Σ_j X_j Λ_j.
//! ```
//!
//! An impulse can only push: a contact whose `Λ_j` comes out negative is left out and the
//! others solved again (at most once per contact).

use nalgebra::{DMatrix, DVector, DefaultAllocator};

use crate::algebra::{Algebra, Saddle, SaddleTerms};
use crate::analysis::init_saddle::not_determined;
use crate::error::SimError;
use crate::model::Hybrid;
use crate::model::state::State;
use crate::shape::dims::{Sizes, Storage};

/// `∂φ_u/∂t` of each unilateral constraint at `(t, q)`: the generated derivative where the
/// derive emits it; elsewhere (an interconnection) zero, after checking that no constraint
/// moves (its value unchanged at `t ± 1e-3`), or an error naming the one that does.
pub(crate) fn moving_speeds<M: Hybrid>(
    model: &M,
    t: f64,
    q: &crate::shape::dims::VecQ<M>,
    names: &[String],
) -> Result<Vec<f64>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let k = names.len();
    let len = model.unilateral_derivatives_len();
    if len > 0 {
        let n = model.sizes().nq;
        let mut all = vec![0.0; len];
        model.unilateral_derivatives(t, q, &mut all);
        let at = k * n * n + k * n;
        return Ok(all[at..at + k].to_vec());
    }
    let (mut before, mut after) = (vec![0.0; k], vec![0.0; k]);
    model.unilateral(t - 1e-3, q, &mut before);
    model.unilateral(t + 1e-3, q, &mut after);
    match (0..k).find(|&j| before[j] != after[j]) {
        None => Ok(vec![0.0; k]),
        Some(j) => Err(SimError::InvalidOption {
            what: "contacts",
            reason: format!(
                "the unilateral constraint `{}` moves with time, and the speed of a moving contact is \
                 generated only for a model that declares it itself, not for an interconnection: declare \
                 it on a model of its own",
                names[j]
            ),
        }),
    }
}

/// What an impact did: each closing contact's impulse, and the first contact it left at rest.
pub(crate) struct Impacts {
    pub impulses: Vec<(usize, f64)>,
    pub resting: Option<usize>,
}

/// The unilateral constraints of a model, evaluated into storage kept between impacts.
pub(crate) struct Contacts {
    pub names: Vec<String>,
    /// `∂φ_u/∂q`, `k × n`, column-major.
    rows: Vec<f64>,
    restitution: Vec<f64>,
    /// The times of the last three impacts at each contact, latest last (NaN before).
    recent: Vec<[f64; 3]>,
    /// The fastest approach seen at each contact.
    fastest: Vec<f64>,
}

/// A contact reopened at a speed below this share of its fastest approach has come to rest:
/// its next impacts would come ever faster without end (a Zeno sequence).
const AT_REST: f64 = 1e-9;

impl Contacts {
    /// The unilateral constraints of `model`.
    pub fn new<M: Hybrid>(model: &M) -> Self
    where
        DefaultAllocator: Storage<M>,
    {
        let names = model.unilateral_names();
        let (k, n) = (names.len(), model.sizes().nq);
        Contacts {
            rows: vec![0.0; k * n],
            restitution: vec![0.0; k],
            recent: vec![[f64::NAN; 3]; k],
            fastest: vec![0.0; k],
            names,
        }
    }

    /// The impact at time `t` of the contacts `closing` (their indices among the unilateral
    /// constraints): changes the velocities of `state` by Newton's law and returns each
    /// contact's impulse `Λ_j` (zero for one that was not approaching). An error if a
    /// restitution is outside `[0, 1]` or if the impact system is singular. A contact that the
    /// impact leaves closed, or reopens too slowly to be told from rest, is named in
    /// [`Impacts::resting`].
    pub fn impact<M: Hybrid>(
        &mut self,
        model: &M,
        t: f64,
        state: &mut State<M>,
        closing: &[usize],
    ) -> Result<Impacts, SimError>
    where
        DefaultAllocator: Storage<M>,
    {
        let (k, sizes, shape) = (self.names.len(), model.sizes(), model.shape());
        let Sizes { nq: n, nc: m, .. } = sizes;
        model.unilateral_dq(t, &state.q, &mut self.rows);
        model.restitution(t, &state.q, &mut self.restitution);
        for &j in closing {
            let e = self.restitution[j];
            if !(0.0..=1.0).contains(&e) {
                return Err(SimError::InvalidOption {
                    what: "restitution",
                    reason: format!(
                        "the coefficient of restitution of `{}` is {e}: it must lie in [0, 1] (0 a plastic \
                         impact, 1 an elastic one)",
                        self.names[j]
                    ),
                });
            }
        }
        let moving = moving_speeds(model, t, &state.q, &self.names)?;
        let rows = &self.rows;
        // Row j of ∂φ_u/∂q times x; and the normal speed of contact j at velocities x, with the
        // speed of a moving contact, ∂φ_u/∂t.
        let dot = |j: usize, x: &[f64]| (0..n).map(|i| rows[j + i * k] * x[i]).sum::<f64>();
        let speed = |j: usize, x: &[f64]| dot(j, x) + moving[j];
        let approach: Vec<f64> = closing.iter().map(|&j| speed(j, state.v.as_slice())).collect();
        if let Some(i) = approach.iter().position(|c| !c.is_finite()) {
            let component = format!(
                "the contact direction ∂φ/∂q of the unilateral constraint `{}`",
                self.names[closing[i]]
            );
            return Err(SimError::NonFinite { t, component });
        }
        let mut active: Vec<usize> = (0..closing.len()).filter(|&i| approach[i] < 0.0).collect();
        let mut impulses: Vec<(usize, f64)> = closing.iter().map(|&j| (j, 0.0)).collect();
        if active.is_empty() {
            return Ok(Impacts { impulses, resting: None });
        }

        // The velocity change per unit impulse on each approaching contact.
        let (mut lvv, mut a) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_cq(&shape));
        model.l_vv(t, &state.q, &state.v, &mut lvv);
        model.constraint_matrix(t, &state.q, &mut a);
        // The model's own rows push back with their one-forms, and with the friction their
        // impulses drive where it slips (`B = A + (B − A)`).
        let slip = M::NON_ASSOCIATED.then(|| {
            let mut slip = M::Algebra::zeros_cq(&shape);
            model.slip_rows(t, &state.q, &state.v, &mut slip);
            slip
        });
        let (own, both);
        let right: &[_] = match &slip {
            Some(slip) => {
                both = [(-1.0, &a), (-1.0, slip)];
                &both
            }
            None => {
                own = [(-1.0, &a)];
                &own
            }
        };
        let mut saddle = M::Algebra::saddle(&shape);
        saddle.assemble(&SaddleTerms::<M, M::Algebra, f64> {
            top: &[(1.0, &lvv)],
            top_transposed: &[],
            identity: 0.0,
            right,
            bottom: &[(1.0, 1.0, &a)],
            corner: (0.0, 0.0),
        });
        saddle.factor().map_err(|s| not_determined(model, t, &state.q, &state.v, s))?;
        // Every touching contact's column: one that was not approaching may be driven in by
        // the others' impulses.
        let mut per_unit = DMatrix::<f64>::zeros(n, closing.len());
        let mut x = vec![0.0; n + m];
        for i in 0..closing.len() {
            x.fill(0.0);
            for (c, xc) in x[..n].iter_mut().enumerate() {
                *xc = rows[closing[i] + c * k];
            }
            saddle.solve(&mut x);
            per_unit.column_mut(i).copy_from_slice(&x[..n]);
        }
        // The normal speed a contact that was not approaching is driven to, below which it
        // joins the impact.
        let driven_in = -1e-9 * approach.iter().fold(0.0f64, |s, x| s.max(x.abs()));

        // Newton's law on the approaching contacts; one that would pull is left out, and one
        // the others' impulses would drive in joins, stopped by its own impulse (plastically: it
        // had no approach to restore). Left and joined by turns, at most as often as the
        // contacts are many, twice.
        let target = |i: usize| match approach[i] < 0.0 {
            true => -(1.0 + self.restitution[closing[i]]) * approach[i],
            false => -approach[i],
        };
        let mut rounds = 0;
        let lambda = loop {
            rounds += 1;
            let size = active.len();
            let mut w = DMatrix::<f64>::zeros(size, size);
            let mut rhs = DVector::<f64>::zeros(size);
            for (r, &i) in active.iter().enumerate() {
                for (c, &l) in active.iter().enumerate() {
                    w[(r, c)] = dot(closing[i], per_unit.column(l).as_slice());
                }
                rhs[r] = target(i);
            }
            let lambda = w.clone().lu().solve(&rhs).or_else(|| w.svd(true, true).solve(&rhs, 1e-12).ok());
            let Some(lambda) = lambda.filter(|l| l.iter().all(|x| x.is_finite())) else {
                return Err(SimError::NotDetermined {
                    t,
                    cause: format!(
                        "the impact at `{}`: its contact direction ∂φ/∂q (its one-form) moves nothing the model's joints and \
                         constraints let move",
                        self.names[closing[active[0]]]
                    ),
                });
            };
            match (0..size).filter(|&r| lambda[r] < 0.0).min_by(|&r, &s| lambda[r].total_cmp(&lambda[s])) {
                Some(r) if size > 1 => {
                    active.remove(r);
                    continue;
                }
                _ => {}
            }
            if rounds > 2 * closing.len() {
                break lambda;
            }
            let speed_after = |i: usize| {
                let change: f64 = active
                    .iter()
                    .enumerate()
                    .map(|(r, &l)| lambda[r].max(0.0) * dot(closing[i], per_unit.column(l).as_slice()))
                    .sum();
                approach[i] + change
            };
            let joins = (0..closing.len())
                .filter(|i| !active.contains(i))
                .map(|i| (i, speed_after(i)))
                .filter(|&(_, s)| s < driven_in)
                .min_by(|a, b| a.1.total_cmp(&b.1));
            match joins {
                Some((i, _)) => active.push(i),
                None => break lambda,
            }
        };
        for (r, &i) in active.iter().enumerate() {
            let impulse = lambda[r].max(0.0);
            impulses[i].1 = impulse;
            for (v, x) in state.v.iter_mut().zip(per_unit.column(i).iter()) {
                *v += x * impulse;
            }
        }

        // A contact left without normal velocity stays closed.
        let reopening: Vec<f64> = closing.iter().map(|&j| speed(j, state.v.as_slice())).collect();
        let mut resting = None;
        for (i, &j) in closing.iter().enumerate().filter(|&(i, _)| approach[i] < 0.0) {
            let recent = &mut self.recent[j];
            *recent = [recent[1], recent[2], t];
            self.fastest[j] = self.fastest[j].max(-approach[i]);
            if reopening[i] <= AT_REST * self.fastest[j] && resting.is_none() {
                resting = Some(j);
            }
        }
        Ok(Impacts { impulses, resting })
    }

    /// The error for contact `j` closing at `t` where it cannot rest, with the time its
    /// impacts accumulate at when they do.
    pub fn closes(&self, j: usize, t: f64) -> SimError {
        SimError::ContactCloses { contact: self.names[j].clone(), t, t_limit: self.accumulation(j) }
    }

    /// Forgets contact `j`'s impacts: after it rested, its next ones start a new sequence.
    pub fn rested(&mut self, j: usize) {
        self.recent[j] = [f64::NAN; 3];
        self.fastest[j] = 0.0;
    }

    /// For a step that failed after impacts at a contact came ever closer together (a Zeno
    /// sequence), that contact: the step failed because of them.
    pub fn zeno(&self, failed_at: f64) -> Option<usize> {
        (0..self.names.len()).find(|&j| {
            let Some(t_limit) = self.accumulation(j) else { return false };
            let [_, t2, t3] = self.recent[j];
            // The step failed within the accumulation, not somewhere else.
            failed_at >= t3 && failed_at <= t_limit + 2.0 * (t3 - t2)
        })
    }

    /// The time of the last impact at contact `j`.
    pub fn last_impact(&self, j: usize) -> f64 {
        self.recent[j][2]
    }

    /// Where the impacts at contact `j` accumulate, if their last three intervals shrink: the
    /// sum of the geometric series their last two intervals start.
    fn accumulation(&self, j: usize) -> Option<f64> {
        let [t1, t2, t3] = self.recent[j];
        let (d1, d2) = (t2 - t1, t3 - t2);
        let ratio = d2 / d1;
        (ratio > 0.0 && ratio < 1.0).then(|| t3 + d2 * ratio / (1.0 - ratio))
    }
}
