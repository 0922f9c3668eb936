"""The checks of the CalculiX comparison (checks.json, validation/Allrun).

compare.py calls record(results) once its results are in; each check is a
measured value beside an independent reference:

column  the twist at 0.1 s of touchFoam (the tutorial's setting, 'default')
        and of CalculiX C3D8R against the converged twist,
        CONVERGED +- CONVERGED_PM, the middle and half-width of the band
        of both codes' Richardson extrapolations
        (../twistingColumn/reference.json).  The error may be at
        most 1.5 times the error measured on 2026-12-05 (touchFoam 11.3 /
        4.1 / 1.3 deg on n = 6 / 12 / 24, C3D8R 11.2 / 2.7 / 0.4, against
        332.2), taken as e(n) = e6 (6/n)^p with the observed order p, plus
        the reference's half-band; and the two codes must bracket it
        (touchFoam from below, CalculiX from above: both converge from
        their side on every mesh measured).
cube    the errors against the closed form (analytic.py) at 0.004 s of
        touchFoam 'default' and CalculiX C3D8: e_Pxx of touchFoam at most
        CalculiX's on the same mesh (measured ratio 0.53 / 0.49 / 0.50 on
        8 / 16 / 32), and, between successive meshes, the observed order
        of e_v and e_Pxx of each code >= 1.8 (second order in space and
        time; measured touchFoam 4.1 / 3.0 and 2.2 / 2.0, CalculiX 2.6 /
        2.3 and 2.1 / 2.1).

Wall times are reported by compare.py, not checked: the machine is shared.
"""

import json
import math
import os

from touchfoam import checks

HERE = os.path.dirname(os.path.abspath(__file__))

#: the converged twist and half its band [deg]: both codes' Richardson
#: extrapolations, ../twistingColumn/reference.json (reference.py), the
#: reference compare.py and timeToAccuracy.py use
with open(os.path.join(HERE, "..", "twistingColumn", "reference.json")) as _f:
    _converged = json.load(_f)
CONVERGED = round(_converged["reference"], 2)
CONVERGED_PM = round(0.5 * (_converged["band"][1] - _converged["band"][0]), 2)
#: (error on n = 6 [deg], observed order) of each code, 2026-12-05
TWIST_ERROR = {("touchFoam", "default"): (11.3, 1.5),
               ("CalculiX", "C3D8R"): (11.2, 1.9)}
ERROR_FACTOR = 1.5
MIN_ORDER = 1.8
CUBE_ELEMENT = "C3D8"


def _run(mesh, code, variant):
    return next((r for r in mesh["runs"] if r["code"] == code
                 and r["variant"] == variant), None)


def column(res):
    for n, mesh in res["meshes"].items():
        n = int(n)
        tf = _run(mesh, "touchFoam", "default")
        cx = _run(mesh, "CalculiX", "C3D8R")
        for key, run in ((("touchFoam", "default"), tf),
                         (("CalculiX", "C3D8R"), cx)):
            if run is None:
                continue
            e6, p = TWIST_ERROR[key]
            bound = ERROR_FACTOR * e6 * (6.0 / n) ** p + CONVERGED_PM
            error = abs(run["twist"] - CONVERGED)
            checks.record(
                HERE, "column %dx%dx%d: %s %s twist at 0.1 s, error [deg]"
                % (n, 6 * n, n, key[0], key[1]),
                error, "<= %.2f (twist %.1f; converged %.1f +- %.1f)"
                % (bound, run["twist"], CONVERGED, CONVERGED_PM),
                error <= bound,
                "bound: %.1f x %.1f (6/n)^%.1f, the error measured on "
                "2026-12-05, + the reference's uncertainty"
                % (ERROR_FACTOR, e6, p))
        if tf and cx:
            ok = (tf["twist"] < CONVERGED + CONVERGED_PM
                  and cx["twist"] > CONVERGED - CONVERGED_PM)
            checks.record(
                HERE, "column %dx%dx%d: touchFoam below, CalculiX C3D8R "
                "above the converged twist" % (n, 6 * n, n),
                "%.1f / %.1f" % (tf["twist"], cx["twist"]),
                "< %.1f / > %.1f" % (CONVERGED + CONVERGED_PM,
                                     CONVERGED - CONVERGED_PM), ok,
                "each code converges from its own side")


def cube(res):
    sizes = sorted(int(n) for n in res["meshes"])
    for n in sizes:
        mesh = res["meshes"][str(n)]
        tf = _run(mesh, "touchFoam", "default")
        cx = _run(mesh, "CalculiX", CUBE_ELEMENT)
        if tf and cx:
            checks.record(
                HERE, "cube %d^3: e_Pxx touchFoam / CalculiX %s"
                % (n, CUBE_ELEMENT), tf["ePxx"] / cx["ePxx"],
                "<= 1 (%.3g / %.3g Pa)" % (tf["ePxx"], cx["ePxx"]),
                tf["ePxx"] <= cx["ePxx"],
                "errors against the closed form, same mesh; e_v is "
                "reported (touchFoam's is larger on coarse meshes)")
    for a, b in zip(sizes, sizes[1:]):
        for code, variant in (("touchFoam", "default"),
                              ("CalculiX", CUBE_ELEMENT)):
            ra = _run(res["meshes"][str(a)], code, variant)
            rb = _run(res["meshes"][str(b)], code, variant)
            if not (ra and rb):
                continue
            for key in ("ev", "ePxx"):
                order = (math.log(ra[key] / rb[key]) / math.log(b / a)
                         if ra[key] > 0 and rb[key] > 0 else float("nan"))
                checks.record(
                    HERE, "cube %d^3 -> %d^3: order of %s, %s %s"
                    % (a, b, "e_v" if key == "ev" else "e_Pxx", code,
                       variant), order, ">= %g" % MIN_ORDER,
                    order >= MIN_ORDER,
                    "%.3g -> %.3g against the closed form"
                    % (ra[key], rb[key]))


def record(results):
    """Record the checks of compare.py's results; the exit status."""
    checks.start(HERE)
    if "column" in results:
        column(results["column"])
    if "cube" in results:
        cube(results["cube"])
    return checks.status(HERE)
