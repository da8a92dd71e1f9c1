//! Export of a model as an FMI 3.0 (or 2.0) co-simulation FMU, for Python (FMPy), Simulink,
//! Dymola, OpenModelica and every other importer of the Functional Mock-up Interface.
//!
//! An FMU is a zip of a shared library that implements FMI's C functions and a
//! `modelDescription.xml` that lists the model's variables. Three pieces make one from a
//! model:
//!
//! 1. [`Export`], on the model: its identifier, the instance an importer starts from, and
//!    optionally start positions and velocities and a default experiment. A model made while
//!    the program runs (a [`Network`](crate::network::Network), a netlist's circuit) is
//!    exported through [`Fmu`] instead, on a type of one's own that makes the model for each
//!    instance, from the FMU's `resources/` if it likes (the example `fmu_netlist` is one
//!    library for every SPICE netlist);
//! 2. [`export_fmu!`](crate::export_fmu), in a crate built as a `cdylib`: the C functions;
//! 3. [`write_fmu`] (or [`build`], which also runs `cargo build`): the `.fmu` file, for
//!    [`Version::Fmi3`] or [`Version::Fmi2`] (one library implements both; the description
//!    says which the importer reads); [`write_fmu_with_resources`] packs files beside it.
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
//! communication point, where inputs may jump. An input in a constraint (a voltage source's
//! voltage, a prescribed position) moves the state when it jumps, as an impulse through the
//! constraint would: to the consistent state nearest in the kinetic-energy norm
//! ([`consistent_state`](crate::consistent_state)), which keeps the momenta (a capacitor's
//! charge) that the constraint does not act on. That projection is set-up work and allocates;
//! an input in a force or a potential restarts without allocating. A step that fails returns `fmi3Discard` and
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
pub use package::{FmuError, build, build_with_resources, write_fmu, write_fmu_with_resources};
pub use variables::DescriptionError;

use std::path::Path;

use crate::nalgebra::DefaultAllocator;
use crate::{Hybrid, InputsOutputs, LagrangeDirac, Parameters, Storage, VecQ};

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
pub trait Export: LagrangeDirac + Hybrid + InputsOutputs + Parameters
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

/// What an FMU's library simulates, and how each instance makes it: the most general way to
/// export, which [`export_fmu!`](crate::export_fmu), [`write_fmu`] and [`Instance`] take.
///
/// Every [`Export`] model is one. A model made while the program runs, a
/// [`Network`](crate::network::Network) built by code or read from a netlist, is exported
/// through a type of one's own that implements this: its [`model`](Fmu::model) builds the
/// network, from files in the FMU's `resources/` folder if it likes
/// ([`write_fmu_with_resources`] packs them; the importer says where it unpacked them).
///
/// ```
/// use std::path::Path;
///
/// use dirac::fmi::{Fmu, Start};
/// use dirac::network::Network;
/// use dirac::prelude::*;
///
/// /// The FMU of the netlist in its `resources/circuit.cir`.
/// struct Netlist;
///
/// impl Fmu for Netlist {
///     type Model = Network;
///     const IDENTIFIER: &'static str = "netlist";
///
///     fn model(resources: Option<&Path>) -> Result<Start<Network>, dirac::fmi::BoxError> {
///         let path = resources.ok_or("the FMU has no resources")?.join("circuit.cir");
///         let circuit = dirac::spice::parse(&std::fs::read_to_string(path)?)?.circuit()?;
///         let (q, v) = circuit.start_values();
///         Ok(Start { model: circuit.network, q, v })
///     }
/// }
///
/// // In a `cdylib` crate: `dirac::export_fmu!(Netlist);`
/// let resources = std::env::temp_dir().join("dirac-doc-netlist");
/// std::fs::create_dir_all(&resources)?;
/// std::fs::write(resources.join("circuit.cir"), "RC\nV1 in 0 DC 1\nR1 in out 1k\nC1 out 0 1u\n")?;
/// let xml = dirac::fmi::describe::<Netlist>(Some(&resources), dirac::fmi::Version::Fmi3)?;
/// let input = xml.lines().find(|l| l.contains(r#"name="v1.u""#)).expect("V1's voltage is a variable");
/// assert!(input.contains(r#"causality="input""#) && input.contains(r#"unit="V""#));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub trait Fmu
where
    DefaultAllocator: Storage<Self::Model>,
{
    /// The model each instance simulates.
    type Model: LagrangeDirac + Hybrid + InputsOutputs + Parameters;

    /// The FMU's model identifier: its name, and its library's name inside the FMU. A C
    /// identifier by FMI's rules.
    const IDENTIFIER: &'static str;

    /// What the model is, for the description's `description` attribute.
    const ABOUT: &'static str = "";

    /// The model an instance starts from, with its start positions and velocities: made for
    /// each instance, and again when an instance is reset or goes back to a saved state.
    /// `resources` is the folder where the importer unpacked the FMU's `resources/` (`None`
    /// if it gives none); when an FMU is written, the folder its resources are packed from.
    fn model(resources: Option<&Path>) -> Result<Start<Self::Model>, BoxError>;

    /// The default experiment.
    fn experiment() -> Experiment {
        Experiment::default()
    }
}

/// Why a model could not be made ([`Fmu::model`]): any error.
pub type BoxError = Box<dyn std::error::Error + Send + Sync>;

/// A model and its start positions and velocities, which initialisation makes consistent with
/// the constraints ([`consistent_state`](crate::consistent_state)).
pub struct Start<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// The model: its parameters and inputs are the variables' start values.
    pub model: M,
    /// Start positions.
    pub q: VecQ<M>,
    /// Start velocities.
    pub v: VecQ<M>,
}

impl<M: Export> Fmu for M
where
    DefaultAllocator: Storage<M>,
{
    type Model = M;
    const IDENTIFIER: &'static str = M::MODEL_IDENTIFIER;
    const ABOUT: &'static str = M::DESCRIPTION;

    fn model(_resources: Option<&Path>) -> Result<Start<M>, BoxError> {
        Ok(start_of(M::instantiate()))
    }

    fn experiment() -> Experiment {
        M::default_experiment()
    }
}

/// An [`Export`] model with its [`start`](Export::start) values.
fn start_of<M: Export>(model: M) -> Start<M>
where
    DefaultAllocator: Storage<M>,
{
    let sizes = model.sizes();
    let (mut q, mut v) = (sizes.zeros_q::<M>(), sizes.zeros_q::<M>());
    model.start(&mut q, &mut v);
    Start { model, q, v }
}

/// The text of the `modelDescription.xml` of FMU `F` for an FMI version, its model made from
/// `resources` ([`Fmu::model`]).
pub fn describe<F: Fmu>(resources: Option<&Path>, version: Version) -> Result<String, FmuError>
where
    DefaultAllocator: Storage<F::Model>,
{
    let start = F::model(resources).map_err(|e| FmuError::Model(e.to_string()))?;
    Ok(variables::description::<F>(&start, version).map(|(text, _)| text)?)
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
    variables::description_of_model(model, version).map(|(text, _)| text)
}

/// The instantiation token (in FMI 2.0, the GUID) of model `M`'s FMU: what an importer passes
/// when it instantiates the FMU, read from the description by FMI tools.
pub fn instantiation_token<M: Export>(version: Version) -> Result<String, DescriptionError>
where
    DefaultAllocator: Storage<M>,
{
    variables::description::<M>(&start_of(M::instantiate()), version).map(|(_, token)| token)
}

/// The value reference of the variable named `name` in `model`'s FMU (`"time"`, `"left.k1"`,
/// `"lambda(rod)"`), if it has one: for code that drives the FMU's C functions itself.
pub fn value_reference<M: LagrangeDirac>(model: &M, name: &str) -> Option<u32>
where
    DefaultAllocator: Storage<M>,
{
    let table = variables::Table::of(model);
    table.named(model, name).map(|variable| table.reference(variable))
}
