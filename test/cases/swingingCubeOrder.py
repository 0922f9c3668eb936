#!/usr/bin/python3
"""Swinging cube: observed convergence order of v and P on 8^3 and 16^3.

    /usr/bin/python3 test/cases/swingingCubeOrder.py [--meshes 8 16]

Runs tutorials/swingingCube to t = 0.004 s with reconstruction linear,
limitedLinear and firstOrder on N^3 cells (N = 8, 16) and computes the L2
errors e = sqrt(sum_e V_e (q_e - q_exact(X_e))^2) of vx vy vz Pxx Pyy Pzz
against the closed-form solution.  The order log(e_8/e_16)/log(2) must be
>= 1.6 for every component with the linear schemes, and with firstOrder
within [0.7, 1.4] for the velocities and >= 0.7 for the stresses: at
t = 0.004 s, cos(w t) = 1.4e-3, so the stresses sit at a node of the
oscillation where the first-order amplitude error (damping) vanishes and
the smaller phase error is what remains (observed order ~3 there).
(validation/swingingCube asks 1.8 between 16 and 32.)
Work folders: test/runs/swingingCubeOrder/.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, postprocess, run, testing  # noqa: E402

NAME = "swingingCubeOrder"
T_END = 0.004
# scheme -> {component kind: (min order, max order or None)}
EXPECTED = {
    "linear": {"U": (1.6, None), "P": (1.6, None)},
    "limitedLinear": {"U": (1.6, None), "P": (1.6, None)},
    "firstOrder": {"U": (0.7, 1.4), "P": (0.7, None)},
}


def body(args):
    root = testing.work_dir(NAME)
    lines, failures = [], []
    for scheme in args.schemes:
        errors = []
        for n in args.meshes:
            case = cases.prepare(
                "swingingCube", os.path.join(root, "%s_N%d" % (scheme, n)),
                n=n, touch={"reconstruction": scheme},
                control={"writePrecision": 17, "endTime": T_END})
            run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
            errors.append(postprocess.swinging_cube_errors(case, T_END))
        h = [1.0 / n for n in args.meshes]
        worst = []
        for comp, (field, _) in postprocess.SWINGING_COMPONENTS.items():
            lo, hi = EXPECTED[scheme][field]
            order = postprocess.observed_orders(
                h, [e[comp]["L2"] for e in errors])[-1]
            worst.append((order if order is not None else float("nan"), comp))
            if order is None or order < lo or (hi is not None and order > hi):
                failures.append("%s %s order %s" % (scheme, comp, order))
        lines.append("%s orders %s" % (scheme, " ".join(
            "%s %.2f" % (c, o) for o, c in worst)))
    summary = "; ".join(lines)
    if failures:
        raise AssertionError("%s (%s)" % (", ".join(failures), summary))
    return summary


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--meshes", type=int, nargs=2, default=[8, 16])
    parser.add_argument("--schemes", nargs="+", choices=list(EXPECTED),
                        default=["linear", "limitedLinear", "firstOrder"])
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args)))
