#!/usr/bin/env python3
"""Find SI units in outputs meant for people (text, HTML, SVG, tables,
JUnit, CSV reasons, diagnostics) of cases in US customary units.

    si_leaks.py FILE...

Prints every hit as FILE:LINE: the unit and its context, and exits 1 when
there is one. HTML and SVG are read as what a browser shows: the text
between tags, with style and script blocks left out and entities decoded,
plus the title and aria-label attributes a reader hovers or hears."""
import html
import re
import sys

NUM = r"(?:\d(?:[\d.]*\d)?(?:e[+-]?\d+)?)"
# A unit is SI when it is written after a number or as a column's unit in
# parentheses or brackets, or when its name cannot be anything else.
PATTERNS = [
    # names no US-customary text uses
    r"\bk?N\*m\b", r"\bkN-m\b", r"\bN-m\b", r"\b[kMG]?Pa\b", r"\b[kM]?N/m\b",
    r"\bkN\b", r"\bMN\b", r"\bm/s\^2\b", r"\bm/s2\b", r"\bcm/s\^2\b",
    r"\bmm/s\^2\b", r"\bk?J/m\^3\b", r"\bMJ/m\^3\b", r"\b[cm]?m\^[23]\b",
    r"\bmm\b", r"\bcm\b", r"\bkg\b", r"\bkJ\b", r"\bkg\*m\^2\b",
    # short names, only as units
    NUM + r" ?(?:m|N|J|gal|Gal)(?![\w/^*'-])",
    r"[(\[](?:m|N|J)[)\]]",
]
RX = re.compile("|".join("(?:%s)" % p for p in PATTERNS))

# Text that names SI units without being a quantity of the case. Each entry
# is matched against the whole line and what it matches is removed before
# the scan; keep it short and say why.
ALLOW = [
    # the accepted units of a dimension, listed by a diagnostic about a
    # unit the case wrote (units.h, rb_dim_units)
    r"\(expected [a-z ]+: [^)]*\)",
    r"expected [a-z ]+: [a-zA-Z0-9^*/.%, ]+$",
]
ALLOW_RX = [re.compile(a) for a in ALLOW]


def visible_text(path, data):
    """The text a reader sees, line by line, with the source line numbers."""
    if not (path.endswith(".html") or path.endswith(".svg") or path.endswith(".xml")):
        return data.split("\n")
    # drop what is not shown, keeping line breaks so lines still count
    def blank(m):
        return "\n" * m.group(0).count("\n")
    data = re.sub(r"(?is)<(style|script)\b.*?</\1>", blank, data)
    data = re.sub(r"(?s)<!--.*?-->", blank, data)
    out = []
    for line in data.split("\n"):
        attrs = re.findall(r'(?:title|aria-label|message|value)="([^"]*)"', line)
        text = re.sub(r"<[^>]*>", " ", line)
        out.append(html.unescape(" ".join([text] + attrs)))
    return out


def scan(path):
    hits = []
    with open(path, encoding="utf-8", errors="replace") as f:
        data = f.read()
    for n, line in enumerate(visible_text(path, data), 1):
        for a in ALLOW_RX:
            line = a.sub(" ", line)
        for m in RX.finditer(line):
            lo, hi = max(0, m.start() - 50), min(len(line), m.end() + 30)
            hits.append("%s:%d: '%s' in: %s" % (path, n, m.group(0).strip(),
                                                line[lo:hi].strip().replace("\n", " ")))
    return hits


def main(argv):
    if len(argv) < 2:
        print("usage: si_leaks.py FILE...", file=sys.stderr)
        return 2
    hits = []
    for p in argv[1:]:
        hits += scan(p)
    for h in hits:
        print(h)
    print("%d files, %d SI units" % (len(argv) - 1, len(hits)))
    return 1 if hits else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
