#!/usr/bin/env python3
"""rockbolt spectrum, synthetic motions and init --ac156 end to end.

    python3 tests/spectrum/spectrum.py ROCKBOLT SCRATCH

Run from the source root.
  - The spectrum of a record (Taft, no building, scaled to a peak) agrees
    with an independent calculation here: the textbook closed-form
    Nigam-Jennings recurrence (not rockbolt's matrix exponential) stepped
    at dt/20, to 2e-3 (what the sub-steps' peaks miss). The floor drops to
    zero after its last sample, as the solver's does: a ramp to zero over
    one more step instead moves the 11.3 Hz ordinate of this window by 3 %.
  - A synthetic AC156 suite: every motion within [1, 1.3] of the RRS at
    its 29 check points, peak >= 0.9 A_RIG, 30 s, 5-95 % Arias >= 20 s;
    JSON, CSV and text agree; the same seed gives the same spectra.
  - A table target read from a CSV file is matched and reported.
  - check, design and batch run on synthetic motions; batch gives each row
    the verdict and usage that check gives the same case.
  - init --ac156 writes a case that loads and whose suite is within.
  - Bad options exit 2 and write nothing."""
import csv, json, math, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, failures, run, src, start, write  # noqa: E402

rb, scratch = start()
G = 9.80665


def nigam_jennings(acc, dt, f, xi, sub=20):
    """Peak w^2|u| and |absolute acceleration| of u'' + 2 xi w u' + w^2 u = -a(t),
    a linear between samples, by the closed-form coefficients (Nigam and
    Jennings 1969), stepped at dt / sub and looked at there."""
    w = 2 * math.pi * f
    h = dt / sub
    wd = w * math.sqrt(1 - xi * xi)
    e = math.exp(-xi * w * h)
    s, c = math.sin(wd * h), math.cos(wd * h)
    a11 = e * (xi / math.sqrt(1 - xi * xi) * s + c)
    a12 = e / wd * s
    a21 = -w / math.sqrt(1 - xi * xi) * e * s
    a22 = e * (c - xi / math.sqrt(1 - xi * xi) * s)
    t1 = (2 * xi * xi - 1) / (w * w * h)
    t2 = 2 * xi / (w ** 3 * h)
    b11 = e * ((t1 + xi / w) * s / wd + (t2 + 1 / (w * w)) * c) - t2
    b12 = -e * (t1 * s / wd + t2 * c) - 1 / (w * w) + t2
    b21 = (e * ((t1 + xi / w) * (c - xi / math.sqrt(1 - xi * xi) * s)
                - (t2 + 1 / (w * w)) * (wd * s + xi * w * c)) + 1 / (w * w * h))
    b22 = -e * (t1 * (c - xi / math.sqrt(1 - xi * xi) * s) - t2 * (wd * s + xi * w * c)) \
        - 1 / (w * w * h)
    u = v = 0.0
    pu = pa = 0.0
    loads = [-x for x in acc]   # the floor drops to zero after the end, as the solver's
    for i in range(len(loads) - 1):
        p0, p1 = loads[i], loads[i + 1]
        for j in range(sub):
            q0 = p0 + (p1 - p0) * j / sub
            q1 = p0 + (p1 - p0) * (j + 1) / sub
            u, v = (a11 * u + a12 * v + b11 * q0 + b12 * q1,
                    a21 * u + a22 * v + b21 * q0 + b22 * q1)
            pu = max(pu, abs(u))
            pa = max(pa, abs(2 * xi * w * v + w * w * u))
    # one free period after the end
    for j in range(int(math.ceil(sub / (f * dt)))):
        u, v = a11 * u + a12 * v, a21 * u + a22 * v
        pu = max(pu, abs(u))
        pa = max(pa, abs(2 * xi * w * v + w * w * u))
    return w * w * pu, pa


# --- a record against the independent recurrence ------------------------
taft = f"{src}/cases/records/taft_1952_s69e.txt"
case = write("taft.yaml", f"""extends: {src}/cases/base/reference-cabinet.yaml
name: taft-spectrum
motion: {{type: record, file: {taft}, format: one-column, units: g, dt: 0.01 s, peak: 0.3 g, window: [0 s, 8 s]}}
""")
tj = os.path.join(scratch, "taft.json")
r = run("spectrum", case, "--json", tj, "--from", "0.5 Hz", "--to", "40", "--per-octave", "2",
        "-q")
if r.returncode != 0:
    fail(f"spectrum of the Taft case exited {r.returncode}: {r.stderr}")
else:
    js = json.load(open(tj))
    raw = [float(x) for x in open(taft).read().split()]
    raw = raw[:801]   # the window [0, 8 s]
    peak = max(abs(x) for x in raw)
    acc = [x * 0.3 * G / peak for x in raw]
    m = js["motions"][0]
    if abs(m["peak_mps2"] - 0.3 * G) > 1e-9:
        fail(f"Taft peak {m['peak_mps2']} != {0.3 * G}")
    for k, f in enumerate(js["frequency_hz"]):
        psa, sa = nigam_jennings(acc, 0.01, f, 0.05)
        for name, got, want in (("psa", m["psa_mps2"][k], psa), ("sa", m["sa_mps2"][k], sa)):
            if abs(got / want - 1) > 2e-3:
                fail(f"Taft {name} at {f:.3f} Hz: {got:.6g} against {want:.6g}")

# --- a synthetic AC156 suite ---------------------------------------------
suite = write("ac156.yaml", f"""extends: {src}/cases/base/reference-cabinet.yaml
name: ac156-suite
motions:
  - type: synthetic
    name: rrs
    spectrum: {{type: ac156, sds: 1.0 g, z_over_h: 1.0}}
    count: 3
    seed: 11
""")
sj, sc, sv = (os.path.join(scratch, n) for n in ("s.json", "s.csv", "s.svg"))
r = run("spectrum", suite, "--json", sj, "--csv", sc, "--svg", sv)
if r.returncode != 0:
    fail(f"spectrum of the AC156 suite exited {r.returncode}: {r.stderr}")
else:
    js = json.load(open(sj))
    rows = list(csv.DictReader(open(sc)))
    if len(js["motions"]) != 3:
        fail(f"{len(js['motions'])} motions, want 3")
    freqs = js["frequency_hz"]
    for i, m in enumerate(js["motions"]):
        if m["name"] != f"rrs-{i + 1}" or m["kind"] != "synthetic":
            fail(f"motion {i}: name {m['name']}, kind {m['kind']}")
        fit, t = m["fit"], m["target"]
        if not (fit["within"] and fit["points"] == 29 and fit["min_ratio"] >= 1.0
                and fit["max_ratio"] <= 1.3):
            fail(f"{m['name']} fit {fit}")
        if abs(t["a_flx_mps2"] - 1.6 * G) > 1e-9 or abs(t["a_rig_mps2"] - 1.2 * G) > 1e-9:
            fail(f"AC156 levels {t['a_flx_mps2']}, {t['a_rig_mps2']}")
        if m["peak_mps2"] < 0.9 * t["a_rig_mps2"]:
            fail(f"{m['name']} peak {m['peak_mps2']} below 0.9 A_RIG")
        if m["arias_t95_s"] - m["arias_t5_s"] < 20:
            fail(f"{m['name']} 5-95 % Arias {m['arias_t95_s'] - m['arias_t5_s']} s")
        if abs(m["end_velocity_mps"]) > 1e-9 or abs(m["end_displacement_m"]) > 1e-9:
            fail(f"{m['name']} ends at {m['end_velocity_mps']} m/s, {m['end_displacement_m']} m")
        mine = [r for r in rows if r["motion"] == m["name"]]
        if len(mine) != len(freqs):
            fail(f"CSV has {len(mine)} rows of {m['name']}, want {len(freqs)}")
        for r_, sa in zip(mine, m["sa_mps2"]):
            if abs(float(r_["sa_g"]) - sa / G) > 1e-5 * sa / G:
                fail(f"CSV sa_g {r_['sa_g']} against JSON {sa / G}")
                break
    if "within" not in r.stdout or r.stdout.count("peak >= 0.9 A_RIG") != 3:
        fail("text report does not state the fits:\n" + r.stdout)
    svg = open(sv).read()
    if svg.count('data-series="target"') != 1 or 'data-series="rrs-3"' not in svg:
        fail("SVG lacks the target or a motion")
    # the same seed, the same motions
    sj2 = os.path.join(scratch, "s2.json")
    run("spectrum", suite, "--json", sj2, "-q")
    if open(sj2).read() != open(sj).read():
        fail("the same seed gave other spectra")

# --- a table target from a CSV file (Eurocode 8 floor spectrum shape) ----
rows = ["# EN 1998-1:2004 4.3.5.2(3): a S = 0.3 g, z = H, T1 = 0.5 s", "frequency_hz,sa_g"]
for i in range(30):
    f = 1.0 * 33.3 ** (i / 29)
    ta = 1 / f
    rows.append(f"{f:.6g},{max(0.3, 0.3 * (6 / (1 + (1 - ta / 0.5) ** 2) - 0.5)):.6g}")
table = write("ec8.csv", "\n".join(rows) + "\n")
tcase = write("ec8.yaml", f"""extends: {src}/cases/base/reference-cabinet.yaml
name: ec8-table
motions:
  - {{type: synthetic, spectrum: {{type: table, file: ec8.csv, damping: 5 %,
     tolerance: {{below: 0.95, above: 1.4}}}}, seed: 3}}
""")
first_f, first_g = 1.0, float(rows[2].split(",")[1])
tj = os.path.join(scratch, "t.json")
r = run("spectrum", tcase, "--json", tj, "-q")
if r.returncode != 0:
    fail(f"spectrum of the table case exited {r.returncode}: {r.stderr}")
else:
    tjs = json.load(open(tj))
    m = tjs["motions"][0]
    if not m["fit"]["within"] or m["fit"]["min_ratio"] < 1.0 or m["target"]["type"] != "table":
        fail(f"table fit {m['fit']}")
    # the table's own tolerance, and the taper below its first frequency:
    # the target there is first_g x f / first_f (written here); a point
    # over 1/3 octave below it must stay under it (3e-3: the generator's
    # quick spectrum)
    if m["target"]["band_lower"] != 0.95 or m["target"]["band_upper"] != 1.4:
        fail(f"table tolerance {m['target']}")
    if not m["summary"]["acceptance"]["pass"]:
        fail(f"table acceptance {m['summary']['acceptance']}")
    low = [(f, sa) for f, sa in zip(tjs["frequency_hz"], m["sa_mps2"])
           if f <= first_f / 2 ** (1 / 3)]
    worst = max(sa / (G * first_g * f / first_f) for f, sa in low)
    print(f"table: below {first_f / 2 ** (1 / 3):.2f} Hz ({len(low)} points) the spectrum "
          f"reaches {worst:.3f} of the taper")
    if not low or worst > 1.003:
        fail(f"the table's low end is not under its taper: {worst}")
# --- AC156-24 with the building's H_f and R_mu and a two-level envelope --
# (ASCE 7-22 13.3.1 written here: T_a 0.5 s, R 8, I_e 1, Omega_0 3 at z/h
# 0.5 with S_DS 1.0 g, enveloped with S_DS 1.5 g at grade)
def levels_2024(sds, zh, ta, r, ie, om):
    if zh <= 0:
        hf, rmu = 1.0, 1.0
    else:
        hf = 1 + min(1 / ta, 2.5) * zh + max(0.0, 1 - (0.4 / ta) ** 2) * zh ** 10
        rmu = max(1.3, math.sqrt(1.1 * r / (ie * om)))
    return min(sds * hf / rmu, 1.6 * sds), 0.4 * sds * hf / rmu


ecase = write("ac156-2024.yaml", f"""extends: {src}/cases/base/reference-cabinet.yaml
name: ac156-2024
motions:
  - type: synthetic
    spectrum: {{type: ac156, edition: 2024, sds: 1.0 g, z_over_h: 0.5, ta: 0.5 s, r: 8,
               ie: 1, omega0: 3, envelope: {{sds: 1.5 g, z_over_h: 0}}}}
    components: horizontal
    seed: 4
  - type: synthetic
    spectrum: {{type: ieee693, level: moderate, damping: 5 %}}
    seed: 4
""")
ej = os.path.join(scratch, "e.json")
r = run("spectrum", ecase, "--json", ej, "-q")
if r.returncode != 0:
    fail(f"spectrum of the AC156-24 / IEEE 693 case exited {r.returncode}: {r.stderr}")
else:
    ms = json.load(open(ej))["motions"]
    t = ms[0]["target"]
    f1, r1 = levels_2024(1.0, 0.5, 0.5, 8, 1, 3)
    f2, r2 = levels_2024(1.5, 0.0, 0.5, 8, 1, 3)
    want = (max(f1, f2) * G, max(r1, r2) * G)
    print(f"AC156-24 enveloped: A_FLX {t['a_flx_mps2'] / G:.6f} g, A_RIG "
          f"{t['a_rig_mps2'] / G:.6f} g (here {want[0] / G:.6f}, {want[1] / G:.6f})")
    if (abs(t["a_flx_mps2"] - want[0]) > 1e-9 * want[0]
            or abs(t["a_rig_mps2"] - want[1]) > 1e-9 * want[1]
            or abs(t["min_peak_mps2"] - 0.9 * want[1]) > 1e-9 * want[1]):
        fail(f"AC156-24 target {t}, want A_FLX, A_RIG {want}")
    if not ms[0]["summary"]["acceptance"]["pass"] or ms[0]["peak_mps2"] < 0.9 * want[1]:
        fail(f"AC156-24 motion not accepted: {ms[0]['summary']['acceptance']}")
    ti = ms[1]["target"]
    if (ti["type"] != "ieee693" or ti["level"] != "moderate" or ti["vertical"]
            or abs(ti["zpa_mps2"] - 0.5 * G) > 1e-9 or abs(ti["beta"] - 1) > 1e-5
            or ms[1]["name"] != "ieee693"):
        fail(f"IEEE 693 target {ti}, name {ms[1]['name']}")
    # the vertical is matched to 80 % of Moderate: its peak at least 0.9 of
    # a 0.4 g ZPA
    if not ms[1]["vertical"]["pga_mps2"] >= 0.9 * 0.4 * G:
        fail(f"IEEE 693 vertical peak {ms[1]['vertical']['pga_mps2']}")
    for what, acc in (("h1", ms[1]["summary"]["acceptance"]),
                      ("h2", ms[1]["h2"]["acceptance"]),
                      ("v", ms[1]["vertical"]["acceptance"])):
        if not acc["pass"]:
            fail(f"IEEE 693 {what} not accepted: {acc}")

# the table is an input: an output over it is refused
r = run("spectrum", tcase, "--csv", table, "-q")
if r.returncode != 2 or not open(table).read().startswith("# EN 1998-1"):
    fail(f"an output over the table was not refused (exit {r.returncode})")

# --- check, design and batch on synthetic motions -----------------------
cj = os.path.join(scratch, "check.json")
r = run("check", suite, "--json", cj, "-q")
if r.returncode not in (0, 1):
    fail(f"check on the suite exited {r.returncode}: {r.stderr}")
else:
    rep = json.load(open(cj))
    kinds = [m["motion"]["kind"] for m in rep["motions"]]
    if kinds != ["synthetic"] * 3:
        fail(f"check report kinds {kinds}")
r = run("design", suite, "-q", "-j", "2")
if r.returncode not in (0, 1):
    fail(f"design on the suite exited {r.returncode}: {r.stderr}")
lst = write("list.csv", "tag,base,mass\nA,ac156.yaml,454 kg\nB,ac156.yaml,700 kg\n")
bj = os.path.join(scratch, "batch.json")
r = run("batch", lst, "--json", bj, "-q")
if r.returncode not in (0, 1):
    fail(f"batch on synthetic rows exited {r.returncode}: {r.stderr}")
else:
    rows = json.load(open(bj))["cases"]
    for row, mass in zip(rows, ("454 kg", "700 kg")):
        one = write(f"row-{row['tag']}.yaml", f"extends: ac156.yaml\nequipment:\n  mass: {mass}\n")
        oj = os.path.join(scratch, f"row-{row['tag']}.json")
        run("check", one, "--json", oj, "-q")
        rep = json.load(open(oj))
        usage = max(max(m["result"]["bolts"]["usage"].values()) for m in rep["motions"])
        force = max(max(m["result"]["peaks"]["max_bolt_force_over_fy"].values())
                    for m in rep["motions"])
        if (row["verdict"] != rep["verdict"]["result"].lower() or row["max"]["usage"] != usage
                or row["max"]["force_over_fy"] != force):
            fail(f"batch row {row['tag']}: {row['verdict']} {row['max']}, check: "
                 f"{rep['verdict']['result']} usage {usage} force {force}")

# --- init --ac156 -----------------------------------------------------------
start = os.path.join(scratch, "start.yaml")
r = run("init", start, "--ac156")
if r.returncode != 0 or not os.path.exists(start):
    fail(f"init --ac156 exited {r.returncode}: {r.stderr}")
else:
    ij = os.path.join(scratch, "start.json")
    r = run("spectrum", start, "--json", ij, "-q")
    if r.returncode != 0:
        fail(f"spectrum of the AC156 starter exited {r.returncode}: {r.stderr}")
    else:
        ms = json.load(open(ij))["motions"]
        if len(ms) != 5 or not all(m["fit"]["within"] for m in ms):
            fail(f"the AC156 starter has {len(ms)} motions, fits "
                 f"{[m['fit']['within'] for m in ms]}")

# --- bad options --------------------------------------------------------------
for args, what in ((["--damping", "150 %"], "a damping ratio"),
                   (["--from", "10 Hz", "--to", "5 Hz"], "needs 0 < from < to"),
                   (["--per-octave", "0"], "points per octave"),
                   (["--from", "0.001", "--to", "10000", "--per-octave", "96"],
                    "at most 2000 points"),
                   (["--to", "fast"], "a frequency")):
    out = os.path.join(scratch, "bad.json")
    r = run("spectrum", suite, "--json", out, *args)
    if r.returncode != 2 or what not in r.stderr or os.path.exists(out):
        fail(f"spectrum {args}: exit {r.returncode}, stderr {r.stderr!r}")

# a closed form too long to sample for the grid: refused, nothing written
long = write("long.yaml", f"""extends: {src}/cases/base/reference-cabinet.yaml
motion: {{type: harmonic, amplitude: 0.2 A*, frequency: 4 Hz, duration: 3000 s}}
""")
out = os.path.join(scratch, "long.json")
r = run("spectrum", long, "--json", out)
if r.returncode != 2 or "10 million samples" not in r.stderr or os.path.exists(out):
    fail(f"a 3000 s harmonic: exit {r.returncode}, {r.stderr.strip()[:200]}")
r = run("spectrum", long, "--to", "1 Hz", "-q")
if r.returncode != 0:
    fail(f"the same with --to 1 Hz: exit {r.returncode}, {r.stderr.strip()[:200]}")

# names longer than a column are shown whole ("elcentro-roo" was the cut
# of "elcentro-roof"), and every column stays aligned under its name
names = ["elcentro-roof-level-7", "taft", "ngawest2-\u00e9tage-3-sud"]
named = write("named.yaml", f"""extends: {src}/cases/base/reference-cabinet.yaml
motions:
""" + "".join(f"  - {{type: harmonic, name: {n}, amplitude: 0.2 A*, frequency: 4 Hz, "
              f"duration: 2 s}}\n" for n in names))
r = run("spectrum", named, "--per-octave", "1")
lines = r.stdout.splitlines()
if r.returncode != 0 or "absolute acceleration spectra (g)" not in lines:
    fail(f"spectrum of long names: exit {r.returncode}, {r.stderr.strip()[:200]}")
else:
    for n in names:
        if not any(l.startswith(n + " ") for l in lines):
            fail(f"the motion table cuts '{n}'")
    head = lines[lines.index("absolute acceleration spectra (g)") + 1]
    rows = lines[lines.index("absolute acceleration spectra (g)") + 2:]
    if head.split()[2:] != names:
        fail(f"the spectra's header cuts the names: {head!r}")
    for row in rows:
        # each value ends where its name ends
        ends_h = [head.index(n) + len(n) for n in names]
        ends_r, pos = [], 0
        for v in row.split()[1:]:
            pos = row.index(v, pos) + len(v)
            ends_r.append(pos)
        if ends_r != ends_h:
            fail(f"a row is not under its names: {row!r} under {head!r}")
            break

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
