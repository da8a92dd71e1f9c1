#!/usr/bin/env bash
# Runs dirac's Radau and Explicit integrators, SUNDIALS IDA and diffsol side by side on the
# pendulum, the paper's chain and (all but IDA) the 8-link pendulum, prints wall-time ratios at
# equal achieved error and draws the work-precision diagram. Not part of CI.
#
# IDA comes from Debian's packages, unpacked into target/peers without installing (its -dev
# package pulls in PETSc and MPI through dependencies the driver does not need), and is
# driven by ida_driver.c: same formulation, analytic Jacobian, same initial state. diffsol is
# the package in benches/peers/diffsol (outside the workspace, so CI never builds it), which
# gives diffsol the explicit-ODE form of each problem (see its src/main.rs).
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
cargo build --release --manifest-path benches/peers/diffsol/Cargo.toml --target-dir "$peers/diffsol"
# diffsol once more with one code unit, the setting its package carried before: timed in the
# same rounds, so that the table shows what the setting does for it.
CARGO_PROFILE_RELEASE_CODEGEN_UNITS=1 cargo build --release --manifest-path benches/peers/diffsol/Cargo.toml \
    --target-dir "$peers/diffsol-cgu1"
cargo bench -p dirac-benches --bench work_precision -- reference > "$peers/reference.txt"
# Every solver runs once per round, the rounds one after the other (A B C … A B C …), and each
# row's time is the median over the rounds: on a shared machine the load drifts over minutes,
# and solvers timed at different moments would carry that drift into their ratios.
rounds="${PEER_ROUNDS:-5}"
# A fresh directory: a longer earlier run's extra rounds must not enter this run's medians.
rm -rf "$peers/rounds"
mkdir -p "$peers/rounds"
for round in $(seq "$rounds"); do
    # shellcheck disable=SC2046
    "$peers/ida_driver" $(cut -d' ' -f1-3 "$peers/reference.txt") > "$peers/rounds/ida.$round.csv"
    for method in bdf esdirk34 tsit45; do
        # shellcheck disable=SC2046
        "$peers/diffsol/release/dirac-peer-diffsol" "$method" $(cat "$peers/reference.txt") \
            > "$peers/rounds/diffsol_$method.$round.csv"
    done
    for method in bdf tsit45; do
        # shellcheck disable=SC2046
        "$peers/diffsol-cgu1/release/dirac-peer-diffsol" "$method" $(cat "$peers/reference.txt") \
            > "$peers/rounds/diffsol1_$method.$round.csv" 2>/dev/null
    done
    cargo bench -q -p dirac-benches --bench work_precision -- radau > "$peers/rounds/radau.$round.csv" 2>/dev/null
    cargo bench -q -p dirac-benches --bench work_precision -- explicit > "$peers/rounds/explicit.$round.csv" 2>/dev/null
done
for name in ida diffsol_bdf diffsol_esdirk34 diffsol_tsit45 radau explicit; do
    python3 benches/peers/median.py "$peers"/rounds/"$name".*.csv > "$peers/$name.csv"
    python3 benches/peers/median.py --min "$peers"/rounds/"$name".*.csv > "$peers/$name.min.csv"
done
echo "dirac Radau:"; cat "$peers/radau.csv"
echo "dirac Explicit:"; cat "$peers/explicit.csv"
echo "SUNDIALS IDA:"; cat "$peers/ida.csv"
for method in bdf esdirk34 tsit45; do echo "diffsol $method:"; cat "$peers/diffsol_$method.csv"; done
# Each round's ratio from that round's curves; the median and the range over the rounds.
r="$peers/rounds"
python3 benches/peers/compare.py "dirac Radau=$r/radau.*.csv" "SUNDIALS IDA=$r/ida.*.csv" \
    "diffsol BDF=$r/diffsol_bdf.*.csv" "diffsol ESDIRK34=$r/diffsol_esdirk34.*.csv" \
    "diffsol Tsit45 (ODE)=$r/diffsol_tsit45.*.csv" "dirac Explicit=$r/explicit.*.csv" \
    --svg "$peers/work_precision.svg"
python3 benches/peers/compare.py "dirac Explicit=$r/explicit.*.csv" \
    "diffsol Tsit45 (ODE)=$r/diffsol_tsit45.*.csv" "diffsol BDF=$r/diffsol_bdf.*.csv" \
    "diffsol Tsit45 (ODE), one code unit=$r/diffsol1_tsit45.*.csv"
python3 benches/peers/compare.py "dirac Radau=$r/radau.*.csv" "diffsol BDF, one code unit=$r/diffsol1_bdf.*.csv"
# The same comparisons over each solver's fastest round: load from other work on a shared
# machine only adds time, and it comes and goes over seconds, so medians over a few rounds can
# still carry it into one solver's time and not the other's.
echo "=== fastest rounds ==="
python3 benches/peers/compare.py "dirac Radau=$peers/radau.min.csv" "diffsol BDF=$peers/diffsol_bdf.min.csv"
python3 benches/peers/compare.py "dirac Explicit=$peers/explicit.min.csv" \
    "diffsol Tsit45 (ODE)=$peers/diffsol_tsit45.min.csv"
