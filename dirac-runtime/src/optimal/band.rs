//! The interior point's linear algebra: the KKT matrix `[W + Σ + δ_w I, Jᵀ; J, −δ_c I]` of a
//! transcription, ordered so that it is banded, and factored as `L D Lᵀ` without pivoting.
//!
//! A transcription's equations couple neighbouring nodes only, so in the right order its KKT
//! matrix is a band whose width does not grow with the number of intervals: its factorisation
//! costs `O(N b²)`, the block-tridiagonal (Riccati) recursion's cost, with no symbolic analysis
//! at each solve. The order is reverse Cuthill-McKee on the variables' graph, with each
//! equation placed right after the last of its variables: an equation is eliminated only once
//! its variables have been, so its pivot is a Schur complement `−J W⁻¹ Jᵀ`, not the zero on
//! the diagonal, and no pivoting is needed where `W` is positive definite on the equations'
//! null space. The inertia, read from `D`, tells the solver when it is not (Sylvester's law).

/// Where each entry of the KKT matrix lives in the band, and the band's storage.
pub(crate) struct Banded {
    /// The order of elimination: `position[k]` of KKT unknown `k` (variables first, then
    /// equations, in the program's numbering).
    position: Vec<usize>,
    /// The half bandwidth.
    pub width: usize,
    dim: usize,
    /// Row-major lower band: row `i` holds columns `i − width ..= i`.
    values: Vec<f64>,
    /// The assembled matrix, kept for iterative refinement.
    matrix: Vec<f64>,
    /// The factor's diagonal `D`.
    pivots: Vec<f64>,
    scratch: Vec<f64>,
    permuted: Vec<f64>,
    ordered: Vec<f64>,
    product: Vec<f64>,
}

/// What a factorisation found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Inertia {
    /// `(positive, negative)` pivots, none zero.
    Counted(usize, usize),
    /// A zero (or vanishing) pivot: the matrix is singular as ordered.
    Singular,
}

impl Banded {
    /// The order and band of the KKT matrix of `variables` unknowns and `equations` rows with
    /// the given Hessian (lower triangle) and Jacobian patterns.
    pub fn new(
        variables: usize,
        equations: usize,
        hessian: &[(usize, usize)],
        jacobian: &[(usize, usize)],
    ) -> Self {
        let order = order(variables, equations, hessian, jacobian);
        let dim = variables + equations;
        let mut position = vec![0; dim];
        for (at, &k) in order.iter().enumerate() {
            position[k] = at;
        }
        let mut width = 0;
        for &(r, c) in hessian {
            width = width.max(position[r].abs_diff(position[c]));
        }
        for &(r, c) in jacobian {
            width = width.max(position[variables + r].abs_diff(position[c]));
        }
        let stored = dim * (width + 1);
        Banded {
            position,
            width,
            dim,
            values: vec![0.0; stored],
            matrix: vec![0.0; stored],
            pivots: vec![0.0; dim],
            scratch: vec![0.0; width + 1],
            permuted: vec![0.0; dim],
            ordered: vec![0.0; dim],
            product: vec![0.0; dim],
        }
    }

    /// The storage index of the symmetric entry `(a, b)` of the KKT matrix (unknowns in the
    /// program's numbering).
    pub fn slot(&self, a: usize, b: usize) -> usize {
        let (pa, pb) = (self.position[a], self.position[b]);
        let (row, column) = if pa >= pb { (pa, pb) } else { (pb, pa) };
        row * (self.width + 1) + (column + self.width - row)
    }

    /// Clears the matrix before assembly.
    pub fn clear(&mut self) {
        self.matrix.fill(0.0);
    }

    /// Adds `value` to the entry stored at `slot`.
    pub fn add(&mut self, slot: usize, value: f64) {
        self.matrix[slot] += value;
    }

    /// Factors the assembled matrix as `L D Lᵀ` and counts the signs of `D`.
    pub fn factor(&mut self) -> Inertia {
        let (b, n) = (self.width, self.dim);
        self.values.copy_from_slice(&self.matrix);
        let (mut positive, mut negative) = (0, 0);
        for i in 0..n {
            let lo = i.saturating_sub(b);
            let row = i * (b + 1) + b - i;
            // scratch[k − lo] = L_ik d_k for the columns already final.
            for j in lo..i {
                let row_j = j * (b + 1) + b - j;
                let mut s = self.values[row + j];
                for k in lo.max(j.saturating_sub(b))..j {
                    s -= self.scratch[k - lo] * self.values[row_j + k];
                }
                self.scratch[j - lo] = s;
                self.values[row + j] = s / self.pivots[j];
            }
            // A pivot vanishes when it is round-off of the terms it is made of: the test is
            // relative to the largest of them, not to the matrix, whose active bounds'
            // barrier terms may be 1e10 times the constraint rows' pivots.
            let mut d = self.values[row + i];
            let mut terms = d.abs();
            for k in lo..i {
                let term = self.scratch[k - lo] * self.values[row + k];
                d -= term;
                terms = terms.max(term.abs());
            }
            if !d.is_finite() || d.abs() <= 1e-14 * terms {
                return Inertia::Singular;
            }
            self.pivots[i] = d;
            if d > 0.0 {
                positive += 1;
            } else {
                negative += 1;
            }
        }
        Inertia::Counted(positive, negative)
    }

    /// Solves `K x = rhs` in place with the factor, then refines once against the assembled
    /// matrix.
    pub fn solve(&mut self, rhs: &mut [f64], residual: &mut [f64]) {
        self.solve_factored(rhs);
        // One step of refinement: r = b − K x, then x += K⁻¹ r. `residual` holds b on entry.
        self.multiply(rhs, residual);
        self.solve_factored(residual);
        for (x, r) in rhs.iter_mut().zip(residual.iter()) {
            *x += r;
        }
    }

    /// `residual ← residual − K x`.
    fn multiply(&mut self, x: &[f64], residual: &mut [f64]) {
        let b = self.width;
        for (k, &at) in self.position.iter().enumerate() {
            self.ordered[at] = x[k];
        }
        self.product.fill(0.0);
        let (m, x, out) = (&self.matrix, &self.ordered, &mut self.product);
        for i in 0..self.dim {
            let lo = i.saturating_sub(b);
            let row = i * (b + 1) + b - i;
            for j in lo..i {
                let a = m[row + j];
                out[i] += a * x[j];
                out[j] += a * x[i];
            }
            out[i] += m[row + i] * x[i];
        }
        for (k, &at) in self.position.iter().enumerate() {
            residual[k] -= self.product[at];
        }
    }

    // Band arithmetic reads several arrays at the same index: indices are clearer than zips.
    #[allow(clippy::needless_range_loop)]
    fn solve_factored(&mut self, rhs: &mut [f64]) {
        let (b, n) = (self.width, self.dim);
        for (k, &at) in self.position.iter().enumerate() {
            self.permuted[at] = rhs[k];
        }
        let y = &mut self.permuted;
        for i in 0..n {
            let lo = i.saturating_sub(b);
            let row = i * (b + 1) + b - i;
            let mut s = y[i];
            for k in lo..i {
                s -= self.values[row + k] * y[k];
            }
            y[i] = s;
        }
        for i in 0..n {
            y[i] /= self.pivots[i];
        }
        for j in (0..n).rev() {
            let lo = j.saturating_sub(b);
            let row = j * (b + 1) + b - j;
            let x = y[j];
            for k in lo..j {
                y[k] -= self.values[row + k] * x;
            }
        }
        for (k, &at) in self.position.iter().enumerate() {
            rhs[k] = self.permuted[at];
        }
    }
}

/// Reverse Cuthill-McKee on the variables (adjacent when they share a Hessian entry or an
/// equation), each equation inserted after the last of its variables.
fn order(
    variables: usize,
    equations: usize,
    hessian: &[(usize, usize)],
    jacobian: &[(usize, usize)],
) -> Vec<usize> {
    let mut of_row: Vec<Vec<usize>> = vec![Vec::new(); equations];
    for &(r, c) in jacobian {
        of_row[r].push(c);
    }
    let mut adjacent: Vec<Vec<usize>> = vec![Vec::new(); variables];
    for &(r, c) in hessian {
        if r != c {
            adjacent[r].push(c);
            adjacent[c].push(r);
        }
    }
    for columns in &of_row {
        for &a in columns {
            adjacent[a].extend(columns.iter().copied().filter(|&b| b != a));
        }
    }
    for list in &mut adjacent {
        list.sort_unstable();
        list.dedup();
    }
    let degree: Vec<usize> = adjacent.iter().map(Vec::len).collect();
    let mut seen = vec![false; variables];
    let mut primal = Vec::with_capacity(variables);
    while primal.len() < variables {
        let start = (0..variables).filter(|&v| !seen[v]).min_by_key(|&v| (degree[v], v)).expect("unvisited");
        seen[start] = true;
        let mut head = primal.len();
        primal.push(start);
        while head < primal.len() {
            let v = primal[head];
            head += 1;
            let mut next: Vec<usize> = adjacent[v].iter().copied().filter(|&w| !seen[w]).collect();
            next.sort_by_key(|&w| (degree[w], w));
            for w in next {
                seen[w] = true;
                primal.push(w);
            }
        }
    }
    primal.reverse();
    let mut at = vec![0; variables];
    for (i, &v) in primal.iter().enumerate() {
        at[v] = i;
    }
    // Equations after their last variable (an equation with none goes first).
    let mut after: Vec<Vec<usize>> = vec![Vec::new(); variables + 1];
    for (r, columns) in of_row.iter().enumerate() {
        let slot = columns.iter().map(|&c| at[c] + 1).max().unwrap_or(0);
        after[slot].push(variables + r);
    }
    let mut order = Vec::with_capacity(variables + equations);
    order.extend(after[0].iter().copied());
    for (i, &v) in primal.iter().enumerate() {
        order.push(v);
        order.extend(after[i + 1].iter().copied());
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A random symmetric quasi-definite system solved through the band, against nalgebra's
    /// dense LU of the same matrix.
    #[test]
    fn banded_solves_match_dense_lu() {
        // Variables 0..6 on a path, two equations each touching three neighbours.
        let hessian = [(0, 0), (1, 0), (1, 1), (2, 2), (3, 2), (3, 3), (4, 4), (5, 4), (5, 5)];
        let jacobian = [(0, 0), (0, 1), (0, 2), (1, 3), (1, 4), (1, 5), (1, 2)];
        let mut band = Banded::new(6, 2, &hessian, &jacobian);
        let mut dense = nalgebra::DMatrix::<f64>::zeros(8, 8);
        let mut seed = 7u64;
        let mut random = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        band.clear();
        for &(r, c) in &hessian {
            let value = if r == c { 2.0 + random() } else { random() };
            band.add(band.slot(r, c), value);
            dense[(r, c)] += value;
            if r != c {
                dense[(c, r)] += value;
            }
        }
        for &(r, c) in &jacobian {
            let value = 1.0 + random();
            band.add(band.slot(6 + r, c), value);
            dense[(6 + r, c)] += value;
            dense[(c, 6 + r)] += value;
        }
        assert_eq!(band.factor(), Inertia::Counted(6, 2));
        let rhs: Vec<f64> = (0..8).map(|_| random()).collect();
        let mut x = rhs.clone();
        let mut residual = rhs.clone();
        band.solve(&mut x, &mut residual);
        let reference = dense.lu().solve(&nalgebra::DVector::from_vec(rhs)).expect("regular");
        for (a, b) in x.iter().zip(reference.iter()) {
            assert!((a - b).abs() < 1e-12, "{a} against {b}");
        }
    }
}
