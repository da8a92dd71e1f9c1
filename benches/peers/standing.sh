#!/usr/bin/env bash
# A quadruped standing on the ground, dirac against MuJoCo in one run: the Unitree A1 from the
# example-robot-data package (its URDF, its base floating, its four feet's spheres touching the
# ground under Coulomb's cone, mu = 0.8) held in the SRDF's standing posture by a joint PD
# controller sampled at 1 kHz for 5 s, and falling for 1 s with the controller off onto its
# joints' stops and its trunk, with the feet's friction and without
# (benches/peers/standing.rs, benches/peers/standing.py), and the standing robot's 3D page
# checked in headless Chromium (tests/browser/chromium.sh). MuJoCo and the robot's data are
# installed into a virtual environment under target/peers; dirac's side is built in a crate of
# its own under target/peers/standing (the 12-joint robot takes a minute to compile). Not part
# of CI.
#
#   bash benches/peers/standing.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
out=$root/target/peers/standing
venv=$root/target/peers/robots-venv
mkdir -p "$out/src"
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet mujoco
"$venv/bin/pip" install --quiet --no-deps example-robot-data
"$venv/bin/pip" install --quiet pillow
site=$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
urdf="$site/cmeel.prefix/share/example-robot-data/robots/a1_description/urdf/a1.urdf"
cat > "$out/Cargo.toml" <<TOML
[package]
name = "standing"
version = "0.0.0"
edition = "2024"
publish = false

[dependencies]
dirac = { path = "$root" }

[profile.release]
debug = false

[workspace]
TOML
sed "s|@URDF@|$urdf|" benches/peers/standing.rs > "$out/src/main.rs"
(cd "$out" && CARGO_TARGET_DIR="$out/target" cargo run --quiet --release > "$out/dirac.csv")
chromium=$(bash tests/browser/chromium.sh)
"$venv/bin/python" benches/peers/standing.py "$urdf" "$out/dirac.csv" "$out/standing.html" "$chromium"
