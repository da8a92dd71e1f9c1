//! Checkpoints within a memory budget: the starts of some steps and the size of every step,
//! from which the sweep solves the steps between two checkpoints again before it goes back
//! over them.
//!
//! Half the budget holds the run's checkpoints: one at every step's start until it is full,
//! then every second one, every fourth, and so on. The other half is the sweep's: a quarter
//! holds whole steps (start and stages) and a quarter the checkpoints of a segment too long
//! for them, one level of segments inside the other (a segment's checkpoints, then each of
//! its pieces' from the last), so that any run fits and every level costs one more solve of
//! it. The run is solved with [`RadauOptions::exact_stages`]: a step solved again from its
//! start and size then has the same stages to round-off, and the gradient is the discrete
//! solution's.

use nalgebra::{DefaultAllocator, Dim};

use super::{Step, Sweep};
use crate::error::SimError;
use crate::methods::radau::{Objective, Radau, RadauOptions};
use crate::model::{LagrangeDirac, Parameters};
use crate::shape::dims::{Sizes, Storage, VecY};

/// A step's start kept: the step's index, its time and the state.
struct Mark<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    index: usize,
    t: f64,
    y: VecY<M>,
}

impl<M: LagrangeDirac> Mark<M>
where
    DefaultAllocator: Storage<M>,
{
    fn zeros(sizes: Sizes) -> Self {
        Mark { index: 0, t: 0.0, y: sizes.zeros_y::<M>() }
    }

    /// The bytes one mark holds, inline and on the heap.
    fn bytes(sizes: Sizes) -> usize {
        let heap = if <M::Ny as Dim>::try_to_usize().is_none() { 8 * sizes.ny() } else { 0 };
        std::mem::size_of::<Self>() + heap
    }
}

/// The checkpoints of a run recorded within a budget ([`Radau::record_within`]).
pub(in crate::methods::radau) struct Checkpoints<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    options: RadauOptions,
    budget: usize,
    sizes: Sizes,
    /// Every step's size, in order.
    steps: Vec<f64>,
    /// The kept starts, in order of their steps: the first `used` of these slots.
    marks: Vec<Mark<M>>,
    used: usize,
    /// The most marks half the budget holds.
    capacity: usize,
    /// A start is kept every `interval` steps.
    interval: usize,
}

impl<M: LagrangeDirac> Checkpoints<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Checkpoints of a model of `sizes` within `budget` bytes, for a run with `options`.
    pub fn new(sizes: Sizes, options: RadauOptions, budget: usize) -> Result<Self, SimError> {
        let state = Mark::<M>::bytes(sizes);
        if budget < 16 * state {
            return Err(SimError::InvalidOption {
                what: "budget",
                reason: format!(
                    "{budget} bytes hold fewer than sixteen of this model's states of {state} bytes: \
                     at least {} bytes",
                    16 * state
                ),
            });
        }
        let options = RadauOptions { exact_stages: true, ..options };
        let capacity = budget / 2 / state;
        Ok(Checkpoints {
            options,
            budget,
            sizes,
            steps: Vec::new(),
            marks: Vec::new(),
            used: 0,
            capacity,
            interval: 1,
        })
    }

    /// The number of steps recorded.
    pub fn steps(&self) -> usize {
        self.steps.len()
    }

    /// The bytes held: the marks' slots and the steps' sizes.
    pub fn bytes(&self) -> usize {
        self.marks.len() * Mark::<M>::bytes(self.sizes) + self.steps.capacity() * std::mem::size_of::<f64>()
    }

    /// Offers the start `y` at `t` of the next step: kept if it falls on the interval, the
    /// kept ones thinned to every second one first when their half of the budget is full.
    pub fn mark(&mut self, t: f64, y: &VecY<M>) {
        let index = self.steps.len();
        if !index.is_multiple_of(self.interval) {
            return;
        }
        if self.used == self.capacity {
            self.interval *= 2;
            let mut kept = 0;
            for i in 0..self.used {
                if self.marks[i].index.is_multiple_of(self.interval) {
                    self.marks.swap(kept, i);
                    kept += 1;
                }
            }
            self.used = kept;
            if !index.is_multiple_of(self.interval) {
                return;
            }
        }
        if self.used == self.marks.len() {
            self.marks.push(Mark::zeros(self.sizes));
        }
        let mark = &mut self.marks[self.used];
        (mark.index, mark.t) = (index, t);
        mark.y.copy_from(y);
        self.used += 1;
    }

    /// Records the size of the step just taken.
    pub fn push(&mut self, h: f64) {
        self.steps.push(h);
    }

    /// Carries `bar` from the run's end to its start through every step, solving the steps
    /// again between checkpoints; returns the running cost's quadrature.
    pub fn sweep(
        &self,
        model: &M,
        sweep: &mut Sweep<M>,
        objective: &Objective<'_, M>,
        bar: &mut VecY<M>,
    ) -> Result<f64, SimError>
    where
        M: Parameters,
    {
        // No more room than the run needs: a budget far above it allocates only that.
        let state = Mark::<M>::bytes(self.sizes);
        let steps = self.steps.len().max(1);
        let whole = (self.budget / 4 / (4 * state)).clamp(1, steps);
        let starts = (self.budget / 4 / state).min(steps);
        let mut pool: Vec<Mark<M>> = (0..starts).map(|_| Mark::zeros(self.sizes)).collect();
        let mut replay = Replay {
            radau: Radau::new(model, self.options)?,
            steps: &self.steps,
            whole: (0..whole).map(|_| Step::zeros(self.sizes)).collect(),
            cursor: self.sizes.zeros_y::<M>(),
            objective,
        };
        let mut value = 0.0;
        let marks = &self.marks[..self.used];
        for (k, mark) in marks.iter().enumerate().rev() {
            let end = marks.get(k + 1).map_or(self.steps.len(), |next| next.index);
            value += replay.segment(model, sweep, bar, mark, end, &mut pool)?;
        }
        Ok(value)
    }
}

/// Solves recorded steps again for the sweep.
struct Replay<'r, 'm, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    radau: Radau<'m, M>,
    steps: &'r [f64],
    /// Room for this many whole steps.
    whole: Vec<Step<M>>,
    cursor: VecY<M>,
    objective: &'r Objective<'r, M>,
}

impl<M: LagrangeDirac + Parameters> Replay<'_, '_, M>
where
    DefaultAllocator: Storage<M>,
{
    /// Sweeps back over the steps from `from` to (not including) `end`, with `pool` for the
    /// checkpoints of the levels below.
    fn segment(
        &mut self,
        model: &M,
        sweep: &mut Sweep<M>,
        bar: &mut VecY<M>,
        from: &Mark<M>,
        end: usize,
        pool: &mut [Mark<M>],
    ) -> Result<f64, SimError> {
        let len = end - from.index;
        if len <= self.whole.len() {
            self.cursor.copy_from(&from.y);
            let mut t = from.t;
            for i in 0..len {
                let h = self.steps[from.index + i];
                self.radau.replay(t, &self.cursor, h, i > 0)?;
                let step = &mut self.whole[i];
                (step.t, step.h) = (t, h);
                step.y.copy_from(&self.cursor);
                for (z, stage) in step.z.iter_mut().zip(&self.radau.stages.z) {
                    z.copy_from(stage);
                }
                self.cursor += &self.radau.stages.z[2];
                t += h;
            }
            let mut value = 0.0;
            for step in self.whole[..len].iter().rev() {
                value += sweep.step(model, step, self.objective, bar)?;
            }
            return Ok(value);
        }
        // As many pieces as leave room for the pieces' own: `count` pieces take `count − 1`
        // starts (the first is `from`), and with `r` starts left a piece of up to `2ʳ` times
        // the whole steps' room can be halved down to them.
        let whole = self.whole.len();
        let reach = |left: usize| whole.saturating_mul(1usize.checked_shl(left as u32).unwrap_or(usize::MAX));
        let Some(count) = (2..=pool.len() + 1).rev().find(|&c| len.div_ceil(c) <= reach(pool.len() + 1 - c))
        else {
            return Err(SimError::InvalidOption {
                what: "budget",
                reason: format!(
                    "too small for this run of {} steps: a stretch of {len} steps between its \
                     checkpoints needs more room than the budget leaves; give it more bytes",
                    self.steps.len()
                ),
            });
        };
        let piece = len.div_ceil(count);
        let count = len.div_ceil(piece);
        let (mine, rest) = pool.split_at_mut(count - 1);
        self.cursor.copy_from(&from.y);
        let mut t = from.t;
        for i in 0..(count - 1) * piece {
            let h = self.steps[from.index + i];
            self.radau.replay(t, &self.cursor, h, i > 0)?;
            self.cursor += &self.radau.stages.z[2];
            t += h;
            if (i + 1).is_multiple_of(piece) {
                let mark = &mut mine[i / piece];
                (mark.index, mark.t) = (from.index + i + 1, t);
                mark.y.copy_from(&self.cursor);
            }
        }
        let mut value = 0.0;
        for k in (0..count).rev() {
            let end = if k + 1 < count { mine[k].index } else { end };
            let start = if k == 0 { from } else { &mine[k - 1] };
            value += self.segment(model, sweep, bar, start, end, rest)?;
        }
        Ok(value)
    }
}
