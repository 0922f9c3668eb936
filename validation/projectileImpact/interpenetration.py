#!/usr/bin/python3
"""How deep the ball's surface points lie below the plate's top surface at
each written time of a finished tutorials/projectileImpact case: the
geometric interpenetration, beside contact.dat's maxPenetration (the
largest gap of the centres of a pair in contact along its normal, which
misses points between the centres).

    /usr/bin/python3 validation/projectileImpact/interpenetration.py CASE

The plate's top is the surface drawn by its deformed points (x +
pointD), each face fanned into triangles about the mean of its points
(touchfoam.contact.depth_below_surface); a ball point's depth is that
surface's height over the point less its own y.  Needs numpy.
"""

import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam.contact import depth_below_surface, read_contact  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.run import time_dirs  # noqa: E402


def main(case):
    mesh = PolyMesh(case)
    ball = mesh.patch_points("ballSurface")
    top_faces = [mesh.faces[f] for f in mesh.patch_faces("plateTop")]
    area = np.linalg.norm(mesh.face_areas[list(mesh.patch_faces("plateTop"))],
                          axis=1)
    h = np.sqrt(area.min())
    rows = read_contact(case)
    print("# smallest plate face %.4g mm" % (1e3 * h))
    print("# time [us]  deepest ball point below the plate [mm]  (/face)"
          "  at r [mm]  contact.dat maxPenetration [mm]")
    for t, name in sorted(time_dirs(case).items()):
        if t <= 0:
            continue
        D = np.asarray(read_field(os.path.join(case, name, "pointD"))
                       .values).reshape(-1, 3)
        x = mesh.points + D
        depth = depth_below_surface(x, ball, top_faces)
        i = int(np.argmax(depth))
        k = int(np.argmin(np.abs(rows["Time"] - t)))
        print("%8.2f  %10.4f  (%.3f)  %8.3f  %10.4f"
              % (1e6 * t, 1e3 * depth[i], depth[i] / h,
                 1e3 * np.hypot(x[ball][i, 0], x[ball][i, 2]),
                 1e3 * rows["maxPenetration"][k]))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
