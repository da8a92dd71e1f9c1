//! Timed switches: switching surfaces whose condition depends on time and parameters alone (a
//! step source's `t < start`, a pulse's edges). Their crossings are known before a step is
//! taken, so the step is made to end at the first one, the model read from the left there, and
//! the integration goes on from the other side: no step straddles the switch, where otherwise
//! the steps would shrink towards it until their error allowed one across, and the state after
//! it would carry that step's error.

use nalgebra::DefaultAllocator;

use super::locate::value;
use super::{Events, INTERIOR};
use crate::error::SimError;
use crate::integrator::Integrator;
use crate::model::LagrangeDirac;
use crate::shape::dims::Storage;

/// How far past a crossing, in round-offs of `t`, a timed switch may stay at zero before its
/// other side is taken to begin there all the same.
const ZERO_RUN: usize = 64;

impl<M: LagrangeDirac> Events<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    /// Before a step: asks the integrator to end it at the first crossing of a timed switch
    /// within it, if there is one (sampled at the step's end and `INTERIOR` times within it,
    /// then bisected to the first time, to round-off, off the switch's present side). The
    /// crossing is then reported by [`Events::locate`] at the step's end, at the first time on
    /// the other side. Does nothing without timed switches, or for a method that cannot end its
    /// steps at a given time (a fixed-step method: the crossing is located within its step).
    pub(crate) fn bound_step<I: Integrator<M>>(&mut self, integrator: &mut I) -> Result<(), SimError> {
        if !self.timed_of.iter().any(|&t| t) {
            return Ok(());
        }
        self.timed_next = None;
        if !integrator.end_step_at(None) {
            return Ok(());
        }
        let (t, end) = (integrator.t(), integrator.next_step_end());
        // (A NaN end is no step ahead either.)
        if end <= t || end.is_nan() {
            return Ok(());
        }
        let mut first: Option<(usize, f64, f64)> = None;
        for k in 0..self.functions.len() {
            let sign = self.signs[k];
            if !self.timed_of[k] || sign == 0.0 {
                continue;
            }
            let off = |g: f64| g.is_nan() || g.signum() != sign || g == 0.0;
            let mut a = t;
            for s in 1..=INTERIOR + 1 {
                let b = t + (end - t) * s as f64 / (INTERIOR + 1) as f64;
                let b = if s == INTERIOR + 1 { end } else { b };
                if first.is_some_and(|(_, t_first, _)| t_first <= a) {
                    break;
                }
                if !off(self.timed_value(k, b, integrator)?) {
                    a = b;
                    continue;
                }
                let crossing = self.first_off(k, (a, b), integrator, off)?;
                let across = self.first_across(k, crossing, integrator)?;
                if first.is_none_or(|(_, t_first, _)| crossing < t_first) {
                    first = Some((k, crossing, across));
                }
                break;
            }
        }
        if let Some((_, crossing, _)) = first
            && integrator.end_step_at(Some(crossing))
        {
            self.timed_next = first;
        }
        Ok(())
    }

    /// At the start, at `t`: a timed switch that is zero there (a pulse train's first edge at
    /// `t = start`) may hold the model on one side at `t` and on the other just after it. It
    /// takes the sign it has at the first time it is not zero, if that comes within the run's
    /// resolution in time (the integrators' smallest step, `16 ε max(|t|, span / 10)`), and
    /// that time is returned, the latest over such switches: the run goes on from there, on
    /// the side the switch then has. `None` if no timed switch is zero at `t`.
    pub(crate) fn start_across<I: Integrator<M>>(&mut self, integrator: &I) -> Result<Option<f64>, SimError> {
        let t = integrator.t();
        let resolution = 16.0 * f64::EPSILON * t.abs().max(0.1 * (integrator.end() - t).abs());
        let mut latest = None;
        for k in 0..self.functions.len() {
            if !self.timed_of[k] || self.signs[k] != 0.0 {
                continue;
            }
            let off = |g: f64| g != 0.0;
            if !off(self.timed_value(k, t + resolution, integrator)?) {
                continue;
            }
            let across = self.first_off(k, (t, t + resolution), integrator, off)?;
            self.signs[k] = self.timed_value(k, across, integrator)?.signum();
            latest = Some(latest.map_or(across, |l: f64| l.max(across)));
        }
        Ok(latest)
    }

    /// The timed switch the integrator was asked to end its step at, if the step it just took
    /// ended there: its index and the first time on its other side, where it is reported.
    pub(crate) fn timed_crossing_at(&mut self, t: f64) -> Option<(usize, f64)> {
        match self.timed_next {
            Some((k, crossing, across)) if crossing == t => {
                self.timed_next = None;
                Some((k, across))
            }
            _ => None,
        }
    }

    /// Timed switch `k`'s value at `t` (any state: it reads none).
    fn timed_value<I: Integrator<M>>(&mut self, k: usize, t: f64, integrator: &I) -> Result<f64, SimError> {
        self.evaluations += 1;
        value(&mut self.functions[k], &self.names[k], t, integrator.state(), integrator.model())
    }

    /// The first time in `(a, b]` at which switch `k` is `off` its present side, `b` being
    /// one: bisection in time to adjacent floating-point numbers.
    fn first_off<I: Integrator<M>>(
        &mut self,
        k: usize,
        (mut a, mut b): (f64, f64),
        integrator: &I,
        off: impl Fn(f64) -> bool,
    ) -> Result<f64, SimError> {
        while a.next_up() < b {
            let mid = a + 0.5 * (b - a);
            let mid = if mid > a && mid < b { mid } else { a.next_up() };
            if off(self.timed_value(k, mid, integrator)?) {
                b = mid;
            } else {
                a = mid;
            }
        }
        Ok(b)
    }

    /// The first time from `crossing` on at which switch `k` is strictly on its other side (a
    /// switch that is zero at its crossing, as `start − t` is at `t = start`, may belong to
    /// either branch there): within [`ZERO_RUN`] round-offs, else `crossing`.
    fn first_across<I: Integrator<M>>(
        &mut self,
        k: usize,
        crossing: f64,
        integrator: &I,
    ) -> Result<f64, SimError> {
        let mut t = crossing;
        for _ in 0..ZERO_RUN {
            let g = self.timed_value(k, t, integrator)?;
            if g != 0.0 && g.signum() != self.signs[k] {
                return Ok(t);
            }
            t = t.next_up();
        }
        Ok(crossing)
    }
}
