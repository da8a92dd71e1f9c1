#!/usr/bin/env bash
# Instructions per F+J call, generated against hand-written, counted by valgrind (callgrind) on
# the kernels benchmark binary: (instructions of k calls − instructions of 0 calls) / k, so
# start-up and the checks are subtracted. Needs valgrind (apt-get install valgrind). Not part
# of CI.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$(cargo bench -p dirac-benches --bench kernels --no-run 2>&1 | sed -n 's/.*Executable .*(\(.*\))$/\1/p')
calls=100000
count() {
    DIRAC_KERNEL_LOOP="$1" DIRAC_KERNEL_CALLS="$2" valgrind --tool=callgrind \
        --callgrind-out-file=/dev/null "$bin" 2>&1 | sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
# Instructions per call of one kernel: $1 = generated or hand-written, $2 = the model.
per_call() {
    echo $(( ($(count "$1 $2" $calls) - $(count "$1 $2" 0)) / calls ))
}
printf '%-12s %12s %12s %7s\n' model generated hand-written ratio
for model in paper cartesian2 cartesian4; do
    g=$(per_call generated "$model")
    h=$(per_call hand-written "$model")
    printf '%-12s %12s %12s %7.2f\n' "$model" "$g" "$h" "$(awk "BEGIN { print $g / $h }")"
done
