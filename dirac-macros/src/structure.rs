//! Structural analysis of a primitive model's condensed Newton system: its sparsity pattern,
//! the check that a perfect matching exists (for closed models, at expansion), and the
//! messages an interconnection uses when its own check fails while it compiles.

use crate::ctxt::Ctxt;
use crate::model::SymModel;

impl SymModel {
    /// The pattern of `[σ L_vv + L_vq − D − K/σ, −Aᵀ; A + G/σ, 0]`, row-major, for a generic σ.
    pub fn condensed_pattern(&mut self) -> Vec<bool> {
        let (n, m) = (self.n(), self.m());
        let k = n + m;
        let (q, v) = (self.q.clone(), self.v.clone());
        let dl_dv = self.dl_dv();
        let dl_dq = self.dl_dq();
        let at_lambda = self.at_lambda();
        let mut pattern = vec![false; k * k];
        for i in 0..n {
            let rate = self.graph.add(&[dl_dq[i], self.force[i], at_lambda[i]]);
            for j in 0..n {
                let entries = [
                    self.graph.diff(dl_dv[i], v[j]),
                    self.graph.diff(dl_dv[i], q[j]),
                    self.graph.diff(rate, v[j]),
                    self.graph.diff(rate, q[j]),
                ];
                pattern[i * k + j] = entries.iter().any(|e| !self.graph.is_zero(*e));
            }
        }
        for r in 0..m {
            let av = {
                let terms: Vec<_> =
                    self.a[r].clone().iter().zip(&v).map(|(&a, &x)| self.graph.mul2(a, x)).collect();
                self.graph.add(&terms)
            };
            for j in 0..n {
                let a = !self.graph.is_zero(self.a[r][j]);
                let g = self.graph.diff(av, q[j]);
                pattern[(n + r) * k + j] = a || !self.graph.is_zero(g);
                pattern[j * k + n + r] = a;
            }
        }
        pattern
    }

    /// What to say about each unknown of the condensed system when nothing determines it.
    pub fn unknown_messages(&self, model: &str) -> Vec<String> {
        let velocities = self.velocities.iter().zip(&self.coordinates).map(|(v, c)| {
            format!(
                "structurally singular model: the velocity `{v}` of `{model}` is determined by no equation: \
                 coordinate `{c}` has no inertia, and no potential or constraint fixes it"
            )
        });
        let multipliers = self.constraint_names.iter().map(|c| {
            format!(
                "structurally singular model: the multiplier of constraint `{c}` of `{model}` is determined by no \
                 equation: the constraint depends on the others, or there are more constraints than velocities"
            )
        });
        velocities.chain(multipliers).collect()
    }

    /// For a closed primitive (no ports): an error at the unknown nothing determines.
    pub fn check_structure(&mut self, cx: &Ctxt, model: &str) {
        if !self.ports.is_empty() {
            return;
        }
        let (n, k) = (self.n(), self.n() + self.m());
        let pattern = self.condensed_pattern();
        if let Some(unknown) = unpaired(&pattern, k) {
            let message = &self.unknown_messages(model)[unknown];
            if unknown < n {
                cx.error_spanned_by(&self.coordinates[unknown], message);
            } else {
                cx.error_spanned_by(&self.constraint_idents[unknown - n], message);
            }
        }
    }
}

/// The first unknown (column) a maximum matching of the `k × k` pattern leaves unpaired.
pub fn unpaired(pattern: &[bool], k: usize) -> Option<usize> {
    let mut row_of = vec![usize::MAX; k];
    fn augment(row: usize, pattern: &[bool], k: usize, visited: &mut [bool], row_of: &mut [usize]) -> bool {
        for c in 0..k {
            if pattern[row * k + c] && !visited[c] {
                visited[c] = true;
                if row_of[c] == usize::MAX || augment(row_of[c], pattern, k, visited, row_of) {
                    row_of[c] = row;
                    return true;
                }
            }
        }
        false
    }
    for row in 0..k {
        let mut visited = vec![false; k];
        augment(row, pattern, k, &mut visited, &mut row_of);
    }
    row_of.iter().position(|r| *r == usize::MAX)
}

#[cfg(test)]
mod tests {
    use super::unpaired;

    #[test]
    fn matches_like_the_runtime_check() {
        assert_eq!(unpaired(&[true, true, false, true, false, false, false, true, true], 3), None);
        assert_eq!(unpaired(&[true, false, false, true, false, true, false, false, true], 3), Some(1));
        assert_eq!(unpaired(&[true, false, false, true, false, false, false, true, true], 3), Some(2));
    }
}
