#!/usr/bin/env python3
"""One verdict whatever runs the case: a property test over random cases.

    python3 tests/verdicts/property.py ROCKBOLT JUDGE_PROBE SCRATCH [N] [SEED]

Run from the source root. Draws N (default 1000) random valid cases (bolt
models, criteria, validity modes, friction coefficients, harmonic, pulse
and record motions, one or two per case, levels from well below uplift to
past yield) and asserts that
  - `rockbolt check CASE --json` and `rockbolt batch` on the case files
    (`--reports`) write byte-identical JSON reports;
  - `rockbolt batch` on an equipment list with one row per case (the case
    as the row's base, nothing overridden) gives every motion the same
    verdict and the same numbers, byte for byte in the report's JSON
    (only the case's name and path, which a list row sets, may differ);
  - the design searches' run at each motion's own level gives the same
    verdict, validity and result as the pipeline (judge_probe);
  - `rockbolt batch --design` gives every motion of the first 16 cases the
    design factor (against the case's own criteria), its bound and the
    recommended gap that `rockbolt design` reports, to the last bit;
  - on those cases, the ends of each design factor's final bracket get the
    one judge's verdicts: the passing end passes, confirmed where it is
    marginal, and the failing end fails (judge_probe --design);
  - no verdict contradicts its own numbers: a passing no-yield run has
    every row force below Fy, a passing no-break run usage below its limit;
  - one "governs" rule: the governing motion of check's JSON is the first
    motion of least margin (0 for a failing motion, else the margin its
    convergence check reports; passes within 1e-9 tie), no more than 1 - the 17.8 utilization of
    any motion with a concrete check; `batch` on the files and `merge` of
    its two shards name the same governing motion and, for a failing
    motion, the same reason as check.
The seed is printed so that a failure can be replayed."""
import json, os, random, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import failures, src, start  # noqa: E402
import e2e  # noqa: E402

rb, probe, scratch = start(3)
n = int(sys.argv[4]) if len(sys.argv) > 4 else 1000
seed = int(sys.argv[5]) if len(sys.argv) > 5 else 20261124
rng = random.Random(seed)
os.makedirs(os.path.join(scratch, "cases"))
records = {
    "elcentro": "  file: {}/cases/records/elcentro_1940_ns.at2\n  format: at2\n",
    "taft": "  file: {}/cases/records/taft_1952_s69e.txt\n  format: one-column\n"
            "  dt: 0.01 s\n  units: g\n",
}


# The governs rule (rb_margin_governs), written again: the first motion of
# least margin, a failing run's 0 below every pass, passes within the tie
# (RB_MARGIN_TIE, include/rockbolt/criteria.h) one margin.
MARGIN_TIE = 1e-9


def governing_index(margins):
    g = 0
    for i in range(1, len(margins)):
        a, b = margins[i], margins[g]
        if (b > 0) if a == 0 else (a < b - MARGIN_TIE):
            g = i
    return g


def u(a, b, fmt="{:.4g}"):
    return fmt.format(rng.uniform(a, b))


def motion(level_unit):
    kind = rng.choice(["harmonic", "harmonic", "pulse", "record", "record"])
    lines = []
    if kind == "harmonic":
        lines += ["  type: harmonic", f"  amplitude: {u(0.01, 0.6)} {level_unit}",
                  f"  frequency: {u(1, 8)} Hz", f"  duration: {u(0.5, 2.5)} s"]
    elif kind == "pulse":
        lines += ["  type: pulse",
                  "  shape: " + rng.choice(["rectangular", "half-sine",
                                            "triangular-decreasing"]),
                  f"  amplitude: {u(0.01, 0.6)} {level_unit}",
                  f"  duration: {u(0.05, 0.5)} s", f"  run_time: {u(1, 2)} s"]
    else:
        name = rng.choice(sorted(records))
        lines += ["  type: record"] + records[name].format(src).rstrip("\n").split("\n")
        if rng.random() < 0.8:
            lines.append(f"  building: {{ frequency: {u(3, 10)} Hz, damping: 5 % }}")
        lines.append(f"  peak: {u(0.01, 0.5)} {level_unit}")
        t0 = rng.uniform(0, 4)
        lines.append(f"  window: [{t0:.3f} s, {t0 + rng.uniform(1, 2.5):.3f} s]")
    if rng.random() < 0.3:
        lines.append("  polarity: -1")
    return lines


def case(i):
    bolts = rng.choice(["rigid-plastic"] * 3 + ["non-yielding"] * 2 +
                       ["elastic-plastic", "none"])
    level = "g" if bolts == "none" else "A*"
    y = [f"name: p{i:04d}", "equipment:", f"  mass: {u(200, 900)} kg",
         f"  height: {u(1.2, 2.4)} m", f"  base_width: {u(0.5, 1.0)} m"]
    if rng.random() < 0.1:
        y.append("  rigid: true")
    else:
        y += [f"  frequency: {u(3, 15)} Hz", f"  damping: {u(1, 5)} %"]
    y += ["anchorage:", f"  model: {bolts}"]
    if bolts != "none":
        y += [f"  bolts_per_row: {rng.randint(1, 3)}", f"  diameter: {u(10, 16)} mm",
              f"  yield_stress: {u(248, 400)} MPa", "  toughness: 82700 kJ/m^3",
              f"  deformable_length: {u(50, 150)} mm", f"  edge_distance: {u(0.04, 0.12)} m"]
        y.append(f"gap_ratio: {rng.choice(['0', u(0.002, 0.03)])}")
    crit = ["criteria:", "  kind: " + rng.choice(["no-yield", "no-break"])]
    if rng.random() < 0.3:
        crit.append(f"  usage_limit: {u(0.3, 1.0)}")
    if rng.random() < 0.4:
        crit.append("  validity: " + rng.choice(["warn", "fail"]))
    if rng.random() < 0.3:
        crit.append(f"  friction_coefficient: {u(0.2, 1.0)}")
    if rng.random() < 0.2:
        crit.append(f"  max_shear_over_w: {u(0.5, 20)}")
    y += crit
    an = ["analysis:"]
    if rng.random() < 0.2:
        an.append("  formulation: " + rng.choice(["small", "consistent"]))
    if rng.random() < 0.15:
        an.append("  integrator: rk45")
    if rng.random() < 0.3:
        an.append("  stretch_past_failure: true")
    if len(an) > 1:
        y += an
    ms = [motion(level) for _ in range(rng.choice([1, 1, 2]))]
    if len(ms) == 1:
        y += ["motion:"] + ms[0]
    else:
        y.append("motions:")
        for m in ms:
            y += ["  - " + m[0].strip()] + ["  " + l for l in m[1:]]
    return "\n".join(y) + "\n"


paths = []
for i in range(n):
    p = os.path.join(scratch, "cases", f"p{i:04d}.yaml")
    with open(p, "w") as f:
        f.write(case(i))
    paths.append(p)

def fail(msg):
    e2e.fail(msg, shown=20)


# check, one process per case, as a user runs it
check_json = {}
for p in paths:
    out = p[:-5] + ".check.json"
    r = subprocess.run([rb, "check", p, "--json", out, "--quiet"], capture_output=True,
                       text=True)
    if r.returncode not in (0, 1):
        fail(f"{p}: check exit {r.returncode}: {r.stderr.strip()[:300]}")
        continue
    with open(out, "rb") as f:
        check_json[p] = f.read()
    rep = json.loads(check_json[p])
    if (rep["verdict"]["pass"]) != (r.returncode == 0):
        fail(f"{p}: check exit {r.returncode} with verdict {rep['verdict']['result']}")
    for m in rep["motions"]:
        v, res = m["verdict"], m["result"]
        kind = rep["criteria"]["kind"]
        if v["pass"] and kind == "no-yield" and res["constants"]["fy_row_n"] > 0:
            f = max(res["peaks"]["max_bolt_force_n"].values()) / res["constants"]["fy_row_n"]
            if f >= 1 or any(res["bolts"]["yielded"].values()):
                fail(f"{p}: {m['name']} passes no-yield with force / Fy {f}")
        if v["pass"] and kind == "no-break":
            if max(res["bolts"]["usage"].values()) >= rep["criteria"]["usage_limit"]:
                fail(f"{p}: {m['name']} passes no-break at usage "
                     f"{max(res['bolts']['usage'].values())}")
        if v["pass"] and rep["criteria"]["validity"] == "fail" and v["validity_warnings"]:
            fail(f"{p}: {m['name']} passes validity: fail with warnings")
        if v["pass"] and not v["criteria_pass"]:
            fail(f"{p}: {m['name']} passes without meeting its criteria")
    # the governing motion, worked out again from the reported margins
    margins = [m["validity"]["convergence"]["margin"] if m["verdict"]["pass"] else 0
               for m in rep["motions"]]
    want = governing_index(margins)
    su = rep["suite"]
    if su["governing_index"] != want + 1 or su["governing_margin"] != margins[want]:
        fail(f"{p}: check governs motion {su['governing_index']} at "
             f"{su['governing_margin']}, margins {margins}")
    for m in rep["motions"]:
        a = m.get("anchorage")
        if a and a.get("utilization") is not None and \
                su["governing_margin"] > max(0.0, 1 - a["utilization"]) + 1e-12:
            fail(f"{p}: governing margin {su['governing_margin']} above the anchorage's "
                 f"{1 - a['utilization']} in {m['name']}")

# batch on the case files: the same reports, byte for byte
reports = os.path.join(scratch, "reports-files")
r = subprocess.run([rb, "batch", *[os.path.relpath(p) for p in paths], "--reports", reports,
                    "--json", os.path.join(scratch, "files.json"), "-q"],
                   capture_output=True, text=True)
if r.returncode not in (0, 1):
    fail(f"batch on the case files: exit {r.returncode}: {r.stderr.strip()[:300]}")
# the reports are named by work index and tag: map them back by name
by_tag = {}
if os.path.isdir(reports):
    for fn in os.listdir(reports):
        if fn.endswith(".json"):
            by_tag[fn.split("-", 1)[1][:-5]] = os.path.join(reports, fn)
for p in paths:
    tag = os.path.basename(p)[:-5]
    if p not in check_json:
        continue
    if tag not in by_tag:
        fail(f"{p}: batch wrote no report")
        continue
    with open(by_tag[tag], "rb") as f:
        b = f.read()
    # batch was given the path relative to the source root, check the
    # absolute one: say so in the one field that names it
    c = json.loads(check_json[p])
    c["case"]["path"] = os.path.relpath(p)
    if json.loads(b) != c:
        fail(f"{p}: batch's report differs from check's")

# batch, and merge of its shards, name check's governing motion and reason
def governing_of_summary(path):
    out = {}
    for c in json.load(open(path))["cases"]:
        runs = c.get("runs") or []
        g = c.get("governing_motion")
        if not runs:
            out[c["source"]] = (g, None)
            continue
        # two motions may share a name: find the run by the rule on the
        # summary's own margins, and hold the name the summary gives to it
        k = governing_index([run["margin"] for run in runs])
        if runs[k]["motion"] != g:
            fail(f"{path}: {c['source']}: governing_motion {g}, least margin {runs[k]['motion']}")
        out[c["source"]] = (g, runs[k]["reason"] if runs[k]["verdict"] == "fail" else None)
    return out


shards = []
for k in (1, 2):
    sj = os.path.join(scratch, f"shard{k}.json")
    r = subprocess.run([rb, "batch", *[os.path.relpath(p) for p in paths], "--shard",
                        f"{k}/2", "--json", sj, "-q"], capture_output=True, text=True)
    if r.returncode not in (0, 1):
        fail(f"batch --shard {k}/2: exit {r.returncode}: {r.stderr.strip()[:300]}")
    shards.append(sj)
merged = os.path.join(scratch, "merged.json")
r = subprocess.run([rb, "merge", *shards, "--json", merged, "-q"], capture_output=True,
                   text=True)
if r.returncode not in (0, 1):
    fail(f"merge: exit {r.returncode}: {r.stderr.strip()[:300]}")
named = 0
if os.path.exists(merged) and os.path.exists(os.path.join(scratch, "files.json")):
    by_batch = governing_of_summary(os.path.join(scratch, "files.json"))
    by_merge = governing_of_summary(merged)
    for p in paths:
        if p not in check_json:
            continue
        rep = json.loads(check_json[p])
        g = rep["motions"][rep["suite"]["governing_index"] - 1]
        want = (rep["suite"]["governing_name"],
                None if g["verdict"]["pass"] else rep["suite"]["governing_reason"])
        src_ = os.path.relpath(p)
        for who, got in (("batch", by_batch.get(src_)), ("merge", by_merge.get(src_))):
            if got != want:
                fail(f"{p}: {who} governs {got}, check {want}")
        named += 1
print(f"governing motion and reason: check, batch and merge agree on {named} cases")

# batch on a list with one row per case, nothing overridden
lst = os.path.join(scratch, "list.csv")
with open(lst, "w") as f:
    f.write("tag,base\n")
    for p in paths:
        f.write(f"{os.path.basename(p)[:-5]},{p}\n")
reports = os.path.join(scratch, "reports-list")
r = subprocess.run([rb, "batch", lst, "--reports", reports, "-q"], capture_output=True,
                   text=True)
if r.returncode not in (0, 1):
    fail(f"batch on the list: exit {r.returncode}: {r.stderr.strip()[:300]}")
by_tag = {}
if os.path.isdir(reports):
    for fn in os.listdir(reports):
        if fn.endswith(".json"):
            by_tag[fn.split("-", 1)[1][:-5]] = os.path.join(reports, fn)
for p in paths:
    tag = os.path.basename(p)[:-5]
    if p not in check_json or tag not in by_tag:
        if p in check_json:
            fail(f"{p}: the list's batch wrote no report")
        continue
    a, b = json.loads(check_json[p]), json.load(open(by_tag[tag]))
    for rep in (a, b):
        rep["case"].pop("path")
        rep["case"].pop("name")
        for m in rep["motions"]:
            m.pop("source", None)
            m.get("motion", {}).pop("source", None)
    if a != b:
        fail(f"{p}: the list row's report differs from check's")

# the design searches' run at each motion's own level
r = subprocess.run([probe, *paths], capture_output=True, text=True)
print(r.stdout.strip().splitlines()[-1] if r.stdout.strip() else "judge_probe: no output")
if r.returncode != 0:
    fail("judge_probe: " + "\n".join(r.stdout.splitlines()[:10]))

# batch --design against design, on the first cases (the searches are slow)
some = [p for p in paths if p in check_json][:16]
r = subprocess.run([probe, "--design", *some], capture_output=True, text=True)
print(r.stdout.strip().splitlines()[-1] if r.stdout.strip() else "judge_probe --design: no output")
if r.returncode != 0:
    fail("judge_probe --design: " + "\n".join(
        line for line in r.stdout.splitlines() if "FAIL" in line or "does not" in line)[:2000])
bj = os.path.join(scratch, "design-batch.json")
r = subprocess.run([rb, "batch", *some, "--design", "--json", bj, "-q"],
                   capture_output=True, text=True)
if r.returncode not in (0, 1):
    fail(f"batch --design: exit {r.returncode}: {r.stderr.strip()[:300]}")
batch_runs, compared = {}, 0
if os.path.exists(bj):
    for c in json.load(open(bj))["cases"]:
        batch_runs[c["source"]] = c["runs"]
for p in some:
    dj = os.path.join(scratch, os.path.basename(p) + ".design.json")
    r = subprocess.run([rb, "design", p, "--json", dj, "-q"], capture_output=True, text=True)
    if r.returncode not in (0, 1) or p not in batch_runs:
        fail(f"{p}: design exit {r.returncode} or no batch --design row")
        continue
    rep = json.load(open(dj))
    own = "no_yield" if rep["criteria"]["kind"] == "no-yield" else "no_break"
    for m, run in zip(rep["motions"], batch_runs[p]):
        f = m["design"]["design_factor"][own]
        g = m["design"].get("recommended_gap") or {}
        want = (f["factor"] if f["level_mps2"] > 0 else None,
                f["no_failure"] if f["level_mps2"] > 0 else None,
                g.get("gap_ratio") if g.get("found") else None)
        got = (run.get("design_factor"),
               run.get("design_factor_bound") if run.get("design_factor") is not None
               else None, run.get("gap_ratio"))
        compared += 1
        if want != got:
            fail(f"{p}: {m['name']}: batch --design gives {got}, design {want}")
print(f"batch --design against design: {compared} motions of {len(some)} cases")

print(f"seed {seed}: {n} cases")
print(f"{n - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
