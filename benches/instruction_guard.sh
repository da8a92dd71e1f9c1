#!/usr/bin/env bash
# A guard on the instructions of whole small-model runs (benches/small_models.rs under
# callgrind): each case of benches/instruction_counts.txt is counted again on this tree and
# compared with the count recorded there; a case more than GUARD_PERCENT (default 2) percent
# above its record fails the guard, and the script exits 1. Exact counts, so a regression
# shows however loaded the machine is (0345906 to 04f348a: Explicit on the 8-link pendulum went
# from 95.7 M to 126.8 M instructions, L_vv evaluated out of line, and no timing noticed it
# among the rounds' spread). Needs valgrind. Not part of CI (it builds the benchmarks in release).
#
# Usage: bash benches/instruction_guard.sh          compare with the records
#        bash benches/instruction_guard.sh --bless  record this tree's counts
#
# The counts depend on the compiler and the libm of the machine: bless again after changing
# either, on a tree whose counts are known good.
set -euo pipefail
cd "$(dirname "$0")/.."
records=benches/instruction_counts.txt
limit=${GUARD_PERCENT:-2}
command -v valgrind >/dev/null || { echo "instruction_guard.sh needs valgrind (apt-get install valgrind)" >&2; exit 2; }
cargo build --release -p dirac-benches --bench small_models 2>&1 | grep -E '^error' >&2 || true
driver=$(find target/release/deps -maxdepth 1 -type f -executable -name 'small_models-*' -printf '%T@ %p\n' |
    sort -n | tail -1 | cut -d' ' -f2)
count() { # $1 = case, $2 = repeats
    "$driver" "$1" 1 >/dev/null 2>&1 ||
        { echo "case '$1' of $records does not run: not a case of benches/small_models.rs" >&2; exit 2; }
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$driver" "$1" "$2" 2>&1 |
        sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
if [ "${1:-}" = "--bless" ]; then
    tmp=$(mktemp)
    grep '^#' "$records" > "$tmp"
    grep -v '^#' "$records" | while read -r case repeats _; do
        echo "$case $repeats $(count "$case" "$repeats")" >> "$tmp"
    done
    mv "$tmp" "$records"
    cat "$records"
    exit 0
fi
failed=0
printf '%-30s %14s %14s %8s\n' case recorded "this tree" change
while read -r case repeats recorded; do
    now=$(count "$case" "$repeats")
    change=$(awk "BEGIN { printf \"%+.1f\", 100 * ($now / $recorded - 1) }")
    verdict=$(awk "BEGIN { print ($now > $recorded * (1 + $limit / 100)) ? \"over\" : \"ok\" }")
    printf '%-30s %14s %14s %7s%% %s\n' "$case" "$recorded" "$now" "$change" "$verdict"
    [ "$verdict" = ok ] || failed=1
done < <(grep -v '^#' "$records")
exit "$failed"
