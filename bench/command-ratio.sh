#!/bin/sh
# Two builds of rockbolt timed on the same command, their runs alternated
# (base, new, base, new, ...), so that a speed holds on a loaded machine as
# the ratio of their medians. Prints each build's median, least and largest
# wall time, the ratio base / new, and the load average before and after.
# With ROWS (the rows of a batch list), also each build's rows per second.
#
# Usage: bench/command-ratio.sh BASE_ROCKBOLT NEW_ROCKBOLT ROUNDS ROWS -- ARGS...
#   (from the source root; ROWS 0 for a command that is not a batch)
# e.g. the varied list on two threads against 4c29ff4 (bench/baseline.sh):
#   bench/varied-list.sh /tmp/varied.csv
#   bench/command-ratio.sh build-base-4c29ff4/rockbolt build/rockbolt 5 1000 \
#       -- batch /tmp/varied.csv --quiet -j 2
# and the design command:
#   bench/command-ratio.sh build-base-4c29ff4/rockbolt build/rockbolt 11 0 \
#       -- design cases/reference-design.yaml --quiet -j 2
set -eu
[ $# -ge 5 ] && [ "$5" = "--" ] || {
    echo "usage: command-ratio.sh BASE NEW ROUNDS ROWS -- ARGS..." >&2; exit 2; }
base=$1 new=$2 rounds=$3 rows=$4
shift 5
for rb in "$base" "$new"; do
    [ -x "$rb" ] || { echo "command-ratio.sh: no executable $rb" >&2; exit 2; }
done
load0=$(cut -d' ' -f1 /proc/loadavg)
out=$(mktemp)
trap 'rm -f "$out"' EXIT INT TERM
i=0
while [ "$i" -lt "$rounds" ]; do
    for which in base new; do
        [ "$which" = base ] && rb=$base || rb=$new
        s=$(date +%s%N)
        rc=0
        "$rb" "$@" >/dev/null 2>&1 || rc=$?
        e=$(date +%s%N)
        # exit 1 is a FAIL verdict: a run all the same
        if [ "$rc" -gt 1 ]; then
            echo "command-ratio.sh: $rb $* exited $rc" >&2
            exit 2
        fi
        echo "$which $(((e - s) / 1000))" >>"$out"
    done
    i=$((i + 1))
done
load1=$(cut -d' ' -f1 /proc/loadavg)
for which in base new; do
    grep "^$which " "$out" | cut -d' ' -f2 | sort -n | awk -v w="$which" -v rows="$rows" '
        { t[NR] = $1 / 1e6 }
        END {
            m = t[int((NR + 1) / 2)]
            printf "%s: median %.3f s (least %.3f, largest %.3f, %d runs)", w, m, t[1], t[NR], NR
            if (rows > 0)
                printf ", %.0f rows/s", rows / m
            printf "\n"
            print m > "/dev/stderr"
        }' 2>>"$out.m"
done
awk 'NR == 1 { b = $1 } NR == 2 { printf "ratio base / new: %.2f\n", b / $1 }' "$out.m"
rm -f "$out.m"
echo "load average: $load0 before, $load1 after"
