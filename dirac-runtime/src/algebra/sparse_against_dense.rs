//! The sparse algebra against the dense one on the same blocks: saddle-point systems,
//! refactorisation with reused pivots, new pivots when they fail, and Radau's condensed
//! solver.

use nalgebra::{Complex, Const};

use crate::algebra::sparse::{Pattern, Sparse, SparseBlock, SparseSaddle, SparseShape};
use crate::algebra::testing::numbers;
use crate::algebra::traits::{Algebra, JacobianBlocks, NewtonSolver, Saddle, SaddleTerms};
use crate::algebra::{Dense, DenseCondensed};
use crate::shape::dims::{Dimensions, Sizes, VecY};

/// Sizes of a model with 6 coordinates and 2 constraints, the first holonomic.
struct Six;

impl Dimensions for Six {
    type Nq = Const<6>;
    type Nc = Const<2>;
    type Nh = Const<1>;
    type Nk = Const<8>;
    type Ny = Const<20>;
}

const SIZES: Sizes = Sizes { nq: 6, nc: 2, nh: 1 };

/// Full patterns in nalgebra's column order, so that a dense block's values are a sparse
/// block's values.
fn full_shape() -> SparseShape {
    let (mut qq, mut cq) = (Pattern::new(6, 6), Pattern::new(2, 6));
    qq.push_dense(0..6, 0, 6);
    cq.push_dense(0..2, 0, 6);
    SparseShape::new(SIZES, qq, cq)
}

fn random_blocks(seed: u64) -> JacobianBlocks<Six, Dense> {
    let mut next = numbers(seed);
    let mut b = JacobianBlocks::<Six, Dense>::zeros();
    for x in b.dpdot_dq.iter_mut().chain(b.dpdot_dv.iter_mut()).chain(b.l_vq.iter_mut()) {
        *x = next();
    }
    for x in b.a.iter_mut().chain(b.dav_dq.iter_mut()) {
        *x = next();
    }
    // A degenerate L_vv: the last velocity has no inertia.
    for i in 0..5 {
        b.l_vv[(i, i)] = 1.0 + i as f64;
    }
    b.l_vv[(0, 1)] = 0.2;
    b.l_vv[(1, 0)] = 0.2;
    b
}

fn sparse_of(dense: &JacobianBlocks<Six, Dense>, shape: &SparseShape) -> JacobianBlocks<Six, Sparse> {
    let mut s = JacobianBlocks::<Six, Sparse>::with_shape(shape);
    s.dpdot_dq.values.copy_from_slice(dense.dpdot_dq.as_slice());
    s.dpdot_dv.values.copy_from_slice(dense.dpdot_dv.as_slice());
    s.l_vq.values.copy_from_slice(dense.l_vq.as_slice());
    s.l_vv.values.copy_from_slice(dense.l_vv.as_slice());
    s.a.values.copy_from_slice(dense.a.as_slice());
    s.dav_dq.values.copy_from_slice(dense.dav_dq.as_slice());
    s
}

/// Solves the same stage-1-like system, with every kind of term, in both algebras.
fn both_saddles(seed: u64) -> (Vec<f64>, Vec<f64>) {
    let shape = full_shape();
    let d = random_blocks(seed);
    let s = sparse_of(&d, &shape);
    let rhs: Vec<f64> = (0..8).map(|i| (i as f64 * 0.7).sin()).collect();
    let mut dense = <Dense as Algebra<Six>>::saddle::<f64>(&SIZES);
    dense.assemble(&SaddleTerms::<Six, Dense, f64> {
        top: &[(2.0, &d.l_vv), (0.3, &d.l_vq)],
        top_transposed: &[(-0.4, &d.dpdot_dv)],
        identity: 0.5,
        right: &[(-1.0, &d.a)],
        bottom: &[(1.0, 0.0, &d.a), (0.0, 1.5, &d.dav_dq)],
        corner: (0.0, 0.0),
    });
    let mut sparse = <Sparse as Algebra<Six>>::saddle::<f64>(&shape);
    Saddle::<Six, Sparse, f64>::assemble(
        &mut sparse,
        &SaddleTerms::<Six, Sparse, f64> {
            top: &[(2.0, &s.l_vv), (0.3, &s.l_vq)],
            top_transposed: &[(-0.4, &s.dpdot_dv)],
            identity: 0.5,
            right: &[(-1.0, &s.a)],
            bottom: &[(1.0, 0.0, &s.a), (0.0, 1.5, &s.dav_dq)],
            corner: (0.0, 0.0),
        },
    );
    dense.factor().expect("nonsingular");
    Saddle::<Six, Sparse, f64>::factor(&mut sparse).expect("nonsingular");
    let (mut x, mut y) = (rhs.clone(), rhs);
    dense.solve(&mut x);
    Saddle::<Six, Sparse, f64>::solve(&mut sparse, &mut y);
    (x, y)
}

fn assert_close(a: &[f64], b: &[f64]) {
    let scale = a.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= 1e-12 * scale, "{a:?} vs {b:?}");
    }
}

#[test]
fn sparse_saddle_solves_what_the_dense_one_does() {
    for seed in 1..6 {
        let (x, y) = both_saddles(seed);
        assert_close(&x, &y);
    }
}

/// `[L_vv Aᵀ; A 0] x = rhs` of the blocks `d` on `shape`, whose `m × n` pattern lists the
/// entries of `A` in `order` (`(row, column)` pairs).
fn solve_on(shape: &SparseShape, d: &JacobianBlocks<Six, Dense>, order: &[(usize, usize)]) -> Vec<f64> {
    let mut l_vv = SparseBlock::zeros(&shape.qq);
    l_vv.values.copy_from_slice(d.l_vv.as_slice());
    let mut a = SparseBlock::zeros(&shape.cq);
    for (value, &(r, c)) in a.values.iter_mut().zip(order) {
        *value = d.a[(r, c)];
    }
    let mut saddle = <Sparse as Algebra<Six>>::saddle::<f64>(shape);
    Saddle::<Six, Sparse, f64>::assemble(
        &mut saddle,
        &SaddleTerms::<Six, Sparse, f64> {
            top: &[(1.0, &l_vv)],
            top_transposed: &[],
            identity: 0.0,
            right: &[(1.0, &a)],
            bottom: &[(1.0, 1.0, &a)],
            corner: (0.0, 0.0),
        },
    );
    Saddle::<Six, Sparse, f64>::factor(&mut saddle).expect("nonsingular");
    let mut x: Vec<f64> = (0..8).map(|i| (i as f64 * 0.7).sin()).collect();
    Saddle::<Six, Sparse, f64>::solve(&mut saddle, &mut x);
    x
}

#[test]
fn saddles_of_a_shape_and_its_clones_share_one_structure_unless_a_pattern_is_replaced() {
    let shape = full_shape();
    let real = SparseSaddle::<f64>::new(&shape);
    let complex = SparseSaddle::<Complex<f64>>::new(&shape.clone());
    assert!(real.shares_structure_with(&complex), "a clone's saddle reuses the ordering");
    // A clone whose public `m × n` pattern is replaced by the same entries in another order
    // (row by row, where `full_shape` lists them column by column): reusing the first
    // structure would put every value of `A` at another's place.
    let rows: Vec<(usize, usize)> = (0..2).flat_map(|r| (0..6).map(move |c| (r, c))).collect();
    let mut replaced = shape.clone();
    let mut cq = Pattern::new(2, 6);
    for &(r, c) in &rows {
        cq.push(r, c);
    }
    replaced.cq = std::sync::Arc::new(cq);
    let own = SparseSaddle::<f64>::new(&replaced);
    assert!(!own.shares_structure_with(&real), "a replaced pattern gets a structure of its own");
    // The reference: the dense saddle of the same blocks, factored by nalgebra's LU.
    let d = random_blocks(7);
    let columns: Vec<(usize, usize)> = (0..6).flat_map(|c| (0..2).map(move |r| (r, c))).collect();
    let mut k = d.l_vv.resize(8, 8, 0.0);
    for r in 0..2 {
        for c in 0..6 {
            k[(6 + r, c)] = d.a[(r, c)];
            k[(c, 6 + r)] = d.a[(r, c)];
        }
    }
    let rhs = nalgebra::DVector::from_fn(8, |i, _| (i as f64 * 0.7).sin());
    let exact = k.lu().solve(&rhs).expect("nonsingular");
    assert_close(exact.as_slice(), &solve_on(&shape, &d, &columns));
    assert_close(exact.as_slice(), &solve_on(&replaced, &d, &rows));
}

/// A 2 × 2 system `[[a, 1], [1, 0]]` in the layout of one velocity and one multiplier.
fn two_by_two(a: f64) -> (SparseShape, SparseBlock, SparseBlock) {
    let sizes = Sizes { nq: 1, nc: 1, nh: 0 };
    let (mut qq, mut cq) = (Pattern::new(1, 1), Pattern::new(1, 1));
    qq.push(0, 0);
    cq.push(0, 0);
    let shape = SparseShape::new(sizes, qq, cq);
    let mut top = SparseBlock::zeros(&shape.qq);
    top.values[0] = a;
    let mut one = SparseBlock::zeros(&shape.cq);
    one.values[0] = 1.0;
    (shape, top, one)
}

struct One;

impl Dimensions for One {
    type Nq = Const<1>;
    type Nc = Const<1>;
    type Nh = Const<0>;
    type Nk = Const<2>;
    type Ny = Const<4>;
}

fn factor_two_by_two(saddle: &mut SparseSaddle<f64>, top: &SparseBlock, one: &SparseBlock) {
    Saddle::<One, Sparse, f64>::assemble(
        saddle,
        &SaddleTerms::<One, Sparse, f64> {
            top: &[(1.0, top)],
            top_transposed: &[],
            identity: 0.0,
            right: &[(1.0, one)],
            bottom: &[(1.0, 1.0, one)],
            corner: (0.0, 0.0),
        },
    );
    Saddle::<One, Sparse, f64>::factor(saddle).expect("nonsingular");
}

/// New values reuse the pivots while they serve, and get new pivots when a reused one
/// becomes small: `[[a, 1], [1, 0]] x = (1, 2)` has `x = (2, 1 − 2a)` for every `a`. The
/// first pivots take `a`; at `a = 1e-14` they fail and the new ones take the constraint's 1,
/// which still serves at `a = 5`.
#[test]
fn refactorisation_reuses_pivots_until_they_fail() {
    let (shape, mut top, one) = two_by_two(4.0);
    let mut saddle = <Sparse as Algebra<One>>::saddle::<f64>(&shape);
    for (a, pivotings) in [(4.0, 1), (3.0, 1), (1e-14, 2), (5.0, 2)] {
        top.values[0] = a;
        factor_two_by_two(&mut saddle, &top, &one);
        let mut x = vec![1.0, 2.0];
        Saddle::<One, Sparse, f64>::solve(&mut saddle, &mut x);
        assert_close(&x, &[2.0, 1.0 - 2.0 * a]);
        assert_eq!(saddle.pivotings(), pivotings, "a = {a}");
    }
}

#[test]
fn singular_systems_name_their_unknown() {
    let (shape, top, _) = two_by_two(1.0);
    let zero = SparseBlock::zeros(&shape.cq);
    let mut saddle = <Sparse as Algebra<One>>::saddle::<f64>(&shape);
    Saddle::<One, Sparse, f64>::assemble(
        &mut saddle,
        &SaddleTerms::<One, Sparse, f64> {
            top: &[(1.0, &top)],
            top_transposed: &[],
            identity: 0.0,
            right: &[(1.0, &zero)],
            bottom: &[(1.0, 1.0, &zero)],
            corner: (0.0, 0.0),
        },
    );
    let error = Saddle::<One, Sparse, f64>::factor(&mut saddle).expect_err("the multiplier has no pivot");
    assert_eq!(error.column, 1);
}

/// An entry stored twice adds up.
#[test]
fn repeated_entries_add() {
    let sizes = Sizes { nq: 2, nc: 0, nh: 0 };
    let mut qq = Pattern::new(2, 2);
    for (r, c) in [(0, 0), (1, 1), (0, 0)] {
        qq.push(r, c);
    }
    let shape = SparseShape::new(sizes, qq, Pattern::new(0, 2));
    let mut block = SparseBlock::zeros(&shape.qq);
    block.values.copy_from_slice(&[1.0, 4.0, 2.0]);
    let mut y = vec![0.0; 2];
    <Sparse as Algebra<Six>>::qq_mul(&block, 1.0, &[1.0, 1.0], &mut y);
    assert_eq!(y, [3.0, 4.0]);
}

/// The dense condensed solver is checked against the full system in `newton`'s tests.
#[test]
fn sparse_condensed_solver_matches_the_dense_one() {
    let shape = full_shape();
    let d = random_blocks(9);
    let s = sparse_of(&d, &shape);
    let (sigma, sigma_c) = (3.7, Complex::new(2.7, 3.1));
    let mut dense = DenseCondensed::<Six>::new(SIZES);
    let mut sparse = <Sparse as Algebra<Six>>::condensed(&shape);
    dense.factor(&d, sigma, sigma_c).expect("nonsingular");
    sparse.factor(&s, sigma, sigma_c).expect("nonsingular");
    let rhs = VecY::<Six>::from_fn(|i, _| (i as f64 * 0.37).sin());
    let im = VecY::<Six>::from_fn(|i, _| (i as f64 * 0.91).cos());
    let (mut a, mut b) = (rhs, rhs);
    dense.solve(&mut a);
    sparse.solve(&mut b);
    assert_close(a.as_slice(), b.as_slice());
    let (mut ar, mut ai, mut br, mut bi) = (rhs, im, rhs, im);
    dense.solve_complex(&mut ar, &mut ai);
    sparse.solve_complex(&mut br, &mut bi);
    assert_close(ar.as_slice(), br.as_slice());
    assert_close(ai.as_slice(), bi.as_slice());
}
