#!/bin/sh
# Issue 41's solver speeds as ratios that hold on any machine: the build of
# BASE (default 4c29ff4, the solver before it) and of NEW (default HEAD),
# both release builds with LTO (bench/baseline.sh), run the same program
# (bench/solve_figures.c) over the same work, their runs alternated, ROUNDS
# rounds (default 7) of RUNS solves (default 40; a tenth as many, at least
# 5, for the elastic-plastic figure, as bench_solve does). For each figure:
# each build's median over the rounds of its medians, the ratio BASE / NEW
# of those, the least and largest ratio of a round, each build's best
# solve over all rounds and their ratio (what a burst of another tenant's
# load on a shared machine disturbs least), and NEW's time over the plain
# linear SDOF loop timed in the same process (the physical floor).
# Usage: bench/solve-ratios.sh [BASE [NEW [ROUNDS [RUNS]]]]   (from the source root)
set -eu
base=${1:-4c29ff4}
new=${2:-HEAD}
rounds=${3:-7}
runs=${4:-40}
bdir=$(sh bench/baseline.sh "$base" "" bench/solve_figures.c)
ndir=$(sh bench/baseline.sh "$new" "" bench/solve_figures.c)
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for fig in floor rigid elastic; do
    n=$runs
    [ "$fig" = elastic ] && n=$(( (runs + 9) / 10 < 5 ? 5 : (runs + 9) / 10 ))
    i=0
    while [ "$i" -lt "$rounds" ]; do
        # alternated, and which goes first alternates too
        if [ $((i % 2)) -eq 0 ]; then order="new base"; else order="base new"; fi
        for which in $order; do
            if [ "$which" = new ]; then d=$ndir; else d=$bdir; fi
            printf '%s %d ' "$which" "$i" >>"$out"
            "$d/solve_figures" "$fig" "$n" >>"$out"
        done
        i=$((i + 1))
    done
done
awk -v base="$base" -v new="$new" -v rounds="$rounds" '
    function median(a, n,   i, j, t) {
        for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] > a[j]; j--) {
            t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
        return n % 2 ? a[(n + 1) / 2] : 0.5 * (a[n / 2] + a[n / 2 + 1])
    }
    { f = $3; ms[$1, f, $2] = $4; steps[$1, f] = $7; sdof[$1, f, $2] = $8; figs[f] = 1
      if (!(($1, f) in best) || $5 < best[$1, f]) best[$1, f] = $5 }
    END {
        split("floor rigid elastic", order, " ")
        for (k = 1; k <= 3; k++) {
            f = order[k]; if (!(f in figs)) continue
            lo = 1e300; hi = 0
            for (i = 0; i < rounds; i++) {
                nb[i + 1] = ms["base", f, i]; nn[i + 1] = ms["new", f, i]
                ns[i + 1] = ms["new", f, i] / sdof["new", f, i]
                r = ms["base", f, i] / ms["new", f, i]
                if (r < lo) lo = r; if (r > hi) hi = r
            }
            mb = median(nb, rounds); mn = median(nn, rounds); s = median(ns, rounds)
            printf "%-8s %s %.4f ms (%d steps), %s %.4f ms (%d steps): %.2f x (rounds %.2f-%.2f; best solves %.4f and %.4f ms, %.2f x); %s over the SDOF loop %.1f x\n",
                f, base, mb, steps["base", f], new, mn, steps["new", f], mb / mn, lo, hi,
                best["base", f], best["new", f], best["base", f] / best["new", f], new, s
        }
    }' "$out"
