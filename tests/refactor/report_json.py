"""What compare.py and rounding.py share: a case's JSON report from one
build, and a report flattened to key paths."""
import json, os, subprocess


def check_report(rb, case, out, timeout):
    """Exit code ("timeout" past timeout seconds) and the JSON report of
    `rb check CASE` (None where it wrote none), written to out."""
    if os.path.exists(out):
        os.remove(out)
    try:
        rc = subprocess.run([rb, "check", case, "--json", out, "--quiet"],
                            capture_output=True, timeout=timeout).returncode
    except subprocess.TimeoutExpired:
        rc = "timeout"
    return rc, (json.load(open(out)) if os.path.exists(out) else None)


def flat(o, p=""):
    """(key path, value) of every leaf: motions[3].bolts.usage[1]."""
    if isinstance(o, dict):
        for k, v in o.items():
            yield from flat(v, f"{p}.{k}" if p else k)
    elif isinstance(o, list):
        for i, v in enumerate(o):
            yield from flat(v, f"{p}[{i}]")
    else:
        yield p, o
