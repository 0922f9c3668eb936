#!/usr/bin/python3
"""Pictures of the sphere impact: the pressure in the quarter ball(s) seen
from the side of the symmetric planes (the section through the contact)
at 5, 15 (near the Hertz peak) and 30 us, one camera for all, the wall
y = 0 drawn under the ball (variant wall).  The stress is concentrated
under the contact, a tenth of the radius across; the rest of the ball
carries the waves it sends.  Run in the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes pressure_<t>us.png.
"""

import os

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.contact import options
from touchfoam.figures import render_deformed

wall = options(os.path.dirname(os.path.abspath(__file__)))["variant"] \
    == "wall"
render_deformed(
    fields=["pressure"],
    titles={"pressure": "pressure [Pa]"},
    times=[5e-6, 1.5e-5, 3e-5],
    time_unit="us",
    view=(-1, 0.3, -1),             # the symmetric planes: the section
    wall=((0.005, 0, 0.005), (0, 1, 0), 0.006) if wall else None,
    size=(800, 800),
    percentiles=(1, 99.5),
)
