#!/usr/bin/env bash
# dirac's Radau against SUNDIALS IDA with KLU on the LC ladder (10⁴ cells by default, or
# DIRAC_LADDER_CELLS), at equal achieved error: the nodal flux error at t = 10 against the exact
# modal solution. IDA, KLU and their libraries come from Debian's packages, unpacked into
# target/peers without installing; the IDA driver (ida_ladder.c) reads the consistent start and
# the reference that benches/ladder_peers.rs writes. Not part of CI.
set -euo pipefail
cd "$(dirname "$0")/../.."
peers=target/peers
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
    -I"$root/usr/include/suitesparse" -L"$lib" -Wl,-rpath,"$PWD/$lib" -lsundials_ida \
    -lsundials_nvecserial -lsundials_sunlinsolklu -lsundials_sunmatrixsparse -lklu -lm
DIRAC_LADDER_CELLS=$cells cargo bench --bench ladder_peers -- setup "$peers/ladder"
DIRAC_LADDER_CELLS=$cells cargo bench --bench ladder_peers > "$peers/ladder/radau.csv"
LD_LIBRARY_PATH="$PWD/$lib" "$peers/ida_ladder" "$cells" "$peers/ladder" > "$peers/ladder/ida.csv"
echo "dirac Radau:"; cat "$peers/ladder/radau.csv"
echo "SUNDIALS IDA + KLU:"; cat "$peers/ladder/ida.csv"
python3 benches/peers/compare.py "$peers/ladder/radau.csv" "SUNDIALS IDA + KLU=$peers/ladder/ida.csv"
