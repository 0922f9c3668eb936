#!/usr/bin/python3
"""Temporal order of RK2 and RK3 on a fixed mesh.

    /usr/bin/python3 test/cases/timeOrder.py [--schemes RK2 RK3]

The swinging cube (smooth, linear reconstruction, mirrors) on a fixed 8^3
mesh, so the semi-discrete system is one ODE, integrated to t = 0.003 s (omega t = 1.18: neither a peak nor a node of v or P, where the phase error would vanish to first order)
with CFL 0.4, 0.2 and 0.1 (dt halved) and against a run at CFL 0.0125:
the error of v and P at t = 0.003 s, e(dt) = |q(dt) - q(dt_ref)| (volume-
weighted L2 over the cells), falls at the scheme's order,
log2(e(2 dt)/e(dt)) on the finer pair within [1.7, 2.5] for RK2 and
[2.6, 3.5] for RK3.  Reported also: the order on the coarser pair.
Measured 2026-12-04 (finer pair): RK2 v 2.18, P 2.08; RK3 v 3.11, P 3.22
(about 50 s).  --schemes RK2 --expect 3 (a wrong reference order) fails.
Work folders: test/runs/timeOrder/.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, run, testing  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

NAME = "timeOrder"
T = 0.003
CFLS = (0.4, 0.2, 0.1)
CFL_REF = 0.0125
BANDS = {"RK2": (1.7, 2.5), "RK3": (2.6, 3.5)}


def solution(root, scheme, cfl):
    case = cases.prepare(
        "swingingCube", os.path.join(root, "%s_CFL%g" % (scheme, cfl)), n=8,
        touch={"timeScheme": scheme, "CFL": cfl},
        control={"writePrecision": 17, "endTime": T, "writeInterval": T})
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    mesh = PolyMesh(case)
    tdir = run.time_dir(case, T)
    return (mesh.cell_volumes,
            read_field(os.path.join(tdir, "U")).internal(mesh.n_cells),
            read_field(os.path.join(tdir, "P")).internal(mesh.n_cells))


def body(args):
    root = testing.work_dir(NAME)
    lines, failures = [], []
    for scheme in args.schemes:
        V, Uref, Pref = solution(root, scheme, CFL_REF)
        eU, eP = [], []
        for cfl in CFLS:
            _, U, P = solution(root, scheme, cfl)
            eU.append(np.sqrt(np.sum(V[:, None] * (U - Uref) ** 2)))
            eP.append(np.sqrt(np.sum(V[:, None] * (P - Pref) ** 2)))
        lo, hi = BANDS[scheme] if args.expect is None else \
            (args.expect - 0.3, args.expect + 0.5)
        for label, e in (("v", eU), ("P", eP)):
            orders = [np.log2(a / b) for a, b in zip(e, e[1:])]
            lines.append("%s %s errors %s, orders %s" % (
                scheme, label, " / ".join("%.2e" % x for x in e),
                " ".join("%.2f" % o for o in orders)))
            if not lo <= orders[-1] <= hi:
                failures.append("%s %s order %.2f outside [%g, %g]"
                                % (scheme, label, orders[-1], lo, hi))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--schemes", nargs="+", default=["RK2", "RK3"],
                        choices=list(BANDS))
    parser.add_argument("--expect", type=float, default=None,
                        help="expected order for every scheme (a "
                        "perturbed reference)")
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args)))
