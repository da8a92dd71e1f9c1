//! The Radau IIA method of order 5 (three stages) and the transformation that splits its
//! stage system into one real and one complex system (Hairer & Wanner, *Solving Ordinary
//! Differential Equations II*, §IV.8; the constants of their RADAU5 code).

/// `√6`.
const SQ6: f64 = 2.449_489_742_783_178;

/// The nodes `c_i`.
pub const C1: f64 = (4.0 - SQ6) / 10.0;
/// Second node.
pub const C2: f64 = (4.0 + SQ6) / 10.0;
/// Third node (the step end).
pub const C3: f64 = 1.0;

/// Weights of the embedded error estimate, times `h`: `e_i h = dd_i`.
pub const DD1: f64 = -(13.0 + 7.0 * SQ6) / 3.0;
/// Second weight.
pub const DD2: f64 = (-13.0 + 7.0 * SQ6) / 3.0;
/// Third weight.
pub const DD3: f64 = -1.0 / 3.0;

/// The Butcher matrix `A` of Radau IIA, order 5, in closed form.
pub const A: [[f64; 3]; 3] = [
    [(88.0 - 7.0 * SQ6) / 360.0, (296.0 - 169.0 * SQ6) / 1800.0, (-2.0 + 3.0 * SQ6) / 225.0],
    [(296.0 + 169.0 * SQ6) / 1800.0, (88.0 + 7.0 * SQ6) / 360.0, (-2.0 - 3.0 * SQ6) / 225.0],
    [(16.0 - SQ6) / 36.0, (16.0 + SQ6) / 36.0, 1.0 / 9.0],
];

/// The eigenvalues of `A⁻¹`: the real `γ` and the complex pair `α ± iβ`.
#[derive(Clone, Copy)]
pub struct Eigen {
    pub gamma: f64,
    pub alpha: f64,
    pub beta: f64,
}

impl Eigen {
    /// `γ/h`, `α/h`, `β/h`: the shifts of a step of size `h`, formed once a step rather than in
    /// every iteration.
    pub fn over(&self, h: f64) -> Eigen {
        Eigen { gamma: self.gamma / h, alpha: self.alpha / h, beta: self.beta / h }
    }
}

/// `γ`, `α`, `β` from their closed forms.
pub fn eigen() -> Eigen {
    let (c81, c9) = (81f64.cbrt(), 9f64.cbrt());
    let u1 = (6.0 + c81 - c9) / 30.0;
    let alph = (12.0 - c81 + c9) / 60.0;
    let beta = (c81 + c9) * 3f64.sqrt() / 60.0;
    let cno = alph * alph + beta * beta;
    Eigen { gamma: 1.0 / u1, alpha: alph / cno, beta: beta / cno }
}

/// `T`, whose columns are the (real and imaginary parts of the) eigenvectors of `A⁻¹`.
pub const T: [[f64; 3]; 3] = [
    [0.09123239487089295, -0.1412552950209542, -0.030029194105147424],
    [0.241717932707107, 0.20412935229379994, 0.3829421127572619],
    [0.966048182615093, 1.0, 0.0],
];

/// `T⁻¹`.
pub const TI: [[f64; 3]; 3] = [
    [4.325579890063155, 0.33919925181580984, 0.5417705399358749],
    [-4.178718591551904, -0.32768282076106237, 0.47662355450055044],
    [-0.5028726349457869, 2.571926949855605, -0.5960392048282249],
];

#[cfg(test)]
mod tests {
    use nalgebra::Matrix3;

    use super::*;

    fn butcher() -> Matrix3<f64> {
        Matrix3::from_fn(|i, j| A[i][j])
    }

    #[test]
    fn nodes_are_the_row_sums() {
        let a = butcher();
        for (i, c) in [C1, C2, C3].iter().enumerate() {
            assert!((a.row(i).sum() - c).abs() < 1e-15);
        }
    }

    /// `T⁻¹ A⁻¹ T = [[γ, 0, 0], [0, α, −β], [0, β, α]]`, and `T⁻¹` inverts `T`.
    #[test]
    fn transformation_block_diagonalises_the_inverse_butcher_matrix() {
        let t = Matrix3::from_fn(|i, j| T[i][j]);
        let ti = Matrix3::from_fn(|i, j| TI[i][j]);
        assert!((t * ti - Matrix3::identity()).amax() < 1e-14);
        let a_inv = butcher().try_inverse().expect("A is invertible");
        let d = ti * a_inv * t;
        let e = eigen();
        let expected = Matrix3::new(e.gamma, 0.0, 0.0, 0.0, e.alpha, -e.beta, 0.0, e.beta, e.alpha);
        assert!((d - expected).amax() < 1e-12, "{d}");
    }
}
