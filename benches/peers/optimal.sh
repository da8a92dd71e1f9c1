#!/usr/bin/env bash
# Optimal control, dirac against CasADi + IPOPT on the same problem and the same IPOPT: the
# cart-pole swing-up (2 s, from hanging to upright at rest, |x| <= 1.5 m, |f| <= 20 N, cost
# the integral of f^2/2) transcribed by DMOC on N intervals, dirac's from the model's generated
# blocks (benches/optimal.rs), CasADi's from SX expressions of the same equations
# (benches/peers/optimal.py). dirac loads the IPOPT that CasADi's wheel carries (DIRAC_IPOPT),
# so both run IPOPT 3.14 with MUMPS and the same options. dirac's rows come twice: solved by
# that IPOPT (`dirac`) and by dirac's own interior point on its banded KKT (`interior`).
# Rounds alternate dirac and CasADi;
# every row is printed, then the medians and the median of the rounds' ratios with their
# range. Not part of CI.
#
# A second problem, the 8-link chain with a torque at each joint raised from hanging to every
# link at 0.5 rad (benches/optimal.rs says which), shows how the two scale with the model.
#
#   bash benches/peers/optimal.sh [rounds] [N ...]      (PROBLEM=chain8 for the chain)
#   TRANSCRIPTION=collocation bash benches/peers/optimal.sh 5   (Radau IIA collocation on both sides)
#   PROBLEM=mpc bash benches/peers/optimal.sh 5 20      (the 100 Hz MPC on the cart-pole)
#
# PROBLEM=acrobot is the acrobot's swing-up; PROBLEM=panda the Panda's arm from its URDF file
# moved between two poses at rest in 2 s within its joint limits and efforts, with the joint
# velocities weighted in the cost (CasADi's side writes its Lagrangian from the numbers
# Pinocchio reads from the same file, checked against Pinocchio's energies). Without that
# weight the Panda's program has many local optima, and the two sides, from the same start
# with the same options, end in different ones.
set -euo pipefail
cd "$(dirname "$0")/../.."
rounds=${1:-7}
shift || true
sizes=${*:-50 100}
problem=${PROBLEM:-cartpole}
out=target/peers/optimal
venv=target/peers/optimal-venv
mkdir -p "$out"
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet casadi
casadi=$("$venv/bin/python" -c 'import casadi, os; print(os.path.dirname(casadi.__file__))')
cargo bench -p dirac-benches --bench optimal --no-run 2> "$out/build.log"
if [ "$problem" = mpc ]; then
    # The receding horizon: no CasADi side; each round runs the closed loop on dirac's interior
    # point and then IPOPT on the same samples in the same process (benches/optimal.rs, `mpc`).
    for round in $(seq "$rounds"); do
        DIRAC_IPOPT="$casadi/libipopt.so.3" cargo bench -q -p dirac-benches --bench optimal -- mpc $sizes 2>> "$out/build.log" \
            | sed "s/^/$round,/"
    done
    exit 0
fi
transcription=${TRANSCRIPTION:-dmoc}
export TRANSCRIPTION=$transcription
rows=$out/rows-$problem-$transcription.csv
: > "$rows"
for round in $(seq "$rounds"); do
    DIRAC_IPOPT="$casadi/libipopt.so.3" cargo bench -q -p dirac-benches --bench optimal -- "$problem" $sizes 2>> "$out/build.log" \
        | sed "s/^/$round,/" >> "$rows"
    "$venv/bin/python" benches/peers/optimal.py "$problem" $sizes | sed "s/^/$round,/" >> "$rows"
done
"$venv/bin/python" - "$rows" <<'PY'
import os, statistics, sys
rows = [l.strip().split(",") for l in open(sys.argv[1])]
print("round  tool    N   cost                 iter  solve ms  eval ms  eval %  setup ms")
for r, tool, name, n, cost, it, solve, ev, setup in rows:
    print(f"{r:>5}  {tool:6} {n:>4}  {float(cost):.12e}  {it:>4}  {1e3*float(solve):8.2f}  {1e3*float(ev):7.2f}"
          f"  {100*float(ev)/float(solve):5.1f}  {1e3*float(setup):8.2f}")
print()
print(f"Each dirac solver against CasADi + IPOPT, both on {os.environ['TRANSCRIPTION']} (medians over the rounds; ratio = median of the rounds' ratios, range)")
print("N    solver    cost                 rel. diff  iter s/C  solve ms s/C           ratio (range)       eval % s/C")
for n in sorted({r[3] for r in rows}, key=int):
    pick = lambda tool, i: [float(r[i]) for r in rows if r[1] == tool and r[3] == n]
    cc, sc = pick("casadi", 4)[0], pick("casadi", 6)
    ec = statistics.median([e / s for e, s in zip(pick("casadi", 7), sc)])
    for tool in ("dirac", "interior"):
        if not pick(tool, 4):
            continue
        cd, sd = pick(tool, 4)[0], pick(tool, 6)
        ratios = sorted(d / c for d, c in zip(sd, sc))
        ed = statistics.median([e / s for e, s in zip(pick(tool, 7), sd)])
        label = "IPOPT" if tool == "dirac" else "interior"
        print(f"{n:4} {label:9} {cd:.12e}  {abs(cd - cc) / abs(cc):.1e}  {int(pick(tool, 5)[0]):>3}/{int(pick('casadi', 5)[0]):<3}"
              f"  {1e3*statistics.median(sd):7.2f} / {1e3*statistics.median(sc):7.2f}    "
              f"{statistics.median(ratios):5.2f} ({ratios[0]:.2f}-{ratios[-1]:.2f})   {100*ed:4.1f} / {100*ec:4.1f}")
PY
