//! Forward sensitivities in Radau by the staggered direct method: after a step's stages have
//! converged, the sensitivities' stage equations
//!
//! ```text
//! M Zs_k = h Σ_j a_kj (J_j (s_n + Zs_j) + g_j),   J_j = ∂f/∂y and g_j = ∂f/∂θ at stage j,
//! ```
//!
//! linear in `Zs`, are solved in one of three ways. The stage Jacobians are evaluated once per
//! step and shared by every sensitivity.
//!
//! - Where the Jacobian is the same at every stage as the one factored for the step (a linear
//!   model's), the factored matrix is the stage system's own and one solve from zero is the
//!   solution, with nothing to iterate ([`Work::direct`]).
//! - On a small model whose sensitivities would take enough iterations in all, the three
//!   stages' coupled system is factored once a step and solved once per sensitivity
//!   ([`Coupled`]).
//! - Otherwise by the simplified Newton iteration on the step's factored matrix, in the same
//!   transformed variables as the state's ([`Work::iterate`]).
//!
//! Nothing allocates in a step.

mod derivatives;
mod work;

use self::derivatives::{Derivatives, estimate};

use nalgebra::DefaultAllocator;

use super::coupled::{Coupled, WORTH_FROM};
use super::dense::Dense;
use super::options::ErrorNorm;
use super::residual::Residual;
use super::stages::three;
use super::tableau::{C1, C2, C3, Eigen};
use crate::algebra::newton::NewtonSolver;
use crate::integrator::held::Held;
use crate::model::blocks::{JacobianBlocks, ResidualBlocks};
use crate::model::state::State;
use crate::model::{LagrangeDirac, ParameterDerivatives};
use crate::shape::dims::{Storage, VecY};
use crate::shape::layout::Layout;
use crate::simulate::sensitivity::Wrt;

/// One sensitivity: what it is with respect to, its value, its stages and its dense output.
struct Column<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    wrt: Wrt,
    /// `s_n`, the sensitivity at the step's start, then at its end.
    s: VecY<M>,
    /// The stage increments `Zs_k`.
    z: [VecY<M>; 3],
    /// `∂f/∂θ` at each stage (zero for an initial value).
    g: [VecY<M>; 3],
    /// `∂f/∂θ` at the step's start, for the error estimate.
    g0: VecY<M>,
    dense: Dense<M>,
    /// The contraction rate the column's iteration showed last (none yet: infinite).
    theta: f64,
}

/// The forward sensitivities of a Radau integration and their work space.
pub(crate) struct Forward<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    columns: Vec<Column<M>>,
    work: Work<M>,
    /// The three stages' coupled system, solved exactly on models small enough.
    coupled: Option<Coupled>,
    /// The Jacobian at the step's start (the last stage of the step before, or the start).
    jac0: JacobianBlocks<M, M::Algebra>,
    state: State<M>,
    blocks: ResidualBlocks<M>,
    /// Every parameter's `∂f/∂θ` blocks, evaluated together where at least half of the
    /// model's parameters (and two or more) are asked for; empty where each is evaluated alone.
    all: Vec<ResidualBlocks<M>>,
    /// The model's parameter derivatives.
    pub derivatives: ParameterDerivatives<M>,
    /// Whether the sensitivities' errors count in the step-size control.
    pub error_control: bool,
    /// Whether the sensitivities' multipliers at the step's start are known: not at the start
    /// of an integration, where they enter only the error estimate, which is then skipped.
    multipliers_known: bool,
    /// Linear iterations of the sensitivity stage systems, over all columns.
    pub iterations: usize,
    /// Steps solved with the coupled system.
    pub coupled_steps: usize,
}

/// What solving one sensitivity's stage system works with: the stage Jacobians, shared by all
/// sensitivities, and vectors for the iteration.
struct Work<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// The Jacobians at the three stages of the step being solved.
    jac: [JacobianBlocks<M, M::Algebra>; 3],
    w: [VecY<M>; 3],
    f: [VecY<M>; 3],
    r: [VecY<M>; 3],
    tmp: VecY<M>,
    weights: VecY<M>,
    layout: Layout,
}

/// Why the sensitivities of a step could not be solved.
pub(crate) enum Failure {
    /// Their linear iteration did not converge with this step size.
    NotConverged,
    /// The right-hand side of sensitivity `column` is not finite in state slot `slot` (a
    /// parameter derivative or a Jacobian entry that is not, at a stage).
    NonFinite { column: usize, slot: usize },
}

/// How the sensitivities' iteration runs: the state's Newton tolerance `fnewt`, the most
/// iterations, the norm of the increments, and the contraction rate `theta` the state's
/// iteration showed last.
pub(crate) struct Iteration {
    pub fnewt: f64,
    pub max_iterations: usize,
    pub norm: ErrorNorm,
    pub theta: f64,
    /// Whether the factored matrix is the sensitivities' exact stage matrix: factored for this
    /// step's size from a Jacobian equal to the one at every stage (a linear model's). Then one
    /// solve from zero is the solution, and there is nothing to iterate.
    pub exact: bool,
    /// The state's Newton iterations in this step: about what each sensitivity's iteration
    /// would need.
    pub state_iterations: usize,
}

/// The stage and state the sensitivities of a step are solved at.
pub(crate) struct At<'a, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    pub t: f64,
    pub h: f64,
    pub y: &'a VecY<M>,
    pub z: &'a [VecY<M>; 3],
}

impl<M: LagrangeDirac> Forward<M>
where
    DefaultAllocator: Storage<M>,
{
    pub fn new(model: &M, derivatives: ParameterDerivatives<M>, wrt: &[Wrt], error_control: bool) -> Self {
        let sizes = model.sizes();
        let shape = model.shape();
        let jac = || JacobianBlocks::with_shape(&shape);
        let columns = wrt
            .iter()
            .map(|&wrt| Column {
                wrt,
                s: sizes.zeros_y::<M>(),
                z: three(sizes),
                g: three(sizes),
                g0: sizes.zeros_y::<M>(),
                dense: Dense::new(sizes),
                theta: f64::INFINITY,
            })
            .collect();
        let work = Work {
            jac: [jac(), jac(), jac()],
            w: three(sizes),
            f: three(sizes),
            r: three(sizes),
            tmp: sizes.zeros_y::<M>(),
            weights: sizes.zeros_y::<M>(),
            layout: Layout::new(sizes),
        };
        let coupled = Coupled::new(&work.layout);
        let asked = wrt.iter().filter(|w| matches!(w, Wrt::Parameter(_))).count();
        // From the model: a composite with arrays has as many as its arrays' lengths make.
        let count = model.parameter_names().len();
        let together = asked >= 2 && 2 * asked >= count;
        let all = if together {
            (0..count).map(|_| ResidualBlocks::with_sizes(&sizes)).collect()
        } else {
            Vec::new()
        };
        Forward {
            columns,
            work,
            coupled,
            jac0: jac(),
            state: State::with_sizes(sizes),
            blocks: ResidualBlocks::with_sizes(&sizes),
            all,
            derivatives,
            error_control,
            multipliers_known: false,
            iterations: 0,
            coupled_steps: 0,
        }
    }

    /// The number of sensitivities.
    pub fn len(&self) -> usize {
        self.columns.len()
    }

    /// Sensitivity `j` at the step reached.
    pub fn value(&self, j: usize) -> &VecY<M> {
        &self.columns[j].s
    }

    /// Sets sensitivity `j` (at a start).
    pub fn set_value(&mut self, j: usize, s: &State<M>) {
        s.write_y(&mut self.columns[j].s);
        self.columns[j].dense.h = 0.0;
        self.multipliers_known = false;
    }

    /// Writes sensitivity `j` at `t` within the last step, which ended at `t_end`, into `out`.
    pub fn interpolate(&self, j: usize, t_end: f64, t: f64, out: &mut State<M>) {
        let c = &self.columns[j];
        c.dense.interpolate(&c.s, t_end, t, out);
    }

    /// What sensitivity `j` is taken with respect to.
    pub fn wrt(&self, j: usize) -> Wrt {
        self.columns[j].wrt
    }

    /// Sensitivity `j`'s multipliers at the start of the last step, into `out`: the quadratic
    /// through their three stage values extrapolated to the step's start. What the multipliers'
    /// sensitivities are at the start of an integration, where the method does not carry them
    /// (they enter no stage equation), to `O(h³)` of the first, short, step.
    pub fn multipliers_at_start(&self, j: usize, out: &mut State<M>) {
        let (l, c) = (self.work.layout, &self.columns[j]);
        let nodes = [C1, C2, C3];
        let lagrange = |k: usize| {
            let (a, b) = (nodes[(k + 1) % 3], nodes[(k + 2) % 3]);
            a * b / ((nodes[k] - a) * (nodes[k] - b))
        };
        let weights = [lagrange(0), lagrange(1), lagrange(2)];
        for i in l.lambda..l.len {
            // The step ended at s = s_n + Zs_3, so stage k holds s − Zs_3 + Zs_k.
            let base = c.s[i] - c.z[2][i];
            out.lambda[i - l.lambda] = (0..3).map(|k| weights[k] * (base + c.z[k][i])).sum();
        }
    }

    /// Evaluates the Jacobian and the parameter derivatives `∂f/∂θ` at the start of an
    /// integration or a restart, for the next step's error estimate, if the sensitivities'
    /// errors are controlled.
    pub fn begin(&mut self, model: &mut Held<'_, M>, residual: &mut Residual<'_, M>, t: f64, y: &VecY<M>) {
        if !self.error_control {
            return;
        }
        residual.apply(model, t, y);
        self.state.read_y(y);
        let s = &self.state;
        model.jacobian_blocks(t, &s.q, &s.v, &s.lambda, &mut self.jac0);
        let mut derivatives = Derivatives {
            of: self.derivatives,
            layout: &self.work.layout,
            blocks: &mut self.blocks,
            all: &mut self.all,
        };
        derivatives.write(model.get(), t, s, &mut self.columns, |c| &mut c.g0);
    }

    /// Evaluates the Jacobians and the parameter derivatives at the step's stages.
    pub fn stages(&mut self, model: &mut Held<'_, M>, residual: &mut Residual<'_, M>, at: &At<'_, M>) {
        for (k, ck) in [C1, C2, C3].into_iter().enumerate() {
            let w = &mut self.work;
            w.tmp.copy_from(at.y);
            w.tmp += &at.z[k];
            // Read as the state's residual is: from the left at a stretch's end.
            let t = residual.model_time(at.t + ck * at.h);
            residual.apply(model, t, &w.tmp);
            self.state.read_y(&w.tmp);
            let s = &self.state;
            model.jacobian_blocks(t, &s.q, &s.v, &s.lambda, &mut w.jac[k]);
            let mut derivatives = Derivatives {
                of: self.derivatives,
                layout: &w.layout,
                blocks: &mut self.blocks,
                all: &mut self.all,
            };
            derivatives.write(model.get(), t, s, &mut self.columns, |c| &mut c.g[k]);
        }
    }

    /// Whether the Jacobians at the three stages of the step all equal `jac`.
    pub fn stage_jacobians_equal(&self, jac: &JacobianBlocks<M, M::Algebra>) -> bool {
        self.work.jac.iter().all(|j| j.same_values(jac))
    }

    /// Solves every sensitivity's stage system with the factored `solver`, the iteration's
    /// increments measured in `weights_of(s)`. Returns the largest weighted error estimate of
    /// the sensitivities (zero unless they are error-controlled), or why it failed.
    pub fn solve<S: NewtonSolver<M, M::Algebra>>(
        &mut self,
        solver: &mut S,
        eig: &Eigen,
        h: f64,
        iteration: &Iteration,
        weights_of: &dyn Fn(&VecY<M>, &mut VecY<M>),
    ) -> Result<f64, Failure> {
        let mut worst: f64 = 0.0;
        let w = &mut self.work;
        let estimated = self.error_control && self.multipliers_known;
        if iteration.exact {
            // The direct solve starts from zero in the transformed variables, for every column.
            w.w.iter_mut().for_each(|w| w.fill(0.0));
        }
        // Otherwise the coupled system where it is small enough, cheaper than the iterations
        // it saves, and not singular; the iteration on the step's factored matrix where not.
        let worth = self.columns.len() * iteration.state_iterations >= WORTH_FROM;
        let mut coupled = match self.coupled.as_mut() {
            Some(coupled) if !iteration.exact && worth => {
                coupled.factor(&w.jac, h).is_ok().then_some(coupled)
            }
            _ => None,
        };
        let iterated = !iteration.exact && coupled.is_none();
        self.coupled_steps += usize::from(coupled.is_some());
        for (column, c) in self.columns.iter_mut().enumerate() {
            if iterated || estimated {
                weights_of(&c.s, &mut w.weights);
            }
            let solved = if iteration.exact {
                w.direct(solver, eig, h, c)
            } else if let Some(coupled) = coupled.as_deref_mut() {
                w.coupled(coupled, h, c)
            } else {
                w.iterate(solver, eig, h, iteration, c)
            };
            self.iterations += solved.map_err(|slot| match slot {
                Some(slot) => Failure::NonFinite { column, slot },
                None => Failure::NotConverged,
            })?;
            if estimated {
                worst = worst.max(estimate(
                    &w.layout,
                    solver,
                    &self.jac0,
                    c,
                    &mut w.tmp,
                    h,
                    &w.weights,
                    iteration.norm,
                ));
            }
        }
        Ok(worst)
    }

    /// Accepts the step of size `h`: each sensitivity moves to the step's end, and (for the
    /// error estimate) the last stage's Jacobian and parameter derivatives become the next
    /// step's start.
    pub fn accept(&mut self, h: f64) {
        for c in &mut self.columns {
            c.dense.update(&c.z, h);
            c.s += &c.z[2];
            if self.error_control {
                c.g0.copy_from(&c.g[2]);
            }
        }
        if self.error_control {
            self.jac0.copy_from(&self.work.jac[2]);
        }
        self.multipliers_known = true;
    }
}
