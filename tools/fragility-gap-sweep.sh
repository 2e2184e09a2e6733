#!/bin/sh
# The reference cabinet's fragility at several gap ratios (docs/fragility.md):
# for each, `rockbolt fragility` on cases/fragility-suite.yaml with that gap
# ratio, and one line: the fitted median and beta of each limit state and
# its probability at the suite's level (0.4 A*).
# Usage: tools/fragility-gap-sweep.sh ROCKBOLT [GAP_RATIO...]   (from the source root)
set -eu
rb=$1
shift
[ $# -gt 0 ] || set -- 0.002 0.005 0.01 0.015 0.02 0.03
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
printf '%-9s' "gap ratio"
for s in first-yield usage overturn lift-off; do printf ' %26s' "$s: median g, beta, P"; done
printf '\n'
for gr in "$@"; do
    printf 'extends: %s/cases/fragility-suite.yaml\ngap_ratio: %s\n' "$(pwd)" "$gr" >"$dir/c.yaml"
    "$rb" fragility "$dir/c.yaml" --json "$dir/f.json" --quiet
    python3 - "$dir/f.json" "$gr" <<'PY'
import json, sys
f = json.load(open(sys.argv[1]))
g = f["g_mps2"]
line = f"{sys.argv[2]:<9}"
for s in f["limit_states"]:
    if s["fitted"]:
        line += f" {s['median_mps2'] / g:9.3f} {s['beta']:6.3f} {s['p_at_level']:8.4f}"
    else:
        line += f" {'not fitted':>26}"
print(line)
PY
done
