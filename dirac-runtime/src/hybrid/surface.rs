//! The linearised jump of a motion across a switching surface: where a non-smooth function or
//! a conditional of the model (`abs`, `signum`, `if a > b { … } else { … }`) switches, at
//! `g(t, q, v) = 0`, the state goes on continuously but its rate jumps from `f⁻` to `f⁺`, and
//! a change of the state or of a parameter that moves the crossing's time `t*` moves the state
//! after it by `(f⁻ − f⁺) δt*`:
//!
//! ```text
//! S = I + (f⁻ − f⁺) ∂t*/∂x,    ∂t*/∂x = −∂g/∂x / ġ⁻,    ġ⁻ = ∂g/∂t + ∂g/∂q v + ∂g/∂v v̇⁻,
//! ```
//!
//! `x = (q, v)`, `f = (v, v̇)`: only the velocities' rows of `S − I` are not zero. The
//! parameters' columns are `(f⁻ − f⁺) ∂t*/∂θ`, `∂t*/∂θ = −∂g/∂θ / ġ⁻`.
//!
//! `v̇` on each side is the acceleration of that side's branch at the crossing: the limit of
//! the accelerations from that side, extrapolated from two points just off the surface
//! (Richardson's, error `O(δ²)` for an offset `δ` of a millionth of the state's size), since at
//! the crossing itself the model evaluates whichever branch the round-off picks.

use nalgebra::{DMatrix, DVector, DefaultAllocator};

use crate::error::SimError;
use crate::hybrid::impact::accelerations;
use crate::model::blocks::ResidualBlocks;
use crate::model::state::State;
use crate::model::{Hybrid, Parameters};
use crate::shape::dims::{Storage, VecC, VecQ};

/// The relative offset from the surface at which each side's accelerations are read.
const OFFSET: f64 = 1e-6;

/// The jump of the sensitivities `s = ∂(q, v)/∂(·)` across a switching surface.
pub(crate) struct SurfaceJump {
    /// `S`, `2n × 2n`, positions first.
    pub matrix: DMatrix<f64>,
    /// The parameters' columns, `2n × P`.
    pub parameters: DMatrix<f64>,
}

/// The jump across the declared event function `surface` (its index among
/// [`Hybrid::events`], named `name`), a switching surface the motion crosses at `t` in the
/// state `at`; `what` names the computation that needs it, for its refusals.
///
/// Refused with [`SimError::InvalidOption`] for a model that does not emit its event
/// functions' gradients (a network, or a model with too many events for dense rows), a surface
/// that reads multipliers, a surface that switches a constraint (the state jumps there onto
/// the other side's constraints, a reset this jump does not carry), and a motion that does not
/// cross the surface there (both sides push into it, or both away: it slides along it, or
/// leaves it either way).
pub(crate) fn surface_jump<M: Hybrid + Parameters>(
    model: &M,
    t: f64,
    at: &State<M>,
    surface: usize,
    (name, what): (&str, &'static str),
) -> Result<SurfaceJump, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let sizes = model.sizes();
    let (n, m, params) = (sizes.nq, sizes.nc, model.parameter_count());
    let count = model.event_declarations().len();
    let Some(row) = event_gradient(model, t, (&at.q, &at.v, &at.lambda), surface) else {
        return refuse(
            what,
            format!(
                "the switching surface `{name}`: its gradient is not generated for this model (a network, \
                 or a model with too many events for dense rows), so a sensitivity cannot be carried \
                 across it"
            ),
        );
    };
    let (g_q, g_v, g_lambda) = (&row[..n], &row[n..2 * n], &row[2 * n..2 * n + m]);
    let (g_t, g_theta) = (row[2 * n + m], &row[2 * n + m + 1..]);
    if g_lambda.iter().any(|&d| d != 0.0) {
        return refuse(
            what,
            format!(
                "the switching surface `{name}` reads multipliers: its crossing's time depends on the \
             multipliers' sensitivities, which the jump does not carry"
            ),
        );
    }
    // Each side's accelerations, from the points offset along the surface's normal in (t, q, v).
    let norm = (g_t * g_t + g_q.iter().chain(g_v).map(|d| d * d).sum::<f64>()).sqrt();
    // The state's size, not the time's: the offset moves the positions and velocities too.
    let scale = at.q.iter().chain(at.v.iter()).fold(1.0f64, |s, x| s.max(x.abs()));
    if norm == 0.0 || !norm.is_finite() {
        return refuse(
            what,
            format!(
                "the switching surface `{name}` has no gradient at t = {t} ({norm:e}): the crossing's time \
             does not follow from the state there"
            ),
        );
    }
    let step = OFFSET * scale / norm;
    let mut values = vec![0.0; count];
    let (mut blocks, mut holonomic) = (ResidualBlocks::<M>::with_sizes(&sizes), sizes.zeros_h::<M>());
    // Each side's accelerations and constraints (`A v + b`, then `φ`), at the surface.
    let mut side = |sign: f64| -> Result<(DVector<f64>, DVector<f64>), SimError> {
        let zeros = || (DVector::<f64>::zeros(n), DVector::<f64>::zeros(m + sizes.nh));
        let mut points = [zeros(), zeros()];
        for (k, (rate, constraints)) in points.iter_mut().enumerate() {
            let d = sign * step * (k + 1) as f64;
            let ts = t + d * g_t;
            let mut q = at.q.clone();
            let mut v = at.v.clone();
            q.iter_mut().zip(g_q).for_each(|(x, &g)| *x += d * g);
            v.iter_mut().zip(g_v).for_each(|(x, &g)| *x += d * g);
            model.events(ts, &q, &v, &at.lambda, &mut values);
            if values[surface] * sign <= 0.0 {
                return refuse(
                    what,
                    format!(
                        "the switching surface `{name}` at t = {t}: a point a millionth of the state off it \
                     is still on the other side ({:e}), so its branches cannot be told apart there",
                        values[surface]
                    ),
                );
            }
            *rate = accelerations(model, ts, &q, &v)?;
            model.residual_blocks(ts, &q, &v, &at.lambda, &mut blocks);
            model.holonomic(ts, &q, &mut holonomic);
            constraints.rows_mut(0, m).copy_from_slice(blocks.constraint_velocity.as_slice());
            constraints.rows_mut(m, sizes.nh).copy_from_slice(holonomic.as_slice());
        }
        let [(near, near_constraints), (far, far_constraints)] = points;
        Ok((near * 2.0 - far, near_constraints * 2.0 - far_constraints))
    };
    let ((positive, on_positive), (negative, on_negative)) = (side(1.0)?, side(-1.0)?);
    // A constraint that switches there (a prescribed motion that steps) makes the state jump at
    // the crossing, onto the other side's constraints: a reset this jump does not carry.
    let jump = &on_positive - &on_negative;
    let size = on_positive.amax().max(on_negative.amax()).max(at.v.amax()).max(1.0);
    if let Some(row) = jump.iter().position(|d| d.abs() > 1e-7 * size) {
        let names = model.constraint_names();
        let which = if row < m {
            format!("the constraint `{}` (its velocity form)", names.get(row).map_or("?", |s| s.as_str()))
        } else {
            format!("the constraint `{}`", names.get(row - m).map_or("?", |s| s.as_str()))
        };
        return refuse(
            what,
            format!(
                "the switching surface `{name}` switches {which} at t = {t} (by {:e}): the state jumps there onto \
             the other side's constraints, and the sensitivity of that reset is not carried",
                jump[row]
            ),
        );
    }
    let speed = |a: &DVector<f64>| {
        g_t + g_q.iter().zip(at.v.iter()).map(|(g, v)| g * v).sum::<f64>()
            + g_v.iter().zip(a.iter()).map(|(g, a)| g * a).sum::<f64>()
    };
    let (rising, falling) = (speed(&negative), speed(&positive));
    let (before, after, speed) = if rising > 0.0 && falling > 0.0 {
        (negative, positive, rising)
    } else if rising < 0.0 && falling < 0.0 {
        (positive, negative, falling)
    } else {
        return refuse(
            what,
            format!(
                "the motion does not cross the switching surface `{name}` at t = {t}: its rate is {rising:e} \
             on the negative side and {falling:e} on the positive one, so it slides along it or leaves it \
             either way, and no crossing time follows from the state"
            ),
        );
    };
    let mut time = DVector::<f64>::zeros(2 * n);
    time.rows_mut(0, n).iter_mut().zip(g_q).for_each(|(x, &g)| *x = -g / speed);
    time.rows_mut(n, n).iter_mut().zip(g_v).for_each(|(x, &g)| *x = -g / speed);
    let time_parameters = DVector::from_iterator(params, g_theta.iter().map(|&g| -g / speed));
    Ok(rate_jump(&before, &after, &time, &time_parameters))
}

/// The gradient of the declared event function `event` at `(t, q, v, λ)`: `∂g/∂q`, `∂g/∂v`,
/// `∂g/∂λ`, `∂g/∂t` and `∂g/∂θ` in turn. `None` for a model that does not generate its event
/// functions' gradients (a network, or a model with too many events for dense rows).
pub(crate) fn event_gradient<M: Hybrid + Parameters>(
    model: &M,
    t: f64,
    (q, v, lambda): (&VecQ<M>, &VecQ<M>, &VecC<M>),
    event: usize,
) -> Option<Vec<f64>>
where
    DefaultAllocator: Storage<M>,
{
    let sizes = model.sizes();
    let count = model.event_declarations().len();
    let width = 2 * sizes.nq + sizes.nc + 1 + model.parameter_count();
    if model.event_derivatives_len() != count * width {
        return None;
    }
    let mut derivatives = vec![0.0; count * width];
    model.event_derivatives(t, q, v, lambda, &mut derivatives);
    derivatives.truncate((event + 1) * width);
    derivatives.drain(..event * width);
    Some(derivatives)
}

/// The jump of a motion whose accelerations change from `before` to `after` at a crossing whose
/// time moves by `time` per unit of the state `(q, v)` and by `time_parameters` per unit of
/// each parameter: `S = I + (f⁻ − f⁺) ∂t*/∂x`, and the parameters' columns
/// `(f⁻ − f⁺) ∂t*/∂θ`.
pub(crate) fn rate_jump(
    before: &DVector<f64>,
    after: &DVector<f64>,
    time: &DVector<f64>,
    time_parameters: &DVector<f64>,
) -> SurfaceJump {
    let n = before.len();
    let mut delay = DVector::<f64>::zeros(2 * n);
    delay.rows_mut(n, n).copy_from(&(before - after));
    let matrix = DMatrix::<f64>::identity(2 * n, 2 * n) + &delay * time.transpose();
    let parameters = &delay * time_parameters.transpose();
    SurfaceJump { matrix, parameters }
}

/// A sensitivity (`what`: forward, or the adjoint) refused across a switching surface, for
/// `reason`.
fn refuse<T>(what: &'static str, reason: String) -> Result<T, SimError> {
    Err(SimError::InvalidOption { what, reason })
}
