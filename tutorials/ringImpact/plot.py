#!/usr/bin/python3
"""Histories of the ring (seed figure 9): linear and angular momentum
(about the ring's initial centre, the origin), per metre of thickness as
the seed's plane problem, energy, and the faces in contact with the wall
and its force per metre.  Run in the case by Allrun; writes
histories.png and prints the largest |p_x|, |p_z| and |L| relative to the
bounds of doc/benchmarks.md, ring impact (1e-8 |p_y(0)| and 1e-8 |p_y(0)| R_outer).
"""

import os

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import figures

R_OUTER = 0.04

case = os.path.dirname(os.path.abspath(__file__))
data = figures.monitor(case)
t = data["Time"]
per_metre = 1.0 / figures.slab_thickness(case, axis=2)
p, L = data["p"] * per_metre, data["L"] * per_metre

py0 = abs(p[0, 1])
print("max |p_x|, |p_z| / |p_y(0)|: %.3g, %.3g (bound 1e-8)"
      % (abs(p[:, 0]).max() / py0, abs(p[:, 2]).max() / py0))
print("max |L_x|, |L_y|, |L_z| / (|p_y(0)| R_outer): %.3g, %.3g, %.3g "
      "(bound 1e-8)" % tuple(abs(L).max(axis=0) / (py0 * R_OUTER)))
contact = t[data["contactFaces(wall)"] > 0] if "contactFaces(wall)" in data \
    else []
if len(contact):
    print("in contact from %.4g s to %.4g s" % (contact[0], contact[-1]))

energy = figures.energy_panel(data)
energy = ("energy per metre [J/m]",
          [(ti, y * per_metre, label) for ti, y, label in energy[1]])
contact_panels = figures.contact_panels(data)
faces, force = contact_panels
force = ("wall force per metre [N/m]",
         [(ti, y * per_metre, label) for ti, y, label in force[1]])
figures.plot_panels(
    [
        ("linear momentum [kg/s]",
         [(t, p[:, i], "p" + "xyz"[i]) for i in range(3)]),
        ("angular momentum [kg m/s]",
         [(t, L[:, i], "L" + "xyz"[i]) for i in range(3)]),
        energy, faces, force,
    ],
    "histories.png", "ms", title="Ring impact (per metre of thickness)",
    case=case)
