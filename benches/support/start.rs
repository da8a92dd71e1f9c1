//! What a peer's driver reads to start from dirac's consistent state: the state `y = (q, v, p, λ)`
//! and its derivative `(v, 0, ṗ, 0)` (the algebraic parts' derivatives zero), as text, one
//! value a line at full precision (`benches/ladder_peers.rs`, `benches/adjoint.rs`).

use std::io::Write;
use std::path::Path;

use dirac::State;
use dirac::prelude::*;

/// Writes `values` into `path`, one a line, at full precision.
pub fn write_values(path: &Path, values: impl Iterator<Item = f64>) {
    let mut f = std::io::BufWriter::new(std::fs::File::create(path).expect("a writable file"));
    for v in values {
        writeln!(f, "{v:.17e}").expect("written");
    }
}

/// Writes `y0.txt` and `yp0.txt` of `model`'s `start` at `t0` into `dir`.
pub fn write_start<M: LagrangeDirac>(model: &M, t0: f64, start: &State<M>, dir: &Path)
where
    dirac::nalgebra::DefaultAllocator: dirac::Storage<M>,
{
    let sizes = model.sizes();
    let mut y = sizes.zeros_y::<M>();
    start.write_y(&mut y);
    let mut f = sizes.zeros_y::<M>();
    model.residual(t0, &y, &mut f);
    let layout = dirac::Layout::new(sizes);
    for i in (layout.v..layout.p).chain(layout.lambda..layout.len) {
        f[i] = 0.0;
    }
    write_values(&dir.join("y0.txt"), y.iter().copied());
    write_values(&dir.join("yp0.txt"), f.iter().copied());
}
