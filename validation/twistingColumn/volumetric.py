#!/usr/bin/python3
"""The twisting column's twist at 0.1 s with a volumetric treatment.

    nice -n 10 /usr/bin/python3 validation/twistingColumn/volumetric.py LABEL N [N ...] [KEY=VALUE ...] [nu=NU]

tutorials/twistingColumn at its setting (linear, RK3, CFL 0.8) on
N x 6N x N cells to 0.1 s, the TOUCH entries KEY=VALUE changed (e.g.
nodalAveraging=cellVolume).  Prints per mesh the twist (postprocess.column_twist
at 0.1 s), the largest energy growth in a step / E0, the energy kept and
the wall time, then the order and Richardson extrapolation through the
last three meshes (fit T + C N^-p) and the errors against the converged
twist of reference.json (issue 35).  Results in
runs/volumetric/LABEL.json.  FINDINGS.md, "The volume of twisted cells".
"""
import json
import math
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, monitor, postprocess, run  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from reference import fit_three  # noqa: E402

#: the converged twist [deg] (reference.py analyse)
with open(os.path.join(HERE, "reference.json")) as _f:
    REFERENCE = round(json.load(_f)["reference"], 2)


def fit(ns, T):
    """Order and limit of T + C n^-p through the last three meshes
    (reference.fit_three; nan where it has none)."""
    p, limit = fit_three(ns[-3:], T[-3:])
    return (float("nan"), float("nan")) if p is None else (p, limit)


def main():
    label = sys.argv[1]
    ns = [int(a) for a in sys.argv[2:] if "=" not in a]
    touch = dict(a.split("=", 1) for a in sys.argv[2:] if "=" in a)
    nu = touch.pop("nu", None)
    rows = []
    for n in ns:
        case = os.path.join(HERE, "runs", "volumetric", "%s_n%d" % (label, n))
        cases.prepare("twistingColumn", case, n=n, touch=touch, nu=nu,
                      control={"endTime": 0.1, "writeInterval": 0.01})
        start = time.time()
        run.run(["touchFoam"], case, timeout=20000)
        wall = time.time() - start
        T = math.degrees([a for t, a in postprocess.column_twist(case)
                          if abs(t - 0.1) < 1e-9][0])
        m = monitor.read_monitor(case)
        E = m["totalEnergy"]
        growth = float(max(0.0, (E[1:] - E[:-1]).max()) / E[0])
        row = {"n": n, "twist": T, "error": T - REFERENCE,
               "growth": growth, "kept": float(E[-1] / E[0]), "wall": wall}
        rows.append(row)
        print("n %2d: twist %.2f deg (error %+.2f), largest growth %.1e E0,"
              " kept %.4f, %.0f s" % (n, T, T - REFERENCE, growth,
                                      row["kept"], wall), flush=True)
    out = {"label": label, "touch": touch, "nu": nu, "rows": rows}
    if len(ns) >= 3:
        p, R = fit(ns, [r["twist"] for r in rows])
        out.update(order=p, extrapolated=R)
        print("order %.2f, extrapolated %.2f deg" % (p, R))
    os.makedirs(os.path.join(HERE, "runs", "volumetric"), exist_ok=True)
    with open(os.path.join(HERE, "runs", "volumetric", label + ".json"),
              "w") as f:
        json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
