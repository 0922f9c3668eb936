#!/usr/bin/python3
"""Pictures of the swinging cube (figures.swinging_cube_pictures): von Mises
stress at 1, 2 and 3 ms on the cube warped by pointD magnified 200 times.
Run in the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes sigmaEq_<t>ms.png.
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import swinging_cube_pictures

swinging_cube_pictures()
