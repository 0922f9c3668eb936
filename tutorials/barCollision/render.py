#!/usr/bin/python3
"""Pictures of the bar collision: pressure along the two bars, seen from
the side (their length filling the picture), at 0.5 and 1.5 ms (in
contact: the compressed zone spreading from the contact at x = 0, then
shrinking as the unloading fronts come back from the free ends) and 2.5 ms
(after the release at 2L/c = 2 ms: equal bars at rest in stress, one
colour).  Run in the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes pressure_<t>ms.png.
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["pressure"],
    titles={"pressure": "pressure [Pa]"},
    times=[5e-4, 1.5e-3, 2.5e-3],
    time_unit="ms",
    view=(0, 0, 1),                 # from the side
    size=(1400, 200),
    percentiles=(0, 100),           # the plateau and the rest both shown
    parallel=True,
)
