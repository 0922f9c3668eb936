#!/usr/bin/python3
"""Pictures of the sliding block: pressure on the block seen along z at
0.05, 0.15, 0.3 and 0.45 s (sliding, then stuck after 0.34 s), one camera
for all so the slide shows, the wall drawn under it.  Run in the case by
Allrun:

    xvfb-run -a pvbatch render.py

Writes pressure_<t>s.png.
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["pressure"],
    titles={"pressure": "pressure [Pa]"},
    times=[0.05, 0.15, 0.3, 0.45],
    time_unit="s",
    view=(0, 0, 1),                 # the plane of the slab
    size=(1000, 400),
    wall=((0.1, 0, 0.0), (0, 1, 0), 0.2),
    parallel=True,
)
