//! The paper's mass-spring chain (Yoshimura, Jacobs & Marsden, §VI), torn into two primitive
//! Lagrange-Dirac systems and interconnected through their ports, as an FMU: its parameters
//! are the masses and spring constants, its start state the chain at rest with `x1 = 0.1`.

use dirac::fmi::{Experiment, Export};
use dirac::prelude::*;

/// Primitive system 1: wall —k1— m1 —k2— m2, port at x2.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x1 => v1, x2 => v2), port(x2))]
#[dirac(unit(x1, x2) = "m", unit(v1, v2) = "m/s", unit(m1, m2) = "kg", unit(k1, k2) = "N/m")]
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

/// Primitive system 2: x̄2 —k3— m3, port at x̄2; degenerate (no kinetic energy in v̄2).
#[derive(LagrangeDirac)]
#[dirac(coordinates(x2bar => v2bar, x3 => v3), port(x2bar))]
#[dirac(unit(x2bar, x3) = "m", unit(v2bar, v3) = "m/s", unit(m3) = "kg", unit(k3) = "N/m")]
#[dirac(lagrangian = 0.5 * m3 * v3 * v3 - 0.5 * k3 * (x3 - x2bar).powi(2))]
pub struct Primitive2 {
    /// Mass m3.
    pub m3: f64,
    /// Spring constant k3 (m2 to m3).
    pub k3: f64,
}

/// The interconnection: ports x2 and x̄2 move together and their efforts balance.
#[derive(Interconnection)]
#[dirac(connect(left.x2, right.x2bar))]
pub struct PaperChain {
    /// Primitive system 1.
    pub left: Primitive1,
    /// Primitive system 2.
    pub right: Primitive2,
}

impl Export for PaperChain {
    const MODEL_IDENTIFIER: &'static str = "paper_chain";
    const DESCRIPTION: &'static str =
        "The mass-spring chain wall-k1-m1-k2-m2-k3-m3, as two Lagrange-Dirac systems joined at m2";

    /// m = (1, 2, 3), k = (4, 5, 6), as in the paper's example.
    fn instantiate() -> Self {
        PaperChain {
            left: Primitive1 { m1: 1.0, m2: 2.0, k1: 4.0, k2: 5.0 },
            right: Primitive2 { m3: 3.0, k3: 6.0 },
        }
    }

    /// At rest with x1 = 0.1; x̄2 = x2 follows from consistency.
    fn start(&self, q: &mut VecQ<Self>, _v: &mut VecQ<Self>) {
        q[Self::left(Primitive1::X1).index()] = 0.1;
    }

    fn default_experiment() -> Experiment {
        Experiment { start: 0.0, stop: 20.0, tolerance: 1e-8, step: 0.01 }
    }
}
