#!/usr/bin/python3
"""Pictures of the bar rebound: pressure on the deformed quarter, seen from
the side of its cut planes, at the seed's times (figure 6, read as 30, 60,
120, 180, 270 us) and at the end, in flight.  Run in the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes pressure_<t>us.png and contact_<t>us.png (the wall patch seen from
below: its faces in contact red, the others blue).
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["pressure"],
    titles={"pressure": "pressure [Pa]"},
    times=[3e-5, 6e-5, 1.2e-4, 1.8e-4, 2.7e-4, 4e-4],
    time_unit="us",
    view=(-1, 0.3, -1),                         # facing the cut planes
    wall=((0, 0, 0), (0, 1, 0), 0.008),
    size=(700, 1000),
    contact=("wall", (0, -1, 0), (0, 0, 1)),    # the end, from below
)
