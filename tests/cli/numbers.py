#!/usr/bin/env python3
"""The numbers of the check command's reports, end to end: the text report
shows the JSON's values at its own precision, the peaks agree with their
normalised forms, a suite's governing motion, maximum and mean follow from
its motions, and every value of a US customary report is the SI one
converted.

    python3 tests/cli/numbers.py ROCKBOLT SCRATCH TEST

Run from the source root (ctest does), one TEST a run:
  consistency  the reference harmonic case: the text's numbers are the
               JSON's, shear / W times W is the shear, the stage times add
               up to the run's end, which is within the motion;
  suite        the reference suite: the governing motion is the one of
               largest usage, the suite's maximum and mean usage are its
               motions';
  units        the US customary case in US units (and in SI when its
               output_units say so, and an SI case in US units), every
               converted value against its SI name at full precision;
  elcentro     the El Centro case's floor scaled to 0.4 A*, its peak uplift
               in a sane range;
  history      --history: a row each 0.01 s at least, 15 fields, the motion
               index and the stage in range, analysis.output_interval obeyed;
  design       the design factor is 1 / the level in A*, no-break's at most
               no-yield's, the bracket within the resolution, the frequency
               sweep's end, the code-static ratio T / phi N_sa.

The commands' exit codes and files are tests/cli/cli_test.sh's."""
import json, os, re, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, finish, run, start, write  # noqa: E402

rb, scratch = start()
test = sys.argv[3]
HARMONIC = "cases/reference-harmonic.yaml"


def check(case, *outs):
    """check case writing JSON and text into the scratch directory: the
    process, the JSON document and the text."""
    j, t = os.path.join(scratch, "r.json"), os.path.join(scratch, "r.txt")
    p = run("check", case, "--json", j, "--text", t, *outs)
    if p.returncode not in (0, 1):
        fail(f"check {case}: exit code {p.returncode}: {p.stderr.strip()}")
        finish()
    with open(j) as f:
        doc = json.load(f)
    with open(t) as f:
        text = f.read()
    return p, doc, text


def near(a, b, rel, what, abs_=0.0):
    if not abs(a - b) <= rel * abs(b) + abs_:
        fail(f"{what}: {a!r} against {b!r} (relative {rel}, absolute {abs_})")


def verdict_agrees(p, doc, text):
    """The text's verdict line is the JSON's, and the exit code follows."""
    result, headline = doc["verdict"]["result"], doc["verdict"]["headline"]
    if not (headline == result or re.match(re.escape(result) + r" \(.*validity warning",
                                            headline)):
        fail(f"headline '{headline}' does not start with the result '{result}'")
    first = text.split("\n", 1)[0]
    if first != f"{headline}: {doc['verdict']['reason']}":
        fail(f"text verdict '{first}' is not the JSON's")
    if (result, p.returncode) not in (("PASS", 0), ("FAIL", 1)):
        fail(f"verdict {result} with exit code {p.returncode}")


def test_consistency():
    p, J, text = check(HARMONIC)
    M = J["motions"][0]
    P, B = M["result"]["peaks"], M["result"]["bolts"]
    a_star_g = J["derived"]["a_star_g"]
    if not 11.5 < a_star_g < 11.9:
        fail(f"A* of the reference cabinet is 11.7 g, not {a_star_g}")
    near(M["motion"]["peak_floor_over_a_star"], 0.6, 0, "the case asks for 0.6 A*", 1e-9)
    f = lambda v, n: f"{v:.{n}f}"  # as the text report rounds
    for line in (
            f"= {f(P['max_u_over_ustatic'], 2)} U_static",
            f"= {f(P['max_theta_over_alpha'], 4)} alpha",
            f"= {f(P['max_shear_elastic_over_w'], 3)} W = "
            f"{f(P['max_shear_elastic_over_v0'], 3)} V0  (elastic",
            f"= {f(P['max_shear_total_over_w'], 3)} W = "
            f"{f(P['max_shear_total_over_v0'], 3)} V0  (total",
            f"= {f(M['motion']['peak_floor_over_a_star'], 4)} A*",
            f"A*           {f(J['derived']['a_star_mps2'], 2)} m/s^2 = "
            f"{f(a_star_g, 3)} g"):
        if line not in text:
            fail(f"text lacks '{line}'")
    for side in ("left", "right"):
        for what, v in (("usage", B["usage"][side]),
                        ("force / Fy", P["max_bolt_force_over_fy"][side]),
                        ("final gap", B["final_gap_ratio"][side])):
            if not v >= 0:
                fail(f"{what} {side} is {v}, below 0")
    for head, vals in (("toughness usage", B["usage"]),
                       ("max force / Fy", P["max_bolt_force_over_fy"])):
        row = rf"^  {re.escape(head)} +{f(vals['left'], 4)} +{f(vals['right'], 4)}$"
        if not re.search(row, text, re.M):
            fail(f"the {head} row differs from the JSON's")
    w = M["result"]["constants"]["weight_n"]
    near(P["max_shear_elastic_n"], P["max_shear_elastic_over_w"] * w, 1e-9,
         "shear / W times W is the shear", 1e-9)
    out = M["result"]["outcome"]
    stages = sum(out["stage_time_s"][s] for s in ("fixed", "uplift", "impact", "held", "yield"))
    near(stages, out["t_end_s"], 1e-6, "stage times add up to t_end", 1e-6)
    if not out["t_end_s"] <= M["motion"]["duration_s"] * (1 + 1e-9):
        fail(f"t_end {out['t_end_s']} past the duration {M['motion']['duration_s']}")


def test_suite():
    p, J, text = check("cases/reference-suite.yaml")
    verdict_agrees(p, J, text)
    if J["suite"]["motions"] != 4:
        fail(f"four motions, not {J['suite']['motions']}")
    usage = [max(m["result"]["bolts"]["usage"].values()) for m in J["motions"]]
    best = max(usage)
    governing = usage.index(best) + 1  # ties to the first
    if J["suite"]["governing_index"] != governing:
        fail(f"governing motion {J['suite']['governing_index']} is not the one of "
             f"largest usage ({governing})")
    near(J["suite"]["max"]["usage"], best, 0, "suite maximum usage", 1e-12)
    near(J["suite"]["mean"]["usage"], sum(usage) / len(usage), 0, "suite mean usage", 1e-9)
    if not re.search(rf"^suite        4 motions; governing: motion {governing}", text, re.M):
        fail("suite line missing from the text report")
    p, J, text = check(HARMONIC)
    if re.search("^suite", text, re.M):
        fail("suite block for a single motion")


def has_all(text, words, what):
    for w in words:
        if w not in text:
            fail(f"{what} lacks '{w}'")


def test_units():
    US = "cases/us-customary.yaml"
    p = run("check", US)
    us = p.stdout
    has_all(us, ("kip, height 2h = 77.087 in", " in^2 each, fy = 36 ksi",
                 "kip, toughness capacity", "ft-lbf", "gap = 0.3071 in", "max force (kip)",
                 "final gap (in)", "energy (ft-lbf)", "kip/in"), "the US report")
    if re.search(r"kN|MPa|m/s\^2| mm", us):
        fail("SI units in the US report")
    if not re.search(r"^A\*  *[0-9.]* g \(uplift", us, re.M):
        fail("A* not in g")
    page = os.path.join(scratch, "us.html")
    run("check", US, "--html", page, "--quiet")
    with open(page) as f:
        html = f.read()
    has_all(html, ("largest bolt force (kip)", "<td>in</td>"), "the US page")
    dtext = os.path.join(scratch, "usd.txt")
    run("design", US, "--text", dtext, "--quiet")
    with open(dtext) as f:
        design = f.read()
    if not re.search(r"up to [0-9.]* A\* \([0-9.]* g\)", design):
        fail("design levels not in g")
    # the gap search's bound (1/4 in by default) is a length too
    if not re.search(r"\(gap [0-9.]* in\)|bounded by design\.max_gap 0\.25 in ", design):
        fail("recommended gap not in inches")
    if re.search(r"m/s\^2| mm\)", design):
        fail("SI units in the US design report")
    with open(US) as f:
        si = write("si.yaml", f.read() + "output_units: si\n")
    out = run("check", si).stdout
    has_all(out, ("M = 454.0 kg", "kN, height 2h = 1.958 m", "mm^2 each", "MPa",
                  "max force (kN)", "final gap (mm)", "energy (J)", "m/s^2 ="),
            "the output_units: si report")
    if re.search("kip|ksi|ft-lbf", out):
        fail("US units in the SI report")
    # an SI case asking for US units
    us_of_si = write("us.yaml", f"extends: {os.getcwd()}/{HARMONIC}\noutput_units: us\n")
    if "max force (kip)" not in run("check", us_of_si).stdout:
        fail("output_units: us on an SI case")
    # every converted value against its SI name, at full precision: the
    # factor is an SI unit in the US one (lb = 0.45359237 kg exactly, ...)
    factors = [("mass", "mass_kg", 0.45359237), ("weight", "weight_kn", 4.4482216152605),
               ("height", "height_m", 0.0254), ("bolt_area", "bolt_area_mm2", 645.16),
               ("yield_stress", "yield_stress_mpa", 6.894757293168361),
               ("gap", "gap_mm", 25.4), ("fy_row", "fy_row_kn", 4.4482216152605),
               ("capacity", "capacity_j", 1.3558179483314004)]
    per_motion = [("max_u", "max_u_mm", 25.4), ("shear_elastic", "shear_elastic_kn",
                                                 4.4482216152605),
                  ("force_left", "force_left_kn", 4.4482216152605),
                  ("force_right", "force_right_kn", 4.4482216152605),
                  ("absorbed_left", "absorbed_left_j", 1.3558179483314004),
                  ("final_gap_right", "final_gap_right_mm", 25.4),
                  ("e_input", "e_input_j", 1.3558179483314004),
                  ("k_row", "k_row_mn_per_m", 0.17512683524647637)]
    line = lambda a, b: f"{{{{{a}:%.17g}}}} {{{{{b}:%.17g}}}}\n"
    tmpl = os.path.join(scratch, "tmpl")
    os.makedirs(tmpl)
    with open(os.path.join(tmpl, "report.txt"), "w") as f:
        f.write("".join(line(a, b) for a, b, _ in factors) + "{{#motions}}\n"
                + "".join(line(a, b) for a, b, _ in per_motion) + "{{/motions}}\n")
    os.environ["RB_TEMPLATE_DIR"] = tmpl
    us_vals, si_vals = run("check", US).stdout, run("check", si).stdout
    del os.environ["RB_TEMPLATE_DIR"]
    names = factors + per_motion
    rows = [r.split() for r in us_vals.splitlines()]
    if len(rows) != len(names):
        fail(f"{len(names)} values in the US report, not {len(rows)}")
    for (a, b, k), r in zip(names, rows):
        us_v, si_v = float(r[0]), float(r[1])
        if si_v == 0 or abs(us_v * k / si_v - 1) > 1e-9:
            fail(f"US {a} {us_v} is not SI {b} {si_v} converted (x {k})")
    for (a, b, _), r in zip(names, (r.split() for r in si_vals.splitlines())):
        if abs(float(r[0]) / float(r[1]) - 1) > 1e-9:
            fail(f"output_units: si {a} {r[0]} is not the SI {b} {r[1]}")


def test_elcentro():
    p, J, text = check("cases/reference-elcentro.yaml")
    m = J["motions"][0]
    near(m["motion"]["peak_floor_over_a_star"], 0.4, 0, "floor peak scaled to 0.4 A*", 1e-6)
    u = m["result"]["peaks"]["max_u_over_ustatic"]
    if not 1 < u < 100:
        fail(f"max U / U_static {u} not in a sane range (1, 100)")


def rows_of(path):
    with open(path) as f:
        return [line.rstrip("\n").split(",") for line in f][1:]


def test_history():
    csv = os.path.join(scratch, "h.csv")
    p, J, text = check(HARMONIC, "--history", csv)
    rows = rows_of(csv)
    duration = J["motions"][0]["motion"]["duration_s"]
    if not len(rows) >= duration / 0.01:
        fail(f"{len(rows)} rows for {duration} s: fewer than one a 0.01 s")
    for i, r in enumerate(rows):
        if len(r) != 15:
            fail(f"row {i + 1} has {len(r)} fields, not 15", 3)
        elif r[0] != "1" or not 1 <= float(r[14]) <= 5:
            fail(f"row {i + 1}: motion index {r[0]} or stage {r[14]} out of range", 3)
    # analysis.output_interval sets the rows of --history
    fine = write("fine.yaml", f"extends: {os.getcwd()}/{HARMONIC}\n"
                              "analysis:\n  output_interval: 2.5 ms\n")
    fine_csv = os.path.join(scratch, "fine.csv")
    p = run("check", fine, "--quiet", "--history", fine_csv)
    rows = rows_of(fine_csv) if p.returncode <= 1 else []
    if len(rows) < 2 or float(rows[1][1]) != 0.0025:
        fail(f"--history ignores analysis.output_interval: {rows[1][:2] if len(rows) > 1 else rows}")


def test_design():
    j = os.path.join(scratch, "d.json")
    p = run("design", "cases/reference-design.yaml", "--json", j, "--quiet")
    if p.returncode not in (0, 1):
        fail(f"design: exit code {p.returncode}: {p.stderr.strip()}")
        finish()
    with open(j) as f:
        J = json.load(f)
    df = J["motions"][0]["design"]["design_factor"]
    ny, nb = df["no_yield"]["factor"], df["no_break"]["factor"]
    level, fails = df["no_yield"]["level_astar"], df["no_yield"]["fail_astar"]
    if not 0.999999 < ny * level < 1.000001:
        fail(f"factor {ny} is not 1 / the level {level} in A*")
    # a run that breaks nothing may still yield: no-yield is the stricter
    if not 1 < nb <= ny:
        fail(f"no-break factor {nb} not in (1, no-yield's {ny}]")
    if not 0 < fails - level <= 0.001 + 1e-12:
        fail(f"bracket [{level}, {fails}] not within the resolution 0.001")
    near(J["design"]["frequency_sweeps"][0]["points"][18]["frequency_ratio"], 2, 0,
         "the 19-point frequency sweep ends at 2", 1e-12)
    k = J["design"]["code_static"]
    near(k["ratio"], k["tension_n"] / k["phi_nsa_n"], 0, "code ratio = T / phi N_sa", 1e-9)


{"consistency": test_consistency, "suite": test_suite, "units": test_units,
 "elcentro": test_elcentro, "history": test_history, "design": test_design}[test]()
finish()
