#!/usr/bin/python3
"""Hertz impact on three meshes (tutorials/sphereImpact; FINDINGS.md).

    . etc/bashrc
    /usr/bin/python3 validation/sphereImpact/study.py \
        [--variant wall|sphere] [--update compatible|plain] [N ...]
    /usr/bin/python3 validation/sphereImpact/study.py --n 8 --grading G ...

Each N runs a copy of the tutorial (./Allrun -variant V -n N, FUpdate by
system/solverOptions); with --grading, each G runs -n 8 (or --n) with
-grading G instead: the cells at the contact refined alone and prints one row: cells, steps, faces in contact at most (quarter model), the peak
contact force and the contact time against the closed form (hertz.py),
the energy at the end, the largest energy growth in a step and, between
two balls, the total momentum drift.  Then the observed order and the
Richardson extrapolation of both quantities from the last three meshes
(refinement ratios N2/N1, N3/N2: the graded meshes are refined
uniformly).
Work folders: validation/sphereImpact/runs/ (ignored).
"""

import argparse
import math
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

from touchfoam import hertz, run  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402


def solve(root, variant, update, n, grading=4):
    case = os.path.join(root, "%s_%s_n%d" % (variant, update, n)
                        + ("" if grading == 4 else "_g%g" % grading))
    if not os.path.exists(os.path.join(case, "log.tutorialResults")):
        if os.path.exists(case):
            shutil.rmtree(case)
        shutil.copytree(run.tutorial_dir("sphereImpact"), case)
        with open(os.path.join(case, "system", "solverOptions"), "w") as f:
            f.write("FUpdate %s;\n" % update)
        run.run(["./Allrun", "-variant", variant, "-n", str(n),
                 "-grading", str(grading)], case,
                name="Allrun", timeout=6 * 3600)
    return case


def row(case, n):
    r = hertz.analyse(case)
    mon = read_monitor(case)
    m = PolyMesh(case)
    out = dict(r, n=n, cells=m.n_cells, steps=len(mon["Time"]))
    print("%5.3g %7d %6d %5d   %10.5g %+7.2f %%   %8.4g us %+7.2f %%   "
          "%.4f  %+.1e  %s"
          % (n, m.n_cells, out["steps"], r["maxFaces"], r["peakForce"],
             100 * r["forceError"], 1e6 * r["contactTime"],
             100 * r["timeError"], r["energyEnd"], r["energyGrowth"],
             "%.1e" % r["momentumDrift"] if "momentumDrift" in r else "-"),
          flush=True)
    if "appliedPeak" in r:
        print("      force the balls receive (their momentum change): peak "
              "%.5g N, %+.2f %%" % (r["appliedPeak"],
                                    100 * r["appliedForceError"]),
              flush=True)
    return out


def richardson(rows, key, ratio):
    """Observed order and extrapolated value of key from the last three
    rows (uniform ratio assumed: the ratio of the first two)."""
    f1, f2, f3 = (rows[-3][key], rows[-2][key], rows[-1][key])
    r21, r32 = ratio
    if (f2 - f1) * (f3 - f2) <= 0:
        return None, None
    # Fixed-point iteration for p with unequal ratios
    p = 1.0
    for _ in range(50):
        s = math.copysign(1.0, (f3 - f2) / (f2 - f1))
        q = math.log((r32 ** p - s) / (r21 ** p - s)) if r21 != r32 else 0
        p = abs(math.log(abs((f2 - f1) / (f3 - f2))) + q) / math.log(r32)
    return p, f3 + (f3 - f2) / (r32 ** p - 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--variant", default="wall")
    parser.add_argument("--update", default="compatible")
    parser.add_argument("--grading", nargs="*", type=float, default=None)
    parser.add_argument("--n", type=int, default=8)
    parser.add_argument("sizes", nargs="*", type=int, default=[4, 6, 8])
    args = parser.parse_args()
    root = os.path.join(HERE, "runs")
    os.makedirs(root, exist_ok=True)
    print("variant %s, FUpdate %s" % (args.variant, args.update))
    print("  N   cells  steps faces   peak force [N]  error    contact "
          "time   error     E_end/E0 dE max  drift")
    rows = []
    if args.grading:
        # The contact's cells refined alone: the ratio of the pole faces'
        # sizes is about G2/G1 to the power (N - 1)/N
        for g in args.grading:
            rows.append(row(solve(root, args.variant, args.update, args.n,
                                  g), g ** ((args.n - 1.0) / args.n)))
    else:
        for n in args.sizes:
            rows.append(row(solve(root, args.variant, args.update, n), n))
    ref = rows[-1]["reference"]
    print("closed form: F_max %.5g N, t_c %.4g us, a_max %.4g m"
          % (ref["F"], 1e6 * ref["tc"], ref["a"]))
    if len(rows) >= 3:
        n1, n2, n3 = (rows[-3]["n"], rows[-2]["n"], rows[-1]["n"])
        for key, exact in (("peakForce", ref["F"]),
                           ("contactTime", ref["tc"])):
            p, ext = richardson(rows, key, (n2 / n1, n3 / n2))
            if p is None:
                print("%s: not monotone over the last three meshes" % key)
            else:
                print("%s: observed order %.2f, extrapolated %.5g (%+.2f %% "
                      "of the closed form)" % (key, p, ext,
                                              100 * (ext / exact - 1)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
