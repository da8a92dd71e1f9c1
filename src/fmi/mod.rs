//! Export of a model as an FMI 3.0 (or 2.0) co-simulation FMU, for Python (FMPy), Simulink,
//! Dymola, OpenModelica and every other importer of the Functional Mock-up Interface.
//!
//! An FMU is a zip of a shared library that implements FMI's C functions and a
//! `modelDescription.xml` that lists the model's variables. Three pieces make one from a
//! model:
//!
//! 1. [`Export`], on the model: its identifier, the instance an importer starts from, and
//!    optionally start positions and velocities and a default experiment;
//! 2. [`export_fmu!`](crate::export_fmu), in a crate built as a `cdylib`: the C functions;
//! 3. [`write_fmu`] (or [`build`], which also runs `cargo build`): the `.fmu` file, for
//!    [`Version::Fmi3`] or [`Version::Fmi2`] (one library implements both; the description
//!    says which the importer reads).
//!
//! The variables, in the order of their value references:
//!
//! | variables | causality, variability | |
//! |---|---|---|
//! | `time` | independent | |
//! | the parameters (`left.k1`) | parameter, fixed | settable before `fmi3ExitInitializationMode` |
//! | the inputs | input, continuous | held over each communication step |
//! | the outputs | output, continuous | |
//! | positions and velocities | local, continuous, `initial="exact"` | start values, made consistent with the constraints at initialisation |
//! | multipliers `lambda(name)` | local, continuous | |
//!
//! `fmi3DoStep` integrates with [`Radau`](crate::Radau) at the tolerance the importer gives
//! (relative and absolute alike; the default experiment's otherwise), restarting at each
//! communication point, where inputs may jump. A step that fails returns `fmi3Discard` and
//! leaves the instance at the step's start; wrong calls return `fmi3Error`; both log why
//! through the importer's callback. `fmi3GetFMUState`, `fmi3SetFMUState` and their
//! serialisation are provided.
//!
//! The guide's "Export as an FMU" section builds one and simulates it from Python.

pub mod abi;
mod export;
mod instance;
mod package;
mod variables;

pub use instance::{Failure, Instance, STEPS_PER_COMMUNICATION_STEP, Snapshot, Status};
pub use package::{FmuError, build, write_fmu};
pub use variables::DescriptionError;

use crate::nalgebra::DefaultAllocator;
use crate::{InputsOutputs, LagrangeDirac, Parameters, Storage, VecQ};

/// The version of the FMI standard an FMU follows. One library serves both: `export_fmu!`
/// exports the functions of each.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Version {
    /// FMI 3.0.
    #[default]
    Fmi3,
    /// FMI 2.0, for importers that do not read 3.0 yet.
    Fmi2,
}

/// The simulation an importer runs by default (`<DefaultExperiment>`).
#[derive(Clone, Copy, Debug)]
pub struct Experiment {
    /// Start time.
    pub start: f64,
    /// Stop time.
    pub stop: f64,
    /// Relative (and absolute) tolerance of the integration inside each step.
    pub tolerance: f64,
    /// Communication step size.
    pub step: f64,
}

impl Default for Experiment {
    fn default() -> Self {
        Experiment { start: 0.0, stop: 10.0, tolerance: 1e-8, step: 0.01 }
    }
}

/// A model that can be exported as an FMU.
///
/// ```
/// use dirac::fmi::Export;
/// use dirac::prelude::*;
///
/// /// A mass on a spring, pushed by an input force `f`.
/// #[derive(LagrangeDirac)]
/// #[dirac(coordinates(x => v), input(f), output(energy) = 0.5 * m * v * v + 0.5 * k * x * x)]
/// #[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x + f * x)]
/// struct Oscillator { m: f64, k: f64, f: f64 }
///
/// impl Export for Oscillator {
///     const MODEL_IDENTIFIER: &'static str = "oscillator";
///
///     fn instantiate() -> Self {
///         Oscillator { m: 1.0, k: 4.0, f: 0.0 }
///     }
///
///     fn start(&self, q: &mut VecQ<Self>, _v: &mut VecQ<Self>) {
///         q[Self::X.index()] = 0.1;
///     }
/// }
///
/// // In a `cdylib` crate: `dirac::export_fmu!(Oscillator);`
/// let xml = dirac::fmi::model_description(&Oscillator::instantiate())?;
/// assert!(xml.contains(r#"<Float64 name="x" valueReference="5""#));
/// # Ok::<(), dirac::fmi::DescriptionError>(())
/// ```
pub trait Export: LagrangeDirac + InputsOutputs + Parameters
where
    DefaultAllocator: Storage<Self>,
{
    /// The FMU's model identifier: its name, and its library's name inside the FMU. A C
    /// identifier by FMI's rules.
    const MODEL_IDENTIFIER: &'static str;

    /// What the model is, for the description's `description` attribute.
    const DESCRIPTION: &'static str = "";

    /// The model an instance starts from: its parameters and inputs are the variables' start
    /// values.
    fn instantiate() -> Self;

    /// Start positions and velocities (zero unless written here). At initialisation they are
    /// made consistent with the constraints ([`consistent_state`](crate::consistent_state)).
    fn start(&self, q: &mut VecQ<Self>, v: &mut VecQ<Self>) {
        let _ = (q, v);
    }

    /// The default experiment.
    fn default_experiment() -> Experiment {
        Experiment::default()
    }
}

/// The text of the model's FMI 3.0 `modelDescription.xml`.
pub fn model_description<M: Export>(model: &M) -> Result<String, DescriptionError>
where
    DefaultAllocator: Storage<M>,
{
    model_description_for(model, Version::Fmi3)
}

/// The text of the model's `modelDescription.xml` for an FMI version.
pub fn model_description_for<M: Export>(model: &M, version: Version) -> Result<String, DescriptionError>
where
    DefaultAllocator: Storage<M>,
{
    variables::description(model, version).map(|(text, _)| text)
}

/// The instantiation token (in FMI 2.0, the GUID) of model `M`'s FMU: what an importer passes
/// when it instantiates the FMU, read from the description by FMI tools.
pub fn instantiation_token<M: Export>(version: Version) -> Result<String, DescriptionError>
where
    DefaultAllocator: Storage<M>,
{
    variables::description(&M::instantiate(), version).map(|(_, token)| token)
}

/// The value reference of the variable named `name` in `model`'s FMU (`"time"`, `"left.k1"`,
/// `"lambda(rod)"`), if it has one: for code that drives the FMU's C functions itself.
pub fn value_reference<M: Export>(model: &M, name: &str) -> Option<u32>
where
    DefaultAllocator: Storage<M>,
{
    let table = variables::Table::of(model);
    table.named(model, name).map(|variable| table.reference(variable))
}
