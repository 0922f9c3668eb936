#!/usr/bin/python3
"""Pictures of the twisting column: pressure and von Mises stress on the
column warped by pointD at 0.1 s (the seed's figure 3: the deformed shape
with its pressure, seen from above one corner), 0.2 s and 0.3 s.  Run in
the case by Allrun:

    xvfb-run -a pvbatch render.py

Writes pressure_<t>s.png and sigmaEq_<t>s.png.
"""

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam.figures import render_deformed

render_deformed(
    fields=["pressure", "sigmaEq"],
    titles={"pressure": "pressure [Pa]",
            "sigmaEq": "von Mises stress [Pa]"},
    times=[0.1, 0.2, 0.3],
    time_unit="s",
    view=(1, 0.6, 1.4),                         # above the corner (+X, +Z)
    size=(600, 1000),
)
