#!/usr/bin/env python3
"""batch --fragility against rockbolt fragility, over random rows.

    python3 tests/fragility/batch_property.py ROCKBOLT SCRATCH [N] [SEED]

Run from the source root. Draws an equipment list of N (default 6) random
rows over a base with five windowed records through buildings, varying the cabinet, the bolts, the gap, the
criterion and the records' peak, plus a free-standing row, and a random
bootstrap seed; then asserts that
  - `batch LIST --fragility --seed S --json` gives each row the level, and
    for each limit state whether it is fitted, its median, beta, interval
    and probability at the level that `rockbolt fragility ROWCASE --seed S
    --json` gives on the same case written as a file, to the last bit, and
    as many motions reaching it as that command has uncensored;
  - `batch --intensity sa` gives each row what `rockbolt fragility ROWCASE
    --intensity sa --json` gives, to the last bit, and says so in its head;
  - `--reports DIR` holds each row's fragility report as `rockbolt
    fragility ROWCASE --json` writes it, byte for byte;
  - the free-standing row keeps its verdict and says why it has no
    fragility, where `rockbolt fragility` refuses the case;
  - the table, JSON, CSV and JUnit outputs are byte-identical with -j 1 and
    -j 2 (also for one case alone, whose searches then share both threads),
    and merging two shards gives the JSON of the whole list.
The seed is printed so that a failure can be replayed."""
import csv, json, os, random, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, failures, run, src, start  # noqa: E402

rb, scratch = start()
n = int(sys.argv[3]) if len(sys.argv) > 3 else 6
seed = int(sys.argv[4]) if len(sys.argv) > 4 else 20260317
rng = random.Random(seed)


# five windows of the records through buildings: with fewer motions the
# bootstrap's percentiles hardly depend on its seed, and a seed mixed up
# would go unseen
WINDOWS = [("elcentro", "elcentro_1940_ns.at2", "at2", 5, 1), ("taft", "taft_1952_s69e.txt",
           "one-column, units: g, dt: 0.01 s", 4, 2),
           ("peknold", "elcentro_1940_ns_peknold.at2", "at2", 6, 0),
           ("ngawest2", "elcentro_1940_ns_ngawest2.at2", "at2", 5, 6),
           ("taft-late", "taft_1952_s69e.txt", "one-column, units: g, dt: 0.01 s", 5, 9)]


def motions(peak):
    lines = ["motions:"]
    for name, rec, fmt, f_hz, t0 in WINDOWS:
        lines.append(f"  - {{type: record, name: {name}, file: {src}/cases/records/{rec}, "
                     f"format: {fmt}, building: {{frequency: {f_hz} Hz, damping: 5 %}}, "
                     f"peak: {peak}, window: [{t0} s, {t0 + 5} s]}}")
    return "\n".join(lines) + "\n"


base = os.path.join(scratch, "base.yaml")
with open(base, "w") as f:
    f.write(f"extends: {src}/cases/base/reference-cabinet.yaml\nname: base\n"
            + motions("3.5 g") + "design:\n  scan_end: 1.0\n"
            "analysis:\n  stretch_past_failure: true\n")


def u(a, b, fmt="{:.4g}"):
    return fmt.format(rng.uniform(a, b))


# column -> (case key path, value drawn)
def draw_row(i):
    row = {"tag": f"R-{i:02d}"}
    if rng.random() < 0.7:
        row["mass"] = f"{u(300, 700)} kg"
    if rng.random() < 0.5:
        row["diameter"] = f"{u(10, 16)} mm"
    if rng.random() < 0.5:
        row["yield_stress"] = f"{u(248, 400)} MPa"
    if rng.random() < 0.6:
        row["gap_ratio"] = rng.choice(["0", u(0.002, 0.025)])
    if rng.random() < 0.4:
        row["damping"] = f"{u(1, 5)} %"
    if rng.random() < 0.4:
        row["criterion"] = rng.choice(["no-yield", "no-break"])
    if rng.random() < 0.3:
        row["usage_limit"] = u(0.4, 1.0)
    if rng.random() < 0.5:
        row["peak"] = f"{u(1.2, 7)} g"
    return row


KEYS = {"mass": ("equipment", "mass"), "damping": ("equipment", "damping"),
        "diameter": ("anchorage", "diameter"), "yield_stress": ("anchorage", "yield_stress"),
        "bolt_model": ("anchorage", "model"), "gap_ratio": (None, "gap_ratio"),
        "criterion": ("criteria", "kind"), "usage_limit": ("criteria", "usage_limit")}


def row_case(row):
    """The row as a case file: the base extended by the row's values."""
    sections = {}
    top = [f"extends: {base}", f"name: {row['tag']}"]
    for col, v in row.items():
        if col in KEYS:
            sec, key = KEYS[col]
            if sec:
                sections.setdefault(sec, []).append(f"  {key}: {v}")
            else:
                top.append(f"{key}: {v}")
    for sec, lines in sections.items():
        top += [f"{sec}:"] + lines
    text = "\n".join(top) + "\n"
    if "peak" in row:
        text += motions(row["peak"])
    p = os.path.join(scratch, row["tag"] + ".yaml")
    with open(p, "w") as f:
        f.write(text)
    return p


rows = [draw_row(i) for i in range(n)]
rows.append({"tag": "FREE", "bolt_model": "none"})
boot_seed = rng.randrange(2 ** 64)
cols = ["tag", "base"] + sorted({c for r in rows for c in r} - {"tag"})
lst = os.path.join(scratch, "list.csv")
with open(lst, "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(cols)
    for r in rows:
        w.writerow([base if c == "base" else r.get(c, "") for c in cols])

outs = {}
for j in ("1", "2"):
    d = os.path.join(scratch, "j" + j)
    os.makedirs(d)
    reports = ["--reports", f"{d}/reports"] if j == "1" else []
    r = run("batch", lst, "--fragility", "--seed", str(boot_seed), "-j", j,
            "--json", f"{d}/b.json", "--csv", f"{d}/b.csv", "--junit", f"{d}/b.xml",
            *reports)
    if r.returncode not in (0, 1):
        fail(f"batch -j {j}: exit {r.returncode}: {r.stderr.strip()[:400]}")
        print(f"seed {seed}")
        sys.exit(1)
    with open(f"{d}/table.txt", "w") as f:
        f.write(r.stdout)
    outs[j] = d
for name in ("b.json", "b.csv", "b.xml", "table.txt"):
    a, b = (open(os.path.join(outs[j], name), "rb").read() for j in ("1", "2"))
    if a != b:
        fail(f"{name} differs between -j 1 and -j 2")

# two shards merged give the whole list's JSON
for k in ("1", "2"):
    r = run("batch", lst, "--fragility", "--seed", str(boot_seed), "--shard", f"{k}/2",
            "-q", "--json", os.path.join(scratch, f"s{k}.json"))
    if r.returncode not in (0, 1):
        fail(f"shard {k}/2: exit {r.returncode}: {r.stderr.strip()[:300]}")
merged = os.path.join(scratch, "merged.json")
r = run("merge", os.path.join(scratch, "s1.json"), os.path.join(scratch, "s2.json"),
        "-q", "--json", merged)
if r.returncode not in (0, 1) or not os.path.exists(merged) or \
        open(merged, "rb").read() != open(os.path.join(outs["1"], "b.json"), "rb").read():
    fail(f"merged shards differ from the whole list (exit {r.returncode}) "
         f"{r.stderr.strip()[:300]}")

summary = json.load(open(os.path.join(outs["1"], "b.json")))
if summary.get("fragility", {}).get("seed") != str(boot_seed):
    fail(f"the summary's seed {summary.get('fragility')} is not {boot_seed}")
by_tag = {c["tag"]: c for c in summary["cases"]}
compared = 0
for row in rows:
    c = by_tag.get(row["tag"])
    if not c or c["verdict"] not in ("pass", "fail"):
        fail(f"{row['tag']}: not solved in the batch: {c and c.get('reason')}")
        continue
    bf = c.get("fragility")
    p = row_case(row)
    fj = os.path.join(scratch, row["tag"] + ".fragility.json")
    r = run("fragility", p, "--seed", str(boot_seed), "--json", fj, "-q")
    if row.get("bolt_model") == "none":
        if r.returncode != 2 or os.path.exists(fj) or "needs bolts" not in r.stderr:
            fail(f"{row['tag']}: fragility of a free-standing case: exit {r.returncode}")
        if not bf or "needs bolts" not in bf.get("error", ""):
            fail(f"{row['tag']}: the batch row gives {bf}, not why it has no fragility")
        continue
    if r.returncode != 0:
        fail(f"{row['tag']}: fragility exit {r.returncode}: {r.stderr.strip()[:300]}")
        continue
    # --reports holds the command's own fragility report, byte for byte
    rdir = os.path.join(outs["1"], "reports")
    got_rep = [x for x in os.listdir(rdir) if x.endswith(f"-{row['tag']}.fragility.json")]
    if len(got_rep) != 1 or \
            open(os.path.join(rdir, got_rep[0]), "rb").read() != open(fj, "rb").read():
        fail(f"{row['tag']}: --reports {got_rep} is not `fragility --json`'s report")
    want = json.load(open(fj))
    if not bf or "limit_states" not in bf:
        fail(f"{row['tag']}: no fragility in the batch row: {bf}")
        continue
    for key in ("g_mps2", "level_mps2"):
        if bf[key] != want[key]:
            fail(f"{row['tag']}: {key} {bf[key]!r}, fragility {want[key]!r}")
    for got, ls in zip(bf["limit_states"], want["limit_states"]):
        name = ls["limit_state"]
        reached = sum(not m["censored"][name] for m in want["motions"])
        if got["limit_state"] != name or got["fitted"] != ls["fitted"] \
                or got["reached"] != reached:
            fail(f"{row['tag']}: {name}: batch {got}, fragility fitted {ls['fitted']}, "
                 f"reached {reached}")
            continue
        for key in ("confirmed", "model_limited"):
            if got.get(key) != ls[key]:
                fail(f"{row['tag']}: {name}: {key} {got.get(key)!r}, fragility {ls[key]!r}")
        for key in ("median_mps2", "beta", "median_lo_mps2", "median_hi_mps2",
                    "p_at_level"):
            if ls["fitted"] and got[key] != ls[key]:
                fail(f"{row['tag']}: {name}: {key} {got[key]!r}, fragility {ls[key]!r}")
        compared += ls["fitted"]
# in Sa(f0): batch --intensity sa against fragility --intensity sa, row by row
sa_json = os.path.join(scratch, "sa.json")
r = run("batch", lst, "--fragility", "--seed", str(boot_seed), "--intensity", "sa", "-q",
        "--json", sa_json)
sa_compared = 0
if r.returncode not in (0, 1) or not os.path.exists(sa_json):
    fail(f"batch --intensity sa: exit {r.returncode}: {r.stderr.strip()[:300]}")
else:
    sa = json.load(open(sa_json))
    if sa.get("fragility", {}).get("intensity") != "spectral_acceleration":
        fail(f"the Sa summary's head says {sa.get('fragility')}")
    sa_cases = {c["tag"]: c for c in sa["cases"]}
    for row in rows:
        if row.get("bolt_model") == "none":
            continue
        bf = sa_cases.get(row["tag"], {}).get("fragility", {})
        fj = os.path.join(scratch, row["tag"] + ".sa.json")
        r = run("fragility", row_case(row), "--seed", str(boot_seed), "--intensity", "sa",
                "--json", fj, "-q")
        if r.returncode != 0 or "limit_states" not in bf:
            fail(f"{row['tag']}: Sa: fragility exit {r.returncode}, batch {bf}")
            continue
        want = json.load(open(fj))
        for key in ("level_mps2", "g_mps2"):
            if bf[key] != want[key]:
                fail(f"{row['tag']}: Sa {key} {bf[key]!r}, fragility {want[key]!r}")
        if bf.get("intensity_freq_hz") != want["intensity_freq_hz"]:
            fail(f"{row['tag']}: Sa at {bf.get('intensity_freq_hz')} Hz, fragility at "
                 f"{want['intensity_freq_hz']} Hz")
        # restated, not the pfa numbers again
        if bf["level_mps2"] == by_tag[row["tag"]]["fragility"]["level_mps2"]:
            fail(f"{row['tag']}: the Sa level is the pfa level")
        for got, ls in zip(bf["limit_states"], want["limit_states"]):
            for key in ("fitted", "median_mps2", "beta", "median_lo_mps2", "median_hi_mps2",
                        "p_at_level"):
                if got.get(key) != ls.get(key) and (ls["fitted"] or key == "fitted"):
                    fail(f"{row['tag']}: Sa {ls['limit_state']}: {key} {got.get(key)!r}, "
                         f"fragility {ls.get(key)!r}")
            sa_compared += ls["fitted"]
print(f"{sa_compared} fitted limit states compared in Sa(f0)")
if sa_compared < len(rows):
    fail(f"only {sa_compared} fitted limit states in Sa: the rows test too little")

# one case alone: its searches get both threads, not one
one = {}
for j in ("1", "2"):
    out = os.path.join(scratch, f"one-j{j}.json")
    r = run("batch", row_case(rows[0]), "--fragility", "--seed", str(boot_seed), "-j", j,
            "-q", "--json", out)
    one[j] = open(out, "rb").read() if os.path.exists(out) else b"exit %d" % r.returncode
if one["1"] != one["2"]:
    fail("a one-case batch differs between -j 1 and -j 2")

# the comparison can see a wrong seed: another seed moves an interval
p = row_case(rows[0])
fj = os.path.join(scratch, "other-seed.json")
r = run("fragility", p, "--seed", str((boot_seed + 1) % 2 ** 64), "--json", fj, "-q")
if r.returncode == 0:
    other = json.load(open(fj))["limit_states"]
    mine = by_tag[rows[0]["tag"]]["fragility"]["limit_states"]
    if all(a.get("median_lo_mps2") == b.get("median_lo_mps2")
           and a.get("median_hi_mps2") == b.get("median_hi_mps2")
           for a, b in zip(mine, other)):
        fail("the intervals do not depend on the seed: the test could not see a wrong one")
else:
    fail(f"fragility with another seed: exit {r.returncode}")
print(f"{compared} fitted limit states of {len(rows)} rows compared, seed {boot_seed}")
if compared < len(rows):
    fail(f"only {compared} fitted limit states: the rows test too little")
print(f"seed {seed}: {len(failures)} failures")
sys.exit(1 if failures else 0)
