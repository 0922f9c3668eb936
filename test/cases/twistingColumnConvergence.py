#!/usr/bin/python3
"""Twisting column: the twist at t = 0.1 s converges towards the reference.

    /usr/bin/python3 test/cases/twistingColumnConvergence.py
        [--reference DEG] [--touch entry=value ...]

tutorials/twistingColumn at its setting (linear, RK3, CFL 0.8) on
n x 6n x n cells, n = 4, 8, 16 (about 45 s), writing every 0.01 s; the
twist at 0.1 s is the mean rotation about the axis of the top-face points
at least 0.25 m from it (postprocess.column_twist, unwrapped).  The
reference is the converged twist of
validation/twistingColumn/reference.json, established independently of
this test from both codes' Richardson extrapolations on finer meshes
(touchFoam to n = 48, CalculiX C3D8R and C3D8 to n = 24).  Measured
2026-12-04: 306.9 / 324.8 / 329.6 deg, observed order 1.88, Richardson
331.4.  The same meshes at nu = 0.495 check that the scheme does not lock
(issue 35, acceptance 1): measured 2026-12-06 322.2 / 333.4 / 336.4 deg,
order 1.89 (its own limit, not the reference's: a softer G twists more).
Asserted:
  - the error |twist - reference| falls monotonically with the mesh, and
    the twist approaches the reference from below;
  - the error on n = 16 is at most 4 deg (1.5 times today's);
  - the observed order log2((T8 - T4)/(T16 - T8)) is within [1.3, 2.5];
  - the Richardson extrapolation T16 + (T16 - T8)/(2^p - 1) is within
    2.5 deg of the reference (today's 0.8 deg);
  - nu = 0.495: the twist rises monotonically with the mesh, its observed
    order is within the same band and within 0.5 of nu = 0.45's (a
    locking scheme converges more slowly as nu -> 0.5), and the total
    energy never grows in a step at either nu (1e-10 E0).
Perturbations that make it fail (2026-12-04): --reference 340 (n = 16
error 10.4 deg, Richardson 8.6 deg off), --touch reconstruction=firstOrder
(49.5 / 78.7 / 125.3 deg: order -0.68, Richardson 0.7 deg).
Work folders: test/runs/twistingColumnConvergence/.
"""

import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, monitor, postprocess, run  # noqa: E402
from touchfoam import testing  # noqa: E402

NAME = "twistingColumnConvergence"
MESHES = (4, 8, 16)
T_TWIST = 0.1
MAX_FINE_ERROR = 4.0
ORDER_BAND = (1.3, 2.5)
RICHARDSON_TOL = 2.5
NU_LOCKING = 0.495
ORDER_DIFFERENCE = 0.5
ENERGY_TOL = 1e-10
#: the converged twist [deg] (validation/twistingColumn/reference.py)
with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                       "..", "validation", "twistingColumn",
                       "reference.json")) as _f:
    REFERENCE = round(json.load(_f)["reference"], 2)


def twist(root, n, touch, nu=None):
    """(twist at 0.1 s [deg], largest energy growth in a step / E0)."""
    name = "n%d" % n if nu is None else "nu%g_n%d" % (nu, n)
    case = cases.prepare("twistingColumn", os.path.join(root, name),
                         n=n, nu=nu, touch=touch,
                         control={"endTime": T_TWIST, "writeInterval": 0.01})
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    history = [a for t, a in postprocess.column_twist(case)
               if abs(t - T_TWIST) < 1e-9]
    if not history:
        raise AssertionError("%s: no write at t = %g" % (name, T_TWIST))
    energy = monitor.read_monitor(case)["totalEnergy"]
    growth = max(b - a for a, b in zip(energy[:-1], energy[1:])) / energy[0]
    return math.degrees(history[0]), growth


def order(T):
    """Observed order and Richardson extrapolation of three twists on
    meshes in the ratio 2 (nan where they do not converge monotonically)."""
    d1, d2 = T[1] - T[0], T[2] - T[1]
    if d1 > 0 and d2 > 0:
        p = math.log(d1 / d2) / math.log(2.0)
        return p, T[2] + d2 / (2 ** p - 1)
    return float("nan"), float("nan")


def body(args):
    root = testing.work_dir(NAME)
    touch = dict(kv.split("=", 1) for kv in args.touch)
    runs = [twist(root, n, touch) for n in MESHES]
    locking = [twist(root, n, touch, NU_LOCKING) for n in MESHES]
    T = [t for t, _ in runs]
    errors = [abs(t - args.reference) for t in T]
    lines = ["twist at 0.1 s %s deg on n = %s (reference %.1f)"
             % (" / ".join("%.1f" % t for t in T),
                " / ".join(str(n) for n in MESHES), args.reference)]
    failures = []
    if not (errors[0] > errors[1] > errors[2]
            and all(t < args.reference for t in T)):
        failures.append("not monotone towards the reference (errors %s)"
                        % " / ".join("%.1f" % e for e in errors))
    if not errors[-1] <= MAX_FINE_ERROR:
        failures.append("n %d error %.1f deg > %g"
                        % (MESHES[-1], errors[-1], MAX_FINE_ERROR))
    p, R = order(T)
    lines.append("observed order %.2f, Richardson %.1f deg" % (p, R))
    if not ORDER_BAND[0] <= p <= ORDER_BAND[1]:
        failures.append("observed order %.2f outside [%g, %g]"
                        % ((p,) + ORDER_BAND))
    if not abs(R - args.reference) <= RICHARDSON_TOL:
        failures.append("Richardson %.1f deg more than %g from %.1f"
                        % (R, RICHARDSON_TOL, args.reference))
    TL = [t for t, _ in locking]
    pL, RL = order(TL)
    lines.append("nu %g: twist %s deg, observed order %.2f (nu 0.45: "
                 "%.2f), Richardson %.1f deg"
                 % (NU_LOCKING, " / ".join("%.1f" % t for t in TL), pL, p,
                    RL))
    if not (ORDER_BAND[0] <= pL <= ORDER_BAND[1]
            and abs(pL - p) <= ORDER_DIFFERENCE):
        failures.append("nu %g: observed order %.2f outside [%g, %g] or "
                        "more than %g from nu 0.45's %.2f (locking)"
                        % ((NU_LOCKING, pL) + ORDER_BAND
                           + (ORDER_DIFFERENCE, p)))
    growth = max(g for _, g in runs + locking)
    lines.append("largest energy growth in a step %.1e E0 (both nu, every "
                 "mesh)" % growth)
    if not growth <= ENERGY_TOL:
        failures.append("energy grew by %.1e E0 in a step" % growth)
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--reference", type=float, default=REFERENCE)
    parser.add_argument("--touch", nargs="*", default=[],
                        help="TOUCH entries entry=value (perturbations)")
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args)))
