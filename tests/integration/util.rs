//! Seeded random states and a finite-difference oracle for generated derivatives.

use dirac::Storage;
use dirac::nalgebra::DefaultAllocator;
use dirac::prelude::*;

/// SplitMix64: a small, seeded generator so every run checks the same states.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }
}

/// A random flat state with every component in `[-1, 1)`.
pub fn random_y<M: LagrangeDirac>(model: &M, rng: &mut Rng) -> VecY<M>
where
    DefaultAllocator: Storage<M>,
{
    let mut y = model.sizes().zeros_y::<M>();
    y.iter_mut().for_each(|x| *x = rng.uniform(-1.0, 1.0));
    y
}

/// Checks `jacobian` against central differences of `residual` at `trials` random states:
/// every entry agrees to `1e-6` relative to the larger of the entry and 1.
pub fn check_jacobian_by_differences<M: LagrangeDirac>(model: &M, seed: u64, trials: usize)
where
    DefaultAllocator: Storage<M>,
{
    let mut rng = Rng::new(seed);
    let ny = model.sizes().ny();
    for _ in 0..trials {
        let t = rng.uniform(0.0, 2.0);
        let y = random_y(model, &mut rng);
        let jac = model.jacobian_matrix(t, &y);
        for c in 0..ny {
            let h = 1e-6 * y[c].abs().max(1.0);
            let (mut plus, mut minus) = (y.clone(), y.clone());
            plus[c] += h;
            minus[c] -= h;
            let fd = (model.residual_vector(t, &plus) - model.residual_vector(t, &minus)) / (2.0 * h);
            for r in 0..ny {
                let (exact, approx) = (jac[(r, c)], fd[r]);
                let tol = 1e-6 * exact.abs().max(1.0);
                assert!(
                    (exact - approx).abs() <= tol,
                    "∂f{r}/∂y{c}: generated {exact}, central difference {approx} at y = {y:?}, t = {t}"
                );
            }
        }
    }
}

/// The compressed-sparse-column Jacobian against the dense one (itself checked against central
/// differences): a well-formed pattern, equal stored values, and exact zeros outside the pattern.
pub fn check_csc_against_dense<M: SparseJacobian>(model: &M, seed: u64, trials: usize)
where
    DefaultAllocator: Storage<M>,
{
    let ny = model.sizes().ny();
    let (starts, rows) = (M::JACOBIAN_COLUMN_STARTS, M::JACOBIAN_ROW_INDICES);
    assert_eq!(starts.len(), ny + 1, "one start per column and the end");
    assert_eq!((starts[0], starts[ny]), (0, rows.len()));
    for c in 0..ny {
        let column = &rows[starts[c]..starts[c + 1]];
        assert!(column.windows(2).all(|w| w[0] < w[1]) && column.iter().all(|&r| r < ny));
    }
    let mut rng = Rng::new(seed);
    let mut values = vec![0.0; rows.len()];
    for _ in 0..trials {
        let t = rng.uniform(0.0, 2.0);
        let y = random_y(model, &mut rng);
        let dense = model.jacobian_matrix(t, &y);
        values.fill(f64::NAN);
        model.jacobian_csc(t, &y, &mut values);
        let mut stored = model.sizes().zeros_yy::<M>();
        for c in 0..ny {
            for k in starts[c]..starts[c + 1] {
                stored[(rows[k], c)] = values[k];
            }
        }
        assert_eq!(stored, dense, "CSC values scattered back differ from the dense Jacobian");
    }
}

/// The roots of `f` in `[a, b]`, in increasing order: each sign change over `pieces` equal
/// pieces, bisected until the midpoint is an end.
pub fn roots_in(f: &dyn Fn(f64) -> f64, a: f64, b: f64, pieces: usize) -> Vec<f64> {
    let at = |i: usize| a + (b - a) * i as f64 / pieces as f64;
    let mut roots = Vec::new();
    for i in 0..pieces {
        let (mut lo, mut hi) = (at(i), at(i + 1));
        if f(lo) * f(hi) >= 0.0 {
            continue;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid == lo || mid == hi {
                break;
            }
            if f(lo) * f(mid) <= 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        roots.push(0.5 * (lo + hi));
    }
    roots
}
