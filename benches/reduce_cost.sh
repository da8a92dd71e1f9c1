#!/usr/bin/env bash
# What `#[dirac(reduce)]` costs a crate's `cargo check`: a composite of 100 parts (two `Segment`s
# of 25 rotational inertias and the 24 springs between them, reduced each on its own, a spring
# joining them and a fixed flange) with `reduce` at both levels against the same composite
# without it (`large`). Each round touches one crate's source and checks it, then the other's
# (its dependencies checked once before), and prints both times and their ratio; the medians
# last. Both crates share one target directory and pin the workspace's Cargo.lock. Not part of CI.
#
#   bash benches/reduce_cost.sh [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
rounds=${1:-5}
dir=target/reduce-cost
mkdir -p "$dir"
export CARGO_TARGET_DIR="$root/$dir/target" CARGO_INCREMENTAL=0

crate() {
    local name=$1 attribute=$2
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
    {
        echo 'use dirac::components::rotational::{Fixed, Inertia, Spring};'
        echo 'use dirac::prelude::*;'
        echo
        echo '#[derive(Interconnection, Clone, Debug)]'
        echo "#[dirac($attribute)]"
        for k in $(seq 0 23); do
            echo "#[dirac(connect(s$k.a, i$k.phi), connect(s$k.b, i$((k + 1)).phi))]"
        done
        printf 'pub struct Segment {'
        for k in $(seq 0 24); do printf ' pub i%d: Inertia,' "$k"; done
        for k in $(seq 0 23); do printf ' pub s%d: Spring,' "$k"; done
        echo ' }'
        echo
        echo '#[derive(Interconnection, Clone, Debug)]'
        echo "#[dirac($attribute)]"
        echo '#[dirac(connect(housing.phi, a.i0.phi), connect(join.a, a.i24.phi), connect(join.b, b.i0.phi))]'
        echo 'pub struct Chain { pub housing: Fixed, pub a: Segment, pub join: Spring, pub b: Segment }'
        echo
        echo 'fn main() { println!("{} coordinates", Chain::NAMES.coordinate_names().len()); }'
    } > "$dir/$name/src/main.rs"
}

crate reduced reduce
crate unreduced large

check() {
    local start end
    touch "$dir/$1/src/main.rs"
    start=$(date +%s.%N)
    (cd "$dir/$1" && cargo check -q)
    end=$(date +%s.%N)
    echo "$end - $start" | bc
}

# The coordinate counts, and every dependency checked before the first round.
for name in reduced unreduced; do
    (cd "$dir/$name" && cargo run -q && cargo check -q)
done
a=()
b=()
for round in $(seq 1 "$rounds"); do
    ta=$(check reduced)
    tb=$(check unreduced)
    a+=("$ta")
    b+=("$tb")
    printf 'round %d: reduced %.2f s, unreduced %.2f s, ratio %.2f\n' "$round" "$ta" "$tb" "$(echo "$ta / $tb" | bc -l)"
done
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
printf 'medians: reduced %.2f s, unreduced %.2f s\n' "$(median "${a[@]}")" "$(median "${b[@]}")"
