#!/usr/bin/python3
"""The rigid wall only pushes: its force is compressive in every step
(issue 28, acceptance 7).

    /usr/bin/python3 test/cases/wallForceSign.py

tutorials/ringImpact at -n 48 to 45 ms (the whole contact) and
tutorials/torusImpact at -n 8 to 20 ms.  The monitor's wallForce(wall)
is the force the momentum rate gets from the wall, the mean over the
step's stages (its impulse is the change of momentum, impactTutorials):
asserted >= 0 along the wall's normal in every step.  Reported: the most
tensile step as a fraction of the largest force and the number of steps
that pull.

Known to fail (test/knownFailures): a face stays in contact while the
traction of its wall Riemann solution t_W is compressive, but the force
the compatible update applies is the reaction of the constraint at the
face's points plus the faces' upwind damping, and both can pull while
t_W pushes (validation/ringImpact/FINDINGS.md).

Work folders: test/runs/wallForceSign/.
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, monitor, run, testing  # noqa: E402

NAME = "wallForceSign"
CASES = (("ringImpact", 48, 0.045), ("torusImpact", 8, 0.02))


def body():
    root = testing.work_dir(NAME)
    failures, lines = [], []
    for tutorial, n, end in CASES:
        case = cases.prepare(tutorial, os.path.join(root, tutorial), n=n,
                             control={"endTime": end})
        run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
        m = monitor.read_monitor(case)
        force = [k for k in m if k.startswith("wallForce")][0]
        contact = [k for k in m if k.startswith("contactFaces")][0]
        f = m[force]
        steps = int(np.count_nonzero(m[contact] > 0))
        if steps == 0:
            failures.append("%s: no contact" % tutorial)
            continue
        pulling = int(np.count_nonzero(f < 0))
        tensile = -min(0.0, float(f.min())) / float(f.max())
        lines.append("%s -n %d: %d of %d steps in contact pull, most "
                     "tensile %.2e of the largest force (at %.4g ms)"
                     % (tutorial, n, pulling, steps, tensile,
                        1e3 * m["Time"][int(np.argmin(f))]))
        if pulling:
            failures.append("%s: the wall pulls in %d steps" % (tutorial,
                                                                 pulling))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
