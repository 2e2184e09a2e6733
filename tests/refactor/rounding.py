#!/usr/bin/env python3
"""Whether the numbers a change moved moved by rounding amplified by the
run itself: for each case, the old build at the case's tolerance against
the new build (the change), and against the old build at a tenth of the
tolerance (how far the run's own numbers are from converged).

    python3 tests/refactor/rounding.py OLD_ROCKBOLT NEW_ROCKBOLT SCRATCH CASE...

Run from the source root. A case whose every moved number moved less
under the change than between the two tolerances is marked "within": its
numbers are not converged to the digits the change touched, and any
change of the order of the additions moves them as much. Others are
marked "beyond", with the key that moved most past its tolerance
scatter. Exit codes and verdicts of the two builds are printed beside.
Relative changes are |b - a| / max(|a|, |b|, 1e-300), over every numeric
key of the JSON report but the solver's settings and step counts (which
say how the run was made, not what it found)."""
import os, sys
from report_json import check_report, flat

old_rb, new_rb, scratch = (os.path.abspath(a) for a in sys.argv[1:4])
cases = sys.argv[4:]
os.makedirs(scratch, exist_ok=True)


def run(rb, case, tag):
    return check_report(rb, case, os.path.join(scratch, tag + ".json"), 300)


def numbers(rep):
    return {k: v for k, v in flat(rep)
            if isinstance(v, (int, float)) and not isinstance(v, bool)
            and not k.startswith("solver.") and "steps" not in k}


def rel(a, b):
    if a is None or b is None:
        return float("inf")
    return abs(b - a) / max(abs(a), abs(b), 1e-300)


def tenth(case, rtol):
    """A case beside CASE that extends it at a tenth of its tolerance."""
    d, base = os.path.split(case)
    path = os.path.join(d, f".{base[:-5]}.tenth.yaml")
    with open(path, "w") as f:
        f.write(f"extends: {base}\nanalysis:\n  tolerance: {rtol / 10:g}\n")
    return path


print("| case | exit old/new | verdict old/new | keys moved | largest move (new vs old) |"
      " largest move (old at tol/10 vs tol) | keys beyond | class |")
print("|---|---|---|---|---|---|---|---|")
beyond_any = False
for case in cases:
    (rc0, a), (rc1, b) = run(old_rb, case, "old"), run(new_rb, case, "new")
    if a is None or b is None:
        print(f"| {case} | {rc0}/{rc1} | | | | | | no report |")
        continue
    na, nb = numbers(a), numbers(b)
    moved = [k for k in na.keys() | nb.keys() if na.get(k) != nb.get(k)]
    if not moved:
        print(f"| {case} | {rc0}/{rc1} | | 0 | | | | unchanged |")
        continue
    t = tenth(case, a["solver"]["rtol"])
    try:
        rc2, c = run(old_rb, t, "tenth")
    finally:
        os.remove(t)
    nc = numbers(c) if c else {}
    worst_new = max(moved, key=lambda k: rel(na.get(k), nb.get(k)))
    worst_tol = max(moved, key=lambda k: rel(na.get(k), nc.get(k)))
    over = [k for k in moved if rel(na.get(k), nb.get(k)) > rel(na.get(k), nc.get(k))]
    # within: the change moves no number more than the tolerance's tenth
    # moves the run's largest-moving number
    m_new, m_tol = rel(na.get(worst_new), nb.get(worst_new)), rel(na.get(worst_tol), nc.get(worst_tol))
    cls = "within" if m_new <= m_tol else f"beyond ({worst_new})"
    beyond_any |= m_new > m_tol
    va, vb = a["verdict"]["result"], b["verdict"]["result"]
    print(f"| {case} | {rc0}/{rc1} | {va}/{vb} | {len(moved)} | {m_new:.2e} ({worst_new}) |"
          f" {m_tol:.2e} | {len(over)} | {cls} |")
sys.exit(1 if beyond_any else 0)
