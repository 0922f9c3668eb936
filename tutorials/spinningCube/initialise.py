#!/usr/bin/python3
"""Initial fields of the spinning cube (free flight, momentum tests).

Writes 0/lm = rho0 (v_t + omega x X) at the cell centres; F = I comes from
0.orig.  The cube starts unstressed, so the spin makes it breathe and
stretch (centrifugal strain rho0 |omega|^2 R^2 / E of a few per cent) while
the total linear and angular momentum must stay constant.
"""

import os
import sys

TRANSLATION = (1.0, 0.5, -0.25)   # v_t [m/s]
OMEGA = (4.0, 6.0, 8.0)           # [rad/s]: corner speed ~9 m/s, U_p 37 m/s


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
from touchfoam.cases import initialise_rigid_motion  # noqa: E402

if __name__ == "__main__":
    case = os.path.dirname(os.path.abspath(__file__))
    n = initialise_rigid_motion(case, TRANSLATION, OMEGA)
    print("initialise: lm = rho0 (v_t + omega x X) in %d cells" % n)
