#!/usr/bin/python3
"""A body sliding along a frictionless rigid wall behaves as the same body
dropped straight, once the drift is removed (issue 28, acceptance 7).

    /usr/bin/python3 test/cases/slidingWallInvariance.py

tutorials/ringImpact at -n 48 (96 cells) to 45 ms (contact from 7 to 36
ms, then free flight), twice: falling at (0, -0.59, 0) m/s as the tutorial,
and at (V, -0.59, 0), V = 0.5 m/s along the wall.  A frictionless flat wall
exerts no tangential force and its contact depends only on normal gaps and
tractions, so Galilean invariance along the wall is exact: the sliding
ring's lm - rho V e_x, D - V t e_x, pointD - V t e_x and F equal the
straight ring's at every written time, and so do the active set (the
'contact' entry) and, in every step, the monitor's time, number of faces
in contact and wall force.  Asserted to 1e-10 of each field's largest
value; p_x must stay rho V times the volume (the wall does not brake it).

With angularMomentumPreservation on (the tutorial's setting) the sliding
ring spun up after first contact (0.17 |p_y(0)| R_outer about its centre
of mass by 36 ms), left the wall 1.5 ms (4 %) early and its fields
differed by 40 % at 45 ms: the correction's target took the wall's torque
from the flux's central traction at the faces, whose sum is not the
force the compatible update applies (the constraint's reaction at the
points), and with a drift the difference has a lever arm.  Since the
torque is that of the applied force the two rings agree to 1e-11.

Work folders: test/runs/slidingWallInvariance/.
"""

import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, monitor, run, testing  # noqa: E402
from touchfoam.foamfile import FoamField, read_dict  # noqa: E402

NAME = "slidingWallInvariance"
N = 48
END = 0.045
V_SLIDE = 0.5
V_FALL = -0.59
TOLERANCE = 1e-10


def contact_entry(folder):
    """The text of the 'contact' entry of lm's wall patch."""
    text = open(os.path.join(folder, "lm")).read()
    patch = text[text.index("rigidWall"):]
    m = re.search(r"\bcontact\s+([^;]*);", patch)
    if not m:
        raise AssertionError("%s/lm: no 'contact' entry" % folder)
    return " ".join(m.group(1).split())


def internal(folder, field):
    f = FoamField(os.path.join(folder, field))
    return np.asarray(f.internal(None), float)


def run_ring(root, tag, vx):
    case = cases.prepare("ringImpact", os.path.join(root, tag), n=N,
                         control=dict(cases.precise_output(),
                                      endTime=END))
    u = FoamField(os.path.join(case, "0", "U"))
    u.set_uniform([vx, V_FALL, 0.0])
    u.write()
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    return case


def written_times(case):
    return sorted((d for d in os.listdir(case)
                   if re.fullmatch(r"[0-9.e+-]+", d) and float(d) > 0),
                  key=float)


def body():
    root = testing.work_dir(NAME)
    straight = run_ring(root, "straight", 0.0)
    sliding = run_ring(root, "sliding", V_SLIDE)
    rho = read_dict(os.path.join(straight, "constant",
                                 "mechanicalProperties"))["rho"]

    failures, lines = [], []
    times = written_times(straight)
    if written_times(sliding) != times or len(times) < 5:
        raise AssertionError("written times differ: %s / %s"
                             % (times, written_times(sliding)))

    worst = {}
    for t in times:
        a, b = os.path.join(straight, t), os.path.join(sliding, t)
        shift = {"lm": rho * V_SLIDE, "D": V_SLIDE * float(t),
                 "pointD": V_SLIDE * float(t)}
        for field in ("lm", "F", "D", "pointD"):
            x, y = internal(a, field), internal(b, field)
            if x.shape != y.shape:
                raise AssertionError("%s/%s: %s against %s values"
                                     % (t, field, y.shape, x.shape))
            if field in shift:
                y = y.copy()
                y[:, 0] -= shift[field]
            d = testing.relative_max_difference(y, x)
            worst[field] = max(worst.get(field, 0.0), d)
            if d > TOLERANCE:
                failures.append("%s at %s: %.1e of its largest value"
                                % (field, t, d))
        if contact_entry(a) != contact_entry(b):
            failures.append("active set differs at %s" % t)

    ms, mb = monitor.read_monitor(straight), monitor.read_monitor(sliding)
    wall = [k for k in ms if k.startswith("contactFaces")][0]
    force = [k for k in ms if k.startswith("wallForce")][0]
    if len(ms["Time"]) != len(mb["Time"]) \
       or np.abs(ms["Time"] - mb["Time"]).max() > 1e-12 * END:
        failures.append("the step sequences differ")
    else:
        if np.any(ms[wall] != mb[wall]):
            i = int(np.argmax(ms[wall] != mb[wall]))
            failures.append("faces in contact differ from %.4g ms"
                            % (1e3 * ms["Time"][i]))
        dF = testing.relative_max_difference(mb[force], ms[force])
        worst["wallForce"] = dF
        if dF > TOLERANCE:
            failures.append("wall force differs by %.1e of its largest" % dF)

    in_contact = ms["Time"][ms[wall] > 0]
    if len(in_contact) == 0 or in_contact[-1] > 0.9 * END:
        failures.append("the ring must touch the wall and leave it before "
                        "%.3g s" % (0.9 * END))
    px = mb["px"]
    px_drift = np.abs(px - px[0]).max() / abs(px[0])
    if px_drift > 1e-12:
        failures.append("p_x of the sliding ring changed by %.1e" % px_drift)

    lines.append("-n %d, V = %g m/s along the wall, contact %.2f-%.2f ms: "
                 "largest difference (drift removed) %s; p_x constant to "
                 "%.1e" % (N, V_SLIDE, 1e3 * in_contact[0],
                           1e3 * in_contact[-1],
                           ", ".join("%s %.1e" % kv for kv in worst.items()),
                           px_drift))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
