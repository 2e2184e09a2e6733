#!/usr/bin/env python3
"""The progress line while a case's suite of synthetic motions is generated:
on a terminal's stderr, never on stdout, a pipe or under --quiet, taken
away before the command goes on, and the report the same bytes either way.

    python3 tests/cli/progress.py ROCKBOLT SCRATCH

Run from the source root (ctest does). stderr is a pseudo-terminal where
the test needs a terminal. The suite is two horizontal AC156 motions of
4 s: the line is always shown for the last, however fast the first was."""
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from e2e import fail, failures, finish, src, start, write  # noqa: E402

rb, scratch = start()
case = write("suite.yaml", f"""extends: {src}/cases/base/reference-cabinet.yaml
name: progress
motions:
  - type: synthetic
    name: ac156
    spectrum: {{type: ac156, sds: 1.0 g, z_over_h: 1.0}}
    count: 2
    seed: 1
    duration: 4 s
    components: horizontal
""")
LINE = b"generating motions: "
CLEAR = b"\r\x1b[K"


def run_on_tty(*args):
    """rockbolt with args, stderr a pseudo-terminal: (exit, stdout, stderr)."""
    master, slave = os.openpty()
    p = subprocess.Popen([rb, *args], stdout=subprocess.PIPE, stderr=slave,
                         stdin=subprocess.DEVNULL)
    os.close(slave)
    err = b""
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:      # the terminal's other end closed
            break
        if not chunk:
            break
        err += chunk
    out = p.stdout.read()
    p.wait()
    os.close(master)
    return p.returncode, out, err


for cmd in (["check", case], ["motion", case, "--dir", os.path.join(scratch, "m")]):
    name = cmd[0]
    rc, out, err = run_on_tty(*cmd)
    if rc not in (0, 1):
        fail(f"{name} on a terminal: exit {rc}: {err[-300:]!r}")
        continue
    if LINE + b"2/2 components" not in err:
        fail(f"{name}: no progress line for the 2 components on the terminal: {err[:300]!r}")
    last = err.rfind(LINE)
    if last >= 0 and CLEAR not in err[last:]:
        fail(f"{name}: the progress line is not taken away: {err[last:last + 200]!r}")
    if LINE in out:
        fail(f"{name}: the progress line on stdout")
    rc, out, err = run_on_tty(*cmd, "--quiet")
    if LINE in err:
        fail(f"{name} --quiet: a progress line on the terminal")

# stderr a pipe (a log, a CI console): nothing, and the same report
tty_json, pipe_json = os.path.join(scratch, "tty.json"), os.path.join(scratch, "pipe.json")
run_on_tty("check", case, "--json", tty_json)
r = subprocess.run([rb, "check", case, "--json", pipe_json], capture_output=True)
if r.returncode not in (0, 1) or LINE in r.stderr or LINE in r.stdout:
    fail(f"check with stderr a pipe: exit {r.returncode}, progress shown or no run")
with open(tty_json, "rb") as a, open(pipe_json, "rb") as b:
    if a.read() != b.read():
        fail("the JSON report differs on a terminal")

# a case with no suite to generate: nothing on the terminal either
rc, out, err = run_on_tty("check", "cases/reference-harmonic.yaml")
if rc not in (0, 1) or LINE in err:
    fail(f"check of a harmonic case on a terminal: exit {rc}, {err[:200]!r}")

finish(None if failures else "progress line: on a terminal alone, cleared, none under --quiet")
