#!/usr/bin/python3
"""Histories of the swinging cube on tetrahedra: the kinetic energy per step against
the closed form's, and the L2 errors of velocity and stress at the written
times (figures.swinging_cube_plot).  Run in the case by Allrun; writes
histories.png.
"""

import os

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import figures

figures.swinging_cube_plot(os.path.dirname(os.path.abspath(__file__)),
                           "Swinging cube on tetrahedra")
