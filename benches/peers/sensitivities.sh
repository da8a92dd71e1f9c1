#!/usr/bin/env bash
# dirac's forward sensitivities beside SUNDIALS IDAS's on the paper's chain (six parameters,
# 20 s, tolerance 1e-8, output every 0.1 s), in one run: `cargo bench -p dirac-benches --bench sensitivities`
# (every model; its paper-chain row and the final sensitivities are the ones to compare) and
# idas_sens.c, linked statically against the SUNDIALS of Debian's libsundials-dev, unpacked into
# target/peers without installing. Not part of CI.
set -euo pipefail
cd "$(dirname "$0")/../.."
peers=target/peers
mkdir -p "$peers/debs"
root="$peers/sundials_dev"
if [ ! -d "$root" ]; then
    (cd "$peers/debs" && apt-get download libsundials-dev)
    dpkg -x "$peers"/debs/libsundials-dev_*.deb "$root"
fi
lib="$root/usr/lib/x86_64-linux-gnu"
gcc -O3 -o "$peers/idas_sens" benches/peers/idas_sens.c -I"$root/usr/include" "$lib/libsundials_idas.a" \
    "$lib/libsundials_nvecserial.a" "$lib/libsundials_sunlinsoldense.a" "$lib/libsundials_sunmatrixdense.a" -lm
cargo bench -p dirac-benches --bench sensitivities
echo
"$peers/idas_sens"
