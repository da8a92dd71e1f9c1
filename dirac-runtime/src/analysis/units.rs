//! A model's own units: diagonal scalings of the velocities and of the constraint rows under
//! which its inertia has a unit diagonal wherever there is some, and its constraint rows have
//! a largest entry about 1. The rank decisions of a start (which velocities inertia fixes,
//! which are left to the forces, whether the multipliers are determined) are taken on the
//! scaled blocks, so that they do not depend on the units a model is written in: a capacitor
//! of 1 pF is inertia as a capacitor of 1 F is, and a network that mixes them keeps both.
//!
//! Coordinates that a row makes aliases (`x_i = ρ x_j`, a connection of two ports, a gear)
//! move as one and are measured in one unit: their class's, from the inertia of their common
//! motion `Σ ρ_i L_ij ρ_j`. Otherwise a connection between a pin of 1 pF and a pin without
//! capacitance would be a row whose entries differ by the square root of 1e12, and the joined
//! node would look as if it had no inertia.

use nalgebra::{DMatrix, DVector};

/// Equilibration sweeps: Ruiz's iteration brings every row within a factor of 2 of 1 in a few
/// sweeps; the bound only keeps a pathological matrix from looping.
const SWEEPS: usize = 40;

/// An entry of `L_vv` (of `A`) below this times the block's largest is round-off of a
/// cancellation, not inertia (not a constraint's one-form).
const NOISE: f64 = 4.0 * f64::EPSILON;

/// The scalings `D_v` (one per velocity) and `D_c` (one per constraint row): the scaled blocks
/// are `L' = D_v L_vv D_v` and `A' = D_c A D_v`, and a solution `(x', y')` of a system in them
/// is `(D_v x', D_c y')` in the model's units.
#[derive(Clone, Debug)]
pub(crate) struct Units {
    /// `D_v`: a velocity's unit is `1 / D_v` of the model's.
    pub velocity: DVector<f64>,
    /// `D_c`: a constraint row's scaling.
    pub row: DVector<f64>,
}

/// The coordinates that alias rows tie together: each coordinate's class (its root) and its
/// ratio to the root, `x_i = ratio_i x_root`.
struct Classes {
    root: Vec<usize>,
    ratio: Vec<f64>,
}

impl Classes {
    /// The classes of the rows of `a` with exactly two entries (`a_i x_i + a_j x_j = 0`):
    /// union by rows, a row that would close a loop with another ratio left out.
    fn of(a: &DMatrix<f64>, floor: f64) -> Classes {
        let n = a.ncols();
        let mut classes = Classes { root: (0..n).collect(), ratio: vec![1.0; n] };
        for k in 0..a.nrows() {
            let mut entries = (0..n).filter(|&j| a[(k, j)].abs() > floor);
            let (Some(i), Some(j), None) = (entries.next(), entries.next(), entries.next()) else {
                continue;
            };
            // x_i = r x_j.
            let r = -a[(k, j)] / a[(k, i)];
            let ((ri, ci), (rj, cj)) = (classes.find(i), classes.find(j));
            if ri != rj {
                // x_i = ci x_ri and x_j = cj x_rj, so x_ri = (r cj / ci) x_rj.
                classes.root[ri] = rj;
                classes.ratio[ri] = r * cj / ci;
            }
        }
        for i in 0..n {
            let (root, ratio) = classes.find(i);
            (classes.root[i], classes.ratio[i]) = (root, ratio);
        }
        classes
    }

    /// The root of `i`'s class and `i`'s ratio to it.
    fn find(&self, mut i: usize) -> (usize, f64) {
        let mut ratio = 1.0;
        while self.root[i] != i {
            ratio *= self.ratio[i];
            i = self.root[i];
        }
        (i, ratio)
    }
}

impl Units {
    /// The scalings of finite blocks: each class of aliases whose common motion has inertia
    /// `I` is measured in `1/√I` of it (a lone coordinate's `1/√L_ii`, Jacobi's scaling); then
    /// Ruiz's equilibration of `A` over its rows and the classes without inertia. A velocity
    /// with neither inertia nor a constraint keeps the model's unit.
    pub fn of(lvv: &DMatrix<f64>, a: &DMatrix<f64>) -> Units {
        let (n, m) = (lvv.nrows(), a.nrows());
        let floor_a = NOISE * a.amax();
        let classes = Classes::of(a, floor_a);
        // The inertia of each class's common motion, at its root: Σ ρ_i L_ij ρ_j.
        let mut inertia = vec![0.0; n];
        for i in 0..n {
            for j in 0..n {
                if classes.root[i] == classes.root[j] {
                    inertia[classes.root[i]] += classes.ratio[i] * lvv[(i, j)] * classes.ratio[j];
                }
            }
        }
        let floor_l = NOISE * lvv.amax();
        let inertial = |i: usize| inertia[classes.root[i]] > floor_l;
        // A member's unit is its ratio times its class's: x_i' = x_root'.
        let mut class_scale: Vec<f64> =
            inertia.iter().map(|&c| if c > floor_l { c.sqrt().recip() } else { 1.0 }).collect();
        let mut units = Units { velocity: DVector::from_element(n, 1.0), row: DVector::from_element(m, 1.0) };
        let (mut rows, mut columns) = (vec![0.0; m], vec![0.0; n]);
        for _ in 0..SWEEPS {
            for i in 0..n {
                units.velocity[i] = classes.ratio[i].abs() * class_scale[classes.root[i]];
            }
            rows.fill(0.0);
            columns.fill(0.0);
            for j in 0..n {
                for k in 0..m {
                    let x = a[(k, j)].abs();
                    if x > floor_a {
                        let scaled = x * units.row[k] * units.velocity[j];
                        rows[k] = f64::max(rows[k], scaled);
                        let c = &mut columns[classes.root[j]];
                        *c = f64::max(*c, scaled);
                    }
                }
            }
            let free = (0..n).filter(|&r| classes.root[r] == r && !inertial(r));
            let settled = |r: f64| r == 0.0 || (0.5..=2.0).contains(&r);
            if rows.iter().all(|&r| settled(r)) && free.clone().all(|r| settled(columns[r])) {
                break;
            }
            for (d, &r) in units.row.iter_mut().zip(&rows) {
                if r > 0.0 {
                    *d /= r.sqrt();
                }
            }
            for r in free {
                if columns[r] > 0.0 {
                    class_scale[r] /= columns[r].sqrt();
                }
            }
        }
        units
    }

    /// `D_v L D_v`.
    pub fn lvv(&self, lvv: &DMatrix<f64>) -> DMatrix<f64> {
        let d = &self.velocity;
        DMatrix::from_fn(lvv.nrows(), lvv.ncols(), |i, j| d[i] * lvv[(i, j)] * d[j])
    }

    /// `D_c A D_v`.
    pub fn a(&self, a: &DMatrix<f64>) -> DMatrix<f64> {
        DMatrix::from_fn(a.nrows(), a.ncols(), |k, j| self.row[k] * a[(k, j)] * self.velocity[j])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A node of 1 F, a node of 1 pF and a node without capacitance joined to the second (an
    /// alias row), and a row over all three: the scaled inertia has a unit diagonal where
    /// there is inertia, the joined node is measured in its class's unit (the alias row's
    /// scaled entries are equal), and each row's largest entry is within a factor of 2 of 1,
    /// whatever the units.
    #[test]
    fn mixed_capacitors_equilibrate_to_one() {
        for unit in [1.0, 1e-12, 1e9] {
            let lvv = DMatrix::from_row_slice(3, 3, &[unit, 0.0, 0.0, 0.0, 1e-12 * unit, 0.0, 0.0, 0.0, 0.0]);
            let a = DMatrix::from_row_slice(2, 3, &[0.0, 1.0, -1.0, 1.0, 2.0, 3.0]);
            let units = Units::of(&lvv, &a);
            let (l, a) = (units.lvv(&lvv), units.a(&a));
            assert!(
                (l.diagonal() - DVector::from_row_slice(&[1.0, 1.0, 0.0])).amax() < 1e-12,
                "unit {unit}: {l}"
            );
            assert!((a[(0, 1)] + a[(0, 2)]).abs() < 1e-12 * a[(0, 1)].abs(), "unit {unit}: {a}");
            for k in 0..2 {
                assert!((0.5..=2.0).contains(&a.row(k).amax()), "unit {unit}: row {k} of {a}");
            }
        }
    }

    /// Two pins joined by a gear's row `x₀ = 4 x₁`, one with inertia: the class's unit is the
    /// inertia of the common motion, `16 J₀ + J₁`, and the scaled row's entries are equal.
    #[test]
    fn a_gear_is_one_class() {
        let lvv = DMatrix::from_row_slice(2, 2, &[2.0, 0.0, 0.0, 0.0]);
        let a = DMatrix::from_row_slice(1, 2, &[1.0, -4.0]);
        let units = Units::of(&lvv, &a);
        // The common motion x₁: kinetic energy ½ · 2 · 16 x₁'², so x₁ is measured in 1/√32.
        assert!((units.velocity[1] - 32f64.sqrt().recip()).abs() < 1e-15, "{units:?}");
        assert!((units.velocity[0] - 4.0 * 32f64.sqrt().recip()).abs() < 1e-15, "{units:?}");
        let a = units.a(&a);
        assert!((a[(0, 0)] + a[(0, 1)]).abs() < 1e-15, "{a}");
    }

    /// A velocity without inertia or constraint keeps its unit; a row of round-off is no
    /// inertia.
    #[test]
    fn zero_and_round_off_rows_stay_unscaled() {
        let lvv = DMatrix::from_row_slice(3, 3, &[2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1e-17]);
        let a = DMatrix::zeros(0, 3);
        let units = Units::of(&lvv, &a);
        assert!((units.velocity[0] - 2f64.sqrt().recip()).abs() < 1e-15);
        assert_eq!(units.velocity[1], 1.0);
        assert_eq!(units.velocity[2], 1.0);
    }
}
