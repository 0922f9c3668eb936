#!/usr/bin/python3
"""Histories of the Taylor bar: length and foot radius (at the written
times, with the literature ranges of doc/benchmarks.md, Taylor impact at 80 us), energy,
momentum, and the faces in contact with the wall and its force (per step,
from the solidMonitor).  Run in the case by Allrun; writes histories.png.
"""

import os

import numpy as np

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import figures

LENGTH = (21.26e-3, 21.49e-3)       # final length [m], literature range
FOOT = (6.89e-3, 7.24e-3)           # final foot radius [m]

case = os.path.dirname(os.path.abspath(__file__))
data = figures.monitor(case)
t = data["Time"]

times, mesh, x = figures.point_positions(case)
top = mesh.points[:, 1] > mesh.points[:, 1].max() - 1e-9
foot = mesh.patch_points("wall")
length = np.array([xi[top, 1].mean() - xi[foot, 1].mean() for xi in x])
radius = np.array([np.hypot(xi[foot, 0], xi[foot, 2]).max() for xi in x])
print("length %.3f mm, foot radius %.3f mm at t = %g s"
      % (1e3 * length[-1], 1e3 * radius[-1], times[-1]))

figures.plot_panels(
    [
        ("length [mm]", [(times, 1e3 * length, "")],
         [(1e3 * LENGTH[0], 1e3 * LENGTH[1], "literature, 80 us")]),
        ("foot radius [mm]", [(times, 1e3 * radius, "")],
         [(1e3 * FOOT[0], 1e3 * FOOT[1], "literature, 80 us")]),
        figures.energy_panel(data),
        ("momentum p_y [kg m/s]", [(t, data["py"], "")]),
    ] + figures.contact_panels(data),
    "histories.png", "us", title="Taylor impact (quarter bar)", case=case)
