//! One instance of an exported model: FMI's states, the model's values and its simulation,
//! with no raw pointers (those stay in [`abi`](super::abi)).

use crate::nalgebra::DefaultAllocator;
use crate::{
    Consistency, Held, InputsOutputs, Integrator, LagrangeDirac, Parameters, Radau, RadauOptions, State,
    Storage, VecQ,
};

use std::path::{Path, PathBuf};

use super::variables::{Table, Variable};
use super::{Export, Fmu, Start};

/// FMI's status codes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
#[repr(i32)]
pub enum Status {
    /// All well.
    Ok = 0,
    /// Done, with something to report.
    Warning = 1,
    /// A step could not be taken; the instance is where it was before the call.
    Discard = 2,
    /// The call was wrong and changed nothing, or failed inside (a panic, caught): after
    /// that, only reading values, `Reset` and `FreeInstance` are allowed.
    Error = 3,
    /// Not returned: nothing dirac does corrupts the process.
    Fatal = 4,
}

/// A failed call: the status to return and the message to log.
#[derive(Debug)]
pub struct Failure {
    /// `Error` or `Discard`.
    pub status: Status,
    /// What went wrong, for the importer's log.
    pub message: String,
}

impl Failure {
    pub(crate) fn error(message: impl Into<String>) -> Failure {
        Failure { status: Status::Error, message: message.into() }
    }

    fn discard(message: impl Into<String>) -> Failure {
        Failure { status: Status::Discard, message: message.into() }
    }
}

/// Where an instance is in FMI's state machine (co-simulation without event mode).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Phase {
    Instantiated,
    Initialization,
    Step,
    Terminated,
    /// A call panicked (the panic was caught): only reading values, `Reset` and
    /// `FreeInstance` are allowed.
    Failed,
}

impl Phase {
    fn name(self) -> &'static str {
        match self {
            Phase::Instantiated => "instantiated",
            Phase::Initialization => "initialization mode",
            Phase::Step => "step mode",
            Phase::Terminated => "terminated",
            Phase::Failed => "failed (after an internal error)",
        }
    }

    fn code(self) -> f64 {
        match self {
            Phase::Instantiated => 0.0,
            Phase::Initialization => 1.0,
            Phase::Step => 2.0,
            Phase::Terminated => 3.0,
            Phase::Failed => 4.0,
        }
    }

    fn from_code(code: f64) -> Option<Phase> {
        [Phase::Instantiated, Phase::Initialization, Phase::Step, Phase::Terminated, Phase::Failed]
            .into_iter()
            .find(|p| p.code() == code)
    }
}

/// A model being simulated for an importer.
pub struct Instance<F: Fmu>
where
    DefaultAllocator: Storage<F::Model>,
{
    pub(crate) phase: Phase,
    /// The model until the first step moves it into the integrator.
    model: Option<F::Model>,
    /// The integrator, from the first step on: kept across steps, so that each communication
    /// point restarts it with its step size (as [`Solve::solve_sampled`](crate::Solve::solve_sampled) does) and a step
    /// allocates nothing.
    radau: Option<Radau<'static, F::Model>>,
    table: Table,
    start_q: VecQ<F::Model>,
    start_v: VecQ<F::Model>,
    t: f64,
    tolerance: f64,
    /// The consistent state at `t`; `None` until initialisation asks for it, and again after
    /// a start value or parameter changes during initialisation.
    state: Option<State<F::Model>>,
    outputs: Vec<f64>,
    /// Where the importer unpacked the FMU's resources: the model is made again from them on
    /// reset and when the instance goes back to a saved state.
    resources: Option<PathBuf>,
}

/// The values an importer saved with `fmi3GetFMUState`, to go back to.
pub struct Snapshot {
    values: Vec<f64>,
}

fn not_computed() -> Failure {
    Failure::error("the state is not computed: the initialisation failed")
}

const SNAPSHOT_MAGIC: f64 = 17.03;

/// The most steps (accepted and rejected) one communication step may take: Radau's default
/// limit, for each communication step rather than for the integrator's whole life.
pub const STEPS_PER_COMMUNICATION_STEP: usize = 1_000_000;

impl<F: Fmu> Instance<F>
where
    DefaultAllocator: Storage<F::Model>,
{
    /// A new instance of FMU `F`: its model made from the FMU's resources folder
    /// ([`Fmu::model`]), its start values, time zero.
    pub fn instantiate(resources: Option<&Path>) -> Result<Instance<F>, Failure> {
        let start =
            F::model(resources).map_err(|e| Failure::error(format!("the model could not be made: {e}")))?;
        Ok(Instance::from_start(start, resources.map(Path::to_path_buf)))
    }

    pub(crate) fn from_start(start: Start<F::Model>, resources: Option<PathBuf>) -> Instance<F> {
        let Start { model, q, v } = start;
        let table = Table::of(&model);
        Instance {
            phase: Phase::Instantiated,
            outputs: vec![0.0; table.outputs],
            model: Some(model),
            radau: None,
            table,
            start_q: q,
            start_v: v,
            t: 0.0,
            tolerance: F::experiment().tolerance,
            state: None,
            resources,
        }
    }

    /// The model, wherever it is.
    fn model(&self) -> &F::Model {
        match (&self.radau, &self.model) {
            (Some(radau), _) => radau.model(),
            (None, Some(model)) => model,
            (None, None) => unreachable!("an instance always holds its model"),
        }
    }

    /// The model to change; the integrator restarts at the next step.
    fn model_mut(&mut self) -> &mut F::Model {
        match (&mut self.radau, &mut self.model) {
            (Some(radau), _) => radau.model_mut().expect("the integrator owns the model"),
            (None, Some(model)) => model,
            (None, None) => unreachable!("an instance always holds its model"),
        }
    }

    /// A new model with these parameter and input values (in the order of the FMU's
    /// variables), to build a new integrator on: after a failed step (the current values), or
    /// to go back to a snapshot (its values).
    fn model_with(&self, parameters: &[f64], inputs: &[f64]) -> Result<F::Model, Failure> {
        let mut model = F::model(self.resources.as_deref())
            .map_err(|e| Failure::error(format!("the model could not be made again: {e}")))?
            .model;
        for (&k, &x) in self.table.parameters.iter().zip(parameters) {
            model.set_parameter_value(k, x);
        }
        for (k, &x) in inputs.iter().enumerate() {
            model.set_input_value(k, x);
        }
        Ok(model)
    }

    /// The current parameter and input values, in the order of the FMU's variables.
    fn values(&self) -> (Vec<f64>, Vec<f64>) {
        let model = self.model();
        let parameters = self.table.parameters.iter().map(|&k| model.parameter_value(k)).collect();
        (parameters, (0..self.table.inputs).map(|k| model.input_value(k)).collect())
    }

    /// Refuses a call (named without its `fmi2`/`fmi3` prefix: one instance serves both) in
    /// the wrong state.
    fn expect(&self, allowed: &[Phase], call: &str) -> Result<(), Failure> {
        if allowed.contains(&self.phase) {
            Ok(())
        } else {
            Err(Failure::error(format!("{call} is not allowed when the instance is {}", self.phase.name())))
        }
    }

    /// `fmi3EnterInitializationMode`.
    pub fn enter_initialization(
        &mut self,
        tolerance: Option<f64>,
        start: f64,
        stop: Option<f64>,
    ) -> Result<(), Failure> {
        self.expect(&[Phase::Instantiated], "EnterInitializationMode")?;
        if let Some(tol) = tolerance {
            if !(tol > 0.0 && tol.is_finite()) {
                return Err(Failure::error(format!("the tolerance {tol} is not positive and finite")));
            }
            self.tolerance = tol;
        }
        if !start.is_finite() {
            return Err(Failure::error(format!("the start time {start} is not finite")));
        }
        if let Some(stop) = stop
            && (stop.is_nan() || stop < start)
        {
            return Err(Failure::error(format!("the stop time {stop} is before the start time {start}")));
        }
        self.t = start;
        self.state = None;
        self.phase = Phase::Initialization;
        Ok(())
    }

    /// The consistent state at the start, computed from the start values when first asked for.
    fn initial_state(&mut self) -> Result<&State<F::Model>, Failure> {
        if self.state.is_none() {
            let state = crate::consistent_state(
                self.model(),
                self.t,
                &self.start_q,
                &self.start_v,
                Consistency::default(),
            )
            .map_err(|e| Failure::error(format!("no consistent initial state: {e}")))?;
            self.state = Some(state);
        }
        self.state.as_ref().ok_or_else(|| Failure::error("no initial state"))
    }

    /// `fmi3ExitInitializationMode`.
    pub fn exit_initialization(&mut self) -> Result<(), Failure> {
        self.expect(&[Phase::Initialization], "ExitInitializationMode")?;
        // Its steps locate no events, so a law's mode would never switch.
        if crate::__private::has_laws(self.model()) {
            return Err(Failure::error(
                "the model has friction laws, diodes or switches (`friction`, `diode`, `switch`), whose modes \
                 switch at events that the FMU's steps do not locate: export a model without them",
            ));
        }
        // The integrator is built at the first step: refuse a tolerance it would refuse now.
        self.options().validate().map_err(|e| Failure::error(e.to_string()))?;
        self.initial_state()?;
        self.phase = Phase::Step;
        Ok(())
    }

    /// `fmi3Terminate`.
    pub fn terminate(&mut self) -> Result<(), Failure> {
        self.expect(&[Phase::Step], "Terminate")?;
        self.phase = Phase::Terminated;
        Ok(())
    }

    /// `fmi3Reset`: back to the instance as instantiated. Nothing changes if the model cannot
    /// be made again.
    pub fn reset(&mut self) -> Result<(), Failure> {
        *self = Instance::instantiate(self.resources.as_deref())?;
        Ok(())
    }

    /// `fmi3GetFloat64`.
    pub fn get(&mut self, vrs: &[u32], values: &mut [f64]) -> Result<(), Failure> {
        if self.phase == Phase::Instantiated {
            return Err(Failure::error(
                "reading values is not allowed before EnterInitializationMode: no value is computed yet",
            ));
        }
        if vrs.len() != values.len() {
            return Err(Failure::error(format!(
                "{} value references but {} values",
                vrs.len(),
                values.len()
            )));
        }
        let needs_state = vrs.iter().any(|&vr| {
            matches!(
                self.table.variable(vr),
                Some(
                    Variable::Output(_)
                        | Variable::Position(_)
                        | Variable::Velocity(_)
                        | Variable::Multiplier(_)
                )
            )
        });
        if needs_state && self.phase == Phase::Initialization {
            self.initial_state()?;
        }
        let mut outputs_current = false;
        for (&vr, value) in vrs.iter().zip(values.iter_mut()) {
            let variable = self.variable(vr)?;
            *value = match variable {
                Variable::Time => self.t,
                Variable::Parameter(k) => self.model().parameter_value(k),
                Variable::Input(k) => self.model().input_value(k),
                Variable::Output(k) => {
                    if !outputs_current {
                        let mut outputs = std::mem::take(&mut self.outputs);
                        let state = self.current()?;
                        self.model().outputs(self.t, &state.q, &state.v, &state.lambda, &mut outputs);
                        self.outputs = outputs;
                        outputs_current = true;
                    }
                    self.outputs[k]
                }
                Variable::Position(k) => self.current()?.q[k],
                Variable::Velocity(k) => self.current()?.v[k],
                Variable::Multiplier(k) => self.current()?.lambda[k],
            };
        }
        Ok(())
    }

    fn current(&self) -> Result<&State<F::Model>, Failure> {
        self.state.as_ref().ok_or_else(not_computed)
    }

    fn variable(&self, vr: u32) -> Result<Variable, Failure> {
        self.table.variable(vr).ok_or_else(|| {
            Failure::error(format!(
                "no Float64 variable has value reference {vr} (the model's are 0 to {})",
                self.table.len() - 1
            ))
        })
    }

    /// `fmi3SetFloat64`. Nothing is changed unless every value can be set.
    pub fn set(&mut self, vrs: &[u32], values: &[f64]) -> Result<(), Failure> {
        if vrs.len() != values.len() {
            return Err(Failure::error(format!(
                "{} value references but {} values",
                vrs.len(),
                values.len()
            )));
        }
        let before_start = matches!(self.phase, Phase::Instantiated | Phase::Initialization);
        for (&vr, &value) in vrs.iter().zip(values) {
            let variable = self.variable(vr)?;
            let settable = match variable {
                Variable::Input(_) => {
                    matches!(self.phase, Phase::Instantiated | Phase::Initialization | Phase::Step)
                }
                Variable::Parameter(_) | Variable::Position(_) | Variable::Velocity(_) => before_start,
                Variable::Time | Variable::Output(_) | Variable::Multiplier(_) => false,
            };
            if !settable {
                return Err(Failure::error(format!(
                    "value reference {vr} ({variable:?}) cannot be set when the instance is {}",
                    self.phase.name()
                )));
            }
            if !value.is_finite() {
                return Err(Failure::error(format!(
                    "value reference {vr} ({variable:?}) cannot be set to {value}"
                )));
            }
        }
        for (&vr, &value) in vrs.iter().zip(values) {
            match self.variable(vr)? {
                Variable::Parameter(k) => self.model_mut().set_parameter_value(k, value),
                Variable::Input(k) => self.model_mut().set_input_value(k, value),
                Variable::Position(k) => self.start_q[k] = value,
                Variable::Velocity(k) => self.start_v[k] = value,
                Variable::Time | Variable::Output(_) | Variable::Multiplier(_) => {}
            }
        }
        if before_start {
            self.state = None;
        }
        Ok(())
    }

    /// `fmi3DoStep`: integrates from `t` to `t + h` with the inputs held, restarting the
    /// integrator at `t` (inputs may have jumped there). On failure the instance stays at `t`.
    pub fn do_step(&mut self, t: f64, h: f64) -> Result<(), Failure> {
        self.expect(&[Phase::Step], "DoStep")?;
        let scale = 1.0 + self.t.abs();
        if !t.is_finite() || (t - self.t).abs() > 1e-12 * scale {
            return Err(Failure::error(format!(
                "DoStep from t = {t}, but the instance is at t = {}",
                self.t
            )));
        }
        if !(h > 0.0 && h.is_finite()) {
            return Err(Failure::error(format!(
                "the communication step size {h} is not positive and finite"
            )));
        }
        // The importer's grid, not a sum of its steps: no drift between the two clocks.
        let (at, end) = (self.t, t + h);
        if !end.is_finite() {
            return Err(Failure::error(format!("the step from t = {t} by {h} ends beyond the largest time")));
        }
        if end <= at {
            return Err(Failure::error(format!("the communication step size {h} is too small at t = {at}")));
        }
        let result = match self.radau.as_mut() {
            Some(radau) => Self::advance(radau, end, false),
            None => {
                let options = self.options();
                let model = self.model.take().expect("the model, before the first step");
                let mut radau =
                    Radau::new(Held::Owned(model), options).map_err(|e| Failure::error(e.to_string()))?;
                let state = self.state.as_ref().ok_or_else(not_computed)?;
                let started = match radau.start(at, state, end) {
                    // An input in a constraint was set after the initialisation: the state
                    // jumps with it, as at a later communication point ([`Self::advance`]).
                    Err(crate::SimError::StateNotConsistent { .. }) => {
                        crate::consistent_state(radau.model(), at, &state.q, &state.v, Consistency::default())
                            .and_then(|jumped| radau.start(at, &jumped, end))
                    }
                    other => other,
                };
                let result = started.and_then(|()| Self::advance(&mut radau, end, true));
                self.radau = Some(radau);
                result
            }
        };
        match result {
            Ok(()) => {
                let (Some(radau), Some(state)) = (&self.radau, &mut self.state) else {
                    return Err(not_computed());
                };
                state.clone_from(radau.state());
                self.t = end;
                Ok(())
            }
            Err(e) => {
                // Back to `t`: a new integrator on the same model starts from the state kept there.
                let (parameters, inputs) = self.values();
                let model = self.model_with(&parameters, &inputs);
                self.radau = None;
                let failed = format!("the step from t = {at} to {end} failed: {e}");
                match model {
                    Ok(model) => {
                        self.model = Some(model);
                        Err(Failure::discard(failed))
                    }
                    Err(again) => {
                        // No model to go on with: the instance cannot continue.
                        self.phase = Phase::Failed;
                        Err(Failure::error(format!("{failed}; {}", again.message)))
                    }
                }
            }
        }
    }

    /// The integrator's options: the tolerance, relative and absolute, and no limit on the
    /// steps of its whole life (it lives across communication steps); [`Self::advance`] limits
    /// each communication step instead.
    fn options(&self) -> RadauOptions {
        RadauOptions { max_steps: usize::MAX, ..RadauOptions::tolerances(self.tolerance, self.tolerance) }
    }

    /// Steps to `end`, restarting there first unless the integrator was just started, with at
    /// most [`STEPS_PER_COMMUNICATION_STEP`] steps and rejections.
    fn advance(radau: &mut Radau<'static, F::Model>, end: f64, started: bool) -> Result<(), crate::SimError> {
        if !started {
            match radau.restart_until(end) {
                // An input in a constraint (a voltage source's voltage, a prescribed position)
                // jumped at the communication point: the state jumps with it, as an impulse
                // through the constraints would take it, to the consistent state nearest in
                // the kinetic-energy norm (a capacitor's charge kept unless the source is across
                // it), and the integration starts again there.
                Err(crate::SimError::ConstraintMoved { .. }) => {
                    let (t, state) = (radau.t(), radau.state());
                    let jumped = crate::consistent_state(
                        radau.model(),
                        t,
                        &state.q,
                        &state.v,
                        Consistency::default(),
                    )?;
                    radau.start(t, &jumped, end)?;
                }
                other => other?,
            }
        }
        let count = |radau: &Radau<'static, F::Model>| {
            let stats = radau.stats();
            stats.steps + stats.rejected
        };
        let before = count(radau);
        while !radau.finished() {
            if count(radau) - before >= STEPS_PER_COMMUNICATION_STEP {
                let max_steps = STEPS_PER_COMMUNICATION_STEP;
                return Err(crate::SimError::TooManySteps { max_steps, t: radau.t(), t_end: end });
            }
            radau.step()?;
        }
        Ok(())
    }

    /// The instance's time.
    pub fn time(&self) -> f64 {
        self.t
    }

    /// Everything `fmi3SetFMUState` needs to come back here, as numbers (also its serialised
    /// form).
    pub fn snapshot(&self) -> Snapshot {
        let mut values = vec![SNAPSHOT_MAGIC, self.phase.code(), self.t, self.tolerance];
        let (parameters, inputs) = self.values();
        values.extend(parameters.iter().chain(&inputs));
        values.extend(self.start_q.iter().chain(self.start_v.iter()));
        match &self.state {
            Some(state) => {
                values.push(1.0);
                values.extend(state.components());
            }
            None => values.push(0.0),
        }
        Snapshot { values }
    }

    /// Goes back to a snapshot; refuses (and changes nothing) one that is not of this model.
    pub fn restore(&mut self, snapshot: &Snapshot) -> Result<(), Failure> {
        let refuse = || Failure::error("the FMU state does not belong to this model");
        let table = self.table.clone();
        let n = self.start_q.len();
        if !snapshot.values.iter().all(|x| x.is_finite()) {
            return Err(refuse());
        }
        let mut values = snapshot.values.iter().copied();
        let mut next = || values.next().ok_or_else(refuse);
        if next()? != SNAPSHOT_MAGIC {
            return Err(refuse());
        }
        let phase = Phase::from_code(next()?).ok_or_else(refuse)?;
        let (t, tolerance) = (next()?, next()?);
        let parameters: Vec<f64> = table.parameters.iter().map(|_| next()).collect::<Result<_, _>>()?;
        let inputs: Vec<f64> = (0..table.inputs).map(|_| next()).collect::<Result<_, _>>()?;
        let starts: Vec<f64> = (0..2 * n).map(|_| next()).collect::<Result<_, _>>()?;
        let state = match next()? {
            0.0 => None,
            1.0 => {
                let mut state = State::<F::Model>::with_sizes(self.model().sizes());
                for x in state.components_mut() {
                    *x = next()?;
                }
                Some(state)
            }
            _ => return Err(refuse()),
        };
        if next().is_ok() {
            return Err(refuse());
        }
        let model = self.model_with(&parameters, &inputs)?;
        // A new integrator starts at the snapshot's time and state at the next step.
        self.radau = None;
        self.model = Some(model);
        for k in 0..n {
            self.start_q[k] = starts[k];
            self.start_v[k] = starts[n + k];
        }
        (self.phase, self.t, self.tolerance, self.state) = (phase, t, tolerance, state);
        Ok(())
    }
}

impl Snapshot {
    /// The serialised form: the numbers' little-endian bytes.
    pub fn to_bytes(&self) -> Vec<u8> {
        self.values.iter().flat_map(|x| x.to_le_bytes()).collect()
    }

    /// The serialised form's length in bytes.
    pub fn byte_len(&self) -> usize {
        8 * self.values.len()
    }

    /// From the serialised form; `None` if it cannot be one.
    pub fn from_bytes(bytes: &[u8]) -> Option<Snapshot> {
        if !bytes.len().is_multiple_of(8) {
            return None;
        }
        let values = bytes
            .chunks_exact(8)
            .map(|chunk| <[u8; 8]>::try_from(chunk).map(f64::from_le_bytes))
            .collect::<Result<Vec<f64>, _>>()
            .ok()?;
        Some(Snapshot { values })
    }
}

impl<M: Export> Instance<M>
where
    DefaultAllocator: Storage<M>,
{
    /// A new instance of an [`Export`] model: the model as [`Export::instantiate`] makes it,
    /// its start values, time zero.
    pub fn new() -> Instance<M> {
        Instance::from_start(super::start_of(M::instantiate()), None)
    }
}

impl<M: Export> Default for Instance<M>
where
    DefaultAllocator: Storage<M>,
{
    fn default() -> Self {
        Instance::new()
    }
}
