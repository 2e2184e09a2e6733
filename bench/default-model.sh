#!/bin/sh
# What the default bolt model costs: the wall time of `rockbolt check` on
# the same case with elastic-plastic rows (a case file's default) and with
# the thesis's rigid-plastic rows, as a user runs it (process, loading,
# the solves, confirming runs, report). Prints the least, median and
# largest of N runs (default 11) of each and the ratio of the medians.
# Usage: bench/default-model.sh [ROCKBOLT] [CASE] [N]   (from the source root;
# CASE names no model; default the panel of tests/verdicts/cases)
set -eu
rb=${1:-build/rockbolt}
case_file=${2:-tests/verdicts/cases/panel.yaml}
n=${3:-11}
[ -x "$rb" ] || { echo "default-model.sh: no executable $rb (build first)" >&2; exit 2; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
abs=$(cd "$(dirname "$case_file")" && pwd)/$(basename "$case_file")
for model in elastic-plastic rigid-plastic; do
    printf 'extends: %s\nanchorage:\n  model: %s\n' "$abs" "$model" >"$dir/$model.yaml"
done
time_model() {
    i=0
    while [ "$i" -lt "$n" ]; do
        s=$(date +%s%N)
        rc=0
        "$rb" check "$dir/$1.yaml" --quiet >/dev/null 2>&1 || rc=$?
        e=$(date +%s%N)
        # exit 1 is a FAIL verdict: a run all the same
        [ "$rc" -le 1 ] || { echo "default-model.sh: check exited $rc" >&2; exit 2; }
        echo $(((e - s) / 1000))
        i=$((i + 1))
    done | sort -n | awk -v m="$1" '
        { t[NR] = $1 / 1e3 }
        END { printf "%s %.1f %.1f %.1f\n", m, t[int((NR + 1) / 2)], t[1], t[NR] }'
}
{ time_model elastic-plastic; time_model rigid-plastic; } | awk -v c="$case_file" -v n="$n" '
    { name[NR] = $1; med[NR] = $2; printf "%s rows: rockbolt check %s: median %.1f ms (least %.1f, largest %.1f, %d runs)\n", $1, c, $2, $3, $4, n }
    END { printf "default (elastic-plastic) over rigid-plastic: %.2f times the wall time\n", med[1] / med[2] }'
