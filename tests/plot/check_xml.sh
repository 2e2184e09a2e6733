#!/bin/sh
# Every figure and the HTML page must parse as XML with a real parser.
# Usage: check_xml.sh PLOT_SAMPLE SCRATCH_DIR   (from the repository root)
# Exit 77 (skipped) when python3 is not installed.
set -eu
sample=$1 dir=$2
command -v python3 >/dev/null 2>&1 || { echo "python3 not installed: skipped"; exit 77; }
rm -rf "$dir" && mkdir -p "$dir"
"$sample" "$dir"
python3 - "$dir" <<'PY'
import glob, os, sys
import xml.etree.ElementTree as E
from html.parser import HTMLParser
d = sys.argv[1]
files = sorted(glob.glob(os.path.join(d, "*.svg"))) + [os.path.join(d, "report.html")]
SVG = "{http://www.w3.org/2000/svg}"
bad = 0
for f in files:
    try:
        root = E.parse(f).getroot()
    except E.ParseError as e:
        print(f"{f}: not well-formed XML: {e}"); bad += 1; continue
    if f.endswith(".svg"):
        if root.tag != SVG + "svg":
            print(f"{f}: root is {root.tag}, not svg"); bad += 1
        if not root.findall(f".//{SVG}path"):
            print(f"{f}: no series drawn"); bad += 1
    else:
        n = len(root.findall(f".//{SVG}svg"))
        if n != len(files) - 1:
            print(f"{f}: {n} inline figures, want {len(files) - 1}"); bad += 1
        # and as HTML: a browser-style parser must see the same figures
        class Count(HTMLParser):
            svgs = 0
            def handle_starttag(self, tag, attrs):
                if tag == "svg": self.svgs += 1
        p = Count(); p.feed(open(f, encoding="utf-8").read()); p.close()
        if p.svgs != n:
            print(f"{f}: html.parser sees {p.svgs} figures, XML {n}"); bad += 1
    print(f"{f}: {os.path.getsize(f)} bytes, ok" if not bad else f"{f}: checked")
sys.exit(1 if bad else 0)
PY
