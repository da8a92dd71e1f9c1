//! Events: named functions `g(t, state, model)` whose sign changes an integration locates
//! between steps, on the integrator's dense output, to round-off in `t`.
//!
//! [`Events`] holds the functions and locates their crossings after each step
//! ([`Events::locate`], which allocates nothing); [`Solve::solve_with_events`](crate::Solve::solve_with_events) runs a whole
//! integration with them, hands each event to the user's action in time order, and restarts
//! from a consistent state when the action reset the state or changed the model.
//!
//! A crossing is a change of sign between two points the locator examined: the ends of steps,
//! and the events located. A function that touches zero without changing sign, or changes
//! sign twice within one step, is not seen; a smaller `max_step` resolves fast ones.

use nalgebra::DefaultAllocator;

use crate::error::SimError;
use crate::hybrid::contacts::{Contacts, Impacts};
use crate::hybrid::event::{Crossing, Event};
use crate::hybrid::laws::{self, Law, Switch};
use crate::model::names::{BLOCKS, CLOSES, CONDUCTS, OPENS, SLIPS, STOPS, SWITCH, TIMED, is_switch};
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac};
use crate::shape::dims::{Sizes, Storage};

pub(crate) mod context;
mod locate;
mod timed;

pub use self::context::EventContext;

/// An event function: `g(t, state, model)`.
type EventFunction<'e, M> = Box<dyn FnMut(f64, &State<M>, &M) -> f64 + 'e>;

/// How many times within each step the switching functions are sampled, beyond its ends,
/// for a surface crossed and crossed back within it.
const INTERIOR: usize = 3;

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
    pub(crate) contacts: Option<Contacts>,
    /// Whether the model's unilateral constraints are left unwatched on purpose
    /// ([`Events::free_motion`]).
    pub(crate) free_motion: bool,
    pub(crate) contact_of: Vec<Option<usize>>,
    /// The contact each release event function opens (in a companion whose contacts rest).
    pub(crate) release_of: Vec<Option<usize>>,
    /// Functions restarted at zero by an impact that reopened their contact: they count as
    /// positive there, so that a closing again within the same step is seen.
    reopened: Vec<bool>,
    /// Whether each function is a switching surface of the model, where the integration
    /// restarts.
    pub(crate) switch_of: Vec<bool>,
    /// Whether each function is a timed switch (a switching surface of time alone), whose
    /// next crossing ends a step ([`Events::bound_step`]).
    pub(crate) timed_of: Vec<bool>,
    /// The timed switch the integrator was asked to end its step at: its index, the step's
    /// end (the first time off the switch's side) and the first time on its other side.
    timed_next: Option<(usize, f64, f64)>,
    /// Whether each function is sampled within each step (switching surfaces, and the ideal
    /// switches' functions of their controls), for a crossing and crossing back.
    pub(crate) sampled: Vec<bool>,
    /// The largest magnitude each function has had at the points examined: the scale against
    /// which a switching function counts as zero where a step fails.
    peak: Vec<f64>,
    /// The model's declared event functions, all at once (`Hybrid::events`), where
    /// `declared` or `switches` watches them: a step is sampled for its switching surfaces with
    /// one evaluation of them all.
    all_declared: Option<AllDeclared<M>>,
    /// Which declared function each watched function is, if it is one.
    pub(crate) declared_of: Vec<Option<usize>>,
    /// The declared functions' values at a sample.
    declared_values: Vec<f64>,
    /// The model's friction laws and ideal diodes, where `declared` or `switches` watches them.
    pub(crate) laws: Vec<Law>,
    /// Which switch of which law each watched function is, if it is one.
    pub(crate) law_of: Vec<Option<Switch>>,
    /// The law switched at the event being handled, whose functions restart positive.
    switched_law: Option<usize>,
    /// For each law, when its latest run of switches close together began and how many it
    /// holds (see [`CHATTER_SWITCHES`]).
    chatter: Vec<(f64, usize)>,
}

/// A law that switches more than this many times, each within [`CHATTER_SPAN`] of the first,
/// ends the run ([`SimError::LawChatters`]): its modes do not settle, and the steps between its
/// switches, too long to fail as too small, would not carry the run anywhere.
const CHATTER_SWITCHES: usize = 100;

/// The span of time, in the model's units, within which [`CHATTER_SWITCHES`] switches of one law
/// end the run (plus the resolution of `t`).
const CHATTER_SPAN: f64 = 1e-7;

/// Which of a model's declared events to watch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Which {
    /// Every one.
    All,
    /// The switching surfaces and the laws' events.
    Switches,
}

/// `Hybrid::events` of a model, as a plain function of the state.
type AllDeclared<M> = fn(&M, f64, &State<M>, &mut [f64]);

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
            free_motion: false,
            contact_of: Vec::new(),
            release_of: Vec::new(),
            reopened: Vec::new(),
            switch_of: Vec::new(),
            timed_of: Vec::new(),
            timed_next: None,
            sampled: Vec::new(),
            peak: Vec::new(),
            all_declared: None,
            declared_of: Vec::new(),
            declared_values: Vec::new(),
            laws: Vec::new(),
            law_of: Vec::new(),
            switched_law: None,
            chatter: Vec::new(),
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
        self.switch_of.push(false);
        self.timed_of.push(false);
        self.sampled.push(false);
        self.declared_of.push(None);
        self.law_of.push(None);
        self
    }

    /// Whether event `index` is one whose crossing makes the state or the model jump: a
    /// contact's, a law's or a switching surface's (not one of the run's own).
    pub(crate) fn jumps_at(&self, index: usize) -> bool {
        self.contact_of[index].is_some() || self.law_of[index].is_some() || self.switch_of[index]
    }

    /// After a restart at an impact: the contacts `reopened` (their indices among the
    /// unilateral constraints) moved away from zero, so their functions count as positive
    /// from there, whatever their sign at the impact.
    ///
    /// Likewise after a law switched: both its functions start at or above zero in the new
    /// mode (a released law's `g` at zero, an engaged one's margin to its bound), so they count
    /// as positive from there, whatever the round-off left.
    pub(crate) fn reopen(&mut self, reopened: &[usize]) {
        let law = self.switched_law.take();
        for k in 0..self.functions.len() {
            let switched = matches!(
                (self.law_of[k], law),
                (Some(Switch::Engage(j) | Switch::Release(j)), Some(l)) if j == l
            );
            if switched || self.contact_of[k].is_some_and(|j| reopened.contains(&j)) {
                self.reopened[k] = true;
                self.signs[k] = 1.0;
                self.lo[k] = self.lo[k].max(0.0);
            }
        }
    }

    /// The index among the unilateral constraints of the contact called `name`.
    pub(crate) fn contact_index(&self, name: &str) -> Option<usize> {
        self.contacts.as_ref()?.names.iter().position(|n| n == name)
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
}

/// What the model's [`Hybrid`] capability adds: its declared events and its contacts.
impl<M: Hybrid> Events<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    /// Adds the events the model declares (`#[dirac(event(name, direction) = g)]`, a function
    /// of time, positions, velocities, multipliers and inputs), each with its name (dotted in
    /// an interconnection: `arm.slack`) and direction. A model assembled while the program runs
    /// (a [`Network`](crate::network::Network)) names its events only then:
    /// [`declared_in`](Self::declared_in) adds them.
    pub fn declared(self) -> Self {
        self.add_declared(M::NAMES.event_declarations(), Which::All, |declared| {
            laws::laws_among(declared, &M::NAMES.coordinate_names(), &M::NAMES.constraint_names())
        })
    }

    /// [`declared`](Self::declared), the events read from `model`: those of the parts of a
    /// [`Network`](crate::network::Network) (`D1.d_conducts`), as well as a derived model's.
    pub fn declared_in(self, model: &M) -> Self {
        self.add_declared(model.event_declarations(), Which::All, |_| laws::laws(model))
    }

    /// Adds the switching surfaces of the model's non-smooth functions and conditionals
    /// (`abs`, `min`, `max`, `clamp`, `signum`, `if a > b { … } else { … }` in its Lagrangian,
    /// forces or constraints; `switch0`, … by name, dotted in an interconnection): at each
    /// crossing, [`Solve::solve_with_events`](crate::Solve::solve_with_events) restarts the integration, so that no
    /// step reaches across the kink. A plain [`Solve::solve`](crate::Solve::solve)
    /// adds them itself; [`Events::declared`] has them among the declared events.
    ///
    /// Also adds the events of the model's laws (`friction`, `diode`, `switch`: `grip_stops`,
    /// `grip_slips`, `d_conducts`, …), at each of which the solve switches the law's mode
    /// before the action sees the event, and restarts from the consistent state in the new
    /// mode. A [`Network`](crate::network::Network)'s come from [`switches_in`](Self::switches_in).
    pub fn switches(self) -> Self {
        self.add_declared(M::NAMES.event_declarations(), Which::Switches, |declared| {
            laws::laws_among(declared, &M::NAMES.coordinate_names(), &M::NAMES.constraint_names())
        })
    }

    /// [`switches`](Self::switches), the surfaces and laws read from `model`: those of the parts
    /// of a [`Network`](crate::network::Network), as well as a derived model's.
    pub fn switches_in(self, model: &M) -> Self {
        self.add_declared(model.event_declarations(), Which::Switches, |_| laws::laws(model))
    }

    /// Adds what makes `model`'s motion piecewise that these events leave unwatched: its
    /// unilateral constraints (unless [`free_motion`](Self::free_motion) asked for the motion
    /// without them), its laws, and, with `surfaces`, its switching surfaces. What every run
    /// watches ([`Run`](crate::simulate::run::Run)); an error where the laws are half watched
    /// (`switches()` on a network, whose parts declare them: `switches_in(&network)` reads them).
    pub(crate) fn watch_model(&mut self, model: &M, surfaces: bool) -> Result<(), SimError> {
        let laws = crate::model::hybrid::has_laws(model);
        // Refused before anything changes, so that the caller's events stay as they were.
        if laws && self.all_declared.is_some() && !self.watches_laws(model) {
            return Err(context::unwatched_laws(model));
        }
        if self.contacts.is_none() && !self.free_motion && !model.unilateral_names().is_empty() {
            *self = std::mem::take(self).contacts(model);
        }
        if self.all_declared.is_none() && (laws || (surfaces && model.has_switches())) {
            *self = std::mem::take(self).switches_in(model);
        }
        Ok(())
    }

    /// Watches the declared events `declared` (all, or the switching surfaces and laws only),
    /// the laws among them found by `laws_of`.
    fn add_declared(
        mut self,
        declared: Vec<(String, i8)>,
        which: Which,
        laws_of: impl FnOnce(&[(String, i8)]) -> Vec<Law>,
    ) -> Self {
        let k = declared.len();
        let has_laws = declared.iter().any(|&(_, code)| matches!(code, STOPS | CONDUCTS | CLOSES));
        let laws = if has_laws { laws_of(&declared) } else { Vec::new() };
        for (j, (name, direction)) in declared.into_iter().enumerate() {
            let crossing = match (direction, which) {
                (STOPS | SLIPS | CONDUCTS | BLOCKS | CLOSES | OPENS, _) => Crossing::Falling,
                (SWITCH | TIMED, _) => Crossing::Either,
                (_, Which::Switches) => continue,
                (d, Which::All) if d < 0 => Crossing::Falling,
                (1, Which::All) => Crossing::Rising,
                (_, Which::All) => Crossing::Either,
            };
            let mut values = vec![0.0; k];
            self = self.on(name, crossing, move |t, s: &State<M>, m: &M| {
                m.events(t, &s.q, &s.v, &s.lambda, &mut values);
                values[j]
            });
            *self.switch_of.last_mut().expect("just added") = is_switch(direction);
            *self.sampled.last_mut().expect("just added") = is_switch(direction);
            *self.timed_of.last_mut().expect("just added") = direction == TIMED;
            *self.declared_of.last_mut().expect("just added") = Some(j);
        }
        self.watch_laws(laws).watch_declared(k)
    }

    /// Marks the watched functions that switch one of the model's laws (`friction`, `diode`),
    /// which [`Solve::solve_with_events`](crate::Solve::solve_with_events) then switches at their events.
    fn watch_laws(mut self, laws: Vec<Law>) -> Self {
        if laws.is_empty() {
            return self;
        }
        self.chatter = vec![(f64::NEG_INFINITY, 0); laws.len()];
        self.laws = laws;
        for (k, declared) in self.declared_of.iter().enumerate() {
            let Some(j) = *declared else { continue };
            self.law_of[k] = self.laws.iter().enumerate().find_map(|(l, law)| {
                (law.engage == j)
                    .then_some(Switch::Engage(l))
                    .or((law.release == j).then_some(Switch::Release(l)))
            });
            // A switch's control may come and go within a step that the motion does not limit
            // (a capacitor long charged, an open circuit at rest), and its functions read the
            // control alone. Friction's and a diode's follow the motion, which the steps resolve.
            self.sampled[k] |= self.law_of[k].is_some_and(|switch| {
                let (Switch::Engage(l) | Switch::Release(l)) = switch;
                self.laws[l].kind == laws::Kind::Switch
            });
        }
        self
    }

    /// Whether every law of `model` is watched (each switch of each), and every function it
    /// declares is read where declared: a [`Network`](crate::network::Network)'s declared
    /// events are not those of [`declared`](Self::declared), which reads a derived model's.
    pub(crate) fn watches_laws(&self, model: &M) -> bool {
        let watched = self.law_of.iter().flatten().count();
        watched == 2 * laws::laws(model).len()
            && self.declared_values.len() == model.event_declarations().len()
    }

    /// Switches the law of event `k` at `t` in `state`, the state there, leaving it consistent
    /// in the law's new mode; whether `k` is a law's event.
    pub(crate) fn switch_law(
        &mut self,
        model: &M,
        k: usize,
        t: f64,
        state: &mut State<M>,
    ) -> Result<bool, SimError> {
        let Some(switch) = self.law_of[k] else { return Ok(false) };
        let (l, engage) = match switch {
            Switch::Engage(l) => (l, true),
            Switch::Release(l) => (l, false),
        };
        let (first, count) = &mut self.chatter[l];
        if t - *first > CHATTER_SPAN + 1e-15 * t.abs() {
            (*first, *count) = (t, 0);
        }
        *count += 1;
        if *count > CHATTER_SWITCHES {
            return Err(SimError::LawChatters {
                law: self.laws[l].name.clone(),
                t,
                switches: *count,
                span: t - *first,
            });
        }
        laws::switch(model, &self.laws[l], engage, t, state, &mut self.declared_values)?;
        self.switched_law = Some(l);
        Ok(true)
    }

    /// Keeps `Hybrid::events` to evaluate the model's `count` declared functions at once.
    fn watch_declared(mut self, count: usize) -> Self {
        self.all_declared =
            Some(|m: &M, t, s: &State<M>, out: &mut [f64]| m.events(t, &s.q, &s.v, &s.lambda, out));
        self.declared_values.resize(count, 0.0);
        self
    }

    /// Leaves the model's unilateral constraints unwatched: the motion passes through them as
    /// if they were not there. Without it (or [`Events::contacts`]), a solve with events of a
    /// model that declares unilateral constraints ends at once in [`SimError::InvalidOption`],
    /// and so do `solve_observed` and `solve_sampled`; a plain
    /// [`Solve::solve`](crate::Solve::solve) watches them. A declared wall never lets
    /// a motion through unannounced.
    pub fn free_motion(mut self) -> Self {
        self.free_motion = true;
        self
    }

    /// Adds the model's unilateral constraints (`#[dirac(unilateral(name) = φ)]`, `φ ≥ 0`), each
    /// an event of its own name when `φ` falls through zero. At such an event
    /// [`Solve::solve_with_events`](crate::Solve::solve_with_events) applies the impact law before the action: the
    /// momentum jumps along the constraint's one-form, `p⁺ = p⁻ + Λ ∂φ/∂q`, so that the normal
    /// velocity is reversed and scaled by the restitution `e`, `∂φ/∂q v⁺ = −e ∂φ/∂q v⁻`,
    /// with the model's own constraints kept; contacts that close at once share one law. The
    /// impulses are recorded ([`Solution::impacts_at`](crate::Solution::impacts_at)); the action sees the state after the
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
        self.free_motion = false;
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
            self.switch_of.push(false);
            self.timed_of.push(false);
            self.sampled.push(false);
            self.declared_of.push(None);
            self.law_of.push(None);
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

    /// The impact at the contact of event `k` at `t`, together with every other contact that
    /// is closed there too (`φ ≤ 0` at the event: its event pending at the same time, or
    /// touching zero exactly): `state`'s velocities change by the impact law; the impulses
    /// are returned.
    pub(crate) fn impact(
        &mut self,
        model: &M,
        k: usize,
        t: f64,
        state: &mut State<M>,
    ) -> Result<Impacts, SimError> {
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
}
