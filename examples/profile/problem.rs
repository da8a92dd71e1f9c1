//! The recovery of `examples/profile_recovery.rs`, shared with its test: the inductance of
//! every cell of an LC ladder recovered from the flux waveforms at a few of its nodes, by
//! L-BFGS (the `argmin` crate) on the gradient of the misfit from one adjoint sweep.
//!
//! The misfit of a profile is `χ²/2` of the waveforms, `½ Σ_s Σ_k (x_s(t_k) − d_s,k)² / σ²` over
//! the sensors `s` and the sample times `t_k`: the sampled costs of one [`Objective`], whose
//! gradient with respect to every parameter one recorded run and one backward sweep give. The unknowns are the
//! logarithms of the inductances (which keeps them positive), with a small penalty on the
//! differences of neighbours where the data are noisy.

#![allow(dead_code)]

use std::cell::{Cell as Counter, RefCell};

use argmin::core::{CostFunction, Error, Executor, Gradient, State as _};
use argmin::solver::linesearch::MoreThuenteLineSearch;
use argmin::solver::quasinewton::LBFGS;
use dirac::State;
use dirac::adjoint::Objective;
use dirac::prelude::*;

/// One section: a series inductor from the previous node `a` to this node `b`, and a
/// capacitor from `b` to ground. Coordinates are node fluxes; their rates are node voltages.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(a => va, b => vb), port(a, b))]
#[dirac(lagrangian = 0.5 * c * vb * vb - (b - a) * (b - a) / (2.0 * l))]
pub struct Cell {
    /// Inductance.
    pub l: f64,
    /// Capacitance.
    pub c: f64,
}

/// The ground node, held at zero flux.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(g => vg), port(g))]
#[dirac(lagrangian = 0.0 * vg)]
#[dirac(holonomic(grounded) = g)]
pub struct Ground {}

/// Ground, then `cells.len()` sections, open at the far end.
#[derive(Interconnection, Clone)]
#[dirac(connect(ground.g, cells[0].a), connect(cells[i].b, cells[i + 1].a))]
pub struct Ladder {
    /// The grounded end.
    pub ground: Ground,
    /// The sections.
    pub cells: Vec<Cell>,
}

/// What is measured, and how.
#[derive(Clone, Debug)]
pub struct Setup {
    /// Cells.
    pub cells: usize,
    /// The cells whose far node's flux is measured.
    pub sensors: Vec<usize>,
    /// The length of the record.
    pub t_end: f64,
    /// The time between samples.
    pub dt: f64,
    /// The noise's standard deviation.
    pub sigma: f64,
    /// The penalty on `Σ (u_{j+1} − u_j)²`, `u = ln l`.
    pub smoothing: f64,
}

impl Setup {
    /// `cells` cells, sensors at a third, two thirds and the open end, samples every 0.1 over
    /// three passes of a wave down the line.
    pub fn new(cells: usize, sigma: f64, smoothing: f64) -> Setup {
        let sensors = vec![cells / 3 - 1, 2 * cells / 3 - 1, cells - 1];
        Setup { cells, sensors, t_end: 3.0 * cells as f64, dt: 0.1, sigma, smoothing }
    }

    /// The sample times, `0, Δt, …, T`.
    pub fn times(&self) -> Vec<f64> {
        let count = (self.t_end / self.dt).round() as usize;
        (0..=count).map(|k| k as f64 * self.dt).collect()
    }
}

/// The true profile: a bump of +50% at 60% of the line over a slope from 1 to 0.75.
pub fn true_profile(cells: usize) -> Vec<f64> {
    (0..cells)
        .map(|j| {
            let x = (j as f64 + 0.5) / cells as f64;
            1.0 + 0.5 * (-((x - 0.6) / 0.12).powi(2)).exp() - 0.25 * x
        })
        .collect()
}

/// The ladder with inductances `profile` and unit capacitances.
pub fn ladder(profile: &[f64]) -> Ladder {
    Ladder { ground: Ground {}, cells: profile.iter().map(|&l| Cell { l, c: 1.0 }).collect() }
}

/// The coordinate of cell `j`'s far node, whose flux a sensor there measures.
pub fn node(model: &Ladder, j: usize) -> usize {
    model.cells(j, Cell::B).index()
}

/// At rest, with a flux bump around the first quarter of the line.
pub fn start(model: &Ladder) -> Result<State<Ladder>, SimError> {
    let n = model.cells.len();
    let sizes = model.sizes();
    let mut q = sizes.zeros_q::<Ladder>();
    for j in 0..n {
        let x = (-((j as f64 - n as f64 / 4.0) / (n as f64 / 12.0)).powi(2)).exp();
        q[node(model, j)] = x;
        if j + 1 < n {
            q[model.cells(j + 1, Cell::A).index()] = x;
        }
    }
    consistent_state(model, 0.0, &q, &sizes.zeros_q::<Ladder>(), Consistency::default())
}

fn options() -> RadauOptions {
    RadauOptions::tolerances(1e-9, 1e-9)
}

/// The waveforms at the sensors, sampled at `setup.times()`: one row a sensor.
pub fn waveforms(profile: &[f64], setup: &Setup) -> Result<Vec<Vec<f64>>, SimError> {
    let model = ladder(profile);
    let times = setup.times();
    let solution =
        Radau::new(&model, options())?.solve(0.0, &start(&model)?, setup.t_end, &Sampling::Times(times))?;
    Ok(setup.sensors.iter().map(|&j| solution.q(model.cells(j, Cell::B)).to_vec()).collect())
}

/// SplitMix64 and Box-Muller: seeded standard normal numbers, so every run sees the same noise.
struct Normal(u64);

impl Normal {
    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn sample(&mut self) -> f64 {
        let (u1, u2) = (self.uniform().max(f64::MIN_POSITIVE), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }
}

/// The true ladder's waveforms with Gaussian noise of deviation `setup.sigma`.
pub fn measurements(setup: &Setup, seed: u64) -> Result<Vec<Vec<f64>>, SimError> {
    let mut normal = Normal(seed);
    let mut data = waveforms(&true_profile(setup.cells), setup)?;
    for value in data.iter_mut().flatten() {
        *value += setup.sigma * normal.sample();
    }
    Ok(data)
}

/// `χ² = Σ (x_s(t_k) − d_s,k)² / σ²` of a profile's waveforms against the data.
pub fn chi2(profile: &[f64], setup: &Setup, data: &[Vec<f64>]) -> Result<f64, SimError> {
    let model = waveforms(profile, setup)?;
    let sum: f64 = model.iter().flatten().zip(data.iter().flatten()).map(|(x, d)| (x - d).powi(2)).sum();
    Ok(sum / setup.sigma.powi(2))
}

/// A point, the misfit there and its gradient.
type Evaluated = (Vec<f64>, f64, Vec<f64>);

/// The misfit and its gradient with respect to `u = ln l`, by one recorded run and one
/// adjoint sweep, remembered for the point last asked (a line search asks for the cost and
/// then the gradient at the same point).
pub struct Misfit<'d> {
    setup: &'d Setup,
    data: &'d [Vec<f64>],
    times: Vec<f64>,
    last: RefCell<Option<Evaluated>>,
    /// The misfit at the first point asked: L-BFGS sees the misfit over it, so that its first
    /// step, along the gradient, is of a size that the line search starts near.
    first: &'d Counter<Option<f64>>,
    /// The simulations run: one recorded run and its sweep each.
    simulations: &'d Counter<usize>,
}

impl<'d> Misfit<'d> {
    /// The misfit of `data` measured with `setup`, the first misfit and the simulations
    /// counted into `first` and `simulations`.
    pub fn new(
        setup: &'d Setup,
        data: &'d [Vec<f64>],
        first: &'d Counter<Option<f64>>,
        simulations: &'d Counter<usize>,
    ) -> Self {
        Misfit { setup, data, times: setup.times(), last: RefCell::new(None), first, simulations }
    }

    /// The misfit at `u` and its gradient.
    pub fn evaluate(&self, u: &[f64]) -> Result<(f64, Vec<f64>), SimError> {
        if let Some((at, value, gradient)) = &*self.last.borrow()
            && at.as_slice() == u
        {
            return Ok((*value, gradient.clone()));
        }
        let setup = self.setup;
        let profile: Vec<f64> = u.iter().map(|x| x.exp()).collect();
        let model = ladder(&profile);
        let nodes: Vec<usize> = setup.sensors.iter().map(|&j| node(&model, j)).collect();
        let weight = 1.0 / setup.sigma.powi(2);
        let cost = |k: usize, _: f64, y: &State<Ladder>, out: &mut State<Ladder>| {
            let mut cost = 0.0;
            for (&i, d) in nodes.iter().zip(self.data) {
                let misfit = y.q[i] - d[k];
                cost += 0.5 * weight * misfit * misfit;
                out.q[i] = weight * misfit;
            }
            cost
        };
        let recording = Radau::new(&model, options())?.record(0.0, &start(&model)?, setup.t_end)?;
        let gradient = recording.gradient(&model, &Objective::samples(&self.times, &cost))?;
        self.simulations.set(self.simulations.get() + 1);
        let names = model.parameter_names();
        let mut value = gradient.value;
        let mut du: Vec<f64> = (0..setup.cells)
            .map(|j| {
                let k =
                    names.iter().position(|n| *n == format!("cells[{j}].l")).expect("each cell's inductance");
                gradient.parameters[k] * profile[j]
            })
            .collect();
        for j in 0..setup.cells - 1 {
            let step = u[j + 1] - u[j];
            value += 0.5 * setup.smoothing * step * step;
            du[j] -= setup.smoothing * step;
            du[j + 1] += setup.smoothing * step;
        }
        *self.last.borrow_mut() = Some((u.to_vec(), value, du.clone()));
        if self.first.get().is_none() {
            self.first.set(Some(value));
        }
        Ok((value, du))
    }
}

impl CostFunction for Misfit<'_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, u: &Vec<f64>) -> Result<f64, Error> {
        let value = self.evaluate(u)?.0;
        Ok(value / self.first.get().unwrap_or(value))
    }
}

impl Gradient for Misfit<'_> {
    type Param = Vec<f64>;
    type Gradient = Vec<f64>;

    fn gradient(&self, u: &Vec<f64>) -> Result<Vec<f64>, Error> {
        let (value, mut gradient) = self.evaluate(u)?;
        let first = self.first.get().unwrap_or(value);
        gradient.iter_mut().for_each(|g| *g /= first);
        Ok(gradient)
    }
}

/// The outcome of a recovery.
#[derive(Clone, Debug)]
pub struct Recovery {
    /// The recovered inductances.
    pub profile: Vec<f64>,
    /// The misfit `χ²/2` (with the penalty) at the end.
    pub misfit: f64,
    /// L-BFGS iterations.
    pub iterations: u64,
    /// Recorded runs with their adjoint sweeps.
    pub simulations: usize,
    /// Why L-BFGS stopped.
    pub termination: String,
}

/// Recovers the profile from `data`, starting from a uniform line of inductance `from`.
pub fn recover(setup: &Setup, data: &[Vec<f64>], from: f64, max_iterations: u64) -> Result<Recovery, Error> {
    let (first, simulations) = (Counter::new(None), Counter::new(0));
    let misfit = Misfit::new(setup, data, &first, &simulations);
    let solver =
        LBFGS::new(MoreThuenteLineSearch::new(), 10).with_tolerance_grad(1e-6)?.with_tolerance_cost(1e-14)?;
    let u0 = vec![from.ln(); setup.cells];
    let result =
        Executor::new(misfit, solver).configure(|state| state.param(u0).max_iters(max_iterations)).run()?;
    let state = result.state();
    let u = state.get_best_param().expect("a best point").clone();
    Ok(Recovery {
        profile: u.iter().map(|x| x.exp()).collect(),
        misfit: state.get_best_cost() * first.get().unwrap_or(1.0),
        iterations: state.get_iter(),
        simulations: simulations.get(),
        termination: format!("{}", state.get_termination_status()),
    })
}
