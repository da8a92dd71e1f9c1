//! Coulomb friction on a contact force (`friction(slide, kinetic = mu * floor) = vx`): a block
//! and a ball on a slope, each case against its closed form.
//!
//! - a block sliding on the flat from `v0` stops after `v0² / (2 μ g)`;
//! - a block on a slope with `μ > tan θ` stays where it is;
//! - one with `μ < tan θ` slides down at `g (sin θ − μ cos θ)`;
//! - a ball that friction holds rolls down at `5/7 g sin θ`.
//!
//! Prints one line per case, `case,quantity,dirac,closed form`, which
//! `benches/peers/friction.sh` sets beside MuJoCo's run of the same cases.
//!
//! ```sh
//! cargo run --release --example contact_friction
//! ```

use dirac::prelude::*;

/// A block of mass `m` on a slope of angle `slope`, `x` down the slope and `y` off it, held on
/// it by the row `floor` and slowed by Coulomb friction on its contact force.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) + m * g * (x * sin(slope) - y * cos(slope)))]
#[dirac(holonomic(floor) = y)]
#[dirac(friction(slide, kinetic = mu * floor) = vx)]
#[dirac(nonnegative(mu))]
struct Block {
    m: f64,
    g: f64,
    slope: f64,
    mu: f64,
}

/// A ball of mass `m` and radius `r` on the same slope, turned by `phi`: friction acts where it
/// touches, whose velocity is `vx − r w`.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy, phi => w))]
#[dirac(
    lagrangian = 0.5 * m * (vx * vx + vy * vy) + 0.2 * m * r * r * w * w
        + m * g * (x * sin(slope) - y * cos(slope))
)]
#[dirac(holonomic(floor) = y)]
#[dirac(friction(touch, kinetic = mu * floor) = vx - r * w)]
#[dirac(nonnegative(mu))]
struct Ball {
    m: f64,
    g: f64,
    r: f64,
    slope: f64,
    mu: f64,
}

const G: f64 = 9.81;

/// Where `x` ends after `t_end`, from velocity `vx0` down the slope, with Radau at 1e-12.
fn final_x<M: Hybrid>(model: &M, vx0: f64, t_end: f64) -> Result<f64, SimError>
where
    DefaultAllocator: Storage<M>,
{
    let (q, mut v) = (model.sizes().zeros_q::<M>(), model.sizes().zeros_q::<M>());
    v[0] = vx0;
    let start = consistent_state(model, 0.0, &q, &v, Consistency::default())?;
    let solution = Radau::new(model, RadauOptions::tolerances(1e-12, 1e-12))?.solve(
        0.0,
        &start,
        t_end,
        &Sampling::Every(t_end),
    )?;
    Ok(solution.last().expect("a sample at the end").q[0])
}

fn main() -> Result<(), SimError> {
    let (v0, mu) = (3.0, 0.4);
    let stop = final_x(&Block { m: 2.0, g: G, slope: 0.0, mu }, v0, 2.0)?;
    println!("block stops on the flat,distance [m],{stop:.15e},{:.15e}", v0 * v0 / (2.0 * mu * G));
    let held = final_x(&Block { m: 2.0, g: G, slope: 0.3, mu: 0.5 }, 0.0, 10.0)?;
    println!("block held on a slope (mu 0.5; tan 0.3 = 0.31),drift in 10 s [m],{held:.15e},0");
    let (slope, mu) = (0.5, 0.3);
    let slides = final_x(&Block { m: 2.0, g: G, slope, mu }, 0.0, 2.0)?;
    let closed = 0.5 * G * (slope.sin() - mu * slope.cos()) * 4.0;
    println!(
        "block slides down a slope (mu 0.3; tan 0.5 = 0.55),x after 2 s [m],{slides:.15e},{closed:.15e}"
    );
    let slope = 0.4;
    let rolls = final_x(&Ball { m: 1.5, g: G, r: 0.1, slope, mu: 0.5 }, 0.0, 2.0)?;
    let closed = 0.5 * 5.0 / 7.0 * G * slope.sin() * 4.0;
    println!("ball rolls down a slope (mu 0.5),x after 2 s [m],{rolls:.15e},{closed:.15e}");
    Ok(())
}
