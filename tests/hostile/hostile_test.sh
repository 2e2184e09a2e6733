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
. tests/expect.sh
base="$PWD/tests/batch/base/harmonic.yaml"
esc=$(printf '\033')
cr=$(printf '\r')

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
    has "$s/out" '^FAIL'
    has "$s/out" 'spoof\\x1b\[2K\\rPASS'
    has "$s/out" "motion 'm\\\\x1b\]0;title\\\\x07\\\\r'"
    has "$s/c.json" '"name":	"spoof\\u001b\[2K\\rPASS"'
    # the verdict line alone, with --text
    run 1 check "$s/c.yaml" --text "$s/c.txt"
    no_ctl "$s/out" "$s/c.txt"
    has "$s/out" "^FAIL.*motion 'm\\\\x1b"
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
format_chars)
    # U+FFFE in a tag (valid UTF-8, not an XML 1.0 character), bidi and
    # invisible format characters (RLO, isolates, zero width, line
    # separator), C1 controls (NEL, CSI) and a formula after a blank
    rlo=$(printf '\342\200\256'); fffe=$(printf '\357\277\276')
    nel=$(printf '\302\205'); csi=$(printf '\302\233')
    lri=$(printf '\342\201\246'); zw=$(printf '\342\200\213'); ls=$(printf '\342\200\250')
    {
        echo 'tag,base,amplitude'
        echo "PASS${rlo}LIAF,$base,0.9 A*"
        echo "i${lri}x${zw}y${ls}z,$base,"
        echo "\" =1+1\",$base,"
    } >"$s/l.csv"
    cat >"$s/c.yaml" <<YAML
extends: $base
name: "n\\u0085c\\u009b2J\\u202eR\\u2066\\ufffe"
motion:
  type: harmonic
  name: "m\\u202e\\ufffe"
  amplitude: 0.9 A*
  frequency: 4 Hz
  duration: 0.5 s
criteria: {kind: no-yield}
YAML
    run 1 batch "$s/l.csv" "$s/c.yaml" -q --junit "$s/b.xml" --csv "$s/b.csv" \
        --json "$s/b.json"
    run 1 batch "$s/l.csv" "$s/c.yaml"
    cp "$s/out" "$s/table.txt"
    run 1 check "$s/c.yaml" --html "$s/c.html" --svg "$s/c.svg" --text "$s/c.txt" \
        --json "$s/c.json"
    for f in b.xml b.csv table.txt c.html c-1.svg c-2.svg c.txt; do
        for ch in "$fffe" "$rlo" "$nel" "$csi" "$lri" "$zw" "$ls"; do
            ! LC_ALL=C grep -q "$ch" "$s/$f" || fail "$f holds a raw format or C1 character"
        done
    done
    has "$s/table.txt" 'PASS\\u202eLIAF'
    has "$s/b.xml" 'R\\u2066\\ufffe'
    has "$s/c.html" 'n\\u0085c\\u009b2J\\u202eR\\u2066\\ufffe'
    has "$s/c-1.svg" 'm\\u202e\\ufffe'
    has "$s/b.csv" ",\"' =1+1\","
    if command -v python3 >/dev/null 2>&1; then
        python3 - "$s" <<'PY' || fail "XML, CSV or JSON"
import csv, json, sys, xml.etree.ElementTree as E
s = sys.argv[1]
E.parse(s + "/b.xml")
E.parse(s + "/c-1.svg")
E.parse(s + "/c-2.svg")
tags = {c["tag"] for c in json.load(open(s + "/b.json", encoding="utf-8"))["cases"]}
# JSON keeps the text exact
name = "n\u0085c\u009b2J\u202eR\u2066\ufffe"
assert name in tags and "PASS\u202eLIAF" in tags, tags
assert json.load(open(s + "/c.json", encoding="utf-8"))["case"]["name"] == name
for r in csv.DictReader(open(s + "/b.csv", newline="", encoding="utf-8")):
    assert r["tag"].lstrip()[:1] not in "=+-@", r["tag"]
PY
    fi
    ;;
json_format_chars)
    # every bidirectional and invisible format character in a case name, a
    # motion name and a list tag: each JSON output holds it as a JSON
    # escape (\u202e), never raw, and reads back to the same text
    all='\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069\u200b\u200c\u200d\u200e\u200f\u2028\u2029\ufeff'
    cat >"$s/c.yaml" <<YAML
extends: $base
name: "c$all."
motion:
  type: harmonic
  name: "m$all."
  amplitude: 0.9 A*
  frequency: 4 Hz
  duration: 0.5 s
criteria: {kind: no-yield}
YAML
    # the second row's base is missing: its error object quotes the path
    python3 - "$s/l.csv" "$base" "$all" <<'PY' || fail "cannot write the list"
import sys
tag = "t" + sys.argv[3].encode().decode("unicode_escape") + "."
with open(sys.argv[1], "w", encoding="utf-8") as f:
    f.write('tag,base\n"%s",%s\n"u%s",missing%s.yaml\n' % (tag, sys.argv[2], tag[1:], tag))
PY
    run 1 check "$s/c.yaml" --json "$s/c.json"
    run 0 spectrum "$s/c.yaml" --json "$s/sp.json"
    run 2 batch "$s/l.csv" "$s/c.yaml" -q --json "$s/b.json"
    run 2 merge "$s/b.json" -q --json "$s/m.json"
    cmp "$s/b.json" "$s/m.json" || fail "merge's JSON differs from batch's"
    python3 - "$s" <<'PY' || fail "JSON outputs hold raw format characters"
import json, sys
s = sys.argv[1]
chars = [chr(c) for c in list(range(0x202a, 0x202f)) + list(range(0x2066, 0x206a))
         + list(range(0x200b, 0x2010)) + [0x2028, 0x2029, 0xfeff]]
def strings(v):
    if isinstance(v, dict):
        for x in v.values():
            yield from strings(x)
    elif isinstance(v, list):
        for x in v:
            yield from strings(x)
    elif isinstance(v, str):
        yield v
for f in ("c.json", "sp.json", "b.json", "m.json"):
    raw = open(s + "/" + f, "rb").read()
    for ch in chars:
        assert ch.encode() not in raw, (f, hex(ord(ch)), "raw")
        assert ("\\u%04x" % ord(ch)).encode() in raw, (f, hex(ord(ch)), "no escape")
    found = set(strings(json.loads(raw.decode("utf-8"))))
    for want in ("c", "m") + (("t", "u") if f in ("b.json", "m.json") else ()):
        text = want + "".join(chars) + "."
        assert text in found, (f, want, [x for x in found if x.startswith(want)])
    if f in ("b.json", "m.json"):
        errs = [c["error"] for c in json.loads(raw)["cases"] if c["error"]]
        assert len(errs) == 1 and "missing" in errs[0]["message"], errs
PY
    ;;
no_quote)
    # a system file named as a record, a YAML file of another kind named as
    # a base: refused at a line and column, none of their text quoted into
    # the terminal, JSON, CSV or JUnit
    printf 'root:x:0:0:root:/root:/bin/bash\nhunter2-secret\n' >"$s/passwd"
    printf 'apiVersion: v1\nkind: Secret\ndata:\n  password: hunter2-secret\n' >"$s/secret.yaml"
    # a duplicate key and an anchor, which the YAML walk meets before it can
    # tell the file is no case: refused, with none of the file's text
    printf 'apiVersion: v1\nkind: Secret\ndata:\n  password: hunter2-secret\n  password: hunter2-other\nmore: &hunter2anchor x\n' >"$s/secret2.yaml"
    printf 'extends: secret2.yaml\nname: ext2\n' >"$s/e2.yaml"
    cat >"$s/r.yaml" <<YAML
extends: $base
name: rec
motion: {type: record, file: passwd, format: auto, units: g, dt: 0.01 s}
YAML
    printf 'extends: secret.yaml\nname: ext\n' >"$s/e.yaml"
    run 2 check "$s/r.yaml"
    has "$s/err" 'r.yaml:3:.*motion.file: cannot read record'
    run 2 check "$s/e.yaml"
    has "$s/err" "e.yaml:1:10: error: extends: '.*secret.yaml' is not a rockbolt case"
    run 2 batch "$s/r.yaml" "$s/e.yaml" "$s/secret.yaml" "$s/e2.yaml" "$s/secret2.yaml" \
        --json "$s/b.json" --csv "$s/b.csv" --junit "$s/b.xml"
    for f in out err b.json b.csv b.xml; do
        for w in root:x /bin/bash hunter2 apiVersion password Secret; do
            lacks "$s/$f" "$w"
        done
    done
    has "$s/b.csv" 'secret.yaml:1:1: case: not a rockbolt case'
    # a file of another kind named as an equipment list
    cp "$s/passwd" "$s/passwd.csv"
    run 2 batch "$s/passwd.csv" --junit "$s/l.xml" --csv "$s/l.csv"
    has "$s/err" "passwd.csv:1:1: error: header: not an equipment list"
    for f in out err l.xml l.csv; do
        for w in root:x /bin/bash hunter2; do
            lacks "$s/$f" "$w"
        done
    done
    ;;
sandbox)
    # inputs confined to a tree: bases, records, lists and row bases
    in="$s/in"
    out=$(mktemp -d "${TMPDIR:-/tmp}/rb-sandbox-XXXXXX") || fail "mktemp"
    trap 'rm -rf "$out"' EXIT
    mkdir -p "$in"
    cp cases/base/reference-cabinet.yaml "$in/cab.yaml"
    cp cases/base/reference-cabinet.yaml "$out/cab.yaml"
    sed "s#^extends: .*#extends: cab.yaml#" "$base" >"$in/base.yaml"
    cp "$in/base.yaml" "$out/base.yaml"
    printf 'extends: base.yaml\nname: a\n' >"$in/a.yaml"
    run 0 check "$in/a.yaml" --sandbox "$in" -q
    # ../ out of the tree, an absolute path, a link that leads out
    printf 'extends: ../../../../../../../../../../../../..%s/base.yaml\nname: b\n' "$out" \
        >"$in/b.yaml"
    printf 'extends: %s/base.yaml\nname: b\n' "$out" >"$in/c.yaml"
    ln -s "$out/base.yaml" "$in/link.yaml"
    printf 'extends: link.yaml\nname: b\n' >"$in/d.yaml"
    for c in b c d; do
        run 2 check "$in/$c.yaml" --sandbox "$in"
        has "$s/err" "$c.yaml:1:10: error: extends: cannot use .* outside the sandbox"
    done
    run 0 check "$in/c.yaml" -q
    # a record outside (the shipped records are allowed)
    printf 'extends: base.yaml\nname: r\nmotion: {type: record, file: /etc/hostname, units: g, dt: 0.01 s}\n' \
        >"$in/r.yaml"
    run 2 check "$in/r.yaml" --sandbox "$in"
    has "$s/err" "r.yaml:3:.*: error: motion.file: .*outside the sandbox"
    # the case itself, and design
    run 2 design "$out/cab.yaml" --sandbox "$in"
    has "$s/err" "cab.yaml: error: case: .* lies outside the sandbox"
    # batch: the list's rows, each checked; a list outside; no default
    printf 'tag,base,motion\nX,%s/base.yaml,taft\nY,base.yaml,elcentro\n' "$out" >"$in/l.csv"
    cp "$in/l.csv" "$out/l.csv"
    run 2 batch "$in/l.csv" "$out/l.csv" "$in/b.yaml" --sandbox "$in" --csv "$s/b.csv" -q
    has "$s/b.csv" "^0,.*l.csv,2,X,.*unreadable.*l.csv:2:3: base: cannot use .*outside the sandbox"
    has "$s/b.csv" "^1,.*l.csv,3,Y,elcentro,1,"
    has "$s/b.csv" "^2,.*l.csv,0,.*unreadable.*the list lies outside the sandbox"
    has "$s/b.csv" "^3,.*b.yaml,0,b,.*unreadable.*outside the sandbox"
    run 0 batch "$in/b.yaml" -q
    run 2 batch "$in/a.yaml" --sandbox "$s/none"
    has "$s/err" "none: error: --sandbox: expected an existing directory"
    run 2 check "$in/a.yaml" --sandbox "$in/a.yaml"
    ;;
row_base_line)
    # a row's base that cannot be used is reported at the row's base cell,
    # also when the row overrides nothing (it had line 0 then)
    mkdir -p "$s/in"
    cp "$base" "$s/base.yaml"
    printf 'tag,base\nX,../base.yaml\nY,missing.yaml\n' >"$s/in/l.csv"
    run 2 batch "$s/in/l.csv" --sandbox "$s/in" --json "$s/r.json" -q
    has "$s/err" "l.csv:2:3: error: base: cannot use .*outside the sandbox"
    has "$s/err" "l.csv:3:3: error: base: cannot open .*missing.yaml"
    python3 - "$s/r.json" <<'PY' || fail "the JSON errors lack the rows' line and column"
import json, sys
cases = json.load(open(sys.argv[1]))["cases"]
assert [(c["error"]["line"], c["error"]["col"]) for c in cases] == [(2, 3), (3, 3)], cases
PY
    # with overrides, at the base's cell too; --base: the row's first column
    printf 'mass,tag,base\n400 kg,X,../base.yaml\n' >"$s/in/m.csv"
    run 2 batch "$s/in/m.csv" --sandbox "$s/in" -q
    has "$s/err" "m.csv:2:10: error: base: cannot use .*outside the sandbox"
    printf 'tag\nX\n' >"$s/in/n.csv"
    run 2 batch "$s/in/n.csv" --base "$s/base.yaml" --sandbox "$s/in" -q
    has "$s/err" "n.csv:2:1: error: base: cannot use .*outside the sandbox"
    ;;
merge_digest)
    # shards of one list merge; shards of two lists with as many rows, and
    # a shard whose verdict was edited by hand, are refused by name
    c="tests/batch/cases/a-pass.yaml tests/batch/cases/b-fail.yaml"
    "$rb" batch $c -q --shard 1/2 --json "$s/s1.json"
    "$rb" batch $c -q --shard 2/2 --json "$s/s2.json"
    has "$s/s1.json" '"inputs_digest":	"sha256:[0-9a-f]\{64\}"'
    has "$s/s1.json" '"digest":	"sha256:[0-9a-f]\{64\}"'
    run 1 merge "$s/s1.json" "$s/s2.json" --json "$s/m.json"
    run 1 batch $c -q --json "$s/all.json"
    cmp "$s/m.json" "$s/all.json" || fail "merged shards differ from one run"
    # merge reads a summary's cases in the list's order, as batch writes them
    python3 - "$s/all.json" "$s/rev.json" <<'PY' || fail "cannot reverse the summary"
import sys
t = open(sys.argv[1]).read()
head, rest = t.split('"cases":\t[', 1)
rows = rest[:rest.rindex("]")].split(', {\n\t\t\t"index"')
rows = [rows[0]] + ['{\n\t\t\t"index"' + r for r in rows[1:]]
assert len(rows) == 2
open(sys.argv[2], "w").write(head + '"cases":\t[' + ", ".join(rows[::-1]) + "]\n}\n")
PY
    run 2 merge "$s/rev.json"
    has "$s/err" "merge: case 1 of 2 is in no summary: .*not in the list's order"
    printf 'tag,base,mass\nA,%s,454 kg\nB,%s,454 kg\n' "$base" "$base" >"$s/l1.csv"
    printf 'tag,base,mass\nA,%s,454 kg\nB,%s,600 kg\n' "$base" "$base" >"$s/l2.csv"
    "$rb" batch "$s/l1.csv" -q --shard 1/2 --json "$s/l1-1.json"
    "$rb" batch "$s/l2.csv" -q --shard 2/2 --json "$s/l2-2.json"
    run 2 merge "$s/l1-1.json" "$s/l2-2.json" --json "$s/bad.json"
    has "$s/err" "l2-2.json: error: inputs_digest: this shard was run on other inputs than '.*l1-1.json'"
    [ ! -e "$s/bad.json" ] || fail "merge wrote an output after an error"
    # a FAIL turned into a PASS, a number changed
    sed 's/"verdict":	"fail"/"verdict":	"pass"/' "$s/s2.json" >"$s/e2.json"
    cmp -s "$s/s2.json" "$s/e2.json" && fail "the edit changed nothing"
    run 2 merge "$s/s1.json" "$s/e2.json"
    # at the case's line and column in the shard
    has "$s/err" "e2.json:[0-9]*:[0-9]*: error: digest: case 2 (tag 'b-fail') does not match its digest"
    sed 's/"usage":	0\.1/"usage":	0.2/' "$s/s1.json" >"$s/e1.json"
    cmp -s "$s/s1.json" "$s/e1.json" && fail "the usage edit changed nothing"
    run 2 merge "$s/e1.json" "$s/s2.json"
    has "$s/err" "e1.json:[0-9]*:[0-9]*: error: digest: case 1 (tag 'a-pass') does not match"
    ;;
*)
    fail "unknown test $t"
    ;;
esac
exit 0
