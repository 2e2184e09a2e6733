#!/usr/bin/env python3
"""rockbolt fragility end to end.

    python3 tests/fragility/fragility.py ROCKBOLT SCRATCH

Run from the source root. On a suite of two shipped records:
  - the JSON is the same, byte for byte, on one thread and on two;
  - each first-yield capacity is, to the search's resolution, the failing
    level of `rockbolt design`'s no-yield design factor search for that
    motion (the same scan; the fragility narrows the bracket by the row
    force's secant where design bisects);
  - a limit state every motion reaches is fitted by the closed form
    (mean and standard deviation over n of ln capacity);
  - a state no motion reaches within the scan is censored at the scan's
    end and not fitted; the CSV has a row per motion and state;
  - the figure's x axis is logarithmic unless --x-scale linear, and a bad
    --x-scale is refused (exit 2, nothing written);
  - a free-standing case is refused (exit 2) and writes nothing;
  - --intensity sa restates every capacity and the level as peak x
    Sa(f0) / peak, with Sa(f0) from `rockbolt spectrum` of the same case
    (another path to the same spectrum), and refits (the closed form where
    no motion is censored); a rigid cabinet refuses it, --sweep-gap takes it."""
import json, math, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, failures, run, src, start  # noqa: E402

rb, scratch = start()


def write_case(name, extra=""):
    p = os.path.join(scratch, name + ".yaml")
    with open(p, "w") as f:
        f.write(f"""extends: {src}/cases/base/reference-cabinet.yaml
name: {name}
motions:
  - {{type: record, name: elcentro, file: {src}/cases/records/elcentro_1940_ns.at2, format: at2, building: {{frequency: 5 Hz, damping: 5 %}}, peak: 0.3 A*, window: [0 s, 12 s]}}
  - {{type: record, name: taft, file: {src}/cases/records/taft_1952_s69e.txt, format: one-column, units: g, dt: 0.01 s, building: {{frequency: 5 Hz, damping: 5 %}}, peak: 0.3 A*, window: [0 s, 12 s]}}
{extra}""")
    return p


case = write_case("suite", "design:\n  scan_end: 0.6\n")
j1, j2 = os.path.join(scratch, "j1.json"), os.path.join(scratch, "j2.json")
csv = os.path.join(scratch, "f.csv")
html = os.path.join(scratch, "f.html")
svg_log, svg_lin = os.path.join(scratch, "log.svg"), os.path.join(scratch, "lin.svg")
r1 = run("fragility", case, "-j", "1", "--json", j1, "--csv", csv, "--html", html,
         "--svg", svg_log, "-q")
r2 = run("fragility", case, "-j", "2", "--json", j2, "--svg", svg_lin, "--x-scale", "linear",
         "-q")
if r1.returncode or r2.returncode:
    fail(f"exit {r1.returncode} / {r2.returncode}: {r1.stderr.strip()[:300]}")
    sys.exit(1)
if open(j1, "rb").read() != open(j2, "rb").read():
    fail("the JSON depends on the thread count")
fr = json.load(open(j1))
states = {s["limit_state"]: s for s in fr["limit_states"]}

# first yield: design's no-yield search, motion by motion
dj = os.path.join(scratch, "d.json")
r = run("design", case, "--json", dj, "-q")
if r.returncode not in (0, 1):
    fail(f"design: exit {r.returncode}: {r.stderr.strip()[:300]}")
else:
    d = json.load(open(dj))
    for m, dm in zip(fr["motions"], d["motions"]):
        df = dm["design"]["design_factor"]["no_yield"]
        want = df["fail_mps2"]
        # the fragility narrows its bracket by the row force's secant, the
        # design factor bisects: the same failing level to the resolution
        tol = df["resolution_astar"] * fr["a_star_mps2"] * (1 + 1e-9)
        if abs(m["capacity_mps2"]["first-yield"] - want) > tol:
            fail(f"{m['name']}: first-yield capacity {m['capacity_mps2']['first-yield']} "
                 f"is not design's failing level {want} to the resolution {tol}")

# a state every motion reaches: the closed form
for name, s in states.items():
    caps = [m["capacity_mps2"][name] for m in fr["motions"]]
    cens = [m["censored"][name] for m in fr["motions"]]
    if any(cens):
        continue
    if not s["fitted"]:
        fail(f"{name}: every motion reaches it, but it is not fitted")
        continue
    x = [math.log(c) for c in caps]
    mu = sum(x) / len(x)
    beta = math.sqrt(sum((v - mu) ** 2 for v in x) / len(x))
    if abs(s["median_mps2"] / math.exp(mu) - 1) > 1e-12 or abs(s["beta"] / beta - 1) > 1e-12:
        fail(f"{name}: fit {s['median_mps2']}, {s['beta']} is not the closed form "
             f"{math.exp(mu)}, {beta}")

# overturning is beyond a scan that ends at 0.6 A*: censored there, not fitted
top = 0.6 * fr["a_star_mps2"]
for m in fr["motions"]:
    if not m["censored"]["overturn"] or abs(m["capacity_mps2"]["overturn"] / top - 1) > 1e-9:
        fail(f"{m['name']}: overturning should be censored at the scan's end {top}")
if states["overturn"]["fitted"]:
    fail("overturn fitted with every motion censored")

page = open(html).read()
if page.count("<svg") != 1 or "first-yield" not in page or "median g" not in page:
    fail("the page lacks the figure or the table")

# the x axis: log by default, linear when asked; the same curves either way
log_svg, lin_svg = open(svg_log).read(), open(svg_lin).read()
if "peak floor acceleration (g), log scale" not in log_svg or "log scale" in lin_svg:
    fail("the figure's x axis is not log by default and linear with --x-scale linear")
if log_svg.count("<path") != lin_svg.count("<path") or "<path" not in log_svg:
    fail("the log and linear figures do not draw the same curves")
for bad, msg in ((["--x-scale", "ln"], "option '--x-scale' needs log or linear (got 'ln')"),
                 (["--x-scale", "log", "--x-scale", "linear"], "'--x-scale' given twice"),
                 (["--x-scale"], "option '--x-scale' needs log or linear")):
    out = os.path.join(scratch, "bad.svg")
    r = run("fragility", case, "--svg", out, *bad)
    if r.returncode != 2 or os.path.exists(out) or msg not in r.stderr:
        fail(f"{bad}: exit {r.returncode}, {r.stderr.strip()[:200]}")

rows = open(csv).read().splitlines()
if len(rows) != 1 + 2 * 4 or rows[0] != ("motion,limit_state,capacity_g,capacity_astar,"
                                         "censored,governing,confirmed,model_limited"):
    fail(f"the CSV has {len(rows)} lines: {rows[:2]}")
elif {r.split(",")[1] for r in rows[1:] if r.split(",")[5] == "1"} != \
        {fr["governing_limit_state"]}:
    fail(f"the CSV's governing rows are not the JSON's {fr['governing_limit_state']}")
else:
    # each row's flags: its state's confirmed, its motion's model_limited
    by_name = {m["name"]: m for m in fr["motions"]}
    confirmed = {s["limit_state"]: s["confirmed"] for s in fr["limit_states"]}
    for r in rows[1:]:
        f = r.split(",")
        want = (str(int(confirmed[f[1]])), str(int(by_name[f[0]]["model_limited"][f[1]])))
        if (f[6], f[7]) != want:
            fail(f"the CSV row {r}: confirmed, model_limited {f[6:8]}, the JSON's {want}")

# no concrete: no anchorage state; the governing state is the lowest fitted
# median of those its criteria (no-break) fail on: usage and overturn
if [s["limit_state"] for s in fr["limit_states"]] != \
        ["first-yield", "usage", "overturn", "lift-off"] \
        or fr["judged_limit_states"] != ["usage", "overturn"]:
    fail(f"limit states {[s['limit_state'] for s in fr['limit_states']]}, judged "
         f"{fr['judged_limit_states']}")
cands = [k for k in fr["judged_limit_states"] if states[k]["fitted"]]
want_g = min(cands, key=lambda k: states[k]["median_mps2"]) if cands else None
if fr["governing_limit_state"] != want_g:
    fail(f"governing {fr['governing_limit_state']}, the lowest median {want_g}")

# free-standing: refused, nothing written
fs = os.path.join(scratch, "free.yaml")
with open(fs, "w") as f:
    f.write(f"extends: {src}/cases/base/reference-cabinet.yaml\nanchorage:\n  model: none\n"
            "motion: {type: harmonic, amplitude: 0.5 g, frequency: 4 Hz, duration: 1 s}\n")
out = os.path.join(scratch, "free.json")
r = run("fragility", fs, "--json", out)
if r.returncode != 2 or os.path.exists(out) or "needs bolts" not in r.stderr:
    fail(f"a free-standing case: exit {r.returncode}, {r.stderr.strip()[:200]}")

# --intensity sa
small = write_case("sa", "design:\n  scan_end: 0.6\n")
pj, sj, spj = (os.path.join(scratch, n) for n in ("pfa.json", "sa.json", "spec.json"))
r1 = run("fragility", small, "--json", pj, "-q")
r2 = run("fragility", small, "--intensity", "sa", "--json", sj, "-q")
r3 = run("spectrum", small, "--from", "5 Hz", "--to", "10 Hz", "--per-octave", "1",
         "--json", spj, "-q")
if r1.returncode or r2.returncode or r3.returncode:
    fail(f"--intensity sa: exits {r1.returncode} {r2.returncode} {r3.returncode}: "
         f"{r2.stderr.strip()[:200]} {r3.stderr.strip()[:200]}")
else:
    pf, sf, sp = json.load(open(pj)), json.load(open(sj)), json.load(open(spj))
    if sf["intensity"] != "spectral_acceleration" or sf["intensity_freq_hz"] != 5.0:
        fail(f"sa intensity fields {sf.get('intensity')}, {sf.get('intensity_freq_hz')}")
    if sp["frequency_hz"][0] != 5.0:
        fail(f"spectrum grid starts at {sp['frequency_hz'][0]}")
    ratios = [m["psa_mps2"][0] / m["peak_mps2"] for m in sp["motions"]]
    if abs(sf["level_mps2"] / (pf["level_mps2"] * ratios[0]) - 1) > 1e-12:
        fail(f"sa level {sf['level_mps2']} against {pf['level_mps2'] * ratios[0]}")
    for mp, ms, rt in zip(pf["motions"], sf["motions"], ratios):
        if abs(ms["im_per_pfa"] / rt - 1) > 1e-12:
            fail(f"{ms['name']} Sa / peak {ms['im_per_pfa']} against the spectrum's {rt}")
        for k, v in mp["capacity_mps2"].items():
            if abs(ms["capacity_mps2"][k] / (v * rt) - 1) > 1e-12:
                fail(f"{ms['name']} {k}: sa capacity {ms['capacity_mps2'][k]} against "
                     f"{v * rt}")
    for ls in sf["limit_states"]:
        k = ls["limit_state"]
        caps = [m["capacity_mps2"][k] for m in sf["motions"]]
        if ls["fitted"] and not any(m["censored"][k] for m in sf["motions"]):
            mu = sum(math.log(c) for c in caps) / len(caps)
            if abs(ls["median_mps2"] / math.exp(mu) - 1) > 1e-12:
                fail(f"sa {k} median {ls['median_mps2']} against {math.exp(mu)}")
rigid = write_case("rigid", "equipment:\n  rigid: true\n")
r = run("fragility", rigid, "--intensity", "sa", "-q")
if r.returncode != 2 or "equipment.frequency" not in r.stderr:
    fail(f"sa on a rigid cabinet: exit {r.returncode}, {r.stderr.strip()[:200]}")
# with --sweep-gap too (sweep.py compares its points)
r = run("fragility", small, "--intensity", "sa", "--sweep-gap", "0.01:0.02:0.01", "-q")
if r.returncode != 0:
    fail(f"sa with --sweep-gap: exit {r.returncode}, {r.stderr.strip()[:200]}")

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
