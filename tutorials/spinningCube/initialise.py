#!/usr/bin/python3
"""Initial fields of the spinning cube (free flight, momentum tests).

Writes 0/lm = rho0 (v_t + omega x X) at the cell centres; F = I comes from
0.orig.  The cube starts unstressed, so the spin makes it breathe and
stretch (centrifugal strain rho0 |omega|^2 R^2 / E of a few per cent) while
the total linear and angular momentum must stay constant.
"""

import os

TRANSLATION = (1.0, 0.5, -0.25)   # v_t [m/s]
OMEGA = (4.0, 6.0, 8.0)           # [rad/s]: corner speed ~9 m/s, U_p 37 m/s


# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.cases import initialise_rigid_motion

if __name__ == "__main__":
    case = os.path.dirname(os.path.abspath(__file__))
    n = initialise_rigid_motion(case, TRANSLATION, OMEGA)
    print("initialise: lm = rho0 (v_t + omega x X) in %d cells" % n)
