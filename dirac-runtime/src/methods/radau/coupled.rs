//! The sensitivities' stage system of one step, solved exactly: the three stages coupled,
//! condensed by the Lagrange-Dirac structure to the velocities and multipliers of every stage,
//! `3 (n + m)` unknowns, factored once a step and shared by every sensitivity.
//!
//! With `S_k = (Q_k, V_k, P_k, Λ_k)` the sensitivity at stage `k` and `s_n = (Q₀, V₀, P₀, Λ₀)`
//! at the step's start, the stage equations `M (S_k − s_n) = h Σ_j a_kj (J_j S_j + g_j)` are
//!
//! ```text
//! Q_k = Q₀ + h Σ_l a_kl V_l                                        (positions)
//! P_k = G_k Q_k + W_k V_k − g_v,k                                   (momenta: algebraic rows)
//! P_k − P₀ = h Σ_j a_kj (D_j Q_j + E_j V_j + A_jᵀ Λ_j + g_p,j)     (momentum balance)
//! 0 = C_k Q_k + A_k V_k + g_c,k                                     (constraints)
//! ```
//!
//! with `G = L_vq`, `W = L_vv`, `D = ∂ṗ/∂q`, `E = ∂ṗ/∂v`, `C = ∂(A v)/∂q` at each stage. The
//! first two are substitutions, so the last two, in `V_1..3` and `Λ_1..3`, are the whole
//! system: nonsingular exactly when the full one is, for degenerate Lagrangians too. Unlike the
//! simplified Newton iteration on the step's factored matrix, whose rate is set by how far the
//! stage Jacobians moved from the factored one, this is one solve per sensitivity on any model.

use nalgebra::{Const, DVector, DefaultAllocator};

use super::tableau::A;
use crate::algebra::lu::{Lu, Singular};
use crate::algebra::{Algebra, JacobianBlocks};
use crate::shape::dims::{Dimensions, Storage, VecY};
use crate::shape::layout::Layout;

/// The iterations a step, over all sensitivities, from which the coupled solve is the cheaper:
/// its factorisation costs about as much as two of the simplified iteration's, and its solves
/// about a third of one each. Measured on the pendulum (`n + m = 3`), the rolling disk (6)
/// and the 8-link pendulum (8) with 1 to 4 sensitivities: the two cost the same at about six
/// iterations a step, with the state's Newton iterations standing for the sensitivities'
/// (they need about as many, 3.2 against 2.9 on the pendulum).
pub const WORTH_FROM: usize = 6;

/// The factors of the coupled matrix, of a size fixed by their type, so that the factorisation
/// and the substitutions run as loops of known length (they are most of what the
/// sensitivities of a small model cost). Up to `3 (n + m) = 24` unknowns: above, the
/// factorisation's `9 (n + m)³` operations a step grow faster than the iteration's `(n + m)²`
/// per sensitivity and iteration, and the iteration is left to do the work.
// One per integration with sensitivities, inside their boxed work space: the variants' sizes
// differ, but no array of them is ever made.
#[allow(clippy::large_enum_variant)]
enum Factors {
    S3(Lu<f64, Const<3>>),
    S6(Lu<f64, Const<6>>),
    S9(Lu<f64, Const<9>>),
    S12(Lu<f64, Const<12>>),
    S15(Lu<f64, Const<15>>),
    S18(Lu<f64, Const<18>>),
    S21(Lu<f64, Const<21>>),
    S24(Lu<f64, Const<24>>),
}

/// Runs `$body` with `$lu` bound to the factors, whatever their size.
macro_rules! with_factors {
    ($factors:expr, $lu:ident => $body:expr) => {
        match $factors {
            Factors::S3($lu) => $body,
            Factors::S6($lu) => $body,
            Factors::S9($lu) => $body,
            Factors::S12($lu) => $body,
            Factors::S15($lu) => $body,
            Factors::S18($lu) => $body,
            Factors::S21($lu) => $body,
            Factors::S24($lu) => $body,
        }
    };
}

impl Factors {
    /// Storage for `size` unknowns, a multiple of 3 up to 24; none above.
    fn new(size: usize) -> Option<Self> {
        Some(match size {
            3 => Factors::S3(Lu::new(size)),
            6 => Factors::S6(Lu::new(size)),
            9 => Factors::S9(Lu::new(size)),
            12 => Factors::S12(Lu::new(size)),
            15 => Factors::S15(Lu::new(size)),
            18 => Factors::S18(Lu::new(size)),
            21 => Factors::S21(Lu::new(size)),
            24 => Factors::S24(Lu::new(size)),
            _ => return None,
        })
    }

    /// The matrix to factor, column by column.
    fn matrix(&mut self) -> &mut [f64] {
        with_factors!(self, lu => lu.matrix_mut().as_mut_slice())
    }

    fn factor(&mut self) -> Result<(), Singular> {
        with_factors!(self, lu => lu.factor())
    }

    fn solve(&self, b: &mut [f64]) {
        with_factors!(self, lu => lu.solve_by_columns(b))
    }
}

/// Where the entries of the coupled matrix go: a dense column-major matrix, or a sparse one.
pub(crate) trait Entries {
    /// Adds `value` at `(row, column)`.
    fn add(&mut self, row: usize, column: usize, value: f64);

    /// Adds `coefficient` times the `n × n` block `x` with its first entry at `(row, column)`.
    fn add_qq<M: Dimensions, Alg: Algebra<M>>(
        &mut self,
        x: &Alg::Qq,
        coefficient: f64,
        row: usize,
        column: usize,
    ) where
        DefaultAllocator: Storage<M>,
    {
        if coefficient != 0.0 {
            Alg::qq_entries(x, |i, c, y| self.add(row + i, column + c, coefficient * y));
        }
    }
}

/// A dense square matrix stored column by column, `size` rows.
pub(crate) struct Columns<'a> {
    pub mat: &'a mut [f64],
    pub size: usize,
}

impl Entries for Columns<'_> {
    fn add(&mut self, row: usize, column: usize, value: f64) {
        self.mat[column * self.size + row] += value;
    }

    /// Column by column where `x` is stored densely, entry by entry otherwise.
    fn add_qq<M: Dimensions, Alg: Algebra<M>>(
        &mut self,
        x: &Alg::Qq,
        coefficient: f64,
        row: usize,
        column: usize,
    ) where
        DefaultAllocator: Storage<M>,
    {
        if coefficient == 0.0 {
            return;
        }
        let size = self.size;
        match Alg::dense_qq(x) {
            Some(d) if d.nrows() > 0 => {
                let n = d.nrows();
                for (c, from) in d.as_slice().chunks_exact(n).enumerate() {
                    let start = (column + c) * size + row;
                    for (to, &y) in self.mat[start..start + n].iter_mut().zip(from) {
                        *to += coefficient * y;
                    }
                }
            }
            _ => Alg::qq_entries(x, |i, c, y| self.mat[(column + c) * size + row + i] += coefficient * y),
        }
    }
}

/// The coupled stage matrix of a step, factored, and the work space of its solves.
pub(crate) struct Coupled {
    lu: Factors,
    /// The right-hand side, then the solution: `(V_k, Λ_k)` for `k = 1, 2, 3`.
    x: DVector<f64>,
    /// `D_j Q₀ + g_p,j` for each stage `j`, then `Q_k`.
    dq: [Vec<f64>; 3],
    n: usize,
    m: usize,
}

impl Coupled {
    /// The work space for a model of this layout, or none if its coupled system is larger than
    /// [`Factors`] hold.
    pub fn new(layout: &Layout) -> Option<Self> {
        let (n, m) = (layout.v - layout.q, layout.len - layout.lambda);
        let size = 3 * (n + m);
        Some(Coupled {
            lu: Factors::new(size)?,
            x: DVector::zeros(size),
            dq: [vec![0.0; n], vec![0.0; n], vec![0.0; n]],
            n,
            m,
        })
    }

    /// Where `V_k` and `Λ_k` start among the unknowns.
    fn starts(&self, k: usize) -> (usize, usize) {
        let stage = k * (self.n + self.m);
        (stage, stage + self.n)
    }

    /// Assembles and factors the coupled matrix of a step of size `h` with the stage
    /// Jacobians `jac`.
    pub fn factor<M: Dimensions, Alg: Algebra<M>>(
        &mut self,
        jac: &[JacobianBlocks<M, Alg>; 3],
        h: f64,
    ) -> Result<(), Singular>
    where
        DefaultAllocator: Storage<M>,
    {
        let (n, m) = (self.n, self.m);
        let mat = self.lu.matrix();
        mat.fill(0.0);
        assemble(jac, h, n, m, &mut Columns { mat, size: 3 * (n + m) });
        self.lu.factor()
    }

    /// Solves the factored system for the sensitivity `s` at the step's start, with parameter
    /// derivatives `g` at the stages (none for an initial value), writing its stage increments
    /// `z_k = S_k − s`.
    pub fn solve<M: Dimensions, Alg: Algebra<M>>(
        &mut self,
        l: &Layout,
        jac: &[JacobianBlocks<M, Alg>; 3],
        h: f64,
        s: &VecY<M>,
        g: Option<&[VecY<M>; 3]>,
        z: &mut [VecY<M>; 3],
    ) where
        DefaultAllocator: Storage<M>,
    {
        let s = s.as_slice();
        let (q0, v0, p0, l0) = (&s[l.q..l.v], &s[l.v..l.p], &s[l.p..l.lambda], &s[l.lambda..l.len]);
        for (j, jj) in jac.iter().enumerate() {
            let dq = &mut self.dq[j];
            match g {
                Some(g) => dq.copy_from_slice(&g[j].as_slice()[l.p..l.lambda]),
                None => dq.fill(0.0),
            }
            Alg::qq_mul(&jj.dpdot_dq, 1.0, q0, dq);
        }
        for (k, jk) in jac.iter().enumerate() {
            let (v, lambda) = self.starts(k);
            let x = self.x.as_mut_slice();
            let rp = &mut x[v..lambda];
            rp.copy_from_slice(p0);
            if let Some(g) = g {
                for (r, gv) in rp.iter_mut().zip(&g[k].as_slice()[l.v..l.p]) {
                    *r += gv;
                }
            }
            Alg::qq_mul(&jk.l_vq, -1.0, q0, rp);
            for (j, dq) in self.dq.iter().enumerate() {
                let c = h * A[k][j];
                for (r, d) in rp.iter_mut().zip(dq) {
                    *r += c * d;
                }
            }
            let rc = &mut x[lambda..lambda + self.m];
            match g {
                Some(g) => {
                    for (r, gc) in rc.iter_mut().zip(&g[k].as_slice()[l.lambda..l.len]) {
                        *r = -gc;
                    }
                }
                None => rc.fill(0.0),
            }
            Alg::cq_mul(&jk.dav_dq, -1.0, q0, rc);
        }
        self.lu.solve(self.x.as_mut_slice());
        let (n, m) = (self.n, self.m);
        let vs = [0, 1, 2].map(|c| self.starts(c).0);
        for (k, (jk, zk)) in jac.iter().zip(z.iter_mut()).enumerate() {
            let (v, lambda) = self.starts(k);
            let x = self.x.as_slice();
            let zk = zk.as_mut_slice();
            // Q_k − Q₀ = h Σ_l a_kl V_l, and Q_k kept for the momenta.
            let qk = &mut self.dq[0];
            for i in 0..n {
                let dq = h * (0..3).map(|c| A[k][c] * x[vs[c] + i]).sum::<f64>();
                zk[l.q + i] = dq;
                qk[i] = q0[i] + dq;
            }
            for (zi, (xi, si)) in zk[l.v..l.p].iter_mut().zip(x[v..lambda].iter().zip(v0)) {
                *zi = xi - si;
            }
            for (zi, (xi, si)) in zk[l.lambda..l.len].iter_mut().zip(x[lambda..lambda + m].iter().zip(l0)) {
                *zi = xi - si;
            }
            // P_k − P₀ = G_k Q_k + W_k V_k − g_v,k − P₀.
            let zp = &mut zk[l.p..l.lambda];
            match g {
                Some(g) => {
                    for (zi, (gv, p)) in zp.iter_mut().zip(g[k].as_slice()[l.v..l.p].iter().zip(p0)) {
                        *zi = -gv - p;
                    }
                }
                None => {
                    for (zi, p) in zp.iter_mut().zip(p0) {
                        *zi = -p;
                    }
                }
            }
            Alg::qq_mul(&jk.l_vq, 1.0, qk, zp);
            Alg::qq_mul(&jk.l_vv, 1.0, &x[v..v + n], zp);
        }
    }
}

/// Adds the coupled matrix of a step of size `h` with the stage Jacobians `jac` into `out`,
/// `3 (n + m)` square: the unknowns `(V_k, Λ_k)` and the rows (momentum balance,
/// constraints) of stage `k` from `k (n + m)`. The adjoint sweep factors its transpose.
pub(crate) fn assemble<M: Dimensions, Alg: Algebra<M>, E: Entries>(
    jac: &[JacobianBlocks<M, Alg>; 3],
    h: f64,
    n: usize,
    m: usize,
    out: &mut E,
) where
    DefaultAllocator: Storage<M>,
{
    let stage = |k: usize| (k * (n + m), k * (n + m) + n);
    let starts = [stage(0), stage(1), stage(2)];
    let (vs, ls) = (starts.map(|s| s.0), starts.map(|s| s.1));
    // Momentum balance of stage r, in V_c: δ_rc W_r + h a_rc (G_r − E_c)
    //   − h² Σ_k a_rk a_kc D_k.
    for (r, jr) in jac.iter().enumerate() {
        for (c, jc) in jac.iter().enumerate() {
            let (row, column) = (vs[r], vs[c]);
            let a = h * A[r][c];
            if r == c {
                out.add_qq::<M, Alg>(&jr.l_vv, 1.0, row, column);
            }
            out.add_qq::<M, Alg>(&jr.l_vq, a, row, column);
            out.add_qq::<M, Alg>(&jc.dpdot_dv, -a, row, column);
            for (k, jk) in jac.iter().enumerate() {
                out.add_qq::<M, Alg>(&jk.dpdot_dq, -h * h * A[r][k] * A[k][c], row, column);
            }
        }
    }
    for (k, jk) in jac.iter().enumerate() {
        // The multipliers of stage k in every stage's momentum balance: −h a_lk A_kᵀ.
        Alg::cq_entries(&jk.a, |r, c, x| {
            for l in 0..3 {
                out.add(vs[l] + c, ls[k] + r, -h * A[l][k] * x);
            }
            // Constraints of stage k: A_k V_k + h Σ_l a_kl C_k V_l.
            out.add(ls[k] + r, vs[k] + c, x);
        });
        Alg::cq_entries(&jk.dav_dq, |r, c, x| {
            for l in 0..3 {
                out.add(ls[k] + r, vs[l] + c, h * A[k][l] * x);
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{DMatrix, DVector};

    use super::*;
    use crate::algebra::Dense;
    use crate::algebra::testing::{self, THREE, Three};
    use crate::shape::dims::Sizes;

    const SIZES: Sizes = THREE;

    /// Seeded blocks, a different Jacobian for each seed, the inertia too.
    fn blocks(seed: u64) -> JacobianBlocks<Three, Dense> {
        let mut b = testing::blocks(seed);
        b.l_vv[(0, 0)] += 0.1 * seed as f64;
        b
    }

    /// The flat Jacobian `J = ∂f/∂y` of `y = (q, v, p, λ)`, written from the equations
    /// `q̇ = v`, `0 = p − ∂L/∂v`, `ṗ = ∂L/∂q + F + Aᵀλ`, `0 = A v + b` independently of the
    /// condensation.
    fn flat(b: &JacobianBlocks<Three, Dense>) -> DMatrix<f64> {
        DMatrix::from_fn(10, 10, |i, j| {
            let (bi, ri) = (i / 3, i % 3);
            let (bj, rj) = (j / 3, j % 3);
            let eye = if ri == rj { 1.0 } else { 0.0 };
            match (bi, bj) {
                (0, 1) => eye,
                (1, 0) => -b.l_vq[(ri, rj)],
                (1, 1) => -b.l_vv[(ri, rj)],
                (1, 2) => eye,
                (2, 0) => b.dpdot_dq[(ri, rj)],
                (2, 1) => b.dpdot_dv[(ri, rj)],
                (2, 3) => b.a[(0, ri)],
                (3, 0) => b.dav_dq[(0, rj)],
                (3, 1) => b.a[(0, rj)],
                _ => 0.0,
            }
        })
    }

    /// The solve satisfies the full stage equations `M (S_k − s) = h Σ_j a_kj (J_j S_j + g_j)`
    /// with a different Jacobian at each stage, for a parameter and for an initial value.
    #[test]
    fn the_solution_satisfies_the_three_coupled_stage_equations() {
        let jac = [blocks(3), blocks(5), blocks(11)];
        let layout = Layout::new(SIZES);
        let mut coupled = Coupled::new(&layout).expect("small enough");
        let h = 0.37;
        coupled.factor(&jac, h).expect("nonsingular");
        let s = VecY::<Three>::from_fn(|i, _| (i as f64 * 0.71).sin());
        let g: [VecY<Three>; 3] = core::array::from_fn(|k| {
            VecY::<Three>::from_fn(|i, _| if i < 3 { 0.0 } else { (i * (k + 2)) as f64 * 0.1 })
        });
        let mass =
            DMatrix::from_fn(10, 10, |i, j| if i == j && (i < 3 || (6..9).contains(&i)) { 1.0 } else { 0.0 });
        for g in [Some(&g), None] {
            let mut z: [VecY<Three>; 3] = core::array::from_fn(|_| VecY::<Three>::zeros());
            coupled.solve(&layout, &jac, h, &s, g, &mut z);
            let stage = |k: usize| DVector::from_fn(10, |i, _| s[i] + z[k][i]);
            for k in 0..3 {
                let zk = DVector::from_fn(10, |i, _| z[k][i]);
                let mut residual = &mass * zk;
                for (j, jj) in jac.iter().enumerate() {
                    let mut fj = flat(jj) * stage(j);
                    if let Some(g) = g {
                        fj += DVector::from_fn(10, |i, _| g[j][i]);
                    }
                    residual -= h * A[k][j] * fj;
                }
                assert!(residual.amax() < 1e-13, "stage {k}: residual {residual}");
            }
        }
    }

    /// Without inertia, forces or constraint rows the stage system has no unknown to solve
    /// for: the factorisation says so (and the sensitivities then iterate instead).
    #[test]
    fn a_singular_coupled_system_is_reported() {
        let zero = || JacobianBlocks::<Three, Dense>::with_shape(&SIZES);
        let mut coupled = Coupled::new(&Layout::new(SIZES)).expect("small enough");
        assert!(coupled.factor(&[zero(), zero(), zero()], 0.1).is_err());
    }

    #[test]
    fn models_too_large_are_left_to_the_iteration() {
        let sizes = Sizes { nq: 6, nc: 3, nh: 0 };
        assert!(Coupled::new(&Layout::new(sizes)).is_none());
    }
}
