#!/usr/bin/python3
"""Initial fields of the swinging cube (BENCHMARKS.md section 1).

Writes 0/F = I + grad u(X, 0) at the cell centres from the closed-form
displacement u = U0 cos(w t) [sin(pi X/2) cos(pi Y/2) cos(pi Z/2), ...];
the initial momentum is zero.  Material constants come from
constant/mechanicalProperties.  Run after blockMesh and restore0Dir.
"""

import os


# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.cases import initialise_swinging_cube

if __name__ == "__main__":
    case = os.path.dirname(os.path.abspath(__file__))
    n = initialise_swinging_cube(case)
    print("initialise: F = I + grad u(X, 0) in %d cells" % n)
