//! Simulation results: a table of named series (state, energy, power, constraint residuals,
//! interconnection forces) sampled at chosen times, with the solver's statistics and CSV export.

use std::any::TypeId;
use std::io::{self, Write};
use std::marker::PhantomData;
use std::sync::{Arc, Mutex, OnceLock, PoisonError};

use nalgebra::{DefaultAllocator, Dim};

use crate::hybrid::event::{Event, Impact};
use crate::model::keys::{Constraint, Coordinate, Input, Output};
use crate::model::state::State;
use crate::model::{DISSIPATED_POWER, LagrangeDirac};
use crate::shape::dims::{Sizes, Storage};
use crate::shape::layout::Layout;

/// When a simulation records a sample.
#[derive(Clone, Debug, PartialEq)]
pub enum Sampling {
    /// At the start and after every accepted step.
    Steps,
    /// Every `dt` from the start, and at the end time if the grid misses it (dense output
    /// between steps).
    Every(f64),
    /// At these increasing times within the time span (dense output between steps).
    Times(Vec<f64>),
}

/// Where each series of a solution sits: `t`, the state's slots in the order of [`Layout`],
/// the derived quantities, the effort at each port, the model's outputs, then its inputs.
#[derive(Clone)]
pub(crate) struct Columns {
    /// Where the state's parts sit among its slots.
    state: Layout,
    /// The ports' coordinate indices.
    pub ports: Vec<usize>,
    /// The number of the model's outputs.
    pub outputs: usize,
    /// The number of the model's inputs.
    pub inputs: usize,
    /// The outputs that are the power a subsystem's dissipation takes (named
    /// `dissipated_power`, at any depth): their sum is the model's dissipated power.
    pub dissipation: Vec<usize>,
    /// The column of each series the model recovers ([`LagrangeDirac::recovered_names`]): a
    /// port's effort column where the name is one, otherwise a column after the inputs'.
    pub recovered: Vec<usize>,
    /// The columns recorded each in its own vector; those after them (the recovered series
    /// that are not a port's effort) are recorded sample by sample in one vector, so that a
    /// short run of a reduced model allocates once for them, not once per series.
    pub stored: usize,
    /// How many series are recorded after the stored columns.
    pub appended: usize,
    /// Each column's unit, where the model declares one (`unit(x) = "m"`): time in seconds,
    /// coordinates, velocities, outputs and inputs as declared.
    pub units: Arc<[Option<&'static str>]>,
}

impl Columns {
    /// The derived quantities, in their column order.
    pub const DERIVED: [&'static str; 7] = [
        "energy",
        "power",
        "dissipated_power",
        "constraint_residual",
        "holonomic_residual",
        "interconnection_power",
        "constraint_power",
    ];

    /// The columns of a model's solution, and their names. A model whose sizes its type fixes
    /// has names its type fixes too (only arrays of subsystems name their parts by instance):
    /// they are built once per type and shared by every solution, which on a small model saves
    /// a tenth of a short integration.
    pub fn of<M: LagrangeDirac>(model: &M) -> (Columns, Arc<[String]>)
    where
        DefaultAllocator: Storage<M>,
    {
        type Cache = Mutex<Vec<(TypeId, Columns, Arc<[String]>)>>;
        static CACHE: OnceLock<Cache> = OnceLock::new();
        if <M::Nq as Dim>::try_to_usize().is_none() || <M::Nc as Dim>::try_to_usize().is_none() {
            let (columns, names) = Self::build(model);
            return (columns, names.into());
        }
        let id = TypeId::of::<M>();
        let cache = CACHE.get_or_init(Cache::default);
        let known = |cache: &Cache| {
            let entries = cache.lock().unwrap_or_else(PoisonError::into_inner);
            entries.iter().find(|(t, ..)| *t == id).map(|(_, c, n)| (c.clone(), Arc::clone(n)))
        };
        if let Some(found) = known(cache) {
            return found;
        }
        let (columns, names) = Self::build(model);
        let names: Arc<[String]> = names.into();
        let mut entries = cache.lock().unwrap_or_else(PoisonError::into_inner);
        entries.push((id, columns.clone(), Arc::clone(&names)));
        (columns, names)
    }

    /// The columns of a model's solution, and their names, built from the model.
    fn build<M: LagrangeDirac>(model: &M) -> (Columns, Vec<String>)
    where
        DefaultAllocator: Storage<M>,
    {
        let ports: Vec<usize> = model.ports().into_iter().map(|c| c.index()).collect();
        let outputs = model.output_names();
        let dissipation = (outputs.iter().enumerate())
            .filter(|(_, o)| o.rsplit('.').next() == Some(DISSIPATED_POWER))
            .map(|(k, _)| k)
            .collect();
        let inputs = model.input_names();
        let coordinates = model.coordinate_names();
        let velocities = model.velocity_names();
        let unit = |name: &String| model.unit_of(name);
        let mut units = vec![Some("s")];
        units.extend(coordinates.iter().map(unit));
        units.extend(velocities.iter().map(unit));
        let unknown = coordinates.len() + model.constraint_names().len() + Self::DERIVED.len() + ports.len();
        units.extend(std::iter::repeat_n(None, unknown));
        units.extend(outputs.iter().map(unit));
        units.extend(inputs.iter().map(unit));
        let mut columns = Columns {
            state: Layout::new(model.sizes()),
            ports,
            outputs: outputs.len(),
            inputs: inputs.len(),
            dissipation,
            recovered: Vec::new(),
            stored: 0,
            appended: 0,
            units: Arc::from([]),
        };
        let mut names = vec!["t".to_owned()];
        names.extend(coordinates.iter().cloned());
        names.extend(velocities);
        names.extend(coordinates.iter().map(|c| format!("p({c})")));
        names.extend(model.constraint_names().iter().map(|c| format!("lambda({c})")));
        names.extend(Self::DERIVED.iter().map(|s| (*s).to_owned()));
        names.extend(columns.ports.iter().map(|&i| format!("f({})", coordinates[i])));
        names.extend(outputs.iter().map(|o| format!("out({o})")));
        names.extend(inputs.iter().map(|u| format!("in({u})")));
        columns.stored = names.len();
        for name in model.recovered_names() {
            let column = names.iter().position(|n| n == name).unwrap_or_else(|| {
                names.push((*name).to_owned());
                units.push(model.unit_of(name));
                names.len() - 1
            });
            columns.recovered.push(column);
        }
        columns.appended = names.len() - columns.stored;
        columns.units = units.into();
        (columns, names)
    }

    /// The column of slot `i` of the state.
    pub fn slot(&self, i: usize) -> usize {
        1 + i
    }

    /// The column of derived quantity `k` of [`Columns::DERIVED`].
    pub fn derived(&self, k: usize) -> usize {
        1 + self.state.len + k
    }

    /// The column of the effort at port `k` (an index into `ports`).
    pub fn port(&self, k: usize) -> usize {
        1 + self.state.len + Self::DERIVED.len() + k
    }

    /// The column of output `k`.
    pub fn output(&self, k: usize) -> usize {
        1 + self.state.len + Self::DERIVED.len() + self.ports.len() + k
    }

    /// The column of input `k`.
    pub fn input(&self, k: usize) -> usize {
        self.output(self.outputs) + k
    }
}

/// The result of a simulation: named series over the sample times, and the statistics `S` of
/// the integrator that produced it ([`RadauStats`](crate::RadauStats) or
/// [`VariationalStats`](crate::VariationalStats)).
pub struct Solution<M: LagrangeDirac, S>
where
    DefaultAllocator: Storage<M>,
{
    layout: Columns,
    names: Arc<[String]>,
    columns: Vec<Vec<f64>>,
    sizes: Sizes,
    /// The work the integrator did.
    pub stats: S,
    events: Vec<Event>,
    event_names: Vec<String>,
    impacts: Vec<Impact>,
    contact_names: Vec<String>,
    /// What the sensitivities are taken with respect to, by name ...
    sensitivity_names: Vec<String>,
    /// ... and their series: sensitivity `j` of state slot `i` at `j * len + i`.
    sensitivities: Vec<Vec<f64>>,
    /// The series after the stored columns, sample by sample ([`Columns::stored`]), and the
    /// same as columns once one is read.
    appended: Vec<f64>,
    appended_columns: OnceLock<Vec<Vec<f64>>>,
    model: PhantomData<fn() -> M>,
}

impl<M: LagrangeDirac, S: std::fmt::Debug> std::fmt::Debug for Solution<M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// The samples' count and time span, the series' names and the statistics (not the data).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let span = (self.t().first(), self.t().last());
        f.debug_struct("Solution")
            .field("samples", &self.len())
            .field("span", &span)
            .field("names", &self.names)
            .field("events", &self.events.len())
            .field("stats", &self.stats)
            .finish()
    }
}

impl<M: LagrangeDirac, S> Solution<M, S>
where
    DefaultAllocator: Storage<M>,
{
    /// A solution from recorded columns.
    pub(crate) fn new(
        layout: Columns,
        names: Arc<[String]>,
        (columns, appended): (Vec<Vec<f64>>, Vec<f64>),
        sizes: Sizes,
        stats: S,
    ) -> Self {
        Solution {
            layout,
            names,
            columns,
            appended,
            appended_columns: OnceLock::new(),
            sizes,
            stats,
            events: Vec::new(),
            event_names: Vec::new(),
            impacts: Vec::new(),
            contact_names: Vec::new(),
            sensitivity_names: Vec::new(),
            sensitivities: Vec::new(),
            model: PhantomData,
        }
    }

    /// This solution with the events located during it, and the names of the event functions.
    pub(crate) fn with_events(mut self, events: Vec<Event>, names: Vec<String>) -> Self {
        self.events = events;
        self.event_names = names;
        self
    }

    /// This solution with the impacts at the model's unilateral constraints, and their names.
    pub(crate) fn with_impacts(mut self, impacts: Vec<Impact>, names: Vec<String>) -> Self {
        self.impacts = impacts;
        self.contact_names = names;
        self
    }

    /// This solution with forward sensitivities: their names, and sensitivity `j` of state slot
    /// `i` at `columns[j * len + i]`.
    pub(crate) fn with_sensitivities(mut self, names: Vec<String>, columns: Vec<Vec<f64>>) -> Self {
        self.sensitivity_names = names;
        self.sensitivities = columns;
        self
    }

    /// What the solution's forward sensitivities are taken with respect to, by name
    /// ([`Sensitivities::names`](crate::simulate::sensitivity::Sensitivities::names)); empty without sensitivities.
    pub fn sensitivity_names(&self) -> &[String] {
        &self.sensitivity_names
    }

    /// The sensitivity `∂x/∂θ` of the state quantity named `quantity` (a column name of the
    /// state: a coordinate `x`, a velocity, `p(x)`, `lambda(c)`) with respect to `wrt` (a
    /// parameter's dotted name, or an initial value `x(t0)`), at each sample; `None` if either
    /// name is unknown.
    pub fn sensitivity(&self, quantity: &str, wrt: &str) -> Option<&[f64]> {
        let len = self.layout.state.len;
        let i = self.names[1..=len].iter().position(|n| n == quantity)?;
        self.sensitivity_at_slot(i, wrt)
    }

    /// `∂q_c/∂θ` with respect to `wrt` at each sample.
    pub fn dq(&self, c: Coordinate<M>, wrt: &str) -> Option<&[f64]> {
        self.sensitivity_at_slot(self.layout.state.q + c.index(), wrt)
    }

    /// `∂v_c/∂θ` with respect to `wrt` at each sample.
    pub fn dv(&self, c: Coordinate<M>, wrt: &str) -> Option<&[f64]> {
        self.sensitivity_at_slot(self.layout.state.v + c.index(), wrt)
    }

    /// `∂p_c/∂θ` with respect to `wrt` at each sample.
    pub fn dp(&self, c: Coordinate<M>, wrt: &str) -> Option<&[f64]> {
        self.sensitivity_at_slot(self.layout.state.p + c.index(), wrt)
    }

    /// `∂λ_k/∂θ` with respect to `wrt` at each sample.
    pub fn dlambda(&self, k: Constraint<M>, wrt: &str) -> Option<&[f64]> {
        self.sensitivity_at_slot(self.layout.state.lambda + k.index(), wrt)
    }

    fn sensitivity_at_slot(&self, i: usize, wrt: &str) -> Option<&[f64]> {
        let j = self.sensitivity_names.iter().position(|n| n == wrt)?;
        Some(&self.sensitivities[j * self.layout.state.len + i])
    }

    /// The gradient `dJ/dθ` of a scalar objective `J` that depends on the state quantity
    /// `quantity` at the samples, by the chain rule over the sensitivities: `dj_dx[k]` is
    /// `∂J/∂x(t_k)`. For a sum of squared errors `J = Σ (x(t_k) − d_k)²` it is
    /// `2 (x(t_k) − d_k)`. One entry per sensitivity, in the order of
    /// [`sensitivity_names`](Solution::sensitivity_names); `None` if the quantity is unknown
    /// or `dj_dx` has not one value per sample.
    pub fn gradient(&self, quantity: &str, dj_dx: &[f64]) -> Option<Vec<f64>> {
        if dj_dx.len() != self.len() {
            return None;
        }
        let names = self.sensitivity_names.clone();
        names
            .iter()
            .map(|wrt| {
                let s = self.sensitivity(quantity, wrt)?;
                Some(s.iter().zip(dj_dx).map(|(a, b)| a * b).sum())
            })
            .collect()
    }

    /// The impacts at the model's unilateral constraints, in time order (with
    /// [`Events::contacts`](crate::hybrid::events::Events::contacts)). Contacts that close at one time share
    /// one impact law and are recorded one by one, each with its own impulse.
    pub fn impacts(&self) -> &[Impact] {
        &self.impacts
    }

    /// The impacts at the unilateral constraint called `name`, in order; `None` if the model
    /// has no unilateral constraint of that name (or the contacts were not watched).
    pub fn impacts_at(&self, name: &str) -> Option<Vec<Impact>> {
        let index = self.contact_names.iter().position(|n| n == name)?;
        Some(self.impacts.iter().filter(|i| i.contact == index).copied().collect())
    }

    /// The name of the unilateral constraint `impact` closed.
    pub fn contact_name(&self, impact: &Impact) -> &str {
        self.contact_names.get(impact.contact).map_or("a contact", String::as_str)
    }

    /// The events located, in time order ([`Solve::solve_with_events`](crate::Solve::solve_with_events)).
    pub fn events(&self) -> &[Event] {
        &self.events
    }

    /// The name of `event`'s function.
    pub fn event_name(&self, event: &Event) -> &str {
        &self.event_names[event.index]
    }

    /// The times of the events of the function called `name`, in order; `None` if no event
    /// function has that name (an empty list if it has, and never crossed).
    pub fn event_times(&self, name: &str) -> Option<Vec<f64>> {
        let index = self.event_names.iter().position(|n| n == name)?;
        Some(self.events.iter().filter(|e| e.index == index).map(|e| e.t).collect())
    }

    /// The number of samples.
    pub fn len(&self) -> usize {
        self.columns[0].len()
    }

    /// Whether there are no samples.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The sample times.
    pub fn t(&self) -> &[f64] {
        &self.columns[0]
    }

    /// The position of coordinate `c` at each sample.
    pub fn q(&self, c: Coordinate<M>) -> &[f64] {
        &self.columns[self.layout.slot(self.layout.state.q + c.index())]
    }

    /// The velocity of coordinate `c`.
    pub fn v(&self, c: Coordinate<M>) -> &[f64] {
        &self.columns[self.layout.slot(self.layout.state.v + c.index())]
    }

    /// The momentum conjugate to coordinate `c`.
    pub fn p(&self, c: Coordinate<M>) -> &[f64] {
        &self.columns[self.layout.slot(self.layout.state.p + c.index())]
    }

    /// The multiplier of constraint `k`.
    pub fn lambda(&self, k: Constraint<M>) -> &[f64] {
        &self.columns[self.layout.slot(self.layout.state.lambda + k.index())]
    }

    /// The series of an output (`#[dirac(output(name) = …)]`), also the column `out(name)`.
    pub fn output(&self, key: Output<M>) -> &[f64] {
        &self.columns[self.layout.output(key.index())]
    }

    /// The series of an input (`#[dirac(input(name))]`: a controller's force, a source's
    /// voltage), also the column `in(name)`: the value the model held at each sample (set by
    /// the user between steps, by `solve_sampled`'s controller, by a drive or a held table).
    pub fn input(&self, key: Input<M>) -> &[f64] {
        &self.columns[self.layout.input(key.index())]
    }

    /// The generalised energy `E = ⟨p, v⟩ − L`.
    pub fn energy(&self) -> &[f64] {
        &self.columns[self.layout.derived(0)]
    }

    /// The power the external forces put in, `⟨F, v⟩`, the dissipation's forces `−∂R/∂v`
    /// excepted (they are [`dissipated_power`](Solution::dissipated_power)): the power of the
    /// sources.
    pub fn power(&self) -> &[f64] {
        &self.columns[self.layout.derived(1)]
    }

    /// The power the dissipation takes out, `⟨∂R/∂v, v⟩ ≥ 0`, summed over the model and its
    /// subsystems (each one's is also the output `dissipated_power`, `motor.dissipated_power`
    /// in an interconnection). On solutions
    /// `dE/dt = power − dissipated power − ∂L/∂t + constraint power`.
    pub fn dissipated_power(&self) -> &[f64] {
        &self.columns[self.layout.derived(2)]
    }

    /// `‖A(q, t) v + b(q, t)‖∞`.
    pub fn constraint_residual(&self) -> &[f64] {
        &self.columns[self.layout.derived(3)]
    }

    /// `‖φ(q, t)‖∞`.
    pub fn holonomic_residual(&self) -> &[f64] {
        &self.columns[self.layout.derived(4)]
    }

    /// The power of the interconnection forces: zero for a lossless interconnection, `−⟨μ, b⟩`
    /// for one that prescribes a relative motion.
    pub fn interconnection_power(&self) -> &[f64] {
        &self.columns[self.layout.derived(5)]
    }

    /// The power `−⟨λ, b(q, t)⟩` the constraints put in by prescribing motion; zero unless
    /// a constraint depends on time. With [`power`](Solution::power),
    /// [`dissipated_power`](Solution::dissipated_power) and `∂L/∂t` it closes the energy
    /// balance, `dE/dt = power − dissipated power − ∂L/∂t + constraint power`.
    pub fn constraint_power(&self) -> &[f64] {
        &self.columns[self.layout.derived(6)]
    }

    /// The interconnection force (effort) at port `c`, if `c` is a port.
    pub fn interconnection_force(&self, c: Coordinate<M>) -> Option<&[f64]> {
        let k = self.layout.ports.iter().position(|&i| i == c.index())?;
        Some(&self.columns[self.layout.port(k)])
    }

    /// The column names, `t` first.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The column with this name.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        let i = self.names.iter().position(|n| n == name)?;
        Some(self.series(i))
    }

    /// Series `i`, in the order of the names.
    fn series(&self, i: usize) -> &[f64] {
        let Some(j) = i.checked_sub(self.columns.len()) else { return &self.columns[i] };
        let appended = self.appended_columns.get_or_init(|| {
            let count = self.layout.appended;
            (0..count).map(|j| self.appended.iter().skip(j).step_by(count).copied().collect()).collect()
        });
        &appended[j]
    }

    /// Every series, in the order of the names, then the sensitivities.
    fn all_series(&self) -> Vec<&[f64]> {
        let series = (0..self.names.len()).map(|i| self.series(i));
        series.chain(self.sensitivities.iter().map(Vec::as_slice)).collect()
    }

    /// The unit of the column `name`, where the model declares it (`unit(x) = "m"`; the parts
    /// of `dirac::components` declare theirs): `s` for `t`, a coordinate's, a velocity's, an
    /// output's (`out(name)`) and an input's (`in(name)`) as declared. What figures label
    /// their axes with.
    pub fn unit(&self, name: &str) -> Option<&'static str> {
        let i = self.names.iter().position(|n| n == name)?;
        self.layout.units.get(i).copied().flatten()
    }

    /// Sample `i` as a state, if there is such a sample.
    pub fn state(&self, i: usize) -> Option<State<M>> {
        if i >= self.len() {
            return None;
        }
        let mut state = State::<M>::with_sizes(self.sizes);
        for (k, x) in state.components_mut().enumerate() {
            *x = self.columns[self.layout.slot(k)][i];
        }
        Some(state)
    }

    /// The last sample as a state, if there is a sample.
    pub fn last(&self) -> Option<State<M>> {
        self.state(self.len().checked_sub(1)?)
    }

    /// Writes the solution as CSV: a header of names, then one row per sample. Sensitivities,
    /// if the solution has them, follow the other columns as `d(x)/d(k)`: the state quantity
    /// `x` with respect to `k`.
    pub fn write_csv(&self, mut out: impl Write) -> io::Result<()> {
        writeln!(out, "{}", self.all_names().join(","))?;
        let series = self.all_series();
        for i in 0..self.len() {
            let row: Vec<String> = series.iter().map(|c| format!("{:e}", c[i])).collect();
            writeln!(out, "{}", row.join(","))?;
        }
        Ok(())
    }

    /// Writes the solution as an Apache Parquet file, readable by Polars, pandas, DuckDB and
    /// Spark: one `DOUBLE` column per series, named and ordered as in
    /// [`write_csv`](Solution::write_csv), the values exactly as computed.
    pub fn write_parquet(&self, out: impl Write) -> io::Result<()> {
        crate::output::parquet::write(out, &self.all_names(), &self.all_series())
    }

    /// Writes the solution as an Apache Arrow IPC file (Feather version 2), readable by Polars
    /// (`read_ipc`), pyarrow, pandas (`read_feather`) and DuckDB without copying: one
    /// non-nullable `Float64` column per series, named and ordered as in
    /// [`write_csv`](Solution::write_csv), the values exactly as computed.
    pub fn write_arrow(&self, out: impl Write) -> io::Result<()> {
        crate::output::arrow::write(out, &self.all_names(), &self.all_series())
    }

    /// The names of every series, the sensitivities' (`d(x)/d(k)`) after the others.
    fn all_names(&self) -> Vec<String> {
        let len = self.layout.state.len;
        let mut names = self.names.to_vec();
        for wrt in &self.sensitivity_names {
            names.extend(self.names[1..=len].iter().map(|quantity| format!("d({quantity})/d({wrt})")));
        }
        names
    }
}
