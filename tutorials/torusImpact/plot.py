#!/usr/bin/python3
"""Histories of the torus: linear and angular momentum (about the origin,
the torus' initial centre), energy, the faces in contact with the wall and
its force (per step, from the solidMonitor), and the smallest and largest
J = det F of the cells at the written times.  Run in the case by Allrun;
writes histories.png and prints the smallest J.
"""

import os

import numpy as np

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import figures

case = os.path.dirname(os.path.abspath(__file__))
data = figures.monitor(case)
t, p, L = data["Time"], data["p"], data["L"]

times, J_min, J_max = figures.cell_extremes(case, "J")
if len(times):
    i = int(np.argmin(J_min))
    print("smallest J %.4g at t = %g s (of the written times)"
          % (J_min[i], times[i]))

figures.plot_panels(
    [
        ("linear momentum [kg m/s]",
         [(t, p[:, i], "p" + "xyz"[i]) for i in range(3)]),
        ("angular momentum [kg m^2/s]",
         [(t, L[:, i], "L" + "xyz"[i]) for i in range(3)]),
        figures.energy_panel(data),
    ] + figures.contact_panels(data) + [
        ("J = det F", [(times, J_min, "min"), (times, J_max, "max")]),
    ],
    "histories.png", "ms", title="Torus impact", case=case)
