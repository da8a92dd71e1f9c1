//! The paper's example (Yoshimura, Jacobs & Marsden, §VI): the mass-spring chain
//!
//! ```text
//! wall —k1— m1 —k2— m2 —k3— m3
//! ```
//!
//! torn into two primitive Lagrange-Dirac systems with boundary ports (Fig. 2):
//!
//! - primitive system 1 on Q1 = (x1, x2): L1 = ½(m1 v1² + m2 v2²) − ½(k1 x1² + k2 (x2 − x1)²);
//! - primitive system 2 on Q2 = (x̄2, x3): L2 = ½ m3 v3² − ½ k3 (x3 − x̄2)², degenerate: it has
//!   no kinetic energy in v̄2, so p̄2 = 0.
//!
//! The derive turns each Lagrangian into its implicit Lagrange-d'Alembert equations. This
//! program prints them: they are the paper's eqs. (9) and (10), with the efforts f2 and f̄2 at
//! the ports, which the interconnection v2 = v̄2, f2 + f̄2 = 0 (eq. 8) later ties together.

use dirac::prelude::*;

/// Primitive system 1: wall —k1— m1 —k2— m2, port at x2.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x1 => v1, x2 => v2), port(x2))]
#[dirac(lagrangian = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2
                   - 0.5 * k1 * x1 * x1 - 0.5 * k2 * (x2 - x1).powi(2))]
pub struct Primitive1 {
    /// Mass m1.
    pub m1: f64,
    /// Mass m2.
    pub m2: f64,
    /// Spring constant k1 (wall to m1).
    pub k1: f64,
    /// Spring constant k2 (m1 to m2).
    pub k2: f64,
}

/// Primitive system 2: x̄2 —k3— m3, port at x̄2.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x2bar => v2bar, x3 => v3), port(x2bar))]
#[dirac(lagrangian = 0.5 * m3 * v3 * v3 - 0.5 * k3 * (x3 - x2bar).powi(2))]
pub struct Primitive2 {
    /// Mass m3.
    pub m3: f64,
    /// Spring constant k3 (m2 to m3).
    pub k3: f64,
}

fn main() {
    println!("Primitive system 1, the paper's eq. (9):\n{}\n", Primitive1::equations().text);
    println!("Primitive system 2, the paper's eq. (10):\n{}\n", Primitive2::equations().text);
    println!("As LaTeX:\n{}\n{}", Primitive1::equations().latex, Primitive2::equations().latex);
}
