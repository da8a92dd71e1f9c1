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
    t_end: f64,
    /// The time of the last sample recorded.
    last: f64,
    buffer: State<M>,
}

/// The most values (samples times series) a solution records: 2^27, 1 GiB of `f64`.
const MAX_VALUES: f64 = (1u64 << 27) as f64;

impl<M: LagrangeDirac> Recorder<M>
where
    DefaultAllocator: Storage<M>,
{
    /// A recorder over `[t0, t_end]`, after checking the sampling against that span.
    pub fn new(sampling: &Sampling, t0: f64, t_end: f64) -> Result<Self, SimError> {
        let (layout, names) = Columns::of::<M>();
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
        let mut columns = Vec::new();
        for _ in 0..names.len() {
            let mut column = Vec::new();
            column.try_reserve_exact(expected as usize).map_err(|_| SimError::InvalidSampling {
                reason: format!("no memory for {expected:e} samples of {} series", names.len()),
            })?;
            columns.push(column);
        }
        let table = Table { layout, columns };
        let buffer = State::zeros();
        Ok(Recorder { table, names, sampling: sampling.clone(), next: 0, t0, t_end, last: f64::NAN, buffer })
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
