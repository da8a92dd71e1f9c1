#!/usr/bin/env bash
# Regenerates tests/references/spice_op.csv and spice_ac.csv, ngspice's operating points and
# small-signal sweeps of the netlists of tests/integration/spice.rs. ngspice comes from Debian's
# package, unpacked into target/peers without installing. Not part of CI: the CSV files are
# committed.
set -euo pipefail
cd "$(dirname "$0")/../.."
peers=target/peers
mkdir -p "$peers/debs"
if [ ! -x "$peers/ngspice/usr/bin/ngspice" ]; then
    (cd "$peers/debs" && apt-get download ngspice)
    dpkg -x "$peers"/debs/ngspice_*.deb "$peers/ngspice"
fi
for what in op ac; do
    python3 "tests/references/spice_$what.py" "$peers/ngspice/usr/bin/ngspice" . "tests/references/spice_$what.csv"
done
