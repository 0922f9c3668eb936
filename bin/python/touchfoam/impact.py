"""Elastic impact in uniaxial strain: a bar hitting a rigid wall.

The bar X in [0, L] moves at -v0 e_x and touches the wall X = 0 at t = 0
(tutorials/elasticImpact).  1D linear theory: a compressive front leaves
the wall at c_p = sqrt((lambda + 2 mu)/rho0); behind it (X < c_p t) the bar
is at rest with sigma_xx = -rho0 c_p v0, ahead of it the bar is unstressed
and still moves at -v0.  In uniaxial strain J = F_xx, so sigma_xx = P_xx.

    initialise_elastic_impact   0/U = -v0 e_x
    ElasticImpact               the closed-form solution
    front_metrics               plateau, front position, overshoot behind
                                the front and precursor ahead of it, from
                                sigma_xx along the bar
    impact_metrics              the same, read from a finished run
"""

import os

import numpy as np

from . import analytic
from .cases import material
from .foamfile import FoamField, read_field
from .mesh import PolyMesh
from .run import time_dir

#: impact speed of the tutorial [m/s] (strain v0/c_p = 1e-4 at c_p = 1000)
V0 = 0.1


class ElasticImpact:
    """Closed-form 1D solution of the bar hitting the wall at X = 0."""

    def __init__(self, E, nu, rho, v0=V0):
        self.E, self.nu, self.rho, self.v0 = E, nu, rho, v0
        self.cp = float(analytic.p_wave_speed(E, nu, rho))
        #: stress jump across the front, rho0 c_p v0 (> 0; sigma_xx is
        #: -jump behind the front)
        self.jump = rho * self.cp * v0

    def front(self, t):
        return self.cp * t

    def sigma_xx(self, X, t):
        return np.where(np.asarray(X)[:, 0] < self.front(t), -self.jump, 0.0)

    def velocity_x(self, X, t):
        return np.where(np.asarray(X)[:, 0] < self.front(t), 0.0, -self.v0)


def initialise_elastic_impact(case, v0=V0):
    """0/U = uniform -v0 e_x (touchFoam starts from lm = rho0 U); F = I
    (0/F absent).  Returns the number of cells."""
    n = PolyMesh(case).n_cells
    U = FoamField(os.path.join(case, "0", "U"))
    U.set_uniform([-v0, 0.0, 0.0])
    U.write()
    return n


def front_metrics(x, sxx, x_front, jump, h, gap=4):
    """Measures of a compressive front in sigma_xx along a bar.

    x, sxx   cell centres along the bar and sigma_xx there (any order)
    x_front  exact front position c_p t;  jump  rho0 c_p v0 (> 0)
    h        cell size;  gap  cells kept clear of the front for the plateau

    Returns a dict:
      plateau     mean sigma_xx over x < x_front - gap h, relative to -jump
                  (1 is exact)
      front       where sigma_xx first crosses -jump/2 coming from the free
                  end (linear interpolation between cell centres)
      offset      (front - x_front)/h, in cells
      overshoot   max(|sigma_xx| - |plateau|) behind the measured front,
                  relative to the jump (>= 0; 0 is monotone)
      precursor   max(sigma_xx) ahead of the measured front (tension, the
                  sign opposite to the plateau), relative to the jump
    """
    order = np.argsort(x)
    x, s = np.asarray(x, float)[order], np.asarray(sxx, float)[order]
    behind = x < x_front - gap * h
    if not behind.any():
        raise ValueError("no cell more than %d cells behind the front at "
                         "%g" % (gap, x_front))
    plateau = float(s[behind].mean())
    # The front: the last cell (from the wall) compressed beyond half the
    # jump, then interpolate to the next one
    half = -0.5 * jump
    below = np.nonzero(s < half)[0]
    if len(below) == 0:
        raise ValueError("sigma_xx never reaches half the jump %g" % half)
    i = below[-1]
    if i + 1 < len(x):
        w = (half - s[i]) / (s[i + 1] - s[i])
        front = float(x[i] + w * (x[i + 1] - x[i]))
    else:
        front = float(x[i])
    back, ahead = x < front, x >= front
    overshoot = float(max(0.0, np.abs(s[back]).max() - abs(plateau)))
    precursor = float(max(0.0, s[ahead].max())) if ahead.any() else 0.0
    return {"plateau": plateau / -jump, "front": front,
            "offset": (front - x_front) / h,
            "overshoot": overshoot / jump, "precursor": precursor / jump}


def impact_metrics(case, t, v0=V0, gap=4):
    """front_metrics of a finished elasticImpact run at time t, plus the
    mean velocity behind the front relative to v0 ('vBehind', 0 exact) and
    ahead of it ('vAhead', -1 exact)."""
    mat = material(case)
    sol = ElasticImpact(mat["E"], mat["nu"], mat["rho"], v0)
    m = PolyMesh(case)
    X = m.cell_centres
    tdir = time_dir(case, t)
    sigma = read_field(os.path.join(tdir, "sigma")).internal(m.n_cells)
    v = read_field(os.path.join(tdir, "U")).internal(m.n_cells)
    x = X[:, 0]
    h = float(np.cbrt(m.cell_volumes.mean()))
    out = front_metrics(x, sigma[:, 0], sol.front(t), sol.jump, h, gap)
    behind = x < sol.front(t) - gap * h
    ahead = x > sol.front(t) + gap * h
    out["vBehind"] = float(v[behind, 0].mean()) / v0
    out["vAhead"] = float(v[ahead, 0].mean()) / v0 if ahead.any() else None
    out["cp"], out["jump"], out["h"] = sol.cp, sol.jump, h
    return out
