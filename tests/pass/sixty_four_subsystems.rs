//! 64 interconnected subsystems: the composite's offsets are prefix sums over arrays of the
//! subsystems' sizes, not a chain of constants that once exceeded the compiler's query depth.

use dirac::prelude::*;
use dirac::Fixed;

/// A mass on a spring between two ports.
#[derive(LagrangeDirac)]
#[dirac(coordinates(xl => vl, x => v), port(xl, x))]
#[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * (x - xl).powi(2))]
pub struct Cell {
    pub m: f64,
    pub k: f64,
}

/// 64 cells in a line, each one's right end joined to the next one's left.
#[derive(Interconnection)]
#[dirac(large)]
#[dirac(connect(c0.x, c1.xl))]
#[dirac(connect(c1.x, c2.xl))]
#[dirac(connect(c2.x, c3.xl))]
#[dirac(connect(c3.x, c4.xl))]
#[dirac(connect(c4.x, c5.xl))]
#[dirac(connect(c5.x, c6.xl))]
#[dirac(connect(c6.x, c7.xl))]
#[dirac(connect(c7.x, c8.xl))]
#[dirac(connect(c8.x, c9.xl))]
#[dirac(connect(c9.x, c10.xl))]
#[dirac(connect(c10.x, c11.xl))]
#[dirac(connect(c11.x, c12.xl))]
#[dirac(connect(c12.x, c13.xl))]
#[dirac(connect(c13.x, c14.xl))]
#[dirac(connect(c14.x, c15.xl))]
#[dirac(connect(c15.x, c16.xl))]
#[dirac(connect(c16.x, c17.xl))]
#[dirac(connect(c17.x, c18.xl))]
#[dirac(connect(c18.x, c19.xl))]
#[dirac(connect(c19.x, c20.xl))]
#[dirac(connect(c20.x, c21.xl))]
#[dirac(connect(c21.x, c22.xl))]
#[dirac(connect(c22.x, c23.xl))]
#[dirac(connect(c23.x, c24.xl))]
#[dirac(connect(c24.x, c25.xl))]
#[dirac(connect(c25.x, c26.xl))]
#[dirac(connect(c26.x, c27.xl))]
#[dirac(connect(c27.x, c28.xl))]
#[dirac(connect(c28.x, c29.xl))]
#[dirac(connect(c29.x, c30.xl))]
#[dirac(connect(c30.x, c31.xl))]
#[dirac(connect(c31.x, c32.xl))]
#[dirac(connect(c32.x, c33.xl))]
#[dirac(connect(c33.x, c34.xl))]
#[dirac(connect(c34.x, c35.xl))]
#[dirac(connect(c35.x, c36.xl))]
#[dirac(connect(c36.x, c37.xl))]
#[dirac(connect(c37.x, c38.xl))]
#[dirac(connect(c38.x, c39.xl))]
#[dirac(connect(c39.x, c40.xl))]
#[dirac(connect(c40.x, c41.xl))]
#[dirac(connect(c41.x, c42.xl))]
#[dirac(connect(c42.x, c43.xl))]
#[dirac(connect(c43.x, c44.xl))]
#[dirac(connect(c44.x, c45.xl))]
#[dirac(connect(c45.x, c46.xl))]
#[dirac(connect(c46.x, c47.xl))]
#[dirac(connect(c47.x, c48.xl))]
#[dirac(connect(c48.x, c49.xl))]
#[dirac(connect(c49.x, c50.xl))]
#[dirac(connect(c50.x, c51.xl))]
#[dirac(connect(c51.x, c52.xl))]
#[dirac(connect(c52.x, c53.xl))]
#[dirac(connect(c53.x, c54.xl))]
#[dirac(connect(c54.x, c55.xl))]
#[dirac(connect(c55.x, c56.xl))]
#[dirac(connect(c56.x, c57.xl))]
#[dirac(connect(c57.x, c58.xl))]
#[dirac(connect(c58.x, c59.xl))]
#[dirac(connect(c59.x, c60.xl))]
#[dirac(connect(c60.x, c61.xl))]
#[dirac(connect(c61.x, c62.xl))]
#[dirac(connect(c62.x, c63.xl))]
pub struct Line {
    pub c0: Cell,
    pub c1: Cell,
    pub c2: Cell,
    pub c3: Cell,
    pub c4: Cell,
    pub c5: Cell,
    pub c6: Cell,
    pub c7: Cell,
    pub c8: Cell,
    pub c9: Cell,
    pub c10: Cell,
    pub c11: Cell,
    pub c12: Cell,
    pub c13: Cell,
    pub c14: Cell,
    pub c15: Cell,
    pub c16: Cell,
    pub c17: Cell,
    pub c18: Cell,
    pub c19: Cell,
    pub c20: Cell,
    pub c21: Cell,
    pub c22: Cell,
    pub c23: Cell,
    pub c24: Cell,
    pub c25: Cell,
    pub c26: Cell,
    pub c27: Cell,
    pub c28: Cell,
    pub c29: Cell,
    pub c30: Cell,
    pub c31: Cell,
    pub c32: Cell,
    pub c33: Cell,
    pub c34: Cell,
    pub c35: Cell,
    pub c36: Cell,
    pub c37: Cell,
    pub c38: Cell,
    pub c39: Cell,
    pub c40: Cell,
    pub c41: Cell,
    pub c42: Cell,
    pub c43: Cell,
    pub c44: Cell,
    pub c45: Cell,
    pub c46: Cell,
    pub c47: Cell,
    pub c48: Cell,
    pub c49: Cell,
    pub c50: Cell,
    pub c51: Cell,
    pub c52: Cell,
    pub c53: Cell,
    pub c54: Cell,
    pub c55: Cell,
    pub c56: Cell,
    pub c57: Cell,
    pub c58: Cell,
    pub c59: Cell,
    pub c60: Cell,
    pub c61: Cell,
    pub c62: Cell,
    pub c63: Cell,
}

fn main() {
    assert_eq!(<Line as Fixed>::NQ, 128);
    assert_eq!(<Line as Fixed>::NC, 63);
    assert_eq!(Line::NAMES.constraint_names().len(), 63);
}
