#!/usr/bin/python3
"""Initial momentum of the bar rebound: p = rho0 v0, v0 = (0, -150, 0) m/s.

Written at every cell centre; rho0 comes from constant/mechanicalProperties;
F = I comes from 0.orig.  Run after blockMesh, transformPoints and restore0Dir.
"""

import os

V0 = (0.0, -150.0, 0.0)     # impact velocity [m/s] (BENCHMARKS.md 4)


# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.cases import initialise_rigid_motion

if __name__ == "__main__":
    case = os.path.dirname(os.path.abspath(__file__))
    n = initialise_rigid_motion(case, V0, (0.0, 0.0, 0.0))
    print("initialise: p = rho0 v0, v0 = %s m/s, in %d cells" % (V0, n))
