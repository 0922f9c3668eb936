"""Quantities the tests and validation scripts measure on finished runs.

    swinging_cube_errors   L2 errors of v and of P_xx, P_yy, P_zz against
                           the closed-form solution
    observed_orders        log(e1/e2) / log(h1/h2) between successive meshes
    energy_increase        largest step-to-step growth of the total energy
    column_twist           mean twist of the column's top face over time
    momentum_drift         drift of the total linear and angular momentum
"""

import os

import numpy as np

from . import analytic
from .cases import material
from .foamfile import read_field
from .mesh import PolyMesh
from .monitor import read_monitor
from .run import time_dir, time_dirs

#: the norm, stated once for the reports
NORM = ("e_L2(q) = sqrt(sum_e V_e (q_e - q_exact(X_e, t))^2), q_e the cell "
        "value, X_e the reference cell centre, V_e the reference cell volume "
        "(the domain volume is 1); 'relMax' divides by max_e |q_exact(X_e, "
        "t)|, 'relAmplitude' by the amplitude of q over all X and t "
        "(U0 w for velocities, (3 lambda + 2 mu) pi/2 U0 for stresses)")

#: component name -> (field, index into the flattened values)
SWINGING_COMPONENTS = {
    "vx": ("U", 0), "vy": ("U", 1), "vz": ("U", 2),
    "Pxx": ("P", 0), "Pyy": ("P", 4), "Pzz": ("P", 8),
}


def swinging_cube_errors(case, t=0.004, U0=None):
    """{component: {L2, relMax, relAmplitude}} for a swinging-cube run."""
    mat = material(case)
    kw = {} if U0 is None else {"U0": U0}
    sol = analytic.SwingingCube(E=mat["E"], nu=mat["nu"], rho=mat["rho"],
                                **kw)
    m = PolyMesh(case)
    X, V = m.cell_centres, m.cell_volumes
    tdir = time_dir(case, t)
    exact = {"U": sol.velocity(X, t),
             "P": analytic.flatten_tensor(sol.stress(X, t))}
    amplitude = {"U": sol.velocity_amplitude(), "P": sol.stress_amplitude()}
    values = {f: read_field(os.path.join(tdir, f)).internal(m.n_cells)
              for f in ("U", "P")}
    out = {}
    for comp, (field, i) in SWINGING_COMPONENTS.items():
        q, qe = values[field][:, i], exact[field][:, i]
        e = float(np.sqrt(np.sum(V * (q - qe) ** 2)))
        out[comp] = {"L2": e,
                     "relMax": e / float(np.abs(qe).max()),
                     "relAmplitude": e / amplitude[field]}
    return out


def observed_orders(h, e):
    """Orders between successive (h, e) pairs (None when an error is 0)."""
    orders = []
    for (h1, e1), (h2, e2) in zip(zip(h, e), zip(h[1:], e[1:])):
        if e1 > 0 and e2 > 0:
            orders.append(float(np.log(e1 / e2) / np.log(h1 / h2)))
        else:
            orders.append(None)
    return orders


def initial_momentum(case, m=None):
    """The momentum touchFoam starts from, per cell: 0/lm if present,
    else rho0 times the velocity 0/U."""
    m = m or PolyMesh(case)
    lm = os.path.join(case, "0", "lm")
    if os.path.exists(lm):
        return read_field(lm).internal(m.n_cells)
    U = read_field(os.path.join(case, "0", "U")).internal(m.n_cells)
    return material(case)["rho"] * np.asarray(U, float)


def initial_energy(case):
    """Kinetic energy sum V |p|^2 / (2 rho0) of the initial momentum (F = I:
    no strain)."""
    m = PolyMesh(case)
    p = initial_momentum(case, m)
    rho = material(case)["rho"]
    return float(np.sum(m.cell_volumes * np.sum(p * p, axis=1)) / (2 * rho))


def energy_increase(case, reference=None):
    """(max_n (E_{n+1} - E_n) / E_ref, E_ref, number of samples).

    E is the monitor's totalEnergy; E_ref defaults to its first sample.
    A positive result means the energy grew somewhere.
    """
    mon = read_monitor(case)
    E = mon["totalEnergy"]
    ref = reference if reference is not None else E[0]
    if len(E) < 2:
        raise ValueError("%s: fewer than 2 monitor samples" % case)
    return float(np.max(np.diff(E)) / ref), float(ref), len(E)


def column_twist(case, t_end=None, top=6.0, rmin=0.25, tol=1e-9):
    """[(t, mean twist angle)] of the column's top face, from pointD.

    The twist of a point is its rotation about +Y in the XZ plane
    (analytic.twist_angle); points closer than rmin to the axis are left
    out (their angle is ill-conditioned).  Angles are unwrapped from one
    write time to the next, so the write interval must be short enough
    for the top to turn less than pi between writes (0.01 s: at most
    Omega dt = 1.05 rad).
    """
    m = PolyMesh(case)
    X = m.points
    top_pts = np.nonzero((np.abs(X[:, 1] - top) < tol)
                         & (np.hypot(X[:, 0], X[:, 2]) >= rmin))[0]
    if len(top_pts) == 0:
        raise ValueError("%s: no top-face points at Y = %g" % (case, top))
    times = sorted(t for t in time_dirs(case) if t > 0)
    if t_end is not None:
        times = [t for t in times if t <= t_end * (1 + tol)]
    history = [(0.0, 0.0)]
    previous = np.zeros(len(top_pts))
    for t in times:
        path = os.path.join(time_dir(case, t), "pointD")
        u = read_field(path).internal(len(X))[top_pts]
        theta = analytic.twist_angle(X[top_pts], u)
        # Unwrap: the branch nearest the previous angle
        theta = previous + np.angle(np.exp(1j * (theta - previous)))
        previous = theta
        history.append((t, float(theta.mean())))
    return history


def momentum_drift(case):
    """Drift of the monitor's total momenta over the run.

    Returns the first samples P0, L0 and the relative drifts
    max_n |P_n - P_0| / |P_0| and max_n |L_n - L_0| / |L_0| (Euclidean
    norms; absolute when the first sample is zero).
    """
    mon = read_monitor(case)
    P, L = mon["p"], mon["L"]
    P0, L0 = np.linalg.norm(P[0]), np.linalg.norm(L[0])
    dP = np.linalg.norm(P - P[0], axis=1).max()
    dL = np.linalg.norm(L - L[0], axis=1).max()
    return {
        "samples": len(P), "P0": P[0].tolist(), "L0": L[0].tolist(),
        "linear": float(dP / P0) if P0 > 0 else float(dP),
        "angular": float(dL / L0) if L0 > 0 else float(dL),
    }


def initial_momenta(case):
    """Total linear and angular momentum (about the origin) of the initial
    momentum."""
    m = PolyMesh(case)
    p = initial_momentum(case, m)
    V = m.cell_volumes[:, None]
    return (np.sum(V * p, axis=0),
            np.sum(V * np.cross(m.cell_centres, p), axis=0))
