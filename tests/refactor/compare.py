#!/usr/bin/env python3
"""Compare the JSON reports of two builds over every case, number by number:
what a change that moves results at the rounding level (a new evaluation
order, a value read from a series instead of a closed form) must show
before the digests of reports.sha256 are recorded anew.

    python3 tests/refactor/compare.py OLD_ROCKBOLT NEW_ROCKBOLT SCRATCH [CASE...]

Run from the source root. Prints each case whose exit code or verdict
differs (and exits 1 if any does), then the largest relative change of
every report key over all cases, largest first, with the case it is
from. Relative changes are |new - old| / max(|old|, |new|, 1e-300)."""
import os, sys
from report_json import check_report, flat

old_rb, new_rb, scratch = (os.path.abspath(a) for a in sys.argv[1:4])
cases = sys.argv[4:]
if not cases:
    for root in ("cases", "tests"):
        for d, _, files in os.walk(root):
            if "fuzz" in d:
                continue
            cases += [os.path.join(d, f) for f in files if f.endswith(".yaml")]
    cases.sort()
os.makedirs(scratch, exist_ok=True)


def run(rb, case, tag):
    return check_report(rb, case, os.path.join(scratch, tag + ".json"), 60)


def generic(key):
    """motions[3].bolts.usage[1] -> motions[].bolts.usage[]"""
    out, skip = [], False
    for ch in key:
        if ch == "[":
            skip = True
            out.append("[]")
        elif ch == "]":
            skip = False
        elif not skip:
            out.append(ch)
    return "".join(out)


worst, differ = {}, []
for case in cases:
    (rc0, a), (rc1, b) = run(old_rb, case, "old"), run(new_rb, case, "new")
    if rc0 != rc1:
        differ.append(f"{case}: exit {rc0} -> {rc1}")
    if a is None or b is None:
        continue
    fa, fb = dict(flat(a)), dict(flat(b))
    for k in fa.keys() | fb.keys():
        x, y = fa.get(k), fb.get(k)
        if x == y:
            continue
        if isinstance(x, (int, float)) and isinstance(y, (int, float)) \
                and not isinstance(x, bool) and not isinstance(y, bool):
            rel = abs(y - x) / max(abs(x), abs(y), 1e-300)
        else:
            if "pass" in k or "verdict" in k or "status" in k:
                differ.append(f"{case}: {k}: {x!r} -> {y!r}")
            rel = float("inf")
        g = generic(k)
        if rel > worst.get(g, (0, ""))[0]:
            worst[g] = (rel, case, x, y)

for line in differ:
    print("DIFFERS", line)
print(f"{len(cases)} cases; keys that moved, largest relative change first:")
for g, (rel, case, x, y) in sorted(worst.items(), key=lambda kv: -kv[1][0]):
    print(f"  {rel:9.2e}  {g}  ({case}: {x!r} -> {y!r})")
sys.exit(1 if differ else 0)
