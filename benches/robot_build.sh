#!/usr/bin/env bash
# What a robot read from a URDF file costs to build: a user crate whose main.rs holds the
# Panda (tests/robots/panda/panda.urdf, 9 joints) or the Talos humanoid
# (tests/robots/talos/talos_reduced.urdf, 32 moving joints, 20 of them with Coulomb friction),
# built once cold, then `touch src/main.rs` and `cargo build --release` ROUNDS times (the
# rebuild after an edit: the derive expands again and the model's code is compiled again;
# dirac itself is not rebuilt). Each crate's program then simulates its robot for 1 s. The
# expansion alone, as the derive runs inside such a build (unoptimised, Cargo's default for
# proc macros), is timed by `DIRAC_TALOS=1 cargo test -p dirac-expand --lib urdf::tests --
# --nocapture`. Not part of CI.
#
#   bash benches/robot_build.sh [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
rounds=${1:-3}
dir=target/robot-build
mkdir -p "$dir"

crate() {
    local name=$1 main=$2
    mkdir -p "$dir/$name/src"
    cat > "$dir/$name/Cargo.toml" <<TOML
[package]
name = "$name"
version = "0.1.0"
edition = "2024"

[dependencies]
dirac = { path = "$root" }

[workspace]
TOML
    cp Cargo.lock "$dir/$name/Cargo.lock"
    printf '%s\n' "$main" > "$dir/$name/src/main.rs"
}

crate panda "use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(urdf = \"$root/tests/robots/panda/panda.urdf\")]
struct Panda;

fn main() -> Result<(), SimError> {
    let q = VecQ::<Panda>::from_column_slice(&[0.3, 0.5, -0.4, -1.2, 0.2, 1.4, 0.6, 0.02, 0.02]);
    let start = consistent_state(&Panda, 0.0, &q, &VecQ::<Panda>::zeros(), Consistency::default())?;
    let clock = std::time::Instant::now();
    let mut radau = Radau::new(&Panda, RadauOptions::tolerances(1e-8, 1e-8))?;
    let swing = radau.solve(0.0, &start, 1.0, &Sampling::Every(0.01))?;
    println!(\"Panda: 1 s swing in {:?}, {} steps\", clock.elapsed(), swing.stats.steps);
    Ok(())
}"

crate talos "use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(urdf = \"$root/tests/robots/talos/talos_reduced.urdf\", large)]
struct Talos;

fn simulate() -> Result<(), SimError> {
    let sizes = Talos.sizes();
    let mut q = VecQ::<Talos>::zeros();
    for (i, name) in Talos::NAMES.coordinate_names().iter().enumerate() {
        if name.starts_with(\"arm_left_4\") || name.starts_with(\"arm_right_4\") {
            q[i] = -0.5;
        }
        if name.starts_with(\"leg_left_1\") {
            q[i] = 0.3;
        }
    }
    let start = consistent_state(&Talos, 0.0, &q, &VecQ::<Talos>::zeros(), Consistency::default())?;
    let clock = std::time::Instant::now();
    let mut explicit = Explicit::new(&Talos, ExplicitOptions::tolerances(1e-6, 1e-6))?;
    let swing = explicit.solve(0.0, &start, 1.0, &Sampling::Every(0.01))?;
    println!(
        \"Talos: {} coordinates, {} rows; 1 s in {:?}, {} steps, {} friction events\",
        sizes.nq, sizes.nc, clock.elapsed(), swing.stats.steps, swing.events().len()
    );
    Ok(())
}

fn main() {
    let run = std::thread::Builder::new().stack_size(256 << 20).spawn(simulate).expect(\"a thread\");
    run.join().expect(\"the simulation\").expect(\"a swing\");
}"

for name in panda talos; do
    (cd "$dir/$name" && cargo build --release --quiet 2>/dev/null)
    times=()
    for _ in $(seq "$rounds"); do
        touch "$dir/$name/src/main.rs"
        start=$(date +%s.%N)
        (cd "$dir/$name" && cargo build --release --quiet 2>/dev/null)
        times+=("$(echo "$(date +%s.%N) - $start" | bc)")
    done
    echo "$name: release rebuilds after an edit: ${times[*]} s"
    "$dir/$name/target/release/$name"
done
