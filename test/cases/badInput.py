#!/usr/bin/python3
"""Bad input stops touchFoam with an error naming the file, the entry and
the valid choices, and writes nothing.

    /usr/bin/python3 test/cases/badInput.py

On a 4^3 swinging cube, one mistake at a time:
  - a misspelt model in constant/mechanicalProperties,
  - nu = 0.5,
  - a misspelt reconstruction scheme and limiter in system/fvSolution TOUCH,
  - CFL = 1.5,
  - a boundary condition of the initial velocity 0/U that is not a solid
    one (fixedValue),
  - a missing TOUCH dictionary entry (riemannSolver),
  - a misspelt keyword in an entry of 0/U: 'tracton' in a traction entry
    (the cube has none: its skewSymmetricPlane patches become one),
    'velocty' in a prescribedVelocity entry and in a symmetricPlane entry;
    the error lists the condition's valid keywords,
  - a misspelt Function1 type of a prescribed velocity (tabel), a pressure
    (sinus) and a rigid wall's velocity (tabel): OpenFOAM's error names the
    entry and the patch and lists the valid types; a rigid wall's velocity
    OpenFOAM cannot integrate (sine) is refused naming the valid ones,
  - a misspelt F update (FUpdate compatibel) and time scheme (timeScheme
    RK4) in system/fvSolution TOUCH,
  - model vonMisesPlastic with yieldStress 0, and with hardeningModulus -1,
  - a misspelt nodalAveraging (pressur), and nodalAveraging deformation
    with vonMisesPlastic (a law with state),
  - a misspelt jumpShare (quadratc); jumpShare, limiter and yieldStress
    written beside their owner's <model>Coeffs sub-dictionary (their place
    before 2026-12-04: the error says where they moved); vonMisesPlastic
    without vonMisesPlasticCoeffs,
  - a misspelt symmetricPlanes (mirorr),
  - 0/U with the dimensions of momentum, a 0/lm beside 0/U that disagrees
    with rho U, and neither 0/U nor 0/lm,
  - patch types of the mesh the solid cannot use, set in
    constant/polyMesh/boundary with 0/U left as it is (OpenFOAM itself
    would stop reading it, without saying what to use): symmetryPlane,
    symmetry, cyclic and cyclicAMI pairs (X0 with X1), a wedge pair (a
    2.5 degree wedge meshed by blockMesh); and symmetryPlane with 0/U
    saying symmetryPlane too (the OpenFOAM way); the error names the
    patch, its type, the boundary file and the solid conditions,
  - a 2D mesh (empty front and back) two cells thick.
Each run must exit non-zero without a signal (the status of a run killed
by one is negative, 128 + signal through a shell), its log must contain
every expected word, and no time folder may be written.  Every mistake is
tried; the failure names
all that were not refused properly.
Work folders: test/runs/badInput/.
"""

import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, run, testing  # noqa: E402

NAME = "badInput"

# (label, file, sed-like (pattern, replacement), words the error must name)
MISTAKES = [
    ("model", "constant/mechanicalProperties",
     (r"model\s+\w+;", "model neoHooke;"),
     ["neoHooke", "mechanicalProperties", "linearElastic", "neoHookean"]),
    ("nu", "constant/mechanicalProperties",
     (r"\nnu\s+[0-9.]+;", "\nnu 0.5;"),
     ["'nu'", "mechanicalProperties", "< 0.5"]),
    ("reconstruction", "system/fvSolution",
     (r"reconstruction\s+\w+;", "reconstruction linar;"),
     ["linar", "fvSolution", "firstOrder", "limitedLinear"]),
    ("limiter", "system/fvSolution",
     (r"limiter\s+\w+;", "limiter minmod;"),
     ["minmod", "BarthJespersen", "Venkatakrishnan"]),
    ("CFL", "system/fvSolution",
     (r"CFL\s+[0-9.]+;", "CFL 1.5;"),
     ["'CFL'", "fvSolution", "0 < CFL <= 1"]),
    ("riemannSolver", "system/fvSolution",
     (r"riemannSolver\s+\w+;", ""),
     ["riemannSolver", "fvSolution"]),
    ("boundary", "0/U",
     (r"type\s+symmetricPlane;", "type fixedValue;"),
     ["fixedValue", "0/U", "symmetricPlane", "traction"]),
    ("tractionKeyword", "0/U",
     (r"type\s+skewSymmetricPlane;",
      "type traction; tracton uniform (1e5 0 0);"),
     ["tracton", "0/U", "traction", "pressure"]),
    ("prescribedVelocityKeyword", "0/U",
     (r"type\s+symmetricPlane;",
      "type prescribedVelocity; velocty uniform (0 0 0);"),
     ["velocty", "0/U", "velocity"]),
    ("velocityFunction1", "0/U",
     (r"type\s+symmetricPlane;",
      "type prescribedVelocity; velocity tabel ((0 (0 0 0)) (1 (1 0 0)));"),
     ["tabel", "velocity", "0/U", "X0", "table", "tableFile", "sine"]),
    ("pressureFunction1", "0/U",
     (r"type\s+skewSymmetricPlane;",
      "type traction; pressure sinus; pressureCoeffs { frequency 1; }"),
     ["sinus", "pressure", "0/U", "X1", "table", "sine", "square"]),
    ("wallFunction1", "0/U",
     (r"type\s+symmetricPlane;",
      "type rigidWall; point (0 0 0); normal (1 0 0); "
      "velocity tabel ((0 (0 0 0)) (1 (1 0 0)));"),
     ["tabel", "velocity", "0/U", "X0", "table", "polynomial"]),
    ("wallVelocityIntegral", "0/U",
     (r"type\s+symmetricPlane;",
      "type rigidWall; point (0 0 0); normal (1 0 0); velocity sine; "
      "velocityCoeffs { frequency 1; amplitude 1; scale (1 0 0); "
      "level (0 0 0); }"),
     ["'sine'", "velocity", "0/U", "X0", "constant", "table", "csvFile"]),
    ("symmetricPlaneKeyword", "0/U",
     (r"type\s+symmetricPlane;",
      "type symmetricPlane; velocty uniform (0 0 0);"),
     ["velocty", "0/U", "patchType"]),
    ("velocityDimensions", "0/U",
     (r"dimensions\s+\[0 1 -1 0 0 0 0\];", "dimensions [1 -2 -1 0 0 0 0];"),
     ["0/U", "[1 -2 -1 0 0 0 0]", "velocity", "[0 1 -1 0 0 0 0]"]),
    # 0/lm beside 0/U, rho U = 0 but lm = (1 0 0): which is meant?
    ("momentumAndVelocity", "0/lm",
     (r"^", "COPY 0/U\n"),
     ["0/lm", "0/U", "disagree", "Remove one"]),
    ("noInitialState", "0/U",
     (r"^", "REMOVE\n"),
     ["0/U", "0/lm", "neither"]),
    ("FUpdate", "system/fvSolution",
     (r"FUpdate\s+\w+;", "FUpdate compatibel;"),
     ["compatibel", "fvSolution", "compatible", "constrained", "plain"]),
    ("timeScheme", "system/fvSolution",
     (r"(CFL\s+[0-9.]+;)", r"\1\n    timeScheme RK4;"),
     ["RK4", "fvSolution", "RK2", "RK3"]),
    ("yieldStress", "constant/mechanicalProperties",
     (r"model\s+\w+;",
      "model vonMisesPlastic;\n"
      "vonMisesPlasticCoeffs { yieldStress 0; hardeningModulus 1e5; }"),
     ["'yieldStress'", "mechanicalProperties", "0 < yieldStress"]),
    ("hardeningModulus", "constant/mechanicalProperties",
     (r"model\s+\w+;",
      "model vonMisesPlastic;\n"
      "vonMisesPlasticCoeffs { yieldStress 1e4; hardeningModulus -1; }"),
     ["'hardeningModulus'", "mechanicalProperties",
      "0 <= hardeningModulus"]),
    ("nodalAveraging", "system/fvSolution",
     (r"(CFL\s+[0-9.]+;)", r"\1\n    nodalAveraging pressur;"),
     ["pressur", "fvSolution", "off", "deformation", "pressure"]),
    ("nodalAveragingLaw",
     ["constant/mechanicalProperties", "system/fvSolution"],
     [(r"model\s+\w+;",
       "model vonMisesPlastic;\n"
       "vonMisesPlasticCoeffs { yieldStress 1e4; hardeningModulus 0; }"),
      (r"(CFL\s+[0-9.]+;)", r"\1\n    nodalAveraging deformation;")],
     ["'nodalAveraging deformation'", "fvSolution", "vonMisesPlastic",
      "nodalAveraging off"]),
    ("jumpShare", "system/fvSolution",
     (r"(CFL\s+[0-9.]+;)",
      r"\1\n    compatibleCoeffs { jumpShare quadratc; }"),
     ["quadratc", "fvSolution", "quadratic", "linear"]),
    # A model's own entries left where they were before 2026-12-04
    ("jumpShareMoved", "system/fvSolution",
     (r"(CFL\s+[0-9.]+;)", r"\1\n    jumpShare linear;"),
     ["'jumpShare'", "fvSolution", "compatibleCoeffs"]),
    ("limiterMoved", "system/fvSolution",
     (r"(CFL\s+[0-9.]+;)", r"\1\n    limiter BarthJespersen;"),
     ["'limiter'", "fvSolution", "limitedLinearCoeffs"]),
    ("yieldStressMoved", "constant/mechanicalProperties",
     (r"model\s+\w+;",
      "model vonMisesPlastic;\nyieldStress 1e4;\n"
      "vonMisesPlasticCoeffs { yieldStress 1e4; hardeningModulus 0; }"),
     ["'yieldStress'", "mechanicalProperties", "vonMisesPlasticCoeffs"]),
    ("lawCoeffsMissing", "constant/mechanicalProperties",
     (r"model\s+\w+;", "model vonMisesPlastic;"),
     ["vonMisesPlasticCoeffs", "mechanicalProperties", "yieldStress",
      "hardeningModulus"]),
    ("symmetricPlanes", "system/fvSolution",
     (r"symmetricPlanes\s+\w+;", "symmetricPlanes mirorr;"),
     ["mirorr", "fvSolution", "oneSided", "mirror"]),
]


# A 2.5 degree wedge about the x axis, 1 x 0.9 radially (not through the
# axis), in place of the unit cube's vertices, its Z0 and Z1 the wedge planes
WEDGE_VERTICES = """vertices
(
    (0 0.1 -0.0043661) (1 0.1 -0.0043661) (1 1 -0.043661) (0 1 -0.043661)
    (0 0.1 0.0043661) (1 0.1 0.0043661) (1 1 0.043661) (0 1 0.043661)
);"""


def boundary_type(patches, entries):
    """Edits of constant/polyMesh/boundary giving each patch the entries
    (its type and what the type needs)."""
    return [(r"(\n    %s\n    \{\n        type\s+)patch;" % patch, r"\g<1>" + entries
             % {"other": other}) for patch, other in patches]


BOUNDARY = "constant/polyMesh/boundary"
SOLID_TYPES = ["symmetricPlane", "skewSymmetricPlane", "traction"]

# (label, files, edits, words, commands to run after the edits)
PATCH_TYPES = [
    ("symmetryPlanePatch", BOUNDARY,
     boundary_type([("X0", "")], "symmetryPlane;"),
     ["X0", "'symmetryPlane'", "boundary", "symmetricPlane", "U"]
     + SOLID_TYPES, []),
    ("symmetryPlaneBoth", [BOUNDARY, "0/U", "0/U"],
     boundary_type([("X0", "")], "symmetryPlane;")
     + [(r'"\(X0\|Y0\|Z0\)"', '"(Y0|Z0)"'),
        (r"boundaryField\s*\{",
         "boundaryField\n{\n    X0 { type symmetryPlane; }")],
     ["X0", "'symmetryPlane'", "boundary"] + SOLID_TYPES, []),
    ("symmetryPatch", BOUNDARY,
     boundary_type([("Y1", "")], "symmetry;"),
     ["Y1", "'symmetry'", "boundary", "symmetricPlane"] + SOLID_TYPES, []),
    ("cyclicPatch", [BOUNDARY, BOUNDARY],
     boundary_type([("X0", "X1"), ("X1", "X0")],
                   "cyclic; neighbourPatch %(other)s;"),
     ["X0", "'cyclic'", "boundary", "Periodic"] + SOLID_TYPES, []),
    ("cyclicAMIPatch", [BOUNDARY, BOUNDARY],
     boundary_type([("X0", "X1"), ("X1", "X0")],
                   "cyclicAMI; neighbourPatch %(other)s;"),
     ["X0", "'cyclicAMI'", "boundary", "Periodic"] + SOLID_TYPES, []),
    ("wedgePatch", ["system/blockMeshDict"] * 4,
     [(r"(?s)vertices\s*\(.*?\);", WEDGE_VERTICES),
      (r"\(\$N \$N \$N\)", "($N $N 1)"),
      (r"Z0 \{ type patch;", "Z0 { type wedge;"),
      (r"Z1 \{ type patch;", "Z1 { type wedge;")],
     ["Z0", "'wedge'", "boundary", "Axisymmetric", "symmetricPlane",
      "sector"] + SOLID_TYPES, [["blockMesh"]]),
    ("emptyTwoCells", ["system/blockMeshDict"] * 3,
     [(r"\(\$N \$N \$N\)", "($N $N 2)"),
      (r"Z0 \{ type patch;", "Z0 { type empty;"),
      (r"Z1 \{ type patch;", "Z1 { type empty;")],
     ["empty", "one cell thick", "boundary"],
     [["blockMesh"], ["cp", "0.orig/F", "0/F"], ["setExprFields"]]),
]


def check(root, label, path, edit, words, commands=()):
    # limitedLinear, so that the limiter is read
    case = cases.prepare("swingingCube", os.path.join(root, label), n=4,
                         touch={"reconstruction": "limitedLinear"})
    # One file and one edit, or a list of files with an edit each
    paths = path if isinstance(path, list) else [path]
    edits = edit if isinstance(edit, list) else [edit]
    for one_path, one_edit in zip(paths, edits):
        target = os.path.join(case, one_path)
        if one_edit[1] == "REMOVE\n":
            os.remove(target)
            continue
        if one_edit[1].startswith("COPY "):
            # A momentum field made from the velocity file: lm = (1 0 0)
            with open(os.path.join(case, one_edit[1].split()[1])) as f:
                text = f.read()
            text = re.sub(r"object\s+U;", "object lm;", text)
            text = re.sub(r"dimensions\s+\[[^]]*\];",
                          "dimensions [1 -2 -1 0 0 0 0];", text)
            text = re.sub(r"internalField\s+[^;]*;",
                          "internalField uniform (1 0 0);", text)
            with open(target, "w") as f:
                f.write(text)
            continue
        with open(target) as f:
            text = f.read()
        new, count = re.subn(one_edit[0], one_edit[1], text, count=1)
        if count != 1:
            raise AssertionError("%s: could not make the mistake in %s"
                                 % (label, one_path))
        with open(target, "w") as f:
            f.write(new)
    for command in commands:
        run.run(command, case)
    log = os.path.join(case, "log.touchFoam")
    with open(log, "w") as f:
        status = subprocess.call(["touchFoam"], cwd=case, stdout=f,
                                 stderr=subprocess.STDOUT)
    with open(log) as f:
        output = f.read()
    if status == 0:
        return "%s: touchFoam accepted the mistake (see %s)" % (label, log)
    if status < 0 or status > 128 or "sigSegv" in output \
            or "printStack" in output:
        return "%s: touchFoam stopped with status %d or a stack trace, " \
            "not an error message (see %s)" % (label, status, log)
    missing = [w for w in words if w not in output]
    if missing:
        return "%s: the error does not name %s (see %s)" % (
            label, ", ".join(missing), log)
    written = [d for d in os.listdir(case)
               if re.match(r"^[0-9.e+-]+$", d) and d != "0"]
    if written:
        return "%s: wrote %s" % (label, written)
    return None


def body():
    root = testing.work_dir(NAME)
    refused, failures = [], []
    for mistake in MISTAKES + PATCH_TYPES:
        failure = check(root, *mistake)
        print("  %-26s %s" % (mistake[0], failure or "refused"))
        if failure:
            failures.append(failure)
        else:
            refused.append(mistake[0])
    if failures:
        raise AssertionError("%d of %d mistakes not refused properly: %s"
                             % (len(failures),
                                len(MISTAKES) + len(PATCH_TYPES),
                                "; ".join(failures)))
    return "%d mistakes refused with file, entry and valid choices: %s" % (
        len(refused), " ".join(refused))


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
