//! The minimal realisation of a linearisation, its states named by the model's coordinates.
//!
//! A model assembled from parts linearises with every coordinate the parts declare: offsets
//! between joined node fluxes that nothing moves, angles that no output reads. The minimal
//! realisation keeps what the inputs reach and the outputs see
//! ([`minimal_realization`](crate::analysis::control::minimal_realization)); within it, a
//! state is named `δq(c)` or `δv(c)` where, on every state reached from rest, that
//! coordinate's displacement or velocity is a function of the kept part alone (it vanishes on
//! what no output sees), so that the state reads exactly what its name says. The names are chosen in the model's order, positions
//! first, each independent enough of those before it; what no coordinate names is `x[i]`.

use nalgebra::{DMatrix, RowDVector};

use crate::analysis::control::{ControlError, minimal_realization};
use crate::analysis::linear::{Basis, Linearization};
use crate::error::SimError;
use crate::model::Named;

/// A name is taken when its functional keeps at least this share of its length outside those
/// of the names chosen before it, so that the change of basis stays well conditioned.
const INDEPENDENT: f64 = 1e-3;

/// A functional counts as vanishing on the removed directions below this share of its length.
const EXACT: f64 = 1e-9;

impl Linearization {
    /// The same input-output model with only the states the inputs reach and the outputs see
    /// (python-control's and MATLAB's `minreal`), named by the model's coordinates where a
    /// coordinate's displacement or velocity reads a state exactly, then by its outputs
    /// (`δy(name)`, [`Basis::Minimal`]). A
    /// direction counts as reached or seen where its singular value exceeds `tolerance` times the
    /// size of the matrices; `1e-9` suits most models. The poles that remain are the model's
    /// own; those removed belong to states no input moves (offsets between joined coordinates)
    /// or no output sees. A model without inputs keeps no state: nothing reaches one.
    ///
    /// The guide's section on linearisation has an example.
    pub fn minreal<M: Named>(&self, model: &M, tolerance: f64) -> Result<Linearization, SimError> {
        let minimal =
            minimal_realization(&self.a, &self.b, &self.c, &self.d, tolerance).map_err(|e| match e {
                ControlError::Tolerance { .. } => {
                    SimError::InvalidOption { what: "tolerance", reason: e.to_string() }
                }
                other => SimError::InvalidOption { what: "minreal", reason: other.to_string() },
            })?;
        let (names, outputs) = (model.coordinate_names(), model.output_names());
        if names.len() != self.positions.nrows() || outputs.len() != self.c.nrows() {
            return Err(SimError::InvalidOption {
                what: "minreal",
                reason: format!(
                    "the model has {} coordinates and {} outputs, the linearisation {} and {}: pass the \
                     model that was linearised",
                    names.len(),
                    outputs.len(),
                    self.positions.nrows(),
                    self.c.nrows()
                ),
            });
        }
        let to_q = self.position_map();
        let to_v = self.velocity_map(&to_q);
        // A velocity an input sets directly (`Q B` has a nonzero row) is not a function of the
        // state; an output with feedthrough neither.
        let direct = &to_q * &self.b;
        let direct_scale = (to_q.amax() * self.b.amax()).max(f64::MIN_POSITIVE);
        let d_scale = self.d.amax().max(f64::MIN_POSITIVE);
        let candidates: Vec<(String, RowDVector<f64>)> = (0..to_q.nrows())
            .map(|k| (format!("δq({})", names[k]), to_q.row(k).into_owned()))
            .chain(
                (0..to_v.nrows())
                    .filter(|&k| direct.row(k).amax() <= 1e-12 * direct_scale)
                    .map(|k| (format!("δv({})", names[k]), to_v.row(k).into_owned())),
            )
            .chain(
                (0..self.c.nrows())
                    .filter(|&k| self.d.row(k).amax() <= 1e-12 * d_scale)
                    .map(|k| (format!("δy({})", outputs[k]), self.c.row(k).into_owned())),
            )
            .collect();
        let basis = &minimal.basis;
        let r = basis.ncols();
        // The kept part within the controllable subspace, `Vᵀ T`, transposed.
        let seen = basis.transpose() * &minimal.controllable;
        // What each functional reads on the states reached from rest (the controllable
        // subspace); those that read nothing there, to rounding, name nothing.
        let reached: Vec<RowDVector<f64>> =
            candidates.iter().map(|(_, f)| f * &minimal.controllable).collect();
        let largest = reached.iter().map(|f| f.norm()).fold(0.0, f64::max);
        let mut rows: Vec<RowDVector<f64>> = Vec::new();
        let mut state_names: Vec<String> = Vec::new();
        // Orthonormal rows spanning those chosen, restricted to the kept state.
        let mut spanned: Vec<RowDVector<f64>> = Vec::new();
        for ((name, functional), reached) in candidates.into_iter().zip(&reached) {
            if rows.len() == r {
                break;
            }
            // The functional must vanish on what no output sees: then the kept state alone
            // fixes its value.
            let length = reached.norm();
            let restricted = &functional * basis;
            if length <= EXACT * largest || (reached - &restricted * &seen).norm() > EXACT * length {
                continue;
            }
            let residual = outside(restricted.clone(), &spanned);
            let left = residual.norm();
            if left > INDEPENDENT * length {
                spanned.push(residual / left);
                rows.push(restricted);
                state_names.push(name);
            }
        }
        // The rest of the kept state: orthonormal directions no name covers.
        for i in 0..r {
            if rows.len() == r {
                break;
            }
            let residual = outside(RowDVector::from_fn(r, |_, j| if i == j { 1.0 } else { 0.0 }), &spanned);
            let left = residual.norm();
            if left > 0.5 {
                let direction = residual / left;
                spanned.push(direction.clone());
                rows.push(direction);
                state_names
                    .push(format!("x[{}]", state_names.iter().filter(|n| n.starts_with("x[")).count()));
            }
        }
        let to_named = if r == 0 { DMatrix::zeros(0, 0) } else { DMatrix::from_rows(&rows) };
        let from_named = if r == 0 {
            DMatrix::zeros(0, 0)
        } else {
            to_named.clone().try_inverse().ok_or_else(|| SimError::InvalidOption {
                what: "minreal",
                reason: "the named states of the minimal realisation are not independent".into(),
            })?
        };
        Ok(Linearization {
            a: &to_named * &minimal.a * &from_named,
            b: &to_named * &minimal.b,
            c: &minimal.c * &from_named,
            d: minimal.d,
            positions: &to_q * basis * &from_named,
            velocities: to_v * basis * &from_named,
            basis: Basis::Minimal(state_names),
        })
    }

    /// `δq = Q x`.
    fn position_map(&self) -> DMatrix<f64> {
        if matches!(self.basis, Basis::Minimal(_)) {
            return self.positions.clone();
        }
        let (n, nz, nx) = (self.positions.nrows(), self.positions.ncols(), self.a.nrows());
        let mut map = DMatrix::zeros(n, nx);
        map.view_mut((0, 0), (n, nz)).copy_from(&self.positions);
        map
    }

    /// `δv = V x` where no input sets the velocity directly: the rate of `δq = Q x`,
    /// `Q (A x + B δu)`, without its inputs' share.
    fn velocity_map(&self, to_q: &DMatrix<f64>) -> DMatrix<f64> {
        if matches!(self.basis, Basis::Minimal(_)) {
            return self.velocities.clone();
        }
        to_q * &self.a
    }
}

/// What of `row` lies outside the orthonormal rows `spanned` (twice projected out: once loses
/// orthogonality where `row` lies nearly inside them).
fn outside(mut row: RowDVector<f64>, spanned: &[RowDVector<f64>]) -> RowDVector<f64> {
    for _ in 0..2 {
        for s in spanned {
            row -= s * row.dot(s);
        }
    }
    row
}
