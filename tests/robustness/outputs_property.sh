#!/bin/sh
# Property: what a command writes does not depend on what else it is asked
# to write. Random valid cases from cases/ go through check, design and
# batch, first with every output option, then with random subsets of them;
# the exit code and the bytes of every file written must be the same as in
# the run with all of them.
#
#   sh tests/robustness/outputs_property.sh ROCKBOLT SCRATCH_DIR [SECONDS] [SEED]
#
# Run from the source root. Stops after SECONDS (default 40) or 200
# trials, whichever comes first; the seed is printed so a failure can be
# replayed.
set -u
RB=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
D=$2
BUDGET=${3:-40}
SEED=${4:-$(od -An -N4 -tu4 /dev/urandom | tr -d ' ')}
rm -rf "$D"
mkdir -p "$D" || exit 1
echo "seed $SEED"

# A linear congruential generator in shell arithmetic: rnd N sets $r in
# [0, N).
state=$((SEED % 2147483647 + 1))
rnd() {
    state=$(( (state * 48271) % 2147483647 ))
    r=$(( state % $1 ))
}

# Cases that solve in well under a second (design: a fraction of one).
CHECK_CASES="cases/free-standing.yaml cases/reference-design.yaml
cases/reference-elcentro.yaml cases/reference-harmonic.yaml
cases/reference-suite.yaml cases/reference-taft.yaml cases/us-customary.yaml
cases/thesis/table-2.2-half-sine.yaml cases/thesis/fig-5.13-harmonic.yaml
cases/thesis/table-6.3-elcentro-0.2.yaml cases/thesis/table-6.1-gr0.01.yaml"
DESIGN_CASES="cases/free-standing.yaml cases/reference-harmonic.yaml
cases/us-customary.yaml cases/thesis/table-2.2-half-sine.yaml
cases/thesis/fig-5.13-harmonic.yaml"

pick() { # pick WORDS...: one of them in $p
    n=$#
    rnd "$n"
    shift "$r"
    p=$1
}

fails=0
# trial NAME CMD MAIN OPTS...: the full run's files are in $D/full; runs
# with the options listed in $SUBSET only, into $D/sub, and compares.
compare_dirs() {
    for f in $(cd "$D/sub" && find . -type f | sort); do
        if ! cmp -s "$D/sub/$f" "$D/full/$f"; then
            echo "FAIL: $desc: $f differs from the run with every output (subset: $subset)"
            fails=$((fails + 1))
            return
        fi
    done
}

# opts_for KIND DIR: the output options of a command, writing into DIR
opts_for() {
    case $1 in
    check) echo "--json $2/r.json --text $2/r.txt --history $2/h.csv --svg $2/f.svg --html $2/p.html" ;;
    design) echo "--json $2/r.json --text $2/r.txt --history $2/h.csv --svg $2/f.svg --html $2/p.html --sweep-csv $2/s.csv" ;;
    batch) echo "--json $2/s.json --csv $2/s.csv --junit $2/s.xml --reports $2/rep" ;;
    esac
}

start=$(date +%s)
trials=0 runs=0
while [ $(( $(date +%s) - start )) -lt "$BUDGET" ] && [ "$trials" -lt 200 ]; do
    trials=$((trials + 1))
    rnd 10
    if [ "$r" -lt 5 ]; then
        kind=check
        pick $CHECK_CASES
        args="check $p"
    elif [ "$r" -lt 7 ]; then
        kind=design
        pick $DESIGN_CASES
        rnd 2
        args="design $p -j $((r + 1))"
    else
        kind=batch
        pick $CHECK_CASES
        a=$p
        pick $CHECK_CASES
        rnd 3
        args="batch $a $p -j $((r + 1))"
        [ "$a" = "$p" ] && args="batch $a -j $((r + 1))"
        rnd 4
        [ "$r" -eq 0 ] && args="batch tests/batch/list.csv $a -j 2"
    fi
    desc="$args"
    rm -rf "$D/full" "$D/sub"
    mkdir -p "$D/full" "$D/sub"
    # shellcheck disable=SC2046
    "$RB" $args $(opts_for $kind "$D/full") -q >/dev/null 2>"$D/err.full"
    rc_full=$?
    runs=$((runs + 1))
    if [ "$rc_full" -gt 2 ]; then
        echo "FAIL: $desc: exit $rc_full with every output"
        head -5 "$D/err.full"
        fails=$((fails + 1))
        continue
    fi
    # two random subsets of the options, each option kept with p = 1/2
    for k in 1 2; do
        rm -rf "$D/sub"
        mkdir -p "$D/sub"
        subset=""
        set -- $(opts_for $kind "$D/sub")
        while [ $# -ge 2 ]; do
            rnd 2
            [ "$r" -eq 1 ] && subset="$subset $1 $2"
            shift 2
        done
        # shellcheck disable=SC2086
        "$RB" $args $subset -q >/dev/null 2>"$D/err.sub"
        rc=$?
        runs=$((runs + 1))
        if [ "$rc" -ne "$rc_full" ]; then
            echo "FAIL: $desc: exit $rc with$subset, $rc_full with every output"
            head -5 "$D/err.sub"
            fails=$((fails + 1))
            continue
        fi
        compare_dirs
    done
done
echo "$trials trials, $runs runs in $(( $(date +%s) - start )) s, $fails failures (seed $SEED)"
[ "$fails" -eq 0 ]
