//! The sparsity structure of a model's condensed Newton system, and the check that it is
//! structurally nonsingular, evaluated while the program compiles.
//!
//! The condensed system (design notes §2.4) has one column per velocity and per multiplier and
//! one row per momentum balance and per constraint. It can be nonsingular only if its pattern
//! has a perfect matching: every unknown paired with an equation it appears in. A velocity that
//! no equation determines (a coordinate without inertia that no constraint or potential fixes)
//! or a dependent constraint leaves an unknown unpaired.

use dirac_structure::matching::{Scratch, unpaired_with_corner};

/// The pattern of the condensed system and a message for each of its unknowns.
#[derive(Clone, Copy, Debug)]
pub struct Structure {
    /// Row-major `(n + m) × (n + m)`: whether the entry can be nonzero.
    pub pattern: &'static [bool],
    /// For each unknown (velocities, then multipliers), what to say when nothing determines it.
    pub unknowns: &'static [&'static str],
}

/// The first unknown of a `k × k` pattern that a maximum matching leaves unpaired, if any.
/// `K` bounds the size (an upper bound is enough); usable in `const` items.
pub const fn unpaired_unknown<const K: usize>(pattern: &[bool], k: usize) -> Option<usize> {
    unpaired_from::<K>(pattern, k, k)
}

/// The first unknown of a `k × k` saddle-point pattern with `n` velocities that nothing
/// determines once redundant rows are allowed: a multiplier whose row acts on no velocity
/// (its column is empty above the corner), else an unknown a maximum matching leaves unpaired
/// with the multipliers' diagonal counted. Rows that fix the same velocities twice pass: the
/// dense solvers fix their multipliers at the least norm (`algebra::lu::Deflation`). `K`
/// bounds the size; usable in `const` items.
pub const fn undetermined_unknown<const K: usize>(pattern: &[bool], k: usize, n: usize) -> Option<usize> {
    let mut c = n;
    while c < k {
        let mut row = 0;
        while row < n && !pattern[row * k + c] {
            row += 1;
        }
        if row == n {
            return Some(c);
        }
        c += 1;
    }
    unpaired_from::<K>(pattern, k, n)
}

/// The matching of [`unpaired_unknown`], with the diagonal counted from `corner` on, over
/// scratch arrays of `K` entries.
const fn unpaired_from<const K: usize>(pattern: &[bool], k: usize, corner: usize) -> Option<usize> {
    let (mut row_of, mut col_of, mut visited) = ([0; K], [0; K], [false; K]);
    let (mut stack_row, mut stack_col, mut parent) = ([0; K], [0; K], [0; K]);
    let mut scratch = Scratch {
        row_of: &mut row_of,
        col_of: &mut col_of,
        visited: &mut visited,
        stack_row: &mut stack_row,
        stack_col: &mut stack_col,
        parent: &mut parent,
    };
    unpaired_with_corner(pattern, k, corner, &mut scratch)
}

/// `values[0] + … + values[end − 1]`; usable in `const` items.
pub const fn prefix_sum(values: &[usize], end: usize) -> usize {
    let (mut i, mut sum) = (0, 0);
    while i < end {
        sum += values[i];
        i += 1;
    }
    sum
}

/// Whether every flag is set; usable in `const` items.
pub const fn all(flags: &[bool]) -> bool {
    let mut i = 0;
    while i < flags.len() {
        if !flags[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// Where unknown `a` of a subsystem's condensed system sits in its composite's: velocities
/// after the subsystem's first coordinate, multipliers at the subsystem's constraint rows
/// (holonomic rows from `h_offset`, the others from `v_offset`), after the composite's `n`.
pub const fn composite_unknown(
    a: usize,
    sub_n: usize,
    sub_h: usize,
    slot: (usize, usize, usize),
    n: usize,
) -> usize {
    let (q_offset, h_offset, v_offset) = slot;
    if a < sub_n {
        q_offset + a
    } else if a - sub_n < sub_h {
        n + h_offset + (a - sub_n)
    } else {
        n + v_offset + (a - sub_n - sub_h)
    }
}

#[cfg(test)]
mod tests {
    use super::{undetermined_unknown, unpaired_unknown};

    #[test]
    fn finds_perfect_matchings_and_their_absence() {
        // A permutation-like pattern needs augmenting paths to be matched fully.
        let full = [true, true, false, true, false, false, false, true, true];
        assert_eq!(unpaired_unknown::<3>(&full, 3), None);
        // Column 1 appears in no row.
        let empty_column = [true, false, false, true, false, true, false, false, true];
        assert_eq!(unpaired_unknown::<3>(&empty_column, 3), Some(1));
        // Rows 0 and 1 can only take column 0; row 2 takes column 1, so column 2 stays unpaired.
        let crowded = [true, false, false, true, false, false, false, true, true];
        assert_eq!(unpaired_unknown::<3>(&crowded, 3), Some(2));
        // Evaluated at compile time, with a bound K above the size k.
        const CHECKED: Option<usize> = unpaired_unknown::<4>(&[true, true, false, true], 2);
        // One velocity fixed by two rows: the second multiplier pairs with its own corner.
        #[rustfmt::skip]
        let twice = [
            true, true, true,
            true, false, false,
            true, false, false,
        ];
        assert_eq!(unpaired_unknown::<3>(&twice, 3), Some(2));
        assert_eq!(undetermined_unknown::<3>(&twice, 3, 1), None);
        // A row on no velocity stays undetermined.
        #[rustfmt::skip]
        let idle = [
            true, true, false,
            true, false, false,
            false, false, false,
        ];
        assert_eq!(undetermined_unknown::<3>(&idle, 3, 1), Some(2));
        assert_eq!(CHECKED, None);
    }
}
