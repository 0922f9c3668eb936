#!/usr/bin/python3
"""A curved body does not sink into the rigid wall (issue 28, acceptance
7).

    /usr/bin/python3 test/cases/wallPenetration.py

tutorials/torusImpact at -n 8 (672 cells), the whole run (38 ms, contact
from 1.4 to about 32 ms), written every 0.2 ms.  The torus touches the wall
at faces inclined to it.  Asserted:
- penetration: at every written time, no point of the wall patch is more
  than 0.05 h below the wall plane y = -0.044, h the square root of the
  wall faces' mean reference area (3.9 mm);
- the impulse of the monitor's wall force over the run is the change of
  p_y (1e-10): the force reported is the one applied.
Reported, not asserted: how far points of faces in contact stay above the
wall (at the written times), and the most tensile step of the wall force
(wallForceSign asserts its sign).

A face entered contact only when the mean of its points reached the wall,
so that the lower points of an inclined face sank by up to half the
face's height difference first and were held there: 0.26 h at -n 8, 0.13
h at -n 16 (validation/taylorImpact/FINDINGS.md).  The tutorial's wall
now has 'touching lowestFreePoint' (validation/ringImpact/FINDINGS.md).

Work folders: test/runs/wallPenetration/.
"""

import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, monitor, run, testing  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

NAME = "wallPenetration"
N = 8
WALL = "wall"
WALL_Y = -0.044
PENETRATION = 0.05      # of h
IMPULSE = 1e-10


def contact_state(folder, n_faces):
    """The 'contact' entry of lm's wall patch: one value per face."""
    text = open(os.path.join(folder, "lm")).read()
    patch = text[text.index("rigidWall"):]
    m = re.search(r"\bcontact\s+uniform\s+([^;\s]+)\s*;", patch)
    if m and m.start() < patch.find("}"):
        return np.full(n_faces, float(m.group(1)))
    m = re.search(r"\bcontact\s+nonuniform\s+List<\w+>\s*(\d+)\s*"
                  r"\(([^)]*)\)", patch)
    if not m:
        raise AssertionError("%s/lm: no 'contact' entry" % folder)
    return np.array(m.group(2).split(), float)


def body():
    case = cases.prepare("torusImpact",
                         os.path.join(testing.work_dir(NAME), "torus"), n=N,
                         control={"writeInterval": 2e-4})
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)

    mesh = PolyMesh(case)
    faces = np.asarray(mesh.patch_faces(WALL))
    points = np.asarray(mesh.patch_points(WALL))
    X = mesh.points
    h = float(np.sqrt(np.mean(np.linalg.norm(
        np.asarray(mesh.face_areas)[faces], axis=1))))
    times = sorted((d for d in os.listdir(case)
                    if re.fullmatch(r"[0-9.e+-]+", d) and float(d) > 0),
                   key=float)
    if len(times) < 150:
        raise AssertionError("%d written times, expected 190" % len(times))

    deepest, at, hover = 0.0, None, 0.0
    for t in times:
        u = np.asarray(read_field(os.path.join(case, t, "pointD"))
                       .internal(len(X)))
        y = X[:, 1] + u[:, 1]
        depth = float((WALL_Y - y[points]).max()) / h
        if depth > deepest:
            deepest, at = depth, t
        contact = contact_state(os.path.join(case, t), len(faces)) > 0.5
        held = [p for k, facei in enumerate(faces) if contact[k]
                for p in mesh.faces[facei]]
        if held:
            hover = max(hover, float((y[held] - WALL_Y).max()) / h)

    m = monitor.read_monitor(case)
    force = [k for k in m if k.startswith("wallForce")][0]
    contact = [k for k in m if k.startswith("contactFaces")][0]
    f = m[force]
    tensile = -min(0.0, float(f.min())) / float(f.max())
    worst_t = m["Time"][int(np.argmin(f))]
    dt = np.diff(np.concatenate([[0.0], m["Time"]]))
    impulse = float(np.sum(f * dt))
    dpy = float(m["py"][-1] - m["py"][0])
    mismatch = abs(impulse - dpy) / abs(dpy)
    steps = int(np.count_nonzero(m[contact] > 0))
    pulling = int(np.count_nonzero(f < 0))

    lines = ["-n %d (h = %.2f mm): deepest wall point %.4f h (at %s s); "
             "points of faces in contact up to %.3f h above the wall; "
             "wall force most tensile %.2e of the largest compressive (at "
             "%.4g ms), %d of %d steps in contact pulling; impulse / "
             "change of p_y - 1 = %.1e"
             % (N, 1e3 * h, deepest, at, hover, tensile, 1e3 * worst_t,
                pulling, steps, mismatch)]
    failures = []
    if steps == 0:
        failures.append("the torus never touched the wall")
    if deepest > PENETRATION:
        failures.append("a wall point %.4f h below the wall (> %.2f h)"
                        % (deepest, PENETRATION))
    if mismatch > IMPULSE:
        failures.append("impulse of the wall force off the change of p_y by "
                        "%.1e" % mismatch)
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
