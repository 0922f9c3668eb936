#!/usr/bin/python3
"""Initial fields of the swinging cube (BENCHMARKS.md section 1).

Writes 0/F = I + grad u(X, 0) at the cell centres from the closed-form
displacement u = U0 cos(w t) [sin(pi X/2) cos(pi Y/2) cos(pi Z/2), ...];
the initial momentum is zero.  Material constants come from
constant/mechanicalProperties.  Run after blockMesh and restore0Dir.
"""

import os
import sys


def _package_dir():
    """bin/python of the repository holding this script (or of
    $TOUCH_PROJECT_DIR), so that copies of the case work too."""
    d = os.path.dirname(os.path.abspath(__file__))
    while d != os.path.dirname(d):
        if os.path.isdir(os.path.join(d, "bin", "python", "touchfoam")):
            return os.path.join(d, "bin", "python")
        d = os.path.dirname(d)
    return os.path.join(os.environ.get("TOUCH_PROJECT_DIR", "."), "bin",
                        "python")


sys.path.insert(0, _package_dir())
from touchfoam.cases import initialise_swinging_cube  # noqa: E402

if __name__ == "__main__":
    case = os.path.dirname(os.path.abspath(__file__))
    n = initialise_swinging_cube(case)
    print("initialise: F = I + grad u(X, 0) in %d cells" % n)
