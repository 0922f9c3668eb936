#!/usr/bin/python3
"""A steel ball on a plate a thousand times its impedance, through
bodyContact with the compatible update: the energy never grows while the
faces enter the contact one ring after another.

    /usr/bin/python3 test/cases/stiffPartner.py

A copy of tutorials/projectileImpact at -n 8 and 10 m/s, frictionless,
both laws linearElastic: the ball steel (7800 kg/m^3, 200 GPa, 0.3), the
plate with 1000 times the steel's density and modulus (the same wave
speed, 1000 times the impedance), FUpdate compatible, to 4 us (the ball's
second ring of faces enters at 3.3 us; about 870 steps).

The compatible update takes the sum of the two sides' contact forces back
from the faces pushed on (balanceContactForces).  Taken by area, half of
it went to the ball, pushing it on at its own velocity while the plate's
contact velocity is the plate's: the energy grew by 1.7e-6 E0 in a step
as the second ring entered (2026-12-07, commit 757fb0d).  Taken in shares
of area times impedance, the correction's power is the sum against the
contact velocity (validation/sphereImpact/FINDINGS.md section 11).
Asserted, every step:
  - kinetic + strain energy grows by no more than 1e-12 E0;
  - the total numerical remainder (the monitor's numericalDissipation)
    does not fall by more than 1e-12 E0;
  - the total p_y constant to MOMENTUM_DRIFT of |p0| (the plate is free;
    the symmetric planes of the quarter model push along x and z only);
and that the case is what it should be: the impedance ratio 1000, and
the number of contact faces grows after the first contact (the entry of
further faces is what this tests).  The two sides hold different areas
here (the ball's pole face is 1.21 times the plate face under it), so
the run must warn once, naming both patches, that their forces part (by
19 % at the first step).
Work folder: test/runs/stiffPartner/.
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import monitor, projectile, run, testing  # noqa: E402

NAME = "stiffPartner"
N = 8
SPEED = 10
END_TIME = "4e-6"

#: the total momentum's drift allowed over |p0|: about 100 times round-off
MOMENTUM_DRIFT = 1e-12

#: (zone, density, modulus): the plate 1000 times the steel in both
MATERIALS = (("projectile", 7800, 200e9), ("plate", 7.8e6, 2e14))
NU = 0.3


def make_case(root):
    return projectile.elastic_copy(root, "n%d" % N, MATERIALS, NU, END_TIME)


def body():
    root = testing.work_dir(NAME)
    case = make_case(root)
    run.run(["./Allrun", "-n", str(N), "-speed", str(SPEED)], case,
            name="Allrun", env=testing.without_pictures(),
            timeout=testing.RUN_TIMEOUT)

    d = monitor.read_monitor(case)
    E = d["totalEnergy"]
    E0 = E[0]
    growth = np.diff(E).max() / E0
    remainder = np.diff(d["numericalDissipation"]).min() / E0
    py = d["py"]
    drift = np.abs(py - py[0]).max() / abs(py[0])

    contact = np.loadtxt(os.path.join(case, "postProcessing", "contact",
                                      "0", "contact.dat"))
    faces = contact[:, 1]
    touching = np.nonzero(faces > 0)[0]

    (_, rho1, e1), (_, rho2, e2) = MATERIALS
    ratio = np.sqrt(rho2 * e2) / np.sqrt(rho1 * e1)

    with open(os.path.join(case, "log.touchFoam")) as f:
        log = f.read()
    warning = "sides' forces of the contact between bodies"
    warnings = log.count(warning)

    failures = []
    if warnings != 1 or "ballSurface plateTop" not in log:
        failures.append("%d warnings that the two sides' forces part "
                        "(naming ballSurface plateTop), not 1" % warnings)
    failures += projectile.invariant_failures(growth, remainder, drift,
                                              MOMENTUM_DRIFT)
    if not abs(ratio - 1000) < 1e-9:
        failures.append("impedance ratio %.6g, not 1000" % ratio)
    if len(touching) == 0:
        failures.append("the ball never touches the plate")
    elif not faces.max() > faces[touching[0]]:
        failures.append("no face entered the contact after the first ones "
                        "(%d faces throughout)" % faces[touching[0]])

    lines = [
        "%d steps to %s s, impedance ratio %.0f" % (len(E) - 1, END_TIME,
                                                    ratio),
        "contact faces %d at first contact, %d at most"
        % (faces[touching[0]] if len(touching) else 0, faces.max()),
        "largest energy change in a step %+.2e E0, smallest change of the "
        "numerical remainder %+.2e E0" % (growth, remainder),
        "p_y drift %.1e |p0|" % drift,
        "warned once that the two sides' forces part",
    ]
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
