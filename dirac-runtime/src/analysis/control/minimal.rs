//! Minimal realisations: the part of a state-space model that the inputs reach and the outputs
//! see (Kalman's decomposition).
//!
//! The controllable subspace is the smallest `A`-invariant subspace holding `range B`; it is
//! grown block by block from `B` (`V₀ = orth B`, then the part of `A Vₖ` outside what is already
//! spanned, kept where its singular values exceed the tolerance), which is the orthogonal
//! staircase of Varga's `ctrbf` written with SVDs. Its orthogonal complement starts at zero and
//! stays there. The observable part of what remains is the same construction on `(Aᵀ, Cᵀ)`: the
//! unobservable subspace is its orthogonal complement, `A`-invariant, and never reaches the
//! outputs. With `T` an orthonormal basis of what is left, `(Tᵀ A T, Tᵀ B, C T, D)` has the same
//! transfer function and is controllable and observable.

use nalgebra::{DMatrix, SVD};

use super::{ControlError, check_model};

/// A minimal realisation of `(A, B, C, D)`, with the map from its state to the original one.
#[derive(Clone, Debug)]
pub struct MinimalRealization {
    /// The state matrix, `r × r`.
    pub a: DMatrix<f64>,
    /// The input matrix, `r × m`.
    pub b: DMatrix<f64>,
    /// The output matrix, `p × r`.
    pub c: DMatrix<f64>,
    /// The feedthrough matrix, unchanged.
    pub d: DMatrix<f64>,
    /// `n × r`, orthonormal columns: the original state's controllable and observable part is
    /// `basis · x`.
    pub basis: DMatrix<f64>,
    /// `n × k`, orthonormal columns: the controllable subspace, where every state reached from
    /// rest lies; `basis` spans its observable part.
    pub controllable: DMatrix<f64>,
}

/// The minimal realisation of `(A, B, C, D)`: the states neither the inputs reach nor the
/// outputs see removed. A direction counts as reached (or seen) where its singular value
/// exceeds `tolerance` times the size of the matrices it comes from (`‖A‖`, `‖B‖`, `‖C‖`);
/// `1e-9` suits models whose entries are within a few decades of one another. Same transfer
/// function, fewer states: python-control's `minreal` and MATLAB's do the same.
///
/// ```
/// use dirac_runtime::analysis::control;
/// use dirac_runtime::nalgebra::DMatrix;
///
/// // Two decoupled first-order lags; the input drives only the first, the output reads both.
/// let a = DMatrix::from_row_slice(2, 2, &[-1.0, 0.0, 0.0, -3.0]);
/// let b = DMatrix::from_column_slice(2, 1, &[1.0, 0.0]);
/// let c = DMatrix::from_row_slice(1, 2, &[1.0, 1.0]);
/// let minimal = control::minimal_realization(&a, &b, &c, &DMatrix::zeros(1, 1), 1e-9)?;
/// assert_eq!(minimal.a.nrows(), 1);
/// assert!((minimal.a[(0, 0)] + 1.0).abs() < 1e-15);
/// # Ok::<(), control::ControlError>(())
/// ```
pub fn minimal_realization(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    c: &DMatrix<f64>,
    d: &DMatrix<f64>,
    tolerance: f64,
) -> Result<MinimalRealization, ControlError> {
    check_model(a, b, c, d)?;
    if !(tolerance.is_finite() && tolerance > 0.0 && tolerance < 1.0) {
        return Err(ControlError::Tolerance { tolerance });
    }
    let controllable = krylov_basis(a, b, tolerance);
    let (ac, cc) = (controllable.transpose() * a * &controllable, c * &controllable);
    let observable = krylov_basis(&ac.transpose(), &cc.transpose(), tolerance);
    let basis = &controllable * &observable;
    Ok(MinimalRealization {
        a: basis.transpose() * a * &basis,
        b: basis.transpose() * b,
        c: c * &basis,
        d: d.clone(),
        basis,
        controllable,
    })
}

/// An orthonormal basis of the smallest `A`-invariant subspace holding `range B`, each block's
/// new directions kept where their singular values exceed `tolerance · scale` (`scale` is
/// `‖B‖` for the first block and `‖A‖` after it, whose blocks are `A` times orthonormal columns).
fn krylov_basis(a: &DMatrix<f64>, b: &DMatrix<f64>, tolerance: f64) -> DMatrix<f64> {
    let n = a.nrows();
    let mut basis: Vec<nalgebra::DVector<f64>> = Vec::new();
    let norm_a = a.norm();
    let mut block = b.clone();
    let mut scale = b.norm();
    while basis.len() < n && block.ncols() > 0 {
        // Twice against what is spanned already: once loses orthogonality where the block lies
        // nearly inside it.
        for _ in 0..2 {
            for v in &basis {
                let along = v.transpose() * &block;
                block -= v * along;
            }
        }
        let svd = SVD::new(block.clone(), true, false);
        let u = svd.u.as_ref().expect("asked for U");
        let threshold = tolerance * scale.max(f64::MIN_POSITIVE);
        let new: Vec<_> = (0..svd.singular_values.len())
            .filter(|&i| svd.singular_values[i] > threshold)
            .map(|i| u.column(i).into_owned())
            .take(n - basis.len())
            .collect();
        if new.is_empty() {
            break;
        }
        let fresh = DMatrix::from_columns(&new);
        basis.extend(new);
        block = a * fresh;
        scale = norm_a;
    }
    if basis.is_empty() { DMatrix::zeros(n, 0) } else { DMatrix::from_columns(&basis) }
}
