#!/usr/bin/python3
"""Pressure along the elastic-impact bar at the written times beside the
1D closed form: behind the front X < c_p t the bar is at rest under
sigma_xx = -rho0 c_p v0 and sigma_yy = sigma_zz = lambda/(lambda + 2 mu)
sigma_xx (uniaxial strain), so the pressure is rho0 c_p v0 (1 + 2 lambda/
(lambda + 2 mu))/3; ahead of it zero.  Run in the case by Allrun; writes
profiles.png and prints the largest overshoot over the plateau.
"""

import os

import numpy as np

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import analytic, figures
from touchfoam.cases import material
from touchfoam.foamfile import read_field
from touchfoam.mesh import PolyMesh
from touchfoam.run import time_dirs

V0 = 0.1            # impact speed [m/s] (0.orig/U)

case = os.path.dirname(os.path.abspath(__file__))
mat = material(case)
lam, mu = analytic.lame(mat["E"], mat["nu"])
c = analytic.p_wave_speed(mat["E"], mat["nu"], mat["rho"])
plateau = mat["rho"] * c * V0 * (1 + 2 * lam / (lam + 2 * mu)) / 3

m = PolyMesh(case)
X = m.cell_centres[:, 0]
order = np.argsort(X)

import matplotlib                                   # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt                     # noqa: E402

fig, ax = plt.subplots(figsize=(8, 4))
overshoot = 0.0
for t, name in sorted(time_dirs(case).items()):
    path = os.path.join(case, name, "pressure")
    if t <= 0 or not os.path.exists(path):
        continue
    p = read_field(path).internal(m.n_cells)
    overshoot = max(overshoot, float(p.max()) / plateau - 1)
    line, = ax.plot(X[order], p[order], "o", ms=2,
                    label="%s" % figures.time_label(t, "ms"))
    ax.plot([0, c * t, c * t, X.max()], [plateau, plateau, 0, 0], "-",
            color=line.get_color(), lw=0.8)
ax.set_xlabel("X [m]")
ax.set_ylabel("pressure [Pa]")
ax.set_title("Elastic impact: touchFoam (dots), closed form (lines)")
ax.grid(True, lw=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(case, "profiles.png"), dpi=120)
print("plot: wrote profiles.png; plateau %.4g Pa (closed form), largest "
      "pressure over it %+.2e" % (plateau, overshoot))
