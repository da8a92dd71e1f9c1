//! Dense output: the collocation polynomial of the last accepted step, for sampling between
//! steps and for the starting values of the next step's Newton iteration.

use nalgebra::DefaultAllocator;

use super::tableau::{C1, C2, TI};
use crate::model::LagrangeDirac;
use crate::model::state::State;
use crate::shape::dims::{Sizes, Storage, VecY};

/// The last step's collocation polynomial, as Newton divided differences at `s = c − 1`.
pub(crate) struct Dense<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    cont: [VecY<M>; 3],
    /// The size of the last accepted step.
    pub h: f64,
}

impl<M: LagrangeDirac> Dense<M>
where
    DefaultAllocator: Storage<M>,
{
    pub fn new(sizes: Sizes) -> Self {
        Dense { cont: [sizes.zeros_y::<M>(), sizes.zeros_y::<M>(), sizes.zeros_y::<M>()], h: 0.0 }
    }

    /// Takes the polynomial of a step of size `h` with stage increments `z`.
    // Indexing vectors of a size known to the compiler beats nalgebra's strided iterators.
    #[allow(clippy::needless_range_loop)]
    pub fn update(&mut self, z: &[VecY<M>; 3], h: f64) {
        // Reciprocals of constants, folded by the compiler: the loop multiplies.
        let (c1m1, c2m1, c1mc2) = (1.0 / (C1 - 1.0), 1.0 / (C2 - 1.0), 1.0 / (C1 - C2));
        let (c1, c2) = (1.0 / C1, 1.0 / C2);
        for i in 0..z[0].len() {
            let (z1, z2, z3) = (z[0][i], z[1][i], z[2][i]);
            let d1 = (z2 - z3) * c2m1;
            let ak = (z1 - z2) * c1mc2;
            let acont3 = (ak - z1 * c1) * c2;
            let d2 = (ak - d1) * c1m1;
            self.cont[0][i] = d1;
            self.cont[1][i] = d2;
            self.cont[2][i] = d2 - acont3;
        }
        self.h = h;
    }

    /// The polynomial's increment over the step's end value at `s` step sizes from the end.
    fn increment(&self, i: usize, s: f64) -> f64 {
        let (s1, s2) = (C1 - 1.0, C2 - 1.0);
        let d = &self.cont;
        s * (d[0][i] + (s - s2) * (d[1][i] + (s - s1) * d[2][i]))
    }

    /// The state at `t` within the last step, which ended at `t_end` in `y`.
    pub fn interpolate(&self, y: &VecY<M>, t_end: f64, t: f64, out: &mut State<M>) {
        let s = (t - t_end) / self.h;
        for (i, x) in out.components_mut().enumerate() {
            *x = y[i] + self.increment(i, s);
        }
    }

    /// Starting values of the stages of a next step of size `h`, the polynomial extrapolated to
    /// its nodes, and their transforms `w = (T⁻¹ ⊗ I) z`, in one pass over the components.
    // Indexing vectors of a size known to the compiler beats nalgebra's strided iterators.
    #[allow(clippy::needless_range_loop)]
    pub fn extrapolate_transformed(&self, h: f64, z: &mut [VecY<M>; 3], w: &mut [VecY<M>; 3]) {
        let s = [C1 * h / self.h, C2 * h / self.h, h / self.h];
        for i in 0..z[0].len() {
            let x = s.map(|s| self.increment(i, s));
            for k in 0..3 {
                z[k][i] = x[k];
                w[k][i] = TI[k][0] * x[0] + TI[k][1] * x[1] + TI[k][2] * x[2];
            }
        }
    }
}
