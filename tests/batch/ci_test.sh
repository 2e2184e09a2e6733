#!/bin/sh
# ci_test.sh TEST ROCKBOLT SCRATCH: what a CI needs of batch and design,
# run from the source tree: JUnit names that survive an inserted row, lists
# in other encodings and separators giving valid UTF-8 outputs, progress on
# a terminal only. Exit 77 (skipped) where a tool it needs is missing.
set -u
t=$1
rb=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
s=$3
src=$(pwd)
rm -rf "$s"
mkdir -p "$s"
fail() { echo "FAIL: $*" >&2; exit 1; }
need_python() { command -v python3 >/dev/null 2>&1 || { echo "python3 not found"; exit 77; }; }

# run EXPECTED_RC ARGS...: rockbolt with stdout/stderr kept in $s
run() {
    want=$1
    shift
    "$rb" "$@" >"$s/out" 2>"$s/err"
    rc=$?
    [ "$rc" -eq "$want" ] || { cat "$s/err" >&2; fail "rockbolt $* exited $rc, expected $want"; }
}
has() { grep -q -- "$2" "$1" || fail "$1 lacks '$2'"; }
lacks() { ! grep -q -- "$2" "$1" || fail "$1 has '$2'"; }

# valid_outputs DIR: b.json is UTF-8 JSON, b.xml well-formed XML, b.csv UTF-8
valid_outputs() {
    python3 - "$1" <<'PY' || fail "an output of $1 is not valid UTF-8 JSON/XML/CSV"
import sys, json, xml.etree.ElementTree as ET
d = sys.argv[1]
json.loads(open(d + "/b.json", "rb").read().decode("utf-8"))
ET.parse(d + "/b.xml")
open(d + "/b.csv", "rb").read().decode("utf-8")
open(d + "/out", "rb").read().decode("utf-8")
open(d + "/err", "rb").read().decode("utf-8")
PY
}

base=$src/tests/batch/base/harmonic.yaml
cd "$s" || exit 1

case $t in
junit_names)
    need_python
    printf 'tag,mass,gap_ratio\nP-1,454 kg,\nP-2,,0.5\nP-3,454 kgs,\n' >a.csv
    printf 'tag,mass,gap_ratio\nP-0,,\nP-1,454 kg,\nP-new,,\nP-2,,0.5\nP-3,454 kgs,\n' >b.csv
    cp a.csv list.csv
    run 2 batch list.csv "$src/tests/batch/cases" --base "$base" --junit a.xml
    cp b.csv list.csv
    run 2 batch list.csv "$src/tests/batch/cases" --base "$base" --junit b.xml
    python3 - a.xml b.xml <<'PY' || fail "JUnit testcase names moved when a row was inserted"
import sys, xml.etree.ElementTree as ET
def cases(f):
    out = {}
    for c in ET.parse(f).getroot().findall("./testsuite/testcase"):
        key = (c.get("classname"), c.get("name"))
        assert key not in out, ("duplicate testcase", key)
        props = c.findall("./properties")
        assert len(props) <= 1, "one <properties> element"
        line = [p.get("value") for p in c.findall("./properties/property") if p.get("name") == "line"]
        out[key] = (line[0] if line else None, c)
    return out
a, b = cases(sys.argv[1]), cases(sys.argv[2])
assert set(a) <= set(b), ("a testcase was renamed", set(a) - set(b))
assert set(b) - set(a) == {("list.csv", "P-0"), ("list.csv", "P-new")}, set(b) - set(a)
for k in a:
    assert "line" not in k[1], k
# the source line is a property, and follows the row
assert a[("list.csv", "P-1")][0] == "2" and b[("list.csv", "P-1")][0] == "3"
assert a[("list.csv", "P-3")][0] == "4" and b[("list.csv", "P-3")][0] == "6"
# case files have no line; a warning property stays beside the line
assert all(v[0] is None for k, v in b.items() if k[0] != "list.csv")
PY
    ;;
*)
    fail "unknown test '$t'"
    ;;
esac
exit 0
