#!/usr/bin/env python3
"""The fragility's searches with fewer runs (docs/fragility.md, "Fewer runs").

    python3 tests/fragility/fewer_runs.py ROCKBOLT SCRATCH

Run from the source root. On cases/fragility-suite.yaml (criterion
no-break) and the same suite judged by no-yield, asserts that
  - each motion's usage and first-yield capacity is, to the search's
    resolution (design.resolution in A*), the failing end of the design
    factor `design` finds for that motion under no-break and no-yield: the
    design factor is the plain scan and bisection, confirmed, so the
    secant that narrows the fragility's brackets moves no capacity by more
    than the resolution, and the governing state's confirmation is
    design's;
  - the governing state is the judged state of the lowest median (usage
    under no-break, first-yield under no-yield), and under no-yield its
    capacities are design's no-yield failing ends to the resolution (it is
    confirmed there, where under no-break it is not);
  - each capacity fails where `check` judges it: at the usage capacity
    with the case's criterion, the usage reaches 1 (or the cabinet
    overturns); at the first-yield capacity, a row yields or reaches Fy;
  - and is a crossing by `check` alone, not by another search: one
    resolution below it the state is not reached (design's factors take
    the same secant as the fragility's searches, so agreeing with them
    does not prove the secant right; `check` at both ends does);
  - every capacity and the governing state are the same with one thread
    and with two (the confirmation's second round of searches included)."""
import json, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, finish, run, src, start, write  # noqa: E402

rb, scratch = start()
SUITE = os.path.join(src, "cases", "fragility-suite.yaml")
noyield = write("noyield.yaml", f"extends: {SUITE}\nname: suite-noyield\n"
                "criteria: {kind: no-yield}\n")


def load(args, name):
    out = os.path.join(scratch, name)
    r = run(*args, "--json", out, "-q")
    if r.returncode not in (0, 1):
        fail(f"{' '.join(args)}: exit {r.returncode}: {r.stderr.strip()[:300]}")
        finish()
    return json.load(open(out))


design = load(("design", SUITE, "-j", "2"), "design.json")
factors = [m["design"]["design_factor"] for m in design["motions"]]
res = factors[0]["no_break"]["resolution_astar"]

for case, judged, governs in ((SUITE, ["usage", "overturn"], "usage"),
                              (noyield, ["first-yield", "overturn"], "first-yield")):
    tag = os.path.basename(case)
    fr = load(("fragility", case, "-j", "2"), f"{tag}.json")
    one = load(("fragility", case, "-j", "1"), f"{tag}.1.json")
    astar = fr["a_star_mps2"]
    tol = res * astar * (1 + 1e-9)
    if fr["judged_limit_states"] != judged or fr["governing_limit_state"] != governs:
        fail(f"{tag}: judged {fr['judged_limit_states']}, governing "
             f"{fr['governing_limit_state']}; want {judged}, {governs}")
    medians = {s["limit_state"]: s["median_mps2"] for s in fr["limit_states"] if s["fitted"]}
    if min(judged, key=lambda k: medians[k]) != governs:
        fail(f"{tag}: {governs} governs but the lowest judged median is another: {medians}")
    if [m["capacity_mps2"] for m in one["motions"]] != [m["capacity_mps2"] for m in
                                                        fr["motions"]] \
            or one["governing_limit_state"] != fr["governing_limit_state"]:
        fail(f"{tag}: the capacities differ between one thread and two")
    for fm, df in zip(fr["motions"], factors):
        for state, crit in (("usage", "no_break"), ("first-yield", "no_yield")):
            cap, want = fm["capacity_mps2"][state], df[crit]["fail_mps2"]
            if fm["censored"][state] or abs(cap - want) > tol:
                fail(f"{tag} {fm['name']}: {state} capacity {cap / astar:.6f} A*, design's "
                     f"{crit} fails at {want / astar:.6f} A* (resolution {res} A*)")
        if case != SUITE:
            continue
        # check at each capacity: the state is reached there
        line = [ln for ln in open(SUITE).read().splitlines()
                if f"name: {fm['name']}," in ln][0]
        for state in ("usage", "first-yield"):
            for below in (0, 1):
                level = fm["capacity_mps2"][state] - below * res * astar
                at = write(f"{fm['name']}-{state}-{below}.yaml",
                           f"extends: {SUITE}\nname: at\nmotions:\n"
                           + line.replace("peak: 0.4 A*", f"peak: {level!r} m/s^2")
                           .replace("file: records/", f"file: {src}/cases/records/") + "\n")
                cj = at[:-5] + ".json"
                r = run("check", at, "--json", cj, "-q")
                if r.returncode not in (0, 1):
                    fail(f"{at}: check exit {r.returncode}: {r.stderr.strip()[:300]}")
                    continue
                res_ = json.load(open(cj))["motions"][0]["result"]
                bolts, out = res_["bolts"], res_["outcome"]
                if state == "usage":
                    reached = max(bolts["usage"].values()) >= 1 or out["overturned"]
                else:
                    fy = res_["constants"]["fy_row_n"]
                    reached = any(bolts["yielded"].values()) or \
                        max(res_["peaks"]["max_bolt_force_n"].values()) >= fy
                if reached == bool(below):
                    fail(f"{fm['name']}: check {below} resolution(s) below its {state} "
                         f"capacity, at {level / astar:.6f} A*, "
                         f"{'reaches' if below else 'does not reach'} it: usage "
                         f"{bolts['usage']}, yielded {bolts['yielded']}")
finish()
