//! Recording a solution while an integrator runs: the samples the [`Sampling`] asks for, each
//! with the derived series (energy, power, constraint residuals, port efforts).

use std::sync::Arc;

use nalgebra::DefaultAllocator;

use crate::algebra::{Algebra, amax};
use crate::analysis::accelerations::Accelerations;
use crate::error::SimError;
use crate::hybrid::event::{Event, Impact};
use crate::integrator::Integrator;
use crate::model::MatCQ;
use crate::model::state::State;
use crate::model::{EnergyBalance, LagrangeDirac};
use crate::output::solution::{Columns, Sampling, Solution};
use crate::shape::dims::{Storage, VecC, VecH, VecQ};

/// Records samples during an integration.
pub(crate) struct Recorder<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    table: Table<M>,
    names: Arc<[String]>,
    sampling: Sampling,
    next: usize,
    /// A time before which a step's end needs nothing recorded (see [`Recorder::quiet_until`]).
    quiet: f64,
    t0: f64,
    t_end: f64,
    /// The time of the last sample recorded.
    last: f64,
    /// The number of samples the sampling asks for (0 for every step: not known).
    expected: f64,
    buffer: State<M>,
    /// The events located, and the names of the event functions.
    events: Vec<Event>,
    event_names: Vec<String>,
    /// The impacts at unilateral constraints, and the constraints' names.
    impacts: Vec<Impact>,
    contact_names: Vec<String>,
}

/// The most values (samples times series) a solution records: 2^27, 1 GiB of `f64`.
const MAX_VALUES: f64 = (1u64 << 27) as f64;

impl<M: LagrangeDirac> Recorder<M>
where
    DefaultAllocator: Storage<M>,
{
    /// A recorder over `[t0, t_end]`, after checking the sampling against that span.
    pub fn new(model: &M, sampling: &Sampling, t0: f64, t_end: f64) -> Result<Self, SimError> {
        let (layout, names) = Columns::of(model);
        let expected = match sampling {
            Sampling::Every(dt) if dt.is_nan() || *dt <= 0.0 || dt.is_infinite() => {
                return Err(SimError::InvalidSampling {
                    reason: format!("the interval {dt} is not positive"),
                });
            }
            Sampling::Every(dt) => ((t_end - t0) / dt).floor() + 2.0,
            Sampling::Times(times) => {
                if times.windows(2).any(|w| w[0].partial_cmp(&w[1]) != Some(std::cmp::Ordering::Less)) {
                    return Err(SimError::InvalidSampling {
                        reason: "the sample times must increase".into(),
                    });
                }
                if times.iter().any(|t| t.is_nan() || *t < t0 || *t > t_end) {
                    return Err(SimError::InvalidSampling {
                        reason: format!("the sample times must lie in [{t0}, {t_end}]"),
                    });
                }
                times.len() as f64
            }
            Sampling::Steps => 0.0,
        };
        let values = expected * names.len() as f64;
        if values.is_nan() || values > MAX_VALUES {
            return Err(SimError::InvalidSampling {
                reason: format!(
                    "{sampling:?} over [{t0}, {t_end}] asks for {expected:e} samples of {} series, more than the \
                     {MAX_VALUES:e} values a solution holds: sample less often, or at chosen times",
                    names.len()
                ),
            });
        }
        let mut columns = Vec::with_capacity(layout.stored);
        for _ in 0..layout.stored {
            let mut column = Vec::new();
            column.try_reserve_exact(expected as usize).map_err(|_| SimError::InvalidSampling {
                reason: format!("no memory for {expected:e} samples of {} series", names.len()),
            })?;
            columns.push(column);
        }
        let (sizes, shape) = (model.sizes(), model.shape());
        let scratch = Scratch {
            a: M::Algebra::zeros_cq(&shape),
            slip: M::Algebra::zeros_cq(&shape),
            av: sizes.zeros_c::<M>(),
            phi: sizes.zeros_h::<M>(),
            forces: sizes.zeros_q::<M>(),
            outputs: vec![0.0; layout.outputs],
            inputs: vec![0.0; layout.inputs],
            recovered: vec![0.0; layout.recovered.len()],
            accelerations: sizes.zeros_q::<M>(),
            motion: (!layout.recovered.is_empty() && M::RECOVERED_READS_ACCELERATIONS).then(|| {
                Box::new(Motion {
                    solver: Accelerations::new(model),
                    lambda: sizes.zeros_c::<M>(),
                    prepared: false,
                })
            }),
        };
        let mut appended = Vec::new();
        appended.try_reserve_exact(expected as usize * layout.appended).map_err(|_| {
            SimError::InvalidSampling {
                reason: format!("no memory for {expected:e} samples of {} series", names.len()),
            }
        })?;
        let table =
            Table { layout, columns, appended, scratch, non_finite_output: None, not_recovered: None };
        let buffer = State::with_sizes(sizes);
        let mut recorder = Recorder {
            table,
            names,
            sampling: sampling.clone(),
            next: 0,
            quiet: f64::NEG_INFINITY,
            t0,
            t_end,
            last: f64::NAN,
            expected,
            buffer,
            events: Vec::new(),
            event_names: Vec::new(),
            impacts: Vec::new(),
            contact_names: Vec::new(),
        };
        recorder.quiet = recorder.quiet_until();
        Ok(recorder)
    }

    /// A time before which a step that ends there records nothing: before the next sample
    /// time (with room for the grid's tolerance) and before the end time. Steps in between
    /// samples then cost one comparison.
    fn quiet_until(&self) -> f64 {
        match &self.sampling {
            Sampling::Steps => f64::NEG_INFINITY,
            Sampling::Times(times) => times.get(self.next).copied().unwrap_or(f64::INFINITY),
            Sampling::Every(dt) => {
                // A sample is due at t when ts ≤ t + 1e-14 |t|; below this bound it is not.
                let ts = self.t0 + self.next as f64 * dt;
                (ts - 4e-14 * (ts.abs() + 1.0)).min(self.t_end)
            }
        }
    }

    /// Checks that `series` more series (sensitivities) at the same samples stay within what a
    /// solution may hold.
    fn check_extra_series(&self, series: usize) -> Result<(), SimError> {
        let values = self.expected * (self.names.len() + series) as f64;
        if values > MAX_VALUES {
            return Err(SimError::InvalidSampling {
                reason: format!(
                    "{:?} asks for {:e} samples of {} series with the sensitivities, more than the {MAX_VALUES:e} \
                     values a solution holds: sample less often, or at chosen times",
                    self.sampling,
                    self.expected,
                    self.names.len() + series
                ),
            });
        }
        Ok(())
    }

    /// Room for `series` more values (sensitivities) at each sample expected, after checking
    /// that they stay within what a solution may hold.
    pub fn extra_series(&self, series: usize) -> Result<Vec<f64>, SimError> {
        self.check_extra_series(series)?;
        let mut values = Vec::new();
        values.try_reserve_exact(self.expected as usize * series).map_err(|_| SimError::InvalidSampling {
            reason: format!("no memory for {:e} samples of {series} sensitivity series", self.expected),
        })?;
        Ok(values)
    }

    /// The number of samples recorded.
    pub fn len(&self) -> usize {
        self.table.columns[0].len()
    }

    /// The time of sample `k`.
    pub fn time(&self, k: usize) -> f64 {
        self.table.columns[0][k]
    }

    /// Records the initial state if the sampling asks for it.
    pub fn record_initial(&mut self, model: &M, t0: f64, state: &State<M>) {
        let wanted = match &self.sampling {
            Sampling::Steps | Sampling::Every(_) => true,
            Sampling::Times(times) => times.first() == Some(&t0),
        };
        if wanted {
            self.table.push(model, t0, state);
            self.last = t0;
            self.next = 1;
            self.quiet = self.quiet_until();
        }
    }

    /// Records the samples that fall in the step just taken, which ended at `t` in `state`;
    /// `interpolate(ts, out)` writes the state at an earlier time of the step.
    pub fn record_step(
        &mut self,
        model: &M,
        t: f64,
        state: &State<M>,
        interpolate: impl Fn(f64, &mut State<M>),
    ) {
        if t < self.quiet {
            return;
        }
        loop {
            let ts = match &self.sampling {
                Sampling::Steps => {
                    self.table.push(model, t, state);
                    self.last = t;
                    return;
                }
                Sampling::Every(dt) => self.t0 + self.next as f64 * dt,
                Sampling::Times(times) => match times.get(self.next) {
                    Some(&ts) => ts,
                    None => return,
                },
            };
            let due = match self.sampling {
                Sampling::Every(_) => ts <= t + 1e-14 * t.abs(),
                _ => ts <= t,
            };
            if !due {
                // A grid that misses the end time still ends with a sample there.
                let missed = match self.sampling {
                    Sampling::Every(dt) => t >= self.t_end && self.last < self.t_end - 1e-9 * dt,
                    _ => false,
                };
                if missed {
                    self.table.push(model, t, state);
                    self.last = t;
                }
                return;
            }
            if ts >= t {
                self.buffer.clone_from(state);
            } else {
                interpolate(ts, &mut self.buffer);
            }
            self.table.push(model, ts, &self.buffer);
            self.last = ts;
            self.next += 1;
            self.quiet = self.quiet_until();
        }
    }

    /// Names the unilateral constraints whose impacts the solution records.
    pub fn name_contacts(&mut self, names: &[String]) {
        self.contact_names = names.to_vec();
    }

    /// Records an impact.
    pub fn record_impact(&mut self, impact: Impact) {
        self.impacts.push(impact);
    }

    /// Names the event functions whose events the solution records.
    pub fn name_events(&mut self, names: &[String]) {
        self.event_names = names.to_vec();
    }

    /// Records an event, and the state at it unless the sampling is at chosen times (or is
    /// [`Sampling::Steps`], whose [`Recorder::record_step`] up to the event recorded it).
    pub fn record_event(&mut self, model: &M, event: Event, state: &State<M>) {
        self.events.push(event);
        if let Sampling::Every(_) = self.sampling {
            self.table.push(model, event.t, state);
            self.last = event.t;
        }
    }

    /// Records the state an event's action reset, unless the sampling is at chosen times.
    pub fn record_reset(&mut self, model: &M, t: f64, state: &State<M>) {
        if !matches!(self.sampling, Sampling::Times(_)) {
            self.table.push(model, t, state);
            self.last = t;
        }
    }

    /// The finished solution of `integrator`'s run, as [`Recorder::finish`]. Where a drive set
    /// the inputs within the steps, the model held at a sample the inputs of the last
    /// evaluation, not the sample's: each sample's inputs and outputs are read again after the
    /// drive sets the inputs at its time and state, and the step's end's inputs restored.
    pub fn finish_from<I: Integrator<M>>(
        mut self,
        integrator: &mut I,
    ) -> Result<Solution<M, I::Stats>, SimError> {
        if integrator.driven() {
            let end = integrator.state().clone();
            for k in 0..self.table.columns[0].len() {
                let t = self.table.columns[0][k];
                for (i, x) in self.buffer.components_mut().enumerate() {
                    *x = self.table.columns[self.table.layout.slot(i)][k];
                }
                integrator.set_inputs_at(t, &self.buffer);
                self.table.derive(integrator.model(), k, t, &self.buffer);
            }
            integrator.set_inputs_at(integrator.t(), &end);
        }
        self.finish(integrator.stats())
    }

    /// The finished solution, with the integrator's statistics; an error naming the first
    /// output or recovered series that was not finite, where it was not (and, for a recovered
    /// series, why its accelerations were not solved there).
    pub fn finish<S>(self, stats: S) -> Result<Solution<M, S>, SimError> {
        if let Some((t, k)) = self.table.non_finite_output {
            // The column is named `out(name)`.
            let column = &self.names[self.table.layout.output(k)];
            let name = column.strip_prefix("out(").and_then(|c| c.strip_suffix(')')).unwrap_or(column);
            let component = format!("the output `{name}`");
            return Err(SimError::NonFinite { t, component });
        }
        if let Some((t, j, known)) = self.table.not_recovered {
            let name = &self.names[self.table.layout.recovered[j]];
            if known {
                return Err(SimError::NonFinite { t, component: format!("the recovered series `{name}`") });
            }
            return Err(SimError::NotDetermined {
                t,
                cause: format!(
                    "the accelerations the recovered series `{name}` reads: the saddle-point system of the \
                     inertia and the constraint rows is singular there, or the model has velocities that only \
                     the forces fix and sizes known only when it runs (their accelerations are solved in models \
                     of fixed size only)"
                ),
            });
        }
        let solution = Solution::new(
            self.table.layout,
            self.names,
            (self.table.columns, self.table.appended),
            self.buffer.sizes(),
            stats,
        );
        Ok(solution.with_events(self.events, self.event_names).with_impacts(self.impacts, self.contact_names))
    }
}

/// The recorded columns, and the storage their derived quantities are computed in.
struct Table<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    layout: Columns,
    columns: Vec<Vec<f64>>,
    /// The series after the stored columns, sample by sample (see `Columns::stored`).
    appended: Vec<f64>,
    scratch: Scratch<M>,
    /// When and which output was first not finite.
    non_finite_output: Option<(f64, usize)>,
    /// When and which recovered series was first not finite, and whether the accelerations it
    /// reads were solved there.
    not_recovered: Option<(f64, usize, bool)>,
}

/// Storage for the derived quantities of a sample.
struct Scratch<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    a: MatCQ<M>,
    /// `B − A` of a model whose friction pushes with a contact force.
    slip: MatCQ<M>,
    av: VecC<M>,
    phi: VecH<M>,
    forces: VecQ<M>,
    outputs: Vec<f64>,
    inputs: Vec<f64>,
    /// The series the model recovers, and the accelerations they read (zero unless
    /// `motion` solves for them).
    recovered: Vec<f64>,
    accelerations: VecQ<M>,
    motion: Option<Box<Motion<M>>>,
}

/// The accelerations at a sample, for the series a reduced model recovers from the balances of
/// coordinates with inertia: the saddle-point solve Explicit steps with, on its own storage.
struct Motion<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    solver: Accelerations<M>,
    lambda: VecC<M>,
    /// Whether the velocities that only the forces fix were looked for (once, at the first
    /// sample: it allocates).
    prepared: bool,
}

impl<M: LagrangeDirac> Motion<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The accelerations at `(t, q, v)` into `out`; false where the system is singular there.
    fn at(&mut self, model: &M, t: f64, s: &State<M>, out: &mut VecQ<M>) -> bool {
        if !self.prepared {
            self.prepared = true;
            if self.solver.prepare(model, t, (&s.q, &s.v)).is_err() {
                self.solver.unprepare();
            }
        }
        self.solver.evaluate(model, t, (&s.q, &s.v), out, &mut self.lambda)
    }
}

impl<M: LagrangeDirac> Table<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Appends one sample of `model` at `t` in state `s`, with its derived quantities.
    fn push(&mut self, model: &M, t: f64, s: &State<M>) {
        let l = &self.layout;
        self.columns[0].push(t);
        for (i, x) in s.components().enumerate() {
            self.columns[l.slot(i)].push(*x);
        }
        for column in &mut self.columns[l.derived(0)..] {
            column.push(0.0);
        }
        self.appended.extend(std::iter::repeat_n(0.0, l.appended));
        self.derive(model, self.columns[0].len() - 1, t, s);
    }

    /// Computes the derived quantities, port efforts, outputs and inputs of sample `k`, at `t`
    /// in state `s`, with the model's inputs as they are now.
    fn derive(&mut self, model: &M, k: usize, t: f64, s: &State<M>) {
        let l = &self.layout;
        let w = &mut self.scratch;
        let energy = model.energy(t, &s.q, &s.v, &s.p);
        let power = model.power(t, &s.q, &s.v);
        model.constraint_matrix(t, &s.q, &mut w.a);
        model.constraint_rate(t, &s.q, &mut w.av);
        let mut cpower = -w.av.dot(&s.lambda);
        M::Algebra::cq_mul(&w.a, 1.0, s.v.as_slice(), w.av.as_mut_slice());
        let av = amax(w.av.as_slice());
        if M::NON_ASSOCIATED {
            // The power of the friction the contact forces drive, `⟨(B − A)ᵀλ, v⟩`, is the
            // constraints' too: the balance's constraint forces are `Bᵀλ`.
            w.av.fill(0.0);
            model.slip_rows(t, &s.q, &s.v, &mut w.slip);
            M::Algebra::cq_mul(&w.slip, 1.0, s.v.as_slice(), w.av.as_mut_slice());
            cpower += w.av.dot(&s.lambda);
        }
        model.holonomic(t, &s.q, &mut w.phi);
        let phi = amax(w.phi.as_slice());
        model.interconnection_forces(t, &s.q, &s.lambda, &mut w.forces);
        let ipower = w.forces.dot(&s.v);
        model.outputs(t, &s.q, &s.v, &s.lambda, &mut w.outputs);
        let dissipated: f64 = l.dissipation.iter().map(|&k| w.outputs[k]).sum();
        let sources = power + dissipated;
        for (j, x) in [energy, sources, dissipated, av, phi, ipower, cpower].into_iter().enumerate() {
            self.columns[l.derived(j)][k] = x;
        }
        for (j, &i) in l.ports.iter().enumerate() {
            self.columns[l.port(j)][k] = w.forces[i];
        }
        for (j, &y) in w.outputs.iter().enumerate() {
            self.columns[l.output(j)][k] = y;
            if !y.is_finite() && self.non_finite_output.is_none_or(|(first, _)| t < first) {
                self.non_finite_output = Some((t, j));
            }
        }
        model.input_values(&mut w.inputs);
        for (j, &u) in w.inputs.iter().enumerate() {
            self.columns[l.input(j)][k] = u;
        }
        if !l.recovered.is_empty() {
            let known = w.motion.as_mut().is_none_or(|m| m.at(model, t, s, &mut w.accelerations));
            if known {
                model.recovered(t, &s.q, &s.v, &w.accelerations, &s.lambda, &mut w.recovered);
            } else {
                w.recovered.fill(f64::NAN);
            }
            for (j, (&column, &x)) in l.recovered.iter().zip(&w.recovered).enumerate() {
                match column.checked_sub(l.stored) {
                    Some(i) => self.appended[k * l.appended + i] = x,
                    None => self.columns[column][k] = x,
                }
                if !x.is_finite() && self.not_recovered.is_none_or(|(first, ..)| t < first) {
                    self.not_recovered = Some((t, j, known));
                }
            }
        }
    }
}
