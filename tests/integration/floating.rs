//! Robots that float and slide, read from URDF files: the Panda on Pinocchio's free flyer
//! against Pinocchio (`tests/references/panda_floating.csv`, computed by
//! `tests/references/robots.py --floating`, independently of dirac), a torque-free symmetric top
//! against its closed form, and a puck on a planar joint under a gravity the model sets.

use dirac::State;
use dirac::nalgebra::{Matrix3, Vector3};
use dirac::prelude::*;

use crate::every_method::{Fineness, Method};
use crate::free_flyer::{against_pinocchio, coordinate, hat};
use crate::zoo::robots::{FloatingPanda, FreeTop, Puck};

/// `exp(θ k̂)` for the rotation vector `θ k` (Rodrigues).
fn rotation(axis_angle: Vector3<f64>) -> Matrix3<f64> {
    let angle = axis_angle.norm();
    if angle == 0.0 {
        return Matrix3::identity();
    }
    let k = hat(&(axis_angle / angle));
    Matrix3::identity() + k * angle.sin() + k * k * (1.0 - angle.cos())
}

#[test]
fn the_floating_panda_has_pinocchios_mass_matrix_gravity_and_bias_torques() {
    let [m, g, b] = against_pinocchio(&FloatingPanda, include_str!("../references/panda_floating.csv"));
    eprintln!("floating Panda against Pinocchio: mass matrix {m:.1e}, gravity {g:.1e}, bias {b:.1e}");
    assert!(m < 1e-12 && g < 1e-12 && b < 1e-12, "{m:e} {g:e} {b:e}");
}

/// The top's moments: `J₁ = J₂ = 1`, `J₃ = 2` (`tests/robots/free/top.urdf`), mass 2.
const TOP: (f64, f64, f64) = (1.0, 2.0, 2.0);

/// The torque-free symmetric top in closed form: with `h = R₀ J Ω₀` its angular momentum in
/// the world and `λ = (J₃ − J₁) Ω₃ / J₁`, `R(t) = exp(t ĥ / J₁) R₀ exp(−λ t ê₃)` (then
/// `RᵀṘ = Rᵀ ĥ R / J₁ − λ ê₃`, whose body components `J⁻¹ Rᵀ h` are the Euler equations'
/// solution), and the centre moves at its initial velocity.
fn top_in_closed_form(r0: &Matrix3<f64>, omega0: Vector3<f64>, t: f64) -> Matrix3<f64> {
    let (j1, j3, _) = TOP;
    let h = r0 * Vector3::new(j1 * omega0.x, j1 * omega0.y, j3 * omega0.z);
    let lambda = (j3 - j1) * omega0.z / j1;
    rotation(h * t / j1) * r0 * rotation(Vector3::new(0.0, 0.0, -lambda * t))
}

/// Every method follows the closed form; the variational one keeps the momenta (the outputs a
/// floating robot has) to round-off, since its discrete Lagrangian has the symmetries of the
/// continuous one.
#[test]
fn a_torque_free_floating_top_turns_as_its_closed_form_and_keeps_its_momenta() {
    let r0 = rotation(Vector3::new(0.3, -0.5, 0.8));
    let (x0, xdot, omega0) =
        (Vector3::new(0.1, -0.2, 0.3), Vector3::new(0.3, 0.0, -0.1), Vector3::new(0.4, -0.3, 1.5));
    let mut start = State::<FreeTop>::zeros();
    let rows = std::array::from_fn(|i| std::array::from_fn(|j| r0[(i, j)]));
    start.place_free_body("root_joint", x0.into(), rows, xdot.into(), omega0.into()).expect("a free joint");
    let wrong = State::<FreeTop>::zeros()
        .place_free_body("top", x0.into(), rows, xdot.into(), omega0.into())
        .map(|_| ());
    let message = wrong.expect_err("no free joint `top`").to_string();
    assert!(
        message.contains("no free joint `top`") && message.contains("its free joints: root_joint"),
        "{message}"
    );
    let start =
        consistent_state(&FreeTop, 0.0, &start.q, &start.v, Consistency::default()).expect("consistent");
    let times: Vec<f64> = (1..=10).map(f64::from).collect();
    each_integrator!(&FreeTop, Fineness::new(1e-12, 1e-12, 1e-3), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 10.0, &Sampling::Times(times.clone())).expect("a solution");
        let mut worst = 0.0_f64;
        for (k, &t) in solution.t().iter().enumerate() {
            let state = solution.state(k).expect("a sample");
            let r = Matrix3::from_fn(|i, j| {
                state.q[coordinate::<FreeTop>(&format!("root_joint_r{}{}", i + 1, j + 1))]
            });
            let x = Vector3::from_fn(|i, _| {
                state.q[coordinate::<FreeTop>(["root_joint_x", "root_joint_y", "root_joint_z"][i])]
            });
            worst =
                worst.max((r - top_in_closed_form(&r0, omega0, t)).amax()).max((x - (x0 + xdot * t)).amax());
        }
        let drift = |name: &str| {
            let column = solution.column(&format!("out({name})")).expect("a momentum");
            let scale = column.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
            column.iter().fold(0.0_f64, |m, x| m.max((x - column[0]).abs())) / scale
        };
        let momentum = ["linear_momentum_x", "linear_momentum_y", "linear_momentum_z"].map(drift);
        let angular = ["angular_momentum_x", "angular_momentum_y", "angular_momentum_z"].map(drift);
        let kept = momentum.into_iter().chain(angular).fold(0.0_f64, f64::max);
        eprintln!(
            "{}: the top against its closed form {worst:.1e} over 10 s, momenta kept to {kept:.1e}",
            method.name()
        );
        if method == Method::Variational {
            // h = 1e-3: second order, 10 s.
            assert!(worst < 1e-4, "{worst:e}");
            // Round-off, accumulated over 10⁴ steps.
            assert!(kept < 5e-13, "{kept:e}");
        } else {
            assert!(worst < 1e-8, "{worst:e}");
            assert!(kept < 1e-9, "{kept:e}");
        }
    });
}

/// A puck on a table's planar joint (the plane normal to z), its centre of mass 0.1 off its
/// frame's origin along its own x, with gravity `g` set by the model along −y: the centre
/// falls as `c₀ + ċ₀ t − ½ g t² ŷ` and the puck turns at its initial rate, so its frame's origin
/// is `c(t) − 0.1 (cos θ, sin θ)`.
#[test]
fn a_puck_on_a_planar_joint_falls_in_its_plane_under_the_gravity_the_model_sets() {
    let puck = Puck { g: 3.0 };
    let (x, y, theta) =
        (coordinate::<Puck>("slide_x"), coordinate::<Puck>("slide_y"), coordinate::<Puck>("slide_theta"));
    let mut start = State::<Puck>::zeros();
    (start.q[x], start.q[y], start.q[theta]) = (0.2, 0.1, 0.4);
    (start.v[x], start.v[y], start.v[theta]) = (0.5, 1.0, 2.0);
    let start = consistent_state(&puck, 0.0, &start.q, &start.v, Consistency::default()).expect("consistent");
    let centre = |q: [f64; 3]| [q[0] + 0.1 * q[2].cos(), q[1] + 0.1 * q[2].sin()];
    let c0 = centre([0.2, 0.1, 0.4]);
    let cdot0 = [0.5 - 0.1 * 2.0 * 0.4_f64.sin(), 1.0 + 0.1 * 2.0 * 0.4_f64.cos()];
    let times: Vec<f64> = (1..=4).map(|k| 0.5 * f64::from(k)).collect();
    each_integrator!(&puck, Fineness::new(1e-12, 1e-12, 1e-3), |method, integrator| {
        let solution =
            integrator.solve(0.0, &start, 2.0, &Sampling::Times(times.clone())).expect("a solution");
        let mut worst = 0.0_f64;
        for (k, &t) in solution.t().iter().enumerate() {
            let state = solution.state(k).expect("a sample");
            let angle = 0.4 + 2.0 * t;
            let c = [c0[0] + cdot0[0] * t, c0[1] + cdot0[1] * t - 0.5 * 3.0 * t * t];
            let want = [c[0] - 0.1 * angle.cos(), c[1] - 0.1 * angle.sin(), angle];
            for (got, want) in [state.q[x], state.q[y], state.q[theta]].into_iter().zip(want) {
                worst = worst.max((got - want).abs());
            }
        }
        eprintln!("{}: the puck against its closed form {worst:.1e}", method.name());
        let bound = if method == Method::Variational { 1e-5 } else { 1e-9 };
        assert!(worst < bound, "{worst:e}");
    });
    // The link's pose is an output; the frames between the planar joint's motions have none.
    let outputs = Puck::NAMES.output_names();
    assert!(
        outputs.iter().any(|o| o == "puck_z") && !outputs.iter().any(|o| o.starts_with("__")),
        "{outputs:?}"
    );
}
