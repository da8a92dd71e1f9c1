//! The Dormand-Prince 5(4) pair (Dormand & Prince 1980) with Shampine's continuous extension
//! of order 4, as in Hairer, Nørsett & Wanner, *Solving Ordinary Differential Equations I*,
//! §II.5 and §II.6 (DOPRI5).

/// The nodes `c_i` of the seven stages.
pub const C: [f64; 7] = [0.0, 0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0];

/// The coefficients `a_ij`, row `i` holding `j < i`; the last row is the weights `b`, so that
/// the seventh stage is evaluated at the new solution (first same as last).
pub const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [0.2, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0, 0.0, 0.0],
    [9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0, 0.0],
    [35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0],
];

/// `b − b̂`: the fifth-order weights minus the embedded fourth-order ones, the local error
/// estimate's coefficients.
pub const E: [f64; 7] =
    [71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0];

/// Shampine's coefficients of the dense output's fourth-degree term.
pub const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

#[cfg(test)]
mod tests {
    use super::*;

    /// The order conditions up to order 5 for a quadrature in `t` (`Σ b_i c_i^k = 1/(k+1)`)
    /// and the row sums `Σ_j a_ij = c_i`, checked to round-off: a mistyped coefficient fails.
    #[test]
    fn the_tableau_meets_its_order_conditions() {
        for (i, row) in A.iter().enumerate() {
            let sum: f64 = row.iter().sum();
            assert!((sum - C[i]).abs() < 1e-14, "row {i}: Σ a = {sum}, c = {}", C[i]);
        }
        let b = A[6];
        for k in 0..5 {
            let q: f64 = (0..6).map(|i| b[i] * C[i].powi(k)).sum();
            assert!((q - 1.0 / f64::from(k + 1)).abs() < 1e-14, "Σ b c^{k} = {q}");
        }
        // Σ b_i a_ij c_j = 1/6 and Σ b_i c_i a_ij c_j = 1/8, Σ b_i a_ij a_jk c_k = 1/24.
        let ac: Vec<f64> = (0..7).map(|i| (0..6).map(|j| A[i][j] * C[j]).sum()).collect();
        let third: f64 = (0..6).map(|i| b[i] * ac[i]).sum();
        assert!((third - 1.0 / 6.0).abs() < 1e-14);
        let fourth: f64 = (0..6).map(|i| b[i] * C[i] * ac[i]).sum();
        assert!((fourth - 1.0 / 8.0).abs() < 1e-14);
        let aac: Vec<f64> = (0..7).map(|i| (0..6).map(|j| A[i][j] * ac[j]).sum()).collect();
        let fifth: f64 = (0..6).map(|i| b[i] * aac[i]).sum();
        assert!((fifth - 1.0 / 24.0).abs() < 1e-14);
        // The embedded weights integrate constants exactly too: Σ (b − b̂) = 0.
        assert!(E.iter().sum::<f64>().abs() < 1e-15);
    }
}
