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
A step made unstable by its time step (the Taylor bar at -n 5, 1071 cells,
vonMisesPlastic on the rigid wall, FUpdate plain at CFL 1, above the
largest stable CFL 0.3 that touchFoam warns of; CFL 5 is refused as input,
0 < CFL <= 1, badInput case CFL; at -n 3 and 4 the bar runs through at
CFL 1 since the plain update takes the symmetric planes' fluxes with
their reference normals, at -n 5 a cell inverts):
  - exits with status 1, after a warning about the CFL number;
  - the report names J = det F of the F it prints (to the 12 printed
    digits), the step (dt = end - start), stage k of 2 of RK2, the nearest
    boundary and its distance equal to the nearest boundary face centre
    computed here from constant/polyMesh (to 1e-9 m), body 0 of 1, and the
    law's state epsilonP and CpInv of the cell: epsilonP > 0 and not below
    the cell's epsilonP in the last good state (a return mapping never
    lowers it);
  - the last good state, written at the step's start, holds epsilonP and
    CpInv besides lm, F, D and pointD.
Two bodies: the swinging cube of the first part with a second cube, apart
from it (x in [-2, -1], listed first in blockMeshDict, free faces 'other'):
the report names body 1 of 2 (regions numbered in the order of their
first cell) and the nearest boundary X1 as before.
Work folders: test/runs/failureReport/.
"""

import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, foamfile, run, testing  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

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
REPORT_RK2 = re.compile(REPORT.pattern.replace("of RK3", "of RK2"), re.S)


LAW_STATE = re.compile(r"law state\s+epsilonP (\S+) CpInv \(([^)]*)\)")
F_LINE = re.compile(r"^\s+F\s+\(([^)]*)\)", re.M)
BODY = re.compile(r"body\s+(\d+) of (\d+)")


def nearest_boundary(case, x0):
    """The patch and the distance of the boundary face centre nearest to
    x0 (empty and processor patches aside)"""
    mesh = PolyMesh(case)
    best = (None, float("inf"))
    for p in mesh.patches:
        if p["type"] in ("empty", "processor") or not p["nFaces"]:
            continue
        faces = mesh.face_centres[p["startFace"]:p["startFace"] + p["nFaces"]]
        d = np.sqrt(((faces - x0)**2).sum(axis=1)).min()
        if d < best[1]:
            best = (p["name"], d)
    return best


def plastic(root, failures, lines):
    """The Taylor bar made unstable by its CFL number: the report names the
    law's state"""
    case = cases.prepare("taylorImpact", os.path.join(root, "plasticCFL"),
                         n=5, touch={"CFL": 1, "FUpdate": "plain"},
                         control={"writePrecision": 17})
    status, text = touch(case)
    found = REPORT_RK2.search(text)
    if not found:
        raise AssertionError("no failure report in %s" % case)
    cell, current, reference, J, t0, t1, dt, stage, nStages, patch, dist = \
        found.groups()
    celli = int(cell)
    x0 = np.array([float(v) for v in reference.split()])
    if status != 1:
        failures.append("(plastic) status %d, not 1" % status)
    if not re.search(r"'CFL' = 1 .* is above 0\.(3|29999)", text):
        failures.append("(plastic) no warning about CFL 1")
    F = np.array([float(v) for v in F_LINE.search(text).group(1).split()])
    detF = np.linalg.det(F.reshape(3, 3))
    if float(J) > 0 or abs(detF - float(J)) > 1e-9*max(1, abs(detF)):
        failures.append("(plastic) J %s, det of the printed F %.12g"
                        % (J, detF))
    if abs(float(t1) - float(t0) - float(dt)) > 1e-9*float(dt):
        failures.append("(plastic) step %s -> %s is not dt %s" % (t0, t1, dt))
    if not 1 <= int(stage) <= int(nStages) == 2:
        failures.append("(plastic) stage %s of %s" % (stage, nStages))
    name, distance = nearest_boundary(case, x0)
    if patch != name or abs(float(dist) - distance) > 1e-9:
        failures.append("(plastic) nearest boundary %s at %s, the mesh's %s "
                        "at %.12g" % (patch, dist, name, distance))
    body_found = BODY.search(text)
    if not body_found or body_found.groups() != ("0", "1"):
        failures.append("(plastic) body %s, not 0 of 1"
                        % (body_found.groups() if body_found else None))
    state = LAW_STATE.search(text)
    written = times(case)
    if not state:
        failures.append("(plastic) no law state epsilonP, CpInv in the report")
    elif not written:
        failures.append("(plastic) no last good state written")
    else:
        last = os.path.join(case, written[-1])
        missing = [f for f in ("lm", "F", "D", "pointD", "epsilonP", "CpInv")
                   if not os.path.isfile(os.path.join(last, f))]
        if missing:
            failures.append("(plastic) %s lacks %s" % (written[-1], missing))
        else:
            eps0 = foamfile.read_field(os.path.join(last, "epsilonP")) \
                .internal(PolyMesh(case).n_cells)[celli]
            eps = float(state.group(1))
            if not eps >= eps0 or not eps > 0:
                failures.append("(plastic) epsilonP %g reported, %g at the "
                                "step's start" % (eps, eps0))
            if abs(float(written[-1]) - float(t0)) > 1e-5*float(t0):
                failures.append("(plastic) last good state at %s, the step "
                                "started at %s" % (written[-1], t0))
            lines.append("plastic: cell %d J %s, stage %s of 2, dt %s, "
                         "nearest %s, epsilonP %g (%g at %s, written)"
                         % (celli, J, stage, dt, patch, eps, eps0,
                            written[-1]))


def two_bodies(root, failures, lines):
    """A second cube apart from the failing one: the report names the body"""
    case = cases.prepare("swingingCube", os.path.join(root, "twoBodies"), n=4,
                         control={"endTime": 0.01, "writePrecision": 17,
                                  "writeControl": "timeStep",
                                  "writeInterval": 100000},
                         initialise=False)
    mesh_dict = os.path.join(case, "system", "blockMeshDict")
    with open(mesh_dict) as f:
        text = f.read()
    text = text.replace("vertices\n(", "vertices\n(\n" + "\n".join(
        "    (%d %d %d)" % (x - 2, y, z) for x, y, z in
        [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
         (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]), 1)
    text = shift_blocks(text)
    with open(mesh_dict, "w") as f:
        f.write(text)
    run.run(["blockMesh"], case)
    run.restore0(case)
    cases.set_initial_state(case)
    launch(case)
    path = os.path.join(case, "0", "U")
    with open(path) as f:
        text = f.read()
    text = re.sub(r"boundaryField\s*\{", "boundaryField\n{\n    other "
                  "{ type traction; }", text, count=1)
    with open(path, "w") as f:
        f.write(text)
    status, text = touch(case)
    found = REPORT.search(text)
    body_found = BODY.search(text)
    if status != 1 or not found:
        failures.append("(two bodies) status %d, report %s"
                        % (status, bool(found)))
        return
    if found.group(10) != "X1":
        failures.append("(two bodies) nearest boundary %s" % found.group(10))
    if not body_found or body_found.groups() != ("1", "2"):
        failures.append("(two bodies) body %s, not 1 of 2"
                        % (body_found.groups() if body_found else None))
    else:
        lines.append("two bodies: cell %s at (%s), body 1 of 2, nearest X1"
                     % (found.group(1), found.group(3)))


def shift_blocks(text):
    """blockMeshDict of the swinging cube (now vertices 8 .. 15) with the
    other cube (vertices 0 .. 7, x in [-2, -1]) listed first, its faces the
    patch 'other'"""
    head, rest = text.split("\nblocks", 1)
    tail = rest.split("mergePatchPairs", 1)[1]
    faces = {"X0": "(8 12 15 11)", "X1": "(9 10 14 13)", "Y0": "(8 9 13 12)",
             "Y1": "(11 15 14 10)", "Z0": "(8 11 10 9)", "Z1": "(12 13 14 15)"}
    return head + """
blocks
(
    hex (0 1 2 3 4 5 6 7) ($N $N $N) simpleGrading (1 1 1)
    hex (8 9 10 11 12 13 14 15) ($N $N $N) simpleGrading (1 1 1)
);

edges
(
);

boundary
(
    other { type patch; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)
        (0 3 2 1) (4 5 6 7)); }
""" + "".join("    %s { type patch; faces (%s); }\n" % kv
              for kv in faces.items()) + ");\n\nmergePatchPairs" + tail


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

    plastic(root, failures, lines)
    two_bodies(root, failures, lines)

    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
