#!/usr/bin/env bash
# Coulomb friction on a contact force, dirac against MuJoCo in one run: the cases of
# examples/contact_friction.rs (a block stopping on the flat, held on a slope, sliding down
# one; a ball rolling down one), each against its closed form, MuJoCo's run of the same case
# beside it (benches/peers/friction.py). MuJoCo is installed into a virtual environment under
# target/peers; nothing is installed system-wide. Not part of CI.
#
#   bash benches/peers/friction.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
out=$PWD/target/peers/friction
venv=$PWD/target/peers/robots-venv
mkdir -p "$out"
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet mujoco
cargo run --release --example contact_friction > "$out/dirac.csv"
"$venv/bin/python" benches/peers/friction.py "$out/dirac.csv"
