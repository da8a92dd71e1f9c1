//! The FMU's variables: which value reference names which part of the model, and the
//! `modelDescription.xml` that lists them.

use std::fmt::Write as _;

use crate::nalgebra::DefaultAllocator;
use crate::{LagrangeDirac, Storage, VecQ};

use super::{Experiment, Export, Fmu, Start, Version};

/// What a value reference refers to. The references are numbered in this order: time, then
/// the parameters, inputs, outputs, positions, velocities and multipliers, each in the
/// model's own order of them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Variable {
    /// The independent variable.
    Time,
    /// Parameter `k` of [`Parameters::parameter_value`](crate::Parameters::parameter_value) (inputs, which are parameters to
    /// the model, are inputs to the FMU).
    Parameter(usize),
    /// Input `k` of [`InputsOutputs::input_value`](crate::InputsOutputs::input_value).
    Input(usize),
    /// Output `k` of [`LagrangeDirac::outputs`](crate::LagrangeDirac::outputs).
    Output(usize),
    /// Position `q[k]`.
    Position(usize),
    /// Velocity `v[k]`.
    Velocity(usize),
    /// Multiplier `λ[k]`.
    Multiplier(usize),
}

/// How many variables of each kind the FMU has.
#[derive(Clone, Debug)]
pub(crate) struct Table {
    /// The model's parameters that are not inputs, by their index in the model.
    pub parameters: Vec<usize>,
    pub inputs: usize,
    pub outputs: usize,
    pub coordinates: usize,
    pub constraints: usize,
}

impl Table {
    pub fn of<M: LagrangeDirac>(model: &M) -> Table
    where
        DefaultAllocator: Storage<M>,
    {
        let sizes = model.sizes();
        let inputs = model.input_names();
        let parameters = model.parameter_names();
        Table {
            parameters: (0..parameters.len()).filter(|&k| !inputs.contains(&parameters[k])).collect(),
            inputs: inputs.len(),
            outputs: model.output_names().len(),
            coordinates: sizes.nq,
            constraints: sizes.nc,
        }
    }

    /// The variable with value reference `vr`, if there is one.
    pub fn variable(&self, vr: u32) -> Option<Variable> {
        let mut k = usize::try_from(vr).ok()?;
        if k == 0 {
            return Some(Variable::Time);
        }
        k -= 1;
        type Kind = fn(usize) -> Variable;
        let kinds: [(usize, Kind); 6] = [
            (self.parameters.len(), Variable::Parameter),
            (self.inputs, Variable::Input),
            (self.outputs, Variable::Output),
            (self.coordinates, Variable::Position),
            (self.coordinates, Variable::Velocity),
            (self.constraints, Variable::Multiplier),
        ];
        for (count, kind) in kinds {
            if k < count {
                return Some(match kind(k) {
                    Variable::Parameter(k) => Variable::Parameter(self.parameters[k]),
                    variable => variable,
                });
            }
            k -= count;
        }
        None
    }

    /// The value reference of a variable.
    pub fn reference(&self, variable: Variable) -> u32 {
        let before = |skip: usize| 1 + skip;
        let parameters = self.parameters.len();
        let k = match variable {
            Variable::Time => 0,
            Variable::Parameter(k) => {
                before(self.parameters.iter().position(|&p| p == k).unwrap_or(usize::MAX - 1))
            }
            Variable::Input(k) => before(parameters) + k,
            Variable::Output(k) => before(parameters + self.inputs) + k,
            Variable::Position(k) => before(parameters + self.inputs + self.outputs) + k,
            Variable::Velocity(k) => before(parameters + self.inputs + self.outputs + self.coordinates) + k,
            Variable::Multiplier(k) => {
                before(parameters + self.inputs + self.outputs + 2 * self.coordinates) + k
            }
        };
        // Value references are 32 bits wide; a model with more variables than that is refused
        // when its description is written.
        u32::try_from(k).unwrap_or(u32::MAX)
    }

    /// The variable a name refers to in `model`'s FMU (`time`, `left.k1`, `lambda(rod)`, …).
    pub fn named<M: LagrangeDirac>(&self, model: &M, name: &str) -> Option<Variable>
    where
        DefaultAllocator: Storage<M>,
    {
        let at = |names: Vec<String>| names.iter().position(|n| n == name);
        if name == "time" {
            return Some(Variable::Time);
        }
        let parameters = model.parameter_names();
        let parameter =
            self.parameters.iter().find(|&&k| parameters[k] == name).map(|&k| Variable::Parameter(k));
        let multiplier = name.strip_prefix("lambda(").and_then(|rest| rest.strip_suffix(')'));
        parameter
            .or_else(|| at(model.input_names()).map(Variable::Input))
            .or_else(|| at(model.output_names()).map(Variable::Output))
            .or_else(|| at(model.coordinate_names()).map(Variable::Position))
            .or_else(|| at(model.velocity_names()).map(Variable::Velocity))
            .or_else(|| {
                let row = model.constraint_names().iter().position(|n| Some(n.as_str()) == multiplier)?;
                Some(Variable::Multiplier(row))
            })
    }

    /// The number of value references in use.
    pub fn len(&self) -> usize {
        1 + self.parameters.len() + self.inputs + self.outputs + 2 * self.coordinates + self.constraints
    }
}

/// Escapes text for an XML attribute value.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "&#{};", c as u32);
            }
            c => out.push(c),
        }
    }
    out
}

/// A start value as XML writes a double. Non-finite values were refused before.
fn number(x: f64) -> String {
    format!("{x:?}")
}

/// Why a model cannot be described as an FMU.
#[derive(Debug, thiserror::Error)]
pub enum DescriptionError {
    /// A start value is not a finite number.
    #[error("the start value of {name} is {value}: an FMU's start values must be finite")]
    NotFinite {
        /// The variable.
        name: String,
        /// Its value.
        value: f64,
    },
    /// Two variables have the same name.
    #[error("two variables are named {0}: an FMU's variable names must be unique")]
    DuplicateName(String),
    /// The model has unilateral constraints, which an FMU's steps would not keep.
    #[error(
        "the model has unilateral constraints ({0}): an FMU integrates without impacts or contact forces, so \
         it would pass through them; export the model without them"
    )]
    Unilateral(String),
    /// The model has laws that switch their modes at events, which an FMU's steps would not.
    #[error(
        "the model has friction laws, diodes or switches ({0}), whose modes switch at events that an FMU's \
         steps do not locate, so each would hold one mode throughout; export the model without them"
    )]
    Laws(String),
    /// The model has more variables than 32-bit value references can number.
    #[error("the model has {0} variables, more than FMI's 32-bit value references can number")]
    TooManyVariables(usize),
}

/// The text of `modelDescription.xml` without its instantiation token, and the token: a hash
/// of the rest, so that a library and a description written from different versions of a model
/// refuse each other.
pub(crate) fn description<F: Fmu>(
    start: &Start<F::Model>,
    version: Version,
) -> Result<(String, String), DescriptionError>
where
    DefaultAllocator: Storage<F::Model>,
{
    let header = Header { identifier: F::IDENTIFIER, about: F::ABOUT, experiment: F::experiment() };
    described(&start.model, &start.q, &start.v, &header, version)
}

/// [`description`] of an [`Export`] model as it is, from its start values.
pub(crate) fn description_of_model<M: Export>(
    model: &M,
    version: Version,
) -> Result<(String, String), DescriptionError>
where
    DefaultAllocator: Storage<M>,
{
    let sizes = model.sizes();
    let (mut q, mut v): (VecQ<M>, VecQ<M>) = (sizes.zeros_q::<M>(), sizes.zeros_q::<M>());
    model.start(&mut q, &mut v);
    let header = Header {
        identifier: M::MODEL_IDENTIFIER,
        about: M::DESCRIPTION,
        experiment: M::default_experiment(),
    };
    described(model, &q, &v, &header, version)
}

/// What the description says of the FMU rather than of its model.
struct Header {
    identifier: &'static str,
    about: &'static str,
    experiment: Experiment,
}

fn described<M: LagrangeDirac + crate::InputsOutputs + crate::Parameters>(
    model: &M,
    q: &VecQ<M>,
    v: &VecQ<M>,
    header: &Header,
    version: Version,
) -> Result<(String, String), DescriptionError>
where
    DefaultAllocator: Storage<M>,
{
    let body = body(model, q, v, header, version)?;
    let token = token(&body);
    let text = body.replacen("@TOKEN@", &token, 1);
    Ok((text, token))
}

/// An FNV-1a hash of the description, written like a GUID.
fn token(body: &str) -> String {
    let mut hash: u128 = 0x6c62272e07bb014262b821756295c58d;
    for byte in body.bytes() {
        hash ^= u128::from(byte);
        hash = hash.wrapping_mul(0x0000000001000000000000000000013B);
    }
    let h = format!("{hash:032x}");
    format!("{{{}-{}-{}-{}-{}}}", &h[0..8], &h[8..12], &h[12..16], &h[16..20], &h[20..32])
}

/// One `<Float64>` element.
struct Float64<'a> {
    name: &'a str,
    vr: u32,
    causality: &'a str,
    variability: &'a str,
    initial: Option<&'a str>,
    start: Option<f64>,
    unit: Option<&'a str>,
    description: &'a str,
}

impl Float64<'_> {
    /// FMI 3.0's `<Float64 .../>`, or FMI 2.0's `<ScalarVariable ...><Real .../></ScalarVariable>`.
    fn write(&self, out: &mut String, version: Version) -> Result<(), DescriptionError> {
        let element = match version {
            Version::Fmi3 => "Float64",
            Version::Fmi2 => "ScalarVariable",
        };
        let _ = write!(
            out,
            "    <{element} name=\"{}\" valueReference=\"{}\" causality=\"{}\" variability=\"{}\"",
            escape(self.name),
            self.vr,
            self.causality,
            self.variability
        );
        if let Some(initial) = self.initial {
            let _ = write!(out, " initial=\"{initial}\"");
        }
        if !self.description.is_empty() {
            let _ = write!(out, " description=\"{}\"", escape(self.description));
        }
        if version == Version::Fmi2 {
            out.push_str(">\n      <Real");
        }
        if let Some(start) = self.start {
            if !start.is_finite() {
                return Err(DescriptionError::NotFinite { name: self.name.to_string(), value: start });
            }
            let _ = write!(out, " start=\"{}\"", number(start));
        }
        if let Some(unit) = self.unit {
            let _ = write!(out, " unit=\"{}\"", escape(unit));
        }
        out.push_str("/>\n");
        if version == Version::Fmi2 {
            out.push_str("    </ScalarVariable>\n");
        }
        Ok(())
    }
}

fn body<M: LagrangeDirac + crate::InputsOutputs + crate::Parameters>(
    model: &M,
    q: &VecQ<M>,
    v: &VecQ<M>,
    header: &Header,
    version: Version,
) -> Result<String, DescriptionError>
where
    DefaultAllocator: Storage<M>,
{
    let unilaterals = model.unilateral_names();
    if !unilaterals.is_empty() {
        return Err(DescriptionError::Unilateral(unilaterals.join(", ")));
    }
    if crate::__private::has_laws(model) {
        return Err(DescriptionError::Laws(crate::__private::law_names(model).join(", ")));
    }
    let table = Table::of(model);
    if u32::try_from(table.len()).is_err() {
        return Err(DescriptionError::TooManyVariables(table.len()));
    }
    let parameters = model.parameter_names();
    let inputs = model.input_names();
    let outputs = model.output_names();
    let coordinates = model.coordinate_names();
    let velocities = model.velocity_names();
    let constraints = model.constraint_names();

    let mut units: Vec<&str> = Vec::new();
    let mut unit = |name: &str| {
        let unit = model.unit_of(name);
        if let Some(u) = unit
            && !units.contains(&u)
        {
            units.push(u);
        }
        unit
    };
    let mut seen = std::collections::HashSet::new();
    let mut variables = String::new();
    let mut element = |e: Float64| -> Result<(), DescriptionError> {
        if !seen.insert(e.name.to_string()) {
            return Err(DescriptionError::DuplicateName(e.name.to_string()));
        }
        e.write(&mut variables, version)
    };
    let (continuous, local) = ("continuous", "local");
    element(Float64 {
        name: "time",
        vr: table.reference(super::variables::Variable::Time),
        causality: "independent",
        variability: continuous,
        initial: None,
        start: None,
        unit: None,
        description: "Simulation time",
    })?;
    for &k in &table.parameters {
        element(Float64 {
            name: &parameters[k],
            vr: table.reference(Variable::Parameter(k)),
            causality: "parameter",
            variability: "fixed",
            initial: None,
            start: Some(model.parameter_value(k)),
            unit: unit(&parameters[k]),
            description: model.doc_of(&parameters[k]).unwrap_or("Parameter"),
        })?;
    }
    for (k, name) in inputs.iter().enumerate() {
        element(Float64 {
            name,
            vr: table.reference(Variable::Input(k)),
            causality: "input",
            variability: continuous,
            initial: None,
            start: Some(model.input_value(k)),
            unit: unit(name),
            description: model.doc_of(name).unwrap_or("Input, held over each communication step"),
        })?;
    }
    for (k, name) in outputs.iter().enumerate() {
        element(Float64 {
            name,
            vr: table.reference(Variable::Output(k)),
            causality: "output",
            variability: continuous,
            initial: None,
            start: None,
            unit: unit(name),
            description: "Output",
        })?;
    }
    for (k, name) in coordinates.iter().enumerate() {
        element(Float64 {
            name,
            vr: table.reference(Variable::Position(k)),
            causality: local,
            variability: continuous,
            initial: Some("exact"),
            start: Some(q[k]),
            unit: unit(name),
            description: "Position; its start value is made consistent with the constraints",
        })?;
    }
    for (k, name) in velocities.iter().enumerate() {
        element(Float64 {
            name,
            vr: table.reference(Variable::Velocity(k)),
            causality: local,
            variability: continuous,
            initial: Some("exact"),
            start: Some(v[k]),
            unit: unit(name),
            description: "Velocity; its start value is made consistent with the constraints",
        })?;
    }
    for (k, name) in constraints.iter().enumerate() {
        element(Float64 {
            name: &format!("lambda({name})"),
            vr: table.reference(Variable::Multiplier(k)),
            causality: local,
            variability: continuous,
            initial: Some("calculated"),
            start: None,
            unit: None,
            description: "Constraint multiplier",
        })?;
    }

    let experiment = header.experiment;
    let description = if header.about.is_empty() { M::NAMES.doc } else { header.about };
    let (identifier, tool) = (escape(header.identifier), env!("CARGO_PKG_VERSION"));
    let mut out = String::new();
    out.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    match version {
        Version::Fmi3 => {
            let _ = writeln!(
                out,
                "<fmiModelDescription fmiVersion=\"3.0\" modelName=\"{identifier}\" instantiationToken=\"@TOKEN@\" \
                 description=\"{}\" generationTool=\"dirac {tool}\" variableNamingConvention=\"flat\">",
                escape(description),
            );
            let _ = writeln!(
                out,
                "  <CoSimulation modelIdentifier=\"{identifier}\" canHandleVariableCommunicationStepSize=\"true\" \
                 canGetAndSetFMUState=\"true\" canSerializeFMUState=\"true\" hasEventMode=\"false\"/>",
            );
        }
        Version::Fmi2 => {
            let _ = writeln!(
                out,
                "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"{identifier}\" guid=\"@TOKEN@\" \
                 description=\"{}\" generationTool=\"dirac {tool}\" variableNamingConvention=\"flat\" \
                 numberOfEventIndicators=\"0\">",
                escape(description),
            );
            let _ = writeln!(
                out,
                "  <CoSimulation modelIdentifier=\"{identifier}\" canHandleVariableCommunicationStepSize=\"true\" \
                 canGetAndSetFMUstate=\"true\" canSerializeFMUstate=\"true\"/>",
            );
        }
    }
    if !units.is_empty() {
        out.push_str("  <UnitDefinitions>\n");
        for unit in &units {
            let _ = writeln!(out, "    <Unit name=\"{}\"/>", escape(unit));
        }
        out.push_str("  </UnitDefinitions>\n");
    }
    out.push_str("  <LogCategories>\n");
    out.push_str("    <Category name=\"logStatusError\" description=\"Calls that failed\"/>\n");
    out.push_str("    <Category name=\"logStatusDiscard\" description=\"Steps that could not be taken\"/>\n");
    out.push_str("  </LogCategories>\n");
    let _ = writeln!(
        out,
        "  <DefaultExperiment startTime=\"{}\" stopTime=\"{}\" tolerance=\"{}\" stepSize=\"{}\"/>",
        number(experiment.start),
        number(experiment.stop),
        number(experiment.tolerance),
        number(experiment.step)
    );
    out.push_str("  <ModelVariables>\n");
    out.push_str(&variables);
    out.push_str("  </ModelVariables>\n  <ModelStructure>\n");
    let outputs = (0..table.outputs).map(|k| table.reference(Variable::Output(k)));
    match version {
        Version::Fmi3 => {
            for vr in outputs.clone() {
                let _ = writeln!(out, "    <Output valueReference=\"{vr}\"/>");
            }
            for vr in outputs {
                let _ = writeln!(out, "    <InitialUnknown valueReference=\"{vr}\"/>");
            }
        }
        Version::Fmi2 if table.outputs > 0 => {
            // FMI 2.0 names variables by their 1-based place in ModelVariables: the value
            // references count from 0 in that order.
            for list in ["Outputs", "InitialUnknowns"] {
                let _ = writeln!(out, "    <{list}>");
                for vr in outputs.clone() {
                    let _ = writeln!(out, "      <Unknown index=\"{}\"/>", vr + 1);
                }
                let _ = writeln!(out, "    </{list}>");
            }
        }
        Version::Fmi2 => {}
    }
    out.push_str("  </ModelStructure>\n</fmiModelDescription>\n");
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn references_and_variables_are_inverse() {
        // Model parameters 0 and 2; parameter 1 is the input.
        let table = Table { parameters: vec![0, 2], inputs: 1, outputs: 3, coordinates: 4, constraints: 2 };
        for vr in 0..table.len() as u32 {
            let variable = table.variable(vr).expect("in range");
            assert_eq!(table.reference(variable), vr, "{variable:?}");
        }
        assert_eq!(table.variable(table.len() as u32), None);
        assert_eq!(table.variable(u32::MAX), None);
        assert_eq!(table.variable(2), Some(Variable::Parameter(2)));
        assert_eq!(table.variable(3), Some(Variable::Input(0)));
        assert_eq!(table.variable(11), Some(Variable::Velocity(0)));
    }

    #[test]
    fn attribute_text_is_escaped() {
        assert_eq!(escape("a<b & \"c\"\n"), "a&lt;b &amp; &quot;c&quot;&#10;");
    }
}
