#!/usr/bin/python3
"""Histories of the plate with a hole: energy (kinetic, stored, total
against the work the pulled end has done) and the momentum p_x (per step,
from the solidMonitor).  Run in the case by Allrun; writes histories.png.
"""

import os

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import figures

case = os.path.dirname(os.path.abspath(__file__))
data = figures.monitor(case)
t = data["Time"]

figures.plot_panels(
    [
        figures.energy_panel(data),
        ("momentum p_x [kg m/s]", [(t, data["px"], "")]),
    ],
    "histories.png", "ms", title="Plate with a hole (plane strain)",
    case=case)
