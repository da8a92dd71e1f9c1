//! The linear-quadratic regulator: the stabilising solutions of the algebraic Riccati equations.
//!
//! Continuous (`lqr`): `AᵀX + XA − XGX + Q = 0` with `G = B R⁻¹ Bᵀ`, by the matrix sign function
//! of the Hamiltonian `H = [[A, −G], [−Q, −Aᵀ]]` (Roberts; determinant scaling, Byers). The
//! stable invariant subspace `[I; X]` of `H` is the kernel of `sign(H) + I`, which gives `X`
//! by least squares. Newton steps (Kleinman) then polish `X`, each solving a Lyapunov
//! equation by the sign function as well.
//!
//! Discrete (`dlqr`): `X = Q + AᵀXA − AᵀXB (R + BᵀXB)⁻¹ BᵀXA`, by the structure-preserving
//! doubling algorithm (Chu, Fan, Lin and Wang): `A₀ = A`, `G₀ = G`, `H₀ = Q`,
//!
//! ```text
//! A_{k+1} = A_k (I + G_k H_k)⁻¹ A_k
//! G_{k+1} = G_k + A_k (I + G_k H_k)⁻¹ G_k A_kᵀ
//! H_{k+1} = H_k + A_kᵀ H_k (I + G_k H_k)⁻¹ A_k  →  X
//! ```
//!
//! which converges quadratically; Newton steps (Hewer) polish it, each solving a Stein equation
//! by Smith's doubling. Both report the relative residual of the solution they return.

use nalgebra::{Complex, DMatrix};

use super::{ControlError, finite, rows, sorted, square};

/// A linear-quadratic regulator: the gain of `u = −K x` that minimises `∫ xᵀQx + uᵀRu dt` (or
/// its sum over samples), the Riccati solution behind it, and the loop it closes.
#[derive(Clone, Debug)]
pub struct Lqr {
    /// The gain `K` (inputs × states): `u = −K x`.
    pub gain: DMatrix<f64>,
    /// The stabilising solution `X` of the Riccati equation (the cost-to-go `xᵀXx`).
    pub riccati: DMatrix<f64>,
    /// The eigenvalues of the closed loop `A − B K`, sorted by real part, then imaginary part.
    pub poles: Vec<Complex<f64>>,
    /// The Riccati equation's residual at `riccati`, relative to the size of its terms
    /// (`‖Ric(X)‖_F / (‖Q‖_F + ‖AᵀX‖_F + ‖XA‖_F + ‖XGX‖_F)` and its discrete counterpart).
    pub residual: f64,
    /// The iterations of the sign function or the doubling, before polishing.
    pub iterations: usize,
}

/// The continuous-time LQR: the gain `K = R⁻¹ BᵀX` of `u = −K x` for `ẋ = A x + B u` that
/// minimises `∫₀^∞ xᵀQx + uᵀRu dt`. `Q` symmetric positive semidefinite, `R` symmetric positive
/// definite; `(A, B)` stabilisable and no mode of `A` unobservable through `Q` on the imaginary
/// axis.
pub fn lqr(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    q: &DMatrix<f64>,
    r: &DMatrix<f64>,
) -> Result<Lqr, ControlError> {
    let (n, g, r_inverse_bt) = weights(a, b, q, r)?;
    let fail = |reason: String| ControlError::NoStabilisingSolution { equation: "continuous", reason };
    let mut hamiltonian = DMatrix::zeros(2 * n, 2 * n);
    hamiltonian.view_mut((0, 0), (n, n)).copy_from(a);
    hamiltonian.view_mut((0, n), (n, n)).copy_from(&-&g);
    hamiltonian.view_mut((n, 0), (n, n)).copy_from(&-q);
    hamiltonian.view_mut((n, n), (n, n)).copy_from(&-a.transpose());
    let (sign, iterations) = sign_function(hamiltonian).map_err(|reason| {
        fail(format!(
            "{reason}: the Hamiltonian has eigenvalues on the imaginary axis, so (A, B) is not stabilisable \
             or a mode on the imaginary axis is not weighted by Q"
        ))
    })?;
    // (sign + I) [I; X] = 0: [W₁₂; W₂₂ + I] X = −[W₁₁ + I; W₂₁].
    let mut lhs = DMatrix::zeros(2 * n, n);
    let mut rhs = DMatrix::zeros(2 * n, n);
    lhs.view_mut((0, 0), (n, n)).copy_from(&sign.view((0, n), (n, n)));
    lhs.view_mut((n, 0), (n, n)).copy_from(&(sign.view((n, n), (n, n)) + DMatrix::identity(n, n)));
    rhs.view_mut((0, 0), (n, n)).copy_from(&-(sign.view((0, 0), (n, n)) + DMatrix::identity(n, n)));
    rhs.view_mut((n, 0), (n, n)).copy_from(&-sign.view((n, 0), (n, n)));
    let svd = lhs.svd(true, true);
    if svd.singular_values.min() <= 1e-12 * svd.singular_values.max() {
        return Err(fail(
            "the stable subspace of the Hamiltonian is not a graph over the states: (A, B) is not stabilisable".into(),
        ));
    }
    let mut x = svd.solve(&rhs, 0.0).map_err(|e| fail(e.to_string()))?;
    symmetrise(&mut x);
    let residual_of = |x: &DMatrix<f64>| {
        let ax = a.transpose() * x;
        let xgx = x * &g * x;
        let residual = &ax + ax.transpose() - &xgx + q;
        (residual, 2.0 * ax.norm() + xgx.norm() + q.norm())
    };
    // Kleinman's Newton steps: (A − GX)ᵀ Δ + Δ (A − GX) + Ric(X) = 0, while they help.
    let (mut residual, mut scale) = residual_of(&x);
    for _ in 0..3 {
        let closed = a - &g * &x;
        let Ok(mut step) = lyapunov(&closed, &residual) else { break };
        symmetrise(&mut step);
        let candidate = &x + step;
        let (next, next_scale) = residual_of(&candidate);
        if next.norm() >= residual.norm() {
            break;
        }
        (x, residual, scale) = (candidate, next, next_scale);
    }
    let gain = &r_inverse_bt * &x;
    let poles = sorted((a - b * &gain).complex_eigenvalues().iter().copied().collect());
    if let Some(pole) = poles.iter().find(|p| p.re >= 0.0) {
        return Err(fail(format!(
            "the loop the solution closes has the pole {pole}, not in the left half-plane"
        )));
    }
    Ok(Lqr { gain, riccati: x, poles, residual: relative(residual.norm(), scale), iterations })
}

/// The discrete-time LQR: the gain `K = (R + BᵀXB)⁻¹ BᵀXA` of `u_k = −K x_k` for
/// `x_{k+1} = A x_k + B u_k` that minimises `Σ x_kᵀQx_k + u_kᵀRu_k`. `Q` symmetric positive
/// semidefinite, `R` symmetric positive definite; `(A, B)` stabilisable and no mode of `A`
/// unobservable through `Q` on the unit circle. With [`zero_order_hold`](super::zero_order_hold),
/// the gain of a controller that holds its output between samples.
pub fn dlqr(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    q: &DMatrix<f64>,
    r: &DMatrix<f64>,
) -> Result<Lqr, ControlError> {
    let (n, g, _) = weights(a, b, q, r)?;
    let fail = |reason: String| ControlError::NoStabilisingSolution { equation: "discrete", reason };
    let identity = DMatrix::<f64>::identity(n, n);
    let (mut ak, mut gk, mut hk) = (a.clone(), g, q.clone());
    let mut iterations = 0;
    loop {
        iterations += 1;
        let lu = (&identity + &gk * &hk).lu();
        let (Some(w_a), Some(w_g)) = (lu.solve(&ak), lu.solve(&gk)) else {
            return Err(fail(format!("I + G H became singular at the doubling's step {iterations}")));
        };
        let next_h = &hk + ak.transpose() * &hk * &w_a;
        gk = &gk + &ak * w_g * ak.transpose();
        ak = &ak * w_a;
        let change = (&next_h - &hk).norm();
        hk = next_h;
        if !hk.iter().all(|x| x.is_finite()) {
            return Err(fail(format!(
                "the doubling diverged at its step {iterations}: a mode on the unit circle is not stabilisable \
                 or not weighted by Q"
            )));
        }
        if change <= 1e-14 * hk.norm() || ak.norm() <= 1e-15 * (1.0 + a.norm()) {
            break;
        }
        if iterations == 100 {
            return Err(fail(
                "the doubling did not settle in 100 steps: a mode on or near the unit circle is not stabilisable \
                 or not weighted by Q"
                    .into(),
            ));
        }
    }
    let mut x = hk;
    symmetrise(&mut x);
    let design = |x: &DMatrix<f64>| -> Option<(DMatrix<f64>, DMatrix<f64>, f64)> {
        let bx = b.transpose() * x;
        let gain = (r + &bx * b).cholesky()?.solve(&(&bx * a));
        let axa = a.transpose() * x * a;
        let correction = a.transpose() * bx.transpose() * &gain;
        let residual = q + &axa - x - &correction;
        Some((gain, residual, q.norm() + axa.norm() + x.norm() + correction.norm()))
    };
    let Some((mut gain, mut residual, mut scale)) = design(&x) else {
        return Err(fail("R + BᵀXB is not positive definite".into()));
    };
    // Hewer's Newton steps: A_cᵀ Δ A_c − Δ + Ric(X) = 0, while they help.
    for _ in 0..3 {
        let closed = a - b * &gain;
        let Ok(mut step) = stein(&closed, &residual) else { break };
        symmetrise(&mut step);
        let candidate = &x + step;
        let Some((next_gain, next, next_scale)) = design(&candidate) else { break };
        if next.norm() >= residual.norm() {
            break;
        }
        (x, gain, residual, scale) = (candidate, next_gain, next, next_scale);
    }
    let poles = sorted((a - b * &gain).complex_eigenvalues().iter().copied().collect());
    if let Some(pole) = poles.iter().find(|p| p.norm() >= 1.0) {
        return Err(fail(format!(
            "the loop the solution closes has the pole {pole} (modulus {:.6}), not inside the unit circle",
            pole.norm()
        )));
    }
    Ok(Lqr { gain, riccati: x, poles, residual: relative(residual.norm(), scale), iterations })
}

/// Checks the sizes and weights; returns the number of states, `G = B R⁻¹ Bᵀ` and `R⁻¹ Bᵀ`.
fn weights(
    a: &DMatrix<f64>,
    b: &DMatrix<f64>,
    q: &DMatrix<f64>,
    r: &DMatrix<f64>,
) -> Result<(usize, DMatrix<f64>, DMatrix<f64>), ControlError> {
    let n = square("A", a)?;
    rows("B", b, n)?;
    let m = b.ncols();
    if n == 0 || m == 0 {
        return Err(ControlError::Shape {
            what: if n == 0 { "A" } else { "B" },
            reason: format!("a design needs states and inputs, but the model has {n} states and {m} inputs"),
        });
    }
    if q.shape() != (n, n) {
        return Err(ControlError::Shape {
            what: "Q",
            reason: format!("must be {n} × {n} (one row per state), but is {} × {}", q.nrows(), q.ncols()),
        });
    }
    if r.shape() != (m, m) {
        return Err(ControlError::Shape {
            what: "R",
            reason: format!("must be {m} × {m} (one row per input), but is {} × {}", r.nrows(), r.ncols()),
        });
    }
    for (what, matrix) in [("A", a), ("B", b), ("Q", q), ("R", r)] {
        finite(what, matrix)?;
    }
    for (what, matrix) in [("Q", q), ("R", r)] {
        let asymmetry = (matrix - matrix.transpose()).amax();
        if asymmetry > 1e-12 * matrix.amax() {
            return Err(ControlError::Weight {
                what,
                reason: format!("is not symmetric (off by {asymmetry:.3e})"),
            });
        }
    }
    let smallest = q.clone().symmetric_eigenvalues().min();
    if n > 0 && smallest < -1e-12 * q.amax() {
        return Err(ControlError::Weight {
            what: "Q",
            reason: format!("is not positive semidefinite (an eigenvalue is {smallest:.3e})"),
        });
    }
    // The iterations square and invert these matrices: entries beyond 1e150 overflow there.
    for (what, matrix) in [("A", a), ("B", b), ("Q", q), ("R", r)] {
        if matrix.amax() > 1e150 {
            return Err(ControlError::Shape {
                what,
                reason: format!(
                    "entries up to {:e} overflow the Riccati iterations: scale the states and inputs",
                    matrix.amax()
                ),
            });
        }
    }
    let Some(cholesky) = r.clone().cholesky() else {
        return Err(ControlError::Weight {
            what: "R",
            reason: "is not positive definite: every input must cost something".into(),
        });
    };
    let r_inverse_bt = cholesky.solve(&b.transpose());
    Ok((n, b * &r_inverse_bt, r_inverse_bt))
}

/// The matrix sign function of `z` by the scaled Newton iteration `Z ← (Z/c + c Z⁻¹)/2`,
/// `c = |det Z|^{1/N}` until the iteration is near its limit. Fails where `z` has an eigenvalue
/// on (or within round-off of) the imaginary axis.
fn sign_function(mut z: DMatrix<f64>) -> Result<(DMatrix<f64>, usize), String> {
    let size = z.nrows() as f64;
    let mut scaling = true;
    for iteration in 1..=100 {
        let lu = z.clone().lu();
        let log_determinant: f64 = lu.u().diagonal().iter().map(|u| u.abs().ln()).sum();
        let Some(inverse) = lu.try_inverse() else {
            return Err(format!("a singular iterate at the sign function's step {iteration}"));
        };
        let c = if scaling { (log_determinant / size).exp() } else { 1.0 };
        let next = (&z / c + inverse * c) * 0.5;
        let change = (&next - &z).norm() / next.norm();
        z = next;
        if !change.is_finite() {
            return Err(format!("a non-finite iterate at the sign function's step {iteration}"));
        }
        if change < 1e-2 {
            scaling = false;
        }
        if change <= 1e-13 {
            return Ok((z, iteration));
        }
    }
    Err("the sign function did not settle in 100 steps".into())
}

/// The solution `X` of `Fᵀ X + X F + C = 0` for a stable `F`, by the sign function:
/// `F ← (F/c + c F⁻¹)/2`, `C ← (C/c + c F⁻ᵀ C F⁻¹)/2` until `F = −I`, then `X = C/2`.
fn lyapunov(f: &DMatrix<f64>, c: &DMatrix<f64>) -> Result<DMatrix<f64>, ()> {
    let n = f.nrows();
    let (mut f, mut c) = (f.clone(), c.clone());
    let mut scaling = true;
    for _ in 0..100 {
        let lu = f.clone().lu();
        let log_determinant: f64 = lu.u().diagonal().iter().map(|u| u.abs().ln()).sum();
        let inverse = lu.try_inverse().ok_or(())?;
        let gamma = if scaling { (log_determinant / n as f64).exp() } else { 1.0 };
        let next_c = (&c / gamma + inverse.transpose() * &c * &inverse * gamma) * 0.5;
        let next_f = (&f / gamma + inverse * gamma) * 0.5;
        let change = (&next_f - &f).norm() / next_f.norm();
        (f, c) = (next_f, next_c);
        if !change.is_finite() {
            return Err(());
        }
        if change < 1e-2 {
            scaling = false;
        }
        if change <= 1e-13 {
            return Ok(c * 0.5);
        }
    }
    Err(())
}

/// The solution `X` of `Fᵀ X F − X + C = 0` for `F` inside the unit circle, by Smith's doubling:
/// `X = Σ (Fᵀ)ᵏ C Fᵏ`, summed in doubling blocks.
fn stein(f: &DMatrix<f64>, c: &DMatrix<f64>) -> Result<DMatrix<f64>, ()> {
    let (mut f, mut x) = (f.clone(), c.clone());
    for _ in 0..60 {
        let added = f.transpose() * &x * &f;
        let done = added.norm() <= 1e-16 * x.norm();
        x += added;
        if !x.iter().all(|v| v.is_finite()) {
            return Err(());
        }
        if done {
            return Ok(x);
        }
        f = &f * &f;
    }
    Err(())
}

/// `(X + Xᵀ)/2`, in place.
fn symmetrise(x: &mut DMatrix<f64>) {
    let transpose = x.transpose();
    *x += transpose;
    *x *= 0.5;
}

/// `residual / scale`, zero where both are.
fn relative(residual: f64, scale: f64) -> f64 {
    if residual == 0.0 { 0.0 } else { residual / scale.max(f64::MIN_POSITIVE) }
}
