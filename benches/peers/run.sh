#!/usr/bin/env bash
# Runs dirac's Radau and SUNDIALS IDA side by side on the pendulum and the paper's chain and
# prints wall-time ratios at equal achieved error. Not part of CI.
#
# IDA comes from Debian's packages, unpacked into target/peers without installing (its -dev
# package pulls in PETSc and MPI through dependencies the driver does not need), and is
# driven by ida_driver.c: same formulation, analytic Jacobian, same initial state.
set -euo pipefail
cd "$(dirname "$0")/../.."
peers=target/peers
mkdir -p "$peers/debs"
if [ ! -d "$peers/sundials" ]; then
    (cd "$peers/debs" && apt-get download libsundials-dev libsundials-ida6 libsundials-nvecserial6 \
        libsundials-sunlinsol3 libsundials-sunmatrix4)
    for deb in "$peers"/debs/*.deb; do dpkg -x "$deb" "$peers/sundials"; done
fi
lib="$peers/sundials/usr/lib/x86_64-linux-gnu"
gcc -O3 -o "$peers/ida_driver" benches/peers/ida_driver.c -I"$peers/sundials/usr/include" -L"$lib" \
    -Wl,-rpath,"$PWD/$lib" -lsundials_ida -lsundials_nvecserial -lsundials_sunlinsoldense \
    -lsundials_sunmatrixdense -lm
cargo bench --bench work_precision -- reference > "$peers/reference.txt"
# shellcheck disable=SC2046
"$peers/ida_driver" $(cat "$peers/reference.txt") > "$peers/ida.csv"
cargo bench --bench work_precision > "$peers/radau.csv"
echo "dirac Radau:"; cat "$peers/radau.csv"
echo "SUNDIALS IDA:"; cat "$peers/ida.csv"
python3 benches/peers/compare.py "$peers/radau.csv" "$peers/ida.csv" "$peers/work_precision.svg"
