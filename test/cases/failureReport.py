#!/usr/bin/python3
"""A step that inverts a cell stops the run with a report that locates it,
writes the last good state and exits non-zero.

    /usr/bin/python3 test/cases/failureReport.py

On a 4^3 swinging cube whose face X1 is loaded by a pressure that jumps
from 0 to 2e8 Pa (12 times E) at t = 4 ms (the cells next to X1 are
crushed in the first step that reaches it), written only at endTime:
  - touchFoam exits with status 1 (FatalError, not a signal);
  - the log names the invalid cell: its label, current and reference
    centre, J = det F <= 0, the step (start -> end), dt, the Runge-Kutta
    stage (k of 3 of RK3), and the nearest boundary, X1, whose distance
    must equal 1 - x of the reference centre (h/2 = 0.125);
  - the last good state is written to the step start's time folder,
    named in the error, and it equals the state a run stopped there by
    maxSteps writes (the same steps, no failure): lm and F to 1e-12;
  - with writeInterval at every step, the failing step's start folder
    exists already: it is not overwritten (its files are unchanged) and
    the error says the last good state is that existing folder.
Work folders: test/runs/failureReport/.
"""

import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, foamfile, run, testing  # noqa: E402

NAME = "failureReport"


def launch(case):
    """X1 loaded by a pressure that jumps from 0 to 2e8 Pa (12 E) at
    t = 4 ms: the cells at X1 invert in the first step that reaches it"""
    path = os.path.join(case, "0", "U")
    with open(path) as f:
        text = f.read()
    text = text.replace('"(X1|Y1|Z1)"', '"(Y1|Z1)"')
    text = re.sub(r"boundaryField\s*\{",
                  "boundaryField\n{\n    X1 { type traction; pressure "
                  "table ((0 0) (0.004 0) (0.0041 2e8)); }", text, count=1)
    with open(path, "w") as f:
        f.write(text)


def times(case):
    return sorted((d for d in os.listdir(case)
                   if re.match(r"^[0-9.e+-]+$", d) and d != "0"), key=float)


def digest(folder):
    out = {}
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if os.path.isfile(path):
            with open(path, "rb") as f:
                out[name] = f.read()
    return out


def prepare(root, label, write_interval, max_steps=1000):
    case = cases.prepare("swingingCube", os.path.join(root, label), n=4,
                         control={"maxSteps": max_steps, "endTime": 0.01,
                                  "writeControl": "timeStep",
                                  "writeInterval": write_interval,
                                  "writePrecision": 17})
    launch(case)
    return case


def touch(case):
    log = os.path.join(case, "log.touchFoam")
    with open(log, "w") as f:
        status = subprocess.call(["touchFoam"], cwd=case, stdout=f,
                                 stderr=subprocess.STDOUT,
                                 timeout=testing.RUN_TIMEOUT)
    with open(log) as f:
        return status, f.read()


REPORT = re.compile(
    r"invalid cell (\d+).*?current centre\s+\(([^)]*)\).*?"
    r"reference centre \(([^)]*)\).*?J = det F\s+(\S+).*?"
    r"step\s+(\S+) -> (\S+) \(dt = (\S+)\).*?stage\s+(\d) of (\d) of RK3.*?"
    r"nearest boundary (\w+) \((\S+) m", re.S)


def body():
    root = testing.work_dir(NAME)
    failures, lines = [], []

    # Written at endTime only: the failure writes the step's start
    case = prepare(root, "writeAtEnd", 100000)
    status, text = touch(case)
    found = REPORT.search(text)
    if status != 1:
        failures.append("status %d, not 1" % status)
    if not found:
        raise AssertionError("no failure report in %s" % case)
    cell, current, reference, J, t0, t1, dt, stage, nStages, patch, dist = \
        found.groups()
    x0 = [float(v) for v in reference.split()]
    if float(J) > 0:
        failures.append("J = %s reported for an invalid cell" % J)
    if patch != "X1" or abs(float(dist) - (1 - x0[0])) > 1e-9:
        failures.append("nearest boundary %s at %s, not X1 at %g"
                        % (patch, dist, 1 - x0[0]))
    if abs(float(t1) - float(t0) - float(dt)) > 1e-9*float(dt):
        failures.append("step %s -> %s is not dt %s" % (t0, t1, dt))
    if not 1 <= int(stage) <= int(nStages) == 3:
        failures.append("stage %s of %s" % (stage, nStages))
    written = times(case)
    if not re.search(r"The last good state is written at time %s"
                     % re.escape(written[-1] if written else "?"), text):
        failures.append("the error does not name the written folder %s"
                        % written)
    steps = len(re.findall(r"^Time = ", text, re.M)) - 1
    lines.append("cell %s at (%s), reference (%s), J %s, step %s -> %s, "
                 "stage %s of %s, nearest %s; status %d; written %s after "
                 "%d good steps" % (cell, current, reference, J, t0, t1,
                                    stage, nStages, patch, status, written,
                                    steps))

    # The same steps stopped by maxSteps: the written state must agree
    good = prepare(root, "stopBefore", 100000, max_steps=steps)
    run.run(["touchFoam"], good, timeout=testing.RUN_TIMEOUT)
    if times(good) != written:
        failures.append("maxSteps %d wrote %s, the failing run %s"
                        % (steps, times(good), written))
    else:
        for field in ("lm", "F"):
            a = foamfile.read_field(os.path.join(case, written[-1], field)).internal(64)
            b = foamfile.read_field(os.path.join(good, written[-1], field)).internal(64)
            scale = max(abs(b).max(), 1e-300)
            diff = abs(a - b).max()/scale
            lines.append("%s at %s: max difference %.2g of max" %
                         (field, written[-1], diff))
            if diff > 1e-12:
                failures.append("%s of the last good state differs by %g"
                                % (field, diff))

    # Written every step: the folder of the step's start exists already
    every = prepare(root, "writeEveryStep", 1)
    status, text = touch(every)
    before = times(every)
    last = before[-1] if before else "0"
    if status != 1:
        failures.append("(written every step) status %d" % status)
    if "The last good state is the existing time folder %s" % last \
            not in text:
        failures.append("(written every step) the error does not name the "
                        "existing folder %s" % last)
    # Its files are the ones the write step wrote: rerun to that time and
    # compare
    again = prepare(root, "writeEveryStepAgain", 1,
                    max_steps=len(before))
    run.run(["touchFoam"], again, timeout=testing.RUN_TIMEOUT)
    if digest(os.path.join(every, last)).get("lm") != \
            digest(os.path.join(again, last)).get("lm"):
        failures.append("the existing folder %s was overwritten" % last)
    lines.append("written every step: status %d, last good state the "
                 "existing %s, unchanged" % (status, last))

    if failures:
        raise AssertionError("; ".join(failures) + " | " + "; ".join(lines))
    return "; ".join(lines)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
