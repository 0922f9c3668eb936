#!/usr/bin/python3
"""Histories of the projectile impact: the contact force of the whole ball
(four times the quarter model's), the two bodies' momenta along the
impact and their sum (constant: no wall acts along y), the energy account
(kinetic, stored, plastic and friction dissipation; their sum never
grows) and the friction ratio |t_t|/|t_n| of the pairs and of the faces
beside mu (from the solidMonitor and postProcessing/contact).  Run in the
case by Allrun; writes histories.png.
"""

import os

import numpy as np

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import figures, projectile
from touchfoam.contact import read_contact

case = os.path.dirname(os.path.abspath(__file__))
r = projectile.analyse(case)
data = figures.monitor(case)
c = read_contact(case)
t, tc = data["Time"], c["Time"]
p0 = r["p0"]
zero = 0.0 * t
friction = data.get("frictionDissipation", zero)
ratios = []
if "maxPairFrictionRatio" in c:
    ratios = [(tc, c["maxPairFrictionRatio"], "largest of a pair"),
              (tc, c["maxFrictionRatio"], "largest of a face"),
              (tc, r["mu"] + 0.0 * tc, "mu")]

figures.plot_panels(
    [
        ("contact force [N]", [(tc, projectile.QUARTER * c["normalForce"],
                                "4 x quarter")]),
        ("p_y / |p0|", [(t, data["py(projectile)"] / p0, "ball"),
                        (t, data["py(plate)"] / p0, "plate"),
                        (t, data["p"][:, 1] / p0, "total")]),
        ("energy / E0", [(t, data["kineticEnergy"] / r["E0"], "kinetic"),
                         (t, data["strainEnergy"] / r["E0"], "stored"),
                         (t, data["plasticDissipation"] / r["E0"],
                          "plastic"),
                         (t, friction / r["E0"], "friction"),
                         (t, (data["totalEnergy"]
                              + data["plasticDissipation"] + friction)
                          / r["E0"], "sum")]),
        ("|t_t| / |t_n|", [(x, np.asarray(y), label)
                           for x, y, label in ratios]),
    ],
    "histories.png", "us", title="Projectile impact: steel ball on a free "
    "aluminium plate, %g m/s" % r["V"], case=case)
