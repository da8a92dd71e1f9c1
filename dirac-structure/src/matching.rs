//! A maximum matching of a square bipartite pattern (equations against unknowns), as a
//! `const fn` over caller-provided scratch space.
//!
//! The one implementation of the structural check: the runtime evaluates it in `const` items
//! (interconnections check themselves when they compile, with arrays on the const stack), and
//! the derive calls it to check primitive models while it expands them (with vectors).

/// The scratch space of [`unpaired`]: each slice holds at least `k` entries.
pub struct Scratch<'a> {
    /// `row_of[c]`: the equation paired with unknown `c`, or `usize::MAX`.
    pub row_of: &'a mut [usize],
    /// `col_of[r]`: the unknown paired with equation `r`, or `usize::MAX`.
    pub col_of: &'a mut [usize],
    /// Unknowns visited by the current search.
    pub visited: &'a mut [bool],
    /// The depth-first search's stack of equations.
    pub stack_row: &'a mut [usize],
    /// The next unknown to try at each depth.
    pub stack_col: &'a mut [usize],
    /// The equation through which each unknown was reached.
    pub parent: &'a mut [usize],
}

const NONE: usize = usize::MAX;

/// The first unknown (column) of the row-major `k × k` pattern that a maximum matching leaves
/// unpaired, if any: the pattern can be nonsingular only if there is none.
pub const fn unpaired(pattern: &[bool], k: usize, s: &mut Scratch<'_>) -> Option<usize> {
    unpaired_with_corner(pattern, k, k, s)
}

/// As [`unpaired`], with the diagonal entries from `corner` on counted as present: the
/// multipliers' corner of a saddle-point system whose redundant rows are deflated, where each
/// multiplier may pair with its own row and only the velocities can stay unpaired.
pub const fn unpaired_with_corner(
    pattern: &[bool],
    k: usize,
    corner: usize,
    s: &mut Scratch<'_>,
) -> Option<usize> {
    let mut i = 0;
    while i < k {
        s.row_of[i] = NONE;
        s.col_of[i] = NONE;
        i += 1;
    }
    let mut r = 0;
    while r < k {
        augment(pattern, k, corner, r, s);
        r += 1;
    }
    let mut c = 0;
    while c < k {
        if s.row_of[c] == NONE {
            return Some(c);
        }
        c += 1;
    }
    None
}

/// Searches depth first, with an explicit stack, for an augmenting path from equation `r` and
/// flips it if there is one.
const fn augment(pattern: &[bool], k: usize, corner: usize, r: usize, s: &mut Scratch<'_>) {
    let mut i = 0;
    while i < k {
        s.visited[i] = false;
        s.parent[i] = NONE;
        i += 1;
    }
    let mut depth = 0;
    s.stack_row[0] = r;
    s.stack_col[0] = 0;
    let mut found = NONE;
    while found == NONE {
        let row = s.stack_row[depth];
        let mut c = s.stack_col[depth];
        let mut advanced = false;
        while c < k {
            if (pattern[row * k + c] || row == c && c >= corner) && !s.visited[c] {
                s.visited[c] = true;
                s.stack_col[depth] = c + 1;
                s.parent[c] = row;
                if s.row_of[c] == NONE {
                    found = c;
                } else {
                    depth += 1;
                    s.stack_row[depth] = s.row_of[c];
                    s.stack_col[depth] = 0;
                }
                advanced = true;
                break;
            }
            c += 1;
        }
        if !advanced {
            if depth == 0 {
                return;
            }
            depth -= 1;
        }
    }
    // Flip the path back to row r.
    let mut c = found;
    loop {
        let row = s.parent[c];
        let previous = s.col_of[row];
        s.row_of[c] = row;
        s.col_of[row] = c;
        if row == r {
            break;
        }
        c = previous;
    }
}
