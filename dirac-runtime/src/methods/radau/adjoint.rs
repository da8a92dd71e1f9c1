//! The discrete adjoint of a Radau IIA integration: the gradient of one objective with respect
//! to every parameter and every initial value at once, by a backward sweep over the recorded
//! steps, exact to round-off for the discrete solution (so it agrees with the forward
//! sensitivities of the same run, not only with the tolerance).
//!
//! A step from `y_n` solves, for its stage values `Y_k = y_n + Z_k` (`y_{n+1} = Y_3`),
//!
//! ```text
//! R_k(Y, y_n, θ) = M (Y_k − y_n) − h Σ_j a_kj f(t_n + c_j h, Y_j, θ) = 0,   k = 1, 2, 3.
//! ```
//!
//! With `Ȳ` the objective's gradient with respect to the stage values (the next step's
//! `ȳ_{n+1}` at `Y_3`, and the running cost's quadrature weights at each stage), the step's
//! adjoint is the transposed stage system `(∂R/∂Y)ᵀ μ = Ȳ`, whose blocks are
//! `δ_jk M − h a_kj J_jᵀ` with `J_j = ∂f/∂y` at stage `j`; then
//!
//! ```text
//! ȳ_n = M Σ_k μ_k,    θ̄ += Σ_j ω_jᵀ ∂f/∂θ(Y_j),    ω_j = h Σ_k a_kj μ_k,
//! ```
//!
//! the last one by the model's transposed parameter blocks
//! ([`Parameters::residual_blocks_vjp_dtheta`]), every parameter in one call. The sweep ends
//! with the transpose of the consistent initial sensitivities' map, which carries `ȳ_0` to
//! the initial positions and velocities and adds the parameters' part of the initial state.
//!
//! The transposed stage system is condensed by the Lagrange-Dirac structure as the forward
//! one is ([`Sweep::step`]), to the momenta's and multipliers' adjoints of the three stages:
//! `3 (n + m)` unknowns, whose matrix is the transpose of the forward coupled one, factored
//! once a step: dense for a model stored dense, in compressed columns by the sparse LU for one
//! stored sparse (its pattern fixed by the blocks', ordered once). Nothing allocates in a
//! backward step.

use nalgebra::{DVector, DefaultAllocator, Dyn};

mod checkpoints;
mod held;
mod record;

use self::checkpoints::Checkpoints;
use super::Radau;
#[cfg(feature = "sparse")]
use super::coupled::Entries;
use super::coupled::{Columns, assemble};
use super::stages::three;
use super::tableau::{A, C1, C2, C3};
use crate::algebra::Algebra;
use crate::algebra::lu::Lu;
#[cfg(feature = "sparse")]
use crate::algebra::lu::Singular;
#[cfg(feature = "sparse")]
use crate::algebra::sparse::lu::{Ordering, SparseLu};
use crate::analysis::diagnose::describe_slot;
use crate::error::SimError;
use crate::hybrid::jumps::Jump;
use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
use crate::model::state::State;
use crate::model::{LagrangeDirac, ParameterDerivatives, Parameters};
use crate::shape::dims::{Sizes, Storage, VecQ, VecY};
use crate::shape::layout::Layout;
use crate::simulate::sensitivity::Initial;

/// The most unknowns of the condensed transposed stage system, `3 (n + m)`, of a model stored
/// dense: 1200 keeps its matrix at 11.5 MB and its factorisation under a second a step. A model
/// stored sparse has its transposed system assembled and factored sparse, whatever its size.
pub const DENSE_LIMIT: usize = 1200;

/// An objective's gradient with respect to a state, written into `out` (zeroed before each
/// call, so that a closure writes only the parts it depends on), and its value returned.
pub type StateFunction<'f, M> = &'f dyn Fn(f64, &State<M>, &mut State<M>) -> f64;

/// A cost at one of an objective's sample times: the closure gets the sample's index `k`, its
/// time and the state there, writes the cost's gradient with respect to that state into `out`
/// (zeroed before each call) and returns the cost.
pub type SampleFunction<'f, M> = &'f dyn Fn(usize, f64, &State<M>, &mut State<M>) -> f64;

/// The objective `G = g(t_N, y_N) + Σ_k g_k(y(t_k)) + ∫ r(t, y) dt` of an adjoint sweep, over
/// the discrete solution: `g` at the last step's end, each `g_k` at a sample time `t_k` on the
/// collocation polynomial of the step that holds it (the values
/// [`DenseOutput::Collocation`](crate::methods::radau::DenseOutput::Collocation) samples), and
/// the running cost `r` integrated by the method's own quadrature over each step's stages
/// (`h Σ_j b_j r(t_j, Y_j)`, of order 5), so that its gradient is exact for what is computed.
pub struct Objective<'f, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    terminal: Option<StateFunction<'f, M>>,
    samples: Option<(&'f [f64], SampleFunction<'f, M>)>,
    running: Option<StateFunction<'f, M>>,
}

impl<'f, M: LagrangeDirac> Objective<'f, M>
where
    DefaultAllocator: Storage<M>,
{
    /// A terminal cost `g(t_N, y_N)`: the closure returns its value and writes `∂g/∂y`.
    pub fn terminal(g: StateFunction<'f, M>) -> Self {
        Objective { terminal: Some(g), samples: None, running: None }
    }

    /// A running cost `∫ r(t, y) dt` alone: the closure returns `r` and writes `∂r/∂y`.
    pub fn running(r: StateFunction<'f, M>) -> Self {
        Objective { terminal: None, samples: None, running: Some(r) }
    }

    /// Costs `Σ_k g_k(y(t_k))` at the sample `times` alone (ascending, within the run): what a
    /// fit to measurements sums. The closure gets `k`, `t_k` and the state there.
    pub fn samples(times: &'f [f64], g: SampleFunction<'f, M>) -> Self {
        Objective { terminal: None, samples: Some((times, g)), running: None }
    }

    /// This objective with costs at sample times added.
    pub fn with_samples(mut self, times: &'f [f64], g: SampleFunction<'f, M>) -> Self {
        self.samples = Some((times, g));
        self
    }

    /// This objective with a running cost added.
    pub fn with_running(mut self, r: StateFunction<'f, M>) -> Self {
        self.running = Some(r);
        self
    }
}

/// One accepted step: where it started, its size and its stage increments.
pub(super) struct Step<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    pub t: f64,
    pub h: f64,
    pub y: VecY<M>,
    pub z: [VecY<M>; 3],
}

impl<M: LagrangeDirac> Step<M>
where
    DefaultAllocator: Storage<M>,
{
    pub fn zeros(sizes: Sizes) -> Self {
        Step { t: 0.0, h: 0.0, y: sizes.zeros_y::<M>(), z: three(sizes) }
    }
}

/// A Radau integration recorded for adjoint sweeps: the consistent start, the end, and
/// either every accepted step's start, size and stages, `4 (3n + m)` numbers a step
/// ([`Radau::record`]), or checkpoints within a memory budget and every step's size
/// ([`Radau::record_within`]).
pub struct Recording<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    t0: f64,
    start: State<M>,
    t_end: f64,
    end: VecY<M>,
    kept: Kept<M>,
    /// The impacts, in order, each after the step it cut short.
    impacts: Vec<Cut<M>>,
    /// The inputs held between samples ([`Radau::record_held`]), if any.
    held: Option<held::Segments>,
}

/// An impact in a recording: step `step` reached past it and was cut at `t`, where the run
/// jumped and restarted.
struct Cut<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    step: usize,
    t: f64,
    jump: Jump<M>,
}

/// What a recording keeps of its steps.
enum Kept<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// Every step, whole.
    Whole(Vec<Step<M>>),
    /// Checkpoints, the steps between them solved again in the sweep.
    Checkpointed(Checkpoints<M>),
}

/// The gradient of an objective with respect to everything the run depends on.
#[derive(Clone)]
pub struct Gradient<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// The objective's value on the recorded run.
    pub value: f64,
    /// `∂G/∂θ_k` for every parameter, in the order of
    /// [`parameter_names`](crate::model::Named::parameter_names).
    pub parameters: Vec<f64>,
    /// `∂G/∂q₀(i)`: with respect to each initial position, through the consistent start, as
    /// [`Sensitivities::initial_position`](crate::simulate::sensitivity::Sensitivities::initial_position) seeds it.
    pub positions: VecQ<M>,
    /// `∂G/∂v₀(i)`, as [`Sensitivities::initial_velocity`](crate::simulate::sensitivity::Sensitivities::initial_velocity)
    /// seeds it.
    pub velocities: VecQ<M>,
    /// `∂G/∂u_k` for each input held between samples ([`Radau::record_held`]), in the order
    /// given there, at each of its samples `k`; empty for a run that held none.
    pub inputs: Vec<Vec<f64>>,
    /// The model's parameter and coordinate names, for reading by name.
    names: (Vec<String>, Vec<String>),
}

impl<M: LagrangeDirac> Gradient<M>
where
    DefaultAllocator: Storage<M>,
{
    /// `∂G/∂θ` for the parameter with this dotted name (`"gear.ratio"`), if the model has one.
    pub fn parameter(&self, name: &str) -> Option<f64> {
        self.names.0.iter().position(|p| p == name).map(|k| self.parameters[k])
    }

    /// `∂G/∂q₀` for the coordinate with this name (`"load.phi"`), if the model has one.
    pub fn position(&self, name: &str) -> Option<f64> {
        self.names.1.iter().position(|c| c == name).map(|i| self.positions[i])
    }

    /// `∂G/∂v₀` for the coordinate with this name, if the model has one.
    pub fn velocity(&self, name: &str) -> Option<f64> {
        self.names.1.iter().position(|c| c == name).map(|i| self.velocities[i])
    }

    /// The parameters' names and their components of the gradient, in order.
    pub fn parameters_by_name(&self) -> impl Iterator<Item = (&str, f64)> {
        self.names.0.iter().map(String::as_str).zip(self.parameters.iter().copied())
    }
}

impl<M: LagrangeDirac> std::fmt::Debug for Gradient<M>
where
    DefaultAllocator: Storage<M>,
{
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Gradient")
            .field("value", &self.value)
            .field("parameters", &self.parameters)
            .field("positions", &self.positions.as_slice())
            .field("velocities", &self.velocities.as_slice())
            .field("inputs", &self.inputs)
            .finish()
    }
}

impl<M: LagrangeDirac> std::fmt::Debug for Recording<M>
where
    DefaultAllocator: Storage<M>,
{
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Recording")
            .field("t0", &self.t0)
            .field("t_end", &self.t_end)
            .field("steps", &self.steps())
            .field("bytes", &self.bytes())
            .finish()
    }
}

impl<M: LagrangeDirac> Recording<M>
where
    DefaultAllocator: Storage<M>,
{
    /// The number of recorded steps.
    pub fn steps(&self) -> usize {
        match &self.kept {
            Kept::Whole(steps) => steps.len(),
            Kept::Checkpointed(checkpoints) => checkpoints.steps(),
        }
    }

    /// The bytes the recording holds for its steps: what
    /// [`record_within`](Radau::record_within)'s budget bounds, with the steps' sizes.
    pub fn bytes(&self) -> usize {
        match &self.kept {
            Kept::Whole(steps) => {
                let state = std::mem::size_of::<f64>() * self.end.len();
                steps.len() * (4 * state + std::mem::size_of::<Step<M>>())
            }
            Kept::Checkpointed(checkpoints) => checkpoints.bytes(),
        }
    }

    /// The state at the end of the run.
    pub fn end(&self, model: &M) -> State<M> {
        State::from_y(model.sizes(), &self.end)
    }

    /// The objective's gradient with respect to every parameter of `model` (the model the run
    /// was recorded with) and every initial position and velocity, by one backward sweep.
    pub fn gradient(&self, model: &M, objective: &Objective<'_, M>) -> Result<Gradient<M>, SimError>
    where
        M: Parameters,
    {
        if self.held.is_some() {
            return Err(SimError::InvalidOption {
                what: "adjoint",
                reason: "the run held inputs between samples (`record_held`): take its gradient with \
                         `gradient_held`, which sets them step by step"
                    .into(),
            });
        }
        self.sweep_back(&|_| model, objective, None)
    }

    /// The backward sweep of [`gradient`](Self::gradient), with the model of each recorded step
    /// (by its index) from `model_at`, and the held inputs' gradients accumulated by `inputs`.
    fn sweep_back<'a>(
        &self,
        model_at: &dyn Fn(usize) -> &'a M,
        objective: &Objective<'_, M>,
        mut inputs: Option<held::Accumulator<'_, M>>,
    ) -> Result<Gradient<M>, SimError>
    where
        M: Parameters + 'a,
    {
        let model = model_at(0);
        let sizes = model.sizes();
        if let Some((times, _)) = objective.samples {
            let slack = 1e-12 * self.t_end.abs().max(1.0);
            let inside = |t: f64| t >= self.t0 && t <= self.t_end + slack;
            if !times.is_sorted() || !times.iter().all(|&t| inside(t)) {
                return Err(SimError::InvalidOption {
                    what: "samples",
                    reason: format!(
                        "an objective's sample times must ascend within the run, [{}, {}]",
                        self.t0, self.t_end
                    ),
                });
            }
        }
        if !self.impacts.is_empty() && objective.running.is_some() {
            return Err(SimError::InvalidOption {
                what: "adjoint",
                reason: "a running cost over a run with impacts or switching surfaces crossed: the steps \
                         cut short there would count past the crossing; sample the cost instead \
                         (`Objective::samples`)"
                    .into(),
            });
        }
        let derivatives = ParameterDerivatives::<M>::of();
        let mut sweep = Sweep::new(model, derivatives)?;
        if let Some(inputs) = &inputs {
            sweep.inputs = Some(inputs.rates);
            sweep.input_rates = vec![0.0; sizes.nq * inputs.count];
            sweep.input_bar = vec![0.0; inputs.count];
        }
        sweep.remaining = objective.samples.map_or(0, |(times, _)| times.len());
        let mut value = 0.0;
        let mut bar = sizes.zeros_y::<M>();
        if let Some(g) = objective.terminal {
            let end = self.end(model);
            zero(&mut sweep.dg);
            value += g(self.t_end, &end, &mut sweep.dg);
            sweep.dg.write_y(&mut bar);
            finite(model, self.t_end, value, &bar, "the terminal cost")?;
        }
        match &self.kept {
            Kept::Whole(steps) => {
                let mut impacts = self.impacts.iter().rev().peekable();
                for (k, step) in steps.iter().enumerate().rev() {
                    if let Some(cut) = impacts.next_if(|cut| cut.step == k) {
                        sweep.cross_back(model_at(k + 1), cut, &mut bar);
                    }
                    value += sweep.step(model_at(k), step, objective, &mut bar)?;
                    if let Some(inputs) = &mut inputs {
                        inputs.add(k, &mut sweep.input_bar);
                    }
                }
            }
            Kept::Checkpointed(checkpoints) => {
                value += checkpoints.sweep(model, &mut sweep, objective, &mut bar)?;
            }
        }
        // Samples at the start itself.
        if let Some((times, g)) = objective.samples {
            for (k, &t) in times.iter().enumerate().take(sweep.remaining) {
                zero(&mut sweep.dg);
                let cost = g(k, t, &self.start, &mut sweep.dg);
                value += cost;
                sweep.dg.write_y(&mut sweep.yj);
                finite(model, t, cost, &sweep.yj, "a sampled cost")?;
                bar += &sweep.yj;
            }
        }
        let mut positions = sizes.zeros_q::<M>();
        let mut velocities = sizes.zeros_q::<M>();
        let mut initial = Initial::new(model, derivatives, self.t0, &self.start)?;
        sweep.stage.read_y(&bar);
        initial.transpose(&sweep.stage, &mut sweep.theta, &mut positions, &mut velocities);
        let names = model.parameter_names();
        if let Some(k) = sweep.theta.iter().position(|g| !g.is_finite()) {
            let component = format!("the gradient with respect to parameter {}", names[k]);
            return Err(SimError::NonFinite { t: self.t0, component });
        }
        if let Some(i) = positions.iter().chain(velocities.iter()).position(|g| !g.is_finite()) {
            let what = if i < positions.len() { "position" } else { "velocity" };
            let name = &model.coordinate_names()[i % positions.len()];
            let component = format!("the gradient with respect to the initial {what} of {name}");
            return Err(SimError::NonFinite { t: self.t0, component });
        }
        let inputs = inputs.map_or_else(Vec::new, held::Accumulator::finish);
        let names = (names, model.coordinate_names());
        Ok(Gradient { value, parameters: sweep.theta, positions, velocities, inputs, names })
    }
}

/// The backward sweep's work space, made once.
pub(super) struct Sweep<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    layout: Layout,
    derivatives: ParameterDerivatives<M>,
    /// The Jacobian blocks at the three stages.
    jac: [JacobianBlocks<M, M::Algebra>; 3],
    /// The condensed transposed stage system's factors, `3 (n + m)` square.
    factors: Factors,
    /// Its right-hand side, then its solution `(μ_p, −ν_λ)` stage by stage.
    x: DVector<f64>,
    /// `Ȳ_j`, the objective's gradient with respect to each stage value.
    ybar: [VecY<M>; 3],
    /// `ν_j = h Σ_k a_kj μ_k` at each stage.
    nu: [VecY<M>; 3],
    /// The stage states `Y_j = y_n + z_j`.
    at: [State<M>; 3],
    /// The objective's samples not yet reached, going back: the first `remaining`.
    remaining: usize,
    /// The samples' gradient with respect to a step's start directly (not through its stages).
    direct: VecY<M>,
    stage: State<M>,
    yj: VecY<M>,
    dg: State<M>,
    weights: ResidualBlocks<M>,
    each: Vec<f64>,
    /// `∂G/∂θ`, summed over the steps.
    theta: Vec<f64>,
    /// The gradient with respect to the state at an impact within the next step back, and its
    /// time ([`Sweep::cross_back`]).
    injected: Option<f64>,
    inject: VecY<M>,
    /// `∂ṗ/∂u` of the model's inputs, where inputs are held ([`Radau::record_held`]), and
    /// its values at a stage (`n × n_u`, column-major).
    inputs: Option<held::InputRates<M>>,
    input_rates: Vec<f64>,
    /// `∂G/∂u` over the last step swept, for every input of the model.
    input_bar: Vec<f64>,
}

impl<M: LagrangeDirac> Sweep<M>
where
    DefaultAllocator: Storage<M>,
{
    fn new(model: &M, derivatives: ParameterDerivatives<M>) -> Result<Self, SimError> {
        let sizes = model.sizes();
        let layout = Layout::new(sizes);
        let count = model.parameter_names().len();
        let shape = model.shape();
        let jac: [JacobianBlocks<M, M::Algebra>; 3] =
            core::array::from_fn(|_| JacobianBlocks::with_shape(&shape));
        let (n, m) = (sizes.nq, sizes.nc);
        let unknowns = 3 * (n + m);
        let factors = if M::Algebra::dense_qq(&jac[0].l_vv).is_some() {
            if unknowns > DENSE_LIMIT {
                return Err(SimError::InvalidOption {
                    what: "adjoint",
                    reason: format!(
                        "the transposed stage system of this model stored dense has {unknowns} unknowns, \
                         above {DENSE_LIMIT}: store it sparse (a model made of arrays of subsystems is)"
                    ),
                });
            }
            Factors::Dense(Lu::new(unknowns))
        } else {
            sparse_factors(&jac, n, m)?
        };
        Ok(Sweep {
            layout,
            derivatives,
            jac,
            factors,
            x: DVector::zeros(3 * (sizes.nq + sizes.nc)),
            ybar: three(sizes),
            nu: three(sizes),
            at: core::array::from_fn(|_| State::with_sizes(sizes)),
            remaining: 0,
            direct: sizes.zeros_y::<M>(),
            stage: State::with_sizes(sizes),
            yj: sizes.zeros_y::<M>(),
            dg: State::with_sizes(sizes),
            weights: ResidualBlocks::with_sizes(&sizes),
            each: vec![0.0; count],
            theta: vec![0.0; count],
            injected: None,
            inject: sizes.zeros_y::<M>(),
            inputs: None,
            input_rates: Vec::new(),
            input_bar: Vec::new(),
        })
    }

    /// Carries `bar`, the gradient with respect to the state just after impact `cut` (where the
    /// run restarted), back across it: the transpose of the forward jump
    /// `s⁺ = S s⁻ + c_θ`, `s_p⁺ = L_vq s_q⁺ + L_vv s_v⁺ + ∂(∂L/∂v)/∂θ`. The parameters' part goes
    /// into `theta`; the part with respect to the state just before the impact waits for the
    /// step it cut short ([`Sweep::step`] reads it on that step's collocation polynomial), and
    /// `bar`, the gradient with respect to that step's end, which the run left, is zero.
    fn cross_back(&mut self, model: &M, cut: &Cut<M>, bar: &mut VecY<M>)
    where
        M: Parameters,
    {
        let l = self.layout;
        let n = l.v - l.q;
        let (t, after) = (cut.t, &cut.jump.after);
        let salt = &cut.jump;
        let shape = model.shape();
        let (mut l_vq, mut l_vv) = (M::Algebra::zeros_qq(&shape), M::Algebra::zeros_qq(&shape));
        model.l_vq(t, &after.q, &after.v, &mut l_vq);
        model.l_vv(t, &after.q, &after.v, &mut l_vv);
        let b = bar.as_slice();
        let mut x = DVector::<f64>::zeros(2 * n);
        x.as_mut_slice()[..n].copy_from_slice(&b[l.q..l.v]);
        x.as_mut_slice()[n..].copy_from_slice(&b[l.v..l.p]);
        let bp = &b[l.p..l.lambda];
        M::Algebra::qq_tr_mul(&l_vq, 1.0, bp, &mut x.as_mut_slice()[..n]);
        M::Algebra::qq_tr_mul(&l_vv, 1.0, bp, &mut x.as_mut_slice()[n..]);
        if !self.theta.is_empty() {
            self.weights.dl_dv.as_mut_slice().copy_from_slice(bp);
            self.weights.momentum_rate.fill(0.0);
            self.weights.constraint_velocity.fill(0.0);
            (self.derivatives.transposed)(
                model,
                t,
                &after.q,
                &after.v,
                &after.lambda,
                &self.weights,
                &mut self.each,
            );
            for (k, theta) in self.theta.iter_mut().enumerate() {
                *theta += self.each[k] + salt.parameters.column(k).dot(&x);
            }
        }
        let before = salt.matrix.tr_mul(&x);
        self.inject.fill(0.0);
        self.inject.as_mut_slice()[l.q..l.v].copy_from_slice(&before.as_slice()[..n]);
        self.inject.as_mut_slice()[l.v..l.p].copy_from_slice(&before.as_slice()[n..]);
        self.injected = Some(t);
        bar.fill(0.0);
    }

    /// Carries `bar` from a step's end (`ȳ_{n+1}`) to its start (`ȳ_n`), adding the
    /// parameters' part into `theta`; returns the running cost's quadrature over the step.
    ///
    /// The transposed stage system `M μ_j − J_jᵀ ν_j = Ȳ_j`, `ν = h (Aᵀ ⊗ I) μ`, condensed by
    /// the elimination that condenses the forward one, transposed: its unknowns are the
    /// momenta's `μ_p` and the multipliers' `−ν_λ` of the three stages, its matrix the
    /// transpose of the forward coupled matrix ([`assemble`]), its right-hand side
    /// `Ȳ_v,j + W_jᵀ Ȳ_p,j + h Σ_k a_kj (Ȳ_q,k + G_kᵀ Ȳ_p,k)` and `Ȳ_λ,j`. The rest follows by
    /// substitution:
    ///
    /// ```text
    /// ν_p,j = h Σ_k a_kj μ_p,k,    ν_v,j = μ_p,j − Ȳ_p,j,
    /// μ_q,j = Ȳ_q,j − G_jᵀ ν_v,j + D_jᵀ ν_p,j + C_jᵀ ν_λ,j,
    /// ```
    ///
    /// with `G = L_vq`, `W = L_vv`, `D = ∂ṗ/∂q`, `E = ∂ṗ/∂v`, `C = ∂(A v)/∂q` at each stage;
    /// `ȳ_n = M Σ_k μ_k` and the parameters' weights are `ν`.
    pub(super) fn step(
        &mut self,
        model: &M,
        step: &Step<M>,
        objective: &Objective<'_, M>,
        bar: &mut VecY<M>,
    ) -> Result<f64, SimError> {
        let l = self.layout;
        let (n, m) = (l.v - l.q, l.len - l.lambda);
        let h = step.h;
        let nodes = [C1, C2, C3];
        let mut value = 0.0;
        for j in 0..3 {
            let t = step.t + nodes[j] * h;
            self.yj.copy_from(&step.y);
            self.yj += &step.z[j];
            self.at[j].read_y(&self.yj);
            let s = &self.at[j];
            model.jacobian_blocks(t, &s.q, &s.v, &s.lambda, &mut self.jac[j]);
            if j == 2 {
                self.ybar[j].copy_from(bar);
            } else {
                self.ybar[j].fill(0.0);
            }
            if let Some(r) = objective.running {
                // The quadrature h Σ_j b_j r(t_j, Y_j), b_j = a_3j.
                let b = h * A[2][j];
                zero(&mut self.dg);
                let cost = r(t, s, &mut self.dg);
                value += b * cost;
                self.dg.write_y(&mut self.yj);
                finite(model, t, cost, &self.yj, "the running cost")?;
                self.ybar[j].axpy(b, &self.yj, 1.0);
            }
        }
        // The samples within the step, `t_n < t_k ≤ t_n + h` (the last step takes every one
        // left), on the collocation polynomial `u(s) = y_n + Σ_j ℓ_j(s) z_j`: their gradient
        // reaches the stages by `ℓ_j(s)` and the start by `1 − Σ_j ℓ_j(s)`.
        let mut direct = false;
        if let Some((times, g)) = objective.samples {
            let first = times[..self.remaining].partition_point(|&t| t <= step.t);
            for (k, &t) in times.iter().enumerate().take(self.remaining).skip(first) {
                let ell = lagrange(((t - step.t) / h).min(1.0));
                self.yj.copy_from(&step.y);
                for (l, z) in ell.iter().zip(&step.z) {
                    self.yj.axpy(*l, z, 1.0);
                }
                self.stage.read_y(&self.yj);
                zero(&mut self.dg);
                let cost = g(k, t, &self.stage, &mut self.dg);
                value += cost;
                self.dg.write_y(&mut self.yj);
                finite(model, t, cost, &self.yj, "a sampled cost")?;
                for (l, ybar) in ell.iter().zip(self.ybar.iter_mut()) {
                    ybar.axpy(*l, &self.yj, 1.0);
                }
                if !direct {
                    self.direct.fill(0.0);
                    direct = true;
                }
                self.direct.axpy(1.0 - ell.iter().sum::<f64>(), &self.yj, 1.0);
            }
            self.remaining = first;
        }
        // An impact cut this step short: the gradient with respect to the state there, on the
        // collocation polynomial as a sample's.
        if let Some(t) = self.injected.take() {
            let ell = lagrange(((t - step.t) / h).min(1.0));
            for (l, ybar) in ell.iter().zip(self.ybar.iter_mut()) {
                ybar.axpy(*l, &self.inject, 1.0);
            }
            if !direct {
                self.direct.fill(0.0);
                direct = true;
            }
            self.direct.axpy(1.0 - ell.iter().sum::<f64>(), &self.inject, 1.0);
        }
        let p_at = |j: usize| j * (n + m);
        let lambda_at = |j: usize| j * (n + m) + n;
        let factored = match &mut self.factors {
            Factors::Dense(lu) => {
                let mat = lu.matrix_mut();
                mat.fill(0.0);
                let size = 3 * (n + m);
                assemble(&self.jac, h, n, m, &mut Columns { mat: mat.as_mut_slice(), size });
                mat.transpose_mut();
                lu.factor()
            }
            #[cfg(feature = "sparse")]
            Factors::Sparse(sparse) => sparse.factor(&self.jac, h, n, m),
        };
        factored.map_err(|_| SimError::SingularMatrix {
            t: step.t,
            h,
            detail: "the transposed stage system of the adjoint sweep".into(),
        })?;
        let x = self.x.as_mut_slice();
        for j in 0..3 {
            let rows = &mut x[p_at(j)..p_at(j) + n];
            let ybar = self.ybar[j].as_slice();
            rows.copy_from_slice(&ybar[l.v..l.p]);
            M::Algebra::qq_tr_mul(&self.jac[j].l_vv, 1.0, &ybar[l.p..l.lambda], rows);
            for (k, jk) in self.jac.iter().enumerate() {
                let c = h * A[k][j];
                let yk = self.ybar[k].as_slice();
                M::Algebra::qq_tr_mul(&jk.l_vq, c, &yk[l.p..l.lambda], rows);
                for (r, y) in rows.iter_mut().zip(&yk[l.q..l.v]) {
                    *r += c * y;
                }
            }
            x[lambda_at(j)..lambda_at(j) + m].copy_from_slice(&ybar[l.lambda..l.len]);
        }
        match &mut self.factors {
            Factors::Dense(lu) => lu.solve_slice(self.x.as_mut_slice()),
            #[cfg(feature = "sparse")]
            Factors::Sparse(sparse) => sparse.lu.solve(self.x.as_mut_slice()),
        }
        // ν at every stage (and μ_p, μ_q), by the substitutions; ȳ_n = M Σ_k μ_k.
        let x = self.x.as_slice();
        bar.fill(0.0);
        for j in 0..3 {
            let nu = self.nu[j].as_mut_slice();
            let ybar = self.ybar[j].as_slice();
            for (c, v) in nu[l.p..l.lambda].iter_mut().enumerate() {
                *v = h * (0..3).map(|k| A[k][j] * x[p_at(k) + c]).sum::<f64>();
            }
            for (v, xi) in nu[l.lambda..l.len].iter_mut().zip(&x[lambda_at(j)..lambda_at(j) + m]) {
                *v = -xi;
            }
            let mu_p = &x[p_at(j)..p_at(j) + n];
            for ((v, mu), y) in nu[l.v..l.p].iter_mut().zip(mu_p).zip(&ybar[l.p..l.lambda]) {
                *v = mu - y;
            }
            let b = bar.as_mut_slice();
            for (bi, mu) in b[l.p..l.lambda].iter_mut().zip(mu_p) {
                *bi += mu;
            }
            // μ_q,j into ȳ_n's positions.
            let (nu_v, rest) = nu[l.v..].split_at(l.p - l.v);
            let (nu_p, nu_lambda) = rest.split_at(l.lambda - l.p);
            let bq = &mut b[l.q..l.v];
            for (bi, y) in bq.iter_mut().zip(&ybar[l.q..l.v]) {
                *bi += y;
            }
            let jj = &self.jac[j];
            M::Algebra::qq_tr_mul(&jj.l_vq, -1.0, nu_v, bq);
            M::Algebra::qq_tr_mul(&jj.dpdot_dq, 1.0, nu_p, bq);
            M::Algebra::cq_tr_mul(&jj.dav_dq, 1.0, nu_lambda, bq);
        }
        if direct {
            *bar += &self.direct;
        }
        if let Some(i) = bar.iter().position(|g| !g.is_finite()) {
            let component = format!("the adjoint of {}", describe_slot(model, i));
            return Err(SimError::NonFinite { t: step.t, component });
        }
        if let Some(rates) = self.inputs {
            // ū += Σ_j ν_p,jᵀ ∂ṗ/∂u(Y_j): a held input enters the forces only.
            let count = self.input_bar.len();
            for (j, node) in nodes.iter().enumerate() {
                rates(model, step.t + node * h, &self.at[j], &mut self.input_rates);
                let nu_p = &self.nu[j].as_slice()[l.p..l.lambda];
                for (i, ubar) in self.input_bar.iter_mut().enumerate().take(count) {
                    let column = &self.input_rates[i * n..(i + 1) * n];
                    *ubar += column.iter().zip(nu_p).map(|(d, w)| d * w).sum::<f64>();
                }
            }
        }
        if self.theta.is_empty() {
            return Ok(value);
        }
        // θ̄ += Σ_j ν_jᵀ ∂f/∂θ(Y_j), the flat ∂f/∂θ being (0, −∂(∂L/∂v)/∂θ, ∂ṗ/∂θ, ∂(A v + b)/∂θ).
        for (j, node) in nodes.iter().enumerate() {
            let t = step.t + node * h;
            let nu = self.nu[j].as_slice();
            for (w, v) in self.weights.dl_dv.iter_mut().zip(&nu[l.v..l.p]) {
                *w = -v;
            }
            self.weights.momentum_rate.as_mut_slice().copy_from_slice(&nu[l.p..l.lambda]);
            self.weights.constraint_velocity.as_mut_slice().copy_from_slice(&nu[l.lambda..l.len]);
            let s = &self.at[j];
            (self.derivatives.transposed)(model, t, &s.q, &s.v, &s.lambda, &self.weights, &mut self.each);
            for (theta, d) in self.theta.iter_mut().zip(&self.each) {
                *theta += d;
            }
        }
        Ok(value)
    }
}

/// The factors of the condensed transposed stage system.
// One per sweep: the variants' sizes differ, but no array of them is made.
#[allow(clippy::large_enum_variant)]
enum Factors {
    /// Of a model stored dense: the matrix assembled dense, transposed and factored.
    Dense(Lu<f64, Dyn>),
    /// Of a model stored sparse: assembled into the transpose's compressed columns.
    #[cfg(feature = "sparse")]
    Sparse(SparseTransposed),
}

/// The factors of a model whose blocks are not stored dense.
#[cfg(feature = "sparse")]
fn sparse_factors<M: LagrangeDirac>(
    jac: &[JacobianBlocks<M, M::Algebra>; 3],
    n: usize,
    m: usize,
) -> Result<Factors, SimError>
where
    DefaultAllocator: Storage<M>,
{
    Ok(Factors::Sparse(SparseTransposed::new(jac, n, m)))
}

/// The factors of a model whose blocks are not stored dense: sparse storage is the feature
/// `sparse`'s, so without it every algebra is dense and this is not reached but by an algebra
/// of the user's own.
#[cfg(not(feature = "sparse"))]
fn sparse_factors<M: LagrangeDirac>(
    _: &[JacobianBlocks<M, M::Algebra>; 3],
    _: usize,
    _: usize,
) -> Result<Factors, SimError>
where
    DefaultAllocator: Storage<M>,
{
    Err(SimError::InvalidOption {
        what: "adjoint",
        reason: "this model's blocks are not stored dense, and the sparse adjoint needs the feature `sparse` of dirac".into(),
    })
}

/// The transpose of the forward coupled matrix in compressed columns, whose pattern the
/// blocks' patterns fix (every coefficient of the method is nonzero), ordered once and
/// refactored each step by the sparse LU the saddle-point systems use.
#[cfg(feature = "sparse")]
struct SparseTransposed {
    /// The slot among the values of each entry [`assemble`] adds, in the order it adds them
    /// (the same every step: it follows the blocks' patterns), so that a step's assembly
    /// scatters without searching.
    slots: Vec<usize>,
    lu: SparseLu<f64>,
}

#[cfg(feature = "sparse")]
impl SparseTransposed {
    /// The pattern from the stage Jacobians' patterns, and its ordering.
    fn new<M: LagrangeDirac>(jac: &[JacobianBlocks<M, M::Algebra>; 3], n: usize, m: usize) -> Self
    where
        DefaultAllocator: Storage<M>,
    {
        /// Every entry the coupled matrix stores, as `(column, row)` of its transpose.
        struct Pattern(Vec<(usize, usize)>);
        impl Entries for Pattern {
            fn add(&mut self, row: usize, column: usize, _: f64) {
                self.0.push((row, column));
            }
        }
        let size = 3 * (n + m);
        let mut pattern = Pattern(Vec::new());
        // Unit coefficients: the pattern, whatever the step size.
        assemble(jac, 1.0, n, m, &mut pattern);
        let mut entries = pattern.0;
        entries.sort_unstable();
        entries.dedup();
        let mut col_ptr = vec![0usize; size + 1];
        for &(column, _) in &entries {
            col_ptr[column + 1] += 1;
        }
        for c in 0..size {
            col_ptr[c + 1] += col_ptr[c];
        }
        let rows: Vec<usize> = entries.into_iter().map(|(_, row)| row).collect();
        /// The slot of each entry added, in order: the coupled matrix's `(row, column)` is the
        /// transpose's `(column, row)`.
        struct Slots<'a> {
            col_ptr: &'a [usize],
            rows: &'a [usize],
            slots: Vec<usize>,
        }
        impl Entries for Slots<'_> {
            fn add(&mut self, row: usize, column: usize, _: f64) {
                let span = self.col_ptr[row]..self.col_ptr[row + 1];
                let at = self.rows[span.clone()].binary_search(&column).expect("an entry of the pattern");
                self.slots.push(span.start + at);
            }
        }
        let mut slots = Slots { col_ptr: &col_ptr, rows: &rows, slots: Vec::new() };
        assemble(jac, 1.0, n, m, &mut slots);
        let slots = slots.slots;
        let order = Ordering::new(size, col_ptr, rows);
        SparseTransposed { slots, lu: SparseLu::new(std::sync::Arc::new(order)) }
    }

    /// Assembles the transpose of the coupled matrix of a step of size `h` and factors it.
    fn factor<M: LagrangeDirac>(
        &mut self,
        jac: &[JacobianBlocks<M, M::Algebra>; 3],
        h: f64,
        n: usize,
        m: usize,
    ) -> Result<(), Singular>
    where
        DefaultAllocator: Storage<M>,
    {
        /// Each entry added into its slot, in the order of [`SparseTransposed::slots`].
        struct Scatter<'a> {
            slots: std::slice::Iter<'a, usize>,
            values: &'a mut [f64],
        }
        impl Entries for Scatter<'_> {
            fn add(&mut self, _: usize, _: usize, value: f64) {
                if let Some(&slot) = self.slots.next() {
                    self.values[slot] += value;
                }
            }
        }
        let (_, values) = self.lu.pattern_and_values();
        values.fill(0.0);
        let mut scatter = Scatter { slots: self.slots.iter(), values };
        assemble(jac, h, n, m, &mut scatter);
        debug_assert!(scatter.slots.next().is_none(), "as many entries as the pattern's pass");
        self.lu.factor()
    }
}

/// The collocation polynomial's weights `ℓ_j(s)` of the stage increments at `s` step sizes
/// into a step: `ℓ_j(s) = (s / c_j) Π_{k ≠ j} (s − c_k) / (c_j − c_k)`, zero at `s = 0` and one
/// at `s = c_j`.
fn lagrange(s: f64) -> [f64; 3] {
    let c = [C1, C2, C3];
    core::array::from_fn(|j| {
        let (a, b) = (c[(j + 1) % 3], c[(j + 2) % 3]);
        s / c[j] * (s - a) / (c[j] - a) * (s - b) / (c[j] - b)
    })
}

/// A [`SimError::NonFinite`] at `t` if an objective's `value` or its gradient `dy` is not
/// finite, naming the first component that is not.
fn finite<M: LagrangeDirac>(model: &M, t: f64, value: f64, dy: &VecY<M>, what: &str) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    if !value.is_finite() {
        return Err(SimError::NonFinite { t, component: format!("the value of {what}") });
    }
    match dy.iter().position(|g| !g.is_finite()) {
        None => Ok(()),
        Some(i) => {
            let component = format!("the derivative of {what} with respect to {}", describe_slot(model, i));
            Err(SimError::NonFinite { t, component })
        }
    }
}

/// Zeroes every part of a state, in place.
fn zero<M: LagrangeDirac>(s: &mut State<M>)
where
    DefaultAllocator: Storage<M>,
{
    s.q.fill(0.0);
    s.v.fill(0.0);
    s.p.fill(0.0);
    s.lambda.fill(0.0);
}
