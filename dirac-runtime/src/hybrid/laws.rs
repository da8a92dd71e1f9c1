//! The set-valued laws a model declares, Coulomb friction with stiction (`friction(c, kinetic =
//! f, stiction = f_s) = g`) and the ideal diode (`diode(c) = g`), switched between their modes
//! as Filippov's sliding modes are.
//!
//! The derive writes law `c` as a row `(1 − s²) g + s² ṡ = 0` on a coordinate `s = c_mode`
//! that holds the mode: 0 engaged (stuck, conducting: the row holds `g = 0` and its multiplier
//! `λ` is the law's force), ±1 released (slipping to the side of `g`'s sign, or blocking: the
//! row holds the slack). It also writes two events, found here by their direction codes:
//!
//! - **engage** (`c_stops`, `c_conducts`), where `g` reaches zero while released. A diode
//!   conducts. Friction sticks where the force that holds it, the multiplier of the engaged row
//!   in the consistent state, stays strictly within `f_s`; otherwise the slip goes on to the
//!   other side.
//! - **release** (`c_slips`, `c_blocks`), where the force reaches its bound (`|λ| = f_s`) or the
//!   current falls to zero: friction slips on the side the force pushed (`s = −sign λ`), so the
//!   force is continuous; a diode blocks.
//!
//! Each switch sets `s` in the state and restarts from the consistent state, so every mode is
//! smooth and every integrator steps it at its order: no chattering, whatever the tolerance.

use nalgebra::DefaultAllocator;

use crate::algebra::{Algebra, amax};
use crate::analysis::accelerations::Accelerations;
use crate::analysis::init::{Consistency, project};
use crate::error::SimError;
use crate::model::hybrid::has_laws;
use crate::model::names::{BLOCKS, CLOSES, CONDUCTS, OPENS, SLIPS, STOPS};
use crate::model::state::State;
use crate::model::{Hybrid, LagrangeDirac};
use crate::shape::dims::{Storage, VecC, VecQ};

/// One law of a model, by the indices the runtime reads it with.
#[derive(Clone, Debug)]
pub(crate) struct Law {
    /// Which law.
    pub kind: Kind,
    /// The coordinate that holds the mode.
    pub mode: usize,
    /// The row, whose multiplier is the law's force.
    pub row: usize,
    /// The engage and release events among the model's declared ones.
    pub engage: usize,
    pub release: usize,
    /// A friction cone's second mode coordinate and second row: its mode is the slip
    /// direction `(q[mode], q[cone.0])`, zero while stuck, and its force `(λ[row], λ[cone.1])`.
    pub cone: Option<(usize, usize)>,
    /// The law's name.
    pub name: String,
}

/// The laws, by what decides their switches.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// Coulomb friction with stiction: released to either side, engaged while its force is
    /// within its bound.
    Friction,
    /// An ideal diode: engaged while its current is not negative.
    Diode,
    /// An ideal switch: engaged while its control is positive.
    Switch,
}

/// Which switch of which law (its index among the model's laws) an event is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Switch {
    Engage(usize),
    Release(usize),
}

/// The force of an engaged friction law must stay this far inside its bound, relative to the
/// force, for the law to stick where its slip stops: at the bound it slips on.
const STRICTLY_WITHIN: f64 = 1e-9;

/// A released law's `g` counts as zero at the start within this share of `1 + |v|`.
const AT_ZERO: f64 = 1e-9;

/// The laws of `model`, from its declared events (dotted names in a composite: the engage
/// event `arm.grip_stops` belongs to the law `arm.grip`, whose mode is `arm.grip_mode`).
pub(crate) fn laws<M: LagrangeDirac>(model: &M) -> Vec<Law>
where
    DefaultAllocator: Storage<M>,
{
    if !has_laws(model) {
        return Vec::new();
    }
    laws_among(&model.event_declarations(), &model.coordinate_names(), &model.constraint_names())
}

/// The laws among the declared events `declared`, with the model's coordinate and constraint
/// names.
pub(crate) fn laws_among(declared: &[(String, i8)], coordinates: &[String], rows: &[String]) -> Vec<Law> {
    let mut out = Vec::new();
    for (engage, (name, code)) in declared.iter().enumerate() {
        let (kind, engaged, released, release_code) = match *code {
            STOPS => (Kind::Friction, "_stops", "_slips", SLIPS),
            CONDUCTS => (Kind::Diode, "_conducts", "_blocks", BLOCKS),
            CLOSES => (Kind::Switch, "_closes", "_opens", OPENS),
            _ => continue,
        };
        let Some(law) = name.strip_suffix(engaged) else { continue };
        let release =
            declared.iter().position(|(n, c)| *c == release_code && *n == format!("{law}{released}"));
        let coordinate = |suffix: &str| coordinates.iter().position(|c| *c == format!("{law}_mode{suffix}"));
        let row_named = |suffix: &str| rows.iter().position(|r| *r == format!("{law}{suffix}"));
        let (mode, row, cone) = match coordinate("") {
            Some(mode) => (Some(mode), row_named(""), None),
            None => match (coordinate("_2"), row_named("_2")) {
                (Some(mode), Some(row)) if kind == Kind::Friction => {
                    (coordinate("_1"), row_named("_1"), Some((mode, row)))
                }
                _ => continue,
            },
        };
        if let (Some(release), Some(mode), Some(row)) = (release, mode, row) {
            out.push(Law { kind, mode, row, engage, release, cone, name: law.to_string() });
        }
    }
    out
}

/// The names of `model`'s laws.
pub fn law_names<M: LagrangeDirac>(model: &M) -> Vec<String>
where
    DefaultAllocator: Storage<M>,
{
    laws(model).into_iter().map(|law| law.name).collect()
}

/// Switches `law` at an event at `t`, in `state` (the state there): sets its mode and leaves
/// `state` consistent in it. `values` holds the model's declared event functions.
pub(crate) fn switch<M: Hybrid>(
    model: &M,
    law: &Law,
    engage: bool,
    t: f64,
    state: &mut State<M>,
    values: &mut [f64],
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    // The slack rests in either mode: its row holds it released, and engaged nothing moves it.
    state.v[law.mode] = 0.0;
    if let Some(cone) = law.cone {
        state.v[cone.0] = 0.0;
        return switch_cone(model, law, engage, t, state, values);
    }
    if !engage {
        let force = state.lambda[law.row];
        state.q[law.mode] = if law.kind == Kind::Friction && force > 0.0 { -1.0 } else { 1.0 };
        consistent(model, t, state)?;
        return dissipating(model, t, state);
    }
    let located = state.q[law.mode];
    state.q[law.mode] = 0.0;
    let stuck = project(model, t, &state.q, &state.v, Consistency::default())?;
    if law.kind == Kind::Friction && !holds(model, law, t, &stuck, values) {
        // Held, the force would exceed the bound: the slip goes on, to the other side.
        state.q[law.mode] = -located;
        consistent(model, t, state)?;
        return dissipating(model, t, state);
    }
    *state = stuck;
    Ok(())
}

/// Switches the friction cone `law` (see [`switch`]). Released, it slips against the force that
/// held it (at its bound, its slip starts at the rate zero). At its engage event the slip has
/// stopped, or turned from the direction frozen in its mode by
/// [`CONE_TURN`](crate::model::names::CONE_TURN): stopped, it sticks (with every other slip
/// stopped there) where the force that holds it stays within its bound, and slips on from rest
/// otherwise; turned, its direction is frozen again along the slip. Either way every stuck cone
/// that cannot hold then starts to slip with it ([`start_slips`]).
fn switch_cone<M: Hybrid>(
    model: &M,
    law: &Law,
    engage: bool,
    t: f64,
    state: &mut State<M>,
    values: &mut [f64],
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    if engage {
        let g = cone_slip(model, law, t, &state.q, &state.v);
        if norm(g) > stopped(&state.v) {
            set_cone(state, law, [g[0] / norm(g), g[1] / norm(g)]);
            consistent(model, t, state)?;
            return dissipating(model, t, state);
        }
        // Every other cone whose slip has stopped here too stops with it (a box's corners
        // on the ground stop together): held one by one, the rows of those still slipping
        // would make the contacts' redundant normal forces decide the motion.
        set_cone(state, law, [0.0, 0.0]);
        for other in laws(model) {
            let Some((mode, _)) = other.cone else { continue };
            let slipping = state.q[other.mode] != 0.0 || state.q[mode] != 0.0;
            if slipping && norm(cone_slip(model, &other, t, &state.q, &state.v)) <= stopped(&state.v) {
                set_cone(state, &other, [0.0, 0.0]);
            }
        }
        consistent(model, t, state)?;
        return start_slips(model, t, state, values, Vec::new());
    }
    // At its bound the slip starts against the force (its rate zero, so along any direction
    // of its own); any other cone that cannot hold once it slips starts with it.
    let direction = against(cone_force(law, state));
    set_cone(state, law, direction);
    consistent(model, t, state)?;
    start_slips(model, t, state, values, vec![(law.clone(), direction)])
}

/// Settles the cones at `t` after a switch, `state` consistent in their modes: every stuck
/// cone that cannot hold starts to slip, together with those `starting` (just released, at
/// rest), in the directions [`starting_directions`] finds for all of them at once; one that
/// would slip backwards in them sticks instead; until each stuck cone holds. `state` is left
/// consistent in the modes found. An error where they do not settle within a round per cone.
fn start_slips<M: Hybrid>(
    model: &M,
    t: f64,
    state: &mut State<M>,
    values: &mut [f64],
    mut starting: Vec<(Law, [f64; 2])>,
) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    let cones: Vec<Law> = laws(model).into_iter().filter(|law| law.cone.is_some()).collect();
    let is_stuck = |state: &State<M>, law: &Law| {
        let (mode, _) = law.cone.expect("a cone");
        state.q[law.mode] == 0.0 && state.q[mode] == 0.0
    };
    for _ in 0..=2 * cones.len() {
        let more: Vec<(Law, [f64; 2])> = cones
            .iter()
            .filter(|law| is_stuck(state, law) && !starting.iter().any(|(s, _)| s.row == law.row))
            .filter(|law| !holds(model, law, t, state, values) || leaving_bound(model, law, t, state, values))
            .map(|law| (law.clone(), against(cone_force(law, state))))
            .collect();
        if more.is_empty() && starting.iter().all(|(law, direction)| slipping_along(state, law, *direction)) {
            return dissipating(model, t, state);
        }
        starting.extend(more);
        // Each starts from rest: stuck, then set in its direction.
        for (law, _) in &starting {
            set_cone(state, law, [0.0, 0.0]);
        }
        consistent(model, t, state)?;
        let refs: Vec<(&Law, [f64; 2])> = starting.iter().map(|(law, direction)| (law, *direction)).collect();
        match starting_directions(model, t, state, refs)? {
            Onset::Directions(directions) => {
                let directions: Vec<[f64; 2]> = directions.into_iter().map(|(_, d)| d).collect();
                for ((law, direction), found) in starting.iter_mut().zip(directions) {
                    *direction = found;
                    set_cone(state, law, found);
                }
            }
            Onset::Backwards(i) => {
                // It sticks; the others are found again without it.
                starting.remove(i);
                for (law, direction) in &starting {
                    set_cone(state, law, *direction);
                }
            }
        }
        consistent(model, t, state)?;
    }
    Err(SimError::NotDetermined {
        t,
        cause: format!(
            "the slips of {} start and stop again as each starts: no modes in which each stuck cone holds \
             and each slip starts along itself were found",
            starting.iter().map(|(law, _)| format!("`{}`", law.name)).collect::<Vec<_>>().join(", ")
        ),
    })
}

/// Whether stuck cone `law`, holding in the consistent `state` with its force at its bound
/// (within [`AT_BOUND`] of it), leaves it at once: its force grows past the bound as the motion
/// goes on. Its release would otherwise come at once after the switch, and a cone that sticks
/// at its bound as another starts to slip can trade switches with it ever faster.
fn leaving_bound<M: Hybrid>(model: &M, law: &Law, t: f64, state: &State<M>, values: &mut [f64]) -> bool
where
    DefaultAllocator: Storage<M>,
{
    model.events(t, &state.q, &state.v, &state.lambda, values);
    let margin = values[law.release];
    if margin > AT_BOUND * norm(cone_force(law, state)) {
        return false;
    }
    let sizes = model.sizes();
    let (mut acceleration, mut lambda) = (sizes.zeros_q::<M>(), sizes.zeros_c::<M>());
    let mut accelerations = Accelerations::new(model);
    if !accelerations.evaluate(model, t, (&state.q, &state.v), &mut acceleration, &mut lambda) {
        return false;
    }
    // Along the motion.
    let h = RATE_STEP;
    // Both margins from the same solve, so that its round-off cancels.
    model.events(t, &state.q, &state.v, &lambda, values);
    let margin = values[law.release];
    let ahead = (&state.q + &state.v * h, &state.v + &acceleration * h);
    let mut later = sizes.zeros_q::<M>();
    if !accelerations.evaluate(model, t + h, (&ahead.0, &ahead.1), &mut later, &mut lambda) {
        return false;
    }
    model.events(t + h, &ahead.0, &ahead.1, &lambda, values);
    values[law.release] < margin
}

/// The share of its force within which a stuck cone's force counts as at its bound.
const AT_BOUND: f64 = 1e-6;

/// Whether cone `law` slips along `direction` in `state` (its frozen direction).
fn slipping_along<M: Hybrid>(state: &State<M>, law: &Law, direction: [f64; 2]) -> bool
where
    DefaultAllocator: Storage<M>,
{
    let (mode, _) = law.cone.expect("a cone");
    state.q[law.mode] == direction[0] && state.q[mode] == direction[1] && norm(direction) > 0.0
}

/// What [`starting_directions`] found: the directions, or the index of a cone that would slip
/// backwards in the only directions in which each slips along itself (so it sticks).
enum Onset<'l> {
    Directions(Vec<(&'l Law, [f64; 2])>),
    Backwards(usize),
}

/// The directions the cones `starting` (stuck in `state`, their forces past their bounds) slip
/// in from rest, from the directions against those forces given with them.
///
/// From rest (`g = 0`) a cone's kinetic force is `−μ N m` along its frozen direction `m`, so the
/// slip starts at the rate `ġ = a − μ N W m` (`W` the Delassus block of the contacts starting,
/// `a` their acceleration without friction). It slips on along `m` only where `ġ = k m` with
/// `k > 0`; against the force that held it is that direction only for a contact alone at its
/// bound (`k = 0`), or with `W` round. Two feet starting at once turn each other's slip: frozen
/// against their forces, their slips would turn from `m` at once, stop and start again ever
/// sooner. The directions and rates `(θ_i, k_i)` of all the cones starting are found together
/// by Newton's method on `ġ_i(m(θ)) − k_i m_i = 0`, `ġ` from the accelerations in those modes
/// (one saddle solve each) by a difference along the motion, its change with the angles by
/// differences too. (The plain iteration `m ← ġ(m)/|ġ(m)|` contracts only by `μN / (|λ| − μN)`
/// for one contact, `λ` the force that would hold it: not at all within twice the bound, where
/// it flips between `m` and `−m`.) An error where no directions slip along themselves, or the
/// accelerations are singular in those modes: the motion is not determined there.
fn starting_directions<'l, M: Hybrid>(
    model: &M,
    t: f64,
    state: &State<M>,
    starting: Vec<(&'l Law, [f64; 2])>,
) -> Result<Onset<'l>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let n = starting.len();
    let mut rates = SlipRates::new(model, state);
    let mut angles: Vec<f64> = starting.iter().map(|(_, m)| m[1].atan2(m[0])).collect();
    let laws: Vec<&Law> = starting.iter().map(|(law, _)| *law).collect();
    let undetermined = |detail: &str| SimError::NotDetermined {
        t,
        cause: format!(
            "the slips of {} start together from rest and {detail}",
            laws.iter().map(|law| format!("`{}`", law.name)).collect::<Vec<_>>().join(", ")
        ),
    };
    let singular = || undetermined("the accelerations are singular in the modes they would slip in");
    let mut g = rates.at(model, t, &laws, &angles).ok_or_else(singular)?;
    let along =
        |g: &[[f64; 2]], angles: &[f64], i: usize| g[i][0] * angles[i].cos() + g[i][1] * angles[i].sin();
    let mut k: Vec<f64> = (0..n).map(|i| along(&g, &angles, i).max(0.0)).collect();
    let residual = |g: &[[f64; 2]], angles: &[f64], k: &[f64]| {
        (0..n)
            .map(|i| norm([g[i][0] - k[i] * angles[i].cos(), g[i][1] - k[i] * angles[i].sin()]))
            .fold(0.0, f64::max)
    };
    // The residual counts against the rates and against how much the friction turns them, and
    // not below the round-off of the rates' differences (where a contact's force is about zero,
    // its friction turns nothing, and any direction starts the slip alike).
    let mut scale = f64::MIN_POSITIVE;
    let noise = 10.0 * f64::EPSILON * (1.0 + state.v.amax()) / RATE_STEP;
    let mut r = residual(&g, &angles, &k);
    let mut converged = false;
    for _ in 0..ONSET_ROUNDS {
        // The Jacobian of the residual in (θ, k), its angle columns by differences.
        let mut jacobian = nalgebra::DMatrix::<f64>::zeros(2 * n, 2 * n);
        for j in 0..n {
            let mut turned = angles.clone();
            turned[j] += ONSET_ANGLE_STEP;
            let g_turned = rates.at(model, t, &laws, &turned).ok_or_else(singular)?;
            for i in 0..n {
                for c in 0..2 {
                    jacobian[(2 * i + c, j)] = (g_turned[i][c] - g[i][c]) / ONSET_ANGLE_STEP;
                }
            }
            scale = scale.max(jacobian.column(j).amax());
            let (sin, cos) = angles[j].sin_cos();
            jacobian[(2 * j, j)] += k[j] * sin;
            jacobian[(2 * j + 1, j)] -= k[j] * cos;
            jacobian[(2 * j, n + j)] = -cos;
            jacobian[(2 * j + 1, n + j)] = -sin;
        }
        scale = g.iter().map(|g| norm(*g)).fold(scale, f64::max);
        converged = r <= (ONSET_TOLERANCE * scale).max(noise);
        if converged {
            break;
        }
        let values = nalgebra::DVector::<f64>::from_iterator(
            2 * n,
            (0..n).flat_map(|i| {
                let (sin, cos) = angles[i].sin_cos();
                [g[i][0] - k[i] * cos, g[i][1] - k[i] * sin]
            }),
        );
        let Some(step) = jacobian.lu().solve(&values) else { break };
        // Halve the step until the residual falls.
        let mut length = 1.0;
        let mut accepted = false;
        for _ in 0..30 {
            let trial_angles: Vec<f64> = (0..n).map(|i| angles[i] - length * step[i]).collect();
            let trial_k: Vec<f64> = (0..n).map(|i| k[i] - length * step[n + i]).collect();
            let Some(trial_g) = rates.at(model, t, &laws, &trial_angles) else {
                length /= 2.0;
                continue;
            };
            let trial_r = residual(&trial_g, &trial_angles, &trial_k);
            if trial_r < r {
                (angles, k, g, r) = (trial_angles, trial_k, trial_g, trial_r);
                accepted = true;
                break;
            }
            length /= 2.0;
        }
        if !accepted {
            break;
        }
    }
    if !converged {
        return Err(undetermined(&format!(
            "no directions were found in which each slips along itself (the slips' rates stay {r:e} off \
             their directions, {:e} relative)",
            r / scale
        )));
    }
    // At its bound a slip starts at the rate zero.
    if let Some(i) = (0..n)
        .filter(|&i| k[i] < -(ONSET_TOLERANCE * scale).max(noise))
        .min_by(|&i, &j| k[i].total_cmp(&k[j]))
    {
        return Ok(Onset::Backwards(i));
    }
    Ok(Onset::Directions(
        laws.into_iter().zip(angles).map(|(law, angle)| (law, [angle.cos(), angle.sin()])).collect(),
    ))
}

/// The rates `ġ` at which the slips of cones start from rest in given directions.
struct SlipRates<M: Hybrid>
where
    DefaultAllocator: Storage<M>,
{
    accelerations: Accelerations<M>,
    acceleration: VecQ<M>,
    lambda: VecC<M>,
    q: VecQ<M>,
    v: VecQ<M>,
}

impl<M: Hybrid> SlipRates<M>
where
    DefaultAllocator: Storage<M>,
{
    fn new(model: &M, state: &State<M>) -> Self {
        let sizes = model.sizes();
        SlipRates {
            accelerations: Accelerations::new(model),
            acceleration: sizes.zeros_q::<M>(),
            lambda: sizes.zeros_c::<M>(),
            q: state.q.clone(),
            v: state.v.clone(),
        }
    }

    /// Each of `laws`' slip rates, frozen at `angles`; `None` where the accelerations are
    /// singular there.
    fn at(&mut self, model: &M, t: f64, laws: &[&Law], angles: &[f64]) -> Option<Vec<[f64; 2]>> {
        for (law, angle) in laws.iter().zip(angles) {
            set_cone_in(&mut self.q, law, [angle.cos(), angle.sin()]);
        }
        let (q, v) = (&self.q, &self.v);
        if !self.accelerations.evaluate(model, t, (q, v), &mut self.acceleration, &mut self.lambda) {
            return None;
        }
        let h = RATE_STEP;
        let ahead = (q + v * h, v + &self.acceleration * h);
        let rates: Vec<[f64; 2]> = laws
            .iter()
            .map(|law| {
                let (g0, g1) =
                    (cone_slip(model, law, t, q, v), cone_slip(model, law, t + h, &ahead.0, &ahead.1));
                [(g1[0] - g0[0]) / h, (g1[1] - g0[1]) / h]
            })
            .collect();
        rates.iter().all(|g| g[0].is_finite() && g[1].is_finite()).then_some(rates)
    }
}

/// The step along the motion by which [`SlipRates`] differentiates the slips: short enough that
/// `g` is linear in it, long enough that its change stands well above the round-off of the
/// velocities.
const RATE_STEP: f64 = 1e-7;

/// The most Newton iterations of [`starting_directions`].
const ONSET_ROUNDS: usize = 50;

/// The residual of [`starting_directions`], relative to the slips' rates, within which the
/// directions stand: the differences that give the rates are good to about `1e-9`.
const ONSET_TOLERANCE: f64 = 1e-8;

/// The turn of a direction by which [`starting_directions`] differentiates the rates.
const ONSET_ANGLE_STEP: f64 = 1e-6;

/// The direction a cone slips in against the force that held it: any, where no force held it
/// (nothing pushes, and the cone's bound is zero).
fn against(force: [f64; 2]) -> [f64; 2] {
    let length = norm(force);
    if length > 0.0 { [-force[0] / length, -force[1] / length] } else { [1.0, 0.0] }
}

/// A cone's force `(λ_1, λ_2)` in `state`.
fn cone_force<M: Hybrid>(law: &Law, state: &State<M>) -> [f64; 2]
where
    DefaultAllocator: Storage<M>,
{
    let (_, row) = law.cone.expect("a cone");
    [state.lambda[law.row], state.lambda[row]]
}

/// Sets a cone's mode, its frozen slip direction (zero: stuck).
fn set_cone<M: Hybrid>(state: &mut State<M>, law: &Law, direction: [f64; 2])
where
    DefaultAllocator: Storage<M>,
{
    set_cone_in(&mut state.q, law, direction);
}

/// Sets a cone's mode in the positions `q`.
fn set_cone_in<M: Hybrid>(q: &mut VecQ<M>, law: &Law, direction: [f64; 2])
where
    DefaultAllocator: Storage<M>,
{
    let (mode, _) = law.cone.expect("a cone");
    q[law.mode] = direction[0];
    q[mode] = direction[1];
}

/// A cone's slip `(g_1, g_2)` at positions `q` and velocities `v`: its rows stuck, `A v + b`.
fn cone_slip<M: Hybrid>(model: &M, law: &Law, t: f64, q: &VecQ<M>, v: &VecQ<M>) -> [f64; 2]
where
    DefaultAllocator: Storage<M>,
{
    let (mode, row) = law.cone.expect("a cone");
    let mut q = q.clone();
    q[law.mode] = 0.0;
    q[mode] = 0.0;
    let shape = model.shape();
    let mut a = M::Algebra::zeros_cq(&shape);
    model.constraint_matrix(t, &q, &mut a);
    let mut rows = model.sizes().zeros_c::<M>();
    model.constraint_rate(t, &q, &mut rows);
    M::Algebra::cq_mul(&a, 1.0, v.as_slice(), rows.as_mut_slice());
    [rows[law.row], rows[row]]
}

/// The slip below which a cone counts as stopped at its engage event, at velocities `v`: a
/// few times the slip within which its kinetic force turns to its frozen direction, and not
/// below the round-off of the velocities.
fn stopped<M: Hybrid>(v: &VecQ<M>) -> f64
where
    DefaultAllocator: Storage<M>,
{
    (4.0 * CONE_ONSET).max(AT_ZERO * (1.0 + v.amax()))
}

/// The slip speed within which a cone's kinetic force turns to its frozen direction (the
/// derive's `CONE_ONSET`).
const CONE_ONSET: f64 = 1e-9;

fn norm(x: [f64; 2]) -> f64 {
    x[0].hypot(x[1])
}

/// Whether engaged `law` holds in the consistent `state`: its force strictly within its bound
/// (friction), its current not negative (diode); a closed switch holds.
fn holds<M: Hybrid>(model: &M, law: &Law, t: f64, state: &State<M>, values: &mut [f64]) -> bool
where
    DefaultAllocator: Storage<M>,
{
    model.events(t, &state.q, &state.v, &state.lambda, values);
    let margin = values[law.release];
    match law.kind {
        Kind::Friction if law.cone.is_some() => {
            margin > STRICTLY_WITHIN * (norm(cone_force(law, state)) + margin.abs())
        }
        Kind::Friction => margin > STRICTLY_WITHIN * (state.lambda[law.row].abs() + margin.abs()),
        Kind::Diode => margin >= 0.0,
        Kind::Switch => true,
    }
}

/// `state` made consistent in its modes, as they are.
fn consistent<M: Hybrid>(model: &M, t: f64, state: &mut State<M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    *state = project(model, t, &state.q, &state.v, Consistency::default())?;
    Ok(())
}

/// Where a solve of `model` with its laws watched starts from `state` at `t0`: `None` where
/// `state` already holds the mode [`consistent_with_laws`] chooses for each law (or the model
/// has none), and otherwise the consistent state in the modes chosen.
pub(crate) fn start_in_modes<M: Hybrid>(
    model: &M,
    t0: f64,
    state: &State<M>,
) -> Result<Option<State<M>>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    if !has_laws(model) {
        return Ok(None);
    }
    let chosen = consistent_with_laws(model, t0, &state.q, &state.v, Consistency::default())?;
    let same = laws(model).iter().all(|law| {
        chosen.q[law.mode] == state.q[law.mode]
            && law.cone.is_none_or(|(mode, _)| chosen.q[mode] == state.q[mode])
    });
    if same {
        dissipating(model, t0, state)?;
    }
    Ok((!same).then_some(chosen))
}

/// The consistent state nearest to positions `q` and velocities `v` at time `t`.
///
/// A model with friction laws or ideal diodes (`friction(...)`, `diode(...)`) has each law's
/// mode in a coordinate of its own (`<law>_mode`); whatever `q` holds there, the mode is chosen
/// from the state: stuck (0) where the relative velocity is zero and the friction force within
/// its bound, slipping (±1, the sign of the relative velocity) otherwise; a diode conducting
/// (0) where its reverse voltage is not positive and its current not negative, blocking (1)
/// otherwise.
pub fn consistent_state<M: Hybrid>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
    options: Consistency,
) -> Result<State<M>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    match has_laws(model) {
        true => consistent_with_laws(model, t, q, v, options),
        false => project(model, t, q, v, options),
    }
}

/// The consistent state nearest to positions `q` and velocities `v` at `t`, with each law's
/// mode chosen from them (whatever `q` held for it): released where its `g` is away from zero
/// (friction slipping to the side of its sign, a diode blocking where it is positive); engaged
/// where `g` is zero (or a diode's negative) if the law holds there, and otherwise released
/// (friction slipping the way its force pushed, a diode blocking).
pub fn consistent_with_laws<M: Hybrid>(
    model: &M,
    t: f64,
    q: &VecQ<M>,
    v: &VecQ<M>,
    options: Consistency,
) -> Result<State<M>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let laws = laws(model);
    let (mut q, mut v) = (q.clone(), v.clone());
    for law in &laws {
        v[law.mode] = 0.0;
        if let Some((mode, _)) = law.cone {
            v[mode] = 0.0;
        }
    }
    let v = &v;
    let mut values = vec![0.0; model.event_declarations().len()];
    // A cone slips along its `g` (keeping the direction frozen in `q` while the slip is within
    // its turn of it), or is tentatively stuck.
    let mut cones = Vec::new();
    for law in laws.iter().filter(|law| law.cone.is_some()) {
        let (mode, _) = law.cone.expect("a cone");
        let g = cone_slip(model, law, t, &q, v);
        let frozen = [q[law.mode], q[mode]];
        let turn = crate::model::names::CONE_TURN.to_radians().tan().recip();
        let (along, across) = (frozen[0] * g[0] + frozen[1] * g[1], frozen[0] * g[1] - frozen[1] * g[0]);
        let keeps = (norm(frozen) - 1.0).abs() < 1e-12 && along - turn * across.abs() > 0.0;
        let direction = match norm(g) > AT_ZERO * (1.0 + v.amax()) {
            true if keeps => frozen,
            true => [g[0] / norm(g), g[1] / norm(g)],
            false => {
                cones.push(law);
                [0.0, 0.0]
            }
        };
        q[law.mode] = direction[0];
        q[mode] = direction[1];
    }
    let lines: Vec<&Law> = laws.iter().filter(|law| law.cone.is_none()).collect();
    // Each other law's `g` is its engage function with the law released to the positive side.
    for law in &lines {
        q[law.mode] = 1.0;
    }
    model.events(t, &q, v, &model.sizes().zeros_c::<M>(), &mut values);
    let at_zero = AT_ZERO * (1.0 + v.amax());
    let mut tentative = cones;
    for law in lines {
        let g = values[law.engage];
        q[law.mode] = match (law.kind, g) {
            (Kind::Friction, g) if g.abs() > at_zero => g.signum(),
            (Kind::Diode, g) if g > at_zero => 1.0,
            // A switch's engage function released is minus its control: open unless positive.
            (Kind::Switch, g) if g >= 0.0 => 1.0,
            (Kind::Switch, _) => 0.0,
            _ => {
                tentative.push(law);
                0.0
            }
        };
    }
    let state = project(model, t, &q, v, options)?;
    let mut released = false;
    let mut starting = Vec::new();
    for law in tentative {
        if holds(model, law, t, &state, &mut values) {
            continue;
        }
        released = true;
        if law.cone.is_some() {
            starting.push((law, against(cone_force(law, &state))));
            continue;
        }
        q[law.mode] = if law.kind == Kind::Friction && state.lambda[law.row] > 0.0 { -1.0 } else { 1.0 };
    }
    if !starting.is_empty() {
        let names = starting.iter().map(|(law, _)| format!("`{}`", law.name)).collect::<Vec<_>>().join(", ");
        match starting_directions(model, t, &state, starting)? {
            Onset::Directions(directions) => {
                for (law, direction) in directions {
                    set_cone_in(&mut q, law, direction);
                }
            }
            Onset::Backwards(_) => {
                let cause = format!(
                    "the slips of {names} start together from rest, and in the only directions in which each slips \
                     along itself one would slip backwards"
                );
                return Err(SimError::NotDetermined { t, cause });
            }
        }
    }
    let state = if released { project(model, t, &q, v, options)? } else { state };
    dissipating(model, t, &state)?;
    Ok(state)
}

/// An error naming the row whose contact force drives friction that puts power into `model`
/// at `state` (`λ_j (B − A)_j v > 0`: a negative coefficient, or a contact force that pulls);
/// `Ok` for a model whose friction takes power out, or that has none on a contact force.
fn dissipating<M: Hybrid>(model: &M, t: f64, state: &State<M>) -> Result<(), SimError>
where
    DefaultAllocator: Storage<M>,
{
    if !M::NON_ASSOCIATED {
        return Ok(());
    }
    let shape = model.shape();
    let mut slip = M::Algebra::zeros_cq(&shape);
    model.slip_rows(t, &state.q, &state.v, &mut slip);
    let mut rates = model.sizes().zeros_c::<M>();
    M::Algebra::cq_mul(&slip, 1.0, state.v.as_slice(), rates.as_mut_slice());
    // Beyond the round-off of velocities that start a slip from rest.
    let scale = 1e-9 * amax(M::Algebra::cq_values(&slip)) * (1.0 + state.v.amax());
    for (j, (rate, lambda)) in rates.iter().zip(state.lambda.iter()).enumerate() {
        let power = rate * lambda;
        if power > scale * lambda.abs() {
            let row = model.constraint_names()[j].clone();
            return Err(SimError::FrictionPushes { t, row, power });
        }
    }
    Ok(())
}
