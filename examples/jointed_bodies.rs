//! Two rigid bodies on two hinges, written with named joints, once as they are (24 coordinates
//! of the bodies and 22 rows) and once under `#[dirac(reduce)]`, which compiles the same
//! declaration to the two joint angles. The program runs both with Radau, prints how far apart
//! they end and what each cost.

use std::error::Error;
use std::time::Instant;

use dirac::components::bodies::RigidBody;
use dirac::prelude::*;

macro_rules! double_pendulum {
    ($(#[$attr:meta])* $name:ident) => {
        /// Link 1 hangs from the origin by its point `a1` above its centre and turns about `y`;
        /// link 2 hangs from link 1's point `b1` below its centre by its own point `a2` above.
        #[derive(Interconnection, Clone, Debug)]
        $(#[$attr])*
        #[dirac(joint(th1 => w1) = revolute(y, world, link1 at [0.0, 0.0, a1]))]
        #[dirac(joint(th2 => w2) = revolute(y, link1 at [0.0, 0.0, -b1], link2 at [0.0, 0.0, a2]))]
        struct $name {
            link1: RigidBody,
            link2: RigidBody,
            a1: f64,
            b1: f64,
            a2: f64,
        }

        impl $name {
            fn new() -> $name {
                $name {
                    link1: RigidBody::new(1.5, [0.13, 0.126, 0.0063]).with_gravity(9.81),
                    link2: RigidBody::new(0.8, [0.025, 0.03, 0.0067]).with_gravity(9.81),
                    a1: 0.5,
                    b1: 0.5,
                    a2: 0.3,
                }
            }
        }
    };
}

double_pendulum!(Bodies);
double_pendulum!(
    #[dirac(reduce)]
    Angles
);

/// Link `k`'s angle about `y` from its rotation: `R e3 = (sin θ, 0, cos θ)`.
fn angle(s: &Solution<Bodies, impl Sized>, link: &str) -> Result<f64, Box<dyn Error>> {
    let at = |entry: &str| -> Result<f64, Box<dyn Error>> {
        let column = s.column(&format!("{link}.{entry}")).ok_or("a rotation entry")?;
        Ok(*column.last().ok_or("a sample")?)
    };
    Ok(at("r13")?.atan2(at("r33")?))
}

fn main() -> Result<(), Box<dyn Error>> {
    println!(
        "as bodies: {} coordinates, {} rows; reduced: {:?}, {} rows, {} coordinates eliminated",
        Bodies::NAMES.coordinate_names().len(),
        Bodies::NAMES.constraint_names().len(),
        Angles::NAMES.coordinate_names(),
        Angles::NAMES.constraint_names().len(),
        Angles::ELIMINATED.len()
    );
    let (th, w) = ([0.9f64, -0.4f64], [0.3, 1.1]);
    let end = Sampling::Times(vec![2.0]);

    let angles = Angles::new();
    let mut q = VecQ::<Angles>::zeros();
    let mut v = VecQ::<Angles>::zeros();
    // The second joint's angle is link 2's angle to link 1.
    (q[0], q[1], v[0], v[1]) = (th[0], th[1] - th[0], w[0], w[1] - w[0]);
    let start = consistent_state(&angles, 0.0, &q, &v, Consistency::default())?;
    let clock = Instant::now();
    let reduced =
        Radau::new(&angles, RadauOptions::tolerances(1e-10, 1e-10))?.solve(0.0, &start, 2.0, &end)?;
    let reduced_time = clock.elapsed();
    let last = reduced.last().ok_or("a sample")?;
    let reduced_angles = [last.q[0], last.q[0] + last.q[1]];

    let bodies = Bodies::new();
    let pose = |body: &RigidBody, centre: [f64; 3], theta: f64, velocity: [f64; 3], rate: f64| {
        let (s, c) = theta.sin_cos();
        body.state(centre, [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]], velocity, [0.0, rate, 0.0])
    };
    let (a1, l1, a2) = (bodies.a1, bodies.a1 + bodies.b1, bodies.a2);
    let (s1, c1, s2, c2) = (th[0].sin(), th[0].cos(), th[1].sin(), th[1].cos());
    let (q1, v1) =
        pose(&bodies.link1, [-a1 * s1, 0.0, -a1 * c1], th[0], [-a1 * c1 * w[0], 0.0, a1 * s1 * w[0]], w[0]);
    let (q2, v2) = pose(
        &bodies.link2,
        [-l1 * s1 - a2 * s2, 0.0, -l1 * c1 - a2 * c2],
        th[1],
        [-l1 * c1 * w[0] - a2 * c2 * w[1], 0.0, l1 * s1 * w[0] + a2 * s2 * w[1]],
        w[1],
    );
    let (mut q, mut v) = (VecQ::<Bodies>::zeros(), VecQ::<Bodies>::zeros());
    q.rows_mut(0, 12).copy_from(&q1);
    q.rows_mut(12, 12).copy_from(&q2);
    v.rows_mut(0, 12).copy_from(&v1);
    v.rows_mut(12, 12).copy_from(&v2);
    let start = consistent_state(&bodies, 0.0, &q, &v, Consistency::default())?;
    let options = RadauOptions { projection: true, ..RadauOptions::tolerances(1e-10, 1e-10) };
    let clock = Instant::now();
    let full = Radau::new(&bodies, options)?.solve(0.0, &start, 2.0, &end)?;
    let full_time = clock.elapsed();
    let full_angles = [angle(&full, "link1")?, angle(&full, "link2")?];

    println!("link angles at t = 2 s: reduced {reduced_angles:.9?}, as bodies {full_angles:.9?}");
    let apart = (reduced_angles[0] - full_angles[0]).abs().max((reduced_angles[1] - full_angles[1]).abs());
    println!(
        "apart by {apart:.1e} rad; Radau took {reduced_time:.2?} reduced against {full_time:.2?} as bodies"
    );
    if apart > 1e-7 {
        return Err(format!("the two forms of the pendulum end {apart:e} rad apart").into());
    }
    Ok(())
}
