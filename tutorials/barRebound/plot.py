#!/usr/bin/python3
"""Histories of the bar rebound: vertical displacement of the points on the
axis at the top and at the bottom (seed figure 7, at the written times),
energy, momentum, and the faces in contact with the wall and its force
(per step, from the solidMonitor).  Run in the case by Allrun; writes
histories.png and prints the times of first contact and of separation.
"""

import os

import numpy as np

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import figures

GAP = 0.004         # initial gap to the wall [m]
LENGTH = 0.0324     # bar length [m]
V0 = 150.0          # impact speed [m/s]

case = os.path.dirname(os.path.abspath(__file__))
data = figures.monitor(case)
t = data["Time"]

times, u = figures.point_history(case, [(0, GAP + LENGTH, 0), (0, GAP, 0)])

faces = data.get("contactFaces(wall)")
if faces is not None and (faces > 0).any():
    touching = np.nonzero(faces > 0)[0]
    print("first contact at %.4g s (gap/v0 = %.4g s); last step in contact "
          "ends at %.4g s%s" % (
              t[touching[0]], GAP / V0, t[touching[-1]],
              "" if touching[-1] < len(t) - 1 else " (still in contact)"))

figures.plot_panels(
    [
        ("y displacement [m]",
         [(times, u[:, 0, 1], "top (0, L, 0)"),
          (times, u[:, 1, 1], "bottom (0, 0, 0)")]),
        figures.energy_panel(data),
        ("momentum p_y [kg m/s]", [(t, data["py"], "")]),
    ] + figures.contact_panels(data),
    "histories.png", "us", title="Bar rebound (quarter bar)", case=case)
