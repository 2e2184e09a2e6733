#!/usr/bin/env python3
"""The anchorage limit state of a fragility, over random cases with concrete.

    python3 tests/fragility/anchorage.py ROCKBOLT SCRATCH [N] [SEED]

Run from the source root. Draws N (default 10) random cases whose
anchorage is cast in concrete (bolts, gap, slab, edge distances, the
17.10.5.3 route, the criterion and the bolt model drawn; two record
windows through a building each) and asserts that
  - `fragility --json` has the anchorage limit state, with a capacity and
    a censored flag for every motion;
  - each motion's anchorage capacity is, to the search resolution
    (design.resolution in A*), the level at which `design` finds that
    motion's anchorage failing: wherever a design factor's failing end
    fails on the anchorage (the 17.8 utilization reaching 1 or the route
    of 17.10.5.3 not met), its failing level and the capacity are at most
    one resolution apart; at least a third of the motions must be
    compared, so that the property cannot hold by comparing nothing;
  - `check` of the case with the motion's peak set to a compared
    capacity reports the anchorage failing there: a 17.8 utilization of
    at least 1, or a route reason;
  - the governing limit state is, among those the case's criteria fail
    on (worked out here from the case: overturn, first-yield or usage,
    the anchorage), the fitted one of the lowest median; the CSV marks
    its rows and no others;
  - the P-58 row's LS1 is the lower of the usage and anchorage medians;
  - `batch --fragility` on the cases gives each its anchorage limit state
    and governing state with the fragility's doubles, and merge of two
    shards reads them back to the same summary.
With `criteria: concrete: false` the state is there but neither judged
nor governing. And on a case without `concrete:` the fragility has no
anchorage limit state anywhere (JSON, CSV, table). The seed is printed so that a
failure can be replayed."""
import csv, json, math, os, random, re, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, failures, run, src, start  # noqa: E402

rb, scratch = start()
n = int(sys.argv[3]) if len(sys.argv) > 3 else 10
seed = int(sys.argv[4]) if len(sys.argv) > 4 else 20261127
rng = random.Random(seed)
print(f"seed {seed}, {n} cases")

# 1/2, 5/8 and 3/4 in bolts: diameter and tensile stress area (ASME B1.1)
BOLTS = [(0.5, 0.142), (0.625, 0.226), (0.75, 0.334)]
# F1554 grades 36 and 55: f_ya, f_uta (ksi)
GRADES = [(36, 58), (55, 75)]


def u(a, b):
    return rng.uniform(a, b)


def record(name, t0):
    if name == "elcentro":
        head = (f"{{type: record, name: m-{name}, file: {src}/cases/records/"
                "elcentro_1940_ns.at2, format: at2")
    else:
        head = (f"{{type: record, name: m-{name}, file: {src}/cases/records/"
                "taft_1952_s69e.txt, format: one-column, units: g, dt: 0.01 s")
    return (f"  - {head}, building: {{frequency: {u(2, 8):.3g} Hz, damping: 5 %}}, "
            f"peak: 0.3 g, window: [{t0:.2f} s, {t0 + u(4, 8):.2f} s]}}\n")


def draw(i):
    d, ase = rng.choice(BOLTS)
    fy, fu = rng.choice(GRADES)
    per_row = rng.choice([1, 2, 2, 3])
    hef = u(3, 6)
    route = rng.choice(["auto", "auto", "ductile", "attachment"])
    model = rng.choice(["", "", "  model: rigid-plastic\n"])
    text = f"""name: a{i:02d}
equipment:
  mass: {u(400, 2500):.4g} lb
  height: {u(50, 100):.4g} in
  base_width: {u(24, 48):.4g} in
  frequency: {u(4, 15):.3g} Hz
  damping: 5 %
anchorage:
{model}  bolts_per_row: {per_row}
  diameter: {d} in
  yield_stress: {fy} ksi
  ultimate_stress: {fu} ksi
  tensile_area: {ase} in^2
  toughness: 12000 in-lb/in^3
  deformable_length: {u(3, 8):.3g} in
  edge_distance: {u(2, 4):.3g} in
  type: cast-in-headed
  embedment: {hef:.3g} in
{"  spacing: %.3g in" % u(6, 14) if per_row > 1 else ""}
gap: {rng.choice(["0 in", "%.3g in" % u(0.02, 0.25)])}
criteria:
  kind: {rng.choice(["no-yield", "no-break"])}
design:
  scan_end: 0.8
motions:
{record("elcentro", u(0, 3))}{record("taft", u(0, 5))}"""
    concrete = f"""concrete:
  strength: {u(2500, 6000):.4g} psi
  cracked: {rng.choice(["true", "false"])}
  thickness: {hef + u(2, 6):.3g} in
  edge_distance: {u(6, 30):.3g} in
  reinforcement: none
  seismic: {rng.choice(["true", "true", "false"])}
  seismic_route: {route}
"""
    return text, concrete


def judged(text, present):
    """The limit states the case's own criteria fail on, from its text."""
    kind = re.search(r"kind: (\S+)", text).group(1)
    out = ["first-yield" if kind == "no-yield" else "usage", "overturn"]
    if "anchorage" in present:
        out.append("anchorage")
    return out


ORDER = ["first-yield", "usage", "overturn", "lift-off", "anchorage"]
compared = motions = 0
files = []
for i in range(n):
    text, concrete = draw(i)
    path = os.path.join(scratch, f"a{i:02d}.yaml")
    with open(path, "w") as f:
        f.write(text + concrete)
    files.append(path)
    fj, fc, fp = (os.path.join(scratch, f"a{i:02d}.{e}") for e in ("f.json", "csv", "p58"))
    r = run("fragility", path, "--json", fj, "--csv", fc, "--p58", fp, "-q")
    if r.returncode != 0:
        fail(f"a{i:02d}: fragility exit {r.returncode}: {r.stderr.strip()[:300]}")
        continue
    fr = json.load(open(fj))
    names = [s["limit_state"] for s in fr["limit_states"]]
    if names != ORDER:
        fail(f"a{i:02d}: limit states {names}, not {ORDER}")
        continue
    states = {s["limit_state"]: s for s in fr["limit_states"]}
    for m in fr["motions"]:
        if "anchorage" not in m["capacity_mps2"] or "anchorage" not in m["censored"]:
            fail(f"a{i:02d} {m['name']}: no anchorage capacity")

    # the governing state: the lowest fitted median of the judged ones
    want_j = judged(text, names)
    if fr["judged_limit_states"] != want_j:
        fail(f"a{i:02d}: judged {fr['judged_limit_states']}, the case's criteria {want_j}")
    fitted = [k for k in want_j if states[k]["fitted"]]
    want_g = min(fitted, key=lambda k: (states[k]["median_mps2"], ORDER.index(k))) \
        if fitted else None
    if fr["governing_limit_state"] != want_g:
        fail(f"a{i:02d}: governing {fr['governing_limit_state']}, lowest median {want_g}")
    rows = list(csv.DictReader(open(fc)))
    marked = {row["limit_state"] for row in rows if row["governing"] == "1"}
    if marked != ({want_g} if want_g else set()):
        fail(f"a{i:02d}: the CSV marks {marked} as governing, not {want_g}")
    if {row["limit_state"] for row in rows} != set(ORDER):
        fail(f"a{i:02d}: the CSV's limit states {sorted({r['limit_state'] for r in rows})}")

    # P-58: LS1 the lower of usage and anchorage
    p58 = list(csv.DictReader(open(fp)))[0]
    ls1 = [k for k in ("usage", "anchorage") if states[k]["fitted"]]
    if ls1:
        k = min(ls1, key=lambda k: (states[k]["median_mps2"], ORDER.index(k)))
        want = states[k]["median_mps2"] / fr["g_mps2"]
        if float(p58["LS1-Theta_0"]) != want or float(p58["LS1-Theta_1"]) != states[k]["beta"]:
            fail(f"a{i:02d}: P-58 LS1 {p58['LS1-Theta_0']}, {p58['LS1-Theta_1']}; the "
                 f"{k} state's {want}, {states[k]['beta']}")
    elif p58["LS1-Theta_0"] != "" or p58["Incomplete"] != "1":
        fail(f"a{i:02d}: P-58 LS1 given with neither state fitted")

    # design: each factor whose failing end fails on the anchorage
    dj = os.path.join(scratch, f"a{i:02d}.d.json")
    r = run("design", path, "--json", dj, "-q")
    if r.returncode not in (0, 1):
        fail(f"a{i:02d}: design exit {r.returncode}: {r.stderr.strip()[:300]}")
        continue
    d = json.load(open(dj))
    for fm, dm in zip(fr["motions"], d["motions"]):
        motions += 1
        cap = fm["capacity_mps2"]["anchorage"]
        first = True
        for crit, df in dm["design"]["design_factor"].items():
            if df["no_failure"] or not df["fail_reason"].startswith("the anchorage "):
                continue
            tol = df["resolution_astar"] * fr["a_star_mps2"] * (1 + 1e-9)
            if fm["censored"]["anchorage"] or abs(cap - df["fail_mps2"]) > tol:
                fail(f"a{i:02d} {fm['name']}: anchorage capacity {cap} (censored "
                     f"{fm['censored']['anchorage']}); design ({crit}) finds the anchorage "
                     f"failing at {df['fail_mps2']}: {df['fail_reason'][:120]}")
            compared += first
            if not first:
                continue
            first = False
            # check at the capacity: the anchorage fails there
            at = os.path.join(scratch, f"a{i:02d}-{fm['name']}.yaml")
            with open(at, "w") as f:
                f.write(f"extends: {path}\nname: at\nmotions:\n" + [
                    line for line in text.splitlines() if fm["name"] in line][0]
                    .replace("peak: 0.3 g", f"peak: {cap!r} m/s^2") + "\n")
            cj = os.path.join(scratch, f"a{i:02d}-{fm['name']}.json")
            r = run("check", at, "--json", cj, "-q")
            if r.returncode not in (0, 1):
                fail(f"{at}: check exit {r.returncode}: {r.stderr.strip()[:300]}")
                continue
            cm = json.load(open(cj))["motions"][0]
            util, reason = cm["anchorage"]["utilization"], cm["verdict"]["reason"]
            if not (util >= 1 - 1e-9 or "17.10.5.3" in reason):
                fail(f"a{i:02d} {fm['name']}: at its anchorage capacity {cap} check finds "
                     f"a utilization of {util} and no route failing: {reason[:120]}")

if motions and compared < motions / 3:
    fail(f"only {compared} of {motions} motions fail on the anchorage in design: the "
         "property was hardly tested")
print(f"{compared} of {motions} motions compared with design")

# batch --fragility: the same anchorage state and governing state, and merge
bj = os.path.join(scratch, "b.json")
r = run("batch", *files, "--fragility", "-q", "--json", bj)
if r.returncode not in (0, 1):
    fail(f"batch: exit {r.returncode}: {r.stderr.strip()[:300]}")
else:
    b = json.load(open(bj))
    for c in b["cases"]:
        fr = json.load(open(os.path.join(scratch, c["tag"] + ".f.json")))
        bf = c["fragility"]
        if bf.get("governing_limit_state", "?") != fr["governing_limit_state"]:
            fail(f"batch {c['tag']}: governing {bf.get('governing_limit_state')}, "
                 f"fragility {fr['governing_limit_state']}")
        for bl, fl in zip(bf["limit_states"], fr["limit_states"]):
            for k in ("limit_state", "fitted", "median_mps2", "beta"):
                if bl.get(k) != fl.get(k):
                    fail(f"batch {c['tag']} {fl['limit_state']}: {k} {bl.get(k)} against "
                         f"{fl.get(k)}")
        if len(bf["limit_states"]) != len(fr["limit_states"]):
            fail(f"batch {c['tag']}: {len(bf['limit_states'])} limit states")
    shards = []
    for s in (1, 2):
        sj = os.path.join(scratch, f"s{s}.json")
        r = run("batch", *files, "--fragility", "-q", "--shard", f"{s}/2", "--json", sj)
        shards.append(sj)
    mj = os.path.join(scratch, "m.json")
    r = run("merge", *shards, "--json", mj)
    if r.returncode not in (0, 1) or open(mj).read() != open(bj).read():
        fail(f"merge of two shards: exit {r.returncode}, {r.stderr.strip()[:300]}; the same "
             "summary as one run: " + str(os.path.exists(mj) and
                                           open(mj).read() == open(bj).read()))

# criteria: concrete: false keeps the state (the concrete still fails) but
# out of those the verdict fails on, and so out of the governing choice
off = os.path.join(scratch, "off.yaml")
with open(off, "w") as f:
    f.write(f"extends: {files[0]}\nname: off\ncriteria:\n  concrete: false\n")
fj = os.path.join(scratch, "off.json")
r = run("fragility", off, "--json", fj, "-q")
if r.returncode != 0:
    fail(f"concrete: false: fragility exit {r.returncode}: {r.stderr.strip()[:300]}")
else:
    fr = json.load(open(fj))
    if [s["limit_state"] for s in fr["limit_states"]] != ORDER \
            or "anchorage" in fr["judged_limit_states"] \
            or fr["governing_limit_state"] == "anchorage":
        fail(f"concrete: false: limit states {[s['limit_state'] for s in fr['limit_states']]}"
             f", judged {fr['judged_limit_states']}, governing {fr['governing_limit_state']}")

# without concrete: no anchorage state anywhere
text, _ = draw(99)
path = os.path.join(scratch, "bare.yaml")
with open(path, "w") as f:
    f.write(text)
fj, fc = os.path.join(scratch, "bare.json"), os.path.join(scratch, "bare.csv")
r = run("fragility", path, "--json", fj, "--csv", fc)
if r.returncode != 0:
    fail(f"bare: fragility exit {r.returncode}: {r.stderr.strip()[:300]}")
else:
    fr = json.load(open(fj))
    if [s["limit_state"] for s in fr["limit_states"]] != ORDER[:4] \
            or "anchorage" in fr["judged_limit_states"] \
            or any("anchorage" in m["capacity_mps2"] or "anchorage" in m["censored"]
                   for m in fr["motions"]) \
            or "anchorage" in open(fc).read() or "anchorage" in r.stdout:
        fail("a case without concrete: has an anchorage limit state")
    if "governing limit state: " not in r.stdout:
        fail(f"the table does not name the governing limit state: {r.stdout[:400]}")

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
