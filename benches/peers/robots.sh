#!/usr/bin/env bash
# dirac against Pinocchio and MuJoCo on the Franka Panda arm read from the same URDF file
# (tests/robots/panda/panda_arm.urdf), in one run on this machine:
#
# 1. one evaluation of what an implicit step needs (dirac's residual and Jacobian) against
#    Pinocchio's `computeABADerivatives`, which returns the accelerations with their analytic
#    derivatives, timed in C++ (pinocchio_panda.cpp, built against the `pin` wheel's library);
# 2. the 1 s free swing from rest under gravity at equal achieved error: dirac's Explicit and
#    Radau over a range of tolerances against MuJoCo's RK4, Euler (its default) and
#    implicitfast over a range of time steps, every error against Pinocchio's dynamics
#    integrated by SciPy's DOP853 at rtol = atol = 1e-12;
#
# every part alternated round by round (PEER_ROUNDS, default 5).
#
# Pinocchio, MuJoCo, SciPy and Eigen's headers are installed into a virtual environment
# under target/peers; nothing is installed system-wide. Not part of CI.
set -euo pipefail
cd "$(dirname "$0")/../.."
out=$PWD/target/peers/robots
venv=$PWD/target/peers/robots-venv
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
# Every round runs each side once, one after the other (Pinocchio, dirac, dirac's swing,
# MuJoCo's swing); a ratio is formed within a round, so the load of the minute it ran in enters
# both sides of it, and the table shows the median and the range of the rounds' ratios.
rounds=${PEER_ROUNDS:-5}
rm -f "$out"/pinocchio_*.csv "$out"/dirac_*.csv "$out"/mujoco_*.csv
for round in $(seq "$rounds"); do
    "$out/pinocchio_panda" "$out/panda_arm.bin" > "$out/pinocchio_$round.csv"
    cargo bench -q -p dirac-benches --bench robots -- evaluate > "$out/dirac_$round.csv"
    cargo bench -q -p dirac-benches --bench robots -- swing "$out" > "$out/dirac_swing_$round.csv"
    "$venv/bin/python" benches/peers/robots.py mujoco tests/robots/panda/panda_arm.urdf "$out" "$round" > /dev/null
done
"$venv/bin/python" benches/peers/robots.py compare tests/robots/panda/panda_arm.urdf "$out" "$rounds"
