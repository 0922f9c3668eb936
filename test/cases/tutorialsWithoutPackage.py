#!/usr/bin/python3
"""Every tutorial sets itself up and runs without the project's Python
package, from the initial state of its closed form.

    /usr/bin/python3 test/cases/tutorialsWithoutPackage.py [--steps 3]

Each tutorial is copied and its own ./Allrun run (small -n, a few steps:
maxSteps in system/controlDict, added as text so that the controlDict keeps
its #includeIfPresent of the set-up precision) with bin/python taken off
PYTHONPATH; that the package then cannot be imported is checked first.
spinningCube runs with -parallel 2 as well.  Asserted per tutorial:
  - ./Allrun exits 0 and touchFoam ends (log 'End', the maxSteps time
    written);
  - the log says the state came from the velocity 0/U;
  - every tutorial skips its pictures (and
    plots) with a message;
  - 0/U (and for the swinging cubes 0/F) at every cell equals the closed
    form at the cell centres (the tutorials' set-up) to 1e-12 of its largest value:
    rigid motion v_t + omega x X (spinningCube: v_t = (1 0.5 -0.25) m/s,
    omega = (4 6 8) rad/s), the twisting column's omega x X with
    omega = (0, 105 sin(pi Y/12), 0), the impact velocities (the
    projectile's ball at -50 m/s, its plate at rest), and the swinging
    cube's F = I + grad u(X, 0) with U = 0;
  - the initial-velocity warning: elasticImpact's bar launched at its
    clamped wall gets it naming the patch 'wall', no other tutorial gets
    one (the twisting column's velocity vanishes at its clamped base only
    between the cell centres), and the swinging cube with U = (1 0 0) gets
    it for the symmetricPlane X0 and not for Y0 or Z0.
Then the restart of spinningCube from the written time with U = lm/rho
beside lm, rounded to 12 digits as a write at writePrecision 12 leaves it:
the log says the two agree and lm is used; with U off by 1e-6 the run
stops naming both files.
Work folders: test/runs/tutorialsWithoutPackage/.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import analytic, cases, foamfile, run, testing  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

NAME = "tutorialsWithoutPackage"
TOLERANCE = 1e-12

SWINGING = "swinging cube mode"
#: the equal bars: +0.1 m/s on x < 0 (bar1), -0.1 m/s on x > 0 (bar2)
BARS = "two bars at +-v"
#: the projectile: the ball (y > 0) at -50 m/s along y, the plate at rest
PROJECTILE = "ball onto a plate at rest"

#: (tutorial, Allrun options, closed-form initial velocity or SWINGING,
#:  pictures and plots that must be skipped)
TUTORIALS = [
    ("spinningCube", ["-n", "3"], ((1.0, 0.5, -0.25), (4.0, 6.0, 8.0)),
     True),
    ("spinningCube", ["-n", "3", "-parallel", "2"],
     ((1.0, 0.5, -0.25), (4.0, 6.0, 8.0)), True),
    ("twistingColumn", ["-n", "2"], "twist", True),
    ("swingingCube", ["-n", "3"], SWINGING, True),
    ("unstructuredCube", ["-n", "2"], SWINGING, True),
    ("elasticImpact", ["-n", "10"], ((-0.1, 0.0, 0.0), (0, 0, 0)), True),
    ("taylorImpact", ["-n", "2"], ((0.0, -227.0, 0.0), (0, 0, 0)), True),
    ("barRebound", ["-n", "2"], ((0.0, -150.0, 0.0), (0, 0, 0)), True),
    ("ringImpact", ["-n", "24"], ((0.0, -0.59, 0.0), (0, 0, 0)), True),
    ("torusImpact", ["-n", "4"], ((0.0, -3.0, 0.0), (0, 0, 0)), True),
    ("slidingBlock", ["-n", "2"], ((1.0, 0.0, 0.0), (0, 0, 0)), True),
    ("barCollision", ["-n", "10"], BARS, True),
    ("sphereImpact", ["-n", "2"], ((0.0, -10.0, 0.0), (0, 0, 0)), True),
    ("projectileImpact", ["-n", "2"], PROJECTILE, True),
]


def environment():
    """os.environ with every bin/python entry taken off PYTHONPATH."""
    env = dict(os.environ)
    kept = [p for p in env.get("PYTHONPATH", "").split(os.pathsep)
            if p and not p.rstrip("/").endswith(os.path.join("bin",
                                                             "python"))]
    env["PYTHONPATH"] = os.pathsep.join(kept)
    status = subprocess.call([run.PYTHON, "-c", "import touchfoam"], env=env,
                             stderr=subprocess.DEVNULL)
    if status == 0:
        raise AssertionError("the touchfoam package is importable without "
                             "bin/python on PYTHONPATH: the test would not "
                             "show anything")
    return env


def add_max_steps(case, steps):
    """maxSteps in system/controlDict, written as text (foamDictionary would
    drop the #includeIfPresent of the set-up precision)."""
    path = os.path.join(case, "system", "controlDict")
    with open(path) as f:
        text = f.read()
    text, count = re.subn(r"(\nendTime\s+[^;]+;\n)",
                          r"\1\nmaxSteps        %d;\n" % steps, text,
                          count=1)
    if count != 1:
        raise AssertionError("%s: no endTime entry" % path)
    with open(path, "w") as f:
        f.write(text)


def closed_form(case, form, X):
    """(U, F or None) of the closed form at the cell centres X."""
    if form == SWINGING:
        mat = cases.material(case)
        sol = analytic.SwingingCube(E=mat["E"], nu=mat["nu"], rho=mat["rho"])
        return sol.velocity(X, 0.0), sol.deformation_gradient(X, 0.0)
    if form == BARS:
        U = np.zeros((len(X), 3))
        U[:, 0] = np.where(X[:, 0] < 0, 0.1, -0.1)
        return U, None
    if form == PROJECTILE:
        U = np.zeros((len(X), 3))
        U[:, 1] = np.where(X[:, 1] > 0, -50.0, 0.0)
        return U, None
    if form == "twist":
        return analytic.TwistingColumn(Omega=105.0, L=6.0).velocity(X), None
    translation, omega = form
    return analytic.rigid_velocity(X, translation, omega), None


def relative_error(value, exact):
    scale = max(np.max(np.abs(exact)), 1e-300)
    return float(np.max(np.abs(np.asarray(value, float) - exact)) / scale)


def check(root, env, tutorial, options, form, skips, steps):
    label = tutorial + "".join(options).replace("-", "_")
    case = os.path.join(root, label)
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(run.tutorial_dir(tutorial), case)
    add_max_steps(case, steps)

    with open(os.path.join(case, "log.Allrun"), "w") as log:
        status = subprocess.call(["./Allrun"] + options, cwd=case, env=env,
                                 stdout=log, stderr=subprocess.STDOUT,
                                 timeout=testing.RUN_TIMEOUT)
    with open(os.path.join(case, "log.Allrun")) as f:
        allrun = f.read()
    problems = []
    if status != 0:
        return ["%s: ./Allrun exited %d (see %s/log.Allrun)"
                % (label, status, case)]
    with open(os.path.join(case, "log.touchFoam")) as f:
        solver = f.read()
    if not re.search(r"^End\s*$", solver, re.M):
        problems.append("%s: touchFoam did not end" % label)
    if "initial state: velocity" not in solver:
        problems.append("%s: the log does not say the state came from 0/U"
                        % label)
    if len(run.time_dirs(case)) < 2:
        problems.append("%s: no time written after %d steps" % (label, steps))
    warned = re.findall(r"violates the (\w+) patch (\w+)", solver)
    expected = [("clamped", "wall")] if tutorial == "elasticImpact" else []
    if warned != expected:
        problems.append("%s: initial-velocity warnings %s, expected %s"
                        % (label, warned, expected))
    if skips and "skipped: the touchfoam package" not in allrun:
        problems.append("%s: no message that pictures and plots are skipped"
                        % label)

    m = PolyMesh(case)
    U_exact, F_exact = closed_form(case, form, m.cell_centres)
    U = foamfile.read_field(os.path.join(case, "0", "U")).internal(m.n_cells)
    errors = ["U %.1e" % relative_error(U, U_exact)]
    if form == SWINGING:
        if np.any(np.asarray(U, float) != 0):
            problems.append("%s: the swinging cube's 0/U is not zero" % label)
        F = foamfile.read_field(os.path.join(case, "0", "F")).internal(
            m.n_cells)
        eF = relative_error(np.asarray(F, float).reshape(-1, 3, 3) - np.eye(3),
                            F_exact - np.eye(3))
        errors = ["F - I %.1e" % eF]
        if eF > TOLERANCE:
            problems.append("%s: 0/F - I differs from the closed form by "
                            "%.2e of its largest value" % (label, eF))
    elif relative_error(U, U_exact) > TOLERANCE:
        problems.append("%s: 0/U differs from the closed form by %.2e of "
                        "its largest value" % (label, relative_error(U, U_exact)))
    print("  %-34s %5d cells, %s" % (label, m.n_cells, ", ".join(errors)))
    return problems


def solver_log(case, env, name):
    """Run touchFoam in case; (exit status, log text)."""
    path = os.path.join(case, "log." + name)
    with open(path, "w") as log:
        status = subprocess.call(["touchFoam"], cwd=case, env=env, stdout=log,
                                 stderr=subprocess.STDOUT,
                                 timeout=testing.RUN_TIMEOUT)
    with open(path) as f:
        return status, f.read()


def check_symmetric_warning(root, env):
    """The swinging cube launched along x through its symmetricPlane X0."""
    case = os.path.join(root, "swingingCube_launched")
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(os.path.join(root, "swingingCube_n3"), case)
    for d in run.time_dirs(case).values():
        if d != "0":
            shutil.rmtree(os.path.join(case, d))
    path = os.path.join(case, "0", "U")
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(re.sub(r"internalField\s+[^;]*;",
                       "internalField uniform (1 0 0);", text))
    status, log = solver_log(case, env, "touchFoam")
    warned = re.findall(r"violates the (\w+) patch (\w+)", log)
    if status != 0 or warned != [("symmetricPlane", "X0")]:
        return ["swinging cube with U = (1 0 0): exit %d, warnings %s, "
                "expected symmetricPlane X0 only" % (status, warned)]
    print("  %-34s warning for symmetricPlane X0 only" % "U = (1 0 0)")
    return []


def check_restart(root, env, steps):
    """Restart with U = lm/rho beside lm: agreed, lm used; U off: refused."""
    base = os.path.join(root, "spinningCube_n3")
    problems = []
    for label, factor in (("restartAgree", 1.0), ("restartDisagree",
                                                  1 + 1e-6)):
        case = os.path.join(root, label)
        if os.path.exists(case):
            shutil.rmtree(case)
        shutil.copytree(base, case)
        times = run.time_dirs(case)
        mid = os.path.join(case, times[max(times)])
        lm = foamfile.FoamField(os.path.join(mid, "lm"))
        rho = cases.material(case)["rho"]
        U = np.asarray(lm.values, float) / rho * factor
        text = open(os.path.join(mid, "lm")).read()
        body = "\n".join("(%.12g %.12g %.12g)" % tuple(v) for v in U)
        text = re.sub(r"object\s+lm;", "object U;", text)
        text = re.sub(r"dimensions\s+\[[^]]*\];",
                      "dimensions [0 1 -1 0 0 0 0];", text)
        text = re.sub(r"internalField\s+nonuniform\s+List<vector>\s*\d+\s*"
                      r"\((.|\n)*?\n\)\s*;",
                      "internalField nonuniform List<vector> %d\n(\n%s\n);"
                      % (len(U), body), text, count=1)
        with open(os.path.join(mid, "U"), "w") as f:
            f.write(text)
        with open(os.path.join(case, "system", "controlDict")) as f:
            control = f.read()
        with open(os.path.join(case, "system", "controlDict"), "w") as f:
            f.write(re.sub(r"maxSteps\s+\d+;", "maxSteps %d;" % (2 * steps),
                           control))
        status, log = solver_log(case, env, "touchFoam.restart")
        if factor == 1.0:
            m = re.search(r"agrees \(max \|lm - rho U\|/max \|lm\| = "
                          r"(\S+)\), lm is used", log)
            if status != 0 or not m:
                problems.append("%s: exit %d, no 'agrees ... lm is used' "
                                "line" % (label, status))
            else:
                print("  %-34s lm used, U agrees to %s" % (label, m.group(1)))
        else:
            if status == 0 or "disagree" not in log or "Remove one" not in log:
                problems.append("%s: U off by 1e-6 was not refused" % label)
            else:
                print("  %-34s refused: both files named" % label)
    return problems


def body(args):
    root = testing.work_dir(NAME)
    env = environment()
    problems = []
    for tutorial, options, form, skips in TUTORIALS:
        problems += check(root, env, tutorial, options, form, skips,
                          args.steps)
    problems += check_symmetric_warning(root, env)
    problems += check_restart(root, env, args.steps)
    if problems:
        raise AssertionError("; ".join(problems))
    return ("%d runs of %d tutorials set up and ran without the package, "
            "initial state = closed form to %.0e; initial-velocity warnings "
            "where due only; restart with U beside lm agrees, a 1e-6 "
            "difference is refused"
            % (len(TUTORIALS), len(set(t[0] for t in TUTORIALS)), TOLERANCE))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=3)
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args)))
