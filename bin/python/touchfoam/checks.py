"""The checks of a validation study: each measured value beside its
reference and the verdict, in <study folder>/checks.json, which
validation/Allrun gathers into one table at the top of its report.

A study's script calls record() where it decides a pass or a fail (or
states a value beside a reference), then ends with
sys.exit(checks.status(HERE)) (or folds it into its own exit status), so
that its exit status is non-zero when one of its checks fails:

    from touchfoam import checks
    checks.record(HERE, "separation agreement n6/n12", 0.012, "<= 0.05",
                  0.012 <= 0.05, note="|t_s(6) - t_s(12)| / t_s(12)")
    ...
    return checks.status(HERE)

The first record() of a process rewrites the file (a run replaces the
checks of the previous run); start() does so explicitly, for a study that
wants an empty list even when it records nothing.  Values are stored as
given when they are numbers or strings (numbers are shown with 4
significant digits in the report), anything else as its str().

    python3 checks.py table DIR...

prints the markdown table of the checks of the studies in DIR... (FAIL
rows first; a study without checks.json gets a row saying it has no
check, counted as a fail), and exits 1 when some row fails.
"""

import json
import os
import sys

FILE = "checks.json"

#: folders whose checks.json this process has already rewritten
_started = set()


def path(folder):
    return os.path.join(os.path.abspath(folder), FILE)


def start(folder):
    """Empty <folder>/checks.json (the start of a run)."""
    with open(path(folder), "w") as f:
        json.dump([], f)
    _started.add(path(folder))


def _value(v):
    if v is None or isinstance(v, (bool, int, float, str)):
        return v
    try:
        return float(v)      # numpy scalars
    except (TypeError, ValueError):
        return str(v)


def record(folder, quantity, measured, reference, passed, note=""):
    """Append one check to <folder>/checks.json: the quantity, its measured
    value, its reference (a value or a condition such as '<= 1e-10'),
    whether it passed, and a note (how it is measured, or why a reduced
    size cannot meet the reference).  Returns passed as a bool."""
    if path(folder) not in _started:
        start(folder)
    rows = load(folder) or []
    rows.append({"quantity": str(quantity), "measured": _value(measured),
                 "reference": _value(reference), "pass": bool(passed),
                 "note": str(note)})
    with open(path(folder), "w") as f:
        json.dump(rows, f, indent=1)
    return bool(passed)


def load(folder):
    """The checks of <folder> (a list of dicts), None without checks.json."""
    try:
        with open(path(folder)) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def status(folder):
    """The exit status of a study: 1 when a check failed or none was
    recorded, 0 otherwise."""
    rows = load(folder)
    return 0 if rows and all(r["pass"] for r in rows) else 1


def _show(v):
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float):
        return "%.4g" % v
    return "-" if v is None else str(v).replace("|", "\\|")


def table(folders):
    """Markdown lines of the checks of every study folder, FAIL rows first,
    and the number of failing rows."""
    rows = []
    for folder in folders:
        study = os.path.basename(os.path.abspath(folder))
        checks = load(folder)
        if not checks:
            rows.append((study, "(no check recorded: %s missing or empty)"
                         % FILE, "-", "-", False,
                         "the study states no measured value beside a "
                         "reference, or it stopped before its checks"))
            continue
        for c in checks:
            rows.append((study, c["quantity"], _show(c["measured"]),
                         _show(c["reference"]), c["pass"], c.get("note", "")))
    failed = [r for r in rows if not r[4]]
    lines = ["| study | quantity | measured | reference | pass/fail | note |",
             "|---|---|---|---|---|---|"]
    for r in failed + [r for r in rows if r[4]]:
        lines.append("| %s | %s | %s | %s | %s | %s |" % (
            r[0], r[1].replace("|", "\\|"), r[2], r[3],
            "pass" if r[4] else "**FAIL**", r[5].replace("|", "\\|")))
    return lines, len(failed), len(rows)


def main(argv):
    if len(argv) < 2 or argv[0] != "table":
        print(__doc__, file=sys.stderr)
        return 2
    lines, failed, total = table(argv[1:])
    print("\n".join(lines))
    print("\n%d checks, %d failed." % (total, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
