#!/usr/bin/env python3
"""rb_diag_set and its field setters (src/util/status.c) are the one way to
write an rb_diag's text: fail on any other write into a `file`, `key` or
`msg` field in src/ (snprintf, vsnprintf, sprintf, strcpy, strcat, memcpy,
...), save for the fields listed below, which are not rb_diag's.

    python3 tests/layers/diag_writes.py SOURCE_ROOT"""
import os, re, sys

WRITERS = r"(?:v?sn?printf|strn?cpy|strn?cat|memcpy|memmove)"
WRITE = re.compile(WRITERS + r"\s*\(\s*([A-Za-z_][\w.\->\[\]]*?)(?:->|\.)(file|key|msg)\s*[,)]")
# lvalues of other structs with a field of the same name: (file, lvalue)
NOT_DIAG = {
    ("src/case/case_value.c", "f"),          # rb_cfield.key, the case's key path
    ("src/case/case_motion.c", "cm"),        # rb_case_motion.key
    ("src/batch/batch_list_csv.c", "col"),   # a list column's case key
}
OWNER = "src/util/status.c"


def offences(root):
    bad = []
    for d, _, files in os.walk(os.path.join(root, "src")):
        for f in sorted(files):
            if not f.endswith((".c", ".h")):
                continue
            path = os.path.join(d, f)
            rel = os.path.relpath(path, root)
            if rel == OWNER:
                continue
            text = open(path, encoding="utf-8").read()
            for m in WRITE.finditer(text):
                if (rel, m.group(1)) in NOT_DIAG:
                    continue
                line = text.count("\n", 0, m.start()) + 1
                bad.append("%s:%d: %s" % (rel, line, m.group(0)))
    return bad


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    # the pattern must see the writes it is there to refuse
    for sample in ('snprintf(d->msg, sizeof d->msg, "x")', "vsnprintf(diag.key, n, f, ap)",
                   "strcat(e->error->file, at)", "memcpy(d->msg, m, sizeof m)"):
        if not WRITE.search(sample):
            print("FAIL: the pattern misses", sample)
            return 1
    for rel, _ in NOT_DIAG:
        if not os.path.exists(os.path.join(root, rel)):
            print("FAIL: %s is listed but gone: update NOT_DIAG" % rel)
            return 1
    bad = offences(root)
    for b in bad:
        print("FAIL: %s: fill an rb_diag with rb_diag_set or rb_diag_set_file/_key/_msg" % b)
    if bad:
        return 1
    print("no write into an rb_diag outside %s" % OWNER)
    return 0


sys.exit(main())
