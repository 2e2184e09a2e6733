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
  - on tests/verdicts/cases/scatter-pass.yaml, whose three runs all
    pass but scatter by more than the least of their margins, the pass
    is not signed: check fails it with the convergence warning and a
    reason naming both margins, each run's margin is check's at its
    tolerance, and with confirm: off it passes;
  - on tests/verdicts/cases/converge-pass.yaml, whose three runs pass
    and lie closer together than it is from the limit but more than
    0.001 apart, the pass is not signed either, unless every run keeps
    the band to spare (confirm: always with a band of 0.15);
  - tests/verdicts/cases/wide-band-pass.yaml, 0.31 from the limit, is
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
    failing = [r for r in c["runs"] if not r["pass"]]
    if not failing:
        fail("no confirming run fails")
    elif not on["motions"][0]["verdict"]["reason"].startswith(
            f"not confirmed: at tolerance {failing[0]['tolerance']:g} (auto), "
            + failing[0]["reason"]):
        fail(f"reason '{on['motions'][0]['verdict']['reason']}' does not name the "
             f"failing run ({failing[0]})")
    # the run as solved is the same with and without confirmation
    if on["motions"][0]["result"] != off["motions"][0]["result"]:
        fail("confirmation changed the reported run")
    if abs(c["margin"] - (1 - on["motions"][0]["result"]["bolts"]["usage"]["right"])) > 1e-15:
        fail(f"margin {c['margin']} is not 1 - the usage")

    # 2. each confirming run is check at its tolerance
    for r in c["runs"]:
        d, _ = check(variant(f"at-{r['tolerance']:g}", "confirm: off",
                             f"tolerance: {r['tolerance']:g}"))
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

# 7. runs that all pass and scatter by more than the least margin: not signed
SCATTER = os.path.join(src, "tests/verdicts/cases/scatter-pass.yaml")
sc, c, margins = unconverged("scatter-pass", SCATTER)
if sc:
    reason = sc["motions"][0]["verdict"]["reason"]
    if not max(margins) - min(margins) >= min(margins):
        fail(f"the margins {margins} do not scatter by their least")
    lo = min(c["runs"], key=lambda r: r["margin"])
    hi = max(c["runs"] + [{"margin": c["margin"], "tolerance": 1e-7}],
             key=lambda r: r["margin"])
    want = (f"not confirmed: {lo['margin']:.3g} to spare of the nearest limit at tolerance "
            f"{lo['tolerance']:.3g} but {hi['margin']:.3g} at {hi['tolerance']:.3g} (auto); "
            "the run does not converge")
    if not reason.startswith(want):
        fail(f"reason '{reason}', expected it to start '{want}'")
    for r in c["runs"]:
        d, _ = check(variant(f"scatter-at-{r['tolerance']:g}", "confirm: off",
                             f"tolerance: {r['tolerance']:g}", base=SCATTER))
        if d and conv(d)["margin"] != r["margin"]:
            fail(f"the run at {r['tolerance']:g} has margin {r['margin']}, check at that "
                 f"tolerance {conv(d)['margin']}")

# 8. runs that agree better than they are from the limit, but do not
#    converge: not signed within the band
CONVERGE = os.path.join(src, "tests/verdicts/cases/converge-pass.yaml")
cv, c, margins = unconverged("converge-pass", CONVERGE)
if cv:
    if not 1e-3 < max(margins) - min(margins) < min(margins):
        fail(f"the margins {margins} should lie more than 0.001 apart, and less than "
             "the least of them")
    if "does not converge" not in cv["motions"][0]["verdict"]["reason"]:
        fail(f"the converge case's reason: {cv['motions'][0]['verdict']['reason']}")
    kept, rc_kept = check(variant("converge-kept", "confirm: always;confirm_band: 0.15",
                                  base=CONVERGE))
    if kept and (rc_kept != 0 or conv(kept)["status"] != "ok"):
        fail(f"with 0.15 to spare in every run the converge case should pass: exit "
             f"{rc_kept}, {conv(kept)}")
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

# 10. bad values
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
