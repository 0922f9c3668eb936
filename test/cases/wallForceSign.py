#!/usr/bin/python3
"""A contact only pushes: the rigid wall's force and the force between
two bodies are compressive in every step (issue 28, acceptance 7).

    /usr/bin/python3 test/cases/wallForceSign.py

Rigid wall: tutorials/ringImpact at -n 48 to 45 ms (the whole contact)
and tutorials/torusImpact at -n 8 to 20 ms (touching lowestFreePoint).
The monitor's wallForce(wall) is the force the momentum rate gets from
the wall, the mean over the step's stages (its impulse is the change of
momentum, impactTutorials): asserted >= 0 along the wall's normal in
every step but for round-off (-1e-12 of the largest force).  Without
the release on the applied force (validation/ringImpact/FINDINGS.md 3)
the ring pulled in 74 of 1070 steps (most tensile 0.131 of the largest
force, at the release) and the torus in 83 of 1443 (0.050): the faces
were released on their wall solution's traction t_W, while the force
the compatible update applies is the constraint's reaction at their
points plus their upwind damping.

Between bodies: tutorials/barCollision, variant equal (two 1 m bars at
+-0.1 m/s), 50 cells a metre, FUpdate compatible, to 3 ms (contact from
0 to 2 ms).  Nothing else acts along x, so the force of the contact on
bar1 in a step is its change of p_x over the step (the Runge-Kutta
combination of the stages' forces): asserted <= 0 (pushing bar1 back)
in every step, and bar2's >= 0, but for round-off (-1e-12 of the
largest).  Reported for every case: the steps in contact, those that
pull and the least compressive step force over the largest.

Work folders: test/runs/wallForceSign/.
"""

import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, monitor, run, testing  # noqa: E402

NAME = "wallForceSign"
WALLS = (("ringImpact", 48, 0.045), ("torusImpact", 8, 0.02))
#: Round-off of a force summed over faces and stages, of the largest one
ROUND_OFF = 1e-12
BARS = {"n": 50, "end": 3e-3}


def judge(label, force, failures, lines, time):
    """force: per step in contact, > 0 compressive."""
    largest = float(np.max(np.abs(force)))
    least = float(np.min(force)) / largest
    pulling = int(np.count_nonzero(force < -ROUND_OFF * largest))
    lines.append("%s: %d of %d steps in contact pull, least compressive "
                 "step force %.2e of the largest (at %.4g ms)"
                 % (label, pulling, len(force), least,
                    1e3 * time[int(np.argmin(force))]))
    if pulling:
        failures.append("%s: the contact pulls in %d steps (most tensile "
                        "%.3g of the largest force)"
                        % (label, pulling, -least))


def walls(root, failures, lines):
    for tutorial, n, end in WALLS:
        case = cases.prepare(tutorial, os.path.join(root, tutorial), n=n,
                             control={"endTime": end})
        run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
        m = monitor.read_monitor(case)
        force = [k for k in m if k.startswith("wallForce")][0]
        contact = [k for k in m if k.startswith("contactFaces")][0]
        touching = m[contact] > 0
        if not np.any(touching):
            failures.append("%s: no contact" % tutorial)
            continue
        judge("%s -n %d (wall)" % (tutorial, n), m[force][touching],
              failures, lines, m["Time"][touching])


def bars(root, failures, lines):
    case = os.path.join(root, "barCollision")
    shutil.copytree(run.tutorial_dir("barCollision"), case)
    with open(os.path.join(case, "system", "solverOptions"), "w") as f:
        f.write("FUpdate compatible;\n")
    run.foam_set(case, "system/controlDict", "endTime", BARS["end"])
    run.run(["./Allrun", "-n", str(BARS["n"])], case, name="Allrun",
            timeout=testing.RUN_TIMEOUT)
    m = monitor.read_monitor(case)
    if "px(bar1)" not in m or "px(bar2)" not in m:
        failures.append("barCollision: no columns px(bar1), px(bar2)")
        return
    t = m["Time"]
    dt = np.diff(t)
    # The force on each bar along x in each step, > 0 compressive (bar1
    # comes from x < 0, bar2 from x > 0)
    push1 = -np.diff(m["px(bar1)"]) / dt
    push2 = np.diff(m["px(bar2)"]) / dt
    largest = max(np.max(np.abs(push1)), np.max(np.abs(push2)))
    touching = (np.abs(push1) > ROUND_OFF * largest) \
        | (np.abs(push2) > ROUND_OFF * largest)
    if not np.any(touching):
        failures.append("barCollision: no contact")
        return
    for bar, push in (("bar1", push1), ("bar2", push2)):
        judge("barCollision equal -n %d (%s)" % (BARS["n"], bar),
              push[touching], failures, lines, t[1:][touching])


def body():
    root = testing.work_dir(NAME)
    failures, lines = [], []
    walls(root, failures, lines)
    bars(root, failures, lines)
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
