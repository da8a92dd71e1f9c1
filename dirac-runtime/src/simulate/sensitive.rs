//! Forward sensitivities carried by a method that can ([`Sensitive`]: Radau), and their
//! recording beside a solution's samples, through impacts, switching surfaces and laws.

use nalgebra::{DVector, DefaultAllocator};

use crate::error::SimError;
use crate::model::blocks::ResidualBlocks;
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac, Parameters};
use crate::shape::dims::Storage;
use crate::shape::layout::Layout;
use std::ops::ControlFlow;

use crate::hybrid::event::Event;
use crate::hybrid::events::{EventContext, Events};
use crate::hybrid::jumps::{Crossed, Jump};
use crate::hybrid::laws;
use crate::integrator::Integrator;
use crate::integrator::restart::restart_nearest_with;
use crate::output::recorder::Recorder;
use crate::output::solution::{Sampling, Solution};
use crate::simulate::run::cycle::{Hooks, drive};
use crate::simulate::run::tangent::Tangent;
use crate::simulate::sensitivity::Sensitivities;

/// An integrator that carries the forward sensitivities of its solution with respect to
/// parameters and initial values: [`Radau`](crate::Radau) (the staggered direct method). A
/// method without them does not implement it, so asking one for sensitivities does not compile.
pub trait Sensitive<M: LagrangeDirac>: Integrator<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Asks the integrator to carry the forward sensitivities of its solution with respect to
    /// `wrt`'s parameters and initial values from its next start (Radau: the staggered direct
    /// method).
    fn carry_sensitivities(&mut self, wrt: &Sensitivities<M>) -> Result<(), SimError>
    where
        M: Parameters;

    /// The names of the sensitivities carried, in order: what they are taken with respect to
    /// (none unless asked for).
    fn sensitivity_names(&self) -> &[String];

    /// Writes sensitivity `j` at the time reached, `∂(q, v, p, λ)/∂θ_j`, into `out`; `false`
    /// (leaving `out` alone) if there is no sensitivity `j`.
    fn sensitivity(&self, j: usize, out: &mut State<M>) -> bool;

    /// Writes sensitivity `j` at time `t` within the last step into `out`; `false` if there is
    /// no sensitivity `j`.
    fn interpolate_sensitivity(&self, j: usize, t: f64, out: &mut State<M>) -> bool;

    /// The parameter sensitivity `j` is taken with respect to (its index), or `None` for an
    /// initial value's (or no sensitivity `j`).
    fn sensitivity_parameter(&self, j: usize) -> Option<usize>;

    /// Restarts the integration at `t` from `state` (consistent) with the sensitivities
    /// `sensitivities` (one per sensitivity carried), after a jump whose derivative the caller
    /// carried them across (an impact).
    fn restart_with_sensitivities(
        &mut self,
        t: f64,
        state: &State<M>,
        sensitivities: &[State<M>],
    ) -> Result<(), SimError>;

    /// Completes sensitivity `j` at the start of the integration, in `out`, with what the first
    /// step taught: the multipliers' sensitivities, which a method may not carry at the start
    /// (Radau extrapolates them from its first step's stages). Does nothing by default.
    fn complete_initial_sensitivity(&self, j: usize, out: &mut State<M>) {
        let _ = (j, out);
    }

    /// Integrates from `state` at `t0` to `t_end` with the sensitivities asked for
    /// ([`Sensitive::carry_sensitivities`]), recording the state as [`Solve::solve`](crate::Solve::solve) does
    /// and every sensitivity at the same samples: read them from the solution by quantity and
    /// name ([`Solution::sensitivity`]). A model with unilateral constraints has its contacts
    /// watched, as [`Solve::solve`](crate::Solve::solve) does, and each sensitivity carried across each impact
    /// by the impact's saltation matrix ([`saltation`](crate::hybrid::impact::saltation)); one with
    /// switching surfaces (`abs`, `signum`, conditionals) has them located, and each
    /// sensitivity carried across each crossing by `(f⁻ − f⁺) ∂t*/∂θ`, the jump of the rate
    /// times the crossing's shift; one with laws (friction, diodes, ideal switches) has them
    /// switched, and each sensitivity carried across each switch the same way, with the rates
    /// of the old mode and the new.
    fn solve_with_sensitivities(
        &mut self,
        t0: f64,
        state: &State<M>,
        t_end: f64,
        sampling: &Sampling,
    ) -> Result<Solution<M, Self::Stats>, SimError>
    where
        Self: Sized,
        M: Hybrid + Parameters,
    {
        record_with_sensitivities(self, t0, state, t_end, sampling)
    }
}

/// The model's switching surfaces, each as `` `name`: g = 0 ``.
fn surfaces<M: LagrangeDirac>(model: &M) -> Vec<String>
where
    DefaultAllocator: Storage<M>,
{
    model
        .event_declarations()
        .into_iter()
        .filter(|&(_, d)| crate::model::names::is_switch(d))
        .map(|(name, _)| format!("`{name}`: {} = 0", model.surface(&name).unwrap_or("?")))
        .collect()
}

/// [`Sensitive::solve_with_sensitivities`]: the run's one loop with the sensitivities
/// carried ([`Carrier`]), the model's contacts, laws and switching surfaces watched.
fn record_with_sensitivities<M: Hybrid + Parameters, I: Sensitive<M>>(
    integrator: &mut I,
    t0: f64,
    state: &State<M>,
    t_end: f64,
    sampling: &Sampling,
) -> Result<Solution<M, I::Stats>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let mut carrier = Carrier::new(integrator)?;
    let mut events = Events::new();
    events.watch_model(integrator.model(), true)?;
    let mut no_action = |_: &Event, _: &mut EventContext<'_, M, I>| ControlFlow::Continue(());
    let hooks = Hooks { action: &mut no_action, every: None, after_step: None, tangent: Some(&mut carrier) };
    let recorder = drive(integrator, (t0, state, t_end), sampling, &mut events, hooks)?;
    carrier.finish(integrator, recorder)
}

/// The forward sensitivities a run carries ([`Tangent`]): recorded beside the samples, carried
/// across each jump by its saltation (see [`carry`]).
pub(crate) struct Carrier<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// The sensitivities at the samples, once the run started.
    rows: Option<SensitivityRows<M>>,
    /// The sensitivities just after the last jump.
    restarted: Vec<State<M>>,
    buffer: State<M>,
}

impl<M: Hybrid + Parameters> Carrier<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Room for the sensitivities `integrator` was asked to carry, after checking that the
    /// run can carry them across what its model's events do.
    pub fn new<I: Sensitive<M>>(integrator: &I) -> Result<Self, SimError> {
        let count = integrator.sensitivity_names().len();
        if count == 0 {
            return Err(SimError::InvalidOption {
                what: "sensitivities",
                reason: "none were asked for: build the integrator with `with_sensitivities`".into(),
            });
        }
        carried_across_events(integrator.model())?;
        let sizes = integrator.model().sizes();
        Ok(Carrier {
            rows: None,
            restarted: vec![State::with_sizes(sizes); count],
            buffer: State::with_sizes(sizes),
        })
    }

    /// The solution of the run, with a column per sensitivity value.
    pub fn finish<I: Sensitive<M>>(
        self,
        integrator: &mut I,
        recorder: Recorder<M>,
    ) -> Result<Solution<M, I::Stats>, SimError> {
        let rows = self.rows.expect("a run that started records its sensitivities");
        rows.finish(integrator, recorder)
    }
}

/// Refuses a model whose events' jumps the sensitivities cannot be carried across: a network's
/// switching surfaces and laws (their event functions' derivatives are not generated for a
/// model assembled while the program runs), and contacts that can rest.
fn carried_across_events<M: Hybrid + Parameters>(model: &M) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let names = model.unilateral_names();
    if let Some(j) = (0..names.len()).find(|&j| model.contact_row(j).is_some()) {
        return Err(SimError::InvalidOption {
            what: "sensitivities",
            reason: format!(
                "the contact `{}` can rest (a companion made by `with_contacts`): resting switches the \
                 model's constraints, and that switch's sensitivities are not carried; carry them on the \
                 model itself, whose impacts are",
                names[j]
            ),
        });
    }
    if names.is_empty() && !model.has_switches() && !crate::model::hybrid::has_laws(model) {
        return Ok(());
    }
    let width = 2 * model.sizes().nq + model.sizes().nc + 1 + model.parameter_count();
    let declared = model.event_declarations().len();
    if declared > 0 && model.event_derivatives_len() != declared * width {
        let what = match model.has_switches() {
            true => format!("its switching surfaces ({})", surfaces(model).join(", ")),
            false => format!("its laws' switches ({})", laws::law_names(model).join(", ")),
        };
        return Err(SimError::InvalidOption {
            what: "sensitivities",
            reason: format!(
                "this model (a network, assembled while the program runs) does not carry \
                 sensitivities across {what}: take differences of solutions"
            ),
        });
    }
    Ok(())
}

impl<M: Hybrid + Parameters, I: Sensitive<M>> Tangent<M, I> for Carrier<M>
where
    DefaultAllocator: Storage<M>,
{
    fn cross(
        &mut self,
        model: &M,
        events: &mut Events<'_, M>,
        event: &Event,
    ) -> Result<Crossed<M>, SimError> {
        events.cross(model, event, "sensitivities")
    }

    fn started(&mut self, integrator: &I, recorder: &Recorder<M>, _: &State<M>) -> Result<(), SimError> {
        let mut rows = SensitivityRows::new(integrator, recorder)?;
        rows.push_initial(integrator, recorder);
        self.rows = Some(rows);
        Ok(())
    }

    fn after_step(&mut self, integrator: &I, _: f64) {
        self.rows.as_mut().expect("started").complete(integrator);
    }

    fn sampled(&mut self, integrator: &I, recorder: &Recorder<M>, before: usize) {
        self.rows.as_mut().expect("started").push_within(integrator, recorder, before);
    }

    fn jump(&mut self, integrator: &mut I, t: f64, mut jump: Jump<M>) -> Result<State<M>, SimError> {
        carry(integrator, &jump, t, &mut self.restarted, &mut self.buffer);
        // From the consistent state nearest to the crossing where the restart refuses it, as a
        // solve does, the sensitivities' momenta following it.
        let restarted = &mut self.restarted;
        restart_nearest_with(integrator, t, &mut jump.after, |integrator, t, after, projected| {
            if projected {
                momenta(integrator, t, after, restarted);
            }
            integrator.restart_with_sensitivities(t, after, restarted)
        })?;
        Ok(jump.after)
    }

    fn restarted(&mut self, recorder: &Recorder<M>, before: usize) {
        self.rows.as_mut().expect("started").push_restart(&self.restarted, recorder, before);
    }
}

/// The sensitivities recorded sample by sample beside a [`Recorder`]'s samples (each sample's
/// values side by side, contiguous writes), turned into one column per value at the end.
pub(crate) struct SensitivityRows<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    rows: Vec<f64>,
    /// Values a sample: every sensitivity's state.
    series: usize,
    len: usize,
    buffer: State<M>,
    /// The samples whose multipliers' sensitivities the next step completes: the start's, and
    /// those just after a restart.
    incomplete: Vec<usize>,
}

impl<M: LagrangeDirac> SensitivityRows<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Room for `integrator`'s sensitivities at `recorder`'s samples.
    pub fn new<I: Sensitive<M>>(integrator: &I, recorder: &Recorder<M>) -> Result<Self, SimError> {
        let sizes = integrator.model().sizes();
        let len = Layout::new(sizes).len;
        let series = integrator.sensitivity_names().len() * len;
        let rows = recorder.extra_series(series)?;
        Ok(SensitivityRows { rows, series, len, buffer: State::with_sizes(sizes), incomplete: Vec::new() })
    }

    /// The sensitivities at the start, if it is sampled, to be completed by the first step.
    pub fn push_initial<I: Sensitive<M>>(&mut self, integrator: &I, recorder: &Recorder<M>) {
        if recorder.len() > 0 {
            for j in 0..integrator.sensitivity_names().len() {
                integrator.sensitivity(j, &mut self.buffer);
                self.rows.extend(self.buffer.components());
            }
            self.incomplete.push(0);
        }
    }

    /// The sensitivities at the samples from `before` on, each within the last step.
    pub fn push_within<I: Sensitive<M>>(&mut self, integrator: &I, recorder: &Recorder<M>, before: usize) {
        for k in before..recorder.len() {
            let ts = recorder.time(k);
            for j in 0..integrator.sensitivity_names().len() {
                if ts >= integrator.t() {
                    integrator.sensitivity(j, &mut self.buffer);
                } else {
                    integrator.interpolate_sensitivity(j, ts, &mut self.buffer);
                }
                self.rows.extend(self.buffer.components());
            }
        }
    }

    /// `sensitivities` at the samples from `before` on, taken where the integration restarts
    /// with them: their multipliers' parts are completed by the next step.
    pub fn push_restart(&mut self, sensitivities: &[State<M>], recorder: &Recorder<M>, before: usize) {
        for k in before..recorder.len() {
            for s in sensitivities {
                self.rows.extend(s.components());
            }
            self.incomplete.push(k);
        }
    }

    /// Completes the multipliers' sensitivities of the samples at the start of the step just
    /// taken from that step (see [`Sensitive::complete_initial_sensitivity`]).
    pub fn complete<I: Sensitive<M>>(&mut self, integrator: &I) {
        let (series, len) = (self.series, self.len);
        for k in self.incomplete.drain(..) {
            for j in 0..integrator.sensitivity_names().len() {
                let row = &mut self.rows[k * series + j * len..k * series + (j + 1) * len];
                for (x, &v) in self.buffer.components_mut().zip(row.iter()) {
                    *x = v;
                }
                integrator.complete_initial_sensitivity(j, &mut self.buffer);
                for (x, &v) in row.iter_mut().zip(self.buffer.components()) {
                    *x = v;
                }
            }
        }
    }

    /// The solution, with a column per sensitivity value.
    pub fn finish<I: Sensitive<M>>(
        self,
        integrator: &mut I,
        recorder: Recorder<M>,
    ) -> Result<Solution<M, I::Stats>, SimError> {
        let (rows, series, samples) = (self.rows, self.series, recorder.len());
        let columns = (0..series).map(|i| (0..samples).map(|k| rows[k * series + i]).collect()).collect();
        let names = integrator.sensitivity_names().to_vec();
        let solution = recorder.finish_from(integrator)?;
        Ok(solution.with_sensitivities(names, columns))
    }
}

/// Each sensitivity just before the jump at `t`, carried across it, into `out`: positions and
/// velocities by its saltation matrix (and a parameter's column), momenta by the Legendre map
/// at the state after it ([`momenta`]), multipliers zero.
pub(crate) fn carry<M: Hybrid + Parameters, I: Sensitive<M>>(
    integrator: &I,
    jump: &Jump<M>,
    t: f64,
    out: &mut [State<M>],
    buffer: &mut State<M>,
) where
    DefaultAllocator: Storage<M>,
{
    let n = integrator.model().sizes().nq;
    let mut x = DVector::<f64>::zeros(2 * n);
    for (j, s) in out.iter_mut().enumerate() {
        integrator.interpolate_sensitivity(j, t, buffer);
        x.rows_mut(0, n).copy_from_slice(buffer.q.as_slice());
        x.rows_mut(n, n).copy_from_slice(buffer.v.as_slice());
        let mut y = &jump.matrix * &x;
        if let Some(k) = integrator.sensitivity_parameter(j) {
            y += jump.parameters.column(k);
        }
        s.q.copy_from_slice(y.rows(0, n).as_slice());
        s.v.copy_from_slice(y.rows(n, n).as_slice());
        s.lambda.fill(0.0);
    }
    momenta(integrator, t, &jump.after, out);
}

/// The momenta's part of each sensitivity in `out`, from its positions' and velocities' by the
/// Legendre map at the state `after`: `s_p = L_vq s_q + L_vv s_v + ∂(∂L/∂v)/∂θ`.
pub(crate) fn momenta<M: Hybrid + Parameters, I: Sensitive<M>>(
    integrator: &I,
    t: f64,
    after: &State<M>,
    out: &mut [State<M>],
) where
    DefaultAllocator: Storage<M>,
{
    let model = integrator.model();
    let sizes = model.sizes();
    let shape = model.shape();
    let mut l_vq = <M::Algebra as crate::algebra::Algebra<M>>::zeros_qq(&shape);
    let mut l_vv = <M::Algebra as crate::algebra::Algebra<M>>::zeros_qq(&shape);
    model.l_vq(t, &after.q, &after.v, &mut l_vq);
    model.l_vv(t, &after.q, &after.v, &mut l_vv);
    let mut blocks = ResidualBlocks::<M>::with_sizes(&sizes);
    for (j, s) in out.iter_mut().enumerate() {
        s.p.fill(0.0);
        if let Some(k) = integrator.sensitivity_parameter(j) {
            model.residual_blocks_dtheta(k, t, &after.q, &after.v, &after.lambda, &mut blocks);
            s.p.copy_from(&blocks.dl_dv);
        }
        <M::Algebra as crate::algebra::Algebra<M>>::qq_mul(&l_vq, 1.0, s.q.as_slice(), s.p.as_mut_slice());
        <M::Algebra as crate::algebra::Algebra<M>>::qq_mul(&l_vv, 1.0, s.v.as_slice(), s.p.as_mut_slice());
    }
}
