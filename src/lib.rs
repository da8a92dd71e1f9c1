//! # dirac
//!
//! Lagrange-Dirac systems (implicit Lagrangian systems) and their interconnection through Dirac
//! structures, compiled to specialised Rust at `cargo build` time.
//!
//! Write a Lagrangian, its constraints and its forces on a struct; `#[derive(LagrangeDirac)]`
//! differentiates them symbolically and emits exact residuals and sparse Jacobians of the
//! implicit Lagrange-d'Alembert equations
//!
//! ```text
//! q̇ = v,   ṗ = ∂L/∂q + F + A(q, t)ᵀ λ,   p = ∂L/∂v,   A(q, t) v + b(q, t) = 0
//! ```
//!
//! Models declared on their own are joined through their ports by
//! `#[derive(Interconnection)]` into a model of the same kind, and simulated by
//! [`Explicit`] (explicit Runge-Kutta, order 5, adaptive, projected onto the constraints: for
//! models that are not stiff), [`Radau`] (Radau IIA, order 5, adaptive: for stiff models) or
//! [`Variational`] (a structure-preserving integrator from the discrete
//! Hamilton-Pontryagin-d'Alembert principle: for long runs).
//!
//! - [`guide`]: a tutorial from a Lagrangian to a plot;
//! - [`attributes`]: the `#[dirac(...)]` reference;
//! - [`paper`]: each concept of the paper and where it lives in the API;
//! - [`compile_time_checks`]: everything `cargo build` checks in a model.
//!
//! Models export as FMI 3.0 co-simulation FMUs for Python, Simulink, Dymola and every other
//! FMI importer: `fmi` (feature `fmi`).
//!
//! # Features
//!
//! A model of fixed size needs none: the derives, the three integrators, events, impacts,
//! sensitivities, the adjoint, linearisation, [`control`] design, [`plot`]s and animations, and
//! CSV, Parquet and Arrow output are always compiled. The rest is opt-in, so that a crate with one
//! model builds in about a third of the time and with half the crates:
//!
//! | feature | on by default | gives | brings |
//! |---|---|---|---|
//! | `components` | yes | `components`: the library of parts | no crate (its code: about 17 s of a release build) |
//! | `sparse` | no | composites made of arrays of subsystems (`cells: Vec<Cell>`), `network`: networks built while the program runs, the sparse adjoint | faer and the crates it brings |
//! | `ensemble` | no | `ensemble`: many runs on all cores | rayon |
//! | `fmi` | no | `fmi`: models exported as FMUs | zip |
//! | `spice` | no | `spice`: SPICE netlists, the `dirac-spice` program (with `sparse` and `components`) | — |
//! | `full` | no | all of the above | |
//! | `ipopt` | no | `optimal::ipopt`: optimal control problems solved by IPOPT, its library loaded when first used (Debian: `coinor-libipopt-dev`) | libloading |
//!
//! ```toml
//! [dependencies]
//! dirac = { version = "0.1", features = ["sparse", "ensemble"] }
//! ```
//!
//! A composite with an array of subsystems, built without `sparse`, is refused when it
//! compiles, with a message that names the feature. dirac's own examples, tests and benchmarks
//! are built with every feature.
//!
//! ```
//! use dirac::prelude::*;
//! use dirac::State;
//!
//! /// A planar pendulum of length `l` in Cartesian coordinates.
//! #[derive(LagrangeDirac)]
//! #[dirac(coordinates(x => vx, y => vy))]
//! #[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
//! #[dirac(holonomic(rod) = x * x + y * y - l * l)]
//! struct Pendulum {
//!     m: f64,
//!     g: f64,
//!     l: f64,
//! }
//!
//! let pendulum = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
//! let mut state = State::<Pendulum>::zeros();
//! state.set_q(Pendulum::X, 1.0).set_v(Pendulum::Y, -0.5);
//!
//! // The constraint row A = ∂φ/∂q = (2x, 2y) at (1, 0).
//! let mut a = MatCQ::<Pendulum>::zeros();
//! pendulum.constraint_matrix(0.0, &state.q, &mut a);
//! assert_eq!(a[(0, 0)], 2.0);
//! assert_eq!(a[(0, 1)], 0.0);
//!
//! // Named access and the derived equations, for people.
//! assert_eq!(Pendulum::ROD.name(), "rod");
//! assert!(Pendulum::equations().text.contains("dp_y/dt = -m*g + 2*y*lambda_rod"));
//! ```

extern crate self as dirac;

#[doc(hidden)]
pub use dirac_macros::__reduce;
pub use dirac_macros::{Interconnection, LagrangeDirac};
pub use dirac_runtime::{
    Algebra, Basis, Capability, Consistency, Constraint, Coordinate, Crossing, Dense, DenseModel,
    DenseOutput, Derivation, Dimensions, DiracStructure, Drive, EnergyBalance, Equations, ErrorNorm, Event,
    EventContext, Events, Explicit, ExplicitOptions, ExplicitStats, Fixed, Held, Hybrid, Impact, Input,
    InputsOutputs, Integrator, JacobianBlocks, LagrangeDirac, Layout, Linearization, MatCQ, MatKK, MatQQ,
    MatYY, Membership, Named, Names, OperationCounts, Output, Parameters, Progress, Radau, RadauOptions,
    RadauStats, ResidualBlocks, Run, Sampling, Sensitive, Sensitivities, SimError, Sizes, Slot, Solution,
    Solve, SparseJacobian, State, Storage, Variational, VariationalOptions, VariationalStats, VecC, VecH,
    VecK, VecQ, VecY, Wrt, consistent_state, linearize,
};

/// Gradients of one objective with respect to every parameter and initial value at once, by
/// the discrete adjoint of a Radau integration.
pub use dirac_runtime::adjoint;

/// What a [`Run`] was asked that feeds back into the model (a controller, an event action, a
/// drive) or carries beside it (sensitivities), which decides, when it compiles, what else it
/// offers.
pub use dirac_runtime::feedback;

/// Control design on the exact linearisation: zero-order hold, continuous and discrete LQR,
/// pole placement, controllability, poles and zeros, frequency and step responses, and a
/// sampled PID controller with anti-windup.
pub use dirac_runtime::analysis::control;

/// The linear-algebra crate dirac is built on, re-exported so that generic code over models
/// and code that uses its matrices need no second, possibly different, version of it.
pub use dirac_runtime::nalgebra;

/// How models store their matrices and solve their linear systems: [`algebra::Dense`] for
/// models of fixed size, [`algebra::Sparse`] for models made of arrays of subsystems.
pub use dirac_runtime::algebra;

/// Many simulations of one model on all cores (parameter sweeps, Monte Carlo), and sweeps
/// larger than one machine split into independent jobs. Feature `ensemble`.
#[cfg(feature = "ensemble")]
pub use dirac_runtime::simulate::ensemble;

/// Optimal control: a problem on a model with inputs, its DMOC transcription with exact
/// sparse derivatives generated when the model compiles, and IPOPT to solve it (feature
/// `ipopt`).
pub use dirac_runtime::optimal;

/// Input sources read by time: tables of samples, held or interpolated.
pub use dirac_runtime::integrator::sources;

/// An impact at unilateral constraints as a map of the state before it, with its derivative
/// with respect to positions, velocities, time and parameters.
pub use dirac_runtime::hybrid::impact;

/// Joint-space dynamics of mechanisms (robots read from URDF files among them): the mass
/// matrix, gravity and bias torques, forward and inverse dynamics; for a robot fixed in the
/// world, by the recursions of its tree generated when it compiles.
///
/// ```
/// use dirac::joint_space;
/// use dirac::prelude::*;
///
/// /// A point mass on a massless rod, hanging from a pivot.
/// #[derive(LagrangeDirac)]
/// #[dirac(coordinates(th => w), lagrangian = 0.5 * m * l * l * w * w + m * g * l * th.cos())]
/// struct Pendulum {
///     m: f64,
///     l: f64,
///     g: f64,
/// }
///
/// let model = Pendulum { m: 2.0, l: 0.5, g: 9.81 };
/// let q = VecQ::<Pendulum>::from_column_slice(&[0.3]);
/// let v = VecQ::<Pendulum>::from_column_slice(&[1.5]);
/// let mass = joint_space::mass_matrix(&model, 0.0, &q);
/// let gravity = joint_space::gravity_torques(&model, 0.0, &q);
/// assert!((mass[(0, 0)] - 2.0 * 0.25).abs() < 1e-15);
/// assert!((gravity[0] - 2.0 * 9.81 * 0.5 * 0.3_f64.sin()).abs() < 1e-15);
/// // The bias of a pendulum in its angle is its gravity torque alone: M does not depend on θ.
/// let bias = joint_space::bias_torques(&model, 0.0, &q, &v);
/// assert!((bias[0] - gravity[0]).abs() < 1e-15);
/// // Forward dynamics: under a torque τ it accelerates by (τ − b) / M.
/// let tau = VecQ::<Pendulum>::from_column_slice(&[2.0]);
/// let a = joint_space::forward_dynamics(&model, 0.0, &q, &v, &tau).expect("a regular M");
/// assert!((a[0] - (2.0 - bias[0]) / mass[(0, 0)]).abs() < 1e-12);
/// ```
pub use dirac_runtime::analysis::joint_space;

/// Networks assembled while the program runs: compiled parts (any model of fixed size, the
/// component library's among them) added under names, their ports connected by name.
/// Feature `sparse`.
///
/// ```
/// use dirac::components::electrical::{Capacitor, Ground, Resistor, VoltageSource};
/// use dirac::network::Network;
/// use dirac::prelude::*;
///
/// # fn main() -> Result<(), Box<dyn std::error::Error>> {
/// // A 1 Ω resistor charging a 1 F capacitor from a 1 V source.
/// let mut b = Network::builder();
/// b.add("V1", VoltageSource { u: 1.0 })?.add("R1", Resistor { r: 1.0 })?;
/// b.add("C1", Capacitor { c: 1.0 })?.add("gnd", Ground {})?;
/// b.connect("V1.p", "R1.p")?.connect("R1.n", "C1.p")?;
/// b.connect("C1.n", "gnd.p")?.connect("V1.n", "gnd.p")?;
/// let rc = b.finish()?;
///
/// let zeros = rc.sizes().zeros_q::<Network>();
/// let start = consistent_state(&rc, 0.0, &zeros, &zeros, Consistency::default())?;
/// let mut radau = Radau::new(&rc, RadauOptions::tolerances(1e-9, 1e-9))?;
/// let end = radau.solve(0.0, &start, 1.0, &Sampling::Times(vec![1.0]))?;
/// let c1 = rc.coordinate_index("C1.p").expect("a pin");
/// // The capacitor's voltage is its pin's node-flux rate: 1 − e^{−t/RC}.
/// let v = end.last().expect("a sample").v[c1];
/// assert!((v - (1.0 - (-1.0f64).exp())).abs() < 1e-7, "{v}");
/// # Ok(())
/// # }
/// ```
///
/// A port that does not exist is an error naming the part's ports:
///
/// ```
/// use dirac::components::electrical::Resistor;
/// use dirac::network::{Network, NetworkError};
///
/// let mut b = Network::builder();
/// b.add("R1", Resistor { r: 1.0 }).expect("a new name");
/// let error = b.connect("R1.p", "R1.x").err().expect("no port x");
/// assert_eq!(error.to_string(), "`R1.x`: part `R1` has no port `x`; its ports are `p`, `n`");
/// ```
#[cfg(feature = "sparse")]
pub use dirac_runtime::network;

#[cfg(feature = "components")]
pub mod components;
#[cfg(feature = "fmi")]
pub mod fmi;
pub mod plot;
#[cfg(feature = "spice")]
pub mod spice;

/// Everything a model file needs: `use dirac::prelude::*;`.
///
/// It includes the bound generic code over any model needs, so a helper over every model
/// compiles with `dirac` as the only dependency:
///
/// ```
/// use dirac::prelude::*;
/// use dirac::State;
///
/// /// The kinetic energy `½ vᵀ L_vv v` of any model (dense or sparse), at its state.
/// fn kinetic_energy<M: LagrangeDirac>(model: &M, state: &State<M>) -> f64
/// where
///     DefaultAllocator: Storage<M>,
/// {
///     let mut mass = M::Algebra::zeros_qq(&model.shape());
///     model.l_vv(0.0, &state.q, &state.v, &mut mass);
///     let mut momentum = model.sizes().zeros_q::<M>();
///     M::Algebra::qq_mul(&mass, 1.0, state.v.as_slice(), momentum.as_mut_slice());
///     0.5 * state.v.dot(&momentum)
/// }
///
/// #[derive(LagrangeDirac)]
/// #[dirac(coordinates(x => v))]
/// #[dirac(lagrangian = 0.5 * m * v * v)]
/// struct Mass { m: f64 }
///
/// let mut state = State::<Mass>::zeros();
/// state.set_v(Mass::X, 2.0);
/// assert_eq!(kinetic_energy(&Mass { m: 3.0 }, &state), 6.0);
/// ```
pub mod prelude {
    pub use crate::nalgebra::DefaultAllocator;
    pub use crate::{
        Algebra, Consistency, Constraint, Coordinate, Crossing, DenseModel, DenseOutput, Derivation,
        Dimensions, DiracStructure, EnergyBalance, Equations, ErrorNorm, Event, Events, Explicit,
        ExplicitOptions, Hybrid, InputsOutputs, Integrator, Interconnection, JacobianBlocks, LagrangeDirac,
        Linearization, MatCQ, MatQQ, MatYY, Named, Parameters, Radau, RadauOptions, ResidualBlocks, Sampling,
        Sensitive, Sensitivities, SimError, Sizes, Solution, Solve, SparseJacobian, Storage, Variational,
        VariationalOptions, VecC, VecH, VecQ, VecY, consistent_state, linearize,
    };
}

/// Documentation: a tutorial from a Lagrangian to a plot.
#[doc = include_str!("docs/guide.md")]
pub mod guide {}

/// Documentation: the `#[dirac(...)]` attributes.
#[doc = include_str!("docs/attributes.md")]
pub mod attributes {}

/// Documentation: each concept of the paper and where it lives in the API.
#[doc = include_str!("docs/paper.md")]
pub mod paper {}

/// Documentation: the paper's terms beside an engineer's.
#[doc = include_str!("docs/words.md")]
pub mod words {}

/// Documentation: everything `cargo build` checks in a model.
#[doc = include_str!("docs/compile_time_checks.md")]
pub mod compile_time_checks {}

/// The runtime crate, for items the prelude does not re-export.
pub use dirac_runtime as runtime;

#[doc(hidden)]
pub use dirac_runtime::__private;

/// The README's examples, compiled and run as doc tests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
