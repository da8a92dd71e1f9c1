//! Snapshot tests of expanded code: the derive's output for small models, pretty-printed and
//! compared with files under `tests/snapshots/`. A change in generated code shows up as a
//! reviewed diff; `DIRAC_BLESS=1 cargo test -p dirac-macros snapshots` rewrites the files.

use std::path::PathBuf;

use quote::quote;

fn check(name: &str, input: proc_macro2::TokenStream) {
    check_with(name, input, crate::expand::derive);
}

fn check_with(
    name: &str,
    input: proc_macro2::TokenStream,
    derive: fn(&syn::DeriveInput) -> proc_macro2::TokenStream,
) {
    let input: syn::DeriveInput = syn::parse2(input).expect("test input parses");
    let expanded = derive(&input);
    let file: syn::File = syn::parse2(expanded).expect("expansion parses as items");
    let pretty = prettyplease::unparse(&file);
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/snapshots").join(format!("{name}.rs"));
    if std::env::var_os("DIRAC_BLESS").is_some() {
        std::fs::create_dir_all(path.parent().expect("has a parent")).expect("create snapshot folder");
        std::fs::write(&path, &pretty).expect("write snapshot");
        return;
    }
    let expected = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(expected == pretty, "expansion of {name} differs from {}:\n{pretty}", path.display());
}

#[test]
fn primitive_system_1() {
    check(
        "primitive1",
        quote! {
            #[dirac(coordinates(x1 => v1, x2 => v2), port(x2))]
            #[dirac(lagrangian = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2
                               - 0.5 * k1 * x1 * x1 - 0.5 * k2 * (x2 - x1).powi(2))]
            pub struct Primitive1 { pub m1: f64, pub m2: f64, pub k1: f64, pub k2: f64 }
        },
    );
}

#[test]
fn pendulum_with_holonomic_constraint() {
    check(
        "pendulum",
        quote! {
            #[dirac(coordinates(x => vx, y => vy))]
            #[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
            #[dirac(holonomic(rod) = x * x + y * y - l * l)]
            struct Pendulum { m: f64, g: f64, l: f64 }
        },
    );
}

#[test]
fn rolling_disk_with_velocity_constraints() {
    check(
        "rolling_disk",
        quote! {
            #[dirac(coordinates(x => v_x, y => v_y, theta => v_theta, phi => v_phi))]
            #[dirac(lagrangian = 0.5 * m * (v_x * v_x + v_y * v_y) + 0.5 * i_roll * v_theta * v_theta
                               + 0.5 * i_turn * v_phi * v_phi)]
            #[dirac(constraint(roll_x) = v_x - r * phi.cos() * v_theta)]
            #[dirac(constraint(roll_y) = v_y - r * sin(phi) * v_theta)]
            pub struct RollingDisk { pub m: f64, pub r: f64, pub i_roll: f64, pub i_turn: f64 }
        },
    );
}

#[test]
fn driven_oscillator_with_forces_and_time() {
    check(
        "driven_oscillator",
        quote! {
            #[dirac(coordinates(x => v))]
            #[dirac(lagrangian = 0.5 * m * v * v - 0.5 * k * x * x)]
            #[dirac(force(x) = -c * v + a * (w * t).sin())]
            pub struct DrivenOscillator { pub m: f64, pub k: f64, pub c: f64, pub a: f64, pub w: f64 }
        },
    );
}

#[test]
fn a_pendulum_with_a_wall_and_events() {
    check(
        "pendulum_and_wall",
        quote! {
            #[dirac(coordinates(x => vx, y => vy))]
            #[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
            #[dirac(holonomic(rod) = x * x + y * y - l * l)]
            #[dirac(unilateral(wall, restitution = e) = x - w * (y / l).cos())]
            #[dirac(event(slack, rising) = rod)]
            #[dirac(event(level) = y * vx)]
            pub struct PendulumAndWall { pub m: f64, pub g: f64, pub l: f64, pub e: f64, pub w: f64 }
        },
    );
}

#[test]
fn every_function_with_both_kinds_of_constraint() {
    check(
        "all_functions",
        quote! {
            #[dirac(coordinates(a => va, b => vb, c => vc))]
            #[dirac(lagrangian = 0.5 * m * (1.0 + 0.25 * a.sin().powi(2)) * va * va
                               + 0.5 * m * vb * vb / (1.0 + c * c) + 0.5 * (2.0 + vc.tanh()) * vc * vc
                               - k * (a.cos() + sqrt(1.0 + b * b) + (1.0 + a * a).ln() + b.exp() * 0.1)
                               + k * atan2(a, 2.0 + b * b) + k * (0.5 * c).tan() + k * c.atan()
                               + k * (a * b).sinh() * 0.1 + k * f64::cosh(0.5 * c) + (1.0 + b * b).powf(0.75)
                               + (2.0 + a * a).powf(0.1 * b) + std::f64::consts::PI * k * (1.0 + c * c).powi(-2))]
            #[dirac(holonomic(link) = a * a + b - c.sin())]
            #[dirac(constraint(slide) = vb * a.cos() - vc * (1.0 + a * a))]
            #[dirac(force(a) = -k * va * (t * 0.5).cos())]
            #[dirac(force(c) = -k * vc.powi(3) + b / (1.0 + t * t))]
            pub struct AllFunctions { pub m: f64, pub k: f64 }
        },
    );
}

#[test]
fn interconnection_by_ports() {
    check_with(
        "chain",
        quote! {
            #[dirac(connect(left.x2, right.x2bar))]
            pub struct Chain { pub left: Primitive1, pub right: Primitive2 }
        },
        |input| crate::interconnect::derive(input, crate::reduce::start),
    );
}

#[test]
fn interconnection_by_a_one_form() {
    check_with(
        "coupled_by_one_form",
        quote! {
            #[dirac(constraint(tie) = (1.0 + 0.1 * wheel.theta.sin()) * wheel.v_theta - c * cart.x.cos() * cart.v_x)]
            pub struct CoupledByOneForm { pub wheel: Wheel, pub cart: Cart, pub c: f64 }
        },
        |input| crate::interconnect::derive(input, crate::reduce::start),
    );
}
