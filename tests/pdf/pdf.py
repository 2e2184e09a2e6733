"""The PDF calculation package end to end (docs/pdf.md), run as

    python3 tests/pdf/pdf.py ROCKBOLT SCRATCH

Every page is rendered with pdftoppm (none blank) and read with pdftotext:
"Page n of m" on each, the cover's fields as the case gives them, every
ACI 318 Chapter 17 clause with its numbers (the JSON report's SI values
converted here to kip: the PDF must be in the case's US customary units,
and its substituted numbers must multiply out), the design factor, the
code-static force; the paper follows the units; fragility and batch
carry their tables; bad input and bad output paths write nothing. Skips
(77) without poppler-utils."""
import json
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.getcwd(), "tests"))
import e2e  # noqa: E402

rb, scratch = e2e.start()
if not shutil.which("pdftoppm") or not shutil.which("pdftotext"):
    print("SKIP: poppler-utils (pdftoppm, pdftotext) is not installed")
    sys.exit(77)

LBF = 4.4482216152605           # N (exact by definition of the pound-force)
KIP = 1000 * LBF
PANEL = "tests/pdf/panel-us.yaml"
PROJECT = {"project": "Hospital roof, distribution panel EP-R1",
           "client": "County Health District", "engineer": "A. Engineer, PE",
           "checker": "B. Checker, SE", "date": "2026-11-27", "revision": "B",
           "job number": "2026-118"}


def out(name):
    return os.path.join(scratch, name)


def n_pages(pdf):
    info = subprocess.run(["pdfinfo", pdf], capture_output=True, text=True).stdout
    m = re.search(r"^Pages:\s+(\d+)", info, re.M)
    return int(m.group(1)) if m else 0


def page_size(pdf):
    info = subprocess.run(["pdfinfo", pdf], capture_output=True, text=True).stdout
    m = re.search(r"^Page size:\s+([\d.]+) x ([\d.]+) pts", info, re.M)
    return (float(m.group(1)), float(m.group(2))) if m else None


def page_text(pdf, i):
    return subprocess.run(["pdftotext", "-layout", "-f", str(i), "-l", str(i), pdf, "-"],
                          capture_output=True, text=True).stdout


def flat(s):
    return " ".join(s.split())


def read_pgm(path):
    """Width, height and the grey bytes of a binary PGM (P5) file."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    w, h = int(fields[1]), int(fields[2])
    return w, h, data[pos + 1:pos + 1 + w * h]


def check_pages(pdf, what):
    """Every page rendered, none blank above its footer, each numbered;
    the text of all pages, flattened."""
    n = n_pages(pdf)
    if n < 1:
        e2e.fail(f"{what}: pdfinfo reads no pages")
        return ""
    prefix = out(os.path.basename(pdf) + "-page")
    r = subprocess.run(["pdftoppm", "-gray", "-r", "30", pdf, prefix], capture_output=True)
    if r.returncode != 0:
        e2e.fail(f"{what}: pdftoppm failed: {r.stderr.decode()[:200]}")
    pages = sorted(f for f in os.listdir(scratch)
                   if f.startswith(os.path.basename(prefix)) and f.endswith(".pgm"))
    if len(pages) != n:
        e2e.fail(f"{what}: pdftoppm rendered {len(pages)} pages, pdfinfo says {n}")
    for k, f in enumerate(pages):
        w, h, px = read_pgm(os.path.join(scratch, f))
        # above the footer (the last tenth of the page): ink on the page
        body = px[:w * (h * 9 // 10)]
        dark = sum(1 for b in body if b < 160)
        if dark < 0.002 * len(body):
            e2e.fail(f"{what}: page {k + 1} is blank ({dark} dark pixels of {len(body)})")
    text = []
    for i in range(1, n + 1):
        t = page_text(pdf, i)
        if f"Page {i} of {n}" not in t:
            e2e.fail(f"{what}: page {i} does not say 'Page {i} of {n}'")
        text.append(t)
    return "\n".join(text)


def num(x, fmt):
    return fmt % x


# ---- design of the US customary panel -------------------------------------
pdf, js = out("panel.pdf"), out("panel.json")
r = e2e.run("design", PANEL, "--pdf", pdf, "--json", js, "-q")
if r.returncode not in (0, 1) or not os.path.exists(pdf):
    e2e.fail(f"design --pdf: exit {r.returncode}, {r.stderr[:300]}")
    e2e.finish()
rep = json.load(open(js))
text = check_pages(pdf, "design")
ft = flat(text)
p1 = flat(page_text(pdf, 1))
for name, value in PROJECT.items():
    if not re.search(re.escape(name) + r"\s+" + re.escape(value), p1):
        e2e.fail(f"cover: '{name}' is not followed by '{value}' on page 1")
for want in ["panel-ep-r1", PANEL, "US customary", "Seismic anchorage design"]:
    if want not in p1:
        e2e.fail(f"cover: '{want}' missing from page 1")
size = page_size(pdf)
if not size or abs(size[0] - 612) > 1 or abs(size[1] - 792) > 1:
    e2e.fail(f"a US customary case is on Letter paper (612 x 792 pt), not {size}")

# the inputs, in the case's own units and numbers
for want in ["1200.0 lb", "90.000 in", "36.000 in", "0.125 in", "36 ksi", "4 ksi",
             "6 in", "12 in", "24 in", "10 in"]:
    value, unit = want.split(" ")
    if not re.search(re.escape(value) + r"\s+" + re.escape(unit) + r"\b", ft):
        e2e.fail(f"inputs: '{want}' missing")

# every Chapter 17 mode: its clause, its equation, and its design strength
# as seismic x phi x nominal in kip, the product checked here
ac = rep["anchorage_check"]
for m in ac["modes"]:
    clause, mode = m["clause"], m["mode"]
    if f"{clause} {mode}" not in ft:
        e2e.fail(f"17: heading '{clause} {mode}' missing")
    if not m["applies"]:
        continue
    nominal, design = m["nominal_n"] / KIP, m["design_n"] / KIP
    line = (f"design strength = seismic x phi x nominal = {m['seismic_factor']:.2f} x "
            f"{m['phi']:.2f} x {nominal:.3f} = {design:.3f} kip")
    if line not in ft:
        e2e.fail(f"17: '{line}' missing")
    if abs(m["seismic_factor"] * m["phi"] * nominal - design) > 5e-4 * max(1, design):
        e2e.fail(f"17: {clause}: {m['seismic_factor']} x {m['phi']} x {nominal} != {design}")
for eq in ["N_sa = A_se,N f_uta (Eq. 17.6.1.2)", "(Eq. 17.6.2.1b)", "(Eq. 17.7.2.1b)",
           "V_cpg = k_cp N_cpg (Eq. 17.7.3.1b)"]:
    if eq not in ft:
        e2e.fail(f"17: equation '{eq}' missing")
# each motion's demand on each mode, tension and shear in kip
for i, mo in enumerate(rep["motions"]):
    a = mo.get("anchorage")
    if not a:
        e2e.fail(f"motion {i + 1}: no anchorage check in the JSON report")
        continue
    head = f"17.8 demand of motion {i + 1}, {mo['name']}"
    if head not in ft:
        e2e.fail(f"'{head}' missing")
    want = (f"N_ua = {a['tension_n'] / KIP:.3f} kip, N_ua / phi N_n = "
            f"{a['tension_ratio']:.3f}; V_ua = {a['shear_n'] / KIP:.3f} kip, "
            f"V_ua / phi V_n = {a['shear_ratio']:.3f}")
    if want not in ft:
        e2e.fail(f"motion {i + 1}: '{want}' missing")
    for mode, ratio in a["mode_ratios"].items():
        if ratio is not None and f"{ratio:.3f} {mode}" not in ft:
            e2e.fail(f"motion {i + 1}: {mode}'s demand / design {ratio:.3f} missing")

# the design summary: design factors, the code-static force in kip
for i, mo in enumerate(rep["motions"]):
    df = mo["design"]["design_factor"]
    row = (f"{i + 1} {df['no_yield']['factor']:.3f} {df['no_break']['factor']:.3f} "
           f"{mo['name']}")
    if row not in ft:
        e2e.fail(f"design summary: row '{row}' missing")
cs = rep["design"]["code_static"]
fp = f"horizontal seismic design force F_p {cs['fp_n'] / KIP:.3f} kip"
if fp not in ft:
    e2e.fail(f"code-static: '{fp}' missing")
if "What this calculation does not check" not in ft:
    e2e.fail("the statement of what is not checked is missing")
if text.count("Figure ") < len(rep["motions"]):
    e2e.fail("fewer figure captions than motions")

# no SI unit in a US customary package, outside the verdict reasons and
# motion descriptions that the JSON report carries as text
rest = ft
strings = []


def collect(v, key=""):
    if isinstance(v, dict):
        for k, x in v.items():
            collect(x, k)
    elif isinstance(v, list):
        for x in v:
            collect(x, key)
    elif isinstance(v, str) and (key.endswith("reason") or key in ("source", "summary")):
        strings.append(flat(v))


collect(rep)
for s in sorted(strings, key=len, reverse=True):
    rest = rest.replace(s, "")
# the figures' titles repeat the motion descriptions, and the headline
# the first reason, each cut where a line ends
rest = re.sub(r"\(synthetic: [^)]*\)|synthetic: AC156 \(2010\) S_DS [\d.]+ m/s\^2", "", rest)
rest = re.sub(r"\(tension [\d.]+ kN, shear [\d.]+ kN\)", "", rest)
si = re.findall(r"\d\s*(kN|MPa|mm|m/s\^2|kJ|MN/m|kg|J|Pa|m)\b", rest)
if si:
    e2e.fail(f"SI units in the US customary package: {sorted(set(si))}")

# ---- check of an SI case: A4, its clauses ----------------------------------
pdf2 = out("concrete.pdf")
r = e2e.run("check", "cases/reference-concrete.yaml", "--pdf", pdf2, "-q")
if r.returncode != 1 or not os.path.exists(pdf2):
    e2e.fail(f"check --pdf: exit {r.returncode} (want 1, the case fails), {r.stderr[:200]}")
else:
    t2 = flat(check_pages(pdf2, "check"))
    size = page_size(pdf2)
    if not size or abs(size[0] - 595.3) > 1 or abs(size[1] - 841.9) > 1:
        e2e.fail(f"an SI case is on A4 paper (595 x 842 pt), not {size}")
    for clause in ["17.6.1", "17.6.2", "17.6.3", "17.6.4", "17.6.5", "17.7.1", "17.7.2",
                   "17.7.3", "17.10.5.3", "17.8"]:
        if clause not in t2:
            e2e.fail(f"check: clause {clause} missing")
    if " kN" not in t2 or "5 Design summary" in t2:
        e2e.fail("check: an SI check has kN and no design summary")

# ---- fragility: its table and its figure -----------------------------------
pdf3 = out("fragility.pdf")
r = e2e.run("fragility", "cases/fragility-suite.yaml", "--pdf", pdf3, "-j", "2")
if r.returncode != 0 or not os.path.exists(pdf3):
    e2e.fail(f"fragility --pdf: exit {r.returncode}, {r.stderr[:200]}")
else:
    t3 = flat(check_pages(pdf3, "fragility"))
    for line in r.stdout.splitlines():
        if line.strip() and flat(line) not in t3:
            e2e.fail(f"fragility: the table's line '{line.strip()}' missing")
            break
    if "Figure 1 of 1" not in t3:
        e2e.fail("fragility: no figure")

# ---- batch: the summary ----------------------------------------------------
pdf4 = out("batch.pdf")
r = e2e.run("batch", "tests/batch/list.csv", "--pdf", pdf4, "-q", "-j", "2")
if not os.path.exists(pdf4) or r.stdout:
    e2e.fail(f"batch --pdf -q: no PDF, or text on stdout (exit {r.returncode})")
else:
    t4 = flat(check_pages(pdf4, "batch"))
    for tag in ["P-101", "P-102", "P-103, spare", "P-104", "P-105", "P-106"]:
        if tag not in t4:
            e2e.fail(f"batch: item {tag} missing from the summary")
    if "Seismic anchorage batch summary" not in t4:
        e2e.fail("batch: no title")

# a list over --base takes the base's project: for its cover and the base's
# units for its paper (the rows share the base)
lst = e2e.write("panel-list.csv", "tag,gap_ratio\nEP-1,0.01\nEP-2,0.02\n")
pdf6 = out("batch-base.pdf")
r = e2e.run("batch", lst, "--base", PANEL, "--pdf", pdf6, "-q")
if not os.path.exists(pdf6):
    e2e.fail(f"batch --base --pdf: no PDF (exit {r.returncode}): {r.stderr[:300]}")
else:
    p1 = flat(page_text(pdf6, 1))
    for name, value in PROJECT.items():
        if not re.search(re.escape(name) + r"\s+" + re.escape(value), p1):
            e2e.fail(f"batch cover: '{name}' is not followed by '{value}' on page 1")
    size = page_size(pdf6)
    if not size or abs(size[0] - 612) > 1 or abs(size[1] - 792) > 1:
        e2e.fail(f"batch over a US base is on Letter paper (612 x 792 pt), not {size}")

# ---- bad input and bad outputs: exit 2, nothing written --------------------
bad = e2e.write("bad-project.yaml", open(PANEL).read().replace(
    "  revision: B\n", "  revison: B\n"))
pdf5 = out("bad.pdf")
r = e2e.run("check", bad, "--pdf", pdf5)
if r.returncode != 2 or os.path.exists(pdf5):
    e2e.fail(f"bad project key: exit {r.returncode} (want 2), PDF written: "
             f"{os.path.exists(pdf5)}")
if not re.search(r"bad-project\.yaml:\d+:3: error: project\.revison: unknown key "
                 r"'revison' \(did you mean 'revision'\?\)", r.stderr):
    e2e.fail(f"bad project key: diagnostic is '{r.stderr.strip()[:200]}'")
r = e2e.run("check", PANEL, "--pdf", out("no-such-dir/x.pdf"))
if r.returncode != 2 or "--pdf" not in r.stderr:
    e2e.fail(f"--pdf into a missing directory: exit {r.returncode}, '{r.stderr[:200]}'")
before = open(PANEL, "rb").read()
r = e2e.run("check", PANEL, "--pdf", PANEL)
if r.returncode != 2 or open(PANEL, "rb").read() != before:
    e2e.fail(f"--pdf naming the case: exit {r.returncode}, case changed: "
             f"{open(PANEL, 'rb').read() != before}")
r = e2e.run("check", PANEL, "--pdf")
if r.returncode != 2 or "--pdf" not in r.stderr:
    e2e.fail(f"--pdf without a file: exit {r.returncode}, '{r.stderr[:200]}'")
r = e2e.run("spectrum", "cases/ac156-roof.yaml", "--pdf", out("s.pdf"))
if r.returncode != 2 or os.path.exists(out("s.pdf")):
    e2e.fail(f"spectrum takes no --pdf: exit {r.returncode}")

e2e.finish()
