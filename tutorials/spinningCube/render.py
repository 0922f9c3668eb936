#!/usr/bin/python3
"""Pictures of the spinning cube: von Mises stress and pressure (the
centrifugal stretch) on the cube in flight at 0.5, 1.0 and 1.4 s, seen from
above one corner.  Run in the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes sigmaEq_<t>s.png and pressure_<t>s.png.
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["sigmaEq", "pressure"],
    titles={"sigmaEq": "von Mises stress [Pa]", "pressure": "pressure [Pa]"},
    times=[0.5, 1.0, 1.4],
    time_unit="s",
    view=(1, 0.8, 1.2),             # above one corner
    size=(800, 800),
)
