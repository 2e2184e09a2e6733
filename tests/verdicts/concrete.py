#!/usr/bin/env python3
"""The concrete check in the verdict, end to end.

    python3 tests/verdicts/concrete.py ROCKBOLT SCRATCH

Run from the source root. On cases/reference-concrete.yaml and variants:
  - the anchorage's demand is the 17.8 interaction of tension and shear at
    one instant: the reported utilization is what rb_aci17_interaction
    gives for the reported tension and shear, and is no larger than the
    interaction of the largest tension with the largest shear;
  - the demand of a run is judged on the strengths concrete governs (the
    bolts' steel is judged by the run's own criterion);
  - 17.10.5.2 exempts a run whose bolts carry no tension; route auto lets
    the run's own demand stand for (d) where the bolts do not yield;
  - an anchorage that is not ductile fails a run judged by route (a) and
    says so; with `seismic: false` it does not;
  - bolts whose f_uta / f_ya is below 1.3 (ASTM F1554 grade 105) with
    threads along part of their length fail a seismic case that is
    ductile in every other respect, and name the threads; threaded over
    their whole length or on upset ends they pass;
  - a utilization of 1 or more fails the case; `criteria: concrete: false`
    keeps the check in the report but out of the verdict;
  - the text report and the page show the modes' table, and the batch
    summary gives each run's governing mode and utilization, which merged
    shards keep byte for byte;
  - the static demand of design.code (row tension, anchor design force as
    shear) is put through the same interaction."""
import json, os, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, failures, src, start  # noqa: E402

rb, scratch = start()


def case(name, extra, level="0.4 A*"):
    p = os.path.join(scratch, name + ".yaml")
    with open(p, "w") as f:
        f.write(f"extends: {src}/cases/reference-concrete.yaml\nname: {name}\n"
                f"motion:\n  peak: {level}\n{extra}")
    return p


def check(p, *args):
    out = os.path.join(scratch, os.path.basename(p)[:-5] + ".json")
    r = subprocess.run([rb, "check", p, "--json", out, *args], capture_output=True,
                       text=True)
    if r.returncode not in (0, 1):
        fail(f"{p}: exit {r.returncode}: {r.stderr.strip()[:300]}")
        return None, r
    return json.load(open(out)), r


def interaction(n, phi_n, v, phi_v):
    rn, rv = n / phi_n, v / phi_v
    if v <= 0.2 * phi_v:
        return rn
    if n <= 0.2 * phi_n:
        return rv
    return max(rn, rv, (rn + rv) / 1.2)


# concurrent demand, on the shipped case
rep, _ = check(os.path.join(src, "cases", "reference-concrete.yaml"))
if rep:
    a, m = rep["anchorage_check"], rep["motions"][0]
    d, peaks = m["anchorage"], m["result"]["peaks"]
    pn, pv = a["phi_nn_concrete_row_n"], a["phi_vn_concrete_n"]
    steel = [x["design_n"] for x in a["modes"] if x["mode"].startswith("steel")]
    concrete = [x["design_n"] for x in a["modes"]
                if x["applies"] and not x["mode"].startswith("steel")]
    if pn in steel and pn not in concrete or pv in steel and pv not in concrete:
        fail(f"the run's strengths {pn}, {pv} are a steel mode's")
    u = interaction(d["tension_n"], pn, d["shear_n"], pv)
    if abs(u - d["utilization"]) > 1e-12 * u:
        fail(f"utilization {d['utilization']} is not the interaction {u} of its demands")
    worst = interaction(max(peaks["max_bolt_force_n"].values()), pn,
                        peaks["max_shear_total_n"], pv)
    if d["utilization"] > worst * (1 + 1e-12):
        fail(f"utilization {d['utilization']} above max-with-max {worst}")
    # 17.8.1 judges tension alone, so the shear at that instant may be 0:
    # the text report also gives the run's largest shear and its ratio
    txt = os.path.join(scratch, "reference-concrete.txt")
    subprocess.run([rb, "check", os.path.join(src, "cases", "reference-concrete.yaml"),
                    "--text", txt, "-q"], capture_output=True)
    line = [x for x in open(txt) if "anchorage (17.8)" in x]
    if not line or "largest shear" not in line[0] or "route: ductile" not in line[0]:
        fail(f"the anchorage line lacks the largest shear or the route: {line}")
    print(f"reference-concrete: utilization {d['utilization']:.3f} at {d['time_s']:.3f} s "
          f"({d['clause']}); largest tension with largest shear {worst:.3f}")

# 17.10.5.2: bolts that carry no tension need no route; auto without yield
# judges the run's own demand; route (a), asked, fails an anchorage that is
# not ductile (here its stretch length) at a level that uses little of it
low = case("low", "", "0.02 A*")
rep, _ = check(low)
if rep:
    m = rep["motions"][0]
    if not m["verdict"]["pass"] or m["anchorage"]["seismic_route"] != "exempt":
        fail(f"a run whose bolts carry no tension is not exempt: {m['verdict']['reason']}")
mid = case("mid", "", "0.1 A*")
rep, _ = check(mid)
if rep:
    m = rep["motions"][0]
    if max(m["result"]["peaks"]["max_bolt_force_n"].values()) <= 0 \
            or m["anchorage"]["seismic_route"] != "dynamic" or not m["verdict"]["pass"]:
        fail(f"auto without yield: {m['anchorage']['seismic_route']}, {m['verdict']['reason']}")
mid_a = case("mid-a", "concrete:\n  seismic_route: ductile\n", "0.1 A*")
rep, _ = check(mid_a)
if rep:
    v = rep["motions"][0]["verdict"]
    if v["pass"] or "not ductile" not in v["reason"]:
        fail(f"route (a) passes an anchorage that is not ductile: {v['reason']}")
    if rep["motions"][0]["anchorage"]["utilization"] >= 1:
        fail("the 0.1 A* run should use less than the design strength")
nonseis = case("nonseismic", "concrete:\n  seismic: false\n  seismic_route: ductile\n",
               "0.1 A*")
rep, _ = check(nonseis)
if rep and not rep["motions"][0]["verdict"]["pass"]:
    fail(f"a non-seismic run fails: {rep['motions'][0]['verdict']['reason']}")

# 17.10.5.3(a)'s threads: grade 105 rods deep in a thick slab with wide
# washers, so that only the threads can make them brittle
g105 = ("anchorage:\n  yield_stress: 105 ksi\n"
        "  ultimate_stress: 125 ksi\n  embedment: 12 in\n  head_bearing_area: 2 in^2\n"
        "  deformable_length: 8 in\nconcrete:\n  thickness: 24 in\n  seismic_route: ductile\n")
for threads, ductile in (("", False), ("partial", False), ("full-length", True),
                         ("upset", True)):
    extra = g105.replace("  deformable_length", f"  threads: {threads}\n  deformable_length") \
        if threads else g105
    txt = os.path.join(scratch, f"g105-{threads or 'default'}.txt")
    rep, _ = check(case(f"g105-{threads or 'default'}", extra, "0.1 A*"), "--text", txt)
    if not rep:
        continue
    a, v = rep["anchorage_check"], rep["motions"][0]["verdict"]
    if a["ductility_margin"] < 1 or not a["stretch_ok"]:
        fail(f"g105 {threads}: the concrete or the stretch length decides "
             f"(margin {a['ductility_margin']})")
    if abs(a["futa_over_fya"] - 125 / 105) > 1e-12 or \
            a["inputs"]["threads"] != (threads or "partial"):
        fail(f"g105 {threads}: reports {a['futa_over_fya']}, {a['inputs']['threads']}")
    if a["threads_ok"] != ductile or a["ductile"] != ductile or v["pass"] != ductile:
        fail(f"g105 {threads}: threads_ok {a['threads_ok']}, ductile {a['ductile']}, "
             f"pass {v['pass']}: {v['reason']}")
    if not ductile and ("f_uta / f_ya" not in v["reason"] or "stretch" in v["reason"]
                        or "concrete lets go" in v["reason"]):
        fail(f"g105 {threads}: the reason does not name the threads alone: {v['reason']}")
    want = f"f_uta / f_ya = 1.190 ({threads or 'partial'} threads) " + \
        ("ok" if ductile else "below 1.3")
    if want not in open(txt).read():
        fail(f"g105 {threads}: the text report lacks '{want}'")

# utilization >= 1 fails; criteria: concrete: false takes it out of the verdict
deep = ("anchorage:\n  deformable_length: 8 in\nconcrete:\n  seismic: false\n"
        "criteria:\n  kind: no-break\n  usage_limit: 100\n")
over = case("over", deep, "0.3 A*")
rep, _ = check(over)
if rep:
    m = rep["motions"][0]
    if m["anchorage"]["utilization"] < 1:
        fail("the 0.3 A* run should exceed the design strength")
    elif m["verdict"]["pass"] or "design strength" not in m["verdict"]["reason"]:
        fail(f"a utilization of {m['anchorage']['utilization']} passes: "
             f"{m['verdict']['reason']}")
off = case("off", deep + "  concrete: false\n", "0.3 A*")
rep, r = check(off, "--text", os.path.join(scratch, "off.txt"),
               "--html", os.path.join(scratch, "off.html"))
if rep:
    m = rep["motions"][0]
    if not m["verdict"]["pass"] or rep["anchorage_check"]["judged"]:
        fail(f"criteria: concrete: false still judges: {m['verdict']['reason']}")
    if "anchorage" not in m:
        fail("criteria: concrete: false drops the demand from the report")
    text = open(os.path.join(scratch, "off.txt")).read()
    for w in ("breakout-tension     17.6.2", "anchorage (17.8)", "reported, not judged",
              "demand / design"):
        if w not in text:
            fail(f"the text report lacks '{w}'")
    if "Anchorage in concrete" not in open(os.path.join(scratch, "off.html")).read():
        fail("the page lacks the concrete table")

# batch: each run's governing mode and utilization
bj, bc = os.path.join(scratch, "b.json"), os.path.join(scratch, "b.csv")
r = subprocess.run([rb, "batch", over, off, "--json", bj, "--csv", bc, "-q"],
                   capture_output=True, text=True)
if r.returncode not in (0, 1):
    fail(f"batch: exit {r.returncode}: {r.stderr.strip()[:300]}")
else:
    for c in json.load(open(bj))["cases"]:
        run = c["runs"][0]
        if "anchor_utilization" not in run or run.get("anchor_mode") is None:
            fail(f"batch summary lacks the anchorage of {c['tag']}")
    head = open(bc).readline()
    if "anchor_mode,anchor_utilization" not in head:
        fail("the batch CSV lacks the anchorage columns")
    # shards merge into the single run's bytes, anchorage and all
    shards = []
    for k in (1, 2):
        sj = os.path.join(scratch, f"s{k}.json")
        subprocess.run([rb, "batch", over, off, "--shard", f"{k}/2", "--json", sj, "-q"],
                       capture_output=True)
        shards.append(sj)
    mj = os.path.join(scratch, "m.json")
    r = subprocess.run([rb, "merge", *shards, "--json", mj, "-q"], capture_output=True,
                       text=True)
    if r.returncode not in (0, 1) or open(mj, "rb").read() != open(bj, "rb").read():
        fail(f"merged shards differ from the single run (exit {r.returncode}: "
             f"{r.stderr.strip()[:200]})")

# the static demand: design.code's row tension and anchor design force
code = case("code", "design:\n  code:\n    edition: ASCE 7-22\n    sds: 1.0\n"
            "    z_over_h: 0.5\n    car: 1\n    rpo: 1.5\n    r: 8\n    ie: 1\n"
            "    omega0: 2.5\n    futa: 58 ksi\n")
cj = os.path.join(scratch, "code.json")
r = subprocess.run([rb, "design", code, "--json", cj, "-q"], capture_output=True, text=True)
if r.returncode not in (0, 1):
    fail(f"design with code: exit {r.returncode}: {r.stderr.strip()[:300]}")
else:
    rep = json.load(open(cj))
    k, a = rep["design"]["code_static"], rep["anchorage_check"]
    u = interaction(k["tension_n"], a["phi_nn_row_n"], k["fp_anchor_n"], a["phi_vn_n"])
    if abs(k.get("concrete_utilization", -1) - u) > 1e-12 * u:
        fail(f"static utilization {k.get('concrete_utilization')} is not {u}")

# S_DS is in g: a bare number, or an acceleration in any unit the case
# takes (as the AC156 spectrum's sds is); every spelling gives the same F_p
if os.path.exists(cj):
    fp = json.load(open(cj))["design"]["code_static"]["fp_n"]
    for spelled in ("1.0 g", "9.80665 m/s^2", "386.0885826771654 in/s^2", "980.665 gal"):
        sp = case("code-" + spelled.split()[1].replace("/", "").replace("^", ""),
                  "design:\n  code:\n    edition: ASCE 7-22\n    sds: " + spelled + "\n"
                  "    z_over_h: 0.5\n    car: 1\n    rpo: 1.5\n    r: 8\n    ie: 1\n"
                  "    omega0: 2.5\n    futa: 58 ksi\n")
        sj = os.path.join(scratch, "code-sds.json")
        r = subprocess.run([rb, "design", sp, "--json", sj, "-q"], capture_output=True,
                           text=True)
        if r.returncode not in (0, 1):
            fail(f"design.code.sds: {spelled}: exit {r.returncode}: {r.stderr.strip()[:300]}")
            continue
        got = json.load(open(sj))["design"]["code_static"]["fp_n"]
        if abs(got - fp) > 1e-12 * fp:
            fail(f"design.code.sds: {spelled} gives F_p {got} N, 1.0 gives {fp} N")

# design.code without ase takes the anchorage's own A_se, by the thread
# standard, not the bolt's gross area (26-38 % more steel): a 3/4-10 UNC rod
# and a 1/2 in (12.7 mm) one, each against the formula worked out here
IN2 = 0.0254 ** 2
KSI = 6894757.29
for name, path, d_in, tpi, n_row, futa in (
        ("panel-us", "tests/pdf/panel-us.yaml", 0.75, 10, 2, 58 * KSI),
        ("reference-design", "cases/reference-design.yaml", 0.5, 13, 2, 414e6)):
    ase = 0.7854 * (d_in - 0.9743 / tpi) ** 2 * IN2
    dj = os.path.join(scratch, name + "-code.json")
    r = subprocess.run([rb, "design", os.path.join(src, path), "--json", dj, "-q"],
                       capture_output=True, text=True)
    if r.returncode not in (0, 1):
        fail(f"design {name}: exit {r.returncode}: {r.stderr.strip()[:300]}")
        continue
    rep = json.load(open(dj))
    k = rep["design"]["code_static"]
    want = 0.75 * n_row * ase * futa
    if abs(k["phi_nsa_n"] - want) > 1e-3 * want:
        fail(f"{name}: code-static phi N_sa {k['phi_nsa_n']:.1f} N is not "
             f"0.75 n A_se f_uta = {want:.1f} N (A_se {ase / IN2:.4f} in^2)")
    a = rep.get("anchorage_check")
    if a and abs(a["tensile_area_m2"] - ase) > 1e-3 * ase:
        fail(f"{name}: the concrete check's A_se {a['tensile_area_m2']} is not {ase}")

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
