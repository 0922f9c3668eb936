#!/usr/bin/python3
"""Where the twisting column's upwindings take the energy out, by region.

    /usr/bin/python3 validation/twistingColumn/losses.py N LABEL [KEY=VALUE ...] [Omega=W] [nu=NU]

A sources.py run (N x 6N x N, the tutorial's settings, KEY=VALUE TOUCH
entries) with DebugSwitches { compatible 1; }, which writes the energy
each cell lost to the momentum upwinding (upwindLoss: interior faces half
to each side, the boundary conditions' to their cell) and each point to
the point upwinding (pointUpwindLoss) since the start.  Prints, at 0.1 s,
their sums over the regions of the column as fractions of E0:
the cells by the number of free (traction) faces they touch (0 interior,
1 face, 2 edge, 3 corner), those touching the clamped base apart; the
points likewise (interior, face, edge, corner of the free surface, base).
Omega=W sets the initial spin's amplitude (rad/s; the tutorial's 105):
a small one (1) is the linear regime; nu=NU Poisson's ratio.  FINDINGS.md, "Sources of the
error".
"""
import json
import math
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, monitor, postprocess, run  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CATEGORIES = ("interior", "face", "edge", "corner", "base")


def free_planes(X, h, L=6.0, a=0.5):
    """How many of the free planes (X, Z = +-a, Y = L) lie within h of X."""
    tol = 0.75 * h
    return ((np.abs(np.abs(X[:, 0]) - a) < tol).astype(int)
            + (np.abs(np.abs(X[:, 2]) - a) < tol).astype(int)
            + (np.abs(X[:, 1] - L) < tol).astype(int))


def categories(X, h):
    c = free_planes(X, h)
    c = np.minimum(c, 3)
    base = X[:, 1] < 0.75 * h
    return c, base


def sums(values, X, h):
    c, base = categories(X, h)
    out = {}
    for k, name in enumerate(CATEGORIES[:4]):
        out[name] = float(values[(c == k) & ~base].sum())
    out["base"] = float(values[base].sum())
    out["count"] = {name: int(((c == k) & ~base).sum())
                    for k, name in enumerate(CATEGORIES[:4])}
    out["count"]["base"] = int(base.sum())
    return out


def main():
    n, label = int(sys.argv[1]), sys.argv[2]
    touch = dict(kv.split("=", 1) for kv in sys.argv[3:])
    Omega = touch.pop("Omega", None)
    nu = touch.pop("nu", None)
    case = os.path.join(HERE, "runs", "losses", "%s_n%d" % (label, n))
    cases.prepare("twistingColumn", case, n=n, touch=touch, nu=nu,
                  control={"endTime": 0.1, "writeInterval": 0.01})
    if Omega is not None:
        cases.initialise_twisting_column(case, Omega=float(Omega))
    run.foam_set(case, "system/controlDict", "DebugSwitches",
                 "{ compatible 1; }")
    start = time.time()
    run.run(["touchFoam"], case, timeout=6000)
    wall = time.time() - start
    twist = math.degrees(postprocess.column_twist(case)[-1][1])
    E = monitor.read_monitor(case)["totalEnergy"]
    m = PolyMesh(case)
    tdir = run.time_dir(case, 0.1)
    h = 1.0 / n
    cell = read_field(os.path.join(tdir, "upwindLoss")).internal(m.n_cells)
    point = read_field(os.path.join(tdir, "pointUpwindLoss")).internal(
        len(m.points))
    cells = sums(np.asarray(cell, float) / E[0], m.cell_centres, h)
    # Points are on the planes: within h/4
    points = sums(np.asarray(point, float) / E[0], m.points, h / 3)
    result = {"n": n, "label": label, "touch": touch, "twist": twist,
              "EbyE0": E[-1] / E[0], "wall": wall,
              "cells": cells, "points": points,
              "cellTotal": float(np.sum(cell)) / E[0],
              "pointTotal": float(np.sum(point)) / E[0]}
    print("%-12s n %d twist %.2f deg  1 - E/E0 %.5f  tallied: cells %.5f"
          " points %.5f  wall %.0f s" % (label, n, twist, 1 - E[-1] / E[0],
                                         result["cellTotal"],
                                         result["pointTotal"], wall))
    for kind in ("cells", "points"):
        print("  %-6s " % kind + "  ".join(
            "%s %.5f (%d)" % (k, result[kind][k], result[kind]["count"][k])
            for k in CATEGORIES))
    out = os.path.join(HERE, "runs", "losses", "%s_n%d.json" % (label, n))
    with open(out, "w") as f:
        json.dump(result, f, indent=1)


if __name__ == "__main__":
    main()
