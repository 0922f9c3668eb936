#!/usr/bin/python3
"""Pictures of the projectile impact: the equivalent stress and the plastic
strain of the plate (and the ball) seen from the side of the symmetric
planes (the section through the impact point) at 5, 15 and 60 us, one
camera for all.  The plastic zone grows under the ball while it is
pressed in and stays as the dent; the elastic waves run through the plate
and the ball.  Run in the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes sigmaEq_<t>us.png and epsilonP.plate_<t>us.png (each law writes
its own plastic strain, zero outside its cells).
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["sigmaEq", "epsilonP.plate"],
    titles={"sigmaEq": "equivalent stress [Pa]",
            "epsilonP.plate": "plastic strain of the plate"},
    times=[5e-6, 1.5e-5, 6e-5],
    time_unit="us",
    view=(-1, 0.3, -1),             # the symmetric planes: the section
    size=(800, 800),
    percentiles=(1, 99.5),
)
