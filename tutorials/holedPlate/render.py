#!/usr/bin/python3
"""Pictures of the plate with a hole: von Mises stress and pressure seen
along z at 2, 3, 5 and 10 ms, the wave pulled in from the right end
reaching and passing the hole.  Run in the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes sigmaEq_<t>ms.png and pressure_<t>ms.png.
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["sigmaEq", "pressure"],
    titles={"sigmaEq": "von Mises stress [Pa]", "pressure": "pressure [Pa]"},
    times=[0.002, 0.003, 0.005, 0.01],
    time_unit="ms",
    view=(0, 0, 1),                 # the plane of the plate
    size=(1000, 600),
    parallel=True,
)
