#!/usr/bin/python3
"""Initial momentum of the elastic impact: p = -rho0 v0 e_x, v0 = 0.1 m/s.

rho0 comes from constant/mechanicalProperties (so an override there keeps
the impact speed); F stays the identity.  Run after blockMesh and
restore0Dir.
"""

import os


# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.impact import V0, initialise_elastic_impact

if __name__ == "__main__":
    case = os.path.dirname(os.path.abspath(__file__))
    n = initialise_elastic_impact(case)
    print("initialise: p = -rho0 v0 e_x, v0 = %g m/s, in %d cells" % (V0, n))
