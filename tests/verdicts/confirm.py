#!/usr/bin/env python3
"""The confirmation of a pass (docs/report-format.md, "Confirmation"), end to end.

    python3 tests/verdicts/confirm.py ROCKBOLT JUDGE_PROBE SCRATCH

Run from the source root. On tests/verdicts/cases/marginal-pass.yaml, a
pass at the default tolerance whose usage reaches the limit at a tighter
one, and on shipped cases:
  - unconfirmed (confirm: off) the marginal case passes; confirmed (the
    default) it fails, with the convergence warning and the failing run's
    reason, in check, batch (table, CSV, JSON) and the design's own
    factor alike;
  - each confirming run is what it says: check at that tolerance with
    confirmation off gives the same verdict, usage, force and rotation,
    to the last bit;
  - only a pass within the band of a limit is confirmed (margin as the
    report gives it), every pass with confirm: always, none with off;
  - a pass far from its limits under a record and a fail are not rerun;
    under a harmonic the band is the whole range, so a pass that moved
    is (cases/free-standing.yaml); the confirming tolerances stop at
    1e-13;
  - the design searches end on a confirmed pass: at the ends of each
    final bracket the one judge passes (confirmed) and fails
    (judge_probe --design), also where the search's last pass was not
    confirmed and it went on below it
    (tests/verdicts/cases/design-confirm.yaml);
  - on tests/verdicts/cases/scatter-pass.yaml, whose runs at the
    default rest fraction pass and scatter, the finest confirming run
    (a hundredth of the rest fraction too) breaks a row: check fails it
    naming that run, and with confirm: off it passes;
  - on tests/verdicts/cases/scatter-runs.yaml, whose three runs all
    pass but scatter by more than the least of their margins, the pass
    is not signed: check fails it with the convergence warning and a
    reason naming both margins, each run's margin is check's at its
    tolerance and rest fraction, and with confirm: off it passes;
  - on tests/verdicts/cases/converge-pass.yaml, whose three runs pass
    and lie closer together than it is from the limit but more than
    0.001 apart, the pass is not signed either, unless every run keeps
    the band to spare (confirm: always with a band of 0.12; its finest
    run keeps 0.125);
  - tests/verdicts/cases/wide-band-pass.yaml, 0.29 from the limit, is
    confirmed within the default band of 0.5 and fails (its run at 1e-8
    breaks a row), where a band of 0.25 signed it unconfirmed;
  - tests/verdicts/cases/harmonic-chaos-pass.yaml, a harmonic pass
    0.937 from its nearest limit whose usage scatters with the tolerance
    (Dormand-Prince at 1e-7 breaks its row), is confirmed and fails,
    where unconfirmed it passes;
  - bad values of the two keys are errors naming file, line, key and
    the expected form."""
import csv, json, os, re, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, failures, finish, run, src, start, write  # noqa: E402

rb, probe, scratch = start(3)
MARGINAL = os.path.join(src, "tests/verdicts/cases/marginal-pass.yaml")


def variant(name, criteria="", analysis="", base=MARGINAL):
    text = f"extends: {base}\nname: {name}\n"
    if criteria:
        text += "criteria:\n" + "".join(f"  {line}\n" for line in criteria.split(";"))
    if analysis:
        text += "analysis:\n" + "".join(f"  {line}\n" for line in analysis.split(";"))
    return write(name + ".yaml", text)


def check(path):
    out = os.path.join(scratch, os.path.basename(path) + ".json")
    p = run("check", path, "--json", out, "--quiet")
    if p.returncode not in (0, 1):
        fail(f"{path}: exit {p.returncode}: {p.stderr.strip()}")
        return None, p.returncode
    with open(out) as f:
        return json.load(f), p.returncode


def conv(d, i=0):
    return d["motions"][i]["validity"]["convergence"]


def at(r, runs):
    """Where a run was solved, as a reason names it: the tolerance, and the
    rest fraction where it is not the first confirming run's (the case's)."""
    where = f"{r['tolerance']:.3g}"
    if r["rest_fraction"] != runs[0]["rest_fraction"]:
        where += f" and rest fraction {r['rest_fraction']:.3g}"
    return where


def solved_as(r):
    """The analysis keys that solve a case as the confirming run r was."""
    return f"tolerance: {r['tolerance']:g};rest_fraction: {r['rest_fraction']:g}"


def runs_are_checks(name, runs, base):
    """Each confirming run's margin is check's at that run's tolerance and
    rest fraction, with confirmation off."""
    for r in runs:
        d, _ = check(variant(f"{name}-at-{r['tolerance']:g}", "confirm: off", solved_as(r),
                             base=base))
        if d and conv(d)["margin"] != r["margin"]:
            fail(f"the run at {r['tolerance']:g} has margin {r['margin']}, check at that "
                 f"tolerance and rest fraction {conv(d)['margin']}")


def unconverged(name, path):
    """A case whose three runs all pass but do not converge: unconfirmed it
    passes; confirmed it fails with the convergence warning. Its report,
    convergence check and three margins (None where it could not run)."""
    on, rc = check(path)
    off, rc_off = check(variant(f"{name}-off", "confirm: off", base=path))
    if not (on and off):
        return None, None, None
    c = conv(on)
    margins = [c["margin"]] + [r["margin"] for r in c["runs"]]
    print(f"{name}: margins {margins}; {on['motions'][0]['verdict']['reason']}")
    if rc_off != 0 or off["verdict"]["result"] != "PASS":
        fail(f"unconfirmed, the {name} case should pass: exit {rc_off}")
    if not all(r["pass"] for r in c["runs"]) or len(c["runs"]) != 2:
        fail(f"every confirming run of the {name} case should pass: {c['runs']}")
    if rc != 1 or on["verdict"]["result"] != "FAIL" or c["status"] != "warning" \
            or "convergence" not in on["verdict"]["validity_warnings"]:
        fail(f"the {name} case should fail with a convergence warning: exit {rc}, {c}")
    if off["motions"][0]["result"] != on["motions"][0]["result"]:
        fail(f"confirmation changed the {name} case's reported run")
    return on, c, margins


# 1. the marginal case: a pass unconfirmed, a fail confirmed
off, rc_off = check(variant("off", "confirm: off"))
on, rc_on = check(MARGINAL)
if off and on:
    if rc_off != 0 or off["verdict"]["result"] != "PASS":
        fail(f"unconfirmed, the marginal case should pass: exit {rc_off}, "
             f"{off['verdict']['reason']}")
    if conv(off)["status"] != "not-checked" or conv(off)["runs"]:
        fail(f"confirm: off still confirmed: {conv(off)}")
    if rc_on != 1 or on["verdict"]["result"] != "FAIL":
        fail(f"confirmed, the marginal case should fail: exit {rc_on}")
    if "convergence" not in on["verdict"]["validity_warnings"]:
        fail(f"no convergence warning: {on['verdict']['validity_warnings']}")
    c = conv(on)
    if c["status"] != "warning" or len(c["runs"]) != 2:
        fail(f"convergence check: {c}")
    if [r["tolerance"] for r in c["runs"]] != [1e-8, 1e-9]:
        fail(f"confirming tolerances {[r['tolerance'] for r in c['runs']]}, "
             "expected a tenth and a hundredth of 1e-7")
    # the case's rest fraction, then a hundredth of it in the last run
    rest = on["solver"]["rest_fraction"]
    if rest != 1e-6 or [r["rest_fraction"] for r in c["runs"]] != [1e-6, 1e-8]:
        fail(f"confirming rest fractions {[r['rest_fraction'] for r in c['runs']]} "
             f"(case {rest}), expected 1e-6 and a hundredth of it")
    failing = [r for r in c["runs"] if not r["pass"]]
    if not failing:
        fail("no confirming run fails")
    elif not on["motions"][0]["verdict"]["reason"].startswith(
            f"not confirmed: at tolerance {at(failing[0], c['runs'])} (auto), "
            + failing[0]["reason"]):
        fail(f"reason '{on['motions'][0]['verdict']['reason']}' does not name the "
             f"failing run ({failing[0]})")
    # the run as solved is the same with and without confirmation
    if on["motions"][0]["result"] != off["motions"][0]["result"]:
        fail("confirmation changed the reported run")
    if abs(c["margin"] - (1 - on["motions"][0]["result"]["bolts"]["usage"]["right"])) > 1e-15:
        fail(f"margin {c['margin']} is not 1 - the usage")

    # 2. each confirming run is check at its tolerance and rest fraction
    for r in c["runs"]:
        d, _ = check(variant(f"at-{r['tolerance']:g}", "confirm: off", solved_as(r)))
        if not d:
            continue
        res = d["motions"][0]["result"]
        same = (d["verdict"]["result"] == ("PASS" if r["pass"] else "FAIL")
                and max(res["bolts"]["usage"].values()) == r["usage"]
                and max(res["peaks"]["max_bolt_force_over_fy"].values())
                == r["max_bolt_force_over_fy"]
                and res["peaks"]["max_theta_over_alpha"] == r["max_theta_over_alpha"])
        if not same:
            fail(f"the confirming run at {r['tolerance']:g} is not check at that "
                 f"tolerance: {r} against {d['verdict']['reason']}")

    # 3. the band: a margin of 0.0166 is outside a band of 0.01
    m = c["margin"]
    narrow, rc = check(variant("narrow", f"confirm_band: {m / 2:.6g}"))
    if narrow and (rc != 0 or conv(narrow)["runs"]):
        fail(f"a band below the margin still confirmed (exit {rc})")
    wide, rc = check(variant("wide", f"confirm_band: {min(1, 2 * m):.6g}"))
    if wide and (rc != 1 or len(conv(wide)["runs"]) != 2):
        fail(f"a band above the margin did not confirm (exit {rc})")

# 4. shipped cases: a confirmed pass stays a pass; a pass far from its
#    limits and a fail are not rerun, but are with confirm: always
taft, rc = check(os.path.join(src, "cases/reference-taft.yaml"))
if taft:
    c = conv(taft)
    if not (rc == 0 and c["margin"] < c["band"] and c["status"] == "ok"
            and all(r["pass"] for r in c["runs"]) and len(c["runs"]) == 2):
        fail(f"reference-taft (usage 0.91) should pass confirmed: exit {rc}, {c}")
far, rc = check(os.path.join(src, "cases/thesis/table-5.1-nonyielding-gr0.01.yaml"))
if far:
    c = conv(far)
    if not (rc == 0 and c["band"] == 0.5 and c["margin"] >= c["band"]
            and c["status"] == "not-checked" and not c["runs"]):
        fail(f"table-5.1 at gr 0.01 (margin {c['margin']}) should not be rerun: {c}")
# under a harmonic the band is the whole range: a pass that moved is rerun
free, rc = check(os.path.join(src, "cases/free-standing.yaml"))
if free:
    c = conv(free)
    if not (rc == 0 and c["band"] == 1 and 0.5 < c["margin"] < 1 and c["status"] == "ok"
            and len(c["runs"]) == 2 and all(r["pass"] for r in c["runs"])):
        fail(f"free-standing (a harmonic, margin {c['margin']}) should pass confirmed: {c}")
always, rc = check(variant("always", "confirm: always",
                           base=os.path.join(src, "cases/free-standing.yaml")))
if always and (rc != 0 or conv(always)["status"] != "ok" or len(conv(always)["runs"]) != 2):
    fail(f"confirm: always did not confirm a clear pass: {conv(always)}")
# near the tightest tolerance the runs stop at 1e-13, what doubles can meet
tight, rc = check(variant("tight", "confirm: always", "tolerance: 1e-12",
                          base=os.path.join(src, "cases/free-standing.yaml")))
if tight and [r["tolerance"] for r in conv(tight)["runs"]] != [1e-13, 1e-13]:
    fail(f"confirming tolerances at 1e-12: {[r['tolerance'] for r in conv(tight)['runs']]}")
elc, rc = check(os.path.join(src, "cases/reference-elcentro.yaml"))
if elc and (rc != 1 or conv(elc)["runs"] or conv(elc)["status"] != "not-checked"):
    fail(f"a failing run was rerun: {conv(elc)}")

# 5. batch and design judge the same way
csv_out = os.path.join(scratch, "b.csv")
p = run("batch", MARGINAL, os.path.join(src, "cases/reference-taft.yaml"),
        "--csv", csv_out, "--quiet")
if p.returncode != 1:
    fail(f"batch of the marginal case and taft: exit {p.returncode}, expected 1")
else:
    with open(csv_out) as f:
        rows = {r["tag"]: r for r in csv.DictReader(f)}
    mp = rows.get("marginal-pass", {})
    if mp.get("verdict") != "fail" or "convergence" not in mp.get("validity_warnings", ""):
        fail(f"batch row of the marginal case: {mp}")
    if rows.get("reference-taft", {}).get("verdict") != "pass":
        fail(f"batch row of taft: {rows.get('reference-taft')}")
des = os.path.join(scratch, "design.json")
p = run("design", MARGINAL, "--json", des, "--quiet")
if p.returncode not in (0, 1):
    fail(f"design of the marginal case: exit {p.returncode}: {p.stderr.strip()}")
else:
    with open(des) as f:
        dd = json.load(f)
    nb = dd["motions"][0]["design"]["design_factor"]["no_break"]
    level = dd["motions"][0]["motion"]["peak_floor_over_a_star"]
    if not nb["level_astar"] < level:
        fail(f"the design passes up to {nb['level_astar']} A*, beyond the case's own "
             f"{level} A*, which check fails confirmed")

# 6. the design searches end on a confirmed pass
DESIGN = os.path.join(src, "tests/verdicts/cases/design-confirm.yaml")
p = subprocess.run([probe, "--design", DESIGN, MARGINAL], capture_output=True, text=True)
print(p.stdout, end="")
if p.returncode != 0:
    fail("judge_probe --design: the judge disagrees with a bracket's end")
fails = [int(x) for x in re.findall(r"design-confirm.yaml: motion 1 no-break: .*"
                                    r"confirm_fails (\d+)", p.stdout)]
if not fails or fails[0] < 1:
    fail(f"design-confirm: the no-break search should have gone on below an "
         f"unconfirmed pass: {fails}")
dj = os.path.join(scratch, "dc.json")
p = run("design", DESIGN, "--json", dj, "--quiet")
if p.returncode in (0, 1):
    with open(dj) as f:
        nb = json.load(f)["motions"][0]["design"]["design_factor"]["no_break"]
    if fails and nb["confirm_fails"] != fails[0]:
        fail(f"the design report's confirm_fails {nb['confirm_fails']} is not the search's")
    n = nb["confirm_fails"]
    if f"; {n} higher pass{'es' if n != 1 else ''} not confirmed" not in nb["summary"]:
        fail(f"the design's summary does not say so: {nb['summary']}")

# 7. a pass whose runs at the case's rest fraction pass and scatter, and
#    whose finest run, at a hundredth of the rest fraction as well, breaks
#    a row: a pass the confirmation at tighter tolerances alone signed
#    wrongly before
SCATTER = os.path.join(src, "tests/verdicts/cases/scatter-pass.yaml")
sc, rc = check(SCATTER)
off, rc_off = check(variant("scatter-off", "confirm: off", base=SCATTER))
if sc and off:
    c = conv(sc)
    runs = c["runs"]
    reason = sc["motions"][0]["verdict"]["reason"]
    print(f"scatter-pass: usages {[r.get('usage') for r in runs]}; {reason}")
    if rc_off != 0 or off["verdict"]["result"] != "PASS":
        fail(f"unconfirmed, the scatter case should pass: exit {rc_off}")
    if len(runs) != 2 or not runs[0]["pass"] or runs[1]["pass"] \
            or runs[1]["rest_fraction"] != 1e-8 or not runs[1]["usage"] >= 1:
        fail(f"the scatter case's run at 1e-8 should pass and its run at a hundredth of "
             f"the tolerance and of the rest fraction break a row: {runs}")
    elif rc != 1 or c["status"] != "warning" or not reason.startswith(
            f"not confirmed: at tolerance {at(runs[1], runs)} (auto), {runs[1]['reason']}"):
        fail(f"the scatter case should fail naming its last run: exit {rc}, '{reason}'")
    runs_are_checks("scatter", runs, SCATTER)

# 7b. runs that all pass and scatter by more than the least margin: not
#     signed
SCATTER_RUNS = os.path.join(src, "tests/verdicts/cases/scatter-runs.yaml")
sr, c, margins = unconverged("scatter-runs", SCATTER_RUNS)
if sr:
    reason = sr["motions"][0]["verdict"]["reason"]
    if not max(margins) - min(margins) >= min(margins):
        fail(f"the margins {margins} do not scatter by their least")
    first = dict(c["runs"][0], margin=c["margin"], tolerance=sr["solver"]["rtol"])
    lo = min([first] + c["runs"], key=lambda r: r["margin"])
    hi = max([first] + c["runs"], key=lambda r: r["margin"])
    want = (f"not confirmed: {lo['margin']:.3g} to spare of the nearest limit at tolerance "
            f"{at(lo, c['runs'])} but {hi['margin']:.3g} at {at(hi, c['runs'])} (auto); "
            "the run does not converge")
    if not reason.startswith(want):
        fail(f"reason '{reason}', expected it to start '{want}'")
    runs_are_checks("scatter-runs", c["runs"], SCATTER_RUNS)

# 8. runs that agree better than they are from the limit, but do not
#    converge: not signed within the band, and the reason names the least
#    and the largest margin with where each was solved
CONVERGE = os.path.join(src, "tests/verdicts/cases/converge-pass.yaml")
cv, c, margins = unconverged("converge-pass", CONVERGE)
if cv:
    if not 1e-3 < max(margins) - min(margins) < min(margins):
        fail(f"the margins {margins} should lie more than 0.001 apart, and less than "
             "the least of them")
    reason = cv["motions"][0]["verdict"]["reason"]
    first = dict(c["runs"][0], margin=c["margin"], tolerance=cv["solver"]["rtol"])
    lo = min([first] + c["runs"], key=lambda r: r["margin"])
    hi = max([first] + c["runs"], key=lambda r: r["margin"])
    want = (f"not confirmed: {lo['margin']:.3g} to spare of the nearest limit at tolerance "
            f"{at(lo, c['runs'])} but {hi['margin']:.3g} at {at(hi, c['runs'])} (auto); "
            "the run does not converge")
    if not reason.startswith(want):
        fail(f"reason '{reason}', expected it to start '{want}'")
    # every run keeps a band of 0.12 to spare, and more than their spread
    kept, rc_kept = check(variant("converge-kept", "confirm: always;confirm_band: 0.12",
                                  base=CONVERGE))
    if kept and (rc_kept != 0 or conv(kept)["status"] != "ok"):
        fail(f"with 0.12 to spare in every run the converge case should pass: exit "
             f"{rc_kept}, {conv(kept)}")
    tight, rc_t = check(variant("converge-tight", "confirm: always;confirm_band: 0.13",
                                base=CONVERGE))
    if tight and rc_t != 1:
        fail(f"with a band of 0.13, which its finest run does not keep, the converge case "
             f"should fail: exit {rc_t}")
WIDE = os.path.join(src, "tests/verdicts/cases/wide-band-pass.yaml")
narrow, rc_narrow = check(variant("wide-narrow", "confirm_band: 0.25", base=WIDE))
wide, rc = check(WIDE)
if narrow and wide:
    m, band = conv(wide)["margin"], conv(wide)["band"]
    if not 0.25 <= m < band:
        fail(f"the wide-band case's margin {m} should lie between 0.25 and the default "
             f"band {band}")
    if rc_narrow != 0 or conv(narrow)["status"] != "not-checked":
        fail(f"with a band of 0.25 the wide-band case passes unconfirmed: exit {rc_narrow}")
    if rc != 1 or conv(wide)["status"] != "warning" \
            or not any(not r["pass"] for r in conv(wide)["runs"]):
        fail(f"the wide-band case should be confirmed and fail: exit {rc}, {conv(wide)}")

# 9. a harmonic pass far outside the record band whose runs do not
#    converge: not signed, where the band of 0.5 signed it unconfirmed
#    and Dormand-Prince breaks its row
CHAOS = os.path.join(src, "tests/verdicts/cases/harmonic-chaos-pass.yaml")
hc, rc = check(CHAOS)
if hc:
    c = conv(hc)
    reason = hc["motions"][0]["verdict"]["reason"]
    if not (rc == 1 and c["band"] == 1 and c["margin"] > 0.9 and c["status"] == "warning"
            and len(c["runs"]) == 2 and all(r["pass"] for r in c["runs"])
            and "does not converge" in reason):
        fail(f"the harmonic chaos case should fail unconverged: exit {rc}, {reason}, {c}")
    usages = [hc["motions"][0]["result"]["bolts"]["usage"]["right"]] \
        + [r["usage"] for r in c["runs"]]
    if not max(usages) > 1.3 * min(usages):
        fail(f"the harmonic chaos case's usages {usages} should scatter")
# the text report's header says which band a harmonic is confirmed within
head = run("check", CHAOS).stdout
if "passes confirmed: marginal (band 0.50; 1 under a harmonic)" not in head:
    fail(f"the chaos case's header does not give the harmonic band: {head[:400]}")
if "under a harmonic" in run("check", os.path.join(src, "cases/reference-taft.yaml")).stdout:
    fail("a record case's header speaks of a harmonic")
banded, rc_b = check(variant("chaos-off", "confirm: off", base=CHAOS))
if banded and rc_b != 0:
    fail(f"unconfirmed, the harmonic chaos case passes as it did: exit {rc_b}")
dp, rc_dp = check(variant("chaos-rk45", "confirm: off", "integrator: rk45", base=CHAOS))
if dp and (rc_dp != 1 or not dp["motions"][0]["result"]["bolts"]["broken"]["right"]):
    fail(f"Dormand-Prince at 1e-7 should break the chaos case's row: exit {rc_dp}")

# 10. a pass that only the rest criterion moves: its runs at the case's
#     rest fraction agree at every tolerance, and the last confirming run,
#     at a hundredth of the rest fraction, finds the usage a finer
#     criterion converges to, past the limit
REST = os.path.join(src, "tests/verdicts/cases/rest-pass.yaml")
rp, rc = check(REST)
rp_off, rc_off = check(variant("rest-off", "confirm: off", base=REST))
# the usage as a rest criterion a decade finer than any confirming run
# finds it, and another two decades finer: the limit the runs approach
fine = [check(variant(f"rest-{rf}", "confirm: off", f"rest_fraction: {rf}", base=REST))[0]
        for rf in ("1e-10", "1e-12")]
if rp and rp_off and all(fine):
    def top(d):
        return max(d["motions"][0]["result"]["bolts"]["usage"].values())
    c = conv(rp)
    runs = c["runs"]
    u0, u10, u12 = top(rp_off), top(fine[0]), top(fine[1])
    limit = rp["criteria"]["usage_limit"]
    print(f"rest-pass: usage {u0} at 1e-6, {[r['usage'] for r in runs]} in the confirming "
          f"runs, {u10} at 1e-10, {u12} at 1e-12 (limit {limit})")
    if not abs(u12 / u10 - 1) < 1e-3:
        fail(f"the rest-pass case's usage does not settle as the rest fraction falls: "
             f"{u10} at 1e-10, {u12} at 1e-12")
    if not (u0 < limit < u10 and abs(u0 / u10 - 1) > 0.03):
        fail(f"the rest-pass case should pass at the default ({u0}) and not at 1e-10 "
             f"({u10}), more than 3 % apart, about its limit {limit}")
    if rc_off != 0:
        fail(f"unconfirmed, the rest-pass case should pass: exit {rc_off}")
    if len(runs) != 2 or [r["rest_fraction"] for r in runs] != [1e-6, 1e-8] \
            or not abs(runs[0]["usage"] / u0 - 1) < 1e-3:
        fail(f"the rest-pass case's run at a tenth of the tolerance should agree with the "
             f"default's to 1e-3, the tolerance alone not seeing it: {runs}")
    elif not abs(runs[1]["usage"] / u10 - 1) < 0.01:
        fail(f"the last confirming run's usage {runs[1]['usage']} should lie within 1 % of "
             f"the run at rest fraction 1e-10 ({u10})")
    if rc != 1 or rp["verdict"]["result"] != "FAIL" or c["status"] != "warning" \
            or not rp["motions"][0]["verdict"]["reason"].startswith(
                "not confirmed: at tolerance 1e-09 and rest fraction 1e-08 (auto), "):
        fail(f"confirmed, the rest-pass case should fail by its last run: exit {rc}, "
             f"'{rp['motions'][0]['verdict']['reason']}'")
    # a rest fraction of the case's own: a hundredth of it in the last run,
    # in decimal steps as the tolerances
    own, _ = check(variant("rest-own", "confirm: always", "rest_fraction: 3e-7", base=REST))
    if own and [r["rest_fraction"] for r in conv(own)["runs"]] != [3e-7, 3e-9]:
        fail(f"rest fractions of the runs of a case at 3e-7: "
             f"{[r['rest_fraction'] for r in conv(own)['runs']]}")

# 11. bad values
for key, value, expected in (("confirm", "maybe", "one of marginal, always, off"),
                             ("confirm_band", "0", "> 0 and <= 1"),
                             ("confirm_band", "1.5", "> 0 and <= 1")):
    path = variant(f"bad-{key}-{value}", f"{key}: {value}")
    p = run("check", path, "--quiet")
    msg = p.stderr
    col = 5 + len(key)  # the value, after "  key: "
    if p.returncode != 2 or not msg.startswith(f"{path}:4:{col}: error: criteria.{key}: ") \
            or expected not in msg:
        fail(f"criteria.{key}: {value}: exit {p.returncode}, '{msg.strip()}'")

finish(f"confirm: {len(failures)} failures")
