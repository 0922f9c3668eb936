#!/usr/bin/python3
"""Pictures of the Taylor bar at the seed's times (figure 5: 10, 30, 50,
80 us): pressure, von Mises stress and equivalent plastic strain on the
quarter warped by pointD, seen from the side of its cut planes.  Run in
the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes pressure_<t>us.png, sigmaEq_<t>us.png, epsilonP_<t>us.png and
contact_<t>us.png (the wall patch seen from below: its faces in contact
red, the others blue).
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["pressure", "sigmaEq", "epsilonP"],
    titles={"pressure": "pressure [Pa]",
            "sigmaEq": "von Mises stress [Pa]",
            "epsilonP": "equivalent plastic strain"},
    times=[1e-5, 3e-5, 5e-5, 8e-5],
    time_unit="us",
    view=(-1, 0.3, -1),                         # facing the cut planes
    wall=((0, 0, 0), (0, 1, 0), 0.008),
    size=(700, 1000),
    contact=("wall", (0, -1, 0), (0, 0, 1)),    # the foot, from below
)
