//! Simulation results: a table of named series (state, energy, power, constraint residuals,
//! interconnection forces) sampled at chosen times, with the solver's statistics and CSV export.

use std::io::{self, Write};
use std::marker::PhantomData;
use std::ops::ControlFlow;

use nalgebra::DefaultAllocator;

use crate::dims::{MatCQ, Storage, VecH, VecQ, VecY};
use crate::error::SimError;
use crate::keys::{Constraint, Coordinate};
use crate::model::LagrangeDirac;
use crate::radau::Stats;
use crate::state::State;

/// When a simulation records a sample.
#[derive(Clone, Debug, PartialEq)]
pub enum Sampling {
    /// At the start and after every accepted step.
    Steps,
    /// Every `dt` from the start, and at the end (dense output between steps).
    Every(f64),
    /// At these increasing times within the time span (dense output between steps).
    Times(Vec<f64>),
}

/// What a recorder needs from an integrator after a step.
pub trait Stepper<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// The time reached.
    fn t(&self) -> f64;
    /// The time the last step started at.
    fn t_previous(&self) -> f64;
    /// The state reached.
    fn y(&self) -> &VecY<M>;
    /// The state at `t` within the last step.
    fn interpolate(&self, t: f64, out: &mut VecY<M>);
}

/// An integrator that [`integrate`] can drive.
pub trait Integrator<M: LagrangeDirac>: Stepper<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The model integrated.
    fn model(&self) -> &M;
    /// Prepares to integrate from `state` at `t0` to `t_end`.
    fn begin(&mut self, t0: f64, state: &State<M>, t_end: f64) -> Result<(), SimError>;
    /// Takes one step.
    fn advance(&mut self) -> Result<(), SimError>;
    /// Whether the end time has been reached.
    fn done(&self) -> bool;
    /// The work done so far.
    fn statistics(&self) -> Stats;
}

/// Integrates from `state` at `t0` to `t_end`, recording samples as `sampling` says and calling
/// `observer` with the time and the state after every step (`ControlFlow::Break(())` stops).
pub fn integrate<M: LagrangeDirac, I: Integrator<M>>(
    integrator: &mut I,
    t0: f64,
    state: &State<M>,
    t_end: f64,
    sampling: &Sampling,
    mut observer: impl FnMut(f64, &VecY<M>) -> ControlFlow<()>,
) -> Result<Solution<M>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let mut recorder = Recorder::new(integrator.model(), sampling, t0, t_end)?;
    integrator.begin(t0, state, t_end)?;
    recorder.record_initial(integrator.model(), t0, integrator.y());
    while !integrator.done() {
        integrator.advance()?;
        recorder.record_step(integrator.model(), integrator);
        if observer(integrator.t(), integrator.y()).is_break() {
            break;
        }
    }
    Ok(recorder.finish(integrator.statistics()))
}

/// The columns of a solution, by name.
struct Layout {
    n: usize,
    m: usize,
    ports: Vec<usize>,
}

impl Layout {
    const DERIVED: [&'static str; 5] =
        ["energy", "power", "constraint_residual", "holonomic_residual", "interconnection_power"];

    fn q(&self) -> usize {
        1
    }
    fn v(&self) -> usize {
        1 + self.n
    }
    fn p(&self) -> usize {
        1 + 2 * self.n
    }
    fn lambda(&self) -> usize {
        1 + 3 * self.n
    }
    fn derived(&self) -> usize {
        1 + 3 * self.n + self.m
    }
    fn forces(&self) -> usize {
        self.derived() + Self::DERIVED.len()
    }
}

/// Records samples during an integration.
pub struct Recorder<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    layout: Layout,
    names: Vec<String>,
    columns: Vec<Vec<f64>>,
    sampling: Sampling,
    next: usize,
    t0: f64,
    buffer: VecY<M>,
}

impl<M: LagrangeDirac> Recorder<M>
where
    DefaultAllocator: Storage<M>,
{
    /// A recorder for `model` over `[t0, t_end]`.
    pub fn new(_model: &M, sampling: &Sampling, t0: f64, t_end: f64) -> Result<Self, SimError> {
        match sampling {
            Sampling::Every(dt) if dt.is_nan() || *dt <= 0.0 || dt.is_infinite() => {
                return Err(SimError::InvalidTimeSpan {
                    reason: format!("sampling interval {dt} is not positive"),
                });
            }
            Sampling::Times(times) => {
                if times.windows(2).any(|w| w[0].partial_cmp(&w[1]) != Some(std::cmp::Ordering::Less)) {
                    return Err(SimError::InvalidTimeSpan { reason: "sample times must increase".into() });
                }
                if times.iter().any(|t| t.is_nan() || *t < t0 || *t > t_end) {
                    return Err(SimError::InvalidTimeSpan {
                        reason: format!("sample times must lie in [{t0}, {t_end}]"),
                    });
                }
            }
            _ => {}
        }
        let layout = Layout { n: M::NQ, m: M::NC, ports: M::NAMES.port_indices() };
        let coordinates = M::coordinate_names();
        let mut names = vec!["t".to_owned()];
        names.extend(coordinates.iter().cloned());
        names.extend(M::velocity_names());
        names.extend(coordinates.iter().map(|c| format!("p({c})")));
        names.extend(M::constraint_names().iter().map(|c| format!("lambda({c})")));
        names.extend(Layout::DERIVED.iter().map(|s| (*s).to_owned()));
        names.extend(layout.ports.iter().map(|&i| format!("f({})", coordinates[i])));
        let columns = vec![Vec::new(); names.len()];
        Ok(Recorder {
            layout,
            names,
            columns,
            sampling: sampling.clone(),
            next: 0,
            t0,
            buffer: VecY::<M>::zeros(),
        })
    }

    fn push(&mut self, model: &M, t: f64, y: &VecY<M>) {
        let l = &self.layout;
        let (n, m) = (l.n, l.m);
        self.columns[0].push(t);
        for (i, x) in y.iter().enumerate() {
            self.columns[1 + i].push(*x);
        }
        let s = State::<M>::from_y(y);
        let energy = model.energy(t, &s.q, &s.v, &s.p);
        let power = model.power(t, &s.q, &s.v);
        let mut a = MatCQ::<M>::zeros();
        model.constraint_matrix(&s.q, &mut a);
        let av = if m == 0 { 0.0 } else { (a * &s.v).amax() };
        let mut phi = VecH::<M>::zeros();
        model.holonomic(&s.q, &mut phi);
        let phi = if M::NH == 0 { 0.0 } else { phi.amax() };
        let mut forces = VecQ::<M>::zeros();
        model.interconnection_forces(&s.q, &s.lambda, &mut forces);
        let ipower = forces.dot(&s.v);
        let d = l.derived();
        for (k, x) in [energy, power, av, phi, ipower].into_iter().enumerate() {
            self.columns[d + k].push(x);
        }
        let f = l.forces();
        for (k, &i) in l.ports.iter().enumerate() {
            self.columns[f + k].push(forces[i]);
        }
        debug_assert_eq!(1 + 3 * n + m, d);
    }

    /// Records the initial state if the sampling asks for it.
    pub fn record_initial(&mut self, model: &M, t0: f64, y: &VecY<M>) {
        let wanted = match &self.sampling {
            Sampling::Steps | Sampling::Every(_) => true,
            Sampling::Times(times) => times.first() == Some(&t0),
        };
        if wanted {
            self.push(model, t0, y);
            self.next = 1;
        }
    }

    /// Records the samples that fall in the step just taken.
    pub fn record_step(&mut self, model: &M, stepper: &impl Stepper<M>) {
        let t = stepper.t();
        match self.sampling.clone() {
            Sampling::Steps => self.push(model, t, stepper.y()),
            Sampling::Every(dt) => loop {
                let ts = self.t0 + self.next as f64 * dt;
                if ts > t * (1.0 + 1e-14) {
                    break;
                }
                self.sample(model, stepper, ts);
            },
            Sampling::Times(times) => {
                while self.next < times.len() && times[self.next] <= t {
                    self.sample(model, stepper, times[self.next]);
                }
            }
        }
    }

    fn sample(&mut self, model: &M, stepper: &impl Stepper<M>, ts: f64) {
        let mut y = std::mem::replace(&mut self.buffer, VecY::<M>::zeros());
        if ts >= stepper.t() {
            y.copy_from(stepper.y());
        } else {
            stepper.interpolate(ts, &mut y);
        }
        self.push(model, ts, &y);
        self.buffer = y;
        self.next += 1;
    }

    /// The finished solution.
    pub fn finish(self, stats: Stats) -> Solution<M> {
        Solution { layout: self.layout, names: self.names, columns: self.columns, stats, model: PhantomData }
    }
}

/// The result of a simulation: named series over the sample times, and solver statistics.
pub struct Solution<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    layout: Layout,
    names: Vec<String>,
    columns: Vec<Vec<f64>>,
    /// The work the integrator did.
    pub stats: Stats,
    model: PhantomData<fn() -> M>,
}

impl<M: LagrangeDirac> Solution<M>
where
    DefaultAllocator: Storage<M>,
{
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
        &self.columns[self.layout.q() + c.index()]
    }

    /// The velocity of coordinate `c`.
    pub fn v(&self, c: Coordinate<M>) -> &[f64] {
        &self.columns[self.layout.v() + c.index()]
    }

    /// The momentum conjugate to coordinate `c`.
    pub fn p(&self, c: Coordinate<M>) -> &[f64] {
        &self.columns[self.layout.p() + c.index()]
    }

    /// The multiplier of constraint `k`.
    pub fn lambda(&self, k: Constraint<M>) -> &[f64] {
        &self.columns[self.layout.lambda() + k.index()]
    }

    /// The generalised energy `E = ⟨p, v⟩ − L`.
    pub fn energy(&self) -> &[f64] {
        &self.columns[self.layout.derived()]
    }

    /// The power of the external forces `⟨F, v⟩`.
    pub fn power(&self) -> &[f64] {
        &self.columns[self.layout.derived() + 1]
    }

    /// `‖A(q) v‖∞`.
    pub fn constraint_residual(&self) -> &[f64] {
        &self.columns[self.layout.derived() + 2]
    }

    /// `‖φ(q)‖∞`.
    pub fn holonomic_residual(&self) -> &[f64] {
        &self.columns[self.layout.derived() + 3]
    }

    /// The power of the interconnection forces, zero for a lossless interconnection.
    pub fn interconnection_power(&self) -> &[f64] {
        &self.columns[self.layout.derived() + 4]
    }

    /// The interconnection force (effort) at port `c`, if `c` is a port.
    pub fn interconnection_force(&self, c: Coordinate<M>) -> Option<&[f64]> {
        let k = self.layout.ports.iter().position(|&i| i == c.index())?;
        Some(&self.columns[self.layout.forces() + k])
    }

    /// The column names, `t` first.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The column with this name.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        let i = self.names.iter().position(|n| n == name)?;
        Some(&self.columns[i])
    }

    /// Sample `i` as a state, if there is such a sample.
    pub fn state(&self, i: usize) -> Option<State<M>> {
        if i >= self.len() {
            return None;
        }
        let y = VecY::<M>::from_fn(|k, _| self.columns[1 + k][i]);
        Some(State::from_y(&y))
    }

    /// Writes the solution as CSV: a header of names, then one row per sample.
    pub fn write_csv(&self, mut out: impl Write) -> io::Result<()> {
        writeln!(out, "{}", self.names.join(","))?;
        for i in 0..self.len() {
            let row: Vec<String> = self.columns.iter().map(|c| format!("{:e}", c[i])).collect();
            writeln!(out, "{}", row.join(","))?;
        }
        Ok(())
    }
}
