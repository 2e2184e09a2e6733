#!/usr/bin/env python3
"""The include graph and the link graph against the layer order.

CMakeLists.txt declares the libraries bottom up (`rb_library(rb_X src/X/*.c)`);
a folder may include a header only of its own folder or of one declared
before it, and a library may call only into itself or libraries declared
before it. Public headers (include/rockbolt) belong to the folder named in
OWNER below: a new header must be given its folder here. Within a folder no
two files may call each other in a circle, except a header with its source
(the link graph between the folder's object files, from nm).

usage: layers.py SOURCE_DIR [BUILD_DIR]   (the link checks need BUILD_DIR)
"""
import os
import re
import subprocess
import sys

# The folder whose library implements (or, for types alone, defines) each
# public header.
OWNER = {
    "status.h": "util", "names.h": "util", "units.h": "util", "textsafe.h": "util",
    "jsonnum.h": "util", "datadir.h": "util", "sandbox.h": "util", "version.h": "util",
    "outplan.h": "output", "outfile.h": "output",
    "motion.h": "motion", "spectrum.h": "motion", "accept.h": "motion",
    "floors.h": "motion",
    "model.h": "core", "solve.h": "core", "criteria.h": "core", "interaction.h": "core",
    "aci17.h": "codes", "aci17_post.h": "codes", "anchor.h": "codes",
    "anchor_hardware.h": "codes", "asce7.h": "codes",
    "record.h": "record", "record_cache.h": "record",
    "design.h": "design",
    "synth.h": "synth",
    "fragility.h": "fragility",
    "case.h": "case", "case_overrides.h": "case",
    "report.h": "report", "jsonprint.h": "report", "jsonbuild.h": "report",
    "template.h": "report", "floor_files.h": "report",
    "plot.h": "plot",
    "pdf.h": "pdf",
    "run.h": "run",
    "batch.h": "batch",
    "rockbolt.h": "cli",
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def layers(src):
    text = open(os.path.join(src, "CMakeLists.txt")).read()
    order = re.findall(r"^rb_library\((rb_\w+)\s+src/(\w+)/\*\.c\)", text, re.M)
    if not order:
        sys.exit("no rb_library declarations in CMakeLists.txt")
    return order


def header_owner(inc, folder):
    """The folder an #include "inc" written in folder names."""
    if inc.startswith("rockbolt/"):
        return OWNER.get(inc[len("rockbolt/"):])
    if "/" not in inc:           # the folder's own header
        return folder
    path = os.path.normpath(os.path.join(folder, inc) if inc.startswith("..") else inc)
    parts = path.split(os.sep)   # folder/file.h, relative or from src/
    return parts[0] if len(parts) == 2 else None


def include_violations(src, rank):
    bad = []
    hdrs = sorted(os.listdir(os.path.join(src, "include/rockbolt")))
    for h in hdrs:
        if h.endswith(".h") and h not in OWNER:
            bad.append(f"include/rockbolt/{h}: no folder owns it (OWNER in {__file__})")
    files = [(f"include/rockbolt/{h}", OWNER.get(h)) for h in hdrs if h.endswith(".h")]
    for folder in sorted(os.listdir(os.path.join(src, "src"))):
        d = os.path.join(src, "src", folder)
        if os.path.isdir(d):
            files += [(f"src/{folder}/{f}", folder) for f in sorted(os.listdir(d))
                      if f.endswith((".c", ".h"))]
    n = 0
    for path, folder in files:
        if folder is None:
            continue
        for inc in INCLUDE.findall(open(os.path.join(src, path)).read()):
            n += 1
            owner = header_owner(inc, folder)
            if owner is None:
                bad.append(f'{path}: #include "{inc}": no folder owns it')
            elif rank.get(owner, -1) > rank.get(folder, -1) and owner in rank:
                bad.append(f'{path} ({folder}) includes "{inc}" of {owner}, above it')
    return bad, n


def symbols(objs):
    """Defined and undefined symbols of each object, from one nm for all of
    them (one process per object made the test slow on a loaded machine)."""
    table = {o: (set(), set()) for o in objs}
    if not objs:
        return table
    out = subprocess.run(["nm", "-A", *objs], capture_output=True, text=True,
                         check=True).stdout
    for line in out.splitlines():
        obj, _, rest = line.partition(":")
        if obj not in table:
            continue
        f = rest.split()
        if len(f) == 2 and f[0] == "U":
            table[obj][1].add(f[1])
        elif len(f) == 3 and f[1] in "TDBRCVW":
            table[obj][0].add(f[2])
    return table


def link_violations(src, build, order, rank):
    bad = []
    objs = {}                   # folder -> {object: (defined, undefined)}
    for lib, folder in order:
        d = os.path.join(build, "CMakeFiles", f"{lib}.dir", "src", folder)
        if not os.path.isdir(d):
            bad.append(f"{d}: not built")
            continue
        # objects of the folder's sources (a moved file leaves its old one)
        names = [o for o in sorted(os.listdir(d)) if o.endswith(".c.o")
                 and os.path.exists(os.path.join(src, "src", folder, o[:-2]))]
        table = symbols([os.path.join(d, o) for o in names])
        objs[folder] = {o[:-len(".c.o")]: table[os.path.join(d, o)] for o in names}
    where = {}
    for folder, fs in objs.items():
        for f, (dfn, _) in fs.items():
            for s in dfn:
                where[s] = (folder, f)
    for folder, fs in objs.items():
        edges = {f: set() for f in fs}
        for f, (_, und) in fs.items():
            for s in und:
                if s not in where:
                    continue
                owner, g = where[s]
                if rank[owner] > rank[folder]:
                    bad.append(f"src/{folder}/{f}.c calls {s} of src/{owner}/{g}.c, above it")
                elif owner == folder and g != f:
                    edges[f].add(g)
        bad += [f"src/{folder}: the files call each other in a circle: {' -> '.join(c)}"
                for c in circles(edges)]
    return bad, len(where)


def circles(edges):
    """One circle per strongly connected component of more than one file."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))
    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    return out


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    src = sys.argv[1]
    order = layers(src)
    rank = {folder: i for i, (_, folder) in enumerate(order)}
    rank["cli"] = len(order)
    bad, n_inc = include_violations(src, rank)
    n_sym = 0
    if len(sys.argv) == 3:
        more, n_sym = link_violations(src, sys.argv[2], order, rank)
        bad += more
    for b in bad:
        print("FAIL:", b)
    print(f"{len(order)} layers ({' < '.join(f for _, f in order)}), "
          f"{n_inc} includes, {n_sym} symbols checked: {len(bad)} violations")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
