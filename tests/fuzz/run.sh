#!/bin/sh
# Run one libFuzzer harness for a bounded time.
#
#   tests/fuzz/run.sh HARNESS SECONDS      HARNESS: case, at2, cosmos, columns,
#                                          table, list, merge
#
# Builds fuzz_HARNESS in $RB_FUZZ_BUILD (default build-fuzz, configured with
# clang and -DRB_FUZZ=ON if it is not yet), seeds it from the repository
# (cases/, cases/records/ cut to a few lines, tests/errors/,
# tests/unit/case_data/, tests/fuzz/seeds/HARNESS/), and fuzzes one process
# on one core for SECONDS. The growing corpus and any crash, leak or
# timeout reproducers stay in $RB_FUZZ_WORK (default
# $RB_FUZZ_BUILD/fuzz-work/HARNESS), outside the source tree: copy a
# reproducer into tests/fuzz/regressions/HARNESS/ to keep it as a ctest.
# Exits with libFuzzer's status (0: nothing found in the time given).
set -eu
if [ $# -ne 2 ]; then
    echo "usage: $0 case|at2|cosmos|columns|table|list|merge SECONDS" >&2
    exit 2
fi
harness=$1
seconds=$2
case $harness in
case) dict=case.dict ;;
at2|cosmos|columns|table) dict=record.dict ;;
list|merge) dict=$harness.dict ;;
*) echo "$0: unknown harness '$harness' (case, at2, cosmos, columns, table, list, merge)" >&2
   exit 2 ;;
esac
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${RB_FUZZ_BUILD:-$root/build-fuzz}
work=${RB_FUZZ_WORK:-$build/fuzz-work/$harness}

if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_C_COMPILER=clang -DRB_FUZZ=ON \
        -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
cmake --build "$build" -j2 --target "fuzz_$harness" >/dev/null

# An AT2 record cut to its header and `keep` data lines, with NPTS made to
# match, so that the seed is short and still a valid record.
cut_at2() {
    awk -v keep="$2" '
        NR <= 3 { print; next }
        NR == 4 { hdr = $0; next }
        NR <= 4 + keep { line[++k] = $0; n += NF; next }
        END { sub(/NPTS= *[0-9]+/, "NPTS= " n, hdr); print hdr
              for (i = 1; i <= k; i++) print line[i] }' "$1"
}

seeds=$work/seeds
rm -rf "$seeds"
mkdir -p "$seeds" "$work/corpus" "$work/artifacts"
case $harness in
case)
    for f in "$root"/cases/*.yaml "$root"/cases/base/*.yaml "$root"/tests/errors/*.yaml \
             "$root"/tests/errors/include/*.yaml "$root"/tests/unit/case_data/*.yaml; do
        [ -f "$f" ] && cp "$f" "$seeds/$(basename "$(dirname "$f")")-$(basename "$f")"
    done ;;
at2|columns)
    for f in "$root"/cases/records/*.at2; do
        cut_at2 "$f" 12 >"$seeds/$(basename "$f")"
    done
    head -n 200 "$root/cases/records/taft_1952_s69e.txt" >"$seeds/taft_1952_s69e.txt" ;;
table)
    cp "$root"/tests/errors/include/table-*.csv "$seeds/" ;;
list)
    cp "$root"/tests/batch/list.csv "$seeds/" ;;
esac
if [ -d "$root/tests/fuzz/seeds/$harness" ]; then
    cp "$root/tests/fuzz/seeds/$harness"/* "$seeds/"
fi
if [ "$harness" = columns ]; then
    cp "$root"/tests/fuzz/seeds/at2/* "$root"/tests/fuzz/seeds/cosmos/* "$seeds/"
fi

# stdin is /dev/null: a case that names /dev/stdin as a record or base must
# not stall the run.
exec "$build/fuzz_$harness" "$work/corpus" "$seeds" \
    -dict="$root/tests/fuzz/dict/$dict" -max_total_time="$seconds" \
    -max_len=8192 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$work/artifacts/" </dev/null
