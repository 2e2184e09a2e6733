#!/usr/bin/env python3
"""How often a signed pass does not hold: the measurement behind the
judge's band and its harmonic rule (docs/report-format.md, "Confirmation").
Not a ctest (minutes, not seconds); run it before changing the judge.

    python3 tests/verdicts/holds.py ROCKBOLT SCRATCH MOTIONS CRITERION N SEED [JOBS]

MOTIONS is `harmonic-pulse` (half a 1-10 Hz harmonic of 0.05-0.7 A* for
15 s, half one pulse of the four shapes, 0.05-1 s, 0.1-3 A*) or
`synthetic` (one AC156 motion, S_DS 0.5-4 g, z/h 0-1, a random seed);
CRITERION is no-break or no-yield. N random cabinets (200-900 kg, 3-15 Hz,
10-16 mm bolts, gap ratios 0.002-0.03, half elastic-plastic) are drawn
with SEED and checked as a user would; each signed pass is solved eight
more times (Taylor steps at 1e-8 to 1e-11, Dormand-Prince at 1e-7 to
1e-10, confirmation off), and a pass that fails in any of them did not
hold. Prints the signed passes by motion kind and convergence status, how
many did not hold, and each that did not, as a case file. A case the
tool refuses (a synthetic seed that does not match) is counted and left
out."""
import json
import os
import random
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

SHAPES = ["rectangular", "half-sine", "triangular-decreasing", "triangular-increasing"]
FURTHER = [("auto", t) for t in (1e-8, 1e-9, 1e-10, 1e-11)] \
    + [("rk45", t) for t in (1e-7, 1e-8, 1e-9, 1e-10)]


def draw(rng, motions, criterion):
    p = {"mass": rng.uniform(200, 900), "f": rng.uniform(3, 15), "dia": rng.uniform(10, 16),
         "gr": rng.uniform(0.002, 0.03),
         "model": rng.choice(["rigid-plastic", "elastic-plastic"]), "crit": criterion}
    if motions == "synthetic":
        p.update(kind="synthetic", sds=rng.uniform(0.5, 4.0), z=rng.uniform(0, 1),
                 seed=rng.randrange(1, 10**6))
    elif rng.random() < 0.5:
        p.update(kind="harmonic", freq=rng.uniform(1, 10), amp=rng.uniform(0.05, 0.7))
    else:
        p.update(kind="pulse", shape=rng.choice(SHAPES), amp=rng.uniform(0.1, 3.0),
                 dur=rng.uniform(0.05, 1.0))
    return p


def case_text(base, p, extra=""):
    t = (f"extends: {base}\nequipment:\n  mass: {p['mass']:.0f} kg\n"
         f"  frequency: {p['f']:.2f} Hz\nanchorage:\n  model: {p['model']}\n"
         f"  diameter: {p['dia']:.1f} mm\ngap_ratio: {p['gr']:.4f}\n"
         f"criteria:\n  kind: {p['crit']}\n")
    if p["kind"] == "synthetic":
        t += (f"motion:\n  type: synthetic\n  spectrum:\n    type: ac156\n"
              f"    sds: {p['sds']:.3f} g\n    z_over_h: {p['z']:.3f}\n  count: 1\n"
              f"  seed: {p['seed']}\n")
    elif p["kind"] == "harmonic":
        t += (f"motion:\n  type: harmonic\n  amplitude: {p['amp']:.3f} A*\n"
              f"  frequency: {p['freq']:.3f} Hz\n  duration: 15 s\n")
    else:
        t += (f"motion:\n  type: pulse\n  shape: {p['shape']}\n  amplitude: {p['amp']:.3f} A*\n"
              f"  duration: {p['dur']:.4f} s\n  run_time: {p['dur'] + 10:.4f} s\n")
    return t + extra


def check(rb, scratch, name, text):
    path = os.path.join(scratch, name + ".yaml")
    out = path + ".json"
    with open(path, "w") as f:
        f.write(text)
    r = subprocess.run([rb, "check", path, "--json", out, "--quiet"], capture_output=True)
    if r.returncode not in (0, 1):
        return None
    with open(out) as f:
        m = json.load(f)["motions"][0]
    os.remove(path)
    os.remove(out)
    return m


def one(args):
    rb, scratch, base, i, p = args
    m = check(rb, scratch, f"c{i}", case_text(base, p))
    if m is None:
        return i, p, None, None, []
    conv = m["validity"]["convergence"]["status"]
    if not m["verdict"]["pass"]:
        return i, p, False, conv, []
    broke = []
    for integ, tol in FURTHER:
        extra = (f"analysis:\n  integrator: {integ}\n  tolerance: {tol:g}\n")
        text = case_text(base, p, extra).replace(
            "criteria:\n", "criteria:\n  confirm: off\n", 1)
        mm = check(rb, scratch, f"c{i}-{integ}-{tol:g}", text)
        if mm is None or not mm["verdict"]["pass"]:
            broke.append(f"{integ} at {tol:g}: "
                         + (mm["verdict"]["reason"] if mm else "not solved"))
    return i, p, True, conv, broke


def main():
    if len(sys.argv) < 7:
        sys.exit(__doc__)
    rb, scratch = (os.path.abspath(a) for a in sys.argv[1:3])
    motions, criterion, n, seed = sys.argv[3], sys.argv[4], int(sys.argv[5]), int(sys.argv[6])
    jobs = int(sys.argv[7]) if len(sys.argv) > 7 else os.cpu_count() or 1
    if motions not in ("harmonic-pulse", "synthetic") or criterion not in ("no-break",
                                                                          "no-yield"):
        sys.exit(__doc__)
    os.makedirs(scratch, exist_ok=True)
    base = os.path.abspath("cases/base/reference-cabinet.yaml")
    rng = random.Random(seed)
    todo = [(rb, scratch, base, i, draw(rng, motions, criterion)) for i in range(n)]
    with ThreadPoolExecutor(jobs) as ex:
        results = list(ex.map(one, todo))
    refused = sum(1 for r in results if r[2] is None)
    signed = [r for r in results if r[2]]
    print(f"{n} cabinets, {motions}, {criterion}: {refused} refused, "
          f"{len(signed)} signed passes")
    groups = {}
    for _, p, _, conv, broke in signed:
        g = groups.setdefault((p["kind"], conv), [0, 0])
        g[0] += 1
        g[1] += bool(broke)
    for (kind, conv), (count, bad) in sorted(groups.items()):
        print(f"  {kind:9s} convergence {conv:11s} {count:5d} passes, {bad} did not hold")
    for i, p, _, _, broke in signed:
        if broke:
            print(f"\ndid not hold ({'; '.join(broke)}):\n" + case_text(base, p))


if __name__ == "__main__":
    main()
