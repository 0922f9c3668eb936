#!/usr/bin/python3
"""The twisting column on tetrahedra twists like on hexahedra (issue 9).

    /usr/bin/python3 test/cases/tetrahedralTwist.py

4 x 24 x 4 hexahedra, and the same hexahedra cut into 6 tetrahedra each
(bin/python/touchfoam/gmsh.py, gmshToFoam) with `nodalAveraging deformation`
(the setting for tetrahedra), nu 0.45, default scheme otherwise, to t = 0.1 s: the total energy never grows (<= 1e-10 E0 per step) and the twist
at t = 0.1 s is within 10 % of the hexahedral one.
Work folders: test/runs/tetrahedralTwist/.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from schemeEnvelope import ENERGY_TOL, TWIST_TOL, column, testing  # noqa

NAME = "tetrahedralTwist"


def body():
    root = testing.work_dir(NAME)
    _, reference = column(root, "hex", end=0.1)
    gain, twist = column(root, "tet", end=0.1, mesh="tet",
                         extra={"nodalAveraging": "deformation"})
    change = (twist - reference) / reference
    summary = ("tetrahedra: dE/E0 %+.1e, twist %.1f deg against %.1f on "
               "hexahedra (%+.1f %%)" % (gain, twist, reference, 100 * change))
    if gain > ENERGY_TOL or abs(change) > TWIST_TOL:
        raise AssertionError(summary)
    return summary


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
