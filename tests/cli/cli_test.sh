#!/bin/sh
# End-to-end tests of the rockbolt executable on the shipped cases.
#
#   sh tests/cli/cli_test.sh TEST ROCKBOLT JSONGET SCRATCH_DIR
#
# Run from the source root (ctest does). Each TEST is one function below;
# it prints what it checked and exits 0 (pass), 1 (fail) or 77 (skipped).
# Exit codes, the JSON/text agreement and the all-or-nothing output files
# are the contract checked here; the numbers themselves are the solver
# tests' business, so only their sanity is checked (the text's numbers
# against the JSON's, a suite's and the US units' are tests/cli/numbers.py's).
set -u

T=$1
RB=$2
JG=$3
D=$4
rm -rf "$D"
mkdir -p "$D" || exit 1

HARMONIC=cases/reference-harmonic.yaml
ELCENTRO=cases/reference-elcentro.yaml

fail() {
    echo "FAIL [$T]: $*"
    for f in "$D/out" "$D/err"; do
        [ -f "$f" ] && { echo "--- $f"; head -40 "$f"; }
    done
    exit 1
}

# run ARGS...: the exit code in $rc, stdout in $D/out, stderr in $D/err
run() {
    "$RB" "$@" >"$D/out" 2>"$D/err"
    rc=$?
}

expect_rc() {
    [ "$rc" -eq "$1" ] || fail "exit code $rc, expected $1 (rockbolt $2)"
}

# jget FILE PATH [DECIMALS]
jget() {
    if [ $# -eq 3 ]; then "$JG" -p "$3" "$1" "$2"; else "$JG" "$1" "$2"; fi ||
        fail "no value at $2 in $1"
}

no_temp_files() {
    ls -a "$1" | grep -q '\.tmp\.' && fail "temporary files left in $1: $(ls -a "$1")"
    return 0
}

# The verdict line of a report and the JSON verdict must agree, and the
# exit code must follow from them.
verdict_agrees() {
    json=$1 text=$2
    result=$(jget "$json" verdict.result)
    headline=$(jget "$json" verdict.headline)
    reason=$(jget "$json" verdict.reason)
    case "$headline" in
        "$result"|"$result ("*" validity warning"*")") ;;
        *) fail "headline '$headline' does not start with the result '$result'" ;;
    esac
    [ "$(head -1 "$text")" = "$headline: $reason" ] ||
        fail "text verdict '$(head -1 "$text")' != JSON '$headline: $reason'"
    case "$result:$rc" in
        PASS:0|FAIL:1) ;;
        *) fail "verdict $result with exit code $rc" ;;
    esac
}

test_help() {
    run --help; expect_rc 0 --help
    for w in check init --json --text --history --quiet "exit codes" \
             "0  the design passes" "2  bad input" "3  internal"; do
        grep -q -- "$w" "$D/out" || fail "--help does not mention '$w'"
    done
    [ -s "$D/err" ] && fail "--help wrote to stderr"
    run check --help; expect_rc 0 "check --help"
    run --version; expect_rc 0 --version
    grep -Eq '^rockbolt [0-9]+\.[0-9]+\.[0-9]+' "$D/out" || fail "--version output"
    echo "help and version: ok"
}

test_usage() {
    run; expect_rc 2 "(no arguments)"
    grep -q '^rockbolt: error: ' "$D/err" || fail "usage error format"
    run frobnicate; expect_rc 2 "unknown command"
    run check; expect_rc 2 "check without a case"
    run check "$HARMONIC" --frobnicate; expect_rc 2 "unknown option"
    grep -q "^rockbolt: error: unknown option '--frobnicate'" "$D/err" ||
        fail "unknown option message"
    [ "$(wc -l <"$D/err")" -eq 1 ] || fail "one line per diagnostic"
    run check "$HARMONIC" --json; expect_rc 2 "--json without a file"
    run check "$HARMONIC" extra.yaml; expect_rc 2 "two case files"
    run check "$HARMONIC" --json "$D/a" --text "$D/a"; expect_rc 2 "same output twice"
    run check "$D/no-such-case.yaml"; expect_rc 2 "missing case file"
    grep -q "no-such-case.yaml" "$D/err" || fail "missing case not named"
    printf 'equipment:\n  mass: -3 kg\n' >"$D/bad.yaml"
    run check "$D/bad.yaml" --json "$D/bad.json"; expect_rc 2 "invalid case"
    grep -Eq "^$D/bad.yaml(:[0-9]+:[0-9]+)?: error: " "$D/err" ||
        fail "case diagnostic not in FILE:LINE:COL: error: form"
    [ -e "$D/bad.json" ] && fail "a report was written for an invalid case"
    [ -s "$D/out" ] && fail "stdout not empty after a usage error"
    echo "usage errors: ok"
}

test_harmonic() {
    run check "$HARMONIC" --json "$D/h.json" --text "$D/h.txt" --history "$D/h.csv"
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "exit code $rc"
    "$JG" "$D/h.json" || fail "JSON does not parse"
    [ "$(jget "$D/h.json" format)" = rockbolt-report ] || fail "format"
    [ "$(jget "$D/h.json" format_version)" = 2 ] || fail "format_version"
    [ "$(jget "$D/h.json" tool.version)" = "$("$RB" --version | cut -d' ' -f2)" ] ||
        fail "tool version"
    [ "$(jget "$D/h.json" case.path)" = "$HARMONIC" ] || fail "case path"
    [ "$(jget "$D/h.json" motions.length)" -ge 1 ] || fail "no motions"
    [ "$(jget "$D/h.json" motions.0.motion.kind)" = harmonic ] || fail "motion kind"
    verdict_agrees "$D/h.json" "$D/h.txt"
    [ "$(cat "$D/out")" = "$(head -1 "$D/h.txt")" ] ||
        fail "with --text, stdout must be the verdict line only"
    no_temp_files "$D"
    echo "harmonic: ok (exit $rc)"
}

test_stdout() {
    run check "$HARMONIC"
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "exit code $rc"
    head -1 "$D/out" | grep -Eq '^(PASS|FAIL)( \([1-9] validity warnings?: [a-z, -]+\))?: .+' ||
        fail "first line is not the verdict"
    grep -q "^motion 1: " "$D/out" || fail "no per-motion section"
    cp "$D/out" "$D/first"
    run check "$HARMONIC"
    cmp -s "$D/out" "$D/first" || fail "text report is not byte-stable"
    run check "$HARMONIC" --quiet
    [ -s "$D/out" ] && fail "--quiet printed something"
    run check "$HARMONIC" --text "$D/t.txt"
    cmp -s "$D/t.txt" "$D/first" || fail "--text differs from stdout"
    echo "stdout: ok"
}

test_elcentro() {
    run check "$ELCENTRO" --json "$D/e.json" --text "$D/e.txt"
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "exit code $rc"
    verdict_agrees "$D/e.json" "$D/e.txt"
    [ "$(jget "$D/e.json" motions.0.motion.kind)" = record ] || fail "record motion"
    grep -q "elcentro_1940_ns.at2" "$D/e.txt" || fail "record source not in text"
    echo "elcentro: ok (exit $rc)"
}

test_unwritable() {
    run check "$HARMONIC" --json /nonexistent-rockbolt-dir/r.json --text "$D/t.txt"
    expect_rc 2 "unwritable --json"
    grep -q "^/nonexistent-rockbolt-dir/r.json: error: --json: " "$D/err" ||
        fail "message does not name the path and option"
    [ -e "$D/t.txt" ] && fail "--text written although --json cannot be"
    : >"$D/plain"
    run check "$HARMONIC" --history "$D/plain/h.csv"; expect_rc 2 "parent is a file"
    grep -q "$D/plain/h.csv" "$D/err" || fail "path not named"
    run check "$HARMONIC" --text "$D"; expect_rc 2 "output is a directory"
    no_temp_files "$D"
    echo "unwritable outputs: ok"
}

# A failed run leaves existing outputs exactly as they were.
test_preserved() {
    echo old >"$D/keep.json"
    echo old >"$D/keep.txt"
    run check "$D/missing.yaml" --json "$D/keep.json" --text "$D/keep.txt"
    expect_rc 2 "missing case"
    [ "$(cat "$D/keep.json")" = old ] && [ "$(cat "$D/keep.txt")" = old ] ||
        fail "existing outputs changed by a failed run"
    run check "$HARMONIC" --json "$D/keep.json" --text "$D/keep.txt" \
        --text2 "$D/x"
    expect_rc 2 "bad option"
    [ "$(cat "$D/keep.json")" = old ] || fail "output changed by a usage error"
    run check "$HARMONIC" --json "$D/keep.json" --text "$D/keep.txt"
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "exit code $rc"
    "$JG" "$D/keep.json" || fail "replaced JSON does not parse"
    tail -c 1 "$D/keep.json" | od -An -c | grep -q '\\n' || fail "JSON lacks a final newline"
    grep -q "^  energy (J)" "$D/keep.txt" || fail "text report is cut short"
    no_temp_files "$D"
    echo "preserved and whole outputs: ok"
}

test_history() {
    run check "$HARMONIC" --quiet --history "$D/h.csv" --json "$D/h.json"
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "exit code $rc"
    head -1 "$D/h.csv" | grep -q '^motion,t_s,accel_mps2,theta_rad,u_m,' || fail "CSV header"
    # the JSON report counts the rows it carries (none without
    # analysis.history), whatever --history asks for
    [ "$(jget "$D/h.json" motions.0.result.cost.history_rows)" = "0" ] ||
        fail "history_rows in JSON depends on --history"
    echo "history: ok"
}

test_init() {
    if [ ! -f templates/starter.yaml ]; then
        echo "templates/starter.yaml not shipped yet: skipped"
        exit 77
    fi
    run init "$D/new.yaml"; expect_rc 0 init
    cmp -s "$D/new.yaml" templates/starter.yaml || fail "init wrote something else"
    echo changed >>"$D/new.yaml"
    cp "$D/new.yaml" "$D/copy.yaml"
    run init "$D/new.yaml"; expect_rc 2 "init over an existing file"
    cmp -s "$D/new.yaml" "$D/copy.yaml" || fail "init overwrote a file"
    grep -q "new.yaml" "$D/err" || fail "message does not name the file"
    run init "$D/none/new.yaml"; expect_rc 2 "init into a missing directory"
    cd "$D" && "$RB" init >/dev/null 2>&1 && [ -f case.yaml ] || fail "init default name"
    cd - >/dev/null
    run check "$D/case.yaml" --quiet
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "the starter case does not run (exit $rc)"
    no_temp_files "$D"
    echo "init: ok"
}

test_template() {
    mkdir -p "$D/tmpl"
    printf '{{verdict}} {{n_motions}}{{#motions}} {{name}}:{{usage_left:%%.3f}}{{/motions}}\n' \
        >"$D/tmpl/report.txt"
    RB_TEMPLATE_DIR=$D/tmpl
    export RB_TEMPLATE_DIR
    run check "$HARMONIC"
    grep -Eq '^(PASS|FAIL) 1 [^:]+:[0-9]+\.[0-9]{3}$' "$D/out" || fail "custom template"
    printf '{{verdict}} {{no_such_name}}\n' >"$D/tmpl/report.txt"
    run check "$HARMONIC" --json "$D/t.json"
    unset RB_TEMPLATE_DIR
    expect_rc 2 "template with an unknown name"
    grep -q "report.txt:1:13: error: no_such_name: unknown name" "$D/err" ||
        fail "template error position"
    [ -e "$D/t.json" ] && fail "output written despite the template error"
    echo "template: ok"
}

# Without anchorage some quantities do not exist: they are null, not NaN.
test_free_standing() {
    run check cases/free-standing.yaml --json "$D/f.json" --text "$D/f.txt"
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "exit code $rc"
    verdict_agrees "$D/f.json" "$D/f.txt"
    [ "$(jget "$D/f.json" derived.theta0_rad)" = null ] || fail "theta0 without bolts"
    [ "$(jget "$D/f.json" motions.0.result.peaks.max_bolt_force_over_fy.left)" = null ] ||
        fail "force / Fy without bolts"
    grep -q "max force / Fy                n/a        n/a" "$D/f.txt" || fail "n/a in text"
    echo "free-standing: ok (exit $rc)"
}

# A solver failure is exit 3, one diagnostic naming the motion, and no
# output. The tolerance of 1e-300 makes the integrator's step underflow at
# once; if the case loader ever rejects it, find another way to fail.
test_solver_error() {
    # A valid case the solver cannot finish: a square wave of +-50 g that
    # flips every sample (10 us) makes the cabinet chatter past the work
    # bound on transitions. (A tolerance of 1e-300 used to serve here; it
    # is now refused at the key, exit 2, before solving.)
    awk 'BEGIN { for (i = 0; i < 30000; i++) print (i % 2 ? -50 : 50) }' >"$D/square.txt"
    printf 'extends: %s/cases/base/reference-cabinet.yaml\nmotion:\n  type: record\n  file: square.txt\n  format: one-column\n  units: g\n  dt: 0.01 ms\n' \
        "$(pwd)" >"$D/tight.yaml"
    echo old >"$D/keep.json"
    run check "$D/tight.yaml" --json "$D/keep.json" --history "$D/h.csv"
    expect_rc 3 "solver failure"
    grep -q "^$D/tight.yaml: error: motion '[^']*': " "$D/err" || fail "solver diagnostic form"
    [ "$(cat "$D/keep.json")" = old ] || fail "output changed by a failed solve"
    [ -e "$D/h.csv" ] && fail "history written by a failed solve"
    [ -s "$D/out" ] && fail "stdout not empty after a failed solve"
    no_temp_files "$D"
    # the motions are solved side by side, but the error is the first
    # failing motion's alone, as if they were solved in order
    sq='type: record, file: square.txt, format: one-column, units: g, dt: 0.01 ms'
    printf 'extends: %s/cases/base/reference-cabinet.yaml\nmotions:\n  - {type: harmonic, name: calm, frequency: 2 Hz, amplitude: 0.01 A*, duration: 1 s}\n  - {%s, name: first}\n  - {%s, name: second}\n' \
        "$(pwd)" "$sq" "$sq" >"$D/two.yaml"
    run check "$D/two.yaml"
    expect_rc 3 "solver failure of two motions"
    [ "$(wc -l <"$D/err")" -eq 1 ] || fail "one diagnostic for two failing motions"
    grep -q "^$D/two.yaml: error: motion 'first': " "$D/err" || fail "the first failing motion named"
    echo "solver error: ok"
}

DESIGN=cases/reference-design.yaml

# `design`: the same verdict and exit code as `check`, the design results
# in both reports, one CSV per sweep (the relations the searches must obey
# are numbers.py's).
test_design() {
    run check "$DESIGN" --quiet
    check_rc=$rc
    run design "$DESIGN" --json "$D/d.json" --text "$D/d.txt" --sweep-csv "$D/sw.csv"
    expect_rc "$check_rc" "design (check exits $check_rc)"
    verdict_agrees "$D/d.json" "$D/d.txt"
    [ -f "$D/sw-1.csv" ] && [ -f "$D/sw-2.csv" ] || fail "sweep CSVs: $(ls "$D")"
    [ "$(wc -l <"$D/sw-1.csv")" -eq 20 ] || fail "frequency sweep CSV: 19 rows + header"
    [ "$(wc -l <"$D/sw-2.csv")" -eq 13 ] || fail "amplitude sweep CSV: 12 rows + header"
    grep -q "design factor, no yield" "$D/d.txt" || fail "design factor not in text"
    grep -q "^code-static  ASCE 7-22" "$D/d.txt" || fail "code-static not in text"
    grep -q "^frequency sweep 1" "$D/d.txt" || fail "frequency sweep not in text"
    no_temp_files "$D"
    echo "design: ok (exit $rc)"
}

# The searches give byte-identical reports on one thread, two and six.
test_design_threads() {
    run design "$DESIGN" -j 1 --json "$D/j1.json" --quiet
    rc1=$rc
    run design "$DESIGN" -j2 --json "$D/j2.json" --quiet
    [ "$rc" -eq "$rc1" ] || fail "exit codes differ: $rc1 and $rc"
    cmp -s "$D/j1.json" "$D/j2.json" || fail "reports differ between -j 1 and -j 2"
    # three searches side by side, two threads each
    run design "$DESIGN" -j 6 --json "$D/j6.json" --quiet
    cmp -s "$D/j1.json" "$D/j6.json" || fail "reports differ between -j 1 and -j 6"
    run design "$DESIGN" -j 0; expect_rc 2 "-j 0"
    run check "$DESIGN" -j 2; expect_rc 2 "-j on check"
    run check "$DESIGN" --sweep-csv "$D/x.csv"; expect_rc 2 "--sweep-csv on check"
    run design "$DESIGN" --sweep-csv /nonexistent-rockbolt-dir/s.csv
    expect_rc 2 "unwritable --sweep-csv"
    echo "design threads: ok"
}

# A case of several motions: the suite names the motion of largest demand
# and the mean and maximum agree with the per-motion results.
# --svg and --html: per motion its time history and, with bolts, its
# hysteresis, then one figure per sweep; the page holds the summary tables,
# every figure and the text report. (XML well-formedness and the browser
# render are the plot tests' business.)
test_figures() {
    run check "$HARMONIC" --svg "$D/h.svg" --quiet
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "exit code $rc"
    [ "$(grep -o '<path' "$D/h-1.svg" | wc -l)" -eq 9 ] || fail "9 series in h-1.svg"
    [ "$(grep -o '<path' "$D/h-2.svg" | wc -l)" -eq 3 ] || fail "3 loops in h-2.svg"
    grep -q "elongation" "$D/h-2.svg" || fail "h-2.svg is not the hysteresis"
    run design "$DESIGN" --svg "$D/f.svg" --html "$D/p.html" --text "$D/p.txt"
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "exit code $rc"
    for f in f-1.svg f-2.svg f-3.svg f-4.svg p.html; do [ -s "$D/$f" ] || fail "$f missing"; done
    [ -e "$D/f-5.svg" ] && fail "history, hysteresis and two sweeps make four figures"
    [ "$(grep -o '<svg' "$D/p.html" | wc -l)" -eq 4 ] || fail "four figures in the page"
    grep -q "design factor, no yield" "$D/p.html" || fail "text report not in the page"
    for w in "Verdict of each motion" "Peaks of each motion" "Cabinet and anchorage" \
        'name="viewport"' "@media print"; do
        grep -qF "$w" "$D/p.html" || fail "the page lacks '$w'"
    done
    run check "$HARMONIC" --svg "$D/same" --html "$D/same"; expect_rc 2 "--svg and --html on one file"
    # "-" is standard output: one figure goes there whole; several are
    # refused before any solving, nothing named "--1" written
    run check cases/free-standing.yaml --svg - --quiet
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "--svg - of one figure: exit code $rc"
    [ "$(head -c 4 "$D/out")" = "<svg" ] && [ "$(grep -c '</svg>' "$D/out")" -eq 1 ] ||
        fail "--svg - of one figure: not one SVG on stdout"
    (cd "$D" && "$RB" check "$OLDPWD/$HARMONIC" --svg - >out 2>err); rc=$?
    expect_rc 2 "check --svg - of two figures"
    grep -q "^-: error: --svg: this run writes 2 figures.*'-' takes one" "$D/err" ||
        fail "--svg - of two figures: no clear refusal"
    [ -s "$D/out" ] && fail "--svg - of two figures wrote to stdout"
    ls "$D" | grep -q -e '^--' && fail "--svg - wrote a numbered file"
    run design "$DESIGN" --sweep-csv - --quiet; expect_rc 2 "--sweep-csv - of two sweeps"
    grep -q "this run writes 2 sweep tables" "$D/err" || fail "--sweep-csv -: no clear refusal"
    no_temp_files "$D"
    echo "figures: ok"
}

# A synthetic motion's figure is titled with its whole description: the
# "/" of "z/h" is no directory (the title was "(record h 0.5, seed 1, ...)"),
# and only a table's file loses its directory.
test_titles() {
    mkdir -p "$D/spectra"
    printf 'f_hz,sa_g\n1,0.5\n50,0.5\n' >"$D/spectra/flat.csv"
    cat >"$D/syn.yaml" <<EOF
extends: $PWD/cases/base/reference-cabinet.yaml
name: EP-R1
motions:
  - {type: synthetic, spectrum: {type: ac156, sds: 1.0 g, z_over_h: 0.5}, seed: 1, duration: 8 s,
     components: horizontal}
  - {type: synthetic, spectrum: {type: table, file: spectra/flat.csv}, seed: 2, duration: 8 s}
EOF
    run check "$D/syn.yaml" --svg "$D/syn.svg" --quiet
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "exit code $rc"
    grep -q '>EP-R1 .* ac156 (synthetic: AC156 (2010) S_DS [^,]*, z/h 0.5, seed 1, motion 1)</text>' \
        "$D/syn-1.svg" || fail "AC156 title: $(grep -o 'bold">[^<]*' "$D/syn-1.svg" | head -1)"
    grep -q '>EP-R1 .* table (synthetic: table flat.csv, seed 2, motion 1)</text>' \
        "$D/syn-3.svg" || fail "table title: $(grep -o 'bold">[^<]*' "$D/syn-3.svg" | head -1)"
    echo "titles: ok"
}

# Output units: a case written in US customary units reports in kip, in,
# ksi, ft-lbf and g; output_units: si turns it back to kN, mm, MPa, J; each
# shown value is the SI one converted, to 1e-9 relative.
case "$T" in
    help|usage|harmonic|stdout|elcentro|unwritable|preserved|history|init|template|solver_error|free_standing|design|design_threads|figures|titles)
        "test_$T" ;;
    *) echo "unknown test $T"; exit 1 ;;
esac
rm -rf "$D"
exit 0
