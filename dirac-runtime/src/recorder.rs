//! Recording a solution while an integrator runs: the samples the [`Sampling`] asks for, each
//! with the derived series (energy, power, constraint residuals, port efforts).

use nalgebra::DefaultAllocator;

use crate::dims::{MatCQ, Storage, VecH, VecQ};
use crate::error::SimError;
use crate::model::LagrangeDirac;
use crate::solution::{Columns, Sampling, Solution};
use crate::state::State;

/// Records samples during an integration.
pub(crate) struct Recorder<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    table: Table,
    names: Vec<String>,
    sampling: Sampling,
    next: usize,
    t0: f64,
    buffer: State<M>,
}

impl<M: LagrangeDirac> Recorder<M>
where
    DefaultAllocator: Storage<M>,
{
    /// A recorder over `[t0, t_end]`, after checking the sampling against that span.
    pub fn new(sampling: &Sampling, t0: f64, t_end: f64) -> Result<Self, SimError> {
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
        let (layout, names) = Columns::of::<M>();
        let table = Table { layout, columns: vec![Vec::new(); names.len()] };
        Ok(Recorder { table, names, sampling: sampling.clone(), next: 0, t0, buffer: State::zeros() })
    }

    /// Records the initial state if the sampling asks for it.
    pub fn record_initial(&mut self, model: &M, t0: f64, state: &State<M>) {
        let wanted = match &self.sampling {
            Sampling::Steps | Sampling::Every(_) => true,
            Sampling::Times(times) => times.first() == Some(&t0),
        };
        if wanted {
            self.table.push(model, t0, state);
            self.next = 1;
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
        loop {
            let ts = match &self.sampling {
                Sampling::Steps => {
                    self.table.push(model, t, state);
                    return;
                }
                Sampling::Every(dt) => self.t0 + self.next as f64 * dt,
                Sampling::Times(times) => match times.get(self.next) {
                    Some(&ts) => ts,
                    None => return,
                },
            };
            let due = match self.sampling {
                Sampling::Every(_) => ts <= t * (1.0 + 1e-14),
                _ => ts <= t,
            };
            if !due {
                return;
            }
            if ts >= t {
                self.buffer.clone_from(state);
            } else {
                interpolate(ts, &mut self.buffer);
            }
            self.table.push(model, ts, &self.buffer);
            self.next += 1;
        }
    }

    /// The finished solution, with the integrator's statistics.
    pub fn finish<S>(self, stats: S) -> Solution<M, S> {
        Solution::new(self.table.layout, self.names, self.table.columns, stats)
    }
}

/// The recorded columns.
struct Table {
    layout: Columns,
    columns: Vec<Vec<f64>>,
}

impl Table {
    /// Appends one sample of `model` at `t` in state `s`, with its derived quantities.
    fn push<M: LagrangeDirac>(&mut self, model: &M, t: f64, s: &State<M>)
    where
        DefaultAllocator: Storage<M>,
    {
        let l = &self.layout;
        self.columns[0].push(t);
        for (i, x) in s.components().enumerate() {
            self.columns[l.slot(i)].push(*x);
        }
        let energy = model.energy(t, &s.q, &s.v, &s.p);
        let power = model.power(t, &s.q, &s.v);
        let mut a = MatCQ::<M>::zeros();
        model.constraint_matrix(&s.q, &mut a);
        let av = if M::NC == 0 { 0.0 } else { (a * &s.v).amax() };
        let mut phi = VecH::<M>::zeros();
        model.holonomic(&s.q, &mut phi);
        let phi = if M::NH == 0 { 0.0 } else { phi.amax() };
        let mut forces = VecQ::<M>::zeros();
        model.interconnection_forces(&s.q, &s.lambda, &mut forces);
        let ipower = forces.dot(&s.v);
        for (k, x) in [energy, power, av, phi, ipower].into_iter().enumerate() {
            self.columns[l.derived(k)].push(x);
        }
        for (k, &i) in l.ports.iter().enumerate() {
            self.columns[l.port(k)].push(forces[i]);
        }
    }
}
