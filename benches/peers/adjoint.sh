#!/usr/bin/env bash
# dirac's adjoint gradients beside SUNDIALS IDAS's adjoint on the LC ladder of
# `cargo bench -p dirac-benches --bench adjoint` (each cell's l_j = 1 + 0.3 sin j and c_j = 1, a
# flux pulse at rest, 5 s): the gradient of ∫ ½ |q|² dt with respect to all 2N parameters, for
# 5, 50, 500 and 5000 cells, at equal achieved error. The dirac side writes the starts and the
# reference gradients (dirac at tolerance 1e-12; IDAS's at 1e-11 is printed against it) and
# times its gradients over tolerances 1e-5 to 1e-10 (`… --bench adjoint -- peers [setup] DIR`);
# idas_adjoint.c, linked against Debian's SUNDIALS and KLU unpacked into target/peers without
# installing, times IDAS's over 1e-5 to 1e-11. Prints both curves and the time ratios at dirac's
# achieved errors, every side alternated round by round (PEER_ROUNDS, default 3). Not part of CI.
set -euo pipefail
cd "$(dirname "$0")/../.."
peers=$PWD/target/peers
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
    -I"$root/usr/include/suitesparse" -L"$lib" -Wl,-rpath,"$lib" -lsundials_idas \
    -lsundials_nvecserial -lsundials_sunlinsolklu -lsundials_sunmatrixsparse -lklu -lm
cargo bench -q -p dirac-benches --bench adjoint -- peers setup "$peers/adjoint"
# Every round runs dirac's sweep, then IDAS's over all sizes and tolerances; each round's ratio
# is formed from that round's two curves (compare.py), so the load of the minutes a round ran
# in enters both sides of its ratio.
rounds=${PEER_ROUNDS:-3}
rm -f "$peers"/adjoint/dirac.*.csv "$peers"/adjoint/idas.*.csv "$peers"/adjoint/idas.*.log
for round in $(seq "$rounds"); do
    cargo bench -q -p dirac-benches --bench adjoint -- peers "$peers/adjoint" > "$peers/adjoint/dirac.$round.csv"
    echo "problem,tol,error,seconds,steps" > "$peers/adjoint/idas.$round.csv"
    for cells in 5 50 500 5000; do
        for tol in 1e-5 1e-6 1e-7 1e-8 1e-9 1e-10 1e-11; do
            LD_LIBRARY_PATH="$lib" "$peers/idas_adjoint" "$cells" "$peers/adjoint/$cells" "$tol" >> "$peers/adjoint/idas.$round.csv" \
                2>> "$peers/adjoint/idas.$round.log"
        done
    done
done
echo "dirac:"; python3 benches/peers/median.py "$peers"/adjoint/dirac.*.csv
echo "SUNDIALS IDAS:"; python3 benches/peers/median.py "$peers"/adjoint/idas.*.csv
grep 'tol 1e-11' "$peers/adjoint/idas.1.log"
python3 benches/peers/compare.py "dirac adjoint=$peers/adjoint/dirac.*.csv" \
    "SUNDIALS IDAS adjoint=$peers/adjoint/idas.*.csv"
