#!/usr/bin/env python3
"""fragility --p58 and batch --fragility --p58: the FEMA P-58 rows that a
loss tool (pelicun, the SimCenter damage and loss library) reads.

    python3 tests/fragility/p58.py ROCKBOLT SCRATCH

Run from the source root. Asserts that
  - the file loads with Python's csv module into exactly the documented
    columns, one row, the ID the case's fragility.p58_id (a comma in it
    quoted), Demand-Type "Peak Floor Acceleration" in g, offset 0,
    directional 1;
  - LS1's median and beta are the usage state's of `fragility --json`
    (median_mps2 / g_mps2, to the last bit), LS2's the overturn state's,
    both lognormal, and LS1's weights the case's, else 0.7 | 0.3;
  - a suite whose scan ends before the cabinet overturns leaves LS2 blank
    and marks the row Incomplete;
  - batch --fragility --p58 writes a row per list item, its ID the tag, each
    row's numbers those of the batch's JSON, and an incomplete blank row for
    a free-standing item;
  - --p58 is refused with --sweep-gap, --intensity sa, onto the case, and in
    batch without --fragility; bad weights are refused at their line."""
import csv, json, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, failures, finish, run, src, start, write  # noqa: E402

rb, scratch = start()

COLUMNS = ["ID", "Incomplete", "Demand-Type", "Demand-Unit", "Demand-Offset",
           "Demand-Directional"]
for k in (1, 2):
    COLUMNS += [f"LS{k}-Family", f"LS{k}-Theta_0", f"LS{k}-Theta_1",
                f"LS{k}-DamageStateWeights"]
# after P-58's own columns: the fragility's flags of each limit state
for k in (1, 2):
    COLUMNS += [f"LS{k}-Confirmed", f"LS{k}-ModelLimited"]

# three 5 s windows of the records through buildings: a fragility in a
# few seconds of CPU
MOTIONS = "".join(
    f"  - {{type: record, name: {n}, file: {src}/cases/records/{r}, format: {fm}, "
    f"building: {{frequency: {f} Hz, damping: 5 %}}, peak: 3.5 g, window: [{t} s, {t + 5} s]}}\n"
    for n, r, fm, f, t in [("elcentro", "elcentro_1940_ns.at2", "at2", 5, 1),
                           ("taft", "taft_1952_s69e.txt", "one-column, units: g, dt: 0.01 s",
                            4, 2),
                           ("ngawest2", "elcentro_1940_ns_ngawest2.at2", "at2", 5, 6)])


def case(name, extra, scan_end="1.5"):
    return write(name + ".yaml",
                 f"extends: {src}/cases/base/reference-cabinet.yaml\nname: {name}\n"
                 f"motions:\n{MOTIONS}design:\n  scan_end: {scan_end}\n"
                 f"analysis:\n  stretch_past_failure: true\n{extra}")


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
        f.seek(0)
        header = next(csv.reader(f))
    if header != COLUMNS:
        fail(f"{path}: columns {header}")
    return rows


def limits(frag):
    """median (g) and beta of each fitted limit state of a fragility JSON."""
    g = frag["g_mps2"]
    return {l["limit_state"]: (l["median_mps2"] / g, l["beta"], l["confirmed"],
                               l["model_limited"]) if l["fitted"] else None
            for l in frag["limit_states"]}


def check_row(what, row, lim, weights):
    for k, state in ((1, "usage"), (2, "overturn")):
        want = lim[state]
        got = (row[f"LS{k}-Family"], row[f"LS{k}-Theta_0"], row[f"LS{k}-Theta_1"])
        if want is None:
            if got != ("", "", ""):
                fail(f"{what}: LS{k} ({state}) not fitted but written as {got}")
            continue
        if got[0] != "lognormal" or float(got[1]) != want[0] or float(got[2]) != want[1]:
            fail(f"{what}: LS{k} {got}, the JSON's {state} has median {want[0]!r} g, "
                 f"beta {want[1]!r}")
        flags = (row[f"LS{k}-Confirmed"], row[f"LS{k}-ModelLimited"])
        if flags != (str(int(want[2])), str(want[3])):
            fail(f"{what}: LS{k} flags {flags}, the JSON's {state} confirmed {want[2]}, "
                 f"model_limited {want[3]}")
    w = row["LS1-DamageStateWeights"]
    if lim["usage"] is not None and [float(x) for x in w.split("|")] != weights:
        fail(f"{what}: LS1 weights '{w}', expected {weights}")
    if row["LS2-DamageStateWeights"] != "":
        fail(f"{what}: LS2 has weights '{row['LS2-DamageStateWeights']}'")
    incomplete = any(lim[s] is None for s in ("usage", "overturn"))
    if row["Incomplete"] != str(int(incomplete)):
        fail(f"{what}: Incomplete {row['Incomplete']}, fitted {lim}")
    fixed = {"Demand-Type": "Peak Floor Acceleration", "Demand-Unit": "g",
             "Demand-Offset": "0", "Demand-Directional": "1"}
    for col, v in fixed.items():
        if row[col] != v:
            fail(f"{what}: {col} '{row[col]}', expected '{v}'")


# the case's own ID (quoted for its comma) and weights
own = case("roof-panel", "fragility:\n  p58_id: \"D.3041.011a-rb, roof\"\n"
           "  damage_state_weights: [60 %, 0.3, 0.1]\n")
p58, js = os.path.join(scratch, "own.csv"), os.path.join(scratch, "own.json")
r = run("fragility", own, "--p58", p58, "--json", js, "-q")
if r.returncode != 0:
    fail(f"fragility --p58: exit {r.returncode}: {r.stderr.strip()}")
    finish()
rows = load(p58)
if len(rows) != 1 or rows[0]["ID"] != "D.3041.011a-rb, roof":
    fail(f"own: rows {rows}")
lim = limits(json.load(open(js)))
if lim["usage"] is None or lim["overturn"] is None:
    fail(f"own: the suite fits neither usage nor overturn: {lim}")
check_row("own", rows[0], lim, [0.6, 0.3, 0.1])

# the defaults, and a scan that ends before the cabinet overturns
short = case("short-scan", "", scan_end="0.5")
p58, js = os.path.join(scratch, "short.csv"), os.path.join(scratch, "short.json")
r = run("fragility", short, "--p58", p58, "--json", js, "-q")
if r.returncode != 0:
    fail(f"fragility --p58 (short scan): exit {r.returncode}: {r.stderr.strip()}")
else:
    rows = load(p58)
    lim = limits(json.load(open(js)))
    if lim["overturn"] is not None or lim["usage"] is None:
        fail(f"short scan: expected usage fitted and overturn not: {lim}")
    if rows[0]["ID"] != "short-scan":
        fail(f"short scan: ID '{rows[0]['ID']}', not the case name")
    check_row("short scan", rows[0], lim, [0.7, 0.3])

# batch: a row per item, the tag as ID, the numbers of the batch's JSON
base = case("base", "")
lst = write("list.csv", "tag,base,mass,bolt_model\nEP-1,base.yaml,454 kg,\n"
            "\"EP-2, spare\",base.yaml,600 kg,\nFREE,base.yaml,,none\n")
bp, bj = os.path.join(scratch, "batch.csv"), os.path.join(scratch, "batch.json")
r = run("batch", lst, "--fragility", "--p58", bp, "--json", bj, "-q")
if r.returncode not in (0, 1):
    fail(f"batch --p58: exit {r.returncode}: {r.stderr.strip()}")
else:
    rows = load(bp)
    summary = json.load(open(bj))
    cases = summary["cases"]
    if [x["ID"] for x in rows] != ["EP-1", "EP-2, spare", "FREE"]:
        fail(f"batch: IDs {[x['ID'] for x in rows]}")
    for row, c in zip(rows, cases):
        fr = c.get("fragility") or {}
        if "limit_states" in fr:
            check_row(f"batch {row['ID']}", row, limits(fr), [0.7, 0.3])
        elif row["Incomplete"] != "1" or any(row[f"LS{k}-Theta_0"] for k in (1, 2)):
            fail(f"batch {row['ID']}: no fragility, yet the row is {row}")

# refusals, before any work (exit 2, nothing written)
for args, says in [(["--sweep-gap", "0:0.02:0.01"], "--sweep-gap"),
                   (["--intensity", "sa"], "--intensity sa"),
                   ([], "the case")]:
    out = own if not args else os.path.join(scratch, "refused.csv")
    r = run("fragility", own, "--p58", out, *args)
    if r.returncode != 2 or says not in r.stderr:
        fail(f"fragility --p58 {args}: exit {r.returncode}, '{r.stderr.strip()}'")
r = run("batch", lst, "--p58", os.path.join(scratch, "refused.csv"))
if r.returncode != 2 or "--fragility" not in r.stderr:
    fail(f"batch --p58 without --fragility: exit {r.returncode}, '{r.stderr.strip()}'")
if os.path.exists(os.path.join(scratch, "refused.csv")):
    fail("a refused --p58 wrote its file")
for weights, says in [("[0.7, 0.2]", "sum to 1"), ("[1.5]", "> 0 and <= 1"),
                      ("[0.2, 0.2, 0.2, 0.2, 0.1, 0.1]", "1 to 5 weights"),
                      ("0.7", "a list")]:
    bad = case("bad", f"fragility:\n  damage_state_weights: {weights}\n")
    r = run("check", bad, "-q")
    line = sum(1 for _ in open(bad))
    if r.returncode != 2 or says not in r.stderr or f"bad.yaml:{line}:" not in r.stderr:
        fail(f"weights {weights}: exit {r.returncode}, '{r.stderr.strip()}'")

finish(f"{len(failures)} failures")
