//! Tsitouras' 5(4) pair (Ch. Tsitouras, "Runge-Kutta pairs of order 5(4) satisfying only the
//! first column simplifying assumption", *Computers & Mathematics with Applications* 62, 2011)
//! with its continuous extension of order 4: seven stages, the last evaluated at the new
//! solution (first same as last). Its error constants are smaller than Dormand and Prince's
//! pair of the same cost, so it reaches a given error in fewer steps.

// The coefficients carry the digits they are published with, some beyond a double's.
#![allow(clippy::excessive_precision)]

/// The nodes `c_i` of the seven stages.
pub const C: [f64; 7] = [0.0, 0.161, 0.327, 0.9, 0.980_025_540_904_509_7, 1.0, 1.0];

/// The coefficients `a_ij`, row `i` holding `j < i`; the last row is the weights `b`.
pub const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [0.161, 0.0, 0.0, 0.0, 0.0, 0.0],
    [-0.008_480_655_492_356_989, 0.335_480_655_492_357, 0.0, 0.0, 0.0, 0.0],
    [2.897_153_057_105_493, -6.359_448_489_975_075, 4.362_295_432_869_581_5, 0.0, 0.0, 0.0],
    [
        5.325_864_828_439_257,
        -11.748_883_564_062_83,
        7.495_539_342_889_836,
        -0.092_495_066_361_755_25,
        0.0,
        0.0,
    ],
    [
        5.861_455_442_946_42,
        -12.920_969_317_847_11,
        8.159_367_898_576_159,
        -0.071_584_973_281_401,
        -0.028_269_050_394_068_383,
        0.0,
    ],
    [
        0.096_460_766_818_065_23,
        0.01,
        0.479_889_650_414_499_6,
        1.379_008_574_103_742,
        -3.290_069_515_436_081,
        2.324_710_524_099_774,
    ],
];

/// `b − b̂`: the fifth-order weights minus the embedded fourth-order ones, the local error
/// estimate's coefficients (the seventh, `1/66`, with the sign the paper's table misprints).
pub const E: [f64; 7] = [
    -0.001_780_011_052_225_777_1,
    -0.000_816_434_459_656_746_9,
    0.007_880_878_010_261_995,
    -0.144_711_007_173_262_9,
    0.582_357_165_452_555_2,
    -0.458_082_105_929_186_97,
    1.0 / 66.0,
];

/// The dense output's weights `b_i(θ) = Σ_k B_THETA[i][k] θ^k`, so that
/// `y(t0 + θh) = y0 + h Σ_i b_i(θ) k_i`; `b_i(1) = b_i`.
pub const B_THETA: [[f64; 5]; 7] = [
    [0.0, 1.0, -2.763_706_197_274_826, 2.913_255_461_821_912_6, -1.053_088_497_729_021_6],
    [0.0, 0.0, 0.1317, -0.2234, 0.1017],
    [0.0, 0.0, 3.930_296_236_894_751, -5.941_033_872_131_505, 2.490_627_285_651_252_8],
    [0.0, 0.0, -12.411_077_166_933_676, 30.338_188_630_282_32, -16.548_102_889_244_903],
    [0.0, 0.0, 37.509_313_416_511_04, -88.178_904_894_766_4, 47.379_521_962_819_28],
    [0.0, 0.0, -27.896_526_289_197_29, 65.091_894_674_793_68, -34.870_657_861_496_61],
    [0.0, 0.0, 1.5, -4.0, 2.5],
];

/// The dense output's weights at `θ`.
pub fn weights_at(theta: f64) -> [f64; 7] {
    B_THETA.map(|b| b[0] + theta * (b[1] + theta * (b[2] + theta * (b[3] + theta * b[4]))))
}

#[cfg(test)]
mod tests {
    use super::*;

    const B: [f64; 7] = [A[6][0], A[6][1], A[6][2], A[6][3], A[6][4], A[6][5], 0.0];

    /// Every order condition of a fifth-order method that a mistyped coefficient would break:
    /// the row sums `Σ_j a_ij = c_i`, the quadratures `Σ b_i c_i^k = 1/(k+1)` (k ≤ 4) and the
    /// trees `Σ b a c = 1/6`, `Σ b c a c = 1/8`, `Σ b a a c = 1/24`, `Σ b a c² = 1/12`,
    /// `Σ b c² a c = 1/10`; the embedded weights' quadratures to order 4; and the dense
    /// output's weights, which must give `b` at θ = 1 and integrate polynomials of degree 3
    /// exactly at every θ (`Σ b_i(θ) c_i^k = θ^{k+1}/(k+1)`).
    #[test]
    fn the_tableau_meets_its_order_conditions() {
        let close = |x: f64, y: f64, what: &str| assert!((x - y).abs() < 1e-13, "{what}: {x} ≠ {y}");
        for (i, row) in A.iter().enumerate() {
            close(row.iter().sum(), C[i], &format!("row {i}"));
        }
        let sum = |f: &dyn Fn(usize) -> f64| (0..7).map(f).sum::<f64>();
        let a = |i: usize, j: usize| if j < 6 { A[i][j] } else { 0.0 };
        let ac = |i: usize| sum(&|j| a(i, j) * C[j]);
        let ac2 = |i: usize| sum(&|j| a(i, j) * C[j] * C[j]);
        let aac = |i: usize| sum(&|j| a(i, j) * ac(j));
        for k in 0..5 {
            close(sum(&|i| B[i] * C[i].powi(k)), 1.0 / f64::from(k + 1), &format!("Σ b c^{k}"));
        }
        close(sum(&|i| B[i] * ac(i)), 1.0 / 6.0, "Σ b a c");
        close(sum(&|i| B[i] * C[i] * ac(i)), 1.0 / 8.0, "Σ b c a c");
        close(sum(&|i| B[i] * aac(i)), 1.0 / 24.0, "Σ b a a c");
        close(sum(&|i| B[i] * ac2(i)), 1.0 / 12.0, "Σ b a c²");
        close(sum(&|i| B[i] * C[i] * C[i] * ac(i)), 1.0 / 10.0, "Σ b c² a c");
        for k in 0..4 {
            close(sum(&|i| (B[i] - E[i]) * C[i].powi(k)), 1.0 / f64::from(k + 1), &format!("Σ b̂ c^{k}"));
        }
        for (b, w) in B.iter().zip(weights_at(1.0)) {
            close(w, *b, "b(1)");
        }
        for theta in [0.1, 0.37, 0.5, 0.8] {
            let w = weights_at(theta);
            for k in 0..4 {
                let exact = theta.powi(k + 1) / f64::from(k + 1);
                close(sum(&|i| w[i] * C[i].powi(k)), exact, &format!("Σ b(θ) c^{k} at θ = {theta}"));
            }
        }
    }
}
