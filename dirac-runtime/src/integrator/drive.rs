//! What every integrator keeps to set its model's inputs within the steps: the user's drive,
//! and the stops, the times where the inputs jump or bend (a table's samples), at which a step
//! ends and the integration restarts, so that no step straddles them.

use nalgebra::DefaultAllocator;

use crate::error::SimError;
use crate::integrator::held::Held;
use crate::model::LagrangeDirac;
use crate::model::state::State;
use crate::shape::dims::{Storage, VecC, VecQ};

/// Sets a model's inputs from time and state before each evaluation. Borrowed, not boxed: an
/// integrator holds nothing that needs dropping at the end of its borrows.
pub(crate) type DriveFn<'m, M> = &'m mut dyn FnMut(f64, &State<M>, &mut M);

/// The times where the inputs jump or bend, sorted, and the end the integration is heading
/// for. The integrator's own end is the end of the stretch it is in: the first stop after the
/// time reached, or the goal. Read without allocating.
#[derive(Clone, Debug, Default)]
pub(crate) struct Stops {
    times: Vec<f64>,
    goal: f64,
    /// The start of the stretch the integration is in.
    start: f64,
    /// The crossing of a timed switch the next step is to end at, if any
    /// ([`Integrator::end_step_at`](crate::integrator::Integrator::end_step_at)).
    timed: Option<f64>,
}

impl Stops {
    /// Stops at `times`: each finite; kept sorted, without repeats. Allocates (not within a
    /// step).
    pub fn set(&mut self, times: &[f64]) -> Result<(), SimError> {
        if let Some(t) = times.iter().find(|t| !t.is_finite()) {
            return Err(SimError::InvalidOption {
                what: "stop_at",
                reason: format!("the time {t} is not finite"),
            });
        }
        self.times = times.to_vec();
        self.times.sort_by(f64::total_cmp);
        self.times.dedup();
        Ok(())
    }

    /// The end of the stretch from `t` towards `goal` (which is kept as the goal): the first
    /// stop beyond `t` and before `goal`, or `goal`. A stop within a few round-offs of `t`
    /// counts as passed, so that no stretch is too short to step.
    pub fn stretch(&mut self, t: f64, goal: f64) -> f64 {
        self.goal = goal;
        self.start = t;
        let passed = t + 64.0 * f64::EPSILON * t.abs().max(1.0);
        let k = self.times.partition_point(|&s| s <= passed);
        let stop = match self.times.get(k) {
            Some(&s) if s < goal => s,
            _ => goal,
        };
        // A timed switch's crossing is exact: it only has to lie ahead.
        match self.timed {
            Some(s) if s > t && s < stop => s,
            _ => stop,
        }
    }

    /// Ends the stretch at `t` too, the crossing of a timed switch (`None`: no such end).
    pub fn set_timed(&mut self, t: Option<f64>) {
        self.timed = t;
    }

    /// The end the integration is heading for.
    #[inline]
    pub fn goal(&self) -> f64 {
        self.goal
    }

    /// Whether the stretch that ends at `end` ended at a stop short of the goal: the
    /// integrator, at `end`, restarts there towards the goal.
    #[inline]
    pub fn due(&self, t: f64, end: f64) -> bool {
        t >= end && end < self.goal
    }

    /// The time at which inputs (and the model itself) are read for an evaluation at `t` in the
    /// stretch that ends at `end`: `t` itself, except at the end of a stretch when there are
    /// stops, where they are read just before it, so that a jump there (a held sample, a timed
    /// switch) reaches no stage of the step that ends at it.
    #[inline]
    pub fn read_at(&self, t: f64, end: f64) -> f64 {
        if (!self.times.is_empty() || self.timed.is_some()) && t >= end { end.next_down() } else { t }
    }
}

/// A drive of the inputs with the state it reads, for the methods that evaluate their model
/// at positions and velocities (Explicit, Variational): the drive reads the state's positions
/// and velocities, its momenta and multipliers those of the last evaluation.
pub(crate) struct Driver<'m, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    drive: Option<(DriveFn<'m, M>, State<M>)>,
    pub stops: Stops,
    /// The prescribed parts of the constraints at a moved time, for their inputs' rate.
    moved: Option<VecC<M>>,
}

impl<M: LagrangeDirac> Default for Driver<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    fn default() -> Self {
        Driver { drive: None, stops: Stops::default(), moved: None }
    }
}

impl<'m, M: LagrangeDirac> Driver<'m, M>
where
    DefaultAllocator: Storage<M>,
{
    /// Sets the inputs before every evaluation from now on, if the model is held exclusively.
    pub fn set(&mut self, model: &mut Held<'_, M>, drive: DriveFn<'m, M>, t: f64) -> Result<(), SimError> {
        if model.get_mut().is_none() {
            return Err(SimError::SharedModel { t });
        }
        self.drive = Some((drive, State::with_sizes(model.sizes())));
        self.moved = Some(model.sizes().zeros_c::<M>());
        Ok(())
    }

    /// The rate at which the drive moves the constraints' prescribed part at `t`, positions
    /// `q` and velocities `v`, `∂b/∂u · u̇`, into `out`: by a difference of the drive's inputs
    /// over a short time about `t`, kept within the stretch (which ends at `end`) so that a
    /// stop's jump or bend is not differenced across; exact for inputs linear in time (a
    /// table read with linear interpolation). Leaves the inputs set at `t`. Zero unless the
    /// model has constraints that prescribe a motion and a drive.
    pub fn input_rate(
        &mut self,
        model: &mut Held<'_, M>,
        (t, end): (f64, f64),
        (q, v): (&VecQ<M>, &VecQ<M>),
        out: &mut VecC<M>,
    ) {
        if !M::PRESCRIBED || self.drive.is_none() || model.get_mut().is_none() {
            return;
        }
        // Central differences balance truncation (δ²) and round-off (ε/δ) at δ ≈ ε^⅓.
        let delta = f64::EPSILON.cbrt() * t.abs().max((end - self.stops.start).abs()).max(1.0);
        let (lo, hi) = ((t - delta).max(self.stops.start), (t + delta).min(end));
        if hi <= lo {
            out.fill(0.0);
            return;
        }
        self.apply(model, (hi, end), q, v);
        model.get().constraint_rate(t, q, out);
        self.apply(model, (lo, end), q, v);
        let Some(moved) = &mut self.moved else { return };
        model.get().constraint_rate(t, q, moved);
        let span = hi - lo;
        out.zip_apply(moved, |rate, before| *rate = (*rate - before) / span);
        self.apply(model, (t, end), q, v);
    }

    /// Whether a drive sets the model's inputs.
    #[inline]
    pub fn driven(&self) -> bool {
        self.drive.is_some()
    }

    /// Sets the model's inputs at time `t` in the stretch that ends at `end`, for positions
    /// `q` and velocities `v`, if a drive does.
    #[inline]
    pub fn apply(&mut self, model: &mut Held<'_, M>, (t, end): (f64, f64), q: &VecQ<M>, v: &VecQ<M>) {
        if let Some((drive, state)) = &mut self.drive
            && let Some(model) = model.get_mut()
        {
            state.q.copy_from(q);
            state.v.copy_from(v);
            drive(self.stops.read_at(t, end), state, model);
        }
    }

    /// Sets the model's inputs at time `t` in the stretch that ends at `end`, for `state`, if a
    /// drive does.
    pub fn apply_state(&mut self, model: &mut Held<'_, M>, (t, end): (f64, f64), state: &State<M>) {
        if let Some((drive, _)) = &mut self.drive
            && let Some(model) = model.get_mut()
        {
            drive(self.stops.read_at(t, end), state, model);
        }
    }
}
