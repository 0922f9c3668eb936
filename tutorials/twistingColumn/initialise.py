#!/usr/bin/python3
"""Initial fields of the twisting column (BENCHMARKS.md section 2).

Writes 0/lm = rho0 v0 at the cell centres, v0 = omega x X with
omega = (0, Omega sin(pi Y / (2 L)), 0), Omega = 105 rad/s, L = 6 m;
F = I comes from 0.orig.  Run after blockMesh and restore0Dir.
"""

import os
import sys

OMEGA = 105.0   # angular velocity amplitude [rad/s]
LENGTH = 6.0    # column length [m]


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
from touchfoam.cases import initialise_twisting_column  # noqa: E402

if __name__ == "__main__":
    case = os.path.dirname(os.path.abspath(__file__))
    n = initialise_twisting_column(case, Omega=OMEGA, L=LENGTH)
    print("initialise: lm = rho0 (omega x X) in %d cells" % n)
