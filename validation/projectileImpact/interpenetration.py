#!/usr/bin/python3
"""How deep the ball's surface points lie below the plate's top surface at
each written time of a finished tutorials/projectileImpact case: the
geometric interpenetration, beside contact.dat's maxPenetration (the
largest gap of the centres of a pair in contact along its normal, which
misses points between the centres).

    /usr/bin/python3 validation/projectileImpact/interpenetration.py CASE

The plate's top is the piecewise-linear surface through its deformed
points (x + pointD), interpolated over (x, z) (scipy's
LinearNDInterpolator on their Delaunay triangulation: within the sagitta
of a face of a quad's bilinear surface); a ball point's depth is that
height less its own y.  Needs numpy and scipy.
"""

import os
import sys

import numpy as np
from scipy.interpolate import LinearNDInterpolator

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam.contact import read_contact  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.run import time_dirs  # noqa: E402


def main(case):
    mesh = PolyMesh(case)
    ball = mesh.patch_points("ballSurface")
    top = mesh.patch_points("plateTop")
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
        surface = LinearNDInterpolator(x[top][:, [0, 2]], x[top][:, 1])
        depth = surface(x[ball][:, [0, 2]]) - x[ball][:, 1]
        depth = np.where(np.isnan(depth), -np.inf, depth)
        i = int(np.argmax(depth))
        k = int(np.argmin(np.abs(rows["Time"] - t)))
        print("%8.2f  %10.4f  (%.3f)  %8.3f  %10.4f"
              % (1e6 * t, 1e3 * depth[i], depth[i] / h,
                 1e3 * np.hypot(x[ball][i, 0], x[ball][i, 2]),
                 1e3 * rows["maxPenetration"][k]))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
