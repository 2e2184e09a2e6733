#!/bin/sh
# batch_test.sh TEST ROCKBOLT SCRATCH: one end-to-end test of the batch
# commands, run from the source tree. Fixtures: tests/batch/cases (a
# passing, a failing, a three-motion suite and an unreadable case) and
# tests/batch/list.csv (rows that pass, fail, or cannot be read).
set -u
t=$1
rb=$2
s=$3
rm -rf "$s"
mkdir -p "$s"
. tests/expect.sh
inputs="tests/batch/cases tests/batch/list.csv"

check_junit() {
    if command -v python3 >/dev/null 2>&1; then
        python3 - "$1" <<'PY' || fail "JUnit XML is not well formed or wrong"
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
assert root.tag == "testsuites", root.tag
cases = root.findall("./testsuite/testcase")
assert len(cases) == int(root.get("tests")), "tests count"
fails = sum(1 for c in cases if c.find("failure") is not None)
errs = sum(1 for c in cases if c.find("error") is not None)
assert fails == int(root.get("failures")), "failures count"
assert errs == int(root.get("errors")), "errors count"
PY
    else
        echo "python3 not found: JUnit well-formedness not checked"
    fi
}

case $t in
outputs)
    run 2 batch $inputs -j 2 --json "$s/b.json" --csv "$s/b.csv" --junit "$s/b.xml"
    # the table: every case, verdicts, the suite's mean and max
    has "$s/out" "a-pass .*pass"
    has "$s/out" "b-fail .*FAIL"
    has "$s/out" "\*strong .*FAIL"
    has "$s/out" "(mean)"
    has "$s/out" "(max) .*FAIL"
    has "$s/out" "P-104 .*UNREADABLE tests/batch/list.csv:6:26: equipment.mass: unknown unit 'kgs'"
    has "$s/out" "10 cases: 2 passed, 4 failed, 4 unreadable, 0 errors; 8 runs"
    # the diagnostics, compiler style
    has "$s/err" "^tests/batch/cases/d-broken.yaml:5:9: error: equipment.mass: missing unit"
    has "$s/err" "^tests/batch/list.csv:7:29: error: gap_ratio: the gap"
    has "$s/err" "^tests/batch/list.csv:8:1: error: row: the row has 4 fields"
    # no progress line when stderr is not a terminal
    lacks "$s/err" "cases, "
    # CSV: header, one row per case and motion, errors last column
    [ "$(head -1 "$s/b.csv")" = "index,source,line,tag,motion,governing,verdict,case_verdict,usage,shear_over_w,force_over_fy,theta_over_alpha,validity_warnings,anchor_mode,anchor_utilization,code_fp_n,code_fp_over_wp,code_tension_n,code_steel_ratio,code_anchor_utilization,governs,reason,error" ] \
        || fail "CSV header"
    [ "$(wc -l <"$s/b.csv")" -eq 13 ] || fail "CSV rows: $(wc -l <"$s/b.csv")"
    has "$s/b.csv" '^2,tests/batch/cases/c-suite.yaml,0,c-suite,strong,1,fail,fail,1,'
    has "$s/b.csv" '^2,tests/batch/cases/c-suite.yaml,0,c-suite,weak,0,pass,fail,'
    # a failing row's reason, in the CSV and under its line in the table
    has "$s/b.csv" '^2,tests/batch/cases/c-suite.yaml,0,c-suite,strong,1,fail,fail,.*,bolt break,a bolt row breaks at t = [0-9.]* s; rigid bolts: an elastic bolt would load the row to [0-9.]* Fy,$'
    has "$s/out" '^ *a bolt row breaks at t = [0-9.]* s; rigid bolts: an elastic bolt would load the row to [0-9.]* Fy$'
    has "$s/b.csv" '^6,tests/batch/list.csv,5,"P-103, spare",motion,1,fail,fail,'
    has "$s/b.csv" '^7,tests/batch/list.csv,6,P-104,,0,unreadable,unreadable,,,,,,,,,,,,,,,"tests/batch/list.csv:6:26: '
    # JSON: counts, governing motion, mean and max of the suite
    has "$s/b.json" '"format":	"rockbolt-batch"'
    has "$s/b.json" '"unreadable":	4'
    has "$s/b.json" '"governing_motion":	"strong"'
    lacks "$s/b.json" '"shard"'
    if command -v python3 >/dev/null 2>&1; then
        python3 - "$s/b.json" <<'PY' || fail "JSON summary content"
import json, sys
d = json.load(open(sys.argv[1]))
c = [x for x in d["cases"] if x["tag"] == "c-suite"][0]
u = [r["usage"] for r in c["runs"]]
assert abs(c["mean"]["usage"] - sum(u) / len(u)) < 1e-12
assert c["max"]["usage"] == max(u)
assert c["verdict"] == "fail" and c["governing_motion"] == "strong"
e = [x for x in d["cases"] if x["tag"] == "P-104"][0]
assert e["error"]["line"] == 6 and e["error"]["col"] == 26
assert e["error"]["key"] == "equipment.mass"
assert [x["index"] for x in d["cases"]] == list(range(10))
PY
    fi
    check_junit "$s/b.xml"
    has "$s/b.xml" '<testcase classname="tests/batch/cases/b-fail.yaml" name="b-fail">'
    has "$s/b.xml" '<error type="unreadable" message="tests/batch/list.csv:6:26: error: equipment.mass'
    lacks "$s/b.xml" 'time='
    ;;
determinism)
    run 2 batch $inputs -j 1 --json "$s/1.json" --csv "$s/1.csv" --junit "$s/1.xml" -q
    run 2 batch $inputs -j 2 --json "$s/2.json" --csv "$s/2.csv" --junit "$s/2.xml" -q
    for f in json csv xml; do
        cmp "$s/1.$f" "$s/2.$f" || fail "-j 1 and -j 2 differ in the $f summary"
    done
    [ ! -s "$s/out" ] || fail "--quiet printed on stdout"
    ;;
shards)
    run 2 batch $inputs --json "$s/all.json" --csv "$s/all.csv" --junit "$s/all.xml" -q
    for i in 1 2 3; do
        # a shard's exit code is its own cases' verdict
        "$rb" batch $inputs --shard $i/3 -j 2 -q --json "$s/s$i.json" 2>/dev/null
    done
    has "$s/s2.json" '"shard":	"2/3"'
    run 2 merge "$s/s3.json" "$s/s1.json" "$s/s2.json" -q \
        --json "$s/m.json" --csv "$s/m.csv" --junit "$s/m.xml"
    for f in json csv xml; do
        cmp "$s/all.$f" "$s/m.$f" || fail "merged shards differ from one run ($f)"
    done
    # contiguous shard sets only: a missing or repeated shard is refused
    run 2 merge "$s/s1.json" "$s/s2.json" --json "$s/bad.json"
    # cases counted from 1 in every message: shard 3 of 3 holds the 3rd
    has "$s/err" "error: merge: case 3 of 10 is in no summary: a shard is missing"
    [ ! -e "$s/bad.json" ] || fail "merge wrote an output after an error"
    run 2 merge "$s/s1.json" "$s/s1.json" "$s/s2.json" "$s/s3.json"
    # the summary is named by its file
    has "$s/err" "error: merge: case 1 is in more than one summary ('$s/s1.json')"
    ;;
errors)
    # exit codes: 0 all pass, 1 a failure, 2 an unreadable case wins over 1
    run 0 batch tests/batch/cases/a-pass.yaml -q
    run 1 batch tests/batch/cases/a-pass.yaml tests/batch/cases/b-fail.yaml -q
    run 2 batch tests/batch/cases/b-fail.yaml tests/batch/cases/d-broken.yaml -q
    # unknown columns are errors at the header, naming the column
    printf 'tag,base,masss\nX,../base/harmonic.yaml,1 kg\n' >"$s/bad-col.csv"
    run 2 batch "$s/bad-col.csv" --base tests/batch/base/harmonic.yaml
    has "$s/err" "bad-col.csv:1:10: error: header: unknown column 'masss'"
    # a list without a base column takes --base; an empty cell keeps the base
    printf 'tag,mass,gap_ratio\nQ-1,500 kg,\nQ-1,400 kg,0.01\n' >"$s/nobase.csv"
    run 2 batch "$s/nobase.csv" --base tests/batch/base/harmonic.yaml --json "$s/n.json"
    has "$s/err" "nobase.csv:3:1: error: tag: duplicate tag 'Q-1' (first given at line 2)"
    has "$s/n.json" '"tag":	"Q-1"'
    # a glob that matches nothing and a missing file are unreadable cases
    run 2 batch "tests/batch/nothing-*.yaml" tests/batch/cases/a-pass.yaml -q
    has "$s/err" "nothing-\*.yaml: error: case: no file matches the pattern"
    # an unknown shipped motion name
    printf 'tag,base,motion\nM-1,%s/tests/batch/base/harmonic.yaml,kobe\n' "$PWD" >"$s/motion.csv"
    run 2 batch "$s/motion.csv"
    has "$s/err" "motion.csv:2:.*: error: motion: unknown motion 'kobe'"
    ;;
usage)
    run 2 batch
    has "$s/err" "batch needs case files"
    run 2 batch tests/batch/cases --shard 4/3
    has "$s/err" "--shard: expected I/N"
    run 2 batch tests/batch/cases -j 0
    run 2 batch tests/batch/cases --frobnicate
    # output paths are checked before any work: nothing is written
    run 2 batch tests/batch/cases --json "$s/nodir/x.json" --csv "$s/x.csv"
    has "$s/err" "--json"
    [ ! -e "$s/x.csv" ] || fail "an output was written after a usage error"
    run 2 batch tests/batch/cases --base "$s/none.yaml"
    run 2 merge
    printf 'not json' >"$s/junk.json"
    run 2 merge "$s/junk.json"
    has "$s/err" "junk.json:1:1: error: summary: not JSON"
    : >"$s/empty.json"
    run 2 merge "$s/empty.json"
    has "$s/err" "empty.json:1:1: error: summary: the file is empty"
    ;;
reports)
    run 2 batch $inputs -q --reports "$s/rep"
    [ -f "$s/rep/0-a-pass.json" ] && [ -f "$s/rep/0-a-pass.txt" ] || { ls "$s/rep" >&2; fail "report names"; }
    [ -f "$s/rep/5-P-102.json" ] || fail "row report"
    [ -f "$s/rep/6-P-103__spare.txt" ] || fail "sanitised tag"
    [ ! -e "$s/rep/3-d-broken.json" ] || fail "a report for an unreadable case"
    [ "$(ls "$s/rep" | wc -l)" -eq 12 ] || fail "report count $(ls "$s/rep" | wc -l)"
    has "$s/rep/1-b-fail.txt" "FAIL"
    ;;
design)
    run 1 batch tests/batch/cases/a-pass.yaml tests/batch/cases/c-suite.yaml --design \
        -q --json "$s/d.json" --csv "$s/d.csv"
    has "$s/d.csv" "design_factor,design_factor_bound,gap_ratio,validity_warnings,anchor_mode,anchor_utilization,code_fp_n,code_fp_over_wp,code_tension_n,code_steel_ratio,code_anchor_utilization,governs,reason,error"
    has "$s/d.json" '"min_design_factor":'
    # the default range ends at design.max_gap, 6.35 mm / 0.78 m = 0.00814
    # for the reference cabinet, below gap_ratio_max 0.03
    has "$s/d.json" '"gap_ratio":	0.0025'
    run 1 batch tests/batch/cases/a-pass.yaml tests/batch/cases/c-suite.yaml --design \
        -q -j 1 --json "$s/d1.json"
    cmp "$s/d.json" "$s/d1.json" || fail "design summaries depend on -j"
    ;;
fragility)
    # the suite's fragility in every output; the unreadable case keeps its error
    run 2 batch tests/batch/cases/a-pass.yaml tests/batch/cases/c-suite.yaml \
        tests/batch/cases/d-broken.yaml --fragility --seed 5 \
        --json "$s/f.json" --csv "$s/f.csv" --junit "$s/f.xml"
    has "$s/out" "^ *\[first-yield\] *median [0-9.]* g, beta [0-9.]*, 90% [0-9.]* to [0-9.]* g; P [0-9.]* at [0-9.]* g; reached by 3 of 3"
    has "$s/out" "^ *\[overturn\] *not fitted; reached by 0 of 3"
    has "$s/out" "d-broken .*UNREADABLE"
    has "$s/f.csv" ",theta_over_alpha,fragility_intensity,fragility_intensity_freq_hz,fragility_level_g,fragility_first_yield_median_g,fragility_first_yield_beta,fragility_first_yield_median_lo_g,fragility_first_yield_median_hi_g,fragility_first_yield_p_at_level,fragility_first_yield_reached,fragility_first_yield_confirmed,fragility_first_yield_model_limited,fragility_usage_median_g,"
    has "$s/f.csv" ",fragility_lift_off_reached,fragility_lift_off_confirmed,fragility_lift_off_model_limited,fragility_anchorage_median_g,"
    has "$s/f.csv" ",fragility_anchorage_reached,fragility_anchorage_confirmed,fragility_anchorage_model_limited,fragility_governing,fragility_error,validity_warnings,"
    has "$s/f.json" '"seed":	"5"'
    has "$s/f.json" '"intensity":	"peak_floor_acceleration"'
    has "$s/f.json" '"limit_state":	"lift-off"'
    has "$s/f.xml" '<property name="fragility.usage.median_g" value="[0-9.]*"/>'
    has "$s/f.xml" '<property name="fragility.governing" value="[a-z-]*"/>'
    check_junit "$s/f.xml"
    if command -v python3 >/dev/null 2>&1; then
        python3 - "$s/f.csv" "$s/f.json" <<'PY' || fail "fragility columns"
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len({len(r) for r in rows}) == 1, "rows of different lengths"
suite = [r for r in rows if r["tag"] == "c-suite"]
assert len(suite) == 3 and len({r["fragility_usage_median_g"] for r in suite}) == 1
assert float(suite[0]["fragility_usage_median_g"]) > 0
assert suite[0]["fragility_intensity"] == "pfa" and suite[0]["fragility_intensity_freq_hz"] == ""
broken = [r for r in rows if r["tag"] == "d-broken"][0]
assert broken["fragility_level_g"] == "" and "missing unit" in broken["error"]
cases = {c["tag"]: c for c in json.load(open(sys.argv[2]))["cases"]}
assert "fragility" not in cases["d-broken"], "an unreadable case has a fragility"
f = cases["c-suite"]["fragility"]
assert [l["limit_state"] for l in f["limit_states"]] == \
    ["first-yield", "usage", "overturn", "lift-off"]
# no concrete: no anchorage state, its columns empty; the governing state
# named in the JSON and on every row of the CSV
assert all(r["fragility_anchorage_reached"] == "" for r in suite)
g = f["governing_limit_state"]
assert g in ("usage", "overturn", "first-yield"), g
assert {r["fragility_governing"] for r in suite} == {g.replace("-", "_")}
PY
    fi
    # the seed belongs to --fragility, and is a whole number
    run 2 batch tests/batch/cases/a-pass.yaml --seed 5 --json "$s/no.json"
    has "$s/err" "error: --seed: the seed of the fragility's bootstrap needs --fragility"
    [ ! -e "$s/no.json" ] || fail "a summary written after a usage error"
    run 2 batch tests/batch/cases/a-pass.yaml --fragility --seed -1 --json "$s/no.json"
    has "$s/err" "option '--seed' needs a whole number from 0 to 18446744073709551615 (got '-1')"
    [ ! -e "$s/no.json" ] || fail "a summary written after a usage error"
    # shards run with other seeds do not merge
    run 0 batch tests/batch/cases/a-pass.yaml tests/batch/cases/c-suite.yaml -q \
        --fragility --shard 1/2 --json "$s/s1.json"
    run 1 batch tests/batch/cases/a-pass.yaml tests/batch/cases/c-suite.yaml -q \
        --fragility --seed 1 --shard 2/2 --json "$s/s2.json"
    run 2 merge "$s/s1.json" "$s/s2.json" --json "$s/m.json"
    has "$s/err" "differ in --seed (1 and 0)"
    [ ! -e "$s/m.json" ] || fail "a merge written from shards of other seeds"
    # nor shards run in other intensities
    run 1 batch tests/batch/cases/a-pass.yaml tests/batch/cases/c-suite.yaml -q \
        --fragility --intensity sa --shard 2/2 --json "$s/s2.json"
    run 2 merge "$s/s1.json" "$s/s2.json" --json "$s/m.json"
    has "$s/err" "differ in --intensity"
    [ ! -e "$s/m.json" ] || fail "a merge written from shards of other intensities"
    # the intensity belongs to --fragility, and is pfa or sa
    run 2 batch tests/batch/cases/a-pass.yaml --intensity sa --json "$s/no.json"
    has "$s/err" "error: --intensity: the intensity of the fragility needs --fragility"
    run 2 batch tests/batch/cases/a-pass.yaml --fragility --intensity g --json "$s/no.json"
    has "$s/err" "option '--intensity' needs pfa or sa (got 'g')"
    [ ! -e "$s/no.json" ] || fail "a summary written after a usage error"
    # in Sa(f0) every output says so: the table, the CSV, the JSON, JUnit
    run 1 batch tests/batch/cases/c-suite.yaml --fragility --intensity sa \
        --json "$s/sa.json" --csv "$s/sa.csv" --junit "$s/sa.xml"
    has "$s/out" "^ *\[first-yield\] *Sa([0-9.]* Hz) median [0-9.]* g"
    has "$s/sa.csv" ",sa,[0-9.]*,[0-9.]*,"
    has "$s/sa.json" '"intensity":	"spectral_acceleration"'
    has "$s/sa.json" '"intensity_freq_hz":	[0-9.]*'
    has "$s/sa.xml" '<property name="fragility.intensity_freq_hz" value="[0-9.]*"/>'
    ;;
*)
    fail "unknown test $t"
    ;;
esac
exit 0
