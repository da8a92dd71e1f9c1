//! dirac's features, seen from a crate that depends on it: with the default features a model of
//! fixed size builds without the sparse path, ensembles or FMI (none of faer, rayon or zip in its
//! dependency graph), and a composite with an array of subsystems is refused when it compiles,
//! with one error that names the feature `sparse` and points at the array; with the feature on,
//! the same composite compiles.
//!
//! Each case is a scratch crate under this test's target directory, depending on this checkout
//! by path, checked by `cargo check --offline` (the workspace's lock file is copied, so every
//! crate is one the workspace has already downloaded). The scratch crates share one target
//! directory, so the dependencies are checked once.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// A pendulum: a model of fixed size, what a first crate has.
const PENDULUM: &str = r#"use dirac::prelude::*;
use dirac::State;

/// A planar pendulum in Cartesian coordinates, held on a circle by a rod.
#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(rod) = x * x + y * y - l * l)]
struct Pendulum {
    m: f64,
    g: f64,
    l: f64,
}

fn main() {
    let pendulum = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let mut state = State::<Pendulum>::zeros();
    state.set_q(Pendulum::X, 1.0);
    let mut radau = Radau::new(&pendulum, RadauOptions::default()).expect("options");
    let _ = radau.solve(0.0, &state, 1.0, &Sampling::Steps);
}
"#;

/// A ladder of LC sections: a composite with an array of subsystems (line 24 is the array).
const LADDER: &str = r#"use dirac::prelude::*;

/// One LC section.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(a => va, b => vb), port(a, b))]
#[dirac(lagrangian = 0.5 * c * vb * vb - (b - a) * (b - a) / (2.0 * l))]
struct Cell {
    l: f64,
    c: f64,
}

/// The grounded end.
#[derive(LagrangeDirac, Clone)]
#[dirac(coordinates(g => vg), port(g))]
#[dirac(lagrangian = 0.0 * vg)]
#[dirac(holonomic(grounded) = g)]
struct Ground {}

/// Sections in a row.
#[derive(Interconnection, Clone)]
#[dirac(connect(ground.g, cells[0].a), connect(cells[i].b, cells[i + 1].a))]
struct Ladder {
    ground: Ground,
    cells: Vec<Cell>,
}

fn main() {
    let ladder = Ladder { ground: Ground {}, cells: vec![Cell { l: 1.0, c: 1.0 }; 3] };
    assert_eq!(ladder.sizes().nq, 7);
}
"#;

/// A scratch crate `name` depending on this checkout with `features` (besides the default
/// ones), with the pendulum and the ladder as two programs.
fn scratch(name: &str, features: &[&str]) -> PathBuf {
    let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join("features");
    let dir = root.join(name);
    std::fs::create_dir_all(dir.join("src/bin")).expect("a scratch folder");
    let features = features.iter().map(|f| format!("\"{f}\"")).collect::<Vec<_>>().join(", ");
    let manifest = format!(
        "[package]\nname = \"{name}\"\nversion = \"0.1.0\"\nedition = \"2024\"\n\n[dependencies]\n\
         dirac = {{ path = {:?}, features = [{features}] }}\n\n[workspace]\n",
        checkout()
    );
    std::fs::write(dir.join("Cargo.toml"), manifest).expect("a manifest");
    std::fs::write(dir.join("src/bin/pendulum.rs"), PENDULUM).expect("a program");
    std::fs::write(dir.join("src/bin/ladder.rs"), LADDER).expect("a program");
    let lock = checkout().join("Cargo.lock");
    std::fs::copy(lock, dir.join("Cargo.lock")).expect("the workspace's lock file");
    dir
}

/// The checkout's root: the facade package and the workspace's lock file.
fn checkout() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("tests/ lies in the checkout")
}

/// `cargo ARGS` in `dir`, offline, into the scratch crates' shared target directory.
fn cargo(dir: &Path, args: &[&str]) -> Output {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let target = Path::new(env!("CARGO_TARGET_TMPDIR")).join("features").join("target");
    Command::new(cargo)
        .args(args)
        .arg("--offline")
        .current_dir(dir)
        .env("CARGO_TARGET_DIR", target)
        .env_remove("RUSTFLAGS")
        .output()
        .expect("cargo runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn with_default_features_a_model_of_fixed_size_builds_without_faer_rayon_or_zip() {
    let dir = scratch("lean_default", &[]);
    let tree = cargo(&dir, &["tree", "--edges", "normal,build", "--prefix", "none", "--format", "{p}"]);
    assert!(tree.status.success(), "{}", text(&tree.stderr));
    let mut crates: Vec<String> = text(&tree.stdout)
        .lines()
        .filter_map(|line| line.split_whitespace().next().map(str::to_owned))
        .filter(|name| name != "lean_default")
        .collect();
    crates.sort();
    crates.dedup();
    for heavy in ["faer", "rayon", "zip"] {
        assert!(!crates.iter().any(|c| c == heavy), "{heavy} is in the default build: {crates:?}");
    }
    // 87 crates were compiled for this crate before the features (BENCHMARKS.md, "First build
    // of a one-model crate"); the goal is at most half.
    assert!(crates.len() <= 43, "{} crates: {crates:?}", crates.len());

    let check = cargo(&dir, &["check", "--bin", "pendulum", "--message-format", "short"]);
    assert!(check.status.success(), "{}", text(&check.stderr));
}

#[test]
fn without_the_feature_sparse_an_array_of_subsystems_is_refused_naming_it_at_the_array() {
    let dir = scratch("lean_refused", &[]);
    let check = cargo(&dir, &["check", "--bin", "ladder", "--message-format", "short"]);
    let stderr = text(&check.stderr);
    assert!(!check.status.success(), "the ladder compiled without `sparse`:\n{stderr}");
    let errors: Vec<&str> =
        stderr.lines().filter(|l| l.contains("error:") && !l.contains("could not compile")).collect();
    // One error, at `Vec<Cell>` (line 24, column 12), naming the field and the feature.
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].starts_with("src/bin/ladder.rs:24:12: error: `cells` is an array of subsystems"),
        "{stderr}"
    );
    assert!(errors[0].contains("needs the feature `sparse` of dirac"), "{stderr}");
    assert!(errors[0].contains(r#"features = ["sparse"]"#), "{stderr}");
}

#[test]
fn with_the_feature_sparse_the_same_array_of_subsystems_compiles() {
    let dir = scratch("lean_sparse", &["sparse"]);
    let check = cargo(&dir, &["check", "--bin", "ladder", "--message-format", "short"]);
    assert!(check.status.success(), "{}", text(&check.stderr));
}

/// The README's first command, `cargo run --release --example mass_spring_chain`, compiles the
/// facade with its default features and the examples' dev-dependencies, nothing else: the
/// tests' and benchmarks' dependencies (trybuild, proptest, num-dual, criterion) live in their
/// own packages, and the examples that need a feature declare it.
#[test]
fn the_first_command_compiles_at_most_sixty_crates() {
    let manifest = checkout().join("Cargo.toml");
    let manifest = manifest.to_str().expect("a UTF-8 path");
    let tree = cargo(
        checkout(),
        &[
            "tree",
            "--manifest-path",
            manifest,
            "--package",
            "dirac",
            "--edges",
            "normal,build,dev",
            "--prefix",
            "none",
            "--format",
            "{p}",
        ],
    );
    assert!(tree.status.success(), "{}", text(&tree.stderr));
    let mut crates: Vec<String> = text(&tree.stdout)
        .lines()
        .filter_map(|line| line.split(" (").next().map(str::to_owned))
        .filter(|line| !line.is_empty())
        .collect();
    crates.sort();
    crates.dedup();
    for heavy in ["criterion", "trybuild", "proptest", "num-dual", "faer", "rayon", "zip"] {
        assert!(
            !crates.iter().any(|c| c.split(' ').next() == Some(heavy)),
            "{heavy} is in the first command: {crates:?}"
        );
    }
    // 166 crates before the tests and benchmarks became packages of their own (BENCHMARKS.md,
    // "First build of a one-model crate").
    assert!(crates.len() <= 60, "{} crates: {crates:?}", crates.len());
}
