#!/bin/sh
# hostile_test.sh TEST ROCKBOLT SCRATCH: one end-to-end test of what text
# and files from hostile inputs may do to rockbolt's outputs
# (docs/robustness.md). Run from the source tree; fixtures are made in
# SCRATCH from tests/batch/base/harmonic.yaml.
set -u
t=$1
rb=$2
s=$3
rm -rf "$s"
mkdir -p "$s"
fail() { echo "FAIL: $*" >&2; exit 1; }
base="$PWD/tests/batch/base/harmonic.yaml"
esc=$(printf '\033')
cr=$(printf '\r')

run() {
    want=$1
    shift
    "$rb" "$@" >"$s/out" 2>"$s/err"
    rc=$?
    [ "$rc" -eq "$want" ] || { cat "$s/err" >&2; fail "rockbolt $* exited $rc, expected $want"; }
}
has() { grep -q -- "$2" "$1" || fail "$1 lacks '$2'"; }
lacks() { ! grep -q -- "$2" "$1" || fail "$1 has '$2'"; }
# no ESC and no carriage return in a file
no_ctl() {
    for f in "$@"; do
        ! LC_ALL=C grep -q "[$esc$cr]" "$f" || fail "$f holds a raw ESC or CR"
    done
}

case $t in
csv_formula)
    # tags and motion names that a spreadsheet would run as formulas
    {
        echo 'tag,base,amplitude'
        echo "\"=HYPERLINK(\"\"http://x.example/\"\",\"\"y\"\")\",$base,"
        echo "+SUM(1),$base,0.2 A*"
        echo "-2+3,$base,"
        echo "@cmd,$base,"
    } >"$s/l.csv"
    cat >"$s/c.yaml" <<YAML
extends: $base
name: "=1+2"
motion:
  type: harmonic
  name: "-cmd|' /C calc'!A0"
  amplitude: 0.3 A*
  frequency: 4 Hz
  duration: 0.5 s
YAML
    printf 'extends: %s\nname: "\\t=tab"\n' "$base" >"$s/d.yaml"
    printf 'extends: %s\nequipment: {mass: -3 kg}\n' "$base" >"$s/=e.yaml"
    run 2 batch "$s/l.csv" "$s/c.yaml" "$s/d.yaml" "$s/=e.yaml" -q --csv "$s/b.csv" \
        --json "$s/b.json"
    has "$s/b.csv" ",\"'=HYPERLINK(\"\"http://x.example/\"\",\"\"y\"\")\","
    has "$s/b.csv" ",\"'+SUM(1)\","
    has "$s/b.csv" ",\"'-2+3\","
    has "$s/b.csv" ",\"'@cmd\","
    has "$s/b.csv" ",\"'=1+2\",\"'-cmd|' /C calc'!A0\","
    has "$s/b.csv" ",\"'\\\\t=tab\","
    # merge renders through the same writer
    run 2 merge "$s/b.json" -q --csv "$s/m.csv"
    cmp "$s/b.csv" "$s/m.csv" || fail "merge's CSV differs from batch's"
    if command -v python3 >/dev/null 2>&1; then
        python3 - "$s/b.csv" <<'PY' || fail "CSV cells"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
assert len(rows) == 7, len(rows)
for r in rows:
    for k in ("tag", "motion", "source", "error"):
        assert r[k][:1] not in "=+-@\t\r" or r[k] == "", (k, r[k])
    # numeric columns stay numbers, negative ones included
    for k in ("index", "line", "governing"):
        int(r[k])
    if r["case_verdict"] in ("pass", "fail"):
        for k in ("usage", "shear_over_w", "force_over_fy", "theta_over_alpha"):
            float(r[k])
PY
    fi
    ;;
control_chars)
    # YAML escapes put ESC and CR in names: "erase the line, print PASS"
    cat >"$s/c.yaml" <<YAML
extends: $base
name: "spoof\\e[2K\\rPASS"
motion:
  type: harmonic
  name: "m\\e]0;title\\a\\r"
  amplitude: 0.9 A*
  frequency: 4 Hz
  duration: 0.5 s
criteria: {kind: no-yield}
YAML
    run 1 check "$s/c.yaml" --json "$s/c.json" --html "$s/c.html" --svg "$s/c.svg"
    no_ctl "$s/out" "$s/c.json" "$s/c.html" "$s/c.svg"
    has "$s/out" '^FAIL: '
    has "$s/out" 'spoof\\x1b\[2K\\rPASS'
    has "$s/out" "motion 'm\\\\x1b\]0;title\\\\x07\\\\r'"
    has "$s/c.json" '"name":	"spoof\\u001b\[2K\\rPASS"'
    # the verdict line alone, with --text
    run 1 check "$s/c.yaml" --text "$s/c.txt"
    no_ctl "$s/out" "$s/c.txt"
    has "$s/out" "^FAIL: motion 'm\\\\x1b"
    # diagnostics on stderr quote the value escaped
    printf 'extends: %s\nname: x\nmotion: {type: "sine\\e[32m\\rPASS"}\n' "$base" >"$s/d.yaml"
    run 2 check "$s/d.yaml"
    no_ctl "$s/err"
    has "$s/err" "found 'sine\\\\x1b\\[32m\\\\rPASS'"
    # batch: table, diagnostics, JUnit (well-formed XML 1.0), CSV, JSON
    run 2 batch "$s/c.yaml" "$s/d.yaml" --csv "$s/b.csv" --junit "$s/b.xml" --json "$s/b.json"
    no_ctl "$s/out" "$s/err" "$s/b.csv" "$s/b.xml" "$s/b.json"
    has "$s/out" 'spoof\\x1b\[2K\\rP'
    has "$s/b.xml" 'name="spoof\\x1b\[2K\\rPASS"'
    if command -v python3 >/dev/null 2>&1; then
        python3 -c 'import sys, xml.etree.ElementTree as E; E.parse(sys.argv[1])' "$s/b.xml" \
            || fail "JUnit is not well-formed XML"
    fi
    ;;
*)
    fail "unknown test $t"
    ;;
esac
exit 0
