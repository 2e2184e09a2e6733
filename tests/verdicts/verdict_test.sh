#!/bin/sh
# The verdict of a run, end to end: one judge for check, design and batch,
# and the model's validity checks beside it (docs/solver.md, Validity).
#
#   sh tests/verdicts/verdict_test.sh TEST ROCKBOLT JSONGET SCRATCH_DIR
#
# Run from the source root (ctest does). Exit 0 pass, 1 fail.
set -u
T=$1 RB=$2 JG=$3 D=$4
rm -rf "$D" && mkdir -p "$D" || exit 1
C=tests/verdicts/cases

fail() {
    echo "FAIL [$T]: $*"
    for f in "$D/out" "$D/err"; do [ -f "$f" ] && { echo "--- $f"; head -20 "$f"; }; done
    exit 1
}
run() { "$RB" "$@" >"$D/out" 2>"$D/err"; rc=$?; }
expect_rc() { [ "$rc" -eq "$1" ] || fail "exit code $rc, expected $1 ($2)"; }
jget() { "$JG" "$1" "$2" || fail "no value at $2 in $1"; }
first_line() { head -1 "$D/out"; }

case $T in
no_yield)
    # Bolts that never yield in the model, judged by "no yield": the row
    # force passes Fy, so check, design and batch all fail the case.
    run check $C/no-yield-nonyielding.yaml --json "$D/c.json"
    expect_rc 1 check
    first_line | grep -q '^FAIL.*a bolt row force reaches Fy (max force / Fy = 1\.[0-9]*; criterion: no yield)' ||
        fail "check's verdict: $(first_line)"
    [ "$(jget "$D/c.json" verdict.result)" = FAIL ] || fail "JSON verdict"
    check_line=$(first_line)
    run design $C/no-yield-nonyielding.yaml --quiet
    expect_rc 1 design
    run design $C/no-yield-nonyielding.yaml
    [ "$(first_line)" = "$check_line" ] || fail "design says '$(first_line)', check '$check_line'"
    run batch $C/no-yield-nonyielding.yaml --json "$D/b.json" --quiet
    expect_rc 1 batch
    grep -q '"verdict":	"fail"' "$D/b.json" || fail "batch verdict"
    echo "no_yield: ok ($check_line)"
    ;;
validity)
    # The reference case fails its criterion and says which assumptions
    # failed too; a passing case with warnings passes with them named, and
    # fails under "validity: fail".
    run check cases/reference-elcentro.yaml --json "$D/r.json"
    expect_rc 1 reference
    first_line | grep -q '^FAIL (2 validity warnings: lift-off, bolt impact): ' ||
        fail "reference verdict line: $(first_line)"
    [ "$(jget "$D/r.json" 'motions.0.validity.lift_off.status')" = warning ] || fail "lift-off status"
    [ "$(jget "$D/r.json" 'motions.0.validity.sliding.status')" = not-checked ] || fail "sliding status"
    [ "$(jget "$D/r.json" 'motions.0.validity.bolt_impact.status')" = warning ] || fail "impact status"
    grep -q 'lift-off             warning: least vertical floor reaction -' "$D/out" ||
        fail "text report lacks the lift-off line"
    run check $C/validity-warn.yaml --json "$D/w.json"
    expect_rc 0 "warnings only"
    first_line | grep -q '^PASS (2 validity warnings: lift-off, bolt impact): ' ||
        fail "warn verdict line: $(first_line)"
    [ "$(jget "$D/w.json" verdict.headline)" = "PASS (2 validity warnings: lift-off, bolt impact)" ] ||
        fail "JSON headline"
    run check $C/validity-fail.yaml
    expect_rc 1 "validity: fail"
    first_line | grep -q '^FAIL (2 validity warnings: lift-off, bolt impact): .*(criteria: validity: fail)' ||
        fail "fail verdict line: $(first_line)"
    # a friction coefficient makes sliding a check, ok or warning
    run check $C/sliding.yaml --json "$D/s.json" --quiet
    [ "$(jget "$D/s.json" 'motions.0.validity.sliding.status')" = warning ] || fail "mu 0.2"
    sed 's/friction_coefficient: 0.2/friction_coefficient: 50/' $C/sliding.yaml >$C/.sliding-50.yaml
    run check $C/.sliding-50.yaml --json "$D/s50.json" --quiet
    rm -f $C/.sliding-50.yaml
    [ "$(jget "$D/s50.json" 'motions.0.validity.sliding.status')" = ok ] || fail "mu 50"
    # the batch summary, CSV and JUnit carry the warnings
    run batch $C/validity-warn.yaml $C/validity-fail.yaml --json "$D/b.json" --csv "$D/b.csv" \
        --junit "$D/b.xml" --quiet
    expect_rc 1 batch
    grep -q '"validity_warnings":	\["lift-off", "bolt impact"\]' "$D/b.json" ||
        fail "batch JSON lacks the warnings"
    grep -q ',lift-off; bolt impact,' "$D/b.csv" || fail "batch CSV lacks the warnings"
    grep -q '<property name="validity_warnings" value="lift-off; bolt impact"/>' "$D/b.xml" ||
        fail "JUnit lacks the warnings"
    grep -q '<system-out>PASS (2 validity warnings: lift-off, bolt impact)</system-out>' "$D/b.xml" ||
        fail "JUnit lacks the headline"
    echo "validity: ok"
    ;;
*)
    fail "unknown test"
    ;;
esac
