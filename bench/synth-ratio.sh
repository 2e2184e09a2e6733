#!/bin/sh
# The synthetic suite's time as a ratio that holds on a loaded machine: two
# builds of bench_synth (BASE, the build before a change, and NEW) run the
# same suite (7 triaxial AC156 sets, seed 156, one core), their runs
# alternated, ROUNDS rounds (default 5), which goes first alternating too.
# Prints each run's wall and CPU (user) seconds, then each build's median
# and the ratios BASE / NEW of the medians, and the load average at the
# start and the end. A BASE built from an older commit: bench/baseline.sh.
# Usage: bench/synth-ratio.sh BASE_BENCH_SYNTH NEW_BENCH_SYNTH [ROUNDS]
set -eu
base=$1
new=$2
rounds=${3:-5}
out=$(mktemp)
run=$(mktemp)
cpu=$(mktemp)
trap 'rm -f "$out" "$run" "$cpu"' EXIT
echo "load at start: $(cut -d' ' -f1-3 /proc/loadavg)"
i=0
while [ "$i" -lt "$rounds" ]; do
    if [ $((i % 2)) -eq 0 ]; then order="new base"; else order="base new"; fi
    for which in $order; do
        if [ "$which" = new ]; then b=$new; else b=$base; fi
        /usr/bin/time -f '%U' -o "$cpu" "$b" 156 1 >"$run"
        wall=$(sed -n 's/.*best of 1: \([0-9.]*\) s.*/\1/p' "$run")
        echo "$which $i wall $wall cpu $(tail -n 1 "$cpu")" | tee -a "$out"
    done
    i=$((i + 1))
done
echo "load at end: $(cut -d' ' -f1-3 /proc/loadavg)"
awk '
function median(a, n,   i, j, t) {
    for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
}
$1 == "base" { nb++; bw[nb] = $4; bc[nb] = $6 }
$1 == "new" { nn++; nw[nn] = $4; nc[nn] = $6 }
END {
    mbw = median(bw, nb); mbc = median(bc, nb); mnw = median(nw, nn); mnc = median(nc, nn)
    printf "base: median wall %.3f s, cpu %.3f s\n", mbw, mbc
    printf "new:  median wall %.3f s, cpu %.3f s\n", mnw, mnc
    printf "ratio base / new: wall %.2f, cpu %.2f\n", mbw / mnw, mbc / mnc
}' "$out"
