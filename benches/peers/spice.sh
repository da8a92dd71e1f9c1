#!/usr/bin/env bash
# dirac-spice against ngspice on the same netlists: LC ladders of 10³ and 10⁴ nodes from a
# pulse (or the sizes in DIRAC_SPICE_SIZES, comma-separated, empty for none), each printed every
# 1 s and, as people write them, every 0.01 s with a largest step of 0.01 s, against their modal
# solution computed in benches/peers/spice_ladder.py; an RLC ladder, a 1 kHz diode clipper (with
# and without a 1 µs largest step) and a circuit of E, F and H controlled sources, against
# references computed there. Each simulator runs over a range of tolerances (ngspice trap and
# gear at reltol 1e-3 … 1e-6), the runs alternated, three rounds; the table gives, for every
# ngspice run, dirac's error at ngspice's wall time and dirac's time at ngspice's error. ngspice
# comes from Debian's package, unpacked into target/peers without installing; numpy and scipy
# into a virtual environment there. Not part of CI.
set -euo pipefail
cd "$(dirname "$0")/../.."
peers=target/peers
mkdir -p "$peers/debs" "$peers/spice"
if [ ! -x "$peers/ngspice/usr/bin/ngspice" ]; then
    (cd "$peers/debs" && apt-get download ngspice)
    dpkg -x "$peers"/debs/ngspice_*.deb "$peers/ngspice"
fi
venv=$peers/spice-venv
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet numpy scipy
cargo build --release --features spice --bin dirac-spice
"$venv/bin/python" benches/peers/spice_ladder.py compare "${DIRAC_SPICE_SIZES-1000,10000}" \
    "$peers/ngspice/usr/bin/ngspice" target/release/dirac-spice "$peers/spice"
