#!/bin/sh
# list_test.sh TEST ROCKBOLT SCRATCH: equipment lists whose columns are any
# case key (docs/batch.md, "Any case key as a column"), run from the
# source tree. Base: tests/batch/list/panel-us.yaml. The expected numbers
# are worked out here, in Python, from the published formulas (ASCE 7-22
# eq. 13.3-1 to 13.3-3 and 13.3.1.1-2, the UNC tensile stress area of
# ASME B1.1, the heavy hex nut of ASME B18.2.2), not from the tool.
set -u
t=$1
rb=$2
s=$3
rm -rf "$s"
mkdir -p "$s"
. tests/expect.sh
base=tests/batch/list/panel-us.yaml
command -v python3 >/dev/null 2>&1 || { echo "python3 not found"; exit 77; }

case $t in
columns)
    # 50 rows varying z/h, S_DS, f'c, embedment and diameter, units in the
    # header or in the cells
    python3 - "$s/list.csv" <<'PY' || fail "list not written"
import sys
zh = [0, 0.25, 0.5, 0.75, 1.0]
sds = [0.5, 0.8, 1.0, 1.5, 2.0]
fc = [3000, 4000, 5000]
hef = [4, 5, 6, 7, 8]
dia = ["0.5", "5/8", "0.75", "7/8", "1"]
with open(sys.argv[1], "w") as f:
    f.write("# roof panels, building C\n")
    f.write("tag,design.code.z_over_h,design.code.sds,concrete.strength [psi],"
            "embedment [in],diameter [in]\n")
    for i in range(50):
        e = hef[(i // 3) % 5]
        # every seventh row gives its own unit where the header has one
        cell = f"{e * 25.4:g} mm" if i % 7 == 3 else str(e)
        f.write(f"EP-{i + 1:02d},{zh[i % 5]},{sds[(i // 5) % 5]},{fc[i % 3]},{cell},"
                f"{dia[(i // 2) % 5]}\n")
PY
    run_rc() { "$rb" "$@" >"$s/out" 2>"$s/err"; echo $?; }
    rc=$(run_rc batch "$s/list.csv" --base "$base" -j 2 --json "$s/b.json" --csv "$s/b.csv" \
        --reports "$s/rep" -q)
    [ "$rc" -le 1 ] || { cat "$s/err" >&2; fail "batch exited $rc"; }
    python3 - "$s" <<'PY' || fail "per-row results"
import csv, glob, json, math, sys
s = sys.argv[1]
IN, LBF, PSI, G = 0.0254, 4.4482216152605, 6894.757293168361, 9.80665
# the list, read back as the test wrote it
rows = [r for r in csv.reader(open(s + "/list.csv")) if r and not r[0].startswith("#")][1:]
summary = json.load(open(s + "/b.json"))
cases = summary["cases"]
assert len(cases) == 50, len(cases)
def frac(x):
    a, _, b = x.partition("/")
    return float(a) / float(b) if b else float(a)
def unc_ase(d_in):
    tpi = {0.5: 13, 0.625: 11, 0.75: 10, 0.875: 9, 1.0: 8}[d_in]
    return 0.7854 * (d_in - 0.9743 / tpi) ** 2          # in^2, ASME B1.1
def heavy_hex_abrg(d_in):
    f = math.floor((1.5 * d_in + 0.125) * 16 + 1e-9) / 16  # B18.2.2 heavy hex nut
    return math.sqrt(3) / 2 * f * f - math.pi / 4 * d_in * d_in
W = 1200 * 0.45359237 * G                                  # N
h, b, l = 45 * IN, 18 * IN, 32 * IN                        # cm height, b, lever arm
reports = {json.load(open(p))["case"]["name"]: json.load(open(p))
           for p in glob.glob(s + "/rep/*.json") if not p.endswith("fragility.json")}
for k, (c, r) in enumerate(zip(cases, rows)):
    tag, zh, sds, fc, hef, dia = r
    assert c["tag"] == tag and c["line"] == k + 3, (c["tag"], c["line"])
    assert c["verdict"] in ("pass", "fail"), (tag, c.get("error"))
    zh, sds, fc, d = float(zh), float(sds), float(fc), frac(dia)
    hef = float(hef[:-3]) / 25.4 if hef.endswith("mm") else float(hef)
    # ASCE 7-22 13.3.1: Hf without Ta, Rmu, Car/Rpo, Ip; bounds 13.3-2, -3
    hf = 1 + 2.5 * zh
    rmu = max(1.3, math.sqrt(1.1 * 8 / (1.5 * 3)))
    fp = 0.4 * sds * 1.5 * W * (hf / rmu) * (1.0 / 1.5)
    fp = min(max(fp, 0.3 * sds * 1.5 * W), 1.6 * sds * 1.5 * W)
    # the far row's tension under Fp Omega0p at the centre of mass, less
    # (0.9 - 0.2 SDS) W about the plate edge
    tension = max(0.0, (2 * fp * h - (0.9 - 0.2 * sds) * W * b) / l)
    cs = c["code_static"]
    assert math.isclose(cs["fp_n"], fp, rel_tol=1e-9), (tag, cs["fp_n"], fp)
    assert math.isclose(cs["fp_over_wp"], fp / W, rel_tol=1e-9), tag
    assert math.isclose(cs["tension_n"], tension, rel_tol=1e-9, abs_tol=1e-9), tag
    a = reports[tag]["anchorage_check"]
    assert math.isclose(a["tensile_area_m2"], unc_ase(d) * IN * IN, rel_tol=1e-9), \
        (tag, a["tensile_area_m2"], unc_ase(d) * IN * IN)
    assert math.isclose(a["head_bearing_area_m2"], heavy_hex_abrg(d) * IN * IN,
                        rel_tol=1e-9), (tag, a["head_bearing_area_m2"])
    assert math.isclose(a["anchor_diameter_m"], d * IN, rel_tol=1e-12), tag
    assert math.isclose(a["inputs"]["strength_pa"], fc * PSI, rel_tol=1e-12), tag
    assert math.isclose(a["inputs"]["embedment_m"], hef * IN, rel_tol=1e-12), tag
    # steel in tension, 17.6.1.2: n A_se f_uta (58 ksi < 1.9 f_ya, 125 ksi)
    steel = [m for m in a["modes"] if m["mode"] == "steel-tension"][0]
    assert math.isclose(steel["nominal_n"], 2 * unc_ase(d) * 58000 * LBF, rel_tol=1e-9), \
        (tag, steel["nominal_n"])
# the CSV carries the same code-static numbers on every row of a case
for row in csv.DictReader(open(s + "/b.csv")):
    c = cases[int(row["index"])]["code_static"]
    assert math.isclose(float(row["code_fp_n"]), c["fp_n"], rel_tol=1e-5), row["tag"]
    assert math.isclose(float(row["code_tension_n"]), c["tension_n"], rel_tol=1e-5,
                        abs_tol=1e-3)
    assert row["code_anchor_utilization"] != "", row["tag"]
PY
    # the table shows the code-static line under each case
    "$rb" batch "$s/list.csv" --base "$base" -j 2 >"$s/table" 2>/dev/null
    [ "$(grep -c '\[code-static\] .* Fp [0-9.]* Wp; static tension of the far row [0-9.]* phi Nsa; 17.8 utilization [0-9.]*$' "$s/table")" -eq 50 ] \
        || fail "the table lacks a code-static line per case"
    ;;
multiline)
    # an Excel cell with line breaks (CRLF line ends, LF inside the cell)
    printf 'tag,description,mass [lb]\r\nEP-1,"Panel EP-1\nroof, north\nspare",1100\r\nEP-2,plain,1250\r\n"EP-3\nB","say ""hi""\n",oops\r\nEP-4,,1300\r\n' \
        >"$s/ml.csv"
    run 2 batch "$s/ml.csv" --base "$base" --json "$s/ml.json" -q
    python3 - "$s/ml.json" <<'PY' || fail "multi-line cells"
import json, sys
c = json.load(open(sys.argv[1]))["cases"]
assert [x["tag"] for x in c] == ["EP-1", "EP-2", "EP-3\nB", "EP-4"], [x["tag"] for x in c]
# each row is numbered by the line it starts on
assert [x["line"] for x in c] == [2, 5, 6, 9], [x["line"] for x in c]
assert [x["verdict"] in ("pass", "fail") for x in c] == [True, True, False, True]
# the bad cell after two multi-line cells: its own line (8) and column
e = c[2]["error"]
assert (e["line"], e["col"], e["key"]) == (8, 3, "equipment.mass"), e
PY
    # a quote never closed is an error at the quote, not a bogus row
    printf 'tag,description\nEP-1,"open\nEP-2,x\n' >"$s/open.csv"
    run 2 batch "$s/open.csv" --base "$base" --json "$s/open.json" -q
    has "$s/err" "open.csv:2:6: error: row: unterminated quoted field"
    python3 -c "import json,sys; c=json.load(open(sys.argv[1]))['cases']; assert len(c)==1, c" \
        "$s/open.json" || fail "rows after an unterminated quote"
    ;;
sizes)
    # a base that writes a 1/2 in bolt's tensile area
    sed 's/^  ultimate_stress: 58 ksi$/&\n  tensile_area: 0.1419 in^2/' "$base" >"$s/base-ase.yaml"
    grep -q "tensile_area" "$s/base-ase.yaml" || fail "fixture"
    printf 'tag,base,diameter,anchorage.tensile_area\nS-1,base-ase.yaml,0.5 in,\nS-2,base-ase.yaml,3/4 in,\nS-3,base-ase.yaml,3/8 in,\nS-4,base-ase.yaml,0.75 in,0.334 in^2\nS-5,base-ase.yaml,,\n' \
        >"$s/sz.csv"
    run 2 batch "$s/sz.csv" --json "$s/sz.json" --reports "$s/rep" -q
    # a row of another size is refused at its diameter cell, naming the
    # base's value; the base's value is not also judged against it
    has "$s/err" "sz.csv:3:19: error: anchorage.diameter: changes the bolt's size from the base's diameter 0.5 in, for which the base gives anchorage.tensile_area '0.1419 in^2' (.*base-ase.yaml:[0-9]*:3)"
    has "$s/err" "sz.csv:4:19: error: anchorage.diameter: changes the bolt's size"
    lacks "$s/err" "must not exceed the bolt's area"
    python3 - "$s" <<'PY' || fail "sizes"
import glob, json, math, sys
s = sys.argv[1]
c = json.load(open(s + "/sz.json"))["cases"]
assert [x["verdict"] in ("pass", "fail") for x in c] == [True, False, False, True, True], \
    [x["verdict"] for x in c]
rep = {json.load(open(p))["case"]["name"]: json.load(open(p))["anchorage_check"]
       for p in glob.glob(s + "/rep/*.json")}
IN2 = 0.0254 ** 2
assert math.isclose(rep["S-1"]["tensile_area_m2"], 0.1419 * IN2, rel_tol=1e-12)
assert math.isclose(rep["S-4"]["tensile_area_m2"], 0.334 * IN2, rel_tol=1e-12)
assert math.isclose(rep["S-5"]["tensile_area_m2"], 0.1419 * IN2, rel_tol=1e-12)
PY
    # the same rule for a case file that extends the base
    printf 'extends: base-ase.yaml\nanchorage:\n  diameter: 0.75 in\n' >"$s/child.yaml"
    run 2 check "$s/child.yaml"
    has "$s/err" "child.yaml:3:13: error: anchorage.diameter: changes the bolt's size from the base's diameter 0.5 in, for which the base gives anchorage.tensile_area '0.1419 in^2' (.*base-ase.yaml:[0-9]*:3): give this case's"
    ;;
errors)
    # a bad cell fails at its line and column, found here from the text
    printf 'tag,concrete.strength [psi],embedment [in]\nE-1,4000,5\nE-2,4000,5 inch\nE-3,4000,5\n' \
        >"$s/bad.csv"
    run 2 batch "$s/bad.csv" --base "$base" -q
    col=$(python3 -c "print(open('$s/bad.csv').read().splitlines()[2].index('5 inch') + 1)")
    has "$s/err" "bad.csv:3:$col: error: anchorage.embedment: unknown unit 'inch'"
    [ "$(grep -c error "$s/err")" -eq 1 ] || fail "other rows failed: $(cat "$s/err")"
    # a value of the base that a row's value makes wrong: at the row
    printf 'tag,concrete.thickness [in]\nT-1,4\n' >"$s/thin.csv"
    run 2 batch "$s/thin.csv" --base "$base" -q
    has "$s/err" "thin.csv:2:1: error: anchorage.embedment: must be less than the slab's thickness .*(the value at tests/batch/list/panel-us.yaml:25:14)"
    # header: a misspelt key with its nearest, a section, a list, a unit
    for h in 'concrete.strenght|unknown key .strenght. in .concrete. (did you mean .strength.?)' \
             'design.code|.design.code. is a section: name one of its keys, such as .design.code.edition.' \
             'motions|.motions. is a list, which one cell cannot give' \
             'embedment [inch]|unknown unit .inch.' \
             'mass,equipment.mass|duplicate column .equipment.mass.' \
             'mass [kilograms-of-a-very-long-unit-name]|expected a name and a unit in brackets' \
             'tag [in]|column .tag. takes no unit' \
             'anchorage.product.kc_cracked.x|.anchorage.product.kc_cracked. is a value, not a section' \
             'project.enginer|unknown key .enginer. in .project. (did you mean .engineer.?)' \
             'motion.vertical.frequncy|unknown key .frequncy. in .motion.vertical. (did you mean .frequency.?)'; do
        col=${h%%|*}
        printf 'tag,%s\nH-1,1\n' "$col" >"$s/h.csv"
        run 2 batch "$s/h.csv" --base "$base" -q
        has "$s/err" "h.csv:1:[0-9]*: error: header: .*${h#*|}"
    done
    # the sections the loader reads besides the motion's own: the cover
    # block and the vertical floor motion are columns like any other
    printf 'tag,project.engineer\nP-1,A. Engineer\n' >"$s/p.csv"
    "$rb" batch "$s/p.csv" --base "$base" -q >"$s/out" 2>"$s/err"
    [ $? -le 1 ] || fail "project.engineer refused: $(cat "$s/err")"
    ;;
*)
    fail "unknown test $t"
    ;;
esac
exit 0
