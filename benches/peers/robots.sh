#!/usr/bin/env bash
# dirac against Pinocchio and MuJoCo on the Franka Panda arm read from the same URDF file
# (tests/robots/panda/panda_arm.urdf), in one run on this machine:
#
# 1. one evaluation of what an implicit step needs (dirac's residual and Jacobian) against
#    Pinocchio's forward dynamics (ABA) plus its analytic derivatives, timed in C++
#    (pinocchio_panda.cpp, built against the `pin` wheel's library), the two alternated;
# 2. the 1 s free swing from rest under gravity at equal achieved error: dirac's Explicit and
#    Radau over a range of tolerances against MuJoCo's RK4, Euler (its default) and
#    implicitfast over a range of time steps, every error against Pinocchio's dynamics
#    integrated by SciPy's DOP853 at rtol = atol = 1e-12.
#
# Pinocchio, MuJoCo, SciPy and Eigen's headers are installed into a virtual environment
# under target/peers; nothing is installed system-wide. Not part of CI.
set -euo pipefail
cd "$(dirname "$0")/../.."
out=target/peers/robots
venv=target/peers/robots-venv
mkdir -p "$out"
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet pin mujoco scipy cmeel-eigen
site=$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
prefix="$site/cmeel.prefix"
"$venv/bin/python" benches/peers/robots.py setup tests/robots/panda/panda_arm.urdf "$out"
if [ ! -x "$out/pinocchio_panda" ]; then
    g++ -O3 -DNDEBUG -std=c++17 -DBOOST_MPL_LIMIT_LIST_SIZE=30 -DBOOST_MPL_LIMIT_VECTOR_SIZE=30 \
        -DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS -DBOOST_FUSION_INVOKE_MAX_ARITY=12 \
        -DPINOCCHIO_ENABLE_TEMPLATE_INSTANTIATION -o "$out/pinocchio_panda" benches/peers/pinocchio_panda.cpp \
        -I"$prefix/include" -I"$prefix/include/eigen3" -L"$prefix/lib" -Wl,-rpath,"$prefix/lib" \
        -lpinocchio_default -lboost_serialization
fi
cargo bench -p dirac-benches --bench robots --no-run
for round in 1 2 3; do
    "$out/pinocchio_panda" "$out/panda_arm.bin" > "$out/pinocchio_$round.csv"
    cargo bench -p dirac-benches --bench robots -- evaluate > "$out/dirac_$round.csv"
done
cargo bench -p dirac-benches --bench robots -- swing "$out" > "$out/dirac_swing.csv"
"$venv/bin/python" benches/peers/robots.py mujoco tests/robots/panda/panda_arm.urdf "$out"
"$venv/bin/python" benches/peers/robots.py compare tests/robots/panda/panda_arm.urdf "$out"
