#!/usr/bin/python3
"""Pictures of the elastic impact: pressure along the bar (seen from the
side, the bar's length filling the picture) at 0.1 ... 0.5 ms, the front
travelling from the clamped end X = 0 at c_p.  Run in the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes pressure_<t>ms.png.
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["pressure"],
    titles={"pressure": "pressure [Pa]"},
    times=[1e-4, 2e-4, 3e-4, 4e-4, 5e-4],
    time_unit="ms",
    view=(0, 0, 1),                 # from the side
    size=(1200, 200),
    percentiles=(0, 100),           # the plateau and the rest both shown
    parallel=True,
)
