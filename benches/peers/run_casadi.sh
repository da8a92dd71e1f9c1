#!/usr/bin/env bash
# Generated residual+Jacobian kernels: dirac's against CasADi's generated C (gcc -O3, its own
# translation unit, called through a function pointer) on the models of benches/kernels.rs.
# Installs CasADi from PyPI. Not part of CI.
set -euo pipefail
cd "$(dirname "$0")/../.."
dir=target/peers/casadi
mkdir -p "$dir"
python3 -m pip install --quiet casadi
python3 benches/peers/casadi_kernels.py "$dir" > "$dir/models.txt"
: > "$dir/casadi.csv"
while read -r name ny nnz; do
    cat > "$dir/main_$name.c" <<C
#include <stdio.h>
typedef long long casadi_int;
int fj_$name(const double **, double **, casadi_int *, double *, int);
int fj_${name}_work(casadi_int *, casadi_int *, casadi_int *, casadi_int *);
double time_kernel(void *, void *, int, int);
int main(void) { printf("$name,%.3f\n", time_kernel((void *)fj_$name, (void *)fj_${name}_work, $ny, $nnz)); return 0; }
C
    gcc -O3 -c "$dir/$name.c" -o "$dir/$name.o"
    gcc -O3 -c benches/peers/casadi_driver.c -o "$dir/driver.o"
    gcc -O3 "$dir/main_$name.c" "$dir/driver.o" "$dir/$name.o" -o "$dir/bench_$name" -lm
    "$dir/bench_$name" >> "$dir/casadi.csv"
done < "$dir/models.txt"
cargo bench -p dirac-benches --bench kernels -- "generated F\+J" 2>&1 | grep -E "^kernels/|time:" > "$dir/dirac.txt"
python3 - "$dir" <<'PY'
import re, sys
d = sys.argv[1]
casadi = dict(l.strip().split(",") for l in open(f"{d}/casadi.csv"))
text = open(f"{d}/dirac.txt").read()
keys = {"paper chain": "chain", "8-link": "pendulum8", "N=2 ": "cartesian2", "N=4 ": "cartesian4",
        "N=8 ": "cartesian8", "N=16 ": "cartesian16"}
units = {"ns": 1.0, "µs": 1e3, "ms": 1e6}
print(f"{'model':14} {'dirac ns':>10} {'CSC ns':>10} {'CasADi ns':>10} {'ratio':>7} {'CSC ratio':>10}")
def times(variant):
    out = {}
    for label, value, unit in re.findall(
            r"kernels/([^\n]*?)/generated F\+J" + re.escape(variant) + r"\s*\n?\s*time:\s*\[\S+ \S+ (\S+) (\S+)", text):
        out[next(v for k, v in keys.items() if k in label + " ")] = float(value) * units[unit]
    return out
dense, csc = times(""), times(" (CSC)")
for name, ours in dense.items():
    theirs = float(casadi[name])
    packed = csc.get(name, float("nan"))
    print(f"{name:14} {ours:10.2f} {packed:10.2f} {theirs:10.2f} {ours / theirs:7.2f} {packed / theirs:10.2f}")
PY
