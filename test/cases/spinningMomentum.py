#!/usr/bin/python3
"""Free flight conserves momentum; angular only with the correction on.

    /usr/bin/python3 test/cases/spinningMomentum.py [--steps 1000]

Runs tutorials/spinningCube (6^3 cells, traction-free, v = v_t + omega x X)
for 1000 steps (controlDict maxSteps) with angularMomentumPreservation on,
then off.  From postProcessing/solidMonitor (written every step with 17
digits), with P the total linear momentum and L the angular momentum about
the origin:

    linear drift   max_n |P_n - P_0| / |P_0|  <= 1e-12   (|P_0| = M |v_t|)
    angular drift  max_n |L_n - L_0| / |L_0|  <= 1e-10   (correction on)

and the angular drift with the correction off must be larger than with it
on (reported).  The monitor's first sample must also agree with the
momenta of p = rho0 0/U (a check of the monitor's definitions: P to
1e-10, L to 1e-3 since the first sample may be taken after one step).
Work folders: test/runs/spinningMomentum/.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, postprocess, run, testing  # noqa: E402

NAME = "spinningMomentum"


def spin(root, label, amp, steps):
    control = cases.precise_output()
    control.update({"maxSteps": steps, "endTime": 100,
                    "writeControl": "timeStep", "writeInterval": steps})
    case = cases.prepare("spinningCube", os.path.join(root, label),
                         touch={"angularMomentumPreservation": amp},
                         control=control)
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    drift = postprocess.momentum_drift(case)
    P_init, L_init = postprocess.initial_momenta(case)
    dP0 = np.linalg.norm(np.array(drift["P0"]) - P_init) / np.linalg.norm(
        P_init)
    dL0 = np.linalg.norm(np.array(drift["L0"]) - L_init) / np.linalg.norm(
        L_init)
    if dP0 > 1e-10 or dL0 > 1e-3:
        raise AssertionError(
            "%s: monitor's first sample P %s L %s differs from the initial "
            "P %s L %s" % (label, drift["P0"], drift["L0"], P_init, L_init))
    if drift["samples"] < steps:
        raise AssertionError("%s: %d monitor samples for %d steps"
                             % (label, drift["samples"], steps))
    return drift


def body(args):
    root = testing.work_dir(NAME)
    on = spin(root, "preservationOn", "on", args.steps)
    off = spin(root, "preservationOff", "off", args.steps)
    summary = ("%d steps: on: linear %.1e angular %.1e; off: linear %.1e "
               "angular %.1e" % (on["samples"], on["linear"], on["angular"],
                                 off["linear"], off["angular"]))
    if on["linear"] > args.linear_tol:
        raise AssertionError("linear momentum drift %.2e > %.0e (%s)"
                             % (on["linear"], args.linear_tol, summary))
    if on["angular"] > args.angular_tol:
        raise AssertionError("angular momentum drift %.2e > %.0e (%s)"
                             % (on["angular"], args.angular_tol, summary))
    if not off["angular"] > on["angular"]:
        raise AssertionError("angular drift without the correction is not "
                             "larger (%s)" % summary)
    return summary


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=1000)
    parser.add_argument("--linear-tol", type=float, default=1e-12)
    parser.add_argument("--angular-tol", type=float, default=1e-10)
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args)))
