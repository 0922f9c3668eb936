#!/usr/bin/python3
"""Pictures of the torus: pressure on the deformed torus at the seed's
times (figure 10: 2, 4, 8, 17, 28, 38 ms).  Run in the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes pressure_<t>ms.png and contact_<t>ms.png (the wall patch seen from
below: its faces in contact red, the others blue).
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["pressure"],
    titles={"pressure": "pressure [Pa]"},
    times=[0.002, 0.004, 0.008, 0.017, 0.028, 0.038],
    time_unit="ms",
    view=(0.6, 0.35, 1),
    wall=((0, -0.044, 0), (0, 1, 0), 0.06),
    contact=("wall", (0, -1, 0), (0, 0, 1)),    # the footprint, from below
)
