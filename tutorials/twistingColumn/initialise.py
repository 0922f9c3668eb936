#!/usr/bin/python3
"""Initial fields of the twisting column (BENCHMARKS.md section 2).

Writes 0/lm = rho0 v0 at the cell centres, v0 = omega x X with
omega = (0, Omega sin(pi Y / (2 L)), 0), Omega = 105 rad/s, L = 6 m;
F = I comes from 0.orig.  Run after blockMesh and restore0Dir.
"""

import os

OMEGA = 105.0   # angular velocity amplitude [rad/s]
LENGTH = 6.0    # column length [m]


# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.cases import initialise_twisting_column

if __name__ == "__main__":
    case = os.path.dirname(os.path.abspath(__file__))
    n = initialise_twisting_column(case, Omega=OMEGA, L=LENGTH)
    print("initialise: lm = rho0 (omega x X) in %d cells" % n)
