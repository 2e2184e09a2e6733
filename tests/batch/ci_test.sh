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
. tests/expect.sh
need_python() { command -v python3 >/dev/null 2>&1 || { echo "python3 not found"; exit 77; }; }


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
encoding)
    need_python
    # a list saved by a spreadsheet in cp1252, and a case file whose name
    # is not UTF-8: every output stays valid UTF-8
    printf 'tag,mass\nPumpe-\326l-1,454 kg\nP-2,4\265 kg\nP-3,454 kg\n' >l.csv
    mkdir cases
    cp "$src/tests/batch/cases/a-pass.yaml" "cases/caf$(printf '\351').yaml"
    run 2 batch l.csv cases --base "$base" --json b.json --csv b.csv --junit b.xml
    valid_outputs .
    has err "^l.csv:2:7: error: encoding: byte 0xD6 is not UTF-8: the list is not UTF-8; save it as UTF-8 or pass --encoding cp1252"
    has err "^l.csv:3:6: error: encoding: byte 0xB5 is not UTF-8"
    has out 'Pumpe-\\xd6l-1 .*UNREADABLE'
    has out "P-3 .*pass"
    has b.json '"tag":.*"Pumpe-\\\\xd6l-1"'
    has b.json '"source":.*"cases/caf\\\\xe9.yaml"'
    # the JSON's \xHH reads back: merged shards are the same bytes
    for i in 1 2; do
        "$rb" batch l.csv cases --base "$base" -q --shard $i/2 --json s$i.json 2>/dev/null
    done
    run 2 merge s1.json s2.json --json m.json --csv m.csv --junit m.xml
    cmp -s b.json m.json && cmp -s b.csv m.csv && cmp -s b.xml m.xml \
        || fail "merged shards differ from the single run"
    # declared: transcoded, so the row runs under its own name
    mkdir dec && cp l.csv dec/
    (cd dec && "$rb" batch l.csv --base "$base" --encoding cp1252 \
        --json b.json --csv b.csv --junit b.xml >out 2>err)
    [ $? -eq 2 ] || fail "batch --encoding cp1252 did not exit 2"
    valid_outputs dec
    python3 - dec <<'PY' || fail "the cp1252 row was not transcoded"
import sys, json
j = json.load(open(sys.argv[1] + "/b.json", encoding="utf-8"))
c = {x["tag"]: x for x in j["cases"]}
assert c["Pumpe-\u00d6l-1"]["verdict"] == "pass", c.keys()
assert "\u00b5 kg" in c["P-2"]["error"]["message"], c["P-2"]["error"]
PY
    # UTF-16 (a spreadsheet's "Unicode text"), declared
    python3 -c "import sys; open('u16.csv','wb').write('tag;mass\nP-\u00e9;454 kg\n'.encode('utf-16'))"
    run 0 batch u16.csv --base "$base" --encoding utf-16 --quiet --json u16.json
    has u16.json "\"tag\":.*\"P-$(printf '\303\251')\""
    run 2 batch u16.csv --base "$base" --quiet
    has err "^u16.csv: error: list: the list holds NUL bytes.*--encoding utf-16"
    # a byte that is not a character of the declared encoding: its place
    printf 'tag,mass\nP-1,454 kg\nP-\201,454 kg\n' >bad.csv
    run 2 batch bad.csv --base "$base" --encoding cp1252 --quiet
    has err "^bad.csv:3:3: error: encoding: byte 0x81 is not a character of the encoding 'cp1252'"
    # an encoding iconv does not know is a usage error, before any work
    run 2 batch l.csv --base "$base" --encoding no-such-code --json never.json
    has err "unknown encoding 'no-such-code'"
    [ ! -e never.json ] || fail "an output was written after a usage error"
    ;;
separators)
    need_python
    # a European spreadsheet: semicolons, decimal commas inside quotes are
    # not separators, a byte-order mark, CRLF line ends
    printf '\357\273\277tag;mass;gap_ratio\r\n"P;1";454 kg;\r\nP-2; 454 kg ;0.01\r\n' >semi.csv
    run 0 batch semi.csv --base "$base" --json b.json --csv b.csv --junit b.xml
    valid_outputs .
    has out "P;1 .*pass"
    has out "P-2 .*pass"
    python3 - <<'PY' || fail "the semicolon list was not read as the comma list"
import json
j = json.load(open("b.json"))
assert [c["tag"] for c in j["cases"]] == ["P;1", "P-2"], j["cases"]
assert [c["line"] for c in j["cases"]] == [2, 3]
PY
    # the same list with commas gives the same results
    printf 'tag,mass,gap_ratio\n"P;1",454 kg,\nP-2,454 kg,0.01\n' >comma.csv
    run 0 batch comma.csv --base "$base" --json c.json
    python3 - <<'PY' || fail "semicolon and comma lists differ"
import json
a = json.load(open("b.json"))["cases"]
b = json.load(open("c.json"))["cases"]
for x, y in zip(a, b):
    assert x["runs"] == y["runs"] and x["tag"] == y["tag"], (x, y)
PY
    # a header with commas keeps semicolons inside fields
    printf 'tag,mass,description\nP-1,454 kg,pump; spare\n' >mixed.csv
    run 0 batch mixed.csv --base "$base" --quiet
    ;;
design_progress)
    # not a terminal: no progress at all, whatever the command prints
    case=$src/cases/reference-design.yaml
    run 1 design "$case" -j 2 --json plain.json
    [ ! -s err ] || { cat err >&2; fail "design wrote to stderr when it is not a terminal"; }
    cp out plain.txt
    # on a terminal (a pseudo-terminal made by script(1)): a line per search,
    # rewritten in place, then the time; the outputs are the same bytes
    command -v script >/dev/null 2>&1 || { echo "script(1) not found"; exit 77; }
    script -qec "'$rb' design '$case' -j 2 --json tty.json >tty.txt" /dev/null >tty.log 2>&1
    rc=$?
    [ -s tty.txt ] || { echo "script(1) could not run a pseudo-terminal here"; exit 77; }
    [ "$rc" -eq 1 ] || fail "design on a terminal exited $rc, expected 1"
    # the searches run side by side, so which one starts first depends on
    # the threads (a motion's, or the frequency sweep, which names no
    # motion): the count starts at 1 and each search is named
    has tty.log "design: search 1/6, [a-z0-9_.': ()]*, [0-9]*:[0-9][0-9] elapsed"
    for what in "design factor (no yield)" "design factor (no break)" "recommended gap" \
                "amplitude sweep" "frequency sweep"; do
        has tty.log "design: search [1-5]/6, [a-z0-9_.': ]*$what, [0-9]*:[0-9][0-9] elapsed"
    done
    has tty.log "design: search 6/6, code-static comparison"
    has tty.log "design: 6 searches in "
    cmp -s plain.txt tty.txt || fail "the text report differs on a terminal"
    cmp -s plain.json tty.json || fail "the JSON report differs on a terminal"
    # --quiet: nothing, on a terminal too
    script -qec "'$rb' design '$case' -j 2 --quiet --json quiet.json" /dev/null >quiet.log 2>&1
    lacks quiet.log "design:"
    cmp -s plain.json quiet.json || fail "the JSON report differs with --quiet"
    ;;
*)
    fail "unknown test '$t'"
    ;;
esac
exit 0
