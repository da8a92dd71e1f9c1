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
        let (to_q, to_v) = self.coordinate_maps();
        let names = model.coordinate_names();
        // Outputs without feedthrough read the state alone, after the coordinates.
        let outputs = model.output_names();
        let d_scale = self.d.amax();
        let read = (0..self.c.nrows())
            .filter(|&k| self.d.row(k).amax() <= 1e-12 * d_scale.max(f64::MIN_POSITIVE))
            .map(|k| (format!("δy({})", outputs[k]), self.c.row(k).into_owned()));
        let candidates: Vec<(String, RowDVector<f64>)> = (0..to_q.nrows())
            .map(|k| (format!("δq({})", names[k]), to_q.row(k).into_owned()))
            .chain(to_v.iter().map(|(k, row)| (format!("δv({})", names[*k]), row.clone())))
            .chain(read)
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
        let mut chosen: Vec<(String, RowDVector<f64>)> = Vec::new();
        // Orthonormal rows spanning the chosen functionals, restricted to the kept state.
        let mut spanned: Vec<RowDVector<f64>> = Vec::new();
        for ((name, functional), reached) in candidates.into_iter().zip(&reached) {
            if chosen.len() == r {
                break;
            }
            // The functional must vanish on what no output sees: then the kept state alone
            // fixes its value.
            let length = reached.norm();
            let restricted = &functional * basis;
            if length <= EXACT * largest || (reached - &restricted * &seen).norm() > EXACT * length {
                continue;
            }
            let mut residual = restricted.clone();
            for _ in 0..2 {
                for row in &spanned {
                    residual -= row * (residual.dot(row));
                }
            }
            let left = residual.norm();
            if left > INDEPENDENT * length {
                spanned.push(residual / left);
                chosen.push((name, restricted));
            }
        }
        // The rest of the kept state: orthonormal directions no name covers.
        let mut rows: Vec<RowDVector<f64>> = chosen.iter().map(|(_, row)| row.clone()).collect();
        let mut state_names: Vec<String> = chosen.into_iter().map(|(name, _)| name).collect();
        let mut unnamed = 0;
        for i in 0..r {
            if rows.len() == r {
                break;
            }
            let mut residual = RowDVector::from_fn(r, |_, j| if i == j { 1.0 } else { 0.0 });
            for _ in 0..2 {
                for row in &spanned {
                    residual -= row * (residual.dot(row));
                }
            }
            let left = residual.norm();
            if left > 0.5 {
                let direction = residual / left;
                spanned.push(direction.clone());
                rows.push(direction);
                state_names.push(format!("x[{unnamed}]"));
                unnamed += 1;
            }
        }
        let to_named = if rows.is_empty() { DMatrix::zeros(0, 0) } else { DMatrix::from_rows(&rows) };
        let Some(from_named) = to_named.clone().try_inverse() else {
            return Err(SimError::InvalidOption {
                what: "minreal",
                reason: "the named states of the minimal realisation are not independent".into(),
            });
        };
        let from_named = if r == 0 { DMatrix::zeros(0, 0) } else { from_named };
        Ok(Linearization {
            a: &to_named * &minimal.a * &from_named,
            b: &to_named * &minimal.b,
            c: &minimal.c * &from_named,
            d: minimal.d,
            positions: &to_q * basis * &from_named,
            velocities: self.velocity_map() * basis * &from_named,
            basis: Basis::Minimal(state_names),
        })
    }

    /// The displacements `δq = Q x` of every coordinate as functionals of the state, and the
    /// velocities `δv = V x` of those whose velocity no input sets directly (by coordinate).
    fn coordinate_maps(&self) -> (DMatrix<f64>, Vec<(usize, RowDVector<f64>)>) {
        let to_q = self.position_map();
        let to_v = self.velocity_map();
        let free = self.velocity_free_of_inputs();
        let rows = (0..to_v.nrows()).filter(|&k| free[k]).map(|k| (k, to_v.row(k).into_owned())).collect();
        (to_q, rows)
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

    /// `δv = V x` for the coordinates [`Linearization::velocity_free_of_inputs`] marks: the rate
    /// of `δq = Q x`, `Q (A x + B δu)`.
    fn velocity_map(&self) -> DMatrix<f64> {
        if matches!(self.basis, Basis::Minimal(_)) {
            return self.velocities.clone();
        }
        self.position_map() * &self.a
    }

    /// Which coordinates' velocities no input sets directly (`Q B` has a zero row).
    fn velocity_free_of_inputs(&self) -> Vec<bool> {
        let to_q = self.position_map();
        let direct = &to_q * &self.b;
        let scale = (to_q.amax() * self.b.amax()).max(f64::MIN_POSITIVE);
        (0..to_q.nrows()).map(|k| direct.row(k).amax() <= 1e-12 * scale).collect()
    }
}
