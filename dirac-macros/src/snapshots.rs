//! Snapshot tests of expanded code: the derive's output for small models, pretty-printed and
//! compared with files under `tests/snapshots/`. A change in generated code shows up as a
//! reviewed diff; `DIRAC_BLESS=1 cargo test -p dirac-macros snapshots` rewrites the files.

use std::path::PathBuf;

use quote::quote;

fn check(name: &str, input: proc_macro2::TokenStream) {
    let input: syn::DeriveInput = syn::parse2(input).expect("test input parses");
    let expanded = crate::expand::derive(&input);
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
