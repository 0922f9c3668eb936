#!/usr/bin/python3
"""Plots of the bar collision against the 1D closed forms of elastic
waves.  Run in the case by Allrun; writes

  profiles.png   sigma_xx along the bars at the written times (dots) and,
                 for two bars of one material, the closed form (lines):
                 -Z1 Z2 v/(Z1 + Z2) behind the fronts that leave the
                 contact at c t, then the unloading fronts coming back from
                 the far ends; zero after the release;
  histories.png  the mean contact traction (normal force / area in
                 contact, postProcessing/contact) beside Z1 Z2 v/(Z1 + Z2)
                 until 2 L1/c, the momentum of each bar (solidMonitor
                 px(bar1), px(bar2)) beside the closed form (the constant
                 contact force exchanging it linearly: equal bars +-M v to
                 -+M v by 2 L1/c; bars of one material, L and 2L: the short
                 bar's momentum handed to the long one), and the energies.
"""

import os

import numpy as np

# The touchfoam package: bin/python, on PYTHONPATH after etc/bashrc
from touchfoam import figures
from touchfoam.contact import RHO, analyse, options, read_contact
from touchfoam.foamfile import read_field
from touchfoam.mesh import PolyMesh
from touchfoam.run import time_dirs

import matplotlib                                   # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt                     # noqa: E402

case = os.path.dirname(os.path.abspath(__file__))
o = options(case)
r = analyse(case)
if o["variant"] == "wall":
    raise SystemExit("plot: the variant 'wall' is the reference of 'equal';"
                     " no plots")

L1, L2, v1, v2 = o["L1"], o["L2"], o["v1"], o["v2"]
c, sigma, tc = r["c1"], r["contactStress"], r["contactTimeExact"]
one_material = abs(r["Z2"] / r["Z1"] - 1) < 1e-12


def sigma_xx_exact(x, t):
    """Closed form for bars of one material: compressed at -sigma between
    the fronts that left x = 0 at c t and, after L1/c, the unloading front
    reflected at bar1's free end (for the equal bars at bar2's too); None
    where not drawn."""
    s = np.zeros_like(x)
    if t >= tc:
        # Equal bars: released at rest, unstressed (the long bar of
        # 'unequal' carries its pulse on: no line drawn)
        return s if L2 == L1 else None
    left = -c * t if t <= L1 / c else -(2 * L1 - c * t)
    right = c * t if t <= L1 / c or L2 > L1 else 2 * L1 - c * t
    s[(x > left) & (x < right)] = -sigma
    return s


# Profiles: sigma_xx along the bars
m = PolyMesh(case)
X = m.cell_centres[:, 0]
order = np.argsort(X)
fig, ax = plt.subplots(figsize=(8, 4))
for t, name in sorted(time_dirs(case).items()):
    path = os.path.join(case, name, "sigma")
    if t <= 0 or not os.path.exists(path):
        continue
    sxx = read_field(path).internal(m.n_cells)[:, 0]
    line, = ax.plot(X[order], sxx[order], "o", ms=2,
                    label=figures.time_label(t, "ms"))
    xs = np.linspace(-L1, L2, 4001)
    exact = sigma_xx_exact(xs, t) if one_material else None
    if exact is not None:
        ax.plot(xs, exact, "-", lw=0.8, color=line.get_color())
ax.axvline(0, color="0.5", lw=0.5)
ax.set_xlabel("x [m] (bar1 on x < 0, bar2 on x > 0)")
ax.set_ylabel("sigma_xx [Pa]")
ax.set_title("Bar collision (%s): touchFoam (dots)%s"
             % (o["variant"], ", closed form (lines)" if one_material
                else "; contact stress %.4g Pa" % -sigma))
ax.grid(True, lw=0.3)
ax.legend(fontsize=8, ncol=2)
fig.tight_layout()
fig.savefig(os.path.join(case, "profiles.png"), dpi=120)
plt.close(fig)
print("plot: wrote profiles.png")

# Histories: contact traction and the bars' momenta
rows = read_contact(case)
tr = rows["Time"]
traction = np.where(rows["area"] > 0,
                    rows["normalForce"] / np.maximum(rows["area"], 1e-300),
                    0.0)
data = figures.monitor(case)
t = data["Time"]
section = (int(o.get("M", 1)) * L1 / o["N1"]) ** 2
M1 = RHO * L1 * section
p1 = M1 * v1
reference = np.where(tr < tc, sigma, 0.0)
momenta = [(t, data["px(bar1)"], "bar1"), (t, data["px(bar2)"], "bar2")]
if o["variant"] == "equal":
    # The contact force Z v A exchanges 2 M v in 2 L/c
    momenta += [(t, np.where(t < tc, p1 * (1 - 2 * t / tc), -p1),
                 "bar1, closed form"),
                (t, np.where(t < tc, -p1 * (1 - 2 * t / tc), p1),
                 "bar2, closed form")]
elif one_material:
    momenta += [(t, np.where(t < tc, p1 * (1 - t / tc), 0.0),
                 "bar1, closed form"),
                (t, np.where(t < tc, p1 * t / tc, p1), "bar2, closed form")]
figures.plot_panels(
    [("contact traction [Pa]",
      [(tr, traction, "normal force / area in contact"),
       (tr, reference, "Z1 Z2 v/(Z1+Z2) until 2 L1/c")]),
     ("momentum p_x [kg m/s]", momenta),
     figures.energy_panel(data)],
    "histories.png", "ms",
    title="Bar collision (%s): 2 L1/c = %.4g ms" % (o["variant"], 1e3 * tc),
    case=case)
print("plot: contact stress on the plateau %.6g Pa (closed form %.6g),"
      " bar momenta at the end %.4f, %.4f of bar1's initial"
      % (r["plateauMean"], sigma, r["bar1End"], r["bar2End"]))
