#!/usr/bin/env python3
"""rockbolt fragility --sweep-gap end to end.

    python3 tests/fragility/sweep.py ROCKBOLT SCRATCH

Run from the source root. On a suite of two shipped records:
  - each point of the sweep is, to the last bit, `rockbolt fragility` on
    the case written with that gap_ratio: (one pipeline), and the JSON is
    the same on one thread and on two;
  - the CSV, the table on stdout and the figure hold every point: one
    curve per limit state and panel, a mark per fitted point, placed by
    its value, the medians on a log axis;
  - with --intensity sa each point is `fragility --intensity sa` on that
    case, to the last bit, and a rigid cabinet (no f0) is refused;
  - a bad range is refused before any search with one line naming
    --sweep-gap and the form it expects, exit 2 and nothing written; so
    are a gap the case's plate cannot take, a case without bolts and
    --x-scale, which the sweep's figure has no use for."""
import json, math, os, sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, failures, run, src, start, write  # noqa: E402

rb, scratch = start()
STATES = ["first-yield", "usage", "overturn", "lift-off"]


case = write("suite.yaml", f"""extends: {src}/cases/base/reference-cabinet.yaml
name: suite
motions:
  - {{type: record, name: elcentro, file: {src}/cases/records/elcentro_1940_ns.at2, format: at2, building: {{frequency: 5 Hz, damping: 5 %}}, peak: 0.3 A*, window: [0 s, 12 s]}}
  - {{type: record, name: taft, file: {src}/cases/records/taft_1952_s69e.txt, format: one-column, units: g, dt: 0.01 s, building: {{frequency: 5 Hz, damping: 5 %}}, peak: 0.3 A*, window: [0 s, 12 s]}}
design:
  scan_end: 0.6
""")
out = {k: os.path.join(scratch, "sweep." + k) for k in ("json", "csv", "svg", "html")}
r = run("fragility", case, "--sweep-gap", "0.005:0.015:0.005", "-j", "2", "--seed", "3",
        *[a for k, p in out.items() for a in ("--" + k, p)])
if r.returncode != 0:
    fail(f"exit {r.returncode}: {r.stderr.strip()[:300]}")
    sys.exit(1)
table = r.stdout
j1 = os.path.join(scratch, "j1.json")
r1 = run("fragility", case, "--sweep-gap", "0.005:0.015:0.005", "-j", "1", "--seed", "3",
         "--json", j1, "-q")
if r1.returncode or open(j1, "rb").read() != open(out["json"], "rb").read():
    fail("the sweep's JSON depends on the thread count")

sw = json.load(open(out["json"]))
ratios = [p["gap_ratio"] for p in sw["points"]]
if sw["format"] != "rockbolt-fragility-gap-sweep" or ratios != [0.005, 0.01, 0.015]:
    fail(f"format {sw['format']}, gap ratios {ratios}")

# each point: the fragility of the case with that gap ratio
for p in sw["points"]:
    c = write(f"gap-{p['gap_ratio']!r}.yaml",
              f"extends: {case}\nname: suite\ngap_ratio: {p['gap_ratio']!r}\n")
    fj = c[:-5] + ".json"
    r = run("fragility", c, "--seed", "3", "--json", fj, "-q")
    if r.returncode:
        fail(f"fragility at gap ratio {p['gap_ratio']}: exit {r.returncode}")
        continue
    f = json.load(open(fj))
    if p["limit_states"] != f["limit_states"] or p["runs"] != f["runs"] \
            or p["governing_limit_state"] != f["governing_limit_state"]:
        fail(f"gap ratio {p['gap_ratio']}: the sweep's point is not the fragility of the "
             f"case with that gap ratio")
    for key in ("g_mps2", "a_star_mps2", "level_mps2"):
        if sw[key] != f[key]:
            fail(f"{key}: sweep {sw[key]}, fragility {f[key]}")
# the gap matters: a sweep whose points were all one fragility would pass the above
# only if the case ignored its gap ratio
meds = [p["limit_states"][0].get("median_mps2") for p in sw["points"]]
if len(set(meds)) != len(meds):
    fail(f"the first-yield medians {meds} do not move with the gap ratio")

g = sw["g_mps2"]
rows = open(out["csv"]).read().splitlines()
if rows[0] != "gap_ratio,limit_state,fitted,median_g,beta,median_lo_g,median_hi_g," \
              "p_at_level,reached,governing" or len(rows) != 1 + 3 * 4:
    fail(f"the CSV: {len(rows)} lines, header {rows[0]}")
else:
    for line, (p, k) in zip(rows[1:], [(p, k) for p in sw["points"] for k in range(4)]):
        f = line.split(",")
        ls = p["limit_states"][k]
        if float(f[0]) != p["gap_ratio"] or f[1] != STATES[k] or f[2] != str(int(ls["fitted"])):
            fail(f"CSV row {line}")
        elif ls["fitted"] and (f[3] != "%.6g" % (ls["median_mps2"] / g)
                               or f[7] != "%.6g" % ls["p_at_level"]):
            fail(f"CSV row {line}: median or P is not the JSON's")
        elif f[9] != str(int(p["governing_limit_state"] == STATES[k])):
            fail(f"CSV row {line}: governing is not the JSON's {p['governing_limit_state']}")

lines = table.splitlines()
data = [l for l in lines if l.split()[:1] and l.split()[0] in ("0.005", "0.01", "0.015")]
if len(data) != 3 or "median g" not in table:
    fail(f"the table has {len(data)} rows of gap ratios")

# the figure: a curve per state and panel, a mark per fitted value where it belongs
NS = "{http://www.w3.org/2000/svg}"
root = ET.parse(out["svg"]).getroot()
paths = {p.get("data-series"): p for p in root.iter(NS + "path")}
want = {f"{s}_{w}" for s in STATES for w in ("p", "median")}
if set(paths) != want:
    fail(f"series {sorted(paths)}")
texts = [t.text for t in root.iter(NS + "text")]
if "median (g), log scale" not in texts or "gap ratio g0 / l (-)" not in texts:
    fail("the figure lacks its axis titles")
circles = [c for c in root.iter(NS + "circle")]
fitted = sum(ls["fitted"] for p in sw["points"] for ls in p["limit_states"])
if len(circles) != 2 * fitted:
    fail(f"{len(circles)} marks for {fitted} fitted points in two panels")
# within a state, a larger P sits higher in the top panel, a larger median
# higher in the bottom one (smaller y), and a larger gap ratio further right
for k, s in enumerate(STATES):
    marks = [(float(c.get("cx")), float(c.get("cy"))) for c in circles
             if c.get("data-limit-state") == s]
    pts = [p for p in sw["points"] if p["limit_states"][k]["fitted"]]
    top, bottom = marks[:len(marks) // 2], marks[len(marks) // 2:]
    for (x1, y1), (x2, y2), a, b in zip(top, top[1:], pts, pts[1:]):
        pa, pb = a["limit_states"][k]["p_at_level"], b["limit_states"][k]["p_at_level"]
        if not x2 > x1 or (abs(pa - pb) > 0.01 and (y2 < y1) != (pb > pa)):
            fail(f"{s}: the top panel's marks do not follow P")
    for (x1, y1), (x2, y2), a, b in zip(bottom, bottom[1:], pts, pts[1:]):
        ma, mb = a["limit_states"][k]["median_mps2"], b["limit_states"][k]["median_mps2"]
        if not x2 > x1 or (abs(ma / mb - 1) > 0.01 and (y2 < y1) != (mb > ma)):
            fail(f"{s}: the bottom panel's marks do not follow the median")
page = open(out["html"]).read()
if page.count("<svg") != 1 or "P(level)" not in page:
    fail("the page lacks the figure or the table")

# in Sa(f0): each point is `fragility --intensity sa` on the case with that
# gap ratio, to the last bit, and the outputs say which intensity they hold
sa_out = {k: os.path.join(scratch, "sa." + k) for k in ("json", "svg")}
r = run("fragility", case, "--sweep-gap", "0.005:0.015:0.005", "--intensity", "sa",
        "--seed", "3", "-q", *[a for k, p in sa_out.items() for a in ("--" + k, p)])
if r.returncode != 0:
    fail(f"--intensity sa: exit {r.returncode}: {r.stderr.strip()[:300]}")
else:
    ssw = json.load(open(sa_out["json"]))
    if ssw["intensity"] != "spectral_acceleration" or ssw.get("intensity_damping") != 0.05:
        fail(f"the Sa sweep's head: {ssw['intensity']}, {ssw.get('intensity_damping')}")
    if ssw["level_mps2"] == sw["level_mps2"]:
        fail("the Sa sweep's level is the peak floor acceleration's")
    for p in ssw["points"]:
        c = os.path.join(scratch, f"gap-{p['gap_ratio']!r}.yaml")
        fj = c[:-5] + ".sa.json"
        r = run("fragility", c, "--seed", "3", "--intensity", "sa", "--json", fj, "-q")
        if r.returncode:
            fail(f"fragility --intensity sa at gap ratio {p['gap_ratio']}: exit {r.returncode}")
            continue
        f = json.load(open(fj))
        if p["limit_states"] != f["limit_states"]:
            fail(f"gap ratio {p['gap_ratio']}: the Sa sweep's point is not the case's "
                 f"fragility in Sa")
        for key in ("level_mps2", "intensity_freq_hz"):
            if ssw[key] != f[key]:
                fail(f"Sa {key}: sweep {ssw[key]}, fragility {f[key]}")
    texts = [t.text for t in ET.parse(sa_out["svg"]).getroot().iter(NS + "text")]
    if "median Sa(f0) (g), log scale" not in texts:
        fail("the Sa sweep's figure does not say its medians are Sa(f0)")
rigid = write("rigid.yaml", f"extends: {case}\nequipment:\n  rigid: true\n")
r = run("fragility", rigid, "--sweep-gap", "0:0.01:0.005", "--intensity", "sa", "-q")
if r.returncode != 2 or "a rigid cabinet has none" not in r.stderr:
    fail(f"an Sa sweep of a rigid cabinet: exit {r.returncode}, {r.stderr.strip()[:200]}")

# bad input: exit 2, one line naming the option and the form, nothing written
FORM = ("needs FROM:TO:STEP, gap ratios of the lever arm with 0 <= FROM < TO <= 1 and "
        "STEP > 0, e.g. 0.002:0.03:0.002")
BAD = [
    (["--sweep-gap", "0.01"], f"rockbolt: error: option '--sweep-gap' {FORM} (got '0.01')"),
    (["--sweep-gap", "a:b:c"], f"rockbolt: error: option '--sweep-gap' {FORM} (got 'a:b:c')"),
    (["--sweep-gap", "0.02:0.01:0.001"],
     f"rockbolt: error: option '--sweep-gap' {FORM} (got '0.02:0.01:0.001')"),
    (["--sweep-gap", "0:0.03:0"], f"rockbolt: error: option '--sweep-gap' {FORM} (got '0:0.03:0')"),
    (["--sweep-gap", "0:0.03:-0.01"],
     f"rockbolt: error: option '--sweep-gap' {FORM} (got '0:0.03:-0.01')"),
    (["--sweep-gap", "-0.01:0.03:0.01"],
     f"rockbolt: error: option '--sweep-gap' {FORM} (got '-0.01:0.03:0.01')"),
    (["--sweep-gap", "0:2:0.1"], f"rockbolt: error: option '--sweep-gap' {FORM} (got '0:2:0.1')"),
    (["--sweep-gap", "nan:0.1:0.01"],
     f"rockbolt: error: option '--sweep-gap' {FORM} (got 'nan:0.1:0.01')"),
    (["--sweep-gap", "0:0.03:0.01:2"],
     f"rockbolt: error: option '--sweep-gap' {FORM} (got '0:0.03:0.01:2')"),
    (["--sweep-gap", "0:0.03:1e-5"], "rockbolt: error: option '--sweep-gap' gives 3001 gap "
     "ratios from 0 to 0.03 in steps of 1e-05; it takes 2 to 100 (each is a whole fragility)"),
    (["--sweep-gap", "0.01:0.02:0.05"], "rockbolt: error: option '--sweep-gap' gives 1 gap "
     "ratio from 0.01 to 0.02 in steps of 0.05; it takes 2 to 100 (each is a whole fragility)"),
    (["--sweep-gap", "0:0.01:0.005", "--sweep-gap", "0:0.02:0.01"],
     "rockbolt: error: option '--sweep-gap' given twice"),
    (["--sweep-gap"], "rockbolt: error: option '--sweep-gap' needs FROM:TO:STEP"),
    (["--sweep-gap", "0:0.01:0.005", "--x-scale", "linear"],
     "rockbolt: error: option '--x-scale' sets the intensity axis of the fragility figure; "
     "the figure of --sweep-gap has the gap ratio along x"),
    # the reference cabinet's plate tips over before a gap of 0.5 l closes
    (["--sweep-gap", "0.1:0.5:0.4"], f"{case}: error: --sweep-gap: invalid value: gap ratio "
     "0.5: the gap lets the plate rotate past the overturning angle alpha before it meets "
     "the bolts (gap 0.39 m)"),
]
for args, want in BAD:
    o = os.path.join(scratch, "bad.json")
    r = run("fragility", case, "--json", o, *args)
    got = r.stderr.splitlines()[0] if r.stderr else ""
    if r.returncode != 2 or got != want or os.path.exists(o):
        fail(f"{args}: exit {r.returncode}, written {os.path.exists(o)}\n  got:  {got}\n"
             f"  want: {want}")
free = write("free.yaml", f"extends: {src}/cases/base/reference-cabinet.yaml\nanchorage:\n"
             "  model: none\nmotion: {type: harmonic, amplitude: 0.5 g, frequency: 4 Hz, "
             "duration: 1 s}\n")
r = run("fragility", free, "--sweep-gap", "0:0.01:0.005")
if r.returncode != 2 or "a case without bolts has no gap to sweep" not in r.stderr:
    fail(f"a free-standing case: exit {r.returncode}, {r.stderr.strip()[:200]}")

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
