//! The linearised jump of a motion at a law's switch (friction that sticks or slips, a diode
//! that conducts or blocks, an ideal switch that closes or opens).
//!
//! At the switch, located where the event function `h` falls through zero, the law's mode
//! coordinate changes and with it the model's constraints, but the positions and velocities go
//! on continuously: engaging, the new row `g = 0` holds there already (it is where `h = ±g`
//! reached zero); releasing, a row is dropped. Only the rate jumps, from `f⁻` (the old mode's)
//! to `f⁺` (the new one's), and the jump is a switching surface's (see the `surface` module):
//!
//! ```text
//! S = I + (f⁻ − f⁺) ∂t*/∂x,    ∂t*/∂x = −(dh/dx) / ḣ⁻,    ∂t*/∂θ = −(dh/dθ) / ḣ⁻.
//! ```
//!
//! Engaging, `S` leaves each sensitivity on the new row's linearisation by itself:
//! `∂g/∂x S s = ∂g/∂x s − ġ⁻ (∂g/∂x s)/ġ⁻ = 0`, since `ġ⁺ = 0` in the engaged mode.
//!
//! A release reads the law's force, the multiplier `λ` of its row (`f_s − |λ|` for friction,
//! `λ` for a diode), so its total derivatives carry `λ`'s: `dh/dx = ∂h/∂x + ∂h/∂λ ∂λ/∂x` and
//! `ḣ⁻ = ∂h/∂t + ∂h/∂q v + ∂h/∂v v̇ + ∂h/∂λ λ̇`, with `λ(t, q, v, θ)` the multipliers of the
//! equations of motion at acceleration level in the engaged mode. `∂λ/∂(t, q, v)` are central
//! differences of those multipliers, Richardson-extrapolated (error `O(δ⁴)`, `δ` a
//! ten-thousandth of each coordinate's size). `∂λ/∂θ` is exact up to one directional
//! difference along the motion: differentiating the acceleration-level system
//! `K (v̇, λ) = r` by `θ` at fixed `(t, q, v)`,
//!
//! ```text
//! K (∂v̇/∂θ, ∂λ/∂θ) = (∂ṗ/∂θ − D(∂(∂L/∂v)/∂θ), −D(∂(A v + b)/∂θ)),
//! ```
//!
//! where `D` is the derivative along the motion `(1, v, v̇)` in `(t, q, v)` and `∂ṗ/∂θ`,
//! `∂(∂L/∂v)/∂θ`, `∂(A v + b)/∂θ` are the generated parameter derivatives of the residual blocks.
//! A coordinate without mass that no constraint reaches has its force balance differentiated
//! along the motion in place of its row (see `impact::motion_at`); its row here is
//! `−D(∂ṗ_i/∂θ)`.
//!
//! The mode coordinates are discrete: their columns of `∂t*/∂x` are left out, and their rows
//! of `S` are zero (the switch sets them, and their rates, by logic).

use nalgebra::{DVector, DefaultAllocator};

use crate::error::SimError;
use crate::hybrid::impact::{Motion, accelerations, motion_at};
use crate::hybrid::surface::{SurfaceJump, event_gradient, rate_jump};
use crate::model::blocks::ResidualBlocks;
use crate::model::state::State;
use crate::model::{Hybrid, Parameters};
use crate::shape::dims::{Storage, VecQ};

/// The relative step of the differences of the multipliers.
const STEP: f64 = 1e-4;

/// The jump at the switch of a law at its declared event `event` (its index among
/// [`Hybrid::events`], named `name`), located at `t`: `before` is the state there in the old
/// mode, `after` the consistent state in the new one; `modes` are the model's mode coordinates.
/// `what` names the computation that needs it, for its refusals.
///
/// Refused with [`SimError::InvalidOption`] for a model that does not emit its event
/// functions' gradients (a network, or a model with too many events for dense rows), and where
/// the motion does not cross the event's zero (grazes it).
pub(crate) fn law_jump<M: Hybrid + Parameters>(
    model: &M,
    t: f64,
    before: &State<M>,
    after: &State<M>,
    event: usize,
    modes: &[usize],
    (name, what): (&str, &'static str),
) -> Result<SurfaceJump, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let sizes = model.sizes();
    let (n, m) = (sizes.nq, sizes.nc);
    let refuse = |reason: String| Err(SimError::InvalidOption { what, reason });
    let old = motion_at(model, t, &before.q, &before.v)?;
    let new = accelerations(model, t, &after.q, &after.v)?;
    let mut lambda = sizes.zeros_c::<M>();
    lambda.copy_from_slice(old.multipliers.as_slice());
    let Some(row) = event_gradient(model, t, (&before.q, &before.v, &lambda), event) else {
        return refuse(format!(
            "the law's event `{name}`: its gradient is not generated for this model (a network, or a \
             model with too many events for dense rows), so the switch's jump is not known"
        ));
    };
    let g_lambda = DVector::from_column_slice(&row[2 * n..2 * n + m]);
    // The gradient in (q, v, t), then the parameters'.
    let mut g_x = DVector::from_iterator(2 * n + 1, row[..2 * n].iter().chain([&row[2 * n + m]]).copied());
    let mut g_theta = DVector::from_column_slice(&row[2 * n + m + 1..]);
    if g_lambda.iter().any(|&d| d != 0.0) {
        for i in 0..=2 * n {
            if modes.iter().any(|&k| i == k || i == n + k) {
                continue;
            }
            g_x[i] += g_lambda.dot(&multipliers_by(model, t, before, i)?);
        }
        g_theta += multipliers_by_parameters(model, t, before, &old, &lambda)?.tr_mul(&g_lambda);
    }
    for &k in modes {
        g_x[k] = 0.0;
        g_x[n + k] = 0.0;
    }
    let speed = g_x[2 * n]
        + g_x.rows(0, n).dot(&DVector::from_column_slice(before.v.as_slice()))
        + g_x.rows(n, n).dot(&old.accelerations);
    if !speed.is_finite() || speed >= 0.0 {
        return refuse(format!(
            "the law's event `{name}` at t = {t}: its function's rate there is {speed:e}, so the motion \
             grazes its zero rather than crossing it, and the switch's time does not follow from the state"
        ));
    }
    let time = DVector::from_iterator(2 * n, g_x.rows(0, 2 * n).iter().map(|&g| -g / speed));
    let time_parameters = g_theta.map(|g| -g / speed);
    let mut jump = rate_jump(&old.accelerations, &new, &time, &time_parameters);
    // The switch sets every mode coordinate and its rate by logic: their sensitivities restart
    // at zero, so that round-off in them does not grow over the switches that follow.
    for &k in modes {
        jump.matrix.row_mut(k).fill(0.0);
        jump.matrix.row_mut(n + k).fill(0.0);
        jump.parameters.row_mut(k).fill(0.0);
        jump.parameters.row_mut(n + k).fill(0.0);
    }
    Ok(jump)
}

/// `∂λ/∂x_i` at the state `at` (`x = (q, v, t)`, `i = 2n` the time), by central differences of
/// the acceleration-level multipliers, Richardson-extrapolated.
fn multipliers_by<M: Hybrid>(model: &M, t: f64, at: &State<M>, i: usize) -> Result<DVector<f64>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let n = at.q.len();
    let x = if i < n {
        at.q[i]
    } else if i < 2 * n {
        at.v[i - n]
    } else {
        t
    };
    let h = STEP * x.abs().max(1.0);
    let (mut q, mut v) = (at.q.clone(), at.v.clone());
    let mut at_offset = |d: f64| -> Result<DVector<f64>, SimError> {
        let mut ts = t;
        match i {
            i if i < n => q[i] = x + d,
            i if i < 2 * n => v[i - n] = x + d,
            _ => ts = t + d,
        }
        let lambda = motion_at(model, ts, &q, &v)?.multipliers;
        q.copy_from(&at.q);
        v.copy_from(&at.v);
        Ok(lambda)
    };
    let near = (at_offset(h)? - at_offset(-h)?) / (2.0 * h);
    let far = (at_offset(2.0 * h)? - at_offset(-2.0 * h)?) / (4.0 * h);
    Ok((near * 4.0 - far) / 3.0)
}

/// `∂λ/∂θ` at the state `at` (`m × P`), from the acceleration-level system `old` solved there
/// with its multipliers `lambda`: see the module's documentation.
fn multipliers_by_parameters<M: Hybrid + Parameters>(
    model: &M,
    t: f64,
    at: &State<M>,
    old: &Motion,
    lambda: &crate::shape::dims::VecC<M>,
) -> Result<nalgebra::DMatrix<f64>, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let sizes = model.sizes();
    let (n, m, params) = (sizes.nq, sizes.nc, model.parameter_count());
    let mut out = nalgebra::DMatrix::<f64>::zeros(m, params);
    let mut blocks = ResidualBlocks::<M>::with_sizes(&sizes);
    // The step along the motion (1, v, v̇), scaled to the state's size.
    let size = at.q.iter().chain(at.v.iter()).fold(1.0f64, |s, x| s.max(x.abs()));
    let rate = 1.0 + at.v.amax() + old.accelerations.amax();
    let h = STEP * size / rate;
    let (mut q, mut v) = (VecQ::<M>::clone(&at.q), VecQ::<M>::clone(&at.v));
    let mut rhs = DVector::<f64>::zeros(n + m);
    for k in 0..params {
        // `(∂(∂L/∂v)/∂θ, ∂(A v + b)/∂θ)` at `d` along the motion.
        let mut along = |d: f64| -> DVector<f64> {
            q.iter_mut().zip(at.q.iter().zip(at.v.iter())).for_each(|(x, (q, v))| *x = q + d * v);
            v.iter_mut()
                .zip(at.v.iter().zip(old.accelerations.iter()))
                .for_each(|(x, (v, a))| *x = v + d * a);
            model.residual_blocks_dtheta(k, t + d, &q, &v, lambda, &mut blocks);
            let rates = blocks
                .dl_dv
                .iter()
                .chain(blocks.constraint_velocity.iter())
                .chain(blocks.momentum_rate.iter());
            DVector::from_iterator(2 * n + m, rates.copied())
        };
        let near = (along(h) - along(-h)) / (2.0 * h);
        let far = (along(2.0 * h) - along(-2.0 * h)) / (4.0 * h);
        let derivative = (near * 4.0 - far) / 3.0;
        model.residual_blocks_dtheta(k, t, &at.q, &at.v, lambda, &mut blocks);
        for i in 0..n {
            rhs[i] = blocks.momentum_rate[i] - derivative[i];
        }
        for i in 0..m {
            rhs[n + i] = -derivative[n + i];
        }
        // A coordinate without mass: its force balance differentiated along the motion.
        for &i in &old.massless {
            rhs[i] = -derivative[n + m + i];
        }
        if !old.system.solve_mut(&mut rhs) || rhs.iter().any(|x| !x.is_finite()) {
            return Err(SimError::NotDetermined {
                t,
                cause: "the law's force's derivative: the mass matrix bordered by the constraint rows is \
                        singular there"
                    .into(),
            });
        }
        out.column_mut(k).copy_from(&rhs.rows(n, m));
    }
    Ok(out)
}
