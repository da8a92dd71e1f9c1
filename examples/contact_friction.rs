//! Coulomb friction on a contact force (`friction(slide, kinetic = mu * floor) = vx`): a block
//! and a ball on a slope, each case against its closed form.
//!
//! - a block sliding on the flat from `v0` stops after `v0² / (2 μ g)`;
//! - a block on a slope with `μ > tan θ` stays where it is;
//! - one with `μ < tan θ` slides down at `g (sin θ − μ cos θ)`;
//! - a ball that friction holds rolls down at `5/7 g sin θ`;
//! - a puck thrown along `x` on the flat with a side force `k μ m g` along `y` (a friction cone,
//!   `= (vx, vy)`) curves and stops at `x = 2 v0² / (μ g (4 − k²))`, `y = k v0² / (4 μ g (1 − k²))`;
//! - a top spinning on a round tip, its centre thrown sideways, slips and then rolls on it (no
//!   closed form: its pose while it slips and the time its tip holds are set beside MuJoCo's).
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

/// A puck on the floor `z = 0`, pushed along `y` by `side`, under Coulomb's cone.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy, z => vz))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy + vz * vz) - m * g * z)]
#[dirac(holonomic(floor) = z)]
#[dirac(force(y) = side)]
#[dirac(friction(slip, kinetic = mu * floor) = (vx, vy))]
#[dirac(nonnegative(mu))]
struct Puck {
    m: f64,
    g: f64,
    mu: f64,
    side: f64,
}

/// A symmetric top on a round tip: centre of mass `(x, y, z)`, ZXZ Euler angles (`psi`
/// precession, `theta` tilt, `phi` spin), the tip's centre at `l` below it along the axis and
/// the tip a ball of radius `r` touching the floor. The point that touches moves with the
/// tip's centre less `r` times the turn `ω × ẑ`; moments `a` across the axis and `c` about it.
#[derive(LagrangeDirac, Clone, Debug)]
#[dirac(coordinates(x => vx, y => vy, z => vz, psi => wpsi, theta => wtheta, phi => wphi))]
#[dirac(
    lagrangian = 0.5 * m * (vx * vx + vy * vy + vz * vz)
        + 0.5 * a * (wtheta * wtheta + wpsi * wpsi * sin(theta) * sin(theta))
        + 0.5 * c * (wphi + wpsi * cos(theta)) * (wphi + wpsi * cos(theta))
        - m * g * z
)]
#[dirac(holonomic(floor) = z - l * cos(theta) - r)]
#[dirac(define(wx) = wtheta * cos(psi) + wphi * sin(theta) * sin(psi))]
#[dirac(define(wy) = wtheta * sin(psi) - wphi * sin(theta) * cos(psi))]
#[dirac(friction(tip, kinetic = mu * floor) = (
    vx - l * (cos(theta) * wtheta * sin(psi) + sin(theta) * cos(psi) * wpsi) - r * wy,
    vy + l * (cos(theta) * wtheta * cos(psi) - sin(theta) * sin(psi) * wpsi) + r * wx
))]
#[dirac(nonnegative(mu))]
struct Top {
    m: f64,
    g: f64,
    l: f64,
    r: f64,
    a: f64,
    c: f64,
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

    let (m, mu, k, v0) = (2.0, 0.4, 0.5, 3.0);
    let puck = Puck { m, g: G, mu, side: k * mu * m * G };
    let mut v = VecQ::<Puck>::zeros();
    v[Puck::X.index()] = v0;
    let start = consistent_state(&puck, 0.0, &VecQ::<Puck>::zeros(), &v, Consistency::default())?;
    let end = Radau::new(&puck, RadauOptions::tolerances(1e-12, 1e-12))?
        .solve(0.0, &start, 1.5, &Sampling::Every(1.5))?
        .last()
        .expect("a sample at the end");
    let closed = [2.0 * v0 * v0 / (mu * G * (4.0 - k * k)), k * v0 * v0 / (4.0 * mu * G * (1.0 - k * k))];
    let case = "puck thrown with a side force (cone; mu 0.4; k 0.5)";
    println!("{case},stop x [m],{:.15e},{:.15e}", end.q[Puck::X.index()], closed[0]);
    println!("{case},stop y [m],{:.15e},{:.15e}", end.q[Puck::Y.index()], closed[1]);

    // 0.5 kg, the tip 4 cm below the centre, a ball of 2 mm; spinning at 200 rad/s, tilted 0.3.
    let top = Top { m: 0.5, g: G, l: 0.04, r: 0.002, a: 1.5e-4, c: 2e-4, mu: 0.3 };
    let theta0 = 0.3f64;
    let (mut q, mut v) = (VecQ::<Top>::zeros(), VecQ::<Top>::zeros());
    q[Top::THETA.index()] = theta0;
    q[Top::Z.index()] = top.l * theta0.cos() + top.r;
    (v[Top::X.index()], v[Top::PHI.index()]) = (0.3, 200.0);
    let start = consistent_state(&top, 0.0, &q, &v, Consistency::default())?;
    let solution = Radau::new(&top, RadauOptions::tolerances(1e-10, 1e-10))?.solve(
        0.0,
        &start,
        0.5,
        &Sampling::Times(vec![0.05, 0.5]),
    )?;
    let slipping = solution.state(0).expect("a sample at 0.05 s");
    let holds = solution.event_times("tip_stops").and_then(|t| t.last().copied()).unwrap_or(f64::NAN);
    let case = "top on a round tip (r 2 mm; mu 0.3; 200 rad/s)";
    println!("{case},centre x after 0.05 s [m],{:.15e},nan", slipping.q[Top::X.index()]);
    println!("{case},tilt after 0.05 s [rad],{:.15e},nan", slipping.q[Top::THETA.index()]);
    println!("{case},time its tip holds [s],{holds:.15e},nan");
    Ok(())
}
