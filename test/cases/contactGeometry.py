#!/usr/bin/python3
"""A rigid wall holds the points it touches on the wall (rigidWall).

    /usr/bin/python3 test/cases/contactGeometry.py

The Taylor bar at -n 4 (the tutorial, 465 cells), 12 us written every
microsecond.  In the first microseconds the release waves from the bar's
side meet on its axis and lift the middle of the impact face off the wall
(up to 0.15 mm at 3 us), then it comes back.  A face's contact is decided
by its gap, and once in contact each of its points keeps the wall's normal
velocity from the stage it reaches the wall ('hold touchingPoints').

Asserted at every written time, for the points of the wall faces in
contact: their distance from the wall plane is at most 3 % of the wall
layer's reference height h (0.79 mm).  With the gap taken from the cell's
motion (X + u + F r) instead of the face's own points, faces touched while
their points hovered up to 80 um (0.10 h) above the wall and were held
there for the rest of the run; with the points' mean, 12 um (0.016 h);
once the wall no longer pulled, the face came back while its points were
up to 0.046 h above the wall, and holding all of a face's points from the
stage the face touched ('hold faces') kept them there: 0.0464 h above,
0.0249 h into it, against 0.0043 h and 0.0175 h with 'hold touchingPoints'
(2026-12-07, validation/sphereImpact/FINDINGS.md 10).
Also asserted: some face leaves the wall and comes back (the case tests
what it is meant to), and no point of a face in contact is more than 3 % of
h into the wall.

Work folders: test/runs/contactGeometry/.
"""

import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, run, testing  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.postprocess import PolyMesh  # noqa: E402

NAME = "contactGeometry"
WALL = "wall"
TOLERANCE = 0.03        # of the wall layer's reference height


def contact_state(folder, n_faces):
    """The 'contact' entry of lm's wall patch: one value per face."""
    text = open(os.path.join(folder, "lm")).read()
    patch = text[text.index("rigidWall"):]
    m = re.search(r"\bcontact\s+uniform\s+([^;\s]+)\s*;", patch)
    if m and m.start() < patch.find("}"):
        return np.full(n_faces, float(m.group(1)))
    m = re.search(r"\bcontact\s+nonuniform\s+List<\w+>\s*(\d+)\s*\(([^)]*)\)",
                  patch)
    if not m:
        raise AssertionError("%s/lm: no 'contact' entry on patch %s"
                             % (folder, WALL))
    return np.array(m.group(2).split(), float)


def body():
    case = os.path.join(testing.work_dir(NAME), "taylorImpact")
    cases.prepare("taylorImpact", case, n=4,
                  control={"endTime": 1.2e-5, "writeInterval": 1e-6})
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)

    mesh = PolyMesh(case)
    wall_faces = np.asarray(mesh.patch_faces(WALL))
    X = mesh.points
    # The wall is the plane Y = 0 with the outward normal -Y (0/U)
    h = 2 * float(np.mean(mesh.cell_centres[mesh.owner[wall_faces], 1]))
    times = sorted((d for d in os.listdir(case)
                    if re.fullmatch(r"[0-9.e+-]+", d) and float(d) > 0),
                   key=float)
    if len(times) < 10:
        raise AssertionError("%d written times, expected 12" % len(times))

    worst_above = worst_below = 0.0
    fewest = len(wall_faces)
    counts = []
    for t in times:
        folder = os.path.join(case, t)
        contact = contact_state(folder, len(wall_faces)) > 0.5
        u = read_field(os.path.join(folder, "pointD")).internal(len(X))
        y = X[:, 1] + np.asarray(u)[:, 1]
        points = sorted({p for k, facei in enumerate(wall_faces)
                         if contact[k] for p in mesh.faces[facei]})
        counts.append(int(contact.sum()))
        fewest = min(fewest, counts[-1])
        if points:
            worst_above = max(worst_above, float(y[points].max()) / h)
            worst_below = max(worst_below, float(-y[points].min()) / h)

    lines = ["wall faces in contact at 1..12 us: %s of %d"
             % (" ".join(str(c) for c in counts), len(wall_faces)),
             "points of faces in contact: at most %.4f h above the wall, "
             "%.4f h into it (h = %.3f mm, tolerance %.2f h)"
             % (worst_above, worst_below, 1e3 * h, TOLERANCE)]
    failures = []
    if fewest == len(wall_faces) or counts[-1] == fewest:
        failures.append("no face left the wall and came back (%s): the case "
                        "does not test re-contact" % counts)
    if worst_above > TOLERANCE:
        failures.append("points of faces in contact up to %.4f h above the "
                        "wall (> %.2f h)" % (worst_above, TOLERANCE))
    if worst_below > TOLERANCE:
        failures.append("points of faces in contact up to %.4f h into the "
                        "wall (> %.2f h)" % (worst_below, TOLERANCE))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
