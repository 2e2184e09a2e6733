#!/usr/bin/env python3
"""Capacities limited by the model, not the bolts (docs/fragility.md,
"Capacities limited by the model"), and which states are confirmed.

    python3 tests/fragility/model_limit.py ROCKBOLT SCRATCH

Run from the source root. Two harmonic motions with harmonic verticals
(the vertical scaled with the horizontal at every level) under which the
reference cabinet's bolts stay elastic until the vertical's downward peak
reaches g. Asserts that
  - each first-yield, usage and overturn capacity is the level where the
    vertical reaches -g, by hand: capacity x downward V peak / H1 peak = g
    (to 1e-12), marked model-limited in the JSON (per motion, and counted
    per limit state), with `^` in the text and hollow in the figure; the
    lift-off capacity, far below it, is not;
  - it is not the bolts': `check` under no-yield at 0.999 of that level
    passes (the bolts stay elastic), and at 1.001 of it the case is refused
    (the vertical reaches -g);
  - the fit counts those capacities as reached at the limit (the reported
    median a lower bound): for two motions the closed-form maximum
    likelihood, median sqrt(c1 c2) and beta |ln(c1 / c2)| / 2;
  - the JSON and the text name the confirmed limit states (the governing
    one) and the others as not confirmed;
  - a motion without a vertical has no model limit (null, nothing marked);
  - the fragility CSV (--csv), the FEMA P-58 row (--p58) and batch
    --fragility (CSV, JSON, table, JUnit) carry the same flags: each
    capacity's or state's model_limited where the hand's limit is the
    capacity, and confirmed for the governing state only (usage; overturn,
    LS2 of the P-58 row, is not)."""
import csv, json, math, os, re, sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, finish, run, src, start, write  # noqa: E402

rb, scratch = start()
BASE = os.path.join(src, "cases", "base", "reference-cabinet.yaml")
H = 0.3                                        # H1 amplitude, g
MOTIONS = [("v90", 0.27, 6), ("v75", 0.225, 7)]  # name, V amplitude (g), V Hz
LIMITED = ["first-yield", "usage", "overturn"]


def harmonic(name, h, v, fv):
    return (f"{{type: harmonic, name: {name}, amplitude: {h!r} g, frequency: 3 Hz, "
            f"duration: 2 s, vertical: {{type: harmonic, amplitude: {v!r} g, "
            f"frequency: {fv} Hz}}}}")


case = write("vertical.yaml", f"extends: {BASE}\nname: vertical-decides\nmotions:\n"
             + "".join(f"  - {harmonic(n, H, v, fv)}\n" for n, v, fv in MOTIONS)
             + "analysis:\n  stretch_past_failure: true\n")
js, svg = os.path.join(scratch, "f.json"), os.path.join(scratch, "f.svg")
r = run("fragility", case, "-j", "2", "--json", js, "--svg", svg)
if r.returncode != 0:
    fail(f"fragility: exit {r.returncode}: {r.stderr.strip()[:300]}")
    finish()
fr = json.load(open(js))
g = fr["g_mps2"]
caps = {}
for m, (name, v, fv) in zip(fr["motions"], MOTIONS):
    hand = H / v     # the level (g) where the downward V peak reaches g
    for s in LIMITED:
        c = m["capacity_mps2"][s]
        if not m["model_limited"][s] or m["censored"][s]:
            fail(f"{name} {s}: not marked limited by the model: {m}")
        if abs(c / g * v / H - 1) > 1e-12:
            fail(f"{name} {s}: capacity {c / g!r} g x V {v} / H1 {H} = "
                 f"{c / g * v / H!r} g, not 1 g")
    if m["model_limited"]["lift-off"] or not m["capacity_mps2"]["lift-off"] < 0.5 * hand * g:
        fail(f"{name}: the lift-off capacity is not the base's own: {m}")
    if m["model_limit_mps2"] is None or abs(m["model_limit_mps2"] / g / hand - 1) > 1e-12:
        fail(f"{name}: model_limit_mps2 {m['model_limit_mps2']}, want {hand * g}")
    caps[name] = hand
    # the bolts hold just below the limit; just above it the case is refused
    for k, want in ((0.999, 0), (1.001, 2)):
        one = write(f"{name}-{k}.yaml", f"extends: {BASE}\nname: near\ncriteria: "
                    f"{{kind: no-yield}}\nmotion: {harmonic(name, k * hand, k * hand * v / H, fv)}\n"
                    "analysis:\n  stretch_past_failure: true\n")
        rc = run("check", one, "-q").returncode
        if rc != want:
            fail(f"{name}: check under no-yield at {k} of the limit: exit {rc}, want {want}")

c1, c2 = (caps[n] * g for n, _, _ in MOTIONS)
want_median, want_beta = math.sqrt(c1 * c2), abs(math.log(c1 / c2)) / 2
for s in fr["limit_states"]:
    k = s["limit_state"]
    n_limited = 2 if k in LIMITED else 0
    if s["model_limited"] != n_limited:
        fail(f"{k}: model_limited {s['model_limited']}, want {n_limited}")
    if k in LIMITED and (abs(s["median_mps2"] / want_median - 1) > 1e-12
                         or abs(s["beta"] - want_beta) > 1e-12):
        fail(f"{k}: median {s['median_mps2']} beta {s['beta']}; the capacities counted as "
             f"reached give {want_median} and {want_beta}")
    if s["confirmed"] != (k == fr["governing_limit_state"]):
        fail(f"{k}: confirmed {s['confirmed']}, governing {fr['governing_limit_state']}")
if fr["confirmed_limit_states"] != [fr["governing_limit_state"]] or \
        fr["governing_limit_state"] != "usage":
    fail(f"confirmed {fr['confirmed_limit_states']}, governing {fr['governing_limit_state']}")

text = r.stdout
if not re.search(r"^confirmed at tighter tolerances: usage .*not confirmed: first-yield, "
                 r"overturn, lift-off", text, re.M):
    fail("the text does not name the confirmed and unconfirmed states:\n" + text)
if "limited by the model: first-yield 2 of 2, usage 2 of 2, overturn 2 of 2" not in text:
    fail("the text does not say which fits the model limits:\n" + text)
if re.search(r"\bnan\b", text, re.I):
    fail("the text prints nan (two motions are too few to resample):\n" + text)
rows = [ln for ln in text.splitlines() if ln.startswith(("v90 ", "v75 "))]
if len(rows) != 2 or any(ln.count("^") != 3 for ln in rows):
    fail(f"the capacities' rows do not mark the three limited ones with ^: {rows}")
figure = open(svg).read()
if figure.count('data-model-limited="1"') != 6 or "hollow: the model" not in figure:
    fail("the figure does not draw the six limited capacities hollow and say why")

# the flags in the other outputs, against the hand's limit and the governing state
gov = fr["governing_limit_state"]
want_p58 = {"LS1-Confirmed": "1", "LS1-ModelLimited": "2",     # usage, governing
            "LS2-Confirmed": "0", "LS2-ModelLimited": "2"}     # overturn
cj, p58 = os.path.join(scratch, "f.csv"), os.path.join(scratch, "f.p58.csv")
r = run("fragility", case, "-j", "2", "--csv", cj, "--p58", p58, "-q")
if r.returncode != 0:
    fail(f"fragility --csv --p58: exit {r.returncode}: {r.stderr.strip()[:300]}")
else:
    with open(cj, newline="") as f:
        rows = list(csv.DictReader(f))
    if len(rows) != 2 * 4:
        fail(f"the fragility CSV has {len(rows)} rows, want 8")
    for row in rows:
        name, s = row["motion"], row["limit_state"]
        hand = H / dict((n, v) for n, v, _ in MOTIONS)[name]
        at_limit = abs(float(row["capacity_g"]) / hand - 1) < 1e-5   # %.6g
        want = (str(int(s == gov)), str(int(s in LIMITED)))
        if (row.get("confirmed"), row.get("model_limited")) != want or \
                at_limit != (s in LIMITED):
            fail(f"fragility CSV {name} {s}: confirmed {row.get('confirmed')}, "
                 f"model_limited {row.get('model_limited')}, capacity "
                 f"{row['capacity_g']} g against the hand's {hand!r}; want {want}")
    with open(p58, newline="") as f:
        prow = list(csv.DictReader(f))
    if len(prow) != 1 or any(prow[0].get(k) != v for k, v in want_p58.items()):
        fail(f"the P-58 row's flags {prow}, want {want_p58}")

lst = write("list.csv", "tag,base\nV,vertical.yaml\n")
bc, bj, bx = (os.path.join(scratch, "b." + e) for e in ("csv", "json", "xml"))
bp = os.path.join(scratch, "b.p58.csv")
r = run("batch", lst, "--fragility", "--csv", bc, "--json", bj, "--junit", bx, "--p58", bp)
if r.returncode not in (0, 1):
    fail(f"batch --fragility: exit {r.returncode}: {r.stderr.strip()[:300]}")
else:
    with open(bc, newline="") as f:
        brow = list(csv.DictReader(f))[0]
    props = {p.get("name"): p.get("value") for p in ET.parse(bx).iter("property")}
    blim = {l["limit_state"]: l for l in json.load(open(bj))["cases"][0]["fragility"]
            ["limit_states"]}
    for s in ("first-yield", "usage", "overturn", "lift-off"):
        col = s.replace("-", "_")
        conf, lim = int(s == gov), 2 if s in LIMITED else 0
        got = (brow.get(f"fragility_{col}_confirmed"), brow.get(f"fragility_{col}_model_limited"),
               blim[s].get("confirmed"), blim[s].get("model_limited"),
               props.get(f"fragility.{s}.confirmed"), props.get(f"fragility.{s}.model_limited"))
        if got != (str(conf), str(lim), bool(conf), lim, str(conf), str(lim)):
            fail(f"batch {s}: CSV, JSON, JUnit flags {got}; want confirmed {conf}, "
                 f"model_limited {lim}")
    lines = {m.group(1): m.group(2) for m in re.finditer(r"\[([a-z-]+)\]\s+(.*)", r.stdout)}
    for s in ("first-yield", "usage", "overturn", "lift-off"):
        ln = lines.get(s, "")
        limited = "2 at the model's limit" in ln
        confirmed = "; confirmed" in ln and "not confirmed" not in ln
        if limited != (s in LIMITED) or confirmed != (s == gov) or \
                (s != gov and "not confirmed" not in ln):
            fail(f"batch table [{s}]: '{ln}'")
        if re.search(r"\bnan\b", ln, re.I):
            fail(f"batch table [{s}] prints nan (two motions are too few to resample): '{ln}'")
    with open(bp, newline="") as f:
        prow = list(csv.DictReader(f))
    if len(prow) != 1 or any(prow[0].get(k) != v for k, v in want_p58.items()):
        fail(f"batch --p58 row's flags {prow}, want {want_p58}")

# the same horizontal without a vertical: no limit of the model
plain = write("plain.yaml", f"extends: {BASE}\nname: plain\nmotions:\n"
              f"  - {{type: harmonic, name: h, amplitude: {H} g, frequency: 3 Hz, "
              "duration: 2 s}\n  - {type: harmonic, name: h2, amplitude: 0.3 g, frequency: "
              "3.5 Hz, duration: 2 s}\nanalysis:\n  stretch_past_failure: true\n")
pj = os.path.join(scratch, "plain.json")
r = run("fragility", plain, "-j", "2", "--json", pj)
if r.returncode != 0:
    fail(f"fragility without a vertical: exit {r.returncode}: {r.stderr.strip()[:300]}")
else:
    p = json.load(open(pj))
    if any(m["model_limit_mps2"] is not None or any(m["model_limited"].values())
           for m in p["motions"]) or "^" in r.stdout or "limited by the model" in r.stdout:
        fail("a suite without a vertical has capacities limited by the model")

finish()
