#!/usr/bin/env bash
# Cold build of a user crate that uses ten parts of dirac::components against one that uses none
# (the README's pendulum), each from an empty target directory, `cargo build --release`, A B A B.
# Both depend on dirac by path and pin the workspace's Cargo.lock; the registry must hold the
# crates (it does after the workspace has built once). Not part of CI.
#
#   bash benches/build_cost.sh [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
rounds=${1:-2}
dir=target/build-cost
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

crate none 'use dirac::prelude::*;

#[derive(LagrangeDirac)]
#[dirac(coordinates(x => vx, y => vy))]
#[dirac(lagrangian = 0.5 * m * (vx * vx + vy * vy) - m * g * y)]
#[dirac(holonomic(rod) = x * x + y * y - l * l)]
struct Pendulum { m: f64, g: f64, l: f64 }

fn main() -> Result<(), SimError> {
    let model = Pendulum { m: 1.0, g: 9.81, l: 1.0 };
    let q = VecQ::<Pendulum>::from([1.0, 0.0]);
    let start = consistent_state(&model, 0.0, &q, &VecQ::<Pendulum>::zeros(), Consistency::default())?;
    let solution = Radau::new(&model, RadauOptions::tolerances(1e-8, 1e-8))?.solve(0.0, &start, 1.0, &Sampling::Steps)?;
    println!("{}", solution.len());
    Ok(())
}'

crate ten 'use dirac::components::electrical::{Ground, Inductor, Resistor, StepVoltage};
use dirac::components::electromechanical::Emf;
use dirac::components::rotational::{Damper, Fixed, IdealGear, Inertia};
use dirac::prelude::*;

#[derive(Interconnection)]
#[dirac(
    connect(source.p, r.p), connect(r.n, l.p), connect(l.n, emf.p), connect(emf.n, ground.p),
    connect(source.n, ground.p), connect(emf.phi, rotor.phi), connect(rotor.phi, gear.a),
    connect(gear.b, load.phi), connect(load.phi, bearing.b), connect(bearing.a, housing.phi)
)]
struct Drive {
    source: StepVoltage, r: Resistor, l: Inductor, emf: Emf, ground: Ground,
    rotor: Inertia, gear: IdealGear, load: Inertia, bearing: Damper, housing: Fixed,
}

fn main() -> Result<(), SimError> {
    let model = Drive {
        source: StepVoltage { offset: 0.0, height: 12.0, start: 0.0 }, r: Resistor { r: 1.0 },
        l: Inductor { l: 0.05 }, emf: Emf { k: 0.5 }, ground: Ground {}, rotor: Inertia { j: 0.01 },
        gear: IdealGear { ratio: 4.0 }, load: Inertia { j: 0.05 }, bearing: Damper { d: 0.1 },
        housing: Fixed { phi0: 0.0 },
    };
    let zero = VecQ::<Drive>::zeros();
    let start = consistent_state(&model, 0.0, &zero, &zero, Consistency::default())?;
    let solution = Radau::new(&model, RadauOptions::tolerances(1e-8, 1e-8))?.solve(0.0, &start, 1.0, &Sampling::Steps)?;
    println!("{}", solution.len());
    Ok(())
}'

build() {
    rm -rf "$dir/$1/target"
    local start end
    start=$(date +%s.%N)
    (cd "$dir/$1" && cargo build --release --quiet)
    end=$(date +%s.%N)
    echo "$end - $start" | bc
}

echo "round,none_s,ten_s,ratio"
for round in $(seq 1 "$rounds"); do
    a=$(build none)
    b=$(build ten)
    echo "$round,$a,$b,$(echo "scale=3; $b / $a" | bc)"
done
(cd "$dir/none" && ./target/release/none > /dev/null) && (cd "$dir/ten" && ./target/release/ten > /dev/null)
echo "both binaries ran"
