#!/usr/bin/env bash
# Instructions of whole small-model runs (benches/small_models.rs) under callgrind, this tree
# against an older commit: exact counts, so the comparison does not depend on the machine's
# load. Needs valgrind (apt-get install valgrind). Not part of CI.
#
# Usage: [CASES="case:repeats …"] bash benches/small_models.sh [BASE]
# (BASE defaults to 0061595, before the large-model work; CASES to every case, each
# `case:repeats`). BASE is checked out in a temporary worktree and built with this tree's driver; for
# commits before DenseModel existed the driver's bound is rewritten to LagrangeDirac.
set -euo pipefail
cd "$(dirname "$0")/.."
base=${1:-0061595}
work=$(mktemp -d)
trap 'git worktree remove --force "$work/tree" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT

build() { # $1 = tree, $2 = target dir; prints the driver's path
    # The benchmarks moved into their own package (benches/Cargo.toml) after 0345906.
    local package=()
    [ -f "$1/benches/Cargo.toml" ] && package=(-p dirac-benches)
    (cd "$1" && CARGO_TARGET_DIR="$2" cargo build --release "${package[@]}" --bench small_models 2>&1 >/dev/null |
        grep -E '^error' >&2 || true)
    find "$2/release/deps" -maxdepth 1 -type f -executable -name 'small_models-*' -printf '%T@ %p\n' |
        sort -n | tail -1 | cut -d' ' -f2
}
count() { # $1 = driver, $2 = case, $3 = repeats
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$1" "$2" "$3" 2>&1 |
        sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}

git worktree add --detach "$work/tree" "$base" >/dev/null 2>&1
cp benches/small_models.rs "$work/tree/benches/"
grep -q 'name = "small_models"' "$work/tree/Cargo.toml" ||
    printf '\n[[bench]]\nname = "small_models"\nharness = false\n' >>"$work/tree/Cargo.toml"
# Before the benchmarks' library (benches/lib.rs), each benchmark took the zoo in by `#[path]`.
[ -f "$work/tree/benches/lib.rs" ] ||
    sed -i 's|^use dirac_benches::zoo;|#[path = "../tests/zoo/mod.rs"]\nmod zoo;|' "$work/tree/benches/small_models.rs"
# Cases whose models the base's zoo does not have yet are dropped from its copy of the driver.
grep -q 'struct SaturatedServo' "$work/tree/tests/zoo/mod.rs" ||
    sed -i '/SaturatedServo\|&servo/d' "$work/tree/benches/small_models.rs"
if ! grep -rq 'trait DenseModel' "$work/tree/dirac-runtime/src"; then
    sed -i 's/DenseModel/LagrangeDirac/g' "$work/tree/benches/small_models.rs"
fi
# The base's target directory, absolute: build() runs inside the worktree.
old=$(build "$work/tree" "$(realpath -m "${BASE_TARGET_DIR:-$work/target}")")
new=$(build . target)

printf '%-30s %14s %14s %8s\n' case "$base" "this tree" change
all="radau-chain:20 radau-pendulum:20 radau-pendulum8:5 variational-pendulum:20
    variational-pendulum-general:20 variational-chain:20 explicit-chain:20 explicit-pendulum:20
    explicit-pendulum8:20 radau-servo:20 explicit-servo:20"
for spec in ${CASES:-$all}; do
    case=${spec%:*} repeats=${spec#*:}
    a=$(count "$old" "$case" "$repeats")
    b=$(count "$new" "$case" "$repeats")
    printf '%-30s %14s %14s %+7.1f%%\n' "$case" "$a" "$b" "$(awk "BEGIN { print 100 * ($b / $a - 1) }")"
done
