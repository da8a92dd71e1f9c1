//! What the derive learns from a model's structure before emitting it: the sparsity pattern
//! of its condensed Newton system (and, for a closed primitive, the check that it is
//! structurally nonsingular), and whether its Lagrangian is separable.

use crate::blocks::Blocks;
use crate::ctxt::Ctxt;
use crate::model::SymModel;
use crate::sym::Graph;
use crate::symbols::Sym;

use dirac_structure::matching;

/// The row-major `(n + m) × (n + m)` pattern of the condensed system `(Δv, Δλ)`: momentum
/// balances and constraint rows against velocities and multipliers.
pub fn condensed_pattern(graph: &Graph, b: &Blocks) -> Vec<bool> {
    let (n, m) = (b.dl_dv.len(), b.a.len());
    let k = n + m;
    let nonzero = |x| !graph.is_zero(x);
    let mut pattern = vec![false; k * k];
    for i in 0..n {
        for j in 0..n {
            pattern[i * k + j] =
                [b.l_vv[i][j], b.l_vq[i][j], b.dpdot_dv[i][j], b.dpdot_dq[i][j]].into_iter().any(nonzero);
        }
    }
    for r in 0..m {
        for j in 0..n {
            let a = nonzero(b.a[r][j]);
            pattern[(n + r) * k + j] = a || nonzero(b.dav_dq[r][j]);
            let slip = b.slip_rows.get(r).is_some_and(|row| nonzero(row[j]));
            pattern[j * k + n + r] = a || slip;
        }
    }
    pattern
}

/// The first unknown (column) a maximum matching of the `k × k` pattern leaves unpaired.
pub fn unpaired(pattern: &[bool], k: usize) -> Option<usize> {
    let (mut row_of, mut col_of, mut visited) = (vec![0; k], vec![0; k], vec![false; k]);
    let (mut stack_row, mut stack_col, mut parent) = (vec![0; k], vec![0; k], vec![0; k]);
    let mut scratch = matching::Scratch {
        row_of: &mut row_of,
        col_of: &mut col_of,
        visited: &mut visited,
        stack_row: &mut stack_row,
        stack_col: &mut stack_col,
        parent: &mut parent,
    };
    matching::unpaired(pattern, k, &mut scratch)
}

/// What to say about each unknown of the condensed system when nothing determines it.
pub fn unknown_messages(model: &SymModel, name: &str) -> Vec<String> {
    let velocities = model.velocities.iter().zip(&model.coordinates).map(|(v, c)| {
        format!(
            "structurally singular model: the velocity `{v}` of `{name}` is determined by no equation: \
             coordinate `{c}` has no inertia, no potential or constraint fixes it, and no force or dissipation \
             depends on its velocity"
        )
    });
    let multipliers = model.constraints.iter().map(|c| {
        format!(
            "structurally singular model: the multiplier of constraint `{}` of `{name}` is determined by no \
             equation: the constraint acts on no velocity (a relation between coordinates alone is a \
             `holonomic` constraint)",
            c.name
        )
    });
    velocities.chain(multipliers).collect()
}

/// The pattern with the multipliers' diagonal filled: what the dense solvers factor once they
/// deflate redundant rows (`dirac_runtime::algebra::lu::Deflation`), so that rows that fix the
/// same velocities twice are matched, and only velocities nothing determines stay unpaired.
pub fn with_corner(pattern: &[bool], n: usize, m: usize) -> Vec<bool> {
    let k = n + m;
    let mut out = pattern.to_vec();
    for r in n..k {
        out[r * k + r] = true;
    }
    out
}

/// The first multiplier whose constraint acts on no velocity (its column of `Aᵀ` is empty).
pub fn idle_row(pattern: &[bool], n: usize, m: usize) -> Option<usize> {
    let k = n + m;
    (0..m).find(|&r| (0..n).all(|j| !pattern[j * k + n + r]))
}

/// For a closed primitive (no ports): an error at the unknown nothing determines. A model
/// with ports may be completed by an interconnection, which checks the whole. Redundant rows
/// (more rows on some velocities than they number) are accepted: their multipliers are fixed
/// at their least norm when the model runs.
pub fn check_structure(cx: &Ctxt, model: &SymModel, name: &str, pattern: &[bool], messages: &[String]) {
    if !model.ports.is_empty() {
        return;
    }
    let (n, m) = (model.n(), model.m());
    if let Some(r) = idle_row(pattern, n, m) {
        cx.error_spanned_by(&model.constraints[r].ident, &messages[n + r]);
    } else if let Some(unknown) = unpaired(&with_corner(pattern, n, m), n + m) {
        if unknown < n {
            cx.error_spanned_by(&model.coordinates[unknown], &messages[unknown]);
        } else {
            let c = &model.constraints[unknown - n];
            let message = format!(
                "structurally singular model: the velocities constraint `{}` of `{name}` acts on are not all \
                 determined: one of them has no inertia, and no potential, force or other constraint fixes it",
                c.name
            );
            cx.error_spanned_by(&c.ident, &message);
        }
    }
}

/// Whether `L = ½ vᵀ M v − V(q, t)` with constant `M` and no forces: every force is zero,
/// `L_vv` depends on parameters only, and `∂L/∂v` vanishes at `v = 0`.
pub fn separable(model: &mut SymModel, b: &Blocks) -> bool {
    let graph = &mut model.graph;
    let symbols = &model.symbols;
    if !b.force.iter().all(|f| graph.is_zero(*f)) {
        return false;
    }
    let constant = b
        .l_vv
        .iter()
        .flatten()
        .all(|&second| graph.deps(second).iter().all(|s| matches!(symbols.kind(s), Sym::Parameter(_))));
    let zero = graph.num(0.0);
    let at_rest = model.v.iter().filter_map(|x| graph.as_sym(*x)).map(|s| (s, zero)).collect();
    constant
        && b.dl_dv.iter().all(|&d| {
            let rest = graph.substitute(d, &at_rest);
            graph.is_zero(rest)
        })
}

/// Whether every entry of the constraint rows `A` depends on the model's parameters alone.
pub fn constant_rows(model: &SymModel, b: &Blocks) -> bool {
    let (graph, symbols) = (&model.graph, &model.symbols);
    b.a.iter()
        .flatten()
        .all(|&entry| graph.deps(entry).iter().all(|s| matches!(symbols.kind(s), Sym::Parameter(_))))
}

#[cfg(test)]
mod tests {
    use super::unpaired;

    #[test]
    fn finds_perfect_matchings_and_their_absence() {
        assert_eq!(unpaired(&[true, true, false, true, false, false, false, true, true], 3), None);
        assert_eq!(unpaired(&[true, false, false, true, false, true, false, false, true], 3), Some(1));
        assert_eq!(unpaired(&[true, false, false, true, false, false, false, true, true], 3), Some(2));
    }
}
