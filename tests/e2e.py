"""What the end-to-end test scripts share: their arguments, a scratch
directory emptied first, the failures they collect and print, and running
rockbolt. A script is run from the source root as

    python3 tests/DIR/SCRIPT.py ROCKBOLT [OTHER...] SCRATCH [...]

and imports this module after putting tests/ on sys.path. start() takes
the paths and empties the scratch directory; run() and write() use them.
"""
import os
import shutil
import subprocess
import sys

src = os.getcwd()
failures = []
_rb = None
_scratch = None


def start(n_paths=2):
    """The first n_paths arguments as absolute paths: rockbolt first, the
    scratch directory last, which is emptied."""
    global _rb, _scratch
    paths = [os.path.abspath(a) for a in sys.argv[1:1 + n_paths]]
    _rb, _scratch = paths[0], paths[-1]
    shutil.rmtree(_scratch, ignore_errors=True)
    os.makedirs(_scratch)
    return paths


def fail(msg, shown=None):
    """Collect a failure; print it (only the first `shown` when given)."""
    failures.append(msg)
    if shown is None or len(failures) <= shown:
        print("FAIL:", msg)


def run(*args):
    """rockbolt with args, output captured as text."""
    return subprocess.run([_rb, *args], capture_output=True, text=True)


def write(name, text):
    """A file of the scratch directory; its path."""
    p = os.path.join(_scratch, name)
    with open(p, "w") as f:
        f.write(text)
    return p


def finish(line=None):
    """Print line (or the count of failures) and exit 1 on any failure."""
    print(line if line is not None else f"{len(failures)} failures")
    sys.exit(1 if failures else 0)
