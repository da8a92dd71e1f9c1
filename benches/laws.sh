#!/usr/bin/env bash
# Instructions of stick-slip written as the friction law against the same law written by hand
# (benches/laws.rs), under callgrind: exact counts, in one build, so the ratio does not depend
# on the machine's load. Needs valgrind (apt-get install valgrind). Not part of CI.
#
# Usage: bash benches/laws.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --bench laws 2>&1 | grep -E '^error' >&2 || true
driver=$(find target/release/deps -maxdepth 1 -type f -executable -name 'laws-*' -printf '%T@ %p\n' |
    sort -n | tail -1 | cut -d' ' -f2)
count() { # $1 = case, $2 = repeats
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$driver" "$1" "$2" 2>&1 |
        sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
printf '%-10s %14s %14s %8s\n' method law "by hand" ratio
for method in radau explicit; do
    a=$(count "$method-law" 20)
    b=$(count "$method-hand" 20)
    printf '%-10s %14s %14s %8.3f\n' "$method" "$a" "$b" "$(awk "BEGIN { print $a / $b }")"
done
