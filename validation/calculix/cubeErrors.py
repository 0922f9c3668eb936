"""The swinging cube's errors against its closed-form solution: touchFoam's
cell values and CalculiX's nodal velocities and element stresses
(compare.py's cube rows; README.md, 'Definitions')."""

import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

from touchfoam import analytic, cases, postprocess, run  # noqa: E402

import ccx  # noqa: E402

#: the time of the errors [s]
CUBE_END = 0.004


def check_cube_material():
    mat = cases.material(run.tutorial_dir("swingingCube"))
    for key in ("E", "nu", "rho"):
        if not math.isclose(mat[key], ccx.CUBE_DECK[key], rel_tol=1e-12):
            raise ValueError("swingingCube %s = %g, the CalculiX deck has %g"
                             % (key, mat[key], ccx.CUBE_DECK[key]))
    p = ccx.CUBE_DECK
    return analytic.SwingingCube(E=p["E"], nu=p["nu"], rho=p["rho"],
                                 U0=p["U0"])


def touch_cube_errors(folder):
    e = postprocess.swinging_cube_errors(folder, CUBE_END)
    ev = math.sqrt(sum(e[c]["L2"] ** 2 for c in ("vx", "vy", "vz")))
    eP = math.sqrt(sum(e[c]["L2"] ** 2 for c in ("Pxx", "Pyy", "Pzz")) / 3)
    return {"ev": ev, "evx": e["vx"]["L2"], "ePxx": e["Pxx"]["L2"],
            "ePnormal": eP, "time": CUBE_END}


def ccx_cube_errors(folder, job, n, sol):
    nodes, elements, _ = ccx.read_inp(os.path.join(folder, job + ".inp"))
    blocks = ccx.read_dat(os.path.join(folder, job + ".dat"))
    vb = ccx.last_block(blocks, "velocities", "NALL")
    sb = ccx.last_block(blocks, "stresses", "EALL")
    t = vb["time"]
    # velocity: nodes, trapezoidal weights (0.5/N on the faces, 1/N inside)
    rows = np.array(vb["rows"])
    X = np.array([nodes[int(i)] for i in rows[:, 0]])
    w1 = np.where((np.abs(X) < 1e-9) | (np.abs(X - 1) < 1e-9), 0.5 / n,
                  1.0 / n)
    w = w1.prod(axis=1)
    if not math.isclose(w.sum(), 1.0, rel_tol=1e-9):
        raise ValueError("%s: nodal weights sum to %g" % (job, w.sum()))
    dv = rows[:, 1:4] - sol.velocity(X, t)
    # stress: element mean over the integration points, at the centroid
    srows = np.array(sb["rows"])
    ids = srows[:, 0].astype(int)
    order = np.unique(ids)
    counts = np.bincount(np.searchsorted(order, ids))
    S = np.zeros((len(order), 6))
    np.add.at(S, np.searchsorted(order, ids), srows[:, 2:8])
    S /= counts[:, None]
    C = np.array([np.mean([nodes[k] for k in elements[e]], axis=0)
                  for e in order])
    P = sol.stress(C, sb["time"])
    dP = S[:, :3] - np.stack([P[:, 0, 0], P[:, 1, 1], P[:, 2, 2]], axis=1)
    V = 1.0 / len(order)            # a uniform mesh of the unit cube
    return {"ev": float(np.sqrt(np.sum(w * np.sum(dv ** 2, axis=1)))),
            "evx": float(np.sqrt(np.sum(w * dv[:, 0] ** 2))),
            "ePxx": float(np.sqrt(V * np.sum(dP[:, 0] ** 2))),
            "ePnormal": float(np.sqrt(V * np.sum(dP ** 2) / 3)),
            "time": t, "integrationPoints": int(counts.max())}
