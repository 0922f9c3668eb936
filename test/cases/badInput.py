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
  - a 2D mesh (empty front and back) two cells thick;
  - the corpus (CORPUS, PARALLEL; listed in test/badInputs.md): every
    entry of the TOUCH dictionary and its Coeffs sub-dictionaries, of
    every law in constant/mechanicalProperties, of the solid boundary
    conditions, of solidMonitor and touchFoam's controlDict entries
    (misspelt: the error names the nearest valid name; out of range;
    missing; of the wrong type; used by another model), fields of the
    wrong class or size, a patch missing from 0/U, NaN and 1e999 in an
    initial field, an inverted initial F, an inverted and a collapsed mesh,
    a time folder from another mesh, truncated and unreadable files, and a
    case decomposed on 2 run with a processor folder missing or an extra
    one (mpirun, 2 ranks).
Each run must exit non-zero without a signal (the status of a run killed
by one is negative, 128 + signal through a shell), its log must contain
every expected word, no time folder may be written and the files of 0/
must be unchanged.  Every mistake is
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


# ---------------------------------------------------------------------------
# The corpus beyond the mistakes above: every entry of the laws, the TOUCH
# dictionary and its Coeffs, the solid conditions, solidMonitor and
# controlDict; meshes, fields, time folders, decomposed cases, files.
# (label, files, edits, words): an edit is (pattern, replacement) or a
# function of the case folder.

def TOUCH_ADD(text):
    """An edit adding text to system/fvSolution TOUCH"""
    return (r"(CFL\s+[0-9.]+;)", r"\1\n    " + text)


def LAW(text):
    """An edit replacing the law's model entry by text"""
    return (r"model\s+\w+;", text)


def U_PATCH(text):
    """An edit replacing the X0 condition of 0/U (symmetricPlane)"""
    return (r"type\s+symmetricPlane;", text)


def rewrite_points(change):
    """An edit of constant/polyMesh/points: every point (x y z) becomes
    change(x, y, z)"""
    def edit(case):
        path = os.path.join(case, "constant", "polyMesh", "points")
        with open(path) as f:
            text = f.read()
        head, sep, body = text.partition("\n(\n")

        def one(m):
            return "(%.12g %.12g %.12g)" % change(*map(float, m.groups()))
        body = re.sub(r"\(([-0-9.e+]+) ([-0-9.e+]+) ([-0-9.e+]+)\)", one, body)
        with open(path, "w") as f:
            f.write(head + sep + body)
    return edit


def write_file(relative, content, mode="w"):
    def edit(case):
        path = os.path.join(case, relative)
        if os.path.isdir(path):
            shutil.rmtree(path)
        elif os.path.exists(path):
            os.remove(path)
        if content is None:
            os.makedirs(path)
            return
        with open(path, mode) as f:
            f.write(content)
    return edit


def truncate(relative, fraction):
    def edit(case):
        path = os.path.join(case, relative)
        with open(path) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(text[:int(len(text)*fraction)])
    return edit


def other_mesh_time(case):
    """A time folder 0.001 holding lm and F of a 2 x 2 x 2 mesh (8 cells)
    in the 4 x 4 x 4 case: latestTime starts from it"""
    folder = os.path.join(case, "0.001")
    os.makedirs(folder)
    for name, cls, dims, value in [
            ("lm", "volVectorField", "[1 -2 -1 0 0 0 0]", "(0 0 0)"),
            ("F", "volTensorField", "[0 0 0 0 0 0 0]",
             "(1 0 0 0 1 0 0 0 1)")]:
        with open(os.path.join(case, "0", "U")) as f:
            text = f.read()
        text = re.sub(r"class\s+\w+;", "class %s;" % cls, text)
        text = re.sub(r"object\s+U;", "object %s;" % name, text)
        text = re.sub(r"dimensions\s+\[[^]]*\];", "dimensions %s;" % dims,
                      text)
        text = re.sub(r"internalField\s+[^;]*;",
                      "internalField nonuniform List<%s> 8(%s);"
                      % ("vector" if name == "lm" else "tensor",
                         " ".join([value]*8)), text)
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)


def processors(count, remove=None):
    """Decompose on 2 ranks (decomposePar), then add processor folders up
    to count or remove one"""
    def edit(case):
        dictionary = os.path.join(case, "system", "decomposeParDict")
        with open(dictionary) as f:
            text = f.read()
        text = re.sub(r"numberOfSubdomains\s+\d+;", "numberOfSubdomains 2;",
                      text)
        text = re.sub(r"method\s+\w+;", "method scotch;", text)
        with open(dictionary, "w") as f:
            f.write(text)
        run.run(["decomposePar", "-force"], case)
        for i in range(2, count):
            shutil.copytree(os.path.join(case, "processor1"),
                            os.path.join(case, "processor%d" % i))
        if remove is not None:
            shutil.rmtree(os.path.join(case, "processor%d" % remove))
    return edit


FV = "system/fvSolution"
MP = "constant/mechanicalProperties"
CD = "system/controlDict"
PLASTIC = "model vonMisesPlastic;\nvonMisesPlasticCoeffs { %s }"

CORPUS = [
    # system/fvSolution TOUCH
    ("TOUCHtimeSchem", FV, TOUCH_ADD("timeSchem RK3;"),
     ["'timeSchem'", "fvSolution", "did you mean 'timeScheme'",
      "nodalAveraging"]),
    ("TOUCHnodalAverging", FV, TOUCH_ADD("nodalAverging pressure;"),
     ["'nodalAverging'", "fvSolution", "did you mean 'nodalAveraging'"]),
    ("TOUCHCFlMisspelt", FV, (r"CFL(\s+[0-9.]+;)", r"CFl\1"),
     ["'CFl'", "fvSolution", "did you mean 'CFL'"]),
    ("TOUCHCFLzero", FV, (r"CFL\s+[0-9.]+;", "CFL 0;"),
     ["'CFL'", "fvSolution", "0 < CFL <= 1"]),
    ("TOUCHCFLnegative", FV, (r"CFL\s+[0-9.]+;", "CFL -0.3;"),
     ["'CFL'", "fvSolution", "0 < CFL <= 1"]),
    ("TOUCHCFLword", FV, (r"CFL\s+[0-9.]+;", "CFL fast;"),
     ["fast", "fvSolution", "scalar"]),
    ("TOUCHriemannSolver", FV, (r"riemannSolver\s+\w+;",
                                "riemannSolver HLLC;"),
     ["HLLC", "fvSolution", "acoustic"]),
    ("TOUCHangularMomentum", FV,
     (r"angularMomentumPreservation\s+\w+;",
      "angularMomentumPreservation maybe;"),
     ["maybe", "fvSolution", "angularMomentumPreservation"]),
    ("TOUCHangularMomentumMissing", FV,
     (r"angularMomentumPreservation\s+\w+;", ""),
     ["angularMomentumPreservation", "fvSolution"]),
    ("TOUCHreconstructionMissing", FV, (r"reconstruction\s+\w+;", ""),
     ["reconstruction", "fvSolution"]),
    ("TOUCHmissing", FV, (r"TOUCH\s*\{", "TOUCHE\n{"),
     ["TOUCH", "fvSolution"]),
    ("TOUCHsymmetricPlanesNumber", FV,
     (r"symmetricPlanes\s+\w+;", "symmetricPlanes 1;"),
     ["symmetricPlanes", "fvSolution"]),
    ("compatibleCoeffsUpwinding", FV,
     TOUCH_ADD("compatibleCoeffs { pointUpwinding -1; }"),
     ["'pointUpwinding'", "fvSolution", "0 <= pointUpwinding"]),
    ("compatibleCoeffsMisspelt", FV,
     TOUCH_ADD("compatibleCoeffs { pointUpwindng 1; }"),
     ["'pointUpwindng'", "compatibleCoeffs", "did you mean 'pointUpwinding'",
      "jumpShare", "pointLimiter"]),
    ("compatibleCoeffsNotDict", FV, TOUCH_ADD("compatibleCoeffs 1;"),
     ["compatibleCoeffs", "fvSolution", "not a sub-dictionary"]),
    ("limitedLinearCoeffsEmpty", FV,
     (r"limitedLinearCoeffs\s*\{[^}]*\}", "limitedLinearCoeffs { }"),
     ["limiter", "limitedLinearCoeffs"]),
    ("limitedLinearCoeffsMisspelt", FV,
     (r"limiter(\s+\w+;)", r"limiter\1 limitr Venkatakrishnan;"),
     ["'limitr'", "limitedLinearCoeffs", "did you mean 'limiter'"]),
    ("fvSolutionTruncated", FV, truncate(FV, 0.7),
     ["fvSolution"]),
    # constant/mechanicalProperties: every entry of every law
    ("lawModelMissing", MP, LAW(""), ["model", "mechanicalProperties"]),
    ("lawEnegative", MP, (r"\nE\s+[0-9.e+]+;", "\nE -1e7;"),
     ["'E'", "mechanicalProperties", "0 < E"]),
    ("lawEmissing", MP, (r"\nE\s+[0-9.e+]+;", "\n"),
     ["'E'", "mechanicalProperties"]),
    ("lawEword", MP, (r"\nE\s+[0-9.e+]+;", "\nE stiff;"),
     ["stiff", "mechanicalProperties", "scalar"]),
    ("lawRhoZero", MP, (r"\nrho\s+[0-9.e+]+;", "\nrho 0;"),
     ["'rho'", "mechanicalProperties", "0 < rho"]),
    ("lawRhoMissing", MP, (r"\nrho\s+[0-9.e+]+;", "\n"),
     ["'rho'", "mechanicalProperties"]),
    ("lawNuMinusOne", MP, (r"\nnu\s+[0-9.]+;", "\nnu -1;"),
     ["'nu'", "mechanicalProperties", "-1 < nu < 0.5"]),
    ("lawNuMissing", MP, (r"\nnu\s+[0-9.]+;", "\n"),
     ["'nu'", "mechanicalProperties"]),
    ("lawUnknownEntry", MP, LAW("model linearElastic;\ndensity 1100;"),
     ["'density'", "mechanicalProperties", "rho", "Valid entries"]),
    ("neoHookeanYieldStress", MP,
     LAW("model neoHookean;\nyieldStress 1e6;"),
     ["'yieldStress'", "mechanicalProperties", "vonMisesPlasticCoeffs"]),
    ("linearElasticPlasticCoeffs", MP,
     LAW("model linearElastic;\n"
         "vonMisesPlasticCoeffs { yieldStress 1e6; hardeningModulus 0; }"),
     ["'vonMisesPlasticCoeffs'", "mechanicalProperties", "Valid entries"]),
    ("plasticYieldStressMisspelt", MP,
     LAW(PLASTIC % "yieldStres 1e6; yieldStress 1e6; hardeningModulus 0;"),
     ["'yieldStres'", "vonMisesPlasticCoeffs", "did you mean 'yieldStress'"]),
    ("plasticYieldStressMissing", MP,
     LAW(PLASTIC % "hardeningModulus 0;"),
     ["yieldStress", "vonMisesPlasticCoeffs"]),
    ("plasticHardeningMissing", MP,
     LAW(PLASTIC % "yieldStress 1e6;"),
     ["hardeningModulus", "vonMisesPlasticCoeffs"]),
    ("plasticYieldStressMeasure", MP,
     LAW(PLASTIC % "yieldStress 1e6; hardeningModulus 0; "
         "yieldStressMeasure vonMises;"),
     ["vonMises", "yieldStressMeasure", "Kirchhoff", "Cauchy"]),
    ("mechanicalPropertiesGarbage", MP,
     write_file(MP, "\x00\x01\x02\xff\xfe binary \x00", "w"),
     ["mechanicalProperties"]),
    ("mechanicalPropertiesFolder", MP, write_file(MP, None),
     ["mechanicalProperties"]),
    ("mechanicalPropertiesTruncated", MP, truncate(MP, 0.8),
     ["mechanicalProperties"]),
    # the solid boundary conditions of 0/U
    ("typeMisspelt", "0/U", U_PATCH("type symetricPlane;"),
     ["'symetricPlane'", "0/U", "did you mean 'symmetricPlane'", "clamped",
      "rigidWall", "traction"]),
    ("patchMissing", "0/U", (r'"\(X0\|Y0\|Z0\)"', '"(Y0|Z0)"'),
     ["X0", "0/U", "no entry", "symmetricPlane"]),
    ("typeMissing", "0/U", U_PATCH("value uniform (0 0 0);"),
     ["type", "0/U"]),
    ("clampedKeyword", "0/U", U_PATCH("type clamped; velocity (0 0 0);"),
     ["'velocity'", "0/U", "clamped"]),
    ("tractionPresure", "0/U", U_PATCH("type traction; presure uniform 1;"),
     ["'presure'", "0/U", "did you mean 'pressure'"]),
    ("prescribedVelocityMissing", "0/U", U_PATCH("type prescribedVelocity;"),
     ["velocity", "0/U", "X0"]),
    ("rigidWallNoNormal", "0/U", U_PATCH("type rigidWall; point (0 0 0);"),
     ["normal", "0/U", "X0"]),
    ("rigidWallZeroNormal", "0/U",
     U_PATCH("type rigidWall; point (0 0 0); normal (0 0 0);"),
     ["normal", "0/U", "X0"]),
    ("rigidWallNormalScalar", "0/U",
     U_PATCH("type rigidWall; point (0 0 0); normal 1;"),
     ["normal", "0/U"]),
    ("rigidWallPointMissing", "0/U",
     U_PATCH("type rigidWall; normal (1 0 0);"),
     ["point", "0/U", "X0"]),
    # the contact issue's entries: friction, touching, body contact, gravity
    ("frictionType", "0/U",
     U_PATCH("type rigidWall; point (0 0 0); normal (1 0 0); friction "
             "{ type coulom; muStatic 0.4; muKinetic 0.3; }"),
     ["coulom", "coulomb", "frictionless"]),
    ("frictionKineticAboveStatic", "0/U",
     U_PATCH("type rigidWall; point (0 0 0); normal (1 0 0); friction "
             "{ type coulomb; muStatic 0.2; muKinetic 0.3; }"),
     ["muKinetic", "muStatic"]),
    ("frictionNegative", "0/U",
     U_PATCH("type rigidWall; point (0 0 0); normal (1 0 0); friction "
             "{ type coulomb; muStatic -0.1; muKinetic 0; }"),
     ["muStatic"]),
    ("wallTouching", "0/U",
     U_PATCH("type rigidWall; point (0 0 0); normal (1 0 0); "
             "touching lowest;"),
     ["touching", "faceMean", "lowestFreePoint"]),
    ("bodyContactPartner", "0/U",
     U_PATCH("type bodyContact; patches (X1);"),
     ["patches", "X1", "not a bodyContact patch"]),
    ("bodyContactFrictionType", "0/U",
     U_PATCH("type bodyContact; friction "
             "{ type coulom; muStatic 0.4; muKinetic 0.3; }"),
     ["coulom", "coulomb", "frictionless"]),
    ("bodyContactFrictionKinetic", "0/U",
     U_PATCH("type bodyContact; friction "
             "{ type coulomb; muStatic 0.2; muKinetic 0.3; }"),
     ["muKinetic", "muStatic"]),
    ("bodyContactFrictionMisspelt", "0/U",
     U_PATCH("type bodyContact; friction "
             "{ type coulomb; muStatic 0.3; muKinetc 0.3; }"),
     ["muKinetc", "coulomb", "did you mean 'muKinetic'"]),
    ("bodyContactFrictionScalar", "0/U",
     U_PATCH("type bodyContact; friction 0.3;"),
     ["friction", "sub-dictionary", "coulomb"]),
    # X0, Y0, Z0 with friction, X1, Y1, Z1 without
    ("bodyContactFrictionDiffers", ["0/U", "0/U"],
     [U_PATCH("type bodyContact; friction "
              "{ type coulomb; muStatic 0.3; muKinetic 0.3; }"),
      (r"type\s+skewSymmetricPlane;", "type bodyContact;")],
     ["0/U", "different 'friction'", "the same friction"]),
    # (the swinging cube's update is compatible)
    ("bodyContactFrictionCompatible", "0/U",
     U_PATCH("type bodyContact; friction "
             "{ type coulomb; muStatic 0.3; muKinetic 0.3; }"),
     ["X0", "FUpdate", "compatible", "plain", "fvSolution"]),
    ("gravityDimensions", "constant/g",
     write_file("constant/g", "FoamFile { version 2.0; format ascii; "
                "class uniformDimensionedVectorField; object g; }\n"
                "dimensions [0 1 -1 0 0 0 0];\nvalue (0 -9.81 0);\n"),
     ["constant/g", "dimensions"]),
    # system/controlDict: solidMonitor and touchFoam's entries
    ("solidMonitorOrgin", CD,
     (r"(type\s+solidMonitor;)", r"\1 orgin (0 0 0);"),
     ["'orgin'", "controlDict", "did you mean 'origin'"]),
    ("solidMonitorOriginScalar", CD,
     (r"(type\s+solidMonitor;)", r"\1 origin 1;"),
     ["origin", "controlDict"]),
    ("maxStepsNegative", CD, (r"(application\s+\w+;)",
                              r"\1\nmaxSteps -5;"),
     ["'maxSteps'", "controlDict", "-1 <= maxSteps"]),
    ("progressIntervalNegative", CD, (r"(application\s+\w+;)",
                                      r"\1\nprogressInterval -1;"),
     ["'progressInterval'", "controlDict", "0 <= progressInterval"]),
    # fields
    ("UwrongClass", "0/U", (r"class\s+volVectorField;",
                            "class volScalarField;"),
     ["0/U", "volScalarField", "volVectorField"]),
    ("FwrongClass", "0/F", (r"class\s+volTensorField;",
                            "class volVectorField;"),
     ["0/F", "volVectorField", "volTensorField"]),
    ("UwrongSize", "0/U", (r"internalField\s+[^;]*;",
                           "internalField nonuniform List<vector> "
                           "3((0 0 0) (0 0 0) (0 0 0));"),
     ["0/U", "size 3", "64"]),
    ("UNaN", "0/U", (r"internalField\s+[^;]*;",
                     "internalField uniform (nan 0 0);"),
     ["0/U", "nan"]),
    ("UInf", "0/U", (r"internalField\s+[^;]*;",
                     "internalField uniform (1e999 0 0);"),
     ["0/U", "internalField"]),
    ("FInverted", "0/F", (r"internalField\s+[^;]*;",
                          "internalField uniform (-1 0 0 0 1 0 0 0 1);"),
     ["initial state", "inverted cell", "det F <= 0"]),
    ("FInf", "0/F", (r"internalField\s+[^;]*;",
                     "internalField uniform (1e999 0 0 0 1 0 0 0 1);"),
     ["0/F", "internalField"]),
    ("UTruncated", "0/U", truncate("0/U", 0.6), ["0/U"]),
    # meshes and time folders
    ("meshInverted", "constant/polyMesh/points",
     rewrite_points(lambda x, y, z: (-x, y, z)),
     ["Cell 0", "constant/polyMesh", "positive volume", "checkMesh"]),
    ("meshZeroVolume", "constant/polyMesh/points",
     rewrite_points(lambda x, y, z: (x, y, 0)),
     ["constant/polyMesh", "positive volume"]),
    ("timeFromOtherMesh", "0.001", other_mesh_time,
     ["0.001", "size 8", "64"]),
]

# (label, edit, words, number of ranks): run decomposed with mpirun
PARALLEL = [
    ("processorMissing", processors(2, remove=1), ["processor"], 2),
    ("processorExtra", processors(3),
     ["3 processor folders", "2 ranks", "decomposePar -force"], 2),
]


def tree_digest(folder):
    """The names and contents of every file below folder"""
    digest = []
    for top, _, files in sorted(os.walk(folder)):
        for name in sorted(files):
            path = os.path.join(top, name)
            with open(path, "rb") as f:
                digest.append((os.path.relpath(path, folder), f.read()))
    return digest


def check(root, label, path, edit, words, commands=(), ranks=None):
    # limitedLinear, so that the limiter is read
    case = cases.prepare("swingingCube", os.path.join(root, label), n=4,
                         touch={"reconstruction": "limitedLinear"})
    # One file and one edit, or a list of files with an edit each
    paths = path if isinstance(path, list) else [path]
    edits = edit if isinstance(edit, list) else [edit]
    for one_path, one_edit in zip(paths, edits):
        target = os.path.join(case, one_path)
        if callable(one_edit):
            one_edit(case)
            continue
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
    before = tree_digest(os.path.join(case, "0"))
    times_before = set(d for d in os.listdir(case)
                       if re.match(r"^[0-9.e+-]+$", d))
    log = os.path.join(case, "log.touchFoam")
    command = ["touchFoam"] if ranks is None else \
        run.mpirun(ranks, ["touchFoam"])
    with open(log, "w") as f:
        try:
            status = subprocess.call(command, cwd=case, stdout=f,
                                     stderr=subprocess.STDOUT,
                                     stdin=subprocess.DEVNULL,
                                     timeout=testing.RUN_TIMEOUT)
        except subprocess.TimeoutExpired:
            return "%s: touchFoam hung (see %s)" % (label, log)
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
               if re.match(r"^[0-9.e+-]+$", d) and d not in times_before]
    if written:
        return "%s: wrote %s" % (label, written)
    if os.path.isdir(os.path.join(case, "0")) \
            and tree_digest(os.path.join(case, "0")) != before:
        return "%s: changed the files of 0/" % label
    return None


def body():
    root = testing.work_dir(NAME)
    refused, failures = [], []
    everything = MISTAKES + PATCH_TYPES + CORPUS \
        + [(label, None, edit, words, (), ranks)
           for label, edit, words, ranks in PARALLEL]
    for mistake in everything:
        label, path, edit = mistake[:3]
        if path is None:
            path, edit = ["."], [edit]
        failure = check(root, label, path, edit, *mistake[3:])
        print("  %-26s %s" % (mistake[0], failure or "refused"))
        if failure:
            failures.append(failure)
        else:
            refused.append(mistake[0])
    if failures:
        raise AssertionError("%d of %d mistakes not refused properly: %s"
                             % (len(failures), len(everything),
                                "; ".join(failures)))
    return "%d mistakes refused with file, entry and valid choices: %s" % (
        len(refused), " ".join(refused))


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
