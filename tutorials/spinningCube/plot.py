#!/usr/bin/python3
"""Histories of the spinning cube: the drift of the total linear and
angular momentum from their initial values (relative; the invariants of
free flight, exact to round-off), and the energy (per step, from the
solidMonitor).  Run in the case by Allrun; writes histories.png.
"""

import os

import numpy as np

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import figures

case = os.path.dirname(os.path.abspath(__file__))
data = figures.monitor(case)
t = data["Time"]
p = np.column_stack([data[k] for k in ("px", "py", "pz")])
L = np.column_stack([data[k] for k in ("Lx", "Ly", "Lz")])
dp = np.linalg.norm(p - p[0], axis=1) / np.linalg.norm(p[0])
dL = np.linalg.norm(L - L[0], axis=1) / np.linalg.norm(L[0])
print("largest drift: linear momentum %.2e, angular momentum %.2e "
      "(relative to the first step's)" % (dp.max(), dL.max()))

figures.plot_panels(
    [
        ("|p - p(0)| / |p(0)|", [(t, dp, "linear momentum")]),
        ("|L - L(0)| / |L(0)|", [(t, dL, "angular momentum")]),
        figures.energy_panel(data),
    ],
    "histories.png", "s", title="Spinning cube in free flight", case=case)
