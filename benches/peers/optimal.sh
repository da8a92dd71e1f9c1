#!/usr/bin/env bash
# Optimal control, dirac against CasADi + IPOPT on the same problem and the same IPOPT: the
# cart-pole swing-up (2 s, from hanging to upright at rest, |x| <= 1.5 m, |f| <= 20 N, cost
# the integral of f^2/2) transcribed by DMOC on N intervals, dirac's from the model's generated
# blocks (benches/optimal.rs), CasADi's from SX expressions of the same equations
# (benches/peers/optimal.py). dirac loads the IPOPT that CasADi's wheel carries (DIRAC_IPOPT),
# so both run IPOPT 3.14 with MUMPS and the same options. Rounds alternate dirac and CasADi;
# every row is printed, then the medians and their ratio. Not part of CI.
#
#   bash benches/peers/optimal.sh [rounds] [N ...]
set -euo pipefail
cd "$(dirname "$0")/../.."
rounds=${1:-7}
shift || true
sizes=${*:-50 100}
out=target/peers/optimal
venv=target/peers/optimal-venv
mkdir -p "$out"
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet casadi
casadi=$("$venv/bin/python" -c 'import casadi, os; print(os.path.dirname(casadi.__file__))')
cargo bench -p dirac-benches --bench optimal --no-run 2> "$out/build.log"
: > "$out/rows.csv"
for round in $(seq "$rounds"); do
    DIRAC_IPOPT="$casadi/libipopt.so.3" cargo bench -q -p dirac-benches --bench optimal -- $sizes 2>> "$out/build.log" \
        | sed "s/^/$round,/" >> "$out/rows.csv"
    "$venv/bin/python" benches/peers/optimal.py $sizes | sed "s/^/$round,/" >> "$out/rows.csv"
done
"$venv/bin/python" - "$out/rows.csv" <<'PY'
import statistics, sys
rows = [l.strip().split(",") for l in open(sys.argv[1])]
print("round  tool    N   cost                 iter  solve ms  eval ms  eval %  setup ms")
for r, tool, n, cost, it, solve, ev, setup in rows:
    print(f"{r:>5}  {tool:6} {n:>4}  {float(cost):.12e}  {it:>4}  {1e3*float(solve):8.2f}  {1e3*float(ev):7.2f}"
          f"  {100*float(ev)/float(solve):5.1f}  {1e3*float(setup):8.2f}")
print()
print("N    cost dirac          cost CasADi         rel. diff  iter d/C  solve ms d/C (median)  ratio  eval % d/C")
for n in sorted({r[2] for r in rows}, key=int):
    pick = lambda tool, i: [float(r[i]) for r in rows if r[1] == tool and r[2] == n]
    cd, cc = pick("dirac", 3)[0], pick("casadi", 3)[0]
    sd, sc = statistics.median(pick("dirac", 5)), statistics.median(pick("casadi", 5))
    ed = statistics.median([e / s for e, s in zip(pick("dirac", 6), pick("dirac", 5))])
    ec = statistics.median([e / s for e, s in zip(pick("casadi", 6), pick("casadi", 5))])
    print(f"{n:4} {cd:.12e}  {cc:.12e}  {abs(cd - cc) / abs(cc):.1e}  {int(pick('dirac', 4)[0])}/{int(pick('casadi', 4)[0])}"
          f"     {1e3*sd:7.2f} / {1e3*sc:7.2f}        {sd / sc:5.2f}  {100*ed:4.1f} / {100*ec:4.1f}")
PY
