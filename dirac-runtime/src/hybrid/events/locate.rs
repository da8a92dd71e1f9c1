//! Locating crossings: after each step, the signs of the event functions at the step's end
//! against those at the last point examined, and a root finder on the integrator's own
//! states within the step for each function whose sign changed.

use nalgebra::DefaultAllocator;

use super::{EventFunction, Events, INTERIOR, MAX_ITERATIONS};
use crate::error::SimError;
use crate::hybrid::event::{Crossing, Event};
use crate::integrator::Integrator;
use crate::model::LagrangeDirac;
use crate::model::state::State;
use crate::shape::dims::Storage;

impl<'e, M: LagrangeDirac> Events<'e, M>
where
    DefaultAllocator: Storage<M>,
{
    /// Starts watching from `state` at `t`: the functions' signs there are the ones a crossing
    /// changes (a function that is zero there takes the sign it first has after). Allocates
    /// the locator's storage; call it before the first step. Two functions of the same name
    /// are refused ([`SimError::InvalidOption`]).
    pub fn begin(&mut self, model: &M, t: f64, state: &State<M>) -> Result<(), SimError> {
        let n = self.functions.len();
        if let Some(k) = (1..n).find(|&k| self.names[..k].contains(&self.names[k])) {
            return Err(SimError::InvalidOption {
                what: "events",
                reason: format!(
                    "two event functions are called `{}`: their events could not be told apart",
                    self.names[k]
                ),
            });
        }
        for v in [&mut self.lo, &mut self.hi, &mut self.signs, &mut self.peak] {
            v.clear();
            v.resize(n, 0.0);
        }
        self.pending.clear();
        self.pending.resize(n, false);
        self.reopened.clear();
        self.reopened.resize(n, false);
        self.at_event = state.clone();
        self.probe = state.clone();
        self.evaluations = 0;
        self.resume(model, t, state)?;
        // A contact must start open or closed, not penetrated.
        if let Some(k) = (0..n).find(|&k| self.contact_of[k].is_some() && self.lo[k] < 0.0) {
            return Err(SimError::StateNotConsistent {
                t,
                equation: format!("unilateral constraint `{}` (φ ≥ 0)", self.names[k]),
                residual: -self.lo[k],
            });
        }
        Ok(())
    }

    /// Watches on from `state` at `t` after a restart there (an action that reset the state or
    /// changed the model): the functions are evaluated anew; one that is zero keeps the sign it
    /// had last, so that an event whose action leaves the function at zero (a ball put back on
    /// the floor) does not fire again before the function moves away from zero.
    pub fn resume(&mut self, model: &M, t: f64, state: &State<M>) -> Result<(), SimError> {
        self.t_lo = t;
        for k in 0..self.functions.len() {
            let g = self.evaluate(k, t, state, model)?;
            self.lo[k] = g;
            if g != 0.0 {
                self.signs[k] = g.signum();
            }
            self.pending[k] = false;
            self.reopened[k] = false;
        }
        self.hi_current = false;
        self.inputs_moved = false;
        Ok(())
    }

    /// Whether function `k` is a release, a force falling through zero (a law's or a resting
    /// contact's): read on exact multipliers ([`Integrator::exact_multipliers`]).
    fn reads_force(&self, k: usize) -> bool {
        matches!(self.law_of[k], Some(crate::hybrid::laws::Switch::Release(_)))
            || self.release_of[k].is_some()
    }

    fn evaluate(&mut self, k: usize, t: f64, state: &State<M>, model: &M) -> Result<f64, SimError> {
        self.evaluations += 1;
        let g = value(&mut self.functions[k], &self.names[k], t, state, model)?;
        self.peak[k] = self.peak[k].max(g.abs());
        Ok(g)
    }

    /// The switching surface the state at `t` sits on, if any: a switching function that is
    /// zero there, relative to the largest magnitude it has had (`1e-6` of it, or of 1). Where
    /// a step fails on such a surface, both sides of it push the motion into it.
    pub(crate) fn sliding_surface(
        &mut self,
        model: &M,
        t: f64,
        state: &State<M>,
    ) -> Result<Option<usize>, SimError> {
        for k in 0..self.functions.len() {
            if !self.switch_of[k] {
                continue;
            }
            let g = self.evaluate(k, t, state, model)?;
            if g.abs() <= 1e-6 * self.peak[k].max(1.0) {
                return Ok(Some(k));
            }
        }
        Ok(None)
    }

    /// The next event within the step the integrator just took, in time order: `None` once
    /// the step holds no more. The state at the event is then [`Events::state`]. Call it
    /// after each step until it returns `None`, handling each event as it comes; after a
    /// restart within the step (at an event), call [`Events::resume`]. Allocates nothing.
    ///
    /// Where the integrator sets inputs within its steps (a Radau drive), they are set for
    /// each time the functions are evaluated at, left at the event's time while it is handled,
    /// and put back at the step's end after it.
    pub fn locate<I: Integrator<M>>(&mut self, integrator: &mut I) -> Result<Option<Event>, SimError> {
        if let Some(k) = self.pending.iter().position(|&p| p) {
            self.pending[k] = false;
            return Ok(Some(self.crossed(k, self.t_lo)));
        }
        let t = integrator.t();
        if !self.hi_current || self.t_hi != t {
            let model = integrator.model();
            let mut exact = false;
            for k in 0..self.functions.len() {
                self.hi[k] = self.evaluate(k, t, integrator.state(), model)?;
                // A release read from the step's own multipliers, where it may have crossed or
                // is near zero, is read again from exact ones.
                let (g, sign) = (self.hi[k], self.signs[k]);
                if self.reads_force(k) && (g.signum() != sign || g.abs() <= 1e-2 * self.peak[k]) {
                    if !exact {
                        self.probe.clone_from(integrator.state());
                        integrator.exact_multipliers(t, &mut self.probe);
                        exact = true;
                    }
                    self.evaluations += 1;
                    let g = value(&mut self.functions[k], &self.names[k], t, &self.probe, model)?;
                    self.peak[k] = self.peak[k].max(g.abs());
                    self.hi[k] = g;
                }
            }
            self.t_hi = t;
            self.hi_current = true;
        }
        // The earliest crossing that counts: a timed switch the step was made to end at counts
        // at the first time on its other side, whatever its value at the step's end.
        let timed = self.timed_crossing_at(t);
        let mut first: Option<(usize, f64)> = timed;
        for k in 0..self.functions.len() {
            let (g, sign) = (self.hi[k], self.signs[k]);
            if g == 0.0 || g.signum() == sign || sign == 0.0 || timed.is_some_and(|(j, _)| j == k) {
                continue;
            }
            if !self.crossings[k].counts(g > 0.0) {
                continue;
            }
            let root = self.root(k, integrator, self.t_hi, g)?;
            if first.is_none_or(|(_, t_first)| root < t_first) {
                first = Some((k, root));
            }
        }
        if self.sampled.iter().any(|&s| s) {
            self.crossed_back(integrator, t, &mut first)?;
        }
        // A contact that is closed (its function zero or crossed, and not reopened by an impact)
        // and goes deeper into its wall closes without an impact: resting contact begins,
        // which is not simulated.
        let closing = (0..self.functions.len()).find(|&k| {
            let (g, lo) = (self.hi[k], self.lo[k]);
            self.contact_of[k].is_some()
                && !self.reopened[k]
                && self.signs[k] <= 0.0
                && g < 0.0
                && g < lo.min(0.0)
        });
        if let (Some(k), None) = (closing, first) {
            return Err(SimError::ContactCloses {
                contact: self.names[k].clone(),
                t: self.t_lo,
                t_limit: None,
            });
        }
        let Some((k, t_event)) = first else {
            // No event in the rest of the step: its end is the next search's start.
            self.t_lo = t;
            if self.inputs_moved {
                self.probe.clone_from(integrator.state());
                integrator.set_inputs_at(t, &self.probe);
                self.inputs_moved = false;
            }
            for k in 0..self.functions.len() {
                self.reopened[k] = false;
                self.lo[k] = self.hi[k];
                if self.hi[k] != 0.0 {
                    self.signs[k] = self.hi[k].signum();
                }
            }
            return Ok(None);
        };
        if t_event >= t {
            self.at_event.clone_from(integrator.state());
        } else {
            integrator.state_at(t_event, &mut self.at_event)?;
        }
        if self.inputs_moved || t_event < t {
            integrator.set_inputs_at(t_event, &self.at_event);
            self.inputs_moved = t_event < t;
        }
        let model = integrator.model();
        // The search goes on from the event; functions that changed sign by then crossed at
        // the same time (within the root finder's resolution), or do not count.
        self.t_lo = t_event;
        let event = self.crossed(k, t_event);
        for j in 0..self.functions.len() {
            self.evaluations += 1;
            let g = value(&mut self.functions[j], &self.names[j], t_event, &self.at_event, model)?;
            self.lo[j] = g;
            if j == k || g == 0.0 || g.signum() == self.signs[j] || self.signs[j] == 0.0 {
                continue;
            }
            if self.crossings[j].counts(g > 0.0) {
                self.pending[j] = true;
            } else {
                self.signs[j] = g.signum();
            }
        }
        Ok(Some(event))
    }

    /// Records that function `k` crossed at `t`: its sign flips.
    fn crossed(&mut self, k: usize, t: f64) -> Event {
        self.signs[k] = -self.signs[k];
        let crossing = if self.signs[k] > 0.0 { Crossing::Rising } else { Crossing::Falling };
        Event { index: k, t, crossing }
    }

    /// Switching surfaces crossed and crossed back within the rest of the step, which its ends
    /// do not show: the dense output is sampled at `INTERIOR` evenly spaced times for the
    /// switching functions that end the step on the side they began it, and the first sample
    /// past a surface brackets its first crossing, which becomes `first` if it comes earlier.
    /// An excursion longer than the samples' spacing is found; a shorter one may not be.
    fn crossed_back<I: Integrator<M>>(
        &mut self,
        integrator: &mut I,
        t: f64,
        first: &mut Option<(usize, f64)>,
    ) -> Result<(), SimError> {
        let t_lo = self.t_lo;
        for s in 1..=INTERIOR {
            let ts = t_lo + (t - t_lo) * s as f64 / (INTERIOR + 1) as f64;
            if first.is_some_and(|(_, t_first)| t_first <= ts) || !(ts > t_lo && ts < t) {
                return Ok(());
            }
            let (mut probed, mut found) = (false, false);
            for k in 0..self.functions.len() {
                let (sign, end) = (self.signs[k], self.hi[k]);
                if !self.sampled[k] || sign == 0.0 || end == 0.0 || end.signum() != sign {
                    continue;
                }
                if !probed {
                    // A switching function reads the motion alone (no multipliers).
                    integrator.interpolate_motion(ts, &mut self.probe);
                    integrator.set_inputs_at(ts, &self.probe);
                    self.inputs_moved = true;
                    if let Some(all) = self.all_declared {
                        self.evaluations += 1;
                        all(integrator.model(), ts, &self.probe, &mut self.declared_values);
                    }
                    probed = true;
                }
                let g = match (self.all_declared, self.declared_of[k]) {
                    (Some(_), Some(j)) => checked(self.declared_values[j], &self.names[k], ts)?,
                    _ => {
                        self.evaluations += 1;
                        value(&mut self.functions[k], &self.names[k], ts, &self.probe, integrator.model())?
                    }
                };
                if (g != 0.0 && g.signum() == sign) || !self.crossings[k].counts(g >= 0.0) {
                    continue;
                }
                let root = if g == 0.0 { ts } else { self.root(k, integrator, ts, g)? };
                // The root finder moved the probe.
                probed = false;
                found = true;
                if first.is_none_or(|(_, t_first)| root < t_first) {
                    *first = Some((k, root));
                }
            }
            if found {
                return Ok(());
            }
        }
        Ok(())
    }

    /// The root of function `k` between the last point examined and `b`, where it has the
    /// value `fb` (of the other sign), by the Illinois variant of regula falsi on the dense
    /// output, safeguarded by bisection: the first time (to round-off) at which the function
    /// is zero or has its new sign.
    fn root<I: Integrator<M>>(
        &mut self,
        k: usize,
        integrator: &mut I,
        b: f64,
        fb: f64,
    ) -> Result<f64, SimError> {
        let (mut a, mut fa, mut b, mut fb) = (self.t_lo, self.lo[k], b, fb);
        if self.reopened[k] {
            // Zero at the impact, positive just after it: the search is for the next zero.
            fa = 0.0;
        } else if fa == 0.0 || fa.signum() != self.signs[k] {
            // The function already had its new sign (or was zero) where the search starts.
            return Ok(a);
        }
        let mut side = 0;
        let mut width = b - a;
        for iteration in 0..MAX_ITERATIONS {
            let resolution = 4.0 * f64::EPSILON * a.abs().max(b.abs());
            if b - a <= resolution {
                break;
            }
            let mid = 0.5 * (a + b);
            let mut c =
                if iteration % 4 == 3 && b - a > 0.5 * width { mid } else { b - fb * (b - a) / (fb - fa) };
            if iteration % 4 == 3 {
                width = b - a;
            }
            if !(c > a && c < b) {
                c = mid;
                if !(c > a && c < b) {
                    break;
                }
            }
            integrator.state_at(c, &mut self.probe)?;
            if self.reads_force(k) {
                integrator.exact_multipliers(c, &mut self.probe);
            }
            integrator.set_inputs_at(c, &self.probe);
            self.inputs_moved = true;
            self.evaluations += 1;
            let fc = value(&mut self.functions[k], &self.names[k], c, &self.probe, integrator.model())?;
            if fc == 0.0 {
                return Ok(c);
            }
            if fc.signum() == fb.signum() {
                (b, fb) = (c, fc);
                if side == -1 {
                    fa *= 0.5;
                }
                side = -1;
            } else {
                (a, fa) = (c, fc);
                if side == 1 {
                    fb *= 0.5;
                }
                side = 1;
            }
        }
        Ok(b)
    }
}

/// The value of the event function `g` called `name` at `t`: an error naming it if it is
/// NaN.
pub(super) fn value<M: LagrangeDirac>(
    g: &mut EventFunction<'_, M>,
    name: &str,
    t: f64,
    state: &State<M>,
    model: &M,
) -> Result<f64, SimError>
where
    DefaultAllocator: Storage<M>,
{
    checked(g(t, state, model), name, t)
}

/// The value `g` of the event function called `name` at `t`, or an error naming it if it is
/// NaN.
fn checked(g: f64, name: &str, t: f64) -> Result<f64, SimError> {
    if g.is_nan() {
        return Err(SimError::NonFinite { t, component: format!("the event function `{name}`") });
    }
    Ok(g)
}
