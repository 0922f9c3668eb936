#!/usr/bin/python3
"""The stable step follows the cells' current heights between opposite
faces (src/TOUCH/stableTimeStep).

    /usr/bin/python3 test/cases/stableStep.py

The 4^3 swinging cube's mesh, at rest (uniform cubic cells: every face
has the same reference height h), starts from a uniform deformation
gradient F, and the first step's deltaT (15 digits in the log,
writeControl timeStep so that nothing adjusts it) is divided by the first
step of F = I: the factor on h/Up.  Asserted to 1e-9 against the closed
form min_f min(J, 1)/(J |F^-T N_f|), N_f = e_x, e_y, e_z:

  simple shear      F = I + 0.5 e_x e_y        1/sqrt(1.25) = 0.894427
                    (the smallest principal stretch, the former measure,
                    is 0.780776: the test tells the two apart)
  compression       F = diag(0.8, 1, 1)         0.8
  tension           F = diag(1.1, 1, 1), J > 1  1/1.1 (the volumetric
                    wave speed grows with J)
  rotation          F = R(30 deg about z)       1 (no step lost to a turn)
  rotated shear     R times the simple shear    0.894427 (frame invariant)

and the first step of F = I itself against dt = CFL h/Up, with
Up = sqrt((lambda + 2 mu)/rho) computed here from E, nu and rho of the
case's mechanicalProperties, h = 1/4 and CFL read from fvSolution (E 1.7e7,
nu 0.3, rho 1100, CFL 0.8: 1.38661064313e-3 s; the log's 15 digits agree
to 1e-12; a CFL of 0.79 in this formula fails).

Work folders: test/runs/stableStep/.
"""

import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, run, testing  # noqa: E402

NAME = "stableStep"
TOLERANCE = 1e-9


def rotation_z(degrees):
    a = math.radians(degrees)
    return np.array([[math.cos(a), -math.sin(a), 0.0],
                     [math.sin(a), math.cos(a), 0.0],
                     [0.0, 0.0, 1.0]])


SHEAR = np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])

DEFORMATIONS = [
    ("identity", np.eye(3)),
    ("shear", SHEAR),
    ("compression", np.diag([0.8, 1.0, 1.0])),
    ("tension", np.diag([1.1, 1.0, 1.0])),
    ("rotation", rotation_z(30)),
    ("rotatedShear", rotation_z(30) @ SHEAR),
]


def expected_factor(F):
    """min over the face normals of min(J, 1)/(J |F^-T N|)."""
    J = np.linalg.det(F)
    inverse_transpose = np.linalg.inv(F).T
    return min(min(J, 1.0) / (J * np.linalg.norm(inverse_transpose @ N))
               for N in np.eye(3))


def smallest_stretch(F):
    return math.sqrt(np.linalg.eigvalsh(F.T @ F)[0])


def first_step(root, label, F):
    case = os.path.join(root, label)
    cases.prepare("swingingCube", case, n=4,
                  control={"endTime": 1, "maxSteps": 1,
                           "writeControl": "timeStep",
                           "writeInterval": 1000},
                  initialise=False)
    path = os.path.join(case, "0", "F")
    text = open(path).read()
    value = "uniform (%s)" % " ".join("%.17g" % x for x in F.reshape(9))
    text, n = re.subn(r"internalField\s+uniform\s*\([^)]*\)",
                      "internalField   " + value, text)
    if n != 1:
        raise RuntimeError("no uniform internalField in %s" % path)
    open(path, "w").write(text)
    log = run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    found = re.findall(r"^Time = \S+\s+deltaT = (\S+)", open(log).read(),
                       re.M)
    if not found:
        raise RuntimeError("no 'deltaT =' line in %s" % log)
    return float(found[0])


def closed_form_step(case, h):
    """CFL h/Up from the material entries, not from the solver."""
    mat = cases.material(case)
    E, nu, rho = mat["E"], mat["nu"], mat["rho"]
    mu = E / (2 * (1 + nu))
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    text = open(os.path.join(case, "system", "fvSolution")).read()
    cfl = float(re.search(r"^\s*CFL\s+([^;\s]+)\s*;", text, re.M).group(1))
    return cfl * h / math.sqrt((lam + 2 * mu) / rho)


def body():
    root = testing.work_dir(NAME)
    reference = None
    lines = []
    failures = []
    for label, F in DEFORMATIONS:
        dt = first_step(root, label, F)
        if reference is None:
            reference = dt
            expected = closed_form_step(os.path.join(root, label), 0.25)
            lines.append("F = I: dt %.12e s (CFL h/Up %.12e)"
                         % (dt, expected))
            if abs(dt - expected) > TOLERANCE * expected:
                failures.append("F = I: dt %.15g s against CFL h/Up %.15g"
                                % (dt, expected))
            continue
        factor = dt / reference
        expected = expected_factor(F)
        lines.append("%s %.6f (expected %.6f, smallest stretch %.6f)"
                     % (label, factor, expected, smallest_stretch(F)))
        if abs(factor - expected) > TOLERANCE * expected:
            failures.append("%s: factor %.12f against %.12f"
                            % (label, factor, expected))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
