#!/usr/bin/python3
"""A restart at the tutorials' own write settings (writePrecision 12)
continues exactly: the state touchFoam restarts from is written with 17
digits whatever writePrecision says.

    /usr/bin/python3 test/cases/restartPrecision.py

The swinging cube at 4 x 4 x 4 cells (neoHookean, as its tutorial) and
the twisting column at 2 x 12 x 2 (RK3, angular momentum preservation),
both written every 1 ms at writePrecision 12 (the tutorials'), run
  - uninterrupted to 4 ms, and
  - to 2 ms, then restarted (startFrom latestTime) to 4 ms;
the files of the state (lm, F, D, pointD) and of the viewing fields (U, J)
at 4 ms must be byte-identical; and a second uninterrupted run must write
every file of every time folder byte-identical to the first (a run is
reproducible).  A run killed while writing leaves its last time folder
cut short (measured: SIGKILL of a 12^3 swinging cube written every step
left a folder holding only P, the first output field written, and every
restart stopped on it): the part run's restart is made from such a
folder, 3 ms holding only the P the whole run wrote there; touchFoam must
warn that 3 ms is incomplete, move it to 0.003.incomplete, start from
2 ms, and end identical.  The state files carry 17 significant
digits, the viewing fields (U) 12.  Before 2026-12-04 the state was
written at writePrecision too and a restart from 12 digits differed
(measured on the swinging cube case of this test at commit a546ea2: lm,
F, D, pointD and U at 4 ms differed).
Work folders: test/runs/restartPrecision/.
"""

import os
import re
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, run, testing  # noqa: E402

NAME = "restartPrecision"
FILES = ["lm", "F", "D", "pointD", "U", "J"]
CONTROL = {"endTime": 0.004, "writeInterval": 0.001, "writePrecision": 12,
           "writeControl": "adjustableRunTime"}


def set_end(case, end):
    path = os.path.join(case, "system", "controlDict")
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(re.sub(r"\nendTime\s+[^;]*;", "\nendTime %g;" % end, text))


def digits(path):
    """Significant digits of the first number of the internal field"""
    with open(path) as f:
        text = f.read()
    m = re.search(r"internalField\s+nonuniform[^(]*\(\s*\(?\s*"
                  r"-?(\d+)\.(\d+)", text)
    return len((m.group(1) + m.group(2)).lstrip("0")) if m else None


def body():
    root = testing.work_dir(NAME)
    failures, lines = [], []
    for tutorial, n in (("swingingCube", 4), ("twistingColumn", 2)):
        whole = cases.prepare(tutorial, os.path.join(root, tutorial + "-whole"),
                              n=n, control=CONTROL)
        part = cases.prepare(tutorial, os.path.join(root, tutorial + "-part"),
                             n=n, control=CONTROL)
        run.run(["touchFoam"], whole, timeout=testing.RUN_TIMEOUT)
        set_end(part, 0.002)
        run.run(["touchFoam"], part, timeout=testing.RUN_TIMEOUT)
        set_end(part, 0.004)
        cut = os.path.join(part, "0.003")
        os.makedirs(cut)
        shutil.copy(os.path.join(whole, "0.003", "P"), cut)
        log = run.run(["touchFoam"], part, name="touchFoam-restart",
                      timeout=testing.RUN_TIMEOUT)
        with open(log) as f:
            text = " ".join(f.read().split())
        if not re.search(r"Time folder 0\.003 is incomplete: its U, written "
                         r"last, is missing .* Moved to 0\.003\.incomplete", text):
            failures.append("%s: no warning that 0.003 is incomplete"
                            % tutorial)
        same = []
        for name in FILES:
            with open(os.path.join(whole, "0.004", name), "rb") as f:
                a = f.read()
            with open(os.path.join(part, "0.004", name), "rb") as f:
                b = f.read()
            if a != b:
                failures.append("%s: %s at 4 ms differs after the restart"
                                % (tutorial, name))
            else:
                same.append(name)
        twice = cases.prepare(tutorial,
                              os.path.join(root, tutorial + "-twice"),
                              n=n, control=CONTROL)
        run.run(["touchFoam"], twice, timeout=testing.RUN_TIMEOUT)
        compared = 0
        for time in sorted(d for d in os.listdir(whole)
                           if re.match(r"^[0-9.]+$", d) and d != "0"):
            for top, _, names in os.walk(os.path.join(whole, time)):
                for name in names:
                    a_path = os.path.join(top, name)
                    b_path = os.path.join(twice, os.path.relpath(a_path,
                                                                 whole))
                    with open(a_path, "rb") as f:
                        a = f.read()
                    with open(b_path, "rb") as f:
                        b = f.read()
                    compared += 1
                    if a != b:
                        failures.append("%s: a second run wrote %s "
                                        "differently" % (tutorial,
                                                         os.path.relpath(
                                                             a_path, whole)))
        lines.append("%s: second run identical in %d files" %
                     (tutorial, compared))
        lm_digits = digits(os.path.join(part, "0.002", "lm"))
        U_digits = digits(os.path.join(part, "0.002", "U"))
        if lm_digits is None or lm_digits < 16:
            failures.append("%s: lm written with %s digits" %
                            (tutorial, lm_digits))
        if U_digits is None or U_digits > 12:
            failures.append("%s: U written with %s digits, not at "
                            "writePrecision 12" % (tutorial, U_digits))
        lines.append("%s: identical %s; lm %s digits, U %s" % (
            tutorial, " ".join(same), lm_digits, U_digits))
    if failures:
        raise AssertionError("; ".join(failures) + " | " + "; ".join(lines))
    return "; ".join(lines)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
