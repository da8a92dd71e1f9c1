//! What the solvers' unit tests share: the sizes of a small model and seeded blocks.

use nalgebra::Const;

use crate::algebra::{Dense, JacobianBlocks};
use crate::shape::dims::{Dimensions, Sizes};

/// Sizes of a model with 3 coordinates and 1 constraint, for testing solvers alone.
pub struct Three;

impl Dimensions for Three {
    type Nq = Const<3>;
    type Nc = Const<1>;
    type Nh = Const<0>;
    type Nk = Const<4>;
    type Ny = Const<10>;
}

/// [`Three`]'s sizes as numbers.
pub const THREE: Sizes = Sizes { nq: 3, nc: 1, nh: 0 };

/// A seeded generator of numbers in [-0.5, 0.5).
pub fn numbers(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    }
}

/// Seeded blocks of [`Three`], with a degenerate `L_vv`: the third velocity has no inertia, as
/// in the paper's system 2.
pub fn blocks(seed: u64) -> JacobianBlocks<Three, Dense> {
    let mut next = numbers(seed);
    let mut b = JacobianBlocks::<Three, Dense>::with_shape(&THREE);
    for x in b.dpdot_dq.iter_mut().chain(b.dpdot_dv.iter_mut()).chain(b.l_vq.iter_mut()) {
        *x = next();
    }
    for x in b.a.iter_mut().chain(b.dav_dq.iter_mut()) {
        *x = next();
    }
    b.l_vv[(0, 0)] = 2.0;
    b.l_vv[(1, 1)] = 1.5;
    b.l_vv[(0, 1)] = 0.3;
    b.l_vv[(1, 0)] = 0.3;
    b
}
