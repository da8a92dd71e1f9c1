//! Parts between domains.

use crate::LagrangeDirac;

/// The electromotive force of a DC machine with constant `k`: the voltage between pins `p` and
/// `n` is `k w` at the rotational flange's speed `w` (its row `emf`), and the current `i`
/// through it, into `p`, turns the flange with the torque `k i`. Lossless: `v i = (k i) w`.
#[derive(LagrangeDirac, Clone, Debug, PartialEq)]
#[dirac(coordinates(p => vp, n => vn, phi => w), port(p, n, phi), nonzero(k))]
#[dirac(lagrangian = 0.0)]
#[dirac(constraint(emf) = vp - vn - k * w)]
#[dirac(output(i) = -emf, output(tau) = -k * emf)]
#[dirac(unit(p, n) = "Wb", unit(vp, vn) = "V", unit(phi) = "rad", unit(w) = "rad/s", unit(k) = "V s/rad")]
#[dirac(unit(i) = "A", unit(tau) = "N m")]
pub struct Emf {
    /// Torque and back-emf constant.
    pub k: f64,
}
