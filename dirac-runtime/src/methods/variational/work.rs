//! The options, counters and work space of a variational step, shared by its two paths.

use crate::analysis::free::FreeVelocities;
use nalgebra::DefaultAllocator;

use crate::algebra::lu::{Deflation, Lu};
use crate::algebra::{Algebra, Saddle, SaddleTerms};
use crate::analysis::diagnose::{pivot_name, singular_cause};
use crate::error::SimError;
use crate::model::LagrangeDirac;
use crate::model::state::State;
use crate::model::{MatCQ, MatQQ};
use crate::shape::dims::{Sizes, Storage, VecC, VecH, VecK, VecQ};

/// Newton tolerances of the two stages.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VariationalOptions {
    /// Converged when the Newton update is below `tolerance · (|x| + s)` in every component
    /// (default `1e-12`; `s` the velocity's scale, the velocity its coordinate has at the
    /// largest momentum of the start, or 1 for a multiplier), or when it has stalled at
    /// round-off below `1e3 · tolerance`.
    pub tolerance: f64,
    /// Newton iterations allowed per stage.
    pub max_iterations: usize,
    /// Whether to use the shortcut for separable models ([`LagrangeDirac::SEPARABLE`] with a
    /// nonsingular mass matrix): the same discrete equations, solved through `m × m` systems
    /// in the multipliers as RATTLE does. On by default.
    pub use_structure: bool,
    /// The most steps an integration may take (default `10_000_000`): a time span that needs
    /// more is refused at the start.
    pub max_steps: usize,
}

impl Default for VariationalOptions {
    fn default() -> Self {
        VariationalOptions {
            tolerance: 1e-12,
            max_iterations: 20,
            use_structure: true,
            max_steps: 10_000_000,
        }
    }
}

impl VariationalOptions {
    /// Checks every option, naming the first one out of its range.
    pub(crate) fn validate(&self) -> Result<(), SimError> {
        if !(self.tolerance > 0.0 && self.tolerance < 1.0) {
            return Err(SimError::InvalidTolerance { what: "tolerance", value: self.tolerance });
        }
        if self.max_iterations == 0 {
            return Err(SimError::InvalidOption { what: "max_iterations", reason: "at least 1".into() });
        }
        if self.max_steps == 0 {
            return Err(SimError::InvalidOption { what: "max_steps", reason: "at least 1".into() });
        }
        Ok(())
    }
}

/// Counters of the work a variational integration did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct VariationalStats {
    /// Steps taken.
    pub steps: usize,
    /// Newton iterations, both stages.
    pub newton_iterations: usize,
    /// LU factorisations: one per Newton iteration on the general path; on the separable path
    /// one per multiplier update and one for the velocity projection.
    pub factorizations: usize,
    /// Sub-steps taken where a whole step's Newton iteration did not converge (see
    /// [`Variational`](crate::methods::variational::Variational)): each counts here, the step they make up in `steps`.
    pub substeps: usize,
}

/// The unknowns and matrices of one step, kept between steps so that a step allocates nothing
/// and Newton starts from the previous step's solution.
pub(crate) struct Work<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    pub sizes: Sizes,
    /// The step velocity `v = (q_{k+1} − q_k)/h`.
    pub v: VecQ<M>,
    /// The stage-1 impulse Λ.
    pub big_lambda: VecC<M>,
    /// The stage-2 impulse Γ.
    pub gamma: VecC<M>,
    /// The multipliers at the last step's midpoint, `(Λ + Γ)/h`, and that step's size; a size
    /// of zero when no step has been taken since the start or a restart.
    pub midpoint: (VecC<M>, f64),
    /// `A(q_k)`.
    pub a0: MatCQ<M>,
    /// `B − A` at the step's start and end, for a model whose friction pushes with a contact
    /// force ([`LagrangeDirac::NON_ASSOCIATED`]): its impulses act along `B`.
    pub slip0: MatCQ<M>,
    pub slip1: MatCQ<M>,
    /// The blocks of the stage systems.
    pub blocks: StageBlocks<M>,
    /// The vectors of the stage systems.
    pub vectors: StageVectors<M>,
    /// The `(n + m)` stage system.
    pub saddle: <M::Algebra as Algebra<M>>::Saddle<f64>,
    /// The `m × m` systems of the separable path, when it is taken.
    pub small: Option<Lu<f64, M::Nc>>,
    /// The separable path's deflation of redundant rows.
    pub small_deflation: Deflation<f64, M::Nc>,
    /// The size of the last Newton update, for the stall test.
    pub last_update: f64,
    /// Each velocity's scale for the Newton test, `min(|p|∞ / L_ii, |v|∞)` (the velocity the
    /// coordinate has at the largest momentum, at most the largest velocity; `|v|∞` for one
    /// without inertia), the largest since the start: the
    /// momenta are what a step balances, and they weigh every coordinate in the model's own
    /// terms (a roll's rate of 1e-12 on an inertia of 1e12 is as large as a slide's of 1 on a
    /// mass of 1).
    pub scale: VecQ<M>,
    /// `∂L/∂q` at the current point (separable models: independent of `v`).
    pub dl_dq: VecQ<M>,
    /// The energy put in since the start by the external forces and by the Lagrangian's
    /// dependence on time, `Σ h (⟨F, v_k⟩ − ∂L/∂t)` at the steps' midpoints.
    pub work: f64,
    /// The velocities no inertia or constraint fixes, solved from the forces at every step's
    /// end; found at the start.
    pub free: Option<FreeVelocities<M>>,
}

impl<M: LagrangeDirac> Work<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Whether `[L_vv Aᵀ; A 0]` at `state` is regular: then every velocity has inertia or a
    /// constraint that fixes it. Factors the stage system's storage (allocates nothing).
    pub fn saddle_regular(&mut self, model: &M, t: f64, state: &State<M>) -> bool {
        let b = &mut self.blocks;
        model.l_vv(t, &state.q, &state.v, &mut b.lvv1);
        model.constraint_matrix(t, &state.q, &mut b.a1);
        if M::NON_ASSOCIATED {
            model.slip_rows(t, &state.q, &state.v, &mut self.slip1);
        }
        assemble_legendre::<M>(&mut self.saddle, (&b.lvv1, &b.a1, &self.slip1), None);
        self.saddle.factor().is_ok()
    }
}

/// Assembles `[L_vv Aᵀ; A 0]` (`−Aᵀ` on the right) for the Legendre map at a step's end,
/// `L_vv` completed by `N Nᵀ` along the velocities only the forces fix. Two fixed lists of
/// terms, so that a model without such velocities sums one.
pub(crate) fn assemble_legendre<M: LagrangeDirac>(
    saddle: &mut <M::Algebra as Algebra<M>>::Saddle<f64>,
    (lvv, a, slip): (&MatQQ<M>, &MatCQ<M>, &MatCQ<M>),
    free: Option<&FreeVelocities<M>>,
) where
    DefaultAllocator: Storage<M>,
{
    let forces = [(-1.0, a), (-1.0, slip)];
    let right = if M::NON_ASSOCIATED { &forces[..] } else { &forces[..1] };
    let bottom = &[(1.0, 1.0, a)];
    let rest =
        |top| SaddleTerms { top, top_transposed: &[], identity: 0.0, right, bottom, corner: (0.0, 0.0) };
    match free {
        None => saddle.assemble(&rest(&[(1.0, lvv)])),
        Some(free) => saddle.assemble(&rest(&[(1.0, lvv), (1.0, &free.projector)])),
    }
}

/// The blocks a stage system is assembled from. Each is written by one model method only
/// (`l_vv`, `l_vq`, `force_dq`, `force_dv`, `constraint_matrix`, `dav_dq`), so none needs
/// zeroing between writes.
pub(crate) struct StageBlocks<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    /// `L_vv` at the step's start and end.
    pub lvv0: MatQQ<M>,
    pub lvv1: MatQQ<M>,
    /// `L_vq` at the step's start and end.
    pub lvq0: MatQQ<M>,
    pub lvq1: MatQQ<M>,
    /// The force Jacobians at the midpoint.
    pub fq: MatQQ<M>,
    pub fv: MatQQ<M>,
    /// `∂((B − A)ᵀ Λ)/∂v` at the step's start, for a model whose slip turns with the velocity.
    pub sv: MatQQ<M>,
    /// `A` at the step's end and midpoint, and `∂(A v)/∂q` at the midpoint.
    pub a1: MatCQ<M>,
    pub am: MatCQ<M>,
    pub gm: MatCQ<M>,
    /// The stage-1 matrix's top terms summed, for dense blocks.
    pub sum: MatQQ<M>,
}

/// The vectors of a stage: end point and midpoint, the model's vectors there, the residual.
pub(crate) struct StageVectors<M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    pub q1: VecQ<M>,
    pub qm: VecQ<M>,
    pub lv0: VecQ<M>,
    pub lv1: VecQ<M>,
    pub lq: VecQ<M>,
    pub f: VecQ<M>,
    pub target: VecQ<M>,
    pub phi: VecH<M>,
    /// `b(q, t)` of the constraints at one of the step's points.
    pub rate: VecC<M>,
    pub r: VecK<M>,
}

impl<M: LagrangeDirac> Work<M>
where
    DefaultAllocator: Storage<M>,
{
    /// Lets [`Work::scale`] grow to the state at a (re)start: a run's scales do not shrink as
    /// its energy does (zero them before a new run). 1 where the state is at rest (no momentum
    /// and no velocity to measure by). Allocates nothing.
    pub fn grow_scales(&mut self, model: &M, t: f64, state: &State<M>) {
        let lvv = &mut self.blocks.lvv0;
        model.l_vv(t, &state.q, &state.v, lvv);
        let diagonal = &mut self.vectors.target;
        diagonal.fill(0.0);
        M::Algebra::qq_entries(lvv, |row, column, value| {
            if row == column {
                diagonal[row] += value;
            }
        });
        let (p, v) = (state.p.amax(), state.v.amax());
        for (s, &inertia) in self.scale.iter_mut().zip(self.vectors.target.iter()) {
            // The velocity the coordinate has at the largest momentum, unless that is beyond the
            // largest velocity (a coordinate of tiny inertia).
            let reached = if inertia > 0.0 { (p / inertia).min(v) } else { v };
            let reached = if reached > 0.0 && reached.is_finite() { reached } else { 1.0 };
            *s = s.max(reached);
        }
    }

    pub fn new(model: &M) -> Self {
        let (sizes, shape) = (model.sizes(), model.shape());
        let qq = || M::Algebra::zeros_qq(&shape);
        let cq = || M::Algebra::zeros_cq(&shape);
        let q = || sizes.zeros_q::<M>();
        Work {
            sizes,
            v: q(),
            big_lambda: sizes.zeros_c::<M>(),
            gamma: sizes.zeros_c::<M>(),
            midpoint: (sizes.zeros_c::<M>(), 0.0),
            a0: cq(),
            slip0: cq(),
            slip1: cq(),
            blocks: StageBlocks {
                lvv0: qq(),
                lvv1: qq(),
                lvq0: qq(),
                lvq1: qq(),
                fq: qq(),
                fv: qq(),
                sv: qq(),
                a1: cq(),
                am: cq(),
                gm: cq(),
                sum: qq(),
            },
            vectors: StageVectors {
                q1: q(),
                qm: q(),
                lv0: q(),
                lv1: q(),
                lq: q(),
                f: q(),
                target: q(),
                phi: sizes.zeros_h::<M>(),
                rate: sizes.zeros_c::<M>(),
                r: sizes.zeros_k::<M>(),
            },
            saddle: M::Algebra::saddle(&shape),
            small: None,
            small_deflation: Deflation::new(sizes.nc),
            last_update: f64::INFINITY,
            scale: q(),
            dl_dq: q(),
            work: 0.0,
            free: None,
        }
    }
}

/// One step from `state` at `t`, being taken.
pub(crate) struct Step<'a, M: LagrangeDirac>
where
    DefaultAllocator: Storage<M>,
{
    pub model: &'a M,
    pub h: f64,
    pub t: f64,
    pub options: &'a VariationalOptions,
    /// The state at the step's start; the paths write the new momenta and velocities into it.
    pub state: &'a mut State<M>,
    pub work: &'a mut Work<M>,
    pub stats: &'a mut VariationalStats,
}

impl<M: LagrangeDirac> Step<'_, M>
where
    DefaultAllocator: Storage<M>,
{
    /// The error for a Newton iteration that ran out of iterations.
    pub fn diverged(&self) -> SimError {
        SimError::NewtonDiverged { t: self.t, h: self.h, iterations: self.options.max_iterations }
    }

    /// The error for a singular stage matrix, at the unknown without a pivot, with its cause.
    pub fn singular(&self, column: usize) -> SimError {
        let cause = singular_cause(self.model, self.t, &self.state.q, &self.state.v);
        SimError::SingularMatrix {
            t: self.t,
            h: self.h,
            detail: format!("{}; {cause}", pivot_name(self.model, column)),
        }
    }
}

/// `1000 steps, 2100 Newton iterations, 2100 factorisations`, and the sub-steps if any.
impl std::fmt::Display for VariationalStats {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} steps, {} Newton iterations, {} factorisations",
            self.steps, self.newton_iterations, self.factorizations
        )?;
        if self.substeps > 0 {
            write!(f, ", {} sub-steps", self.substeps)?;
        }
        Ok(())
    }
}
