#!/usr/bin/env python3
"""A case in US customary units gets every number of every output for
people in US customary units (docs/case-format.md, Output units).

    python3 tests/units/us_units.py ROCKBOLT SCRATCH

Run from the source root. Every shipped case written in US customary units
(cases/*.yaml, chosen here by counting the units its quantities are written
in, its bases' included, or by its output_units), and the cases of
tests/units/cases (a panel with concrete, an AC156 suite, a record, the
design searches and the code-static table, failing on its anchorage; an SI
case asking for output_units: us; a free-standing cabinet that slides), go
through check (text, HTML, SVG), design (text, HTML, SVG, PDF), fragility
(text, HTML, SVG, PDF), spectrum (text, HTML, SVG), batch (table, CSV,
JUnit, PDF, of the cases; table, CSV, JUnit of an equipment list), and the bad inputs of tests/units/bad through check
(their diagnostics). The PDFs are read as pdftotext gives their text.
si_leaks.py then reads every one of those outputs as
a person would and fails on any SI unit in them. JSON and CSV data files
keep SI (with unit-suffixed names) and are not read, except the batch CSV's
reasons. The test also asserts that it saw the quantities it looks for
(a verdict's tension, S_DS, a lever arm, the concrete edge), so that an
output that lost them cannot pass."""
import glob
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
from e2e import fail, failures, finish, start  # noqa: E402

rb, scratch = start()

US_UNITS = {"in", "ft", "lb", "lbm", "lbs", "kip", "kips", "lbf", "psi", "ksi",
            "in-lb/in^3", "in-lbf/in^3", "in/s^2", "ft/s^2", "in^2", "lb*in^2",
            "lb*ft^2", "lbf/in", "kip/in"}
SI_UNITS = {"m", "mm", "cm", "kg", "N", "kN", "MN", "Pa", "kPa", "MPa", "GPa",
            "J/m^3", "kJ/m^3", "MJ/m^3", "kN*m/m^3", "kN.m/m^3", "m/s^2", "cm/s^2",
            "gal", "Gal", "m^2", "mm^2", "cm^2", "kg*m^2", "kg.m^2", "N/m", "kN/m",
            "MN/m", "N/mm", "kN/mm"}
QTY = re.compile(r":\s*['\"]?[-+]?[\d.]+(?:e[-+]?\d+)?(?:[ -]\d+/\d+|/\d+)?\s*([^\s,'\"}\]#]+)")


def unit_counts(path, seen=None):
    """Quantities of a case file and its bases written in US / SI units."""
    seen = seen or set()
    if path in seen or not os.path.exists(path):
        return 0, 0, None
    seen.add(path)
    us = si = 0
    asked = None
    base = None
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0]
            m = re.match(r"\s*extends:\s*(\S+)", line)
            if m:
                base = os.path.join(os.path.dirname(path), m.group(1))
            m = re.match(r"\s*output_units:\s*(\w+)", line)
            if m:
                asked = m.group(1)
            for u in QTY.findall(line):
                us += u in US_UNITS
                si += u in SI_UNITS
    if base:
        bus, bsi, basked = unit_counts(base, seen)
        us, si = us + bus, si + bsi
        asked = asked or basked
    return us, si, asked


def is_us(path):
    us, si, asked = unit_counts(path)
    return asked == "us" if asked else us > si


shipped = sorted(p for p in glob.glob(os.path.join("cases", "*.yaml")) if is_us(p))
if "cases/us-customary.yaml" not in shipped:
    fail("cases/us-customary.yaml is not seen as a US customary case")
own = sorted(glob.glob(os.path.join(HERE, "cases", "*.yaml")))
bad = sorted(glob.glob(os.path.join(HERE, "bad", "*.yaml")))
print("US cases: %s; own: %d; bad inputs: %d" % (", ".join(shipped), len(own), len(bad)))

people = []   # outputs for people


def run(name, args, codes=(0, 1)):
    """rockbolt args in the scratch directory, its stdout and stderr kept
    as outputs for people; fails on an exit code outside codes."""
    out = os.path.join(scratch, name + ".stdout")
    err = os.path.join(scratch, name + ".stderr")
    with open(out, "w") as fo, open(err, "w") as fe:
        p = subprocess.run([rb, *args], stdout=fo, stderr=fe, cwd=scratch)
    if p.returncode not in codes:
        fail("%s: exit %d (expected %s): %s" % (name, p.returncode, codes,
                                               open(err).read()[:300]))
    people.extend([out, err])
    return p.returncode


def outputs(prefix):
    """The files a command wrote under prefix (figures FILE-1, FILE-2, ...)."""
    return sorted(glob.glob(os.path.join(scratch, prefix + "*")))


cases = [os.path.abspath(p) for p in shipped] + own
for case in cases:
    n = os.path.splitext(os.path.basename(case))[0]
    run("check-" + n, ["check", case, "--text", "check-%s.txt" % n,
                       "--html", "check-%s.html" % n, "--svg", "check-%s.svg" % n])
    run("design-" + n, ["design", case, "-j", "2", "--text", "design-%s.txt" % n,
                        "--html", "design-%s.html" % n, "--svg", "design-%s.svg" % n,
                        "--pdf", "design-%s.pdf" % n])
    run("spectrum-" + n, ["spectrum", case, "--html", "spectrum-%s.html" % n,
                          "--svg", "spectrum-%s.svg" % n])
    for kind in ("check", "design", "spectrum"):
        people += outputs("%s-%s." % (kind, n)) + outputs("%s-%s-" % (kind, n))

panel = os.path.join(HERE, "cases", "panel-us.yaml")
run("fragility", ["fragility", panel, "-j", "2", "--html", "fragility.html",
                  "--svg", "fragility.svg", "--pdf", "fragility.pdf"])
people += outputs("fragility.") + outputs("fragility-")

run("batch", ["batch", *cases, "-j", "2", "--design", "--csv", "batch.csv",
              "--junit", "batch.xml", "--pdf", "batch.pdf"])
run("batch-list", ["batch", os.path.join(HERE, "list.csv"), "-j", "2", "--fragility",
                   "--csv", "batch-list.csv", "--junit", "batch-list.xml"])
people += outputs("batch.csv") + outputs("batch.xml") + outputs("batch-list.")

for case in bad:
    n = os.path.splitext(os.path.basename(case))[0]
    run("bad-" + n, ["check", case, "--text", "bad-%s.txt" % n], codes=(2,))

# a calculation package is read as its text (pdftotext, poppler-utils)
pdfs = sorted(glob.glob(os.path.join(scratch, "*.pdf")))
if len(pdfs) != len(cases) + 2:
    fail("%d PDF files written, expected %d" % (len(pdfs), len(cases) + 2))
for pdf in pdfs:
    p = subprocess.run(["pdftotext", "-layout", pdf, pdf + ".txt"], capture_output=True,
                       text=True)
    if p.returncode != 0:
        fail("pdftotext %s: %s" % (pdf, p.stderr[:200]))
    people.append(pdf + ".txt")
people = sorted(set(p for p in people if os.path.isfile(p) and not p.endswith(".pdf")))

# the quantities the scan is about must be there, in US customary units
# (an output that dropped them would pass the scan)
def text_of(*names):
    return "".join(open(os.path.join(scratch, n), errors="replace").read() for n in names)


want = [
    ("check-panel-us.stdout", r"\(tension [\d.]+ kip, shear [\d.]+ kip\)", "the verdict's forces"),
    ("check-panel-us.txt", r"S_DS 1\.5 g", "the synthetic motion's S_DS"),
    ("check-panel-us.txt", r"edge none near", "a slab without an edge"),
    ("check-free-us.txt", r"harmonic 0\.3 g", "a harmonic's amplitude"),
    ("bad-geometry.stderr", r"lever arm 16 in must exceed half the base width \(18 in\)",
     "the lever arm's message"),
    ("bad-geometry.stderr", r"deformable_length: must be between [\d.]+ in and [\d.]+ in",
     "the deformable length's range"),
    ("bad-gap.stderr", r"the gap \(20 in,", "the gap's message"),
    ("bad-embedment.stderr", r"must be from 1\.5 in to 25 in", "the embedment's range"),
    ("bad-embedment-past-slab.stderr", r"\(embedment 7 in, slab 6 in\)",
     "the embedment against the slab"),
    ("batch.stdout", r"kip", "a batch reason's force"),
    ("design-panel-us.pdf.txt", r"kip", "the calculation package's forces"),
    # 100 lb in^2 over 1200 lb x (18^2 + 45^2) in^2 = 3.5476e-5
    ("bad-inertia.stderr", r"\(got 3\.548e-05 M R\^2\)", "the inertia's message"),
]
for name, rx, what in want:
    try:
        text = text_of(name)
    except OSError:
        fail("%s: missing" % name)
        continue
    if not re.search(rx, text):
        fail("%s: %s not found (/%s/)" % (name, what, rx))

scan = subprocess.run([sys.executable, os.path.join(HERE, "si_leaks.py"), *people],
                      capture_output=True, text=True)
lines = scan.stdout.splitlines()
for line in lines[:-1][:60]:
    print(line.replace(scratch + os.sep, ""))
print(lines[-1] if lines else scan.stderr)
if scan.returncode != 0:
    fail("SI units in the outputs of US customary cases (above)")
finish("%d outputs for people read, %d failures" % (len(people), len(failures)))
