#!/bin/sh
# A varied equipment list for timing `rockbolt batch` the way a review runs
# it (issue 16's benchmark): N rows (default 1000) over the shipped records,
# 200-900 kg, 3-15 Hz frames, 10-16 mm bolts, gap ratios 0.002-0.03 and
# peaks of 0.05-0.5 A*, every row a different cabinet, drawn with a fixed
# seed. Writes LIST.csv; the base is cases/reference-elcentro.yaml. A
# third argument sets every row's peak to that many A* instead (the same
# cabinets at 0.002 A* never leave the floor: what a batch costs where
# nothing rocks).
# Usage: bench/varied-list.sh LIST.csv [N [PEAK]]   (from the source root), then
#   time build/rockbolt batch LIST.csv --quiet
set -eu
out=$1
n=${2:-1000}
peak=${3:-}
base="$(pwd)/cases/reference-elcentro.yaml"
awk -v n="$n" -v base="$base" -v peak="$peak" 'BEGIN {
    srand(20261124)
    print "tag,base,mass,frequency,diameter,gap_ratio,motion,peak"
    for (i = 1; i <= n; i++) {
        rec = (rand() < 0.5) ? "elcentro" : "taft"
        mass = 200 + 700 * rand(); f = 3 + 12 * rand(); dia = 10 + 6 * rand()
        gr = 0.002 + 0.028 * rand(); a = 0.05 + 0.45 * rand()
        printf "R-%d,%s,%.0f kg,%.2f Hz,%.1f mm,%.4f,%s,%.3f A*\n", i, base,
            mass, f, dia, gr, rec, peak != "" ? peak : a
    }
}' >"$out"
