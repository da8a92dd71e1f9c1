//! Where the parts of a composite made of arrays of subsystems sit, for code that
//! `#[derive(Interconnection)]` generates. Not part of the public API.
//!
//! Such a composite is sized when it runs: its fields hold `count` subsystems each (one for a
//! plain field). Coordinates follow field order and, within a field, element order. Rows are
//! every subsystem's holonomic rows (same order), then every subsystem's other rows, then the
//! composite's own rows, one block per row pattern (`connect(cells[i].b, cells[i + 1].a)`) with
//! one row for each element index `i` that names only existing elements. Block values follow
//! the same order: each subsystem's dense blocks, column by column, then the own rows'
//! entries, instance by instance.

use crate::model::assemble::Offsets;
use crate::shape::dims::Sizes;

/// One field of a composite made of arrays: how many subsystems it holds and their sizes.
#[derive(Clone, Copy, Debug)]
pub struct Field {
    /// Subsystems in the field: its length for an array, 1 otherwise.
    pub count: usize,
    /// Each subsystem's sizes.
    pub sizes: Sizes,
}

/// A row pattern of the composite's own rows: its instances and the entries of each.
#[derive(Clone, Copy, Debug)]
pub struct Pattern {
    /// The element index `i` of the first instance.
    pub first: isize,
    /// How many instances there are.
    pub count: usize,
    /// Entries of one instance in the `m × n` blocks.
    pub cq: usize,
    /// Entries of one instance in the `n × n` blocks.
    pub qq: usize,
}

/// The element indices `i` for which every element a row pattern names exists: the largest
/// range with `0 ≤ i + offset < len` for every `(len, offset)`, as its first index and length.
/// A pattern that names no element index (`connect(wall.x, cells[0].a)`) passes no pairs and
/// gets one instance, `i = 0`, if `fixed` (whether every element it names exists) holds.
pub fn instances(named: &[(usize, isize)], fixed: bool) -> (isize, usize) {
    if !fixed {
        return (0, 0);
    }
    if named.is_empty() {
        return (0, 1);
    }
    let first = named.iter().map(|&(_, offset)| -offset).max().unwrap_or(0);
    let end = named.iter().map(|&(len, offset)| len as isize - offset).min().unwrap_or(0);
    (first, (end - first).max(0) as usize)
}

/// Where every subsystem and own row of a composite made of arrays sits.
#[derive(Clone, Copy, Debug)]
pub struct Placement<const F: usize, const R: usize> {
    fields: [Field; F],
    q0: [usize; F],
    h0: [usize; F],
    v0: [usize; F],
    qq0: [usize; F],
    cq0: [usize; F],
    /// The own row patterns.
    pub patterns: [Pattern; R],
    row0: [usize; R],
    own_qq0: [usize; R],
    own_cq0: [usize; R],
    /// The composite's sizes.
    pub sizes: Sizes,
    /// Values of an `n × n` block.
    pub qq_len: usize,
    /// Values of an `m × n` block.
    pub cq_len: usize,
}

impl<const F: usize, const R: usize> Placement<F, R> {
    /// The placement of these fields and row patterns.
    pub fn new(fields: [Field; F], patterns: [Pattern; R]) -> Self {
        let (mut q0, mut h0, mut v0, mut qq0, mut cq0) = ([0; F], [0; F], [0; F], [0; F], [0; F]);
        let (mut nq, mut nh, mut other, mut qq, mut cq) = (0, 0, 0, 0, 0);
        for (f, field) in fields.iter().enumerate() {
            let s = field.sizes;
            (q0[f], h0[f], v0[f], qq0[f], cq0[f]) = (nq, nh, other, qq, cq);
            nq += field.count * s.nq;
            nh += field.count * s.nh;
            other += field.count * (s.nc - s.nh);
            qq += field.count * s.nq * s.nq;
            cq += field.count * s.nc * s.nq;
        }
        for v in &mut v0 {
            *v += nh;
        }
        let (mut row0, mut own_qq0, mut own_cq0) = ([0; R], [0; R], [0; R]);
        let mut rows = nh + other;
        for (r, p) in patterns.iter().enumerate() {
            (row0[r], own_qq0[r], own_cq0[r]) = (rows, qq, cq);
            rows += p.count;
            qq += p.count * p.qq;
            cq += p.count * p.cq;
        }
        let sizes = Sizes { nq, nc: rows, nh };
        Placement {
            fields,
            q0,
            h0,
            v0,
            qq0,
            cq0,
            patterns,
            row0,
            own_qq0,
            own_cq0,
            sizes,
            qq_len: qq,
            cq_len: cq,
        }
    }

    /// Where element `e` of field `f` sits.
    pub fn slot(&self, f: usize, e: usize) -> Offsets {
        let s = self.fields[f].sizes;
        Offsets { q: self.q0[f] + e * s.nq, h: self.h0[f] + e * s.nh, v: self.v0[f] + e * (s.nc - s.nh) }
    }

    /// Where the values of element `e` of field `f`'s `n × n` blocks start.
    pub fn qq_at(&self, f: usize, e: usize) -> usize {
        let n = self.fields[f].sizes.nq;
        self.qq0[f] + e * n * n
    }

    /// Where the values of element `e` of field `f`'s `m × n` blocks start.
    pub fn cq_at(&self, f: usize, e: usize) -> usize {
        let s = self.fields[f].sizes;
        self.cq0[f] + e * s.nc * s.nq
    }

    /// The row of instance `n` of own row pattern `r`.
    pub fn row(&self, r: usize, n: usize) -> usize {
        self.row0[r] + n
    }

    /// Where the `n × n` entries of instance `n` of own row pattern `r` start.
    pub fn own_qq_at(&self, r: usize, n: usize) -> usize {
        self.own_qq0[r] + n * self.patterns[r].qq
    }

    /// Where the `m × n` entries of instance `n` of own row pattern `r` start.
    pub fn own_cq_at(&self, r: usize, n: usize) -> usize {
        self.own_cq0[r] + n * self.patterns[r].cq
    }

    /// Appends the dense blocks of every subsystem to the patterns of the `n × n` and `m × n`
    /// blocks, in the order the generated methods write their values.
    pub fn member_patterns(&self, qq: &mut crate::algebra::Pattern, cq: &mut crate::algebra::Pattern) {
        for (f, field) in self.fields.iter().enumerate() {
            let s = field.sizes;
            for e in 0..field.count {
                let slot = self.slot(f, e);
                qq.push_dense(slot.q..slot.q + s.nq, slot.q, s.nq);
                let rows = (0..s.nc).map(move |r| if r < s.nh { slot.h + r } else { slot.v + r - s.nh });
                cq.push_dense(rows, slot.q, s.nq);
            }
        }
    }
}

/// Copies a subsystem's dense block (column by column) into a composite block's values.
pub fn put(values: &mut [f64], at: usize, block: &[f64]) {
    values[at..at + block.len()].copy_from_slice(block);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn instances_are_the_indices_naming_existing_elements() {
        // cells[i] and cells[i + 1] in an array of 5: i = 0..4.
        assert_eq!(instances(&[(5, 0), (5, 1)], true), (0, 4));
        // cells[i - 1] and cells[i]: i = 1..5.
        assert_eq!(instances(&[(5, -1), (5, 0)], true), (1, 4));
        // An empty array: no instance.
        assert_eq!(instances(&[(0, 0), (0, 1)], true), (0, 0));
        assert_eq!(instances(&[], true), (0, 1));
        assert_eq!(instances(&[], false), (0, 0));
    }

    #[test]
    fn placement_orders_holonomic_rows_first_then_other_rows_then_own_rows() {
        let one = Sizes { nq: 2, nc: 2, nh: 1 };
        let fields =
            [Field { count: 3, sizes: one }, Field { count: 1, sizes: Sizes { nq: 1, nc: 0, nh: 0 } }];
        let patterns = [Pattern { first: 0, count: 2, cq: 2, qq: 0 }];
        let p = Placement::new(fields, patterns);
        assert_eq!(p.sizes, Sizes { nq: 7, nc: 3 + 3 + 2, nh: 3 });
        assert_eq!(p.slot(0, 2).q, 4);
        assert_eq!(p.slot(0, 2).h, 2);
        assert_eq!(p.slot(0, 2).v, 3 + 2);
        assert_eq!(p.slot(1, 0).q, 6);
        assert_eq!(p.row(0, 1), 7);
        assert_eq!((p.qq_len, p.cq_len), (3 * 4 + 1, 3 * 4 + 4));
        assert_eq!(p.own_cq_at(0, 1), 12 + 2);
        let (mut qq, mut cq) = (crate::algebra::Pattern::new(7, 7), crate::algebra::Pattern::new(8, 7));
        p.member_patterns(&mut qq, &mut cq);
        assert_eq!((qq.len(), cq.len()), (13, 12));
        // Element 1's other row sits after every holonomic row.
        assert_eq!((cq.rows[4 + 1], cq.cols[4 + 1]), (4, 2));
    }
}
