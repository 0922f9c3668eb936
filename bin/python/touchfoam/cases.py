"""Set-up of the touchFoam tutorials: initial fields and run copies.

The tutorials set their initial state with OpenFOAM's setExprFields
(system/setExprFieldsDict) or a uniform 0.orig/U; the tests and validation
scripts call prepare() to make a copy of a tutorial with other settings,
meshed and initialised exactly as its Allrun does (set_initial_state), and
the initialise_* functions to write an initial velocity or F of their own
into 0/U and 0/F.
"""

import os
import re

import numpy as np

from . import analytic
from .foamfile import FoamField, read_dict
from .mesh import PolyMesh
from .run import (PYTHON, copy_case, foam_set, restore0, run, tutorial_dir,
                  write_options)

IDENTITY = np.eye(3).ravel()


def material(case):
    """mechanicalProperties of a case (optional overrides included)."""
    d = read_dict(os.path.join(case, "constant", "mechanicalProperties"))
    for key in ("rho", "E", "nu"):
        if not isinstance(d.get(key), float):
            raise ValueError("mechanicalProperties: %s missing or not a "
                             "number" % key)
    return d


def _write_U_F(case, U=None, F=None):
    """Write 0/U and 0/F internal fields (None: leave the file alone);
    touchFoam starts from lm = rho0 U."""
    if U is not None:
        fld = FoamField(os.path.join(case, "0", "U"))
        fld.set_internal(U)
        fld.write()
    if F is not None:
        fld = FoamField(os.path.join(case, "0", "F"))
        fld.set_internal(F.reshape(len(F), 9))
        fld.write()


def initialise_swinging_cube(case, U0=None):
    """0/F = I + grad u(X_e, 0) at the cell centres; U stays zero.

    The initial velocity of the swinging cube is exactly zero.
    """
    mat = material(case)
    kw = {} if U0 is None else {"U0": U0}
    sol = analytic.SwingingCube(E=mat["E"], nu=mat["nu"], rho=mat["rho"], **kw)
    X = PolyMesh(case).cell_centres
    _write_U_F(case, U=sol.velocity(X, 0.0),
               F=sol.deformation_gradient(X, 0.0))
    return len(X)


def initialise_twisting_column(case, Omega=105.0, L=6.0):
    """U = omega x X at the cell centres; F = I (from 0.orig)."""
    X = PolyMesh(case).cell_centres
    _write_U_F(case, U=analytic.TwistingColumn(Omega=Omega, L=L).velocity(X))
    return len(X)


def initialise_rigid_motion(case, translation, omega):
    """U = v_t + omega x X at the cell centres; F = I."""
    X = PolyMesh(case).cell_centres
    _write_U_F(case, U=analytic.rigid_velocity(X, translation, omega))
    return len(X)


def set_initial_state(case):
    """The initial state as the tutorials' Allruns set it: setExprFields
    with system/setExprFieldsDict (if the case has one), at writePrecision
    17 so that the fields keep every digit (the Allruns do the same through
    system/controlOptions, which a controlDict rewritten by foamDictionary
    no longer includes); the tutorials without one start from the uniform
    velocity of 0.orig/U."""
    if not os.path.exists(os.path.join(case, "system", "setExprFieldsDict")):
        return
    control = os.path.join(case, "system", "controlDict")
    with open(control) as f:
        original = f.read()
    try:
        foam_set(case, "system/controlDict", "writePrecision", 17)
        run(["setExprFields"], case)
    finally:
        with open(control, "w") as f:
            f.write(original)


# -- run copies -------------------------------------------------------------

def impact_mesh_options(tutorial, n):
    """system/meshOptions entries of './Allrun -n n' for the impact
    tutorials (their Allruns derive the block counts from n; blockMesh
    takes integer counts only)."""
    if tutorial in ("taylorImpact", "barRebound"):
        # n across the radius: core, outer blocks, along the axis (L/R = 81/8)
        nc = (2 * n + 1) // 3
        return {"N": n, "Nc": nc, "Nr": n - nc, "Ny": (81 * n + 4) // 8}
    if n % 4:
        raise ValueError("%s: n must be a multiple of 4, got %d"
                         % (tutorial, n))
    if tutorial == "ringImpact":
        # n around the ring, (Ro - Ri)/(pi (Ri + Ro)) = 1/22 of it across
        return {"N": n, "Nq": n // 4, "Nr": max(1, (n + 11) // 22)}
    # torusImpact: n around the tube, 7n layers around the axis
    return {"N": n, "Nq": n // 4, "Nr": (n // 4 + 1) // 2, "Nt": 7 * n}


#: Meshing after blockMesh, as in the impact tutorials' Allruns
IMPACT_MESHING = {
    "taylorImpact": [],
    "barRebound": [["transformPoints", "-translate", "(0 0.004 0)"]],
    "ringImpact": [["mirrorMesh", "-overwrite"],
                   ["createPatch", "-overwrite"]],
    "torusImpact": [["extrudeMesh"], ["createPatch", "-overwrite"]],
}


def mesh_case(case, tutorial, n=None):
    """Make the mesh of a copy the way the tutorial's Allrun does."""
    if tutorial == "unstructuredCube":
        args = [PYTHON, "makeMesh.py"] + ([] if n is None else ["-n", str(n)])
        run(args, case, "makeMesh")
        run(["gmshToFoam", "cube.msh"], case)
        run(["checkMesh"], case)
    elif tutorial in IMPACT_MESHING:
        write_options(case, "system/meshOptions",
                      {} if n is None else impact_mesh_options(tutorial, n))
        run(["blockMesh"], case)
        for cmd in IMPACT_MESHING[tutorial]:
            run(cmd, case)
        run(["checkMesh"], case)
    else:
        write_options(case, "system/meshOptions",
                      {} if n is None else {"N": n})
        run(["blockMesh"], case)


#: The TOUCH entries of one model, read from its <model>Coeffs
#: sub-dictionary of TOUCH (the owner named in doc/entries.md)
TOUCH_COEFFS = {"jumpShare": "compatibleCoeffs",
                "pointUpwinding": "compatibleCoeffs",
                "pointLimiter": "compatibleCoeffs",
                "limiter": "limitedLinearCoeffs"}


def set_touch(case, key, value):
    """Set an entry of system/fvSolution's TOUCH; a model's own entry
    (TOUCH_COEFFS) goes to its Coeffs sub-dictionary, made when missing."""
    path = "TOUCH/" + key
    if key in TOUCH_COEFFS:
        coeffs = TOUCH_COEFFS[key]
        with open(os.path.join(case, "system", "fvSolution")) as f:
            text = f.read()
        if not re.search(r"\b%s\s*\{" % coeffs, text):
            foam_set(case, "system/fvSolution", "TOUCH/" + coeffs, "{}")
        path = "TOUCH/%s/%s" % (coeffs, key)
    foam_set(case, "system/fvSolution", path, value)


def prepare(tutorial, dst, n=None, nu=None, touch=None, control=None,
            initialise=True):
    """A meshed and initialised copy of tutorials/<tutorial> at dst.

    n        cells per side (swingingCube, spinningCube, unstructuredCube),
             across the column (twistingColumn: n x 6n x n), the bar's
             radius (taylorImpact, barRebound), around the ring or the
             tube (ringImpact, torusImpact): the Allruns' -n
    nu       Poisson's ratio override (constant/materialOptions)
    touch    {entry: value} for fvSolution's TOUCH dictionary (a model's
             own entries, TOUCH_COEFFS, go to its Coeffs sub-dictionary)
    control  {entry: value} for system/controlDict ('functions/solidMonitor/
             writePrecision' style paths allowed)
    """
    copy_case(tutorial_dir(tutorial), dst)
    if nu is not None:
        write_options(dst, "constant/materialOptions", {"nu": nu})
    for key, value in (touch or {}).items():
        set_touch(dst, key, value)
    for key, value in (control or {}).items():
        foam_set(dst, "system/controlDict", key, value)
    restore0(dst)
    mesh_case(dst, tutorial, n)
    if initialise:
        set_initial_state(dst)
    return dst


def precise_output(digits=17):
    """controlDict entries for output that round-trips doubles exactly."""
    return {"writePrecision": digits,
            "functions/solidMonitor/writePrecision": digits}
