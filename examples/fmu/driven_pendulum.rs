//! A pendulum in Cartesian coordinates, held on its circle by a constraint and pushed sideways
//! by an input force: an FMU with an input, two outputs and a multiplier.

use dirac::fmi::{Experiment, Export};
use dirac::prelude::*;

/// A bob of mass `m` on a rod of length `l` under gravity `g`, pushed along `x` by the input
/// force `f`. Outputs: its energy and its height.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy), input(f))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y, force(x) = f)]
#[dirac(holonomic(rod) = x * x + y * y - l * l)]
#[dirac(output(energy) = 0.5 * m * (vx * vx + vy * vy) + m * g * y, output(height) = y)]
#[dirac(unit(x, y, l, height) = "m", unit(vx, vy) = "m/s", unit(m) = "kg", unit(g) = "m/s2")]
#[dirac(unit(f) = "N", unit(energy) = "J")]
pub struct DrivenPendulum {
    /// Mass of the bob.
    pub m: f64,
    /// Gravity.
    pub g: f64,
    /// Length of the rod.
    pub l: f64,
    /// Horizontal force on the bob (the input).
    pub f: f64,
}

/// The angle the pendulum starts at, from hanging straight down.
pub const START_ANGLE: f64 = 0.5;

impl Export for DrivenPendulum {
    // The description is the struct's doc comment.
    const MODEL_IDENTIFIER: &'static str = "driven_pendulum";

    fn instantiate() -> Self {
        DrivenPendulum { m: 1.0, g: 9.81, l: 1.0, f: 0.0 }
    }

    /// At rest, `START_ANGLE` from hanging straight down.
    fn start(&self, q: &mut VecQ<Self>, _v: &mut VecQ<Self>) {
        let (s, c) = START_ANGLE.sin_cos();
        q[Self::X.index()] = self.l * s;
        q[Self::Y.index()] = -self.l * c;
    }

    fn default_experiment() -> Experiment {
        Experiment { start: 0.0, stop: 10.0, tolerance: 1e-8, step: 0.01 }
    }
}
