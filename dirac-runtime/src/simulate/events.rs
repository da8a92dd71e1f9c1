//! Events: named functions `g(t, state, model)` whose sign changes an integration locates
//! between steps, on the integrator's dense output, to round-off in `t`.
//!
//! [`Events`] holds the functions and locates their crossings after each step
//! ([`Events::locate`], which allocates nothing); [`SolveWithEvents::solve_with_events`] runs a whole
//! integration with them, hands each event to the user's action in time order, and restarts
//! from a consistent state when the action reset the state or changed the model.
//!
//! A crossing is a change of sign between two points the locator examined: the ends of steps,
//! and the events located. A function that touches zero without changing sign, or changes
//! sign twice within one step, is not seen; a smaller `max_step` resolves fast ones.

use std::ops::ControlFlow;

use nalgebra::DefaultAllocator;

use crate::analysis::diagnose::check_constraints_kept;
use crate::analysis::init::{Consistency, consistent_state};
use crate::error::SimError;
use crate::model::LagrangeDirac;
use crate::model::state::State;
use crate::shape::dims::{Sizes, Storage};
use crate::simulate::contacts::{Contacts, Impacts};
use crate::simulate::integrator::Integrator;
use crate::simulate::recorder::Recorder;
use crate::simulate::restart::constraint_violation;
use crate::simulate::solution::{Crossing, Event, Impact, Sampling, Solution};

/// An event function: `g(t, state, model)`.
type EventFunction<'e, M> = Box<dyn FnMut(f64, &State<M>, &M) -> f64 + 'e>;

/// The most iterations of the root finder for one crossing; the bracket halves at least every
/// fourth, so 4 × 64 covers the width of any `f64` interval.
const MAX_ITERATIONS: usize = 256;

/// A set of named event functions, and the locator of their crossings.
///
/// The facade's guide (`dirac::guide`, section "Events") has a runnable example: a ball that
/// bounces on the floor.
pub struct Events<'e, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    names: Vec<String>,
    crossings: Vec<Crossing>,
    functions: Vec<EventFunction<'e, M>>,
    /// The last point examined: its time and the functions' values there.
    t_lo: f64,
    lo: Vec<f64>,
    /// The sign each function had last when it was not zero (0 before it was ever nonzero).
    signs: Vec<f64>,
    /// The values at the end of the step being searched, and whether they are current.
    t_hi: f64,
    hi: Vec<f64>,
    hi_current: bool,
    /// Events that crossed at `t_lo` together with the one reported there.
    pending: Vec<bool>,
    /// The state at the last event located.
    at_event: State<M>,
    /// The state at the root finder's trial points.
    probe: State<M>,
    /// Whether the inputs were last set for a time before the step's end (a trial time of
    /// the root finder, or an event), so that they are to be put back at the step's end.
    inputs_moved: bool,
    evaluations: usize,
    /// The model's unilateral constraints, when watched ([`Events::contacts`]), and which
    /// of them each event function is.
    contacts: Option<Contacts>,
    contact_of: Vec<Option<usize>>,
    /// The contact each release event function opens (in a companion whose contacts rest).
    release_of: Vec<Option<usize>>,
    /// Functions restarted at zero by an impact that reopened their contact: they count as
    /// positive there, so that a closing again within the same step is seen.
    reopened: Vec<bool>,
}

impl<M: LagrangeDirac> Default for Events<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    fn default() -> Self {
        Self::new()
    }
}

impl<'e, M: LagrangeDirac> Events<'e, M>
where
    DefaultAllocator: Storage<M>,
{
    /// No events yet.
    pub fn new() -> Self {
        Events {
            names: Vec::new(),
            crossings: Vec::new(),
            functions: Vec::new(),
            t_lo: f64::NAN,
            lo: Vec::new(),
            signs: Vec::new(),
            t_hi: f64::NAN,
            hi: Vec::new(),
            hi_current: false,
            pending: Vec::new(),
            at_event: State::with_sizes(Sizes { nq: 0, nc: 0, nh: 0 }.typed::<M>()),
            probe: State::with_sizes(Sizes { nq: 0, nc: 0, nh: 0 }.typed::<M>()),
            inputs_moved: false,
            evaluations: 0,
            contacts: None,
            contact_of: Vec::new(),
            release_of: Vec::new(),
            reopened: Vec::new(),
        }
    }

    /// Adds the event `name`: the crossings of zero by `g(t, state, model)` in the direction
    /// `crossing`. Its index is the number of events added before it.
    pub fn on(
        mut self,
        name: impl Into<String>,
        crossing: Crossing,
        g: impl FnMut(f64, &State<M>, &M) -> f64 + 'e,
    ) -> Self {
        self.names.push(name.into());
        self.crossings.push(crossing);
        self.functions.push(Box::new(g));
        self.contact_of.push(None);
        self.release_of.push(None);
        self
    }

    /// Adds the events the model declares (`#[dirac(event(name, direction) = g)]`, a function
    /// of time, positions, velocities, multipliers and inputs), each with its name (dotted in
    /// an interconnection: `arm.slack`) and direction.
    pub fn declared(mut self) -> Self {
        let declared = M::NAMES.event_declarations();
        let k = declared.len();
        for (j, (name, direction)) in declared.into_iter().enumerate() {
            let crossing = match direction {
                d if d < 0 => Crossing::Falling,
                d if d > 0 => Crossing::Rising,
                _ => Crossing::Either,
            };
            let mut values = vec![0.0; k];
            self = self.on(name, crossing, move |t, s: &State<M>, m: &M| {
                m.events(t, &s.q, &s.v, &s.lambda, &mut values);
                values[j]
            });
        }
        self
    }

    /// Adds the model's unilateral constraints (`#[dirac(unilateral(name) = φ)]`, `φ ≥ 0`), each
    /// an event of its own name when `φ` falls through zero. At such an event
    /// [`SolveWithEvents::solve_with_events`] applies the impact law before the action: the
    /// momentum jumps along the constraint's one-form, `p⁺ = p⁻ + Λ ∂φ/∂q`, so that the normal
    /// velocity is reversed and scaled by the restitution `e`, `∂φ/∂q v⁺ = −e ∂φ/∂q v⁻`,
    /// with the model's own constraints kept; contacts that close at once share one law. The
    /// impulses are recorded ([`Solution::impacts_at`]); the action sees the state after the
    /// impact, and its impulse ([`EventContext::impulse`]).
    ///
    /// A contact that comes to rest (an impact leaves it closed or reopens it too slowly to
    /// tell from rest, its impacts accumulate in a Zeno sequence, or it is pressed in without
    /// an impact) closes in a companion made by the derive's `with_contacts()`, held by its
    /// row `<name>_force`, and opens again where that row's multiplier, the contact force,
    /// falls through zero (the event `<name> opens`, added here). In any other model, or one
    /// the integrator does not hold exclusively, it ends the integration with
    /// [`SimError::ContactCloses`]. An interconnection watches its subsystems' contacts, by
    /// dotted name (`ball.floor`).
    pub fn contacts(mut self, model: &M) -> Self {
        let contacts = Contacts::new(model);
        let k = contacts.names.len();
        for (j, name) in contacts.names.iter().enumerate() {
            let mut values = vec![0.0; k];
            self.names.push(name.clone());
            self.crossings.push(Crossing::Falling);
            self.functions.push(Box::new(move |t, s: &State<M>, m: &M| {
                // A closed contact (in a companion with contacts that can rest) is held, not watched.
                if m.contact_closed(j) {
                    return 1.0;
                }
                m.unilateral(t, &s.q, &mut values);
                values[j]
            }));
            self.contact_of.push(Some(j));
            self.release_of.push(None);
        }
        // In a companion whose contacts rest, a closed contact opens where its force, the
        // multiplier of its row, falls through zero.
        for (j, name) in contacts.names.iter().enumerate() {
            if let Some(row) = model.contact_row(j) {
                self = self.on(format!("{name} opens"), Crossing::Falling, move |_, s: &State<M>, m: &M| {
                    if m.contact_closed(j) { s.lambda[row] } else { 1.0 }
                });
                *self.release_of.last_mut().expect("just added") = Some(j);
            }
        }
        self.contacts = Some(contacts);
        self
    }

    /// After a restart at an impact: the contacts `reopened` (their indices among the
    /// unilateral constraints) moved away from zero, so their functions count as positive
    /// from there, whatever their sign at the impact.
    fn reopen(&mut self, reopened: &[usize]) {
        for k in 0..self.functions.len() {
            if self.contact_of[k].is_some_and(|j| reopened.contains(&j)) {
                self.reopened[k] = true;
                self.signs[k] = 1.0;
                self.lo[k] = self.lo[k].max(0.0);
            }
        }
    }

    /// The index among the unilateral constraints of the contact called `name`.
    fn contact_index(&self, name: &str) -> Option<usize> {
        self.contacts.as_ref()?.names.iter().position(|n| n == name)
    }

    /// The impact at the contact of event `k` at `t`, together with every other contact that
    /// is closed there too (`φ ≤ 0` at the event: its event pending at the same time, or
    /// touching zero exactly): `state`'s velocities change by the impact law; the impulses
    /// are returned.
    fn impact(&mut self, model: &M, k: usize, t: f64, state: &mut State<M>) -> Result<Impacts, SimError> {
        let contact = self.contact_of[k].expect("event k watches a contact");
        let mut closing = vec![contact];
        for j in 0..self.functions.len() {
            if let (true, Some(other)) = (j != k && self.lo[j] <= 0.0, self.contact_of[j]) {
                closing.push(other);
                self.pending[j] = false;
            }
        }
        let contacts = self.contacts.as_mut().expect("contact events come with their contacts");
        contacts.impact(model, t, state, &closing)
    }

    /// The events' names, in the order of their indices.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The name of `event`.
    pub fn name(&self, event: &Event) -> &str {
        &self.names[event.index]
    }

    /// The index of the event called `name`.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }

    /// The number of evaluations of event functions since the last [`Events::begin`].
    pub fn evaluations(&self) -> usize {
        self.evaluations
    }

    /// The state at the last event [`Events::locate`] returned.
    pub fn state(&self) -> &State<M> {
        &self.at_event
    }

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
        for v in [&mut self.lo, &mut self.hi, &mut self.signs] {
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

    fn evaluate(&mut self, k: usize, t: f64, state: &State<M>, model: &M) -> Result<f64, SimError> {
        self.evaluations += 1;
        value(&mut self.functions[k], &self.names[k], t, state, model)
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
            for k in 0..self.functions.len() {
                self.hi[k] = self.evaluate(k, t, integrator.state(), model)?;
            }
            self.t_hi = t;
            self.hi_current = true;
        }
        // The earliest crossing that counts.
        let mut first: Option<(usize, f64)> = None;
        for k in 0..self.functions.len() {
            let (g, sign) = (self.hi[k], self.signs[k]);
            if g == 0.0 || g.signum() == sign || sign == 0.0 {
                continue;
            }
            if !self.crossings[k].counts(g > 0.0) {
                continue;
            }
            let root = self.root(k, integrator)?;
            if first.is_none_or(|(_, t_first)| root < t_first) {
                first = Some((k, root));
            }
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

    /// The root of function `k` between the last point examined and the step's end, by the
    /// Illinois variant of regula falsi on the dense output, safeguarded by bisection: the
    /// first time (to round-off) at which the function is zero or has its new sign.
    fn root<I: Integrator<M>>(&mut self, k: usize, integrator: &mut I) -> Result<f64, SimError> {
        let (mut a, mut fa, mut b, mut fb) = (self.t_lo, self.lo[k], self.t_hi, self.hi[k]);
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
fn value<M: LagrangeDirac>(
    g: &mut EventFunction<'_, M>,
    name: &str,
    t: f64,
    state: &State<M>,
    model: &M,
) -> Result<f64, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let g = g(t, state, model);
    if g.is_nan() {
        return Err(SimError::NonFinite { t, component: format!("the event function `{name}`") });
    }
    Ok(g)
}

/// What an event's action may do: read the event's time and state, reset the state, change
/// the model (if the integrator holds it exclusively).
pub struct EventContext<'a, M: LagrangeDirac, I>
where
    DefaultAllocator: Storage<M>,
{
    t: f64,
    state: &'a mut State<M>,
    integrator: &'a mut I,
    reset: bool,
    /// How far the state was from the constraints before the model was first handed out.
    before: Option<f64>,
    /// The impulse of the event's contact, when the event is an impact.
    impulse: Option<f64>,
}

impl<'a, M: LagrangeDirac, I: Integrator<M>> EventContext<'a, M, I>
where
    DefaultAllocator: Storage<M>,
{
    pub(crate) fn new(t: f64, state: &'a mut State<M>, integrator: &'a mut I) -> Self {
        EventContext { t, state, integrator, reset: false, before: None, impulse: None }
    }

    /// The impulse `Λ ≥ 0` the impact law gave the event's contact, when the event is a
    /// unilateral constraint's ([`Events::contacts`]); the state is then the one after it.
    pub fn impulse(&self) -> Option<f64> {
        self.impulse
    }

    /// The event's time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// The state at the event.
    pub fn state(&self) -> &State<M> {
        self.state
    }

    /// The state at the event, to reset: the integration restarts from the consistent state
    /// nearest to the positions and velocities left here (see
    /// [`consistent_state`]: momenta and multipliers are computed,
    /// not read).
    pub fn state_mut(&mut self) -> &mut State<M> {
        self.reset = true;
        self.state
    }

    /// The model.
    pub fn model(&self) -> &M {
        self.integrator.model()
    }

    /// The model, to change (its inputs, its parameters): the integration restarts at the
    /// event. A change that moves a constraint off the state is refused with
    /// [`SimError::ConstraintMoved`] unless the state is reset too.
    pub fn model_mut(&mut self) -> Result<&mut M, SimError> {
        if self.before.is_none() {
            self.before = Some(constraint_violation(self.integrator.model(), self.t, self.state));
        }
        let t = self.t;
        self.integrator.model_mut().ok_or(SimError::SharedModel { t })
    }

    /// Whether the action reset the state or changed the model.
    pub(crate) fn changes(&self) -> (bool, Option<f64>) {
        (self.reset, self.before)
    }
}

/// Running an integration with events: implemented for every [`Integrator`] (and in the
/// facade's prelude).
pub trait SolveWithEvents<M: LagrangeDirac>: Integrator<M> + Sized
where
    DefaultAllocator: Storage<M>,
{
    /// [`Integrator::solve`] with events: after each step, the crossings of the `events`'
    /// functions within it are located on the dense output and handed to `action` in time
    /// order, with an [`EventContext`] to read the state at the event, reset it
    /// ([`EventContext::state_mut`]) or change the model ([`EventContext::model_mut`]).
    ///
    /// - An action that changes nothing costs no restart: the search goes on within the step.
    /// - After a reset or a change, the integration restarts at the event from the consistent
    ///   state nearest to the one the action left ([`consistent_state`]).
    /// - `ControlFlow::Break(())` ends the solution at the event (the integrator itself stays
    ///   at the end of the step that held it; [`Integrator::restart_at`] moves it back).
    ///
    /// The solution records every event ([`Solution::events`](crate::simulate::solution::Solution::events)) and, unless it samples at
    /// chosen times, the state at each event, twice when the action reset it (before, then
    /// after). The [`Events`] type has an example.
    fn solve_with_events(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
        events: &mut Events<'_, M>,
        mut action: impl FnMut(&Event, &mut EventContext<'_, M, Self>) -> ControlFlow<()>,
    ) -> Result<Solution<M, Self::Stats>, SimError> {
        let mut recorder = Recorder::new(self.model(), sampling, t0, t_end)?;
        recorder.name_events(events.names());
        if let Some(contacts) = &events.contacts {
            recorder.name_contacts(&contacts.names);
        }
        self.start(t0, state, t_end)?;
        events.begin(self.model(), t0, self.state())?;
        recorder.record_initial(self.model(), t0, self.state());
        let mut after = state.clone();
        let mut reopened = Vec::new();
        while !self.finished() {
            if let Err(error) = self.step() {
                // A step that fails where impacts accumulate fails because of them: the contact
                // comes to rest where the integrator stands, if it can.
                let Some(j) = (match (&error, &events.contacts) {
                    (SimError::StepSizeTooSmall { t, .. }, Some(contacts)) => contacts.zeno(*t),
                    _ => None,
                }) else {
                    return Err(error);
                };
                rest_where_it_stands(self, events, &mut recorder, j)?;
                continue;
            }
            let mut restarted = false;
            loop {
                let event = match events.locate(self) {
                    Ok(Some(event)) => event,
                    Ok(None) => break,
                    // A contact pressed in without an impact rests from the step's end, if it can.
                    Err(SimError::ContactCloses { contact, t_limit: None, .. })
                        if events
                            .contact_index(&contact)
                            .is_some_and(|j| self.model().contact_row(j).is_some()) =>
                    {
                        let j = events.contact_index(&contact).expect("just found");
                        rest_where_it_stands(self, events, &mut recorder, j)?;
                        restarted = true;
                        break;
                    }
                    Err(error) => return Err(error),
                };
                let t = event.t;
                recorder.record_step(self.model(), t, events.state(), |ts, out| self.interpolate(ts, out));
                recorder.record_event(self.model(), event, events.state());
                after.clone_from(events.state());
                let mut impulse = None;
                let mut switched = false;
                reopened.clear();
                if let Some(contact) = events.contact_of[event.index] {
                    let impacts = events.impact(self.model(), event.index, t, &mut after)?;
                    for &(j, lambda) in &impacts.impulses {
                        recorder.record_impact(Impact { contact: j, t, impulse: lambda });
                        if lambda > 0.0 {
                            reopened.push(j);
                        }
                        if j == contact {
                            impulse = Some(lambda);
                        }
                    }
                    if let Some(j) = impacts.resting {
                        // Left at rest: the contact closes, if it can, and the restart
                        // projects the state onto it (a plastic impact).
                        if !close(self, j, true) {
                            let contacts =
                                events.contacts.as_ref().expect("contact events come with their contacts");
                            return Err(contacts.closes(j, t));
                        }
                        events.contacts.as_mut().expect("contact events come with their contacts").rested(j);
                        reopened.retain(|&c| c != j);
                        switched = true;
                    }
                }
                if let Some(j) = events.release_of[event.index] {
                    switched |= close(self, j, false);
                }
                let mut context = EventContext::new(t, &mut after, self);
                context.impulse = impulse;
                context.reset = !reopened.is_empty() || switched;
                let flow = action(&event, &mut context);
                let (reset, before) = context.changes();
                if flow.is_break() {
                    return recorder.finish(self.stats());
                }
                if reset || before.is_some() {
                    if let (false, Some(before)) = (reset, before) {
                        check_constraints_kept(self.model(), t, &after, before)?;
                    }
                    restart_from(self, events, &mut recorder, t, &after)?;
                    events.reopen(&reopened);
                    restarted = true;
                    break;
                }
            }
            if !restarted {
                recorder.record_step(self.model(), self.t(), self.state(), |t, out| self.interpolate(t, out));
            }
        }
        recorder.finish(self.stats())
    }
}

impl<M: LagrangeDirac, I: Integrator<M>> SolveWithEvents<M> for I where DefaultAllocator: Storage<M> {}

/// Closes (or opens) contact `j` of the integrator's model, if the model can rest it (a
/// companion made by `with_contacts`) and the integrator holds it exclusively.
fn close<M: LagrangeDirac, I: Integrator<M>>(integrator: &mut I, j: usize, closed: bool) -> bool
where
    DefaultAllocator: Storage<M>,
{
    integrator.model().contact_row(j).is_some()
        && integrator.model_mut().is_some_and(|model| model.set_contact_closed(j, closed))
}

/// Contact `j` comes to rest where the integrator stands (the end of its last step): closed,
/// the state projected onto it, the integration restarted there. An error naming the contact
/// if the model cannot rest it.
fn rest_where_it_stands<M: LagrangeDirac, I: Integrator<M>>(
    integrator: &mut I,
    events: &mut Events<'_, M>,
    recorder: &mut Recorder<M>,
    j: usize,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let t = integrator.t();
    let contacts = events.contacts.as_mut().expect("contacts are watched");
    if !close(integrator, j, true) {
        return Err(contacts.closes(j, contacts.last_impact(j).min(t)));
    }
    contacts.rested(j);
    let state = integrator.state().clone();
    restart_from(integrator, events, recorder, t, &state)
}

/// Restarts the integration at `t` from the consistent state nearest to `state`, watching on
/// from there and recording it.
fn restart_from<M: LagrangeDirac, I: Integrator<M>>(
    integrator: &mut I,
    events: &mut Events<'_, M>,
    recorder: &mut Recorder<M>,
    t: f64,
    state: &State<M>,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let consistent = consistent_state(integrator.model(), t, &state.q, &state.v, Consistency::default())?;
    integrator.restart_at(t, &consistent)?;
    events.resume(integrator.model(), t, &consistent)?;
    recorder.record_reset(integrator.model(), t, &consistent);
    Ok(())
}
