#!/bin/sh
# The fuzz stage of .ci/run: build every libFuzzer harness with clang
# (-DRB_FUZZ=ON, in $RB_FUZZ_BUILD, default build-fuzz) and run each from
# its seeds for SECONDS (default 10), one process each. Fails on a build
# error or on anything a harness finds (its reproducer is left in
# $RB_FUZZ_BUILD/fuzz-work/HARNESS/artifacts/).
set -eu
seconds=${1:-10}
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${RB_FUZZ_BUILD:-$root/build-fuzz}
harnesses="case at2 cosmos columns table list merge"
cmake -S "$root" -B "$build" -DCMAKE_C_COMPILER=clang -DRB_FUZZ=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo
targets=
for h in $harnesses; do
    targets="$targets fuzz_$h"
done
# shellcheck disable=SC2086
cmake --build "$build" -j2 --target $targets
fail=0
for h in $harnesses; do
    echo "fuzz: $h for $seconds s"
    log=$build/fuzz-$h.log
    if RB_FUZZ_BUILD=$build "$root/tests/fuzz/run.sh" "$h" "$seconds" >"$log" 2>&1; then
        grep -E '^(#[0-9]+.*DONE|stat::number_of_executed_units)' "$log" || true
    else
        tail -n 40 "$log"
        echo "fuzz: $h FAILED (log: $log)"
        fail=1
    fi
done
exit $fail
