#!/usr/bin/env bash
# dirac's adjoint gradients beside SUNDIALS IDAS's adjoint on the LC ladder of
# `cargo bench -p dirac-benches --bench adjoint` (each cell's l_j = 1 + 0.3 sin j and c_j = 1, a flux pulse at
# rest, 5 s, tolerance 1e-8): the gradient of ∫ ½ |q|² dt with respect to all 2N parameters,
# for 5, 50, 500 and 5000 cells. The dirac side writes the start and its own gradient and times
# its gradients (`cargo bench -p dirac-benches --bench adjoint -- peers DIR`); idas_adjoint.c, linked against
# Debian's SUNDIALS and KLU unpacked into target/peers without installing, times IDAS's and
# compares the two gradients. Prints both CSVs and their time ratios. Not part of CI.
set -euo pipefail
cd "$(dirname "$0")/../.."
peers=target/peers
mkdir -p "$peers/debs" "$peers/adjoint"
root="$peers/sundials_idas"
if [ ! -d "$root" ]; then
    (cd "$peers/debs" && apt-get download libsundials-dev libsundials-idas5 libsundials-nvecserial6 \
        libsundials-sunlinsol3 libsundials-sunmatrix4 libklu1 libamd2 libbtf1 libcolamd2 \
        libsuitesparseconfig5 libsuitesparse-dev)
    for deb in "$peers"/debs/*.deb; do dpkg -x "$deb" "$root"; done
fi
lib="$root/usr/lib/x86_64-linux-gnu"
gcc -O3 -o "$peers/idas_adjoint" benches/peers/idas_adjoint.c -I"$root/usr/include" \
    -I"$root/usr/include/suitesparse" -L"$lib" -Wl,-rpath,"$PWD/$lib" -lsundials_idas \
    -lsundials_nvecserial -lsundials_sunlinsolklu -lsundials_sunmatrixsparse -lklu -lm
cargo bench -p dirac-benches --bench adjoint -- peers "$peers/adjoint" | tee "$peers/adjoint/dirac.csv"
echo "cells,n_theta,seconds,steps_forward,steps_backward,G,difference" | tee "$peers/adjoint/idas.csv"
for cells in 5 50 500 5000; do
    LD_LIBRARY_PATH="$PWD/$lib" "$peers/idas_adjoint" "$cells" "$peers/adjoint/$cells" | tee -a "$peers/adjoint/idas.csv"
done
python3 - "$peers/adjoint" <<'PY'
import csv, sys
d = {r["cells"]: r for r in csv.DictReader(open(f"{sys.argv[1]}/dirac.csv"))}
print("| cells | N_θ | dirac | IDAS adjoint | dirac / IDAS | IDAS steps (forward, backward) | dirac steps | gradients' difference |")
print("|---|---|---|---|---|---|---|---|")
for r in csv.DictReader(open(f"{sys.argv[1]}/idas.csv")):
    a, b = float(d[r["cells"]]["seconds"]), float(r["seconds"])
    print(f"| {r['cells']} | {r['n_theta']} | {a*1e3:.2f} ms | {b*1e3:.2f} ms | {a/b:.3f} | {r['steps_forward']}, {r['steps_backward']} | {d[r['cells']]['steps']} | {float(r['difference']):.1e} |")
PY
