#!/usr/bin/env bash
# dirac's Radau against SUNDIALS IDA with KLU and against diffsol with its sparse backend (faer)
# on the LC ladder (10⁴ cells by default, or DIRAC_LADDER_CELLS), at equal achieved error: the
# nodal flux error at t = 10 against the exact modal solution. IDA, KLU and their libraries come
# from Debian's packages, unpacked into target/peers without installing; the IDA driver
# (ida_ladder.c) integrates the same index-2 DAE as dirac. diffsol (benches/peers/diffsol,
# src/bin/ladder.rs) gets the reduced ODE in the node fluxes, 2N unknowns, which is what a
# diffsol user would write: its BDF cannot start an index-2 DAE. Every driver reads the
# consistent start and the reference that benches/ladder_peers.rs writes. The IDA driver builds
# its Jacobian's compressed-column pattern once and scatters the values into it afterwards.
# Every solver alternated round by round (PEER_ROUNDS, default 3). Not part of CI.
set -euo pipefail
cd "$(dirname "$0")/../.."
peers=$PWD/target/peers
cells=${DIRAC_LADDER_CELLS:-10000}
mkdir -p "$peers/debs" "$peers/ladder"
if [ ! -d "$peers/sundials_klu" ]; then
    (cd "$peers/debs" && apt-get download libsundials-dev libsundials-ida6 libsundials-nvecserial6 \
        libsundials-sunlinsol3 libsundials-sunmatrix4 libklu1 libamd2 libbtf1 libcolamd2 \
        libsuitesparseconfig5 libsuitesparse-dev)
    for deb in "$peers"/debs/*.deb; do dpkg -x "$deb" "$peers/sundials_klu"; done
fi
root="$peers/sundials_klu"
lib="$root/usr/lib/x86_64-linux-gnu"
gcc -O3 -o "$peers/ida_ladder" benches/peers/ida_ladder.c -I"$root/usr/include" \
    -I"$root/usr/include/suitesparse" -L"$lib" -Wl,-rpath,"$lib" -lsundials_ida \
    -lsundials_nvecserial -lsundials_sunlinsolklu -lsundials_sunmatrixsparse -lklu -lm
DIRAC_LADDER_CELLS=$cells cargo bench -p dirac-benches --bench ladder_peers -- setup "$peers/ladder"
cargo build --release --manifest-path benches/peers/diffsol/Cargo.toml --target-dir "$peers/diffsol" --bin ladder
DIRAC_LADDER_CELLS=$cells cargo bench -p dirac-benches --bench ladder_peers --no-run
# Every round runs each solver once, one after the other; each round's ratio is formed from
# that round's curves (compare.py), so the load of the minutes a round ran in enters both
# sides of its ratio.
rounds=${PEER_ROUNDS:-3}
rm -f "$peers"/ladder/*.[0-9]*.csv
for round in $(seq "$rounds"); do
    DIRAC_LADDER_CELLS=$cells cargo bench -q -p dirac-benches --bench ladder_peers > "$peers/ladder/radau.$round.csv"
    LD_LIBRARY_PATH="$lib" "$peers/ida_ladder" "$cells" "$peers/ladder" > "$peers/ladder/ida.$round.csv"
    for method in bdf esdirk34 tsit45; do
        "$peers/diffsol/release/ladder" "$method" "$peers/ladder" > "$peers/ladder/diffsol_$method.$round.csv"
    done
done
for name in radau ida diffsol_bdf diffsol_esdirk34 diffsol_tsit45; do
    echo "$name:"; python3 benches/peers/median.py "$peers"/ladder/"$name".*.csv
done
python3 benches/peers/compare.py "$peers/ladder/radau.*.csv" "SUNDIALS IDA + KLU=$peers/ladder/ida.*.csv" \
    "diffsol BDF + sparse LU (ODE)=$peers/ladder/diffsol_bdf.*.csv" \
    "diffsol ESDIRK34 + sparse LU (ODE)=$peers/ladder/diffsol_esdirk34.*.csv" \
    "diffsol Tsit45 (ODE)=$peers/ladder/diffsol_tsit45.*.csv"
