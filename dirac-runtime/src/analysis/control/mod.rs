//! Control design on a linear model `ẋ = A x + B u`, `y = C x + D u`: the exact linearisation
//! [`linearize`](crate::linearize) gives, or any other.
//!
//! - [`zero_order_hold`]: the sampled model under an input held between samples (exact, by the
//!   matrix exponential).
//! - [`lqr`] and [`dlqr`]: the linear-quadratic regulator, continuous and discrete, with the
//!   Riccati solution and its residual.
//! - [`place`]: the gain that puts the poles of a single-input model where they are asked for.
//! - [`controllability_matrix`], [`observability_matrix`], [`rank`]: which states the inputs
//!   move and the outputs see.
//! - [`minimal_realization`]: the states the inputs reach and the outputs see, and no others.
//! - [`poles`], [`zeros`]: the eigenvalues of `A`, and the zeros of a single-input,
//!   single-output model.
//! - [`frequency_response`] (Bode data) and [`step_response`], both exact.
//! - [`Pid`]: a sampled PID controller with a filtered derivative and anti-windup.
//!
//! Matrices are `DMatrix<f64>`, as [`Linearization`](crate::Linearization) holds them.
//!
//! ```
//! use dirac_runtime::analysis::control;
//! use dirac_runtime::nalgebra::DMatrix;
//!
//! // A double integrator (position, velocity) pushed by a force.
//! let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, 0.0]);
//! let b = DMatrix::from_column_slice(2, 1, &[0.0, 1.0]);
//! let design = control::lqr(&a, &b, &DMatrix::identity(2, 2), &DMatrix::identity(1, 1))?;
//! // The closed form: K = [1, √3].
//! assert!((design.gain[(0, 0)] - 1.0).abs() < 1e-12);
//! assert!((design.gain[(0, 1)] - 3f64.sqrt()).abs() < 1e-12);
//! assert!(design.poles.iter().all(|p| p.re < 0.0));
//! assert!(design.residual < 1e-14);
//! # Ok::<(), control::ControlError>(())
//! ```

mod minimal;
mod pid;
mod response;
mod riccati;

pub use minimal::{MinimalRealization, minimal_realization};
pub use pid::Pid;
pub use response::{FrequencyResponse, StepResponse, frequency_response, step_response};
pub use riccati::{Lqr, dlqr, lqr};

use nalgebra::{Complex, DMatrix};

/// Why a control design or analysis could not be carried out.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ControlError {
    /// A matrix has the wrong number of rows or columns for the others.
    #[error("{what}: {reason}")]
    Shape {
        /// The matrix.
        what: &'static str,
        /// What its size should be.
        reason: String,
    },
    /// A matrix holds a NaN or an infinity.
    #[error("{what} holds a non-finite entry ({value}) at row {row}, column {column}")]
    NotFinite {
        /// The matrix.
        what: &'static str,
        /// Its entry.
        value: f64,
        /// The entry's row.
        row: usize,
        /// The entry's column.
        column: usize,
    },
    /// A weight is not symmetric, or not positive (semi)definite as the design needs.
    #[error("the weight {what} {reason}")]
    Weight {
        /// The weight (`Q` or `R`).
        what: &'static str,
        /// What is wrong with it.
        reason: String,
    },
    /// The inputs cannot move every state.
    #[error(
        "the inputs cannot move every state: the controllability matrix has rank {rank} of {states}, so \
         no gain places every pole"
    )]
    NotControllable {
        /// The rank of `[B, AB, …, Aⁿ⁻¹B]`.
        rank: usize,
        /// The number of states.
        states: usize,
    },
    /// The Riccati equation has no solution that stabilises the loop.
    #[error("no gain stabilises the loop ({equation} Riccati equation): {reason}")]
    NoStabilisingSolution {
        /// `"continuous"` or `"discrete"`.
        equation: &'static str,
        /// What failed.
        reason: String,
    },
    /// A relative tolerance outside `(0, 1)`.
    #[error("the tolerance {tolerance:e} is not a relative tolerance: give one in (0, 1), such as 1e-9")]
    Tolerance {
        /// The tolerance given.
        tolerance: f64,
    },
    /// The asked poles are not closed under complex conjugation, so no real gain places them.
    #[error("the poles asked for are not in conjugate pairs: {pole} has no conjugate among them")]
    UnpairedPole {
        /// The pole without its conjugate.
        pole: Complex<f64>,
    },
    /// A frequency at which the model has a pole: its response there is infinite.
    #[error("the frequency ω = {frequency} rad/s is a pole of the model: its response there is infinite")]
    AtPole {
        /// The frequency, in rad/s.
        frequency: f64,
    },
}

/// The controllability matrix `[B, AB, A²B, …, Aⁿ⁻¹B]` (`n × n m`).
pub fn controllability_matrix(a: &DMatrix<f64>, b: &DMatrix<f64>) -> Result<DMatrix<f64>, ControlError> {
    let n = square("A", a)?;
    rows("B", b, n)?;
    let m = b.ncols();
    let mut matrix = DMatrix::zeros(n, n * m);
    let mut block = b.clone();
    for k in 0..n {
        matrix.view_mut((0, k * m), (n, m)).copy_from(&block);
        block = a * &block;
    }
    Ok(matrix)
}

/// The observability matrix `[C; CA; CA²; …; CAⁿ⁻¹]` (`n p × n`).
pub fn observability_matrix(a: &DMatrix<f64>, c: &DMatrix<f64>) -> Result<DMatrix<f64>, ControlError> {
    let n = square("A", a)?;
    columns("C", c, n)?;
    let p = c.nrows();
    let mut matrix = DMatrix::zeros(n * p, n);
    let mut block = c.clone();
    for k in 0..n {
        matrix.view_mut((k * p, 0), (p, n)).copy_from(&block);
        block = &block * a;
    }
    Ok(matrix)
}

/// The numerical rank of `matrix`: its singular values above `max(rows, columns) · ε · σ_max`.
pub fn rank(matrix: &DMatrix<f64>) -> usize {
    if matrix.is_empty() {
        return 0;
    }
    let singular = matrix.singular_values();
    let largest = singular.max();
    let tolerance = matrix.nrows().max(matrix.ncols()) as f64 * f64::EPSILON * largest;
    singular.iter().filter(|&&s| s > tolerance).count()
}

/// The eigenvalues of `A`, sorted by real part, then imaginary part.
pub fn poles(a: &DMatrix<f64>) -> Result<Vec<Complex<f64>>, ControlError> {
    square("A", a)?;
    finite("A", a)?;
    Ok(sorted(a.complex_eigenvalues().iter().copied().collect()))
}

/// The zeros of the transfer function from input `input` to output `output`,
/// `C (sI − A)⁻¹ B + D`: the roots of its numerator, sorted as [`poles`] are.
///
/// The numerator's coefficients come from the Markov parameters `C Aᵏ B` and the coefficients
/// of `det(sI − A)` (Leverrier's recursion), so a structural zero such as `CB = 0` is exact.
/// Zeros that cancel poles are kept, as a transfer function from a minimal realisation would
/// not show them.
pub fn zeros(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    c: &DMatrix<f64>,
    d: &DMatrix<f64>,
    output: usize,
    input: usize,
) -> Result<Vec<Complex<f64>>, ControlError> {
    let n = check_model(a, b, c, d)?;
    index("input", input, b.ncols())?;
    index("output", output, c.nrows())?;
    let (b, c) = (b.column(input).into_owned(), c.row(output).into_owned());
    // det(sI − A) = sⁿ + a₁ sⁿ⁻¹ + … + aₙ and adj(sI − A) = Σₖ sⁿ⁻¹⁻ᵏ Nₖ with N₀ = I,
    // Nₖ = A Nₖ₋₁ + aₖ I, aₖ = −tr(A Nₖ₋₁) / k.
    let mut numerator = vec![d[(output, input)]];
    let mut adjugate = DMatrix::<f64>::identity(n, n);
    let mut scale = d[(output, input)].abs();
    for k in 1..=n {
        let coefficient = (&c * &adjugate * &b)[(0, 0)];
        scale = scale.max(c.norm() * adjugate.norm() * b.norm());
        let product = a * &adjugate;
        let ak = -product.trace() / k as f64;
        // sⁿ⁻ᵏ: C Nₖ₋₁ B and d aₖ, from d·det(sI − A).
        numerator.push(coefficient + d[(output, input)] * ak);
        adjugate = product + DMatrix::identity(n, n) * ak;
    }
    // Leading coefficients that vanish to round-off lower the degree.
    let first = numerator.iter().position(|x| x.abs() > 1e-12 * scale.max(f64::MIN_POSITIVE));
    let Some(first) = first else {
        return Ok(Vec::new());
    };
    Ok(roots(&numerator[first..]))
}

/// The roots of `c₀ sᵏ + c₁ sᵏ⁻¹ + … + cₖ` (`c₀ ≠ 0`), as eigenvalues of the companion matrix.
fn roots(coefficients: &[f64]) -> Vec<Complex<f64>> {
    let degree = coefficients.len() - 1;
    if degree == 0 {
        return Vec::new();
    }
    let companion = DMatrix::from_fn(degree, degree, |i, j| {
        if i == 0 {
            -coefficients[j + 1] / coefficients[0]
        } else if i == j + 1 {
            1.0
        } else {
            0.0
        }
    });
    sorted(companion.complex_eigenvalues().iter().copied().collect())
}

/// The gain `K` (`1 × n`) of `u = −K x` that gives `A − B K` the eigenvalues `poles`, for a model
/// with one input (Ackermann's formula, `K = eₙᵀ 𝒞⁻¹ φ(A)` with `φ` the polynomial whose roots
/// are `poles`). Complex poles come in conjugate pairs.
///
/// Ackermann's formula loses accuracy as the controllability matrix's condition number grows;
/// the gain is for models of a few states.
pub fn place(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    poles: &[Complex<f64>],
) -> Result<DMatrix<f64>, ControlError> {
    let n = square("A", a)?;
    rows("B", b, n)?;
    finite("A", a)?;
    finite("B", b)?;
    if b.ncols() != 1 {
        return Err(ControlError::Shape {
            what: "B",
            reason: format!("pole placement here is for one input, but B has {} columns", b.ncols()),
        });
    }
    if n == 0 {
        return Err(ControlError::Shape {
            what: "A",
            reason: "pole placement needs a model with states".into(),
        });
    }
    if poles.len() != n {
        return Err(ControlError::Shape {
            what: "poles",
            reason: format!("{} poles asked for a model of {n} states: ask for {n}", poles.len()),
        });
    }
    for pole in poles {
        if !(pole.re.is_finite() && pole.im.is_finite()) {
            return Err(ControlError::Shape {
                what: "poles",
                reason: format!("the pole {pole} is not finite"),
            });
        }
        let paired = pole.im == 0.0
            || poles.iter().any(|other| (other - pole.conj()).norm() <= 1e-12 * pole.norm().max(1.0));
        if !paired {
            return Err(ControlError::UnpairedPole { pole: *pole });
        }
    }
    let controllability = controllability_matrix(a, b)?;
    let rank = rank(&controllability);
    if rank < n {
        return Err(ControlError::NotControllable { rank, states: n });
    }
    // φ(s) = Π (s − pᵢ) = sⁿ + φ₁ sⁿ⁻¹ + … + φₙ: its coefficients are real for conjugate pairs.
    let mut polynomial = vec![Complex::new(1.0, 0.0)];
    for pole in poles {
        let mut next = polynomial.clone();
        next.push(Complex::new(0.0, 0.0));
        for (k, coefficient) in polynomial.iter().enumerate() {
            next[k + 1] -= coefficient * pole;
        }
        polynomial = next;
    }
    // φ(A) by Horner's rule.
    let mut phi = DMatrix::<f64>::zeros(n, n);
    for coefficient in &polynomial {
        phi = a * &phi + DMatrix::identity(n, n) * coefficient.re;
    }
    let mut last = nalgebra::DVector::zeros(n);
    last[n - 1] = 1.0;
    let selector = controllability
        .transpose()
        .lu()
        .solve(&last)
        .ok_or(ControlError::NotControllable { rank: n - 1, states: n })?;
    let gain = selector.transpose() * phi;
    Ok(DMatrix::from_row_slice(1, n, gain.as_slice()))
}

/// `values` sorted by real part, then imaginary part.
pub(crate) fn sorted(mut values: Vec<Complex<f64>>) -> Vec<Complex<f64>> {
    values.sort_by(|x, y| x.re.total_cmp(&y.re).then(x.im.total_cmp(&y.im)));
    values
}

/// The size of the square matrix `m`.
pub(crate) fn square(what: &'static str, m: &DMatrix<f64>) -> Result<usize, ControlError> {
    if m.nrows() != m.ncols() {
        return Err(ControlError::Shape {
            what,
            reason: format!("must be square, but is {} × {}", m.nrows(), m.ncols()),
        });
    }
    Ok(m.nrows())
}

/// Checks that `m` has `n` rows.
pub(crate) fn rows(what: &'static str, m: &DMatrix<f64>, n: usize) -> Result<(), ControlError> {
    if m.nrows() != n {
        return Err(ControlError::Shape {
            what,
            reason: format!("must have {n} rows (A's), but has {}", m.nrows()),
        });
    }
    Ok(())
}

/// Checks that `m` has `n` columns.
pub(crate) fn columns(what: &'static str, m: &DMatrix<f64>, n: usize) -> Result<(), ControlError> {
    if m.ncols() != n {
        return Err(ControlError::Shape {
            what,
            reason: format!("must have {n} columns (A's rows), but has {}", m.ncols()),
        });
    }
    Ok(())
}

/// Checks that every entry of `m` is finite.
pub(crate) fn finite(what: &'static str, m: &DMatrix<f64>) -> Result<(), ControlError> {
    match m.iter().position(|x| !x.is_finite()) {
        None => Ok(()),
        Some(at) => {
            Err(ControlError::NotFinite { what, value: m[at], row: at % m.nrows(), column: at / m.nrows() })
        }
    }
}

/// Checks that `index` names one of `count` inputs or outputs.
pub(crate) fn index(what: &'static str, index: usize, count: usize) -> Result<(), ControlError> {
    if index >= count {
        return Err(ControlError::Shape {
            what,
            reason: format!("index {index}, but the model has {count}"),
        });
    }
    Ok(())
}

/// Checks that `(A, B, C, D)` fit together and are finite; returns the number of states.
pub(crate) fn check_model(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    c: &DMatrix<f64>,
    d: &DMatrix<f64>,
) -> Result<usize, ControlError> {
    let n = square("A", a)?;
    rows("B", b, n)?;
    columns("C", c, n)?;
    if d.nrows() != c.nrows() || d.ncols() != b.ncols() {
        return Err(ControlError::Shape {
            what: "D",
            reason: format!(
                "must be {} × {} (C's rows × B's columns), but is {} × {}",
                c.nrows(),
                b.ncols(),
                d.nrows(),
                d.ncols()
            ),
        });
    }
    for (what, m) in [("A", a), ("B", b), ("C", c), ("D", d)] {
        finite(what, m)?;
    }
    Ok(n)
}

/// The zero-order-hold discretisation of `ẋ = A x + B u` over the sample time `dt`: with `u`
/// held between samples, `x_{k+1} = A_d x_k + B_d u_k` exactly, where `[[A_d, B_d], [0, I]]` is
/// the matrix exponential of `[[A, B], [0, 0]] dt`.
pub fn zero_order_hold(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    dt: f64,
) -> Result<(DMatrix<f64>, DMatrix<f64>), ControlError> {
    let n = square("A", a)?;
    rows("B", b, n)?;
    finite("A", a)?;
    finite("B", b)?;
    if !(dt.is_finite() && dt > 0.0) {
        return Err(ControlError::Shape {
            what: "dt",
            reason: format!("the sample time must be positive, not {dt}"),
        });
    }
    let m = b.ncols();
    let mut augmented = DMatrix::zeros(n + m, n + m);
    augmented.view_mut((0, 0), (n, n)).copy_from(a);
    augmented.view_mut((0, n), (n, m)).copy_from(b);
    let exponential = (augmented * dt).exp();
    finite("the matrix exponential of [[A, B], [0, 0]] dt", &exponential)?;
    Ok((exponential.view((0, 0), (n, n)).into_owned(), exponential.view((0, n), (n, m)).into_owned()))
}
