#!/usr/bin/python3
"""Pictures of the swinging cube on tetrahedra: von Mises stress on the cube warped by
pointD (200 times; pointD counts from the strained start, so the shape is
u(t) - u(0)) at 1, 2 and 3 ms, seen from above the corner (1, 1, 1).  Run
in the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes sigmaEq_<t>ms.png.
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["sigmaEq"],
    titles={"sigmaEq": "von Mises stress [Pa]"},
    times=[0.001, 0.002, 0.003],
    time_unit="ms",
    view=(1, 0.8, 1.2),             # above the corner (1, 1, 1)
    size=(800, 800),
    scale=200.0,
)
