#!/usr/bin/python3
"""touchFoam against CalculiX 2.20 on the same meshes (issue 11, bullet 4).

    ./compare.py [--cases column cube] [-sizes 6 12] [--cube-sizes 16 32]
                 [--elements C3D8R C3D8] [--cube-elements C3D8 C3D8R]
                 [--settings default limitedLinear-RK2-CFL0.3 ...]
                 [--cube-settings default linear-RK2-CFL0.6 ...]
                 [--reference T] [--band LOW HIGH]
                 [--reference-size 24] [--build-label LABEL] [--no-run]
                 [--repeat R]

Runs, one at a time and on one thread each (OMP_NUM_THREADS=1 for ccx),
CalculiX (decks written by decks.py,
explicit, its own increment) and touchFoam on the same structured hex
meshes, in runs/<case>/n<n>/<code>/, and reports for each run the wall time
of the solver process (and its CPU time), the steps or increments, and the
error:

column  tutorials/twistingColumn, n x 6n x n cells or C3D8R/C3D8 elements,
        nu = 0.45, to t = 0.1 s.  Twist = mean over the top-face points at
        least 0.25 from the axis (postprocess.column_twist's set) of the
        rotation about +Y (analytic.twist_angle), the same points and
        formula for both codes.  Error = |twist(0.1 s) - reference|.  The
        codes converge from opposite sides, so their finest values bracket
        the converged twist.  The defaults of --reference and --band are
        the converged twist and its band of
        validation/twistingColumn/reference.json (both codes' Richardson
        extrapolations);
        --reference-size 24 makes the two runs (under nice, kept in runs/)
        and takes both from them.  Every verdict is also checked over the
        whole band.  Both codes write only at 0.1 s,
        so each point's angle is taken on the branch nearest the reference
        (valid while the error is below 180 deg; on 6x36x6 it equals
        column_twist's unwrapping of 0.01 s writes).  touchFoam settings
        (--settings; SETTINGS below): the tutorial as it is (linear, RK3,
        CFL 0.8, solidMonitor every step, writes every 0.05 s) and others
        spelt out in full (reconstruction, time scheme, CFL) with the
        monitor off and one write at 0.1 s.  For each mesh: the
        fastest touchFoam setting whose error is at most CalculiX's, and
        the ratio of the wall times.
cube    tutorials/swingingCube on N^3 cells or C3D8/C3D8R elements, to
        t = 0.004 s, against the closed-form solution (analytic.py):
          e_v   = sqrt(sum_i w_i |v_i - v(X_i)|^2), the velocity vector:
                  touchFoam cell centres with cell volumes, CalculiX nodes
                  with trapezoidal weights;
          e_vx  = the same for v_x alone (validation/swingingCube's
                  number; e_v = sqrt(3) e_vx by the cube's symmetry);
          e_Pxx = sqrt(sum_e V_e (P_xx,e - P_xx(X_e))^2): touchFoam's cell
                  values, CalculiX's element stress (the mean over its
                  integration points) at the element centroid.
        Errors at equal wall time: each code's log e - log wall line
        between successive meshes, evaluated at every run's wall time
        (outside a code's range: extrapolated, marked).

--repeat R runs every CalculiX and touchFoam job R times, round robin over
all of them (the first repeat of every job, then the second, ...), so that
a change of the machine's speed within the run falls on both codes alike;
the wall and CPU times reported are the medians of the R runs (as the
issue's own side-by-side table), each run's are kept in run.json.

Writes results.json, results.md, column.png, cube.png, and the tables into
README.md between '<!-- results -->' and '<!-- /results -->'.  --no-run
re-analyses runs/.  Needs etc/bashrc and ccx.  The CalculiX side is in
ccx.py; the comparisons (fastest as accurate, equal wall time), the tables
and the plots in report.py; the checks against the converged twist and the
closed form (checks.json, exit status 1 when one fails) in
calculixChecks.py.
"""

import argparse
import datetime
import json
import math
import os
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))
sys.path.insert(0, HERE)

from touchfoam import analytic, cases, provenance, run  # noqa
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402

import calculixChecks  # noqa: E402
import ccx  # noqa: E402
import report  # noqa: E402
from cubeErrors import (CUBE_END, check_cube_material,  # noqa: E402
                        ccx_cube_errors, touch_cube_errors)

COLUMN_END = 0.1
COLUMN_NU = 0.45
TOP = 6.0
RMIN = 0.25              # postprocess.column_twist's default
#: the converged twist at 0.1 s and its band [deg] when --reference-size
#: is not given: both codes' Richardson extrapolations
#: (validation/twistingColumn/reference.py, FINDINGS.md there)
REFERENCE_FILE = os.path.join(HERE, "..", "twistingColumn", "reference.json")
with open(REFERENCE_FILE) as _f:
    _converged = json.load(_f)
REFERENCE = round(_converged["reference"], 2)
BAND = tuple(round(b, 2) for b in _converged["band"])
REFERENCE_SETTING = "default"
REFERENCE_ELEMENT = "C3D8R"
NICE = ("nice", "-n", "19")
RUN_INFO = "run.json"
NEVER = 1000000000       # an interval that is never reached

#: touchFoam settings: TOUCH entries of system/fvSolution; 'quiet' turns the
#: solidMonitor off (executeInterval and writeInterval: it computes in
#: execute(), so writeInterval alone would leave it running every step) and
#: writes the fields at the end time only
def spelt_out(reconstruction, scheme, cfl):
    """A setting named and given by its reconstruction, time scheme and CFL
    number, monitor off."""
    return ("%s-%s-CFL%.1f" % (reconstruction, scheme, cfl),
            {"touch": {"reconstruction": reconstruction, "timeScheme": scheme,
                       "CFL": cfl}, "quiet": True})


#: The tutorial as it is (column: linear, RK2, CFL 0.5; cube: RK3 0.8) with the
#: solidMonitor every step, the tutorials' former setting (limitedLinear,
#: RK2, CFL 0.3), and the points of validation/accuracyVsCost's front
SETTINGS = dict(
    [("default", {"touch": {}, "quiet": False})]
  + [spelt_out(*s) for s in (
        ("limitedLinear", "RK2", 0.3), ("linear", "RK2", 0.5),
        ("linear", "RK2", 0.6), ("linear", "RK3", 0.8),
        ("linear", "RK3", 1.0))])


def describe(setting):
    s = SETTINGS[setting]
    if not s["touch"] and not s["quiet"]:
        return "tutorial as is"
    return ", ".join(["%s %s" % kv for kv in s["touch"].items()]
                     + (["monitor off, one write"] if s["quiet"] else []))


def run_dir(case, n, code):
    return os.path.join(HERE, "runs", case, "n%d" % n, code)


def reference_dir(n, code):
    """The column's reference runs (not timed: they run under nice)."""
    return os.path.join(HERE, "runs", "column", "reference-n%d" % n, code)


def _save(folder, info):
    with open(os.path.join(folder, RUN_INFO), "w") as f:
        json.dump(info, f, indent=1)


def _load(folder):
    path = os.path.join(folder, RUN_INFO)
    if not os.path.exists(path):
        raise run.RunError("%s missing: run without --no-run first" % path)
    with open(path) as f:
        return json.load(f)


def _stamp():
    return {"started": datetime.datetime.now().isoformat(timespec="seconds"),
            "loadBefore": list(os.getloadavg())}


def _repeated(folder, repeat):
    """The wall and CPU times of the earlier repeats of a job (empty for
    the first), read before its folder is remade."""
    if repeat == 0 or not os.path.exists(os.path.join(folder, RUN_INFO)):
        return {"walls": [], "cpus": []}
    old = _load(folder)
    return {"walls": old.get("walls", [old["wall"]]),
            "cpus": old.get("cpus", [old["cpu"]])}


def _with_repeats(info, earlier):
    """info's wall and cpu become the medians over this and the earlier
    repeats; the single runs are kept."""
    info["walls"] = earlier["walls"] + [info["wall"]]
    info["cpus"] = earlier["cpus"] + [info["cpu"]]
    info["wall"] = float(np.median(info["walls"]))
    info["cpu"] = float(np.median(info["cpus"]))
    return info


# -- touchFoam ----------------------------------------------------------------

def touch_control(setting, end, extra=None):
    control = {"endTime": end}
    control.update(extra or {})
    if SETTINGS[setting]["quiet"]:
        control.update({"writeInterval": end,
                        "functions/solidMonitor/executeInterval": NEVER,
                        "functions/solidMonitor/writeInterval": NEVER})
    return control


def run_touchfoam(case, tutorial, n, setting, control, folder=None,
                  prefix=(), repeat=0):
    folder = folder or run_dir(case, n, "touchFoam-" + setting)
    print("touchFoam %s n=%d %s%s" % (case, n, setting,
                                      " (%s)" % " ".join(prefix) if prefix
                                      else ""), flush=True)
    earlier = _repeated(folder, repeat)
    info = _stamp()
    start = time.perf_counter()
    cases.prepare(tutorial, folder, n=n, touch=SETTINGS[setting]["touch"],
                  control=control, **({"nu": COLUMN_NU}
                                      if tutorial == "twistingColumn" else {}))
    info["prepareWall"] = time.perf_counter() - start
    info["wall"], info["cpu"] = ccx.timed(list(prefix) + ["touchFoam"],
                                          folder, "touchFoam",
                                          env=ccx.ONE_THREAD)
    info["loadAfter"] = list(os.getloadavg())
    info["steps"], info["clockTime"] = provenance.log_steps_and_clock(folder)
    info["dt0"] = _first_dt(folder)
    info["setting"] = setting
    _save(folder, _with_repeats(info, earlier))
    print("    wall %.2f s, cpu %.2f s, %d steps" % (
        info["wall"], info["cpu"], info["steps"]), flush=True)


def _first_dt(folder):
    with open(os.path.join(folder, "log.touchFoam"), errors="replace") as f:
        for line in f:
            if line.startswith("Time = ") and "deltaT" in line:
                return float(line.split("deltaT =")[1])
    return None


# -- CalculiX -----------------------------------------------------------------

def run_calculix(case, n, element, folder=None, prefix=(), repeat=0):
    folder = folder or run_dir(case, n, "ccx-" + element)
    job = "%s%d_%s" % (case, n, element)
    print("ccx %s n=%d %s%s" % (case, n, element,
                                " (%s)" % " ".join(prefix) if prefix
                                else ""), flush=True)
    earlier = _repeated(folder, repeat)
    if os.path.exists(folder):
        shutil.rmtree(folder)
    info = _stamp()
    start = time.perf_counter()
    if case == "column":
        ccx.column_deck(folder, job, n, element, COLUMN_NU, COLUMN_END)
    else:
        ccx.cube_deck(folder, job, n, element, CUBE_END)
    info["prepareWall"] = time.perf_counter() - start
    info["wall"], info["cpu"] = ccx.run_ccx(folder, job, prefix)
    info["loadAfter"] = list(os.getloadavg())
    info["job"] = job
    info["element"] = element
    info["steps"] = ccx.increments(os.path.join(folder, job + ".frd"))
    dts = ccx.selected_dt(os.path.join(folder, "log.ccx"))
    info["dt0"] = dts[0] if dts else None
    if info["steps"] is None and info["dt0"]:
        # No results in the .frd (the cube deck prints to the .dat only):
        # the increment is fixed for the step and the last one is cut to
        # end at t_end (log: 'the increment size exceeds the remainder')
        end = COLUMN_END if case == "column" else CUBE_END
        info["steps"] = int(math.ceil(end / info["dt0"] - 1e-9))
    _save(folder, _with_repeats(info, earlier))
    print("    wall %.2f s, cpu %.2f s, %s increments" % (
        info["wall"], info["cpu"], info["steps"]), flush=True)


# -- twisting column ----------------------------------------------------------

def top_twist(X, u, reference_deg, rmin=RMIN):
    """Mean twist [deg] of the top-face points of X (displacements u),
    each angle on the branch nearest the reference."""
    X, u = np.asarray(X, float), np.asarray(u, float)
    top = (np.abs(X[:, 1] - TOP) < 1e-9) & (np.hypot(X[:, 0], X[:, 2])
                                            >= max(rmin, 1e-12))
    if not top.any():
        raise ValueError("no top-face points")
    ref = math.radians(reference_deg)
    theta = analytic.twist_angle(X[top], u[top])
    theta = ref + np.angle(np.exp(1j * (theta - ref)))
    return math.degrees(float(theta.mean())), int(top.sum())


def touch_top(folder, t):
    m = PolyMesh(folder)
    u = read_field(os.path.join(run.time_dir(folder, t), "pointD")
                   ).internal(len(m.points))
    return m.points, u


def ccx_top(folder, job, t):
    nodes, _, _ = ccx.read_inp(os.path.join(folder, job + ".inp"))
    block = ccx.last_block(ccx.read_dat(os.path.join(folder, job + ".dat")),
                           "displacements", "NTOP")
    if abs(block["time"] - t) > 1e-6 * t:
        raise ValueError("%s: last NTOP print at t = %g, not %g"
                         % (job, block["time"], t))
    rows = np.array(block["rows"])
    X = np.array([nodes[int(i)] for i in rows[:, 0]])
    return X, rows[:, 1:4]


def check_column_material():
    mat = cases.material(run.tutorial_dir("twistingColumn"))
    for key in ("E", "rho"):
        if not math.isclose(mat[key], ccx.COLUMN_DECK[key], rel_tol=1e-12):
            raise ValueError("twistingColumn %s = %g, the CalculiX deck has "
                             "%g" % (key, mat[key], ccx.COLUMN_DECK[key]))


def reference_twist(args):
    """(reference, band, record): given, or from the reference runs.

    The two codes approach the converged twist from opposite sides
    (touchFoam from below, CalculiX from above, on every mesh measured),
    so on the finest mesh their values bracket it: the band is that
    bracket, the reference its middle.
    """
    if not args.reference_size:
        return args.reference, list(args.band), {
            "source": "--reference and --band; the defaults are those of "
            "validation/twistingColumn/reference.json, both codes' "
            "Richardson extrapolations"}
    n = args.reference_size
    twists = {}
    for code in ("ccx-" + REFERENCE_ELEMENT,
                 "touchFoam-" + REFERENCE_SETTING):
        folder = reference_dir(n, code)
        info = _load(folder)
        twists[code] = {"twist": _twist_of(folder, code, info, args),
                        "wall": info["wall"], "cpu": info["cpu"],
                        "steps": info["steps"]}
        twists[code].update(_richardson(code, n, twists[code]["twist"],
                                        args))
    values = sorted(t["twist"] for t in twists.values())
    return (0.5 * (values[0] + values[1]), values,
            {"source": "the bracket of CalculiX %s and touchFoam %s on "
             "%dx%dx%d" % (REFERENCE_ELEMENT, REFERENCE_SETTING, n, 6 * n, n),
             "runs": twists})


def _twist_of(folder, code, info, args):
    X, u = (ccx_top(folder, info["job"], COLUMN_END)
            if code.startswith("ccx") else touch_top(folder, COLUMN_END))
    return top_twist(X, u, args.reference)[0]


def _richardson(code, n, finest, args):
    """Observed order and extrapolated twist from n/4, n/2 (comparison
    runs, when present) and n: T* = T_n + (T_n - T_n/2) / (2^p - 1)."""
    t = []
    for m in (n // 4, n // 2):
        folder = run_dir("column", m, code)
        if n % 4 or not os.path.exists(os.path.join(folder, RUN_INFO)):
            return {}
        t.append(_twist_of(folder, code, _load(folder), args))
    t.append(finest)
    d1, d2 = t[1] - t[0], t[2] - t[1]
    if d1 * d2 <= 0 or abs(d2) >= abs(d1):
        return {"coarser": t[:2], "order": None, "extrapolated": None}
    p = math.log(d1 / d2) / math.log(2.0)
    # Far from any order a scheme can have: not in the asymptotic range,
    # and the extrapolation would mean nothing
    usable = 0.5 <= p <= 4.0
    return {"coarser": t[:2], "order": p,
            "extrapolated": t[2] + d2 / (2.0 ** p - 1.0) if usable
            else None}


def analyse_column(args):
    check_column_material()
    ref, band_ends, record = reference_twist(args)
    band = np.linspace(band_ends[0], band_ends[1], 41)
    out = {"time": COLUMN_END, "nu": COLUMN_NU, "reference": ref,
           "band": band_ends, "referenceFrom": record, "rmin": RMIN,
           "meshes": {}}
    for n in args.sizes:
        rows = []
        for element in args.elements:
            folder = run_dir("column", n, "ccx-" + element)
            info = _load(folder)
            X, u = ccx_top(folder, info["job"], COLUMN_END)
            rows.append(_column_row("CalculiX", element, info, X, u, ref))
        for setting in args.settings:
            folder = run_dir("column", n, "touchFoam-" + setting)
            info = _load(folder)
            X, u = touch_top(folder, COLUMN_END)
            rows.append(_column_row("touchFoam", setting, info, X, u, ref))
        fastest = report.fastest_as_accurate_twist(rows, ref, band)
        out["meshes"][str(n)] = {"cells": 6 * n ** 3, "runs": rows,
                                 "fastest": fastest}
    out["equalWall"] = report.equal_wall(out, ("error",))
    return out


def _column_row(code, variant, info, X, u, ref):
    twist, npts = top_twist(X, u, ref)
    twist_all, _ = top_twist(X, u, ref, rmin=0.0)
    return {"code": code, "variant": variant,
            "description": describe(variant) if code == "touchFoam"
            else "explicit, one step, CalculiX's increment",
            "wall": info["wall"], "cpu": info["cpu"], "steps": info["steps"],
            "dt0": info["dt0"], "prepareWall": info["prepareWall"],
            "load": [info["loadBefore"][0], info["loadAfter"][0]],
            "twist": twist, "points": npts, "twistAllPoints": twist_all,
            "error": abs(twist - ref)}


# -- swinging cube ------------------------------------------------------------

def analyse_cube(args):
    sol = check_cube_material()
    out = {"time": CUBE_END, "meshes": {}}
    for n in args.cube_sizes:
        rows = []
        for element in args.cube_elements:
            folder = run_dir("cube", n, "ccx-" + element)
            info = _load(folder)
            e = ccx_cube_errors(folder, info["job"], n, sol)
            rows.append(_cube_row("CalculiX", element, info, e))
        for setting in args.cube_settings:
            folder = run_dir("cube", n, "touchFoam-" + setting)
            info = _load(folder)
            rows.append(_cube_row("touchFoam", setting, info,
                                  touch_cube_errors(folder)))
        fastest = {k: report.fastest_as_accurate(rows, k)
                   for k in ("ev", "ePxx")}
        out["meshes"][str(n)] = {"cells": n ** 3, "runs": rows,
                                 "fastest": fastest}
    out["equalWall"] = report.equal_wall(out, ("ev", "ePxx"))
    return out


def _cube_row(code, variant, info, errors):
    row = {"code": code, "variant": variant,
           "description": describe(variant) if code == "touchFoam"
           else "explicit, CalculiX's increment",
           "wall": info["wall"], "cpu": info["cpu"], "steps": info["steps"],
           "dt0": info["dt0"], "prepareWall": info["prepareWall"],
           "load": [info["loadBefore"][0], info["loadAfter"][0]]}
    row.update(errors)
    return row


# -- main ---------------------------------------------------------------------

def run_all(args):
    if "column" in args.cases and args.reference_size:
        # Kept between invocations (Allclean removes them): they are long
        n = args.reference_size
        ccx_ref = reference_dir(n, "ccx-" + REFERENCE_ELEMENT)
        tf_ref = reference_dir(n, "touchFoam-" + REFERENCE_SETTING)
        if not os.path.exists(os.path.join(ccx_ref, RUN_INFO)):
            run_calculix("column", n, REFERENCE_ELEMENT, prefix=NICE,
                         folder=ccx_ref)
        if not os.path.exists(os.path.join(tf_ref, RUN_INFO)):
            run_touchfoam("column", "twistingColumn", n, REFERENCE_SETTING,
                          touch_control(REFERENCE_SETTING, COLUMN_END),
                          prefix=NICE, folder=tf_ref)
    for r in range(args.repeat):
        if args.repeat > 1:
            print("repeat %d of %d" % (r + 1, args.repeat), flush=True)
        if "column" in args.cases:
            for n in args.sizes:
                for element in args.elements:
                    run_calculix("column", n, element, repeat=r)
                for setting in args.settings:
                    run_touchfoam("column", "twistingColumn", n, setting,
                                  touch_control(setting, COLUMN_END),
                                  repeat=r)
        if "cube" in args.cases:
            for n in args.cube_sizes:
                for element in args.cube_elements:
                    run_calculix("cube", n, element, repeat=r)
                for setting in args.cube_settings:
                    run_touchfoam("cube", "swingingCube", n, setting,
                                  touch_control(setting, CUBE_END,
                                                {"writePrecision": 17}),
                                  repeat=r)


def build_label(given=None):
    """Which touchFoam ran: --build-label, else provenance.build_label()
    flagged when src/ or applications/ differ from the commit, or the
    folder of a touchFoam that is not this checkout's."""
    solver = shutil.which("touchFoam") or "?"
    if given:
        return "%s (%s)" % (given, solver)
    if not os.path.realpath(solver).startswith(
            os.path.realpath(run.project_dir()) + os.sep):
        return "touchFoam of %s (not this checkout's build)" % solver
    label = provenance.build_label()
    try:
        dirty = subprocess.check_output(
            ["git", "-C", run.project_dir(), "status", "--porcelain", "--",
             "src", "applications"], text=True).strip()
    except (OSError, subprocess.CalledProcessError):
        return label + " (git status unknown)"
    return label + (" + uncommitted changes in src/ or applications/"
                    if dirty else "")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cases", nargs="+", choices=["column", "cube"],
                        default=["column", "cube"])
    parser.add_argument("-sizes", "--sizes", type=int, nargs="+",
                        default=[6, 12], help="column: n x 6n x n")
    parser.add_argument("--cube-sizes", type=int, nargs="+",
                        default=[16, 32], help="cube: N^3")
    parser.add_argument("--elements", nargs="+", default=["C3D8R", "C3D8"],
                        choices=["C3D8R", "C3D8"])
    parser.add_argument("--cube-elements", nargs="+",
                        default=["C3D8", "C3D8R"], choices=["C3D8R", "C3D8"])
    parser.add_argument("--settings", nargs="+", choices=list(SETTINGS),
                        default=list(SETTINGS))
    parser.add_argument("--cube-settings", nargs="+", choices=list(SETTINGS),
                        default=["default", "linear-RK2-CFL0.6",
                                 "linear-RK3-CFL1.0"])
    parser.add_argument("--reference", type=float, default=REFERENCE,
                        help="reference twist at 0.1 s [deg]")
    parser.add_argument("--band", type=float, nargs=2, default=list(BAND),
                        help="band of plausible references [deg]")
    parser.add_argument("--reference-size", type=int, default=None,
                        help="run CalculiX %s and touchFoam %s on n x 6n x n "
                        "(under nice, unless runs/ has them) and take the "
                        "reference from them"
                        % (REFERENCE_ELEMENT, REFERENCE_SETTING))
    parser.add_argument("--build-label", default=None,
                        help="name of the touchFoam build in the PATH")
    parser.add_argument("--no-run", action="store_true",
                        help="only analyse the existing runs/")
    parser.add_argument("--repeat", type=int, default=1,
                        help="runs of every job, round robin; the medians "
                        "of their times are reported")
    args = parser.parse_args()
    if args.repeat < 1:
        parser.error("--repeat must be at least 1, not %d" % args.repeat)
    args.sizes, args.cube_sizes = sorted(args.sizes), sorted(args.cube_sizes)
    try:
        if not args.no_run:
            run.check_openfoam()
            ccx.check_ccx()
            run_all(args)
        results = {"date": datetime.date.today().isoformat(),
                   "command": " ".join(sys.argv),
                   "build": build_label(args.build_label),
                   "ccx": ccx.version(),
                   "threads": 1,
                   "repeat": args.repeat}
        if "column" in args.cases:
            results["column"] = analyse_column(args)
        if "cube" in args.cases:
            results["cube"] = analyse_cube(args)
    except (run.RunError, OSError, ValueError) as err:
        print("compare: %s" % err, file=sys.stderr)
        return 1
    with open(os.path.join(HERE, "results.json"), "w") as f:
        json.dump(results, f, indent=1)
    report.write_reports(results)
    report.plot(results)
    status = calculixChecks.record(results)
    print("wrote results.json, results.md, checks.json (%s)"
          % ("every check passes" if status == 0 else "a check FAILS"))
    return status


if __name__ == "__main__":
    sys.exit(main())
