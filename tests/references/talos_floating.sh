#!/usr/bin/env bash
# Checks Talos on a free flyer (tests/robots/talos/talos_reduced.urdf, 32 joints) against
# Pinocchio's mass matrix, gravity and bias torques at 10 random states, as
# tests/integration/floating.rs checks the floating Panda in CI. Not part of CI: the humanoid's
# model takes minutes to compile. Installs Pinocchio into target/references/venv; builds a
# small crate under target/talos-floating that reads the same URDF.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
venv=target/references/venv
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet scipy pin
crate=target/talos-floating
mkdir -p "$crate/src"
"$venv/bin/python" tests/references/robots.py --floating tests/robots/talos/talos_reduced.urdf "$crate/talos_floating.csv" 47
cat > "$crate/Cargo.toml" <<TOML
[package]
name = "talos-floating"
version = "0.0.0"
edition = "2024"
publish = false

[dependencies]
dirac = { path = "$root" }

[workspace]
TOML
cat > "$crate/src/main.rs" <<RUST
use dirac::prelude::*;

#[path = "$root/tests/integration/free_flyer.rs"]
mod free_flyer;

/// Talos, its pelvis floating on Pinocchio's free flyer.
#[derive(LagrangeDirac)]
#[dirac(urdf = "$root/tests/robots/talos/talos_reduced.urdf", floating, large)]
struct Talos;

fn main() {
    let [m, g, b] = free_flyer::against_pinocchio(&Talos, include_str!("../talos_floating.csv"));
    println!("floating Talos against Pinocchio: mass matrix {m:.1e}, gravity {g:.1e}, bias {b:.1e}");
    assert!(m < 1e-12 && g < 1e-12 && b < 1e-12, "{m:e} {g:e} {b:e}");
}
RUST
cd "$crate"
CARGO_TARGET_DIR="$root/target/talos-floating/target" cargo run --quiet
