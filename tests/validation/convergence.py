#!/usr/bin/env python3
"""The floor between samples: a record with samples inserted on its own
straight lines (dt/10) is the same ground motion, so it must give the same
results.

    python3 tests/validation/convergence.py ROCKBOLT SCRATCH

Run from the source root. For every shipped record, without a building
(the record is the floor itself) and through 5, 8 and 10 Hz buildings, the
reference cabinet at 0.3 A* is checked on the record as read and on the
record with nine samples inserted between each two, both written as one
column in g. Asserted: the same verdict, and every governing result
(rotation, frame deflection and elastic shear, the floor's peak, each
row's usage, absorbed energy, final gap, first yield and break times, the
overturning time) and every peak (total shear, bolt force, friction
demand and least floor reaction, located between the check points of a
step) within 1e-6 relative. Printed, not asserted: the largest relative
change of every other number (energies, counts, times spent in a stage
or off the floor), which docs/solver.md discusses."""
import json, os, shutil, subprocess, sys

rb, scratch = (os.path.abspath(a) for a in sys.argv[1:3])
src = os.getcwd()
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)
records = [  # file, dt when the file does not say
    ("elcentro_1940_ns.at2", None),
    ("elcentro_1940_ns_ngawest2.at2", None),
    ("elcentro_1940_ns_peknold.at2", None),
    ("taft_1952_s69e.txt", 0.01),
]
buildings = [0, 5, 8, 10]
GOVERNING = ("peaks.", "constants.peak_floor_mps2", "bolts.usage", "bolts.absorbed_j",
             "bolts.final_gap_m", "bolts.first_yield_s", "bolts.break_s",
             "outcome.overturn_s")
TOL = 1e-6
failures = []


def read(path, dt):
    lines = open(path).read().splitlines()
    if path.endswith(".at2"):
        head = next(l for l in lines[:6] if "DT=" in l)
        dt = float(head.split("DT=")[1].split()[0].rstrip(","))
        start = lines.index(head) + 1
        return dt, [float(x) for l in lines[start:] for x in l.split()]
    return dt, [float(x) for l in lines for x in l.split()]


def write(path, vals):
    with open(path, "w") as f:
        f.write("\n".join(repr(v) for v in vals) + "\n")


def flat(o, p=""):
    if isinstance(o, dict):
        for k, v in o.items():
            yield from flat(v, f"{p}.{k}" if p else k)
    elif not isinstance(o, list):
        yield p, o


def case(path, rec, dt, building):
    b = (f"  building:\n    frequency: {building} Hz\n    damping: 5 %\n" if building
         else "")
    with open(path, "w") as f:
        f.write(f"extends: {src}/cases/base/reference-cabinet.yaml\nname: conv\nmotion:\n"
                f"  type: record\n  file: {rec}\n  format: one-column\n  units: g\n"
                f"  dt: {dt!r} s\n{b}  peak: 0.3 A*\n")


def run(yaml):
    out = yaml[:-5] + ".json"
    r = subprocess.run([rb, "check", yaml, "--json", out], capture_output=True, text=True)
    if r.returncode not in (0, 1):
        failures.append(f"{yaml}: exit {r.returncode}: {r.stderr.strip()[:200]}")
        return None
    return json.load(open(out))["motions"][0]


for name, dt0 in records:
    dt, vals = read(os.path.join(src, "cases", "records", name), dt0)
    fine = []
    for a, b in zip(vals, vals[1:]):
        fine += [a + (b - a) * j / 10 for j in range(10)]
    fine.append(vals[-1])
    coarse_file = os.path.join(scratch, name + ".txt")
    fine_file = os.path.join(scratch, name + ".fine.txt")
    write(coarse_file, vals)
    write(fine_file, fine)
    for building in buildings:
        tag = f"{name} {'no building' if not building else f'{building} Hz building'}"
        a_yaml = os.path.join(scratch, f"{name}-{building}.yaml")
        b_yaml = os.path.join(scratch, f"{name}-{building}-fine.yaml")
        case(a_yaml, coarse_file, dt, building)
        case(b_yaml, fine_file, dt / 10, building)
        a, b = run(a_yaml), run(b_yaml)
        if not a or not b:
            continue
        if a["verdict"]["pass"] != b["verdict"]["pass"]:
            failures.append(f"{tag}: verdict {a['verdict']['pass']} -> {b['verdict']['pass']}")
        fa, fb = dict(flat(a["result"])), dict(flat(b["result"]))
        gov, other = (0.0, ""), (0.0, "")
        for k, x in fa.items():
            y = fb.get(k)
            if isinstance(x, bool) or not isinstance(x, (int, float)) \
                    or not isinstance(y, (int, float)) or k.startswith("cost."):
                if x != y and k in GOVERNING:
                    failures.append(f"{tag}: {k} {x} -> {y}")
                continue
            d = 0.0 if x == y else abs(x - y) / max(abs(x), abs(y))
            if k.startswith(GOVERNING):
                gov = max(gov, (d, k))
                if d > TOL:
                    failures.append(f"{tag}: {k} {x} -> {y} ({d:.2e} relative)")
            else:
                other = max(other, (d, k))
        print(f"{tag}: governing within {gov[0]:.1e} ({gov[1] or '-'}); "
              f"others within {other[0]:.1e} ({other[1] or '-'})")

for f in failures:
    print("FAIL:", f)
print(f"{len(records) * len(buildings)} record x building pairs, {len(failures)} failures")
sys.exit(1 if failures else 0)
