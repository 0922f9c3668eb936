#!/usr/bin/python3
"""Histories of the sliding block: its mean velocity p_x/M per step
beside the rigid block's v0 - mu g t (zero after v0/(mu g)), the friction's
work against the kinetic energy, and the energy (from the solidMonitor).
Run in the case by Allrun; writes histories.png.
"""

import os

import numpy as np

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import figures

V0 = 1.0            # launch speed [m/s] (0.orig/U)
MU_G = 0.3 * 9.81   # muKinetic g [m/s^2] (0.orig/U, constant/g)

case = os.path.dirname(os.path.abspath(__file__))
data = figures.monitor(case)
t = data["Time"]
mass = data["px"][0] / V0
v = data["px"] / mass
rigid = np.maximum(V0 - MU_G * t, 0.0)
print("mean velocity at the end %.3g v0; rigid block stops at %.4g s"
      % (v[-1] / V0, V0 / MU_G))

figures.plot_panels(
    [
        ("velocity p_x/M [m/s]",
         [(t, v, "touchFoam"), (t, rigid, "rigid block, v0 - mu g t")]),
        figures.energy_panel(data),
    ] + figures.contact_panels(data),
    "histories.png", "s", title="Sliding block (Coulomb friction, gravity)",
    case=case)
