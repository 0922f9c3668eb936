#!/usr/bin/python3
"""Pictures of the ring: pressure on the deformed slab, seen along z, at
first contact, the deepest compression, the rebound and 0.18 s (the
seed's mesh study, figure 8).  Run in the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes pressure_<t>ms.png and contact_<t>ms.png (the wall patch seen from
below: its faces in contact red, the others blue).
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["pressure"],
    titles={"pressure": "pressure [Pa]"},
    times=[0.01, 0.02, 0.03, 0.18],
    time_unit="ms",
    view=(0, 0, 1),
    wall=((0, -0.044, 0), (0, 1, 0), 0.06),
    contact=("wall", (0, -1, 0.3), (0, 0, 1)),  # the strip, from below
)
