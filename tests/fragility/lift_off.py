#!/usr/bin/env python3
"""The lift-off capacity against a brute-force scan (docs/fragility.md,
"Fewer runs").

    python3 tests/fragility/lift_off.py ROCKBOLT SCRATCH

Run from the source root. Over random cabinets (mass, frame frequency,
gap ratio, bolt size) under windows of the shipped records through random
buildings, `rockbolt fragility` gives each motion's lift-off capacity. The
search starts its bracket at the uplift level of one held run; this test
does not: with `rockbolt check` alone it scans down from the capacity in
steps of the search's resolution (1e-5 A*) until a run whose base never
lifts (below that level the response is linear and the base stays on the
floor, so nothing lower can lift off). The capacity must fail (least
vertical reaction at or below zero) and every level of the scan pass: the
capacity is the first failing level to the search's own resolution, which
is what the old bisection from 0 promised. The first-yield capacities are
held to `rockbolt design`'s no-yield search by tests/fragility/fragility.py."""
import json, os, random, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, failures, finish, run, src, start, write  # noqa: E402

rb, scratch = start()
RES = 1e-5       # the lift-off search's resolution, in A*
MAX_SCAN = 60    # levels scanned down before giving up on a case
RECORDS = [
    "{type: record, name: %s, file: %s/cases/records/elcentro_1940_ns.at2, format: at2",
    "{type: record, name: %s, file: %s/cases/records/taft_1952_s69e.txt, format: "
    "one-column, units: g, dt: 0.01 s",
    "{type: record, name: %s, file: %s/cases/records/elcentro_1940_ns_peknold.at2, "
    "format: at2",
]


def motion(name, rec, bf, t0, peak):
    return (RECORDS[rec] % (name, src) + ", building: {frequency: %.4g Hz, damping: 5 %%}, "
            "window: [%.3g s, %.3g s], peak: %s}" % (bf, t0, t0 + 6, peak))


def case(name, body, motions):
    return write(name + ".yaml", "extends: %s/cases/base/reference-cabinet.yaml\nname: %s\n"
                 "%smotions:\n%sanalysis:\n  stretch_past_failure: true\n"
                 "design:\n  scan_end: 0.3\n" % (src, name, body,
                                                  "".join("  - %s\n" % m for m in motions)))


def lifts(body, m, level_astar, i):
    """(least vertical reaction over W, uplifts) of a check run at a level."""
    j = os.path.join(scratch, "c%d.json" % i)
    p = case("c%d" % i, body, [m.replace("PEAK", "%.12g A*" % level_astar)])
    r = run("check", p, "--json", j, "-q")
    if not os.path.exists(j):
        fail("check %s: exit %d %s" % (p, r.returncode, r.stderr[:200]))
        return None
    mo = json.load(open(j))["motions"][0]
    return (mo["validity"]["lift_off"]["min_vertical_reaction_over_w"],
            mo["result"]["outcome"]["uplifts"])


rng = random.Random(41)
checked = scans = 0
for n in range(6):
    body = ("equipment:\n  mass: %.5g kg\n  frequency: %.4g Hz\ngap_ratio: %.4g\n"
            "anchorage:\n  diameter: %.4g mm\n"
            % (rng.uniform(250, 900), rng.uniform(3, 10), rng.uniform(0.003, 0.02),
               rng.choice([9.5, 12.7, 15.9])))
    ms = [motion("m%d" % k, rng.randrange(3), rng.uniform(2, 8), rng.uniform(0, 10), "PEAK")
          for k in range(2)]
    fj = os.path.join(scratch, "f%d.json" % n)
    p = case("f%d" % n, body, [m.replace("PEAK", "0.2 A*") for m in ms])
    r = run("fragility", p, "--json", fj, "-q", "-j", "2")
    if r.returncode:
        fail("fragility %s: exit %d %s" % (p, r.returncode, r.stderr[:300]))
        continue
    fr = json.load(open(fj))
    a_star = fr["a_star_mps2"]
    for k, m in enumerate(ms):
        got = fr["motions"][k]
        if got["censored"]["lift-off"]:
            continue
        cap = got["capacity_mps2"]["lift-off"] / a_star
        at = lifts(body, m, cap, 0)
        if at is None:
            continue
        checked += 1
        if not at[0] <= 0:
            fail("case %d motion %d: the capacity %.9g A* does not lift off (%.4g W)"
                 % (n, k, cap, at[0]))
        for j in range(1, MAX_SCAN + 1):
            lv = cap - j * RES
            below = lifts(body, m, lv, 1)
            if below is None:
                break
            scans += 1
            if below[0] <= 0:
                fail("case %d motion %d: %.9g A*, %d resolutions below the capacity, lifts "
                     "off already (%.4g W)" % (n, k, lv, j, below[0]))
                break
            if below[1] == 0:
                break
        else:
            fail("case %d motion %d: still rocking %d resolutions below the capacity"
                 % (n, k, MAX_SCAN))
if checked < 8:
    fail("only %d capacities checked" % checked)
finish("%d lift-off capacities scanned down to the floor (%d runs), %d failures"
       % (checked, scans, len(failures)))
