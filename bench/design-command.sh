#!/bin/sh
# Wall time of the whole `rockbolt design` command, as a user runs it
# (issue 16's benchmark): the process, the case and record loading, the
# check before the searches, the searches and the text report, where
# bench_design times the searches alone. Prints the least, median and
# largest of N runs (default 21) against the 0.2 s target.
# Usage: bench/design-command.sh [ROCKBOLT] [CASE] [N]   (from the source root)
set -eu
rb=${1:-build/rockbolt}
case_file=${2:-cases/reference-design.yaml}
n=${3:-21}
[ -x "$rb" ] || { echo "design-command.sh: no executable $rb (build first)" >&2; exit 2; }
times=""
i=0
while [ "$i" -lt "$n" ]; do
    s=$(date +%s%N)
    rc=0
    "$rb" design "$case_file" --quiet >/dev/null 2>&1 || rc=$?
    e=$(date +%s%N)
    # exit 1 is a FAIL verdict (the reference case's): a run all the same
    if [ "$rc" -gt 1 ]; then
        echo "design-command.sh: rockbolt design $case_file exited $rc" >&2
        exit 2
    fi
    times="$times$(((e - s) / 1000))
"
    i=$((i + 1))
done
printf "%s" "$times" | sort -n | awk -v c="$case_file" -v n="$n" '
    { t[NR] = $1 / 1e6 }
    END {
        m = t[int((NR + 1) / 2)]
        printf "rockbolt design %s: median %.3f s (least %.3f, largest %.3f, %d runs); target 0.2 s: %s\n",
            c, m, t[1], t[NR], n, m < 0.2 ? "met" : "NOT met"
    }'
