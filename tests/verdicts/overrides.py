#!/usr/bin/env python3
"""Equipment-list columns against every form of a base's motion.

    python3 tests/verdicts/overrides.py ROCKBOLT SCRATCH_DIR

Run from the source root. For each base in tests/verdicts/bases and each
motion column, a row that restates the base's own value must give exactly
the numbers `rockbolt check` gives on the base, motion by motion; a column
that cannot apply to the base must be an error at the row (exit 2, the
list's file:line on stderr), never a silent change of the motions."""
import json, os, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, failures, start  # noqa: E402

rb, scratch = start()
bases = os.path.abspath("tests/verdicts/bases")

# column -> the base's own value, restated
RESTATE = {"motion": "elcentro", "peak": "0.3 A*", "amplitude": "0.6 A*",
           "building_frequency": "5 Hz", "building_damping": "5 %"}
# base -> {column: "same" | "error"}; columns not named are not tried
EXPECT = {
    "single-record": {"motion": "same", "peak": "same", "building_frequency": "same",
                      "building_damping": "same", "amplitude": "error"},
    "list-records": {"motion": "error", "peak": "same", "building_frequency": "same",
                     "building_damping": "same", "amplitude": "error"},
    "single-harmonic": {"amplitude": "same", "peak": "error",
                        "building_frequency": "error"},
    "list-harmonics": {"amplitude": "same", "peak": "error", "building_damping": "error",
                       "motion": "error"},
    "list-mixed": {"motion": "error", "peak": "error", "amplitude": "error",
                   "building_frequency": "error"},
}
FIELDS = ("usage", "shear_over_w", "force_over_fy", "theta_over_alpha")
def check_numbers(base):
    out = os.path.join(scratch, base + ".check.json")
    p = subprocess.run([rb, "check", os.path.join(bases, base + ".yaml"), "--json", out,
                        "--quiet"], capture_output=True, text=True)
    if p.returncode not in (0, 1):
        fail(f"check {base}: exit {p.returncode}: {p.stderr.strip()}")
        return None
    runs = []
    for m in json.load(open(out))["motions"]:
        res = m["result"]
        fy = res["peaks"]["max_bolt_force_over_fy"]
        runs.append({"usage": max(res["bolts"]["usage"].values()),
                     "shear_over_w": res["peaks"]["max_shear_elastic_over_w"],
                     "force_over_fy": max(fy.values()),
                     "theta_over_alpha": res["peaks"]["max_theta_over_alpha"],
                     "pass": m["verdict"]["pass"]})
    return runs


for base, columns in EXPECT.items():
    want = check_numbers(base)
    if want is None:
        continue
    for col, expect in columns.items():
        lst = os.path.join(scratch, f"{base}-{col}.csv")
        with open(lst, "w") as f:
            f.write(f"tag,base,{col}\nrow,{os.path.join(bases, base + '.yaml')},"
                    f"{RESTATE[col]}\n")
        out = os.path.join(scratch, f"{base}-{col}.json")
        if os.path.exists(out):
            os.remove(out)
        p = subprocess.run([rb, "batch", lst, "--json", out, "--quiet"],
                           capture_output=True, text=True)
        what = f"{base} + {col}"
        if expect == "error":
            if p.returncode != 2:
                fail(f"{what}: exit {p.returncode}, expected 2 (the column cannot apply)")
            elif f"{lst}:2:" not in p.stderr:
                fail(f"{what}: the error does not point at the row: {p.stderr.strip()}")
            else:
                print(f"ok {what}: refused at the row: {p.stderr.strip().splitlines()[0]}")
            continue
        if p.returncode not in (0, 1):
            fail(f"{what}: exit {p.returncode}: {p.stderr.strip()}")
            continue
        runs = json.load(open(out))["cases"][0]["runs"]
        if len(runs) != len(want):
            fail(f"{what}: {len(runs)} motions, the base has {len(want)}")
            continue
        for i, (r, w) in enumerate(zip(runs, want)):
            for k in FIELDS:
                if r[k] != w[k]:
                    fail(f"{what}: motion {i + 1} {k} = {r[k]!r}, check on the base "
                         f"gives {w[k]!r}")
            if (r["verdict"] == "pass") != w["pass"]:
                fail(f"{what}: motion {i + 1} verdict {r['verdict']}, check says "
                     f"{'pass' if w['pass'] else 'fail'}")
        print(f"ok {what}: {len(runs)} motion(s) as check on the base")

print(f"{sum(len(c) for c in EXPECT.values()) - len(failures)} passed, "
      f"{len(failures)} failed")
sys.exit(1 if failures else 0)
