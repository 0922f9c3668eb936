#!/usr/bin/python3
"""Accuracy against cost of the scheme settings (issue 11): which
reconstruction, CFL number and time scheme give the least error per second.

    ./accuracyVsCost.py [-quick] [--case swingingCube twistingColumn]
                        [--build-label LABEL] [--no-run]

Cases (tutorial settings otherwise):
    swingingCube    tutorials/swingingCube on N^3 cells, N = 8 16 32 (quick:
                    8 16), to t = 0.004 s; errors: the volume-weighted L2
                    norms of v and of the normal stresses P_xx, P_yy, P_zz
                    against the closed-form solution
                    (postprocess.swinging_cube_errors, as
                    validation/swingingCube), each the RMS over its three
                    components divided by the amplitude of the quantity
                    (convergence.amplitudes: U0 w, (3 lambda + 2 mu) pi/2
                    U0); the error of a run is the larger of the two.
                    Fields are written at 0.004 s only.
    twistingColumn  tutorials/twistingColumn, nu = 0.45, on n x 6n x n
                    cells, n = 4 6 8 12 (quick: 4 6), to t = 0.1 s, fields
                    written every 0.02 s (the top turns at most 2.1 rad
                    between writes: the twist unwraps); error: |mean top
                    twist at 0.1 s (postprocess.column_twist, as
                    validation/twistingColumn) - 330.7 deg|, the middle of
                    the band 328.9-332.6 deg bracketed by touchFoam and
                    CalculiX C3D8R on 24x144x24 (validation/calculix; the
                    302-306 deg once quoted came from the peer's
                    unwrapping of the angles, see its README).

Settings: reconstruction firstOrder | linear | limitedLinear, timeScheme
RK2 at CFL 0.3 0.5 0.7 and RK3 at CFL 0.5 1.0 (0.7 and 1.0 are the measured
limits of the compatible update, validation/stabilityMap).  Not a full
factorial; every setting runs on every mesh of its case:
    round 0   one factor at a time around the tutorial's setting (the other
              reconstructions at its time setting, the other time settings
              at its reconstruction): 7 settings;
    round k   on each mesh, the reconstructions on the Pareto front of the
              runs that share a time setting, and the time settings on the
              front of the runs that share a reconstruction, are combined;
              the combinations not run yet are run; repeated until no new
              combination appears (at most 3 rounds).
A run is on a Pareto front when it is admissible (it reached its end time
and its energy never grew in a step) and no admissible run that costs less
has a smaller error.  The cost of a run is its time-loop time without
output, from touchFoam's ExecutionTime lines (the process CPU time, 0.01 s
resolution): the mean increment of ExecutionTime over the steps after the
first that wrote no fields, times the number of steps (loop_times; the
loop with output is kept too, 'loopCPUWithOutput').  A run
whose loop takes less than 2 s is repeated (at most 15 times in all, the
outputs cleared in between; the tutorial's setting on the tutorial's mesh at
least 3 times, for the spread) and the mean is used (ExecutionTime ticks
every 0.01 s: the mean of repeats resolves a run shorter than a few ticks,
their least or median would not; a run whose every repeat read 0 has no
cost); the user CPU time (getrusage, the whole process with its start-up)
and the wall time of every repeat are kept too.  One run at a time.

Energy: for every run the largest growth of the solidMonitor's totalEnergy
in one step, over E0 (the energy of 0/: kinetic from lm, strain from F;
E_{-1} = E0); a run that gained energy (> 1e-10 E0 in a step, the
tolerance of validation/twistingColumn) or stopped is not admissible.

Recommendation (recommend(), per case): among the settings none of whose
runs gained energy, compared with the tutorial's setting on the tutorial's
mesh (cube 16, column 8): the least error at its cost, interpolated in
log-log along each setting's meshes, when its error falls with every
refinement; otherwise (the column: the twist moves away from the reference
as the mesh is refined) the cheapest setting on that mesh whose twist is
within 2 deg (half the reference band) of the tutorial setting's, loop
times within 10 % counting as a tie won by the closer twist.  Each case's
recommended setting, and the other case's, are run again on its mesh over
a longer time (cube 0.08 s, about 5 periods; column 0.3 s, the tutorial's
end time); the sweep passes when each case's own recommendation never
gains energy there.

The solver used is the touchFoam found in the PATH and the libTOUCH.so
found in LD_LIBRARY_PATH (etc/bashrc), copied to runs/build/ before the
first run so that a rebuild during the sweep cannot mix builds;
--build-label names it when it is not the git checkout of
$TOUCH_PROJECT_DIR (as validation/stabilityMap).

Writes results.json, results.md, swingingCube.png and twistingColumn.png
(matplotlib; skipped when it is missing); -quick writes them to
runs/quick/ instead, so that a check never replaces the full results.
--no-run analyses the runs in runs/ (every setting found there).
"""

import argparse
import datetime
import json
import math
import os
import resource
import shutil
import statistics
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
VALIDATION = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(VALIDATION, "..", "bin", "python"))
for _folder in ("swingingCube", "twistingColumn", "stabilityMap"):
    sys.path.insert(0, os.path.join(VALIDATION, _folder))

from touchfoam import analytic, cases, postprocess, run  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402
import convergence  # noqa: E402  (validation/swingingCube)
import stabilityMap  # noqa: E402  (validation/stabilityMap)
import twist  # noqa: E402  (validation/twistingColumn)

RECONSTRUCTIONS = ["firstOrder", "linear", "limitedLinear"]
# (timeScheme, CFL); the largest of each scheme is its measured limit
TIME_SETTINGS = [("RK2", 0.3), ("RK2", 0.5), ("RK2", 0.7),
                 ("RK3", 0.5), ("RK3", 1.0)]
MAX_ROUNDS = 3
MIN_TIMED = 2.0         # repeat a run until its loop times add up to this [s]
MAX_REPEATS = 15
REFERENCE_REPEATS = 3   # the tutorial's setting on its mesh: the timing noise
EXTRAPOLATE = 4.0       # log-log extrapolation beyond the finest mesh's cost
COST_TIE = 0.1          # loop times closer than this (relative) are a tie
ERROR_TIE = 0.1         # errors at equal cost closer than this: a tie
RUN_INFO = "accuracyVsCost.json"

TWIST_REFERENCE = 330.7                 # deg, mean top twist at 0.1 s
TWIST_BAND = (328.9, 332.6)             # deg, validation/calculix

CASES = {
    "swingingCube": {
        "tutorial": "swingingCube", "nu": None,
        "meshes": [8, 16, 32], "quickMeshes": [8, 16], "tutorialMesh": 16,
        "default": ("linear", "RK2", 0.3),
        # one write, at the time compared.  The tutorial writes every 1 ms:
        # on 32^3 (linear, RK3, CFL 1.0) those writes took half the loop
        # time (2.6 and 3.1 s against 1.2 and 1.3 s), and adjustableRunTime
        # shortens steps to land on them (20 steps against 18)
        "control": {"endTime": convergence.T_END, "writePrecision": 17,
                    "writeInterval": convergence.T_END},
        "energyEnd": 0.08, "quantity": None,
    },
    "twistingColumn": {
        "tutorial": "twistingColumn", "nu": 0.45,
        "meshes": [4, 6, 8, 12], "quickMeshes": [4, 6], "tutorialMesh": 8,
        "default": ("limitedLinear", "RK2", 0.3),
        "control": {"endTime": twist.T_TWIST, "writeInterval": 0.02},
        # the tutorial's setting also on 16 x 96 x 16 (full sweep only):
        # does the twist settle?
        "anchorMeshes": [16],
        "energyEnd": 0.3,
        # the recommendation when the error does not fall with refinement:
        # the twist within the reference band's half-width of the tutorial
        # setting's
        "quantity": "twistDeg",
        "tolerance": 0.5 * (TWIST_BAND[1] - TWIST_BAND[0]),
    },
}


# -- settings -----------------------------------------------------------------

def label(s):
    """'linear-RK2-CFL0.3' for s = (reconstruction, scheme, CFL)."""
    return "%s-%s-CFL%s" % s


def parse_label(text):
    r, scheme, cfl = text.split("-")
    return r, scheme, float(cfl[3:])


def one_at_a_time(default):
    r0, scheme0, cfl0 = default
    out = [(r, scheme0, cfl0) for r in RECONSTRUCTIONS]
    out += [(r0, sc, c) for sc, c in TIME_SETTINGS if (sc, c) != (scheme0,
                                                                   cfl0)]
    return out


def case_dir(name, s, n, kind="sweep"):
    return os.path.join(HERE, "runs", name, kind, "%s-n%d" % (label(s), n))


# -- the build ----------------------------------------------------------------

def snapshot_build(build_label):
    """Copy touchFoam and libTOUCH.so to runs/build; the environment that
    runs them, and what they are."""
    info = stabilityMap.build_info(build_label)
    if not (info["touchFoam"] and info["libTOUCH"]):
        raise run.RunError("touchFoam or libTOUCH.so not found: source "
                           "etc/bashrc")
    dst = os.path.join(HERE, "runs", "build")
    for sub, src in (("bin", info["touchFoam"]), ("lib", info["libTOUCH"])):
        os.makedirs(os.path.join(dst, sub), exist_ok=True)
        shutil.copy2(src, os.path.join(dst, sub))
    copy = os.path.join(dst, "lib", "libTOUCH.so")
    if stabilityMap._md5(copy) != info["libTOUCHmd5"]:
        raise run.RunError("libTOUCH.so changed while it was copied; "
                           "run again")
    env = {"PATH": os.path.join(dst, "bin") + os.pathsep
           + os.environ["PATH"],
           "LD_LIBRARY_PATH": os.path.join(dst, "lib") + os.pathsep
           + os.environ.get("LD_LIBRARY_PATH", "")}
    info["snapshot"] = dst
    return env, info


# -- one run ----------------------------------------------------------------

def loop_times(log, write_times=()):
    """{steps, loopCPU, loopCPUWithOutput, clockTime} from log.touchFoam.

    loopCPUWithOutput is ExecutionTime at the last step minus that at the
    first, times steps/(steps - 1) (the first step counted at the mean
    cost).  loopCPU leaves out the steps that wrote fields (those ending at
    write_times): the mean of the other steps' ExecutionTime increments
    times steps.  The output is the same for every setting on a mesh, and
    its time varied with the other jobs' disk use: on 32^3 the single write
    of the cube took from 0.4 to 1.5 s of a 1.4-2.5 s loop.
    """
    times, values, clock = [], [], None
    with open(log, errors="replace") as f:
        for line in f:
            if line.startswith("Time = "):
                times.append(float(line.split()[2]))
            elif line.startswith("ExecutionTime") and len(times) > len(
                    values):
                values.append(float(line.split()[2]))
                clock = float(line.split("ClockTime =")[1].split()[0])
    steps = len(values)
    out = {"steps": steps, "loopCPU": None, "loopCPUWithOutput": None,
           "clockTime": clock}
    if steps < 2:
        return out
    out["loopCPUWithOutput"] = (values[-1] - values[0]) * steps / (steps - 1)
    writes = [float(w) for w in write_times]
    plain = [b - a for t, a, b in zip(times[1:], values, values[1:])
             if not any(abs(t - w) <= 1e-9 * max(1.0, w) for w in writes)]
    if plain:
        out["loopCPU"] = sum(plain) / len(plain) * steps
    return out


def clear_outputs(case):
    """Remove what touchFoam wrote (time folders > 0, postProcessing)."""
    for t, name in run.time_dirs(case).items():
        if t > 0:
            shutil.rmtree(os.path.join(case, name))
    shutil.rmtree(os.path.join(case, "postProcessing"), ignore_errors=True)


def timed_run(case, env):
    """One touchFoam run: {loop, user, sys, wall, clock, steps, load}."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    load = os.getloadavg()[0]
    start = time.monotonic()
    try:
        run.run(["touchFoam"], case, env=env)
        error = None
    except run.RunError as err:
        error = (stabilityMap.fatal_message(os.path.join(case,
                                                         "log.touchFoam"))
                 or str(err).split("\n")[0])
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    times = loop_times(os.path.join(case, "log.touchFoam"),
                       [t for t in run.time_dirs(case) if t > 0])
    return {"runError": error, "steps": times["steps"],
            "loopCPU": times["loopCPU"],
            "loopCPUWithOutput": times["loopCPUWithOutput"],
            "userCPU": after.ru_utime - before.ru_utime,
            "sysCPU": after.ru_stime - before.ru_stime,
            "wall": wall, "clockTime": times["clockTime"],
            "loadAverage1min": load}


def run_point(name, s, n, env, build, kind="sweep", end=None, rnd=None):
    """Prepare and run setting s on mesh n; writes <case>/accuracyVsCost.json.

    kind 'sweep' times the run (repeats); 'energy' runs once to `end`.
    """
    spec = CASES[name]
    case = case_dir(name, s, n, kind)
    control = dict(spec["control"])
    if end is not None:
        control.update({"endTime": end, "writeInterval": end})
    r, scheme, cfl = s
    print("%-14s %-28s n = %-3d %s" % (name, label(s), n, kind), flush=True)
    info = {"case": name, "setting": label(s), "reconstruction": r,
            "timeScheme": scheme, "CFL": cfl, "n": n, "kind": kind,
            "round": rnd,
            "control": control, "date": datetime.datetime.now().isoformat(
                timespec="seconds"), "libTOUCHmd5": build["libTOUCHmd5"],
            "repeats": []}
    cases.prepare(spec["tutorial"], case, n=n, nu=spec["nu"],
                  touch={"reconstruction": r, "timeScheme": scheme,
                         "CFL": cfl}, control=control)
    least = REFERENCE_REPEATS if (s == spec["default"] and n ==
                                  spec["tutorialMesh"]) else 1
    while True:
        rep = timed_run(case, env)
        info["repeats"].append(rep)
        loops = [x["loopCPU"] or 0.0 for x in info["repeats"]]
        if (kind != "sweep" or rep["runError"]
                or len(loops) >= max(least, MAX_REPEATS)
                or (sum(loops) >= MIN_TIMED and len(loops) >= least)):
            break
        clear_outputs(case)
    info["runError"] = info["repeats"][-1]["runError"]
    with open(os.path.join(case, RUN_INFO), "w") as f:
        json.dump(info, f, indent=2)
    return info


# -- measurements of one run --------------------------------------------------

def initial_energy(case):
    """Total energy of 0/: kinetic sum V |lm|^2/(2 rho0) plus the strain
    energy of 0/F (linearElastic or neoHookean, as the laws' strainEnergy)."""
    mat = cases.material(case)
    m = PolyMesh(case)
    F = read_field(os.path.join(case, "0", "F")).internal(m.n_cells)
    F = F.reshape(-1, 3, 3)
    lam, mu = analytic.lame(mat["E"], mat["nu"])
    if mat["model"] == "linearElastic":
        eps = 0.5 * (F + np.transpose(F, (0, 2, 1))) - np.eye(3)
        tr = np.trace(eps, axis1=1, axis2=2)
        w = mu * np.sum(eps * eps, axis=(1, 2)) + 0.5 * lam * tr ** 2
    elif mat["model"] == "neoHookean":
        J = np.linalg.det(F)
        kappa = lam + 2.0 * mu / 3.0
        w = (0.5 * mu * (J ** (-2.0 / 3.0) * np.sum(F * F, axis=(1, 2)) - 3)
             + 0.5 * kappa * (J - 1) ** 2)
    else:
        raise ValueError("%s: no strain energy for model %s"
                         % (case, mat["model"]))
    return postprocess.initial_energy(case) + float(np.sum(m.cell_volumes
                                                           * w))


def energy_behaviour(case):
    """{E0, maxGrowth (largest one-step growth / E0, the first step from
    E0 included), kept (last / E0), samples}."""
    E0 = initial_energy(case)
    E = read_monitor(case)["totalEnergy"]
    growth = np.diff(np.concatenate([[E0], E])) / E0
    return {"E0": E0, "maxGrowth": float(growth.max()),
            "stepsWithGrowth": int(np.sum(growth > 0)),
            "kept": float(E[-1] / E0), "samples": len(E)}


def cube_errors(case):
    errs = postprocess.swinging_cube_errors(case, convergence.T_END)
    amp_v, amp_P = convergence.amplitudes()

    def rms(comps):
        return float(math.sqrt(sum(errs[c]["L2"] ** 2 for c in comps)
                               / len(comps)))
    ev, eP = rms(("vx", "vy", "vz")), rms(("Pxx", "Pyy", "Pzz"))
    return {"velocityL2": ev, "stressL2": eP, "velocity": ev / amp_v,
            "stress": eP / amp_P, "error": max(ev / amp_v, eP / amp_P)}


def column_errors(case):
    history = postprocess.column_twist(case, t_end=twist.T_TWIST)
    at = [a for t, a in history if abs(t - twist.T_TWIST) < 1e-9]
    if not at:
        raise ValueError("%s: no twist at t = %g" % (case, twist.T_TWIST))
    deg = math.degrees(at[0])
    return {"twistDeg": deg, "signedErrorDeg": deg - TWIST_REFERENCE,
            "error": abs(deg - TWIST_REFERENCE)}


def analyse_point(case):
    """The row of one run folder (None when it was not run)."""
    try:
        with open(os.path.join(case, RUN_INFO)) as f:
            info = json.load(f)
    except (OSError, ValueError):
        return None
    reps = info.pop("repeats")
    row = dict(info)
    loops = [x["loopCPU"] for x in reps if x["loopCPU"] is not None]
    stages = {"RK2": 2, "RK3": 3}[info["timeScheme"]]
    row.update({
        "repeats": len(reps), "steps": reps[-1]["steps"], "stages": stages,
        "cost": statistics.mean(loops) if loops and max(loops) > 0
        else None,
        "loopCPUWithOutput": statistics.mean(
            x["loopCPUWithOutput"] for x in reps
            if x.get("loopCPUWithOutput") is not None)
        if any(x.get("loopCPUWithOutput") is not None for x in reps)
        else None,
        "loopCPUAll": loops,
        "loopCPUSpread": (max(loops) - min(loops)) / statistics.median(loops)
        if len(loops) > 1 and statistics.median(loops) > 0 else None,
        "userCPU": statistics.mean(x["userCPU"] for x in reps),
        "wall": statistics.mean(x["wall"] for x in reps),
        "clockTime": reps[-1]["clockTime"],
        "loadAverage1min": max(x["loadAverage1min"] for x in reps),
    })
    try:
        row["cells"] = PolyMesh(case).n_cells
        if row["cost"] and row["steps"]:
            # the noise-free part of the cost is cells x steps x stages
            row["usPerCellStage"] = 1e6 * row["cost"] / (
                row["cells"] * row["steps"] * stages)
        row["energy"] = energy_behaviour(case)
        if row["runError"] is None and row["kind"] == "sweep":
            row.update(cube_errors(case) if row["case"] == "swingingCube"
                       else column_errors(case))
    except (OSError, ValueError, run.RunError) as err:
        row["runError"] = row["runError"] or str(err)
    return row


# -- fronts and the recommendation --------------------------------------------

def admissible(r):
    """The run reached its end and its energy never grew in a step."""
    return (not r.get("runError") and "energy" in r
            and r["energy"]["maxGrowth"] <= twist.ENERGY_TOL)


def pareto(points, key="error"):
    """The admissible points (dicts with cost and key) no cheaper one beats,
    by cost."""
    good = sorted((p for p in points if p.get("cost") is not None
                   and p.get(key) is not None and admissible(p)),
                  key=lambda p: p["cost"])
    front, best = [], math.inf
    for p in good:
        if p[key] < best:
            front.append(p)
            best = p[key]
    return front


def front_levels(rows):
    """(reconstructions, time settings) that are on a Pareto front of their
    factor: on some mesh, the reconstructions on the front of the runs that
    share a time setting, and the time settings on the front of the runs
    that share a reconstruction."""
    recs, times = set(), set()
    for n in {r["n"] for r in rows}:
        here = [parse_label(r["setting"]) + (r,) for r in rows
                if r["n"] == n]
        for t in {h[1:3] for h in here}:
            recs |= {parse_label(r["setting"])[0] for r in pareto(
                [h[3] for h in here if h[1:3] == t])}
        for rec in {h[0] for h in here}:
            times |= {parse_label(r["setting"])[1:] for r in pareto(
                [h[3] for h in here if h[0] == rec])}
    return recs, times


def closure(settings, rows):
    """The combinations of front_levels(rows) not in settings."""
    recs, times = front_levels(rows)
    return sorted({(r,) + t for r in recs for t in times} - set(settings),
                  key=label)


def _loglog(pts, x):
    """log-log interpolation in the (x, y) points sorted by x at x; beyond
    the last point, extrapolation of the last segment up to EXTRAPOLATE
    times its x.  (y, extrapolated) or (None, None)."""
    pts = [(a, b) for a, b in pts if a > 0 and b > 0]
    for (x1, y1), (x2, y2) in zip(pts, pts[1:]):
        last = (x2, y2) == pts[-1]
        if x2 > x1 and x1 <= x <= (x2 * EXTRAPOLATE if last else x2):
            w = math.log(x / x1) / math.log(x2 / x1)
            return math.exp((1 - w) * math.log(y1) + w * math.log(y2)), \
                x > x2
    return None, None


def by_setting(rows):
    out = {}
    for r in rows:
        out.setdefault(r["setting"], []).append(r)
    return out


def energy_grows(rows):
    """True when a run of these gained energy in a step (or stopped)."""
    return not all(admissible(r) for r in rows)


def converges(rows):
    """The errors of one setting fall with every refinement."""
    e = [r.get("error") for r in sorted(rows, key=lambda r: r["n"])]
    return None not in e and all(b < a for a, b in zip(e, e[1:]))


def recommend(name, rows, meshes):
    """The recommended setting of a case, from its rows.

    The reference is the tutorial's setting on the tutorial's mesh (the
    largest mesh run when that is not).  Settings whose runs gained energy
    in a step on some mesh (or stopped) are not eligible.
      equal cost  (when the reference setting's error falls with every
                  refinement) each setting's error at the reference's cost,
                  interpolated in log-log along its meshes; the least wins.
                  Also its cost at the reference's error (the speed-up).
      tolerance   (otherwise: the error is not a discretisation error that
                  refinement removes, and a smaller one on a coarser mesh
                  is luck) on the reference mesh, the cheapest setting
                  whose `quantity` is within `tolerance` of the reference
                  setting's; settings within COST_TIE of its cost are a tie,
                  won by the one closest to the reference setting.
    """
    spec = CASES[name]
    n_ref = spec["tutorialMesh"] if spec["tutorialMesh"] in meshes \
        else max(meshes)
    settings = by_setting(rows)
    default = label(spec["default"])
    ref = [r for r in settings.get(default, []) if r["n"] == n_ref]
    if not ref or ref[0].get("cost") is None or ref[0].get("error") is None:
        return None
    ref = ref[0]
    out = {"mesh": n_ref, "defaultSetting": default,
           "referenceCost": ref["cost"], "referenceError": ref["error"],
           "defaultConverges": converges(settings[default]),
           "frontOnMesh": [r["setting"] for r in pareto(
               [r for r in rows if r["n"] == n_ref])]}
    ranking = []
    if out["defaultConverges"] or not spec.get("quantity"):
        out["rule"] = "equalCost"
        for s, v in settings.items():
            pts = sorted((r["cost"], r["error"]) for r in v
                         if r.get("cost") and r.get("error"))
            e, extra_e = _loglog(pts, ref["cost"])
            c, extra_c = _cost_at_error(pts, ref["error"])
            ranking.append({"setting": s, "errorAtCost": e,
                            "costAtError": c,
                            "extrapolated": bool(extra_e or extra_c),
                            "energyGrows": energy_grows(v)})
        ranking.sort(key=lambda x: (x["errorAtCost"] is None,
                                    x["errorAtCost"] or 0))
    else:
        out["rule"] = "tolerance"
        key, tol = spec["quantity"], spec["tolerance"]
        out.update({"quantity": key, "tolerance": tol,
                    "referenceQuantity": ref[key]})
        for s, v in settings.items():
            here = [r for r in v if r["n"] == n_ref]
            if not here or here[0].get(key) is None:
                continue
            r = here[0]
            ranking.append({"setting": s, "cost": r["cost"],
                            "quantity": r[key],
                            "deviation": r[key] - ref[key],
                            "within": abs(r[key] - ref[key]) <= tol,
                            "energyGrows": energy_grows(v)})
        ranking.sort(key=lambda x: (not x["within"], x["cost"]))
    out["ranking"] = ranking

    def choose(candidates):
        """The first of candidates; on a cost tie (tolerance rule) the one
        closest to the reference setting.  (setting, the tied settings)"""
        if not candidates:
            return None, []
        if out["rule"] != "tolerance":
            best = candidates[0]["errorAtCost"]
            return candidates[0]["setting"], [
                x["setting"] for x in candidates
                if x["errorAtCost"] <= best * (1 + ERROR_TIE)]
        ties = [x for x in candidates
                if x["cost"] <= candidates[0]["cost"] * (1 + COST_TIE)]
        best = min(ties, key=lambda x: abs(x["deviation"]))
        return best["setting"], [x["setting"] for x in ties]

    usable = [x for x in ranking if x.get("within", True)
              and (x.get("errorAtCost") is not None
                   or out["rule"] == "tolerance")]
    out["setting"], out["tied"] = choose(
        [x for x in usable if not x["energyGrows"]])
    out["bestIgnoringEnergy"] = choose(usable)[0]
    return out


def _cost_at_error(pts, error):
    """Cost at which a setting's (cost, error) curve reaches `error`
    (log-log, the error falling along the curve)."""
    for (c1, e1), (c2, e2) in zip(pts, pts[1:]):
        if e2 < e1 and e2 <= error <= e1:
            w = math.log(error / e1) / math.log(e2 / e1)
            return math.exp((1 - w) * math.log(c1) + w * math.log(c2)), False
    return None, None


# -- the sweep ----------------------------------------------------------------

def sweep_rows(name, meshes):
    """Rows of every sweep run folder of case `name` on `meshes`."""
    folder = os.path.join(HERE, "runs", name, "sweep")
    rows = []
    for entry in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        row = analyse_point(os.path.join(folder, entry))
        if row and row["n"] in meshes:
            rows.append(row)
    return rows


def sweep(name, meshes, anchors, env, build):
    """Run round 0 and the closure rounds on `meshes`, then the tutorial's
    setting on `anchors`; {setting: round}."""
    settings = {}
    todo = one_at_a_time(CASES[name]["default"])
    for rnd in range(MAX_ROUNDS + 1):
        for s in todo:
            settings[label(s)] = rnd
            for n in meshes:
                run_point(name, s, n, env, build, rnd=rnd)
        rows = [r for r in sweep_rows(name, meshes)
                if r["setting"] in settings and r["n"] in meshes]
        todo = closure([parse_label(s) for s in settings], rows)
        if not todo or rnd == MAX_ROUNDS:
            break
        print("%s: round %d adds %s" % (name, rnd + 1,
                                        ", ".join(map(label, todo))))
    for n in anchors:
        run_point(name, CASES[name]["default"], n, env, build, rnd=0)
    return settings


def analyse_case(name, meshes, rounds=None):
    rows = sweep_rows(name, meshes)
    if rounds is not None:
        rows = [r for r in rows if r["setting"] in rounds]
    for r in rows:
        # --no-run: the round each run recorded
        r["round"] = r.get("round") if rounds is None \
            else rounds[r["setting"]]
    keys = ["error"] + (["velocity", "stress"] if name == "swingingCube"
                        else [])
    fronts = {k: [(r["setting"], r["n"]) for r in pareto(rows, k)]
              for k in keys}
    for r in rows:
        r["onFront"] = (r["setting"], r["n"]) in fronts["error"]
    return {"rows": sorted(rows, key=lambda r: (r["n"], r.get("cost") or 0)),
            "fronts": fronts, "costPerCellStage": cost_summary(rows),
            "recommended": recommend(name, rows, meshes)}


def cost_summary(rows):
    """{reconstruction: {n: [min, median, max] us per cell-stage}} over the
    runs whose loop took at least MIN_TIMED s in all: the spread at fixed
    reconstruction and mesh is the timing noise (and the per-step work
    that depends on the time scheme: the step size, the writes)."""
    out = {}
    for r in rows:
        if r.get("usPerCellStage") and sum(r["loopCPUAll"]) >= MIN_TIMED:
            out.setdefault(r["reconstruction"], {}).setdefault(
                r["n"], []).append(r["usPerCellStage"])
    return {rec: {n: [min(v), statistics.median(v), max(v)]
                  for n, v in sorted(d.items())} for rec, d in out.items()}


def energy_check(name, setting, n, env, build, do_run):
    """Run `setting` on mesh n of case `name` to the case's energyEnd; its
    energy behaviour (None when it was not run)."""
    s = parse_label(setting)
    end = CASES[name]["energyEnd"]
    if do_run:
        run_point(name, s, n, env, build, kind="energy", end=end)
    row = analyse_point(case_dir(name, s, n, "energy"))
    if row is None:
        return None
    e = row.get("energy", {})
    return {"setting": setting, "n": n, "endTime": end,
            "runError": row["runError"], "steps": row["steps"],
            "cost": row["cost"], "energy": e,
            "pass": bool(row["runError"] is None and e
                         and e["maxGrowth"] <= twist.ENERGY_TOL)}


def energy_checks(results, env, do_run):
    """Every case's recommended setting on every case's reference mesh:
    'energyCheck' (its own) and 'energyCrossChecks' (the others')."""
    recs = [out["recommended"]["setting"] for out in
            results["cases"].values() if out["recommended"]
            and out["recommended"]["setting"]]
    for name, out in results["cases"].items():
        out["energyCheck"], out["energyCrossChecks"] = None, []
        if not out["recommended"]:
            continue
        own = out["recommended"]["setting"]
        for setting in ([own] if own else []) + sorted(set(recs) - {own}):
            chk = energy_check(name, setting, out["recommended"]["mesh"],
                               env, results["build"], do_run)
            if setting == own:
                out["energyCheck"] = chk
            elif chk:
                out["energyCrossChecks"].append(chk)


# -- report -------------------------------------------------------------------

def _f(x, fmt):
    return "-" if x is None else fmt % x


def table(name, rows):
    cube = name == "swingingCube"
    head = ["n", "cells", "setting", "round", "steps", "loop CPU [s]",
            "repeats", "us/cell-stage", "user CPU [s]", "wall [s]"]
    head += (["e(v)/(U0 w)", "e(P)/P_amp", "error"] if cube
             else ["twist 0.1 s [deg]", "error [deg]"])
    head += ["dE/E0 max", "E_end/E0", "front"]
    lines = ["| " + " | ".join(head) + " |",
             "|" + "|".join("---" for _ in head) + "|"]
    for r in rows:
        e = r.get("energy", {})
        cells = [str(r["n"]), _f(r.get("cells"), "%d"), r["setting"],
                 _f(r.get("round"), "%d"), _f(r.get("steps"), "%d"),
                 _f(r.get("cost"), "%.2f"), str(r["repeats"]),
                 _f(r.get("usPerCellStage"), "%.2f"),
                 _f(r.get("userCPU"), "%.2f"), _f(r.get("wall"), "%.2f")]
        if cube:
            cells += [_f(r.get("velocity"), "%.2e"),
                      _f(r.get("stress"), "%.2e"), _f(r.get("error"), "%.2e")]
        else:
            cells += [_f(r.get("twistDeg"), "%.1f"),
                      _f(r.get("signedErrorDeg"), "%+.1f")]
        cells += [_f(e.get("maxGrowth"), "%.1e"), _f(e.get("kept"), "%.3f"),
                  "**yes**" if r["onFront"] else ""]
        lines.append("| " + " | ".join(cells) + " |")
    failed = [r for r in rows if r.get("runError")]
    if failed:
        lines += ["", "Runs that stopped:"] + [
            "- %s n = %d: %s" % (r["setting"], r["n"], r["runError"])
            for r in failed]
    return "\n".join(lines)


def recommendation_text(name, out):
    rec, chk = out["recommended"], out.get("energyCheck")
    if not rec:
        return "No recommendation: the tutorial's setting was not run."
    fmt = "%.3g deg" if name == "twistingColumn" else "%.3g"
    grows = [x["setting"] for x in rec["ranking"] if x["energyGrows"]]
    text = ["Reference: the tutorial's setting %s on n = %d, %.2f s of loop "
            "CPU, error %s; its error %s with every refinement."
            % (rec["defaultSetting"], rec["mesh"], rec["referenceCost"],
               fmt % rec["referenceError"],
               "falls" if rec["defaultConverges"] else "does NOT fall"), ""]
    if rec["rule"] == "equalCost":
        text += ["Each setting's error at the reference's cost and its cost "
                 "at the reference's error, interpolated in log-log along "
                 "its meshes (x: extrapolated at most %gx beyond the finest "
                 "mesh's cost; E: gained energy in a step on some mesh):"
                 % EXTRAPOLATE, "",
                 "| setting | error at %.2f s | loop CPU for error %s |"
                 % (rec["referenceCost"], fmt % rec["referenceError"]),
                 "|---|---|---|"]
        for x in rec["ranking"]:
            text.append("| %s%s%s | %s | %s |" % (
                x["setting"], " x" if x["extrapolated"] else "",
                " E" if x["energyGrows"] else "",
                _f(x["errorAtCost"], fmt), _f(x["costAtError"], "%.2f s")))
    else:
        text += ["The error is then no discretisation error that refinement "
                 "removes (a smaller one on a coarser mesh is a "
                 "cancellation), so the settings are compared on n = %d: the "
                 "cheapest whose %s is within %g of the reference setting's "
                 "(%.1f; E: gained energy in a step on some mesh):"
                 % (rec["mesh"], rec["quantity"], rec["tolerance"],
                    rec["referenceQuantity"]), "",
                 "| setting | loop CPU [s] | %s | difference |"
                 % rec["quantity"], "|---|---|---|---|"]
        for x in rec["ranking"]:
            text.append("| %s%s | %.2f | %.1f | %+.1f%s |" % (
                x["setting"], " E" if x["energyGrows"] else "", x["cost"],
                x["quantity"], x["deviation"],
                "" if x["within"] else " (outside)"))
    if len(rec.get("tied", [])) > 1:
        text += ["", ("Within %.0f %% of the cheapest loop time (a tie, won "
                      "by the smaller difference): %s." if rec["rule"] ==
                      "tolerance" else "Within %.0f %% of the least error "
                      "at that cost (a tie within the timing noise): %s.")
                 % (100 * (COST_TIE if rec["rule"] == "tolerance"
                           else ERROR_TIE), ", ".join(rec["tied"]))]
    text += ["", "Recommended (energy never grew in its runs): **%s**%s.  "
             "Pareto front on n = %d (cheapest first): %s."
             % (rec["setting"], "" if rec["setting"] ==
                rec["bestIgnoringEnergy"] else
                " (%s ranks first but gained energy)"
                % rec["bestIgnoringEnergy"], rec["mesh"],
                ", ".join(rec["frontOnMesh"]))]
    if grows:
        text += ["", "Gained energy in a step on some mesh: %s."
                 % ", ".join(sorted(grows))]
    for i, chk in enumerate([chk] + out.get("energyCrossChecks", [])):
        if not chk:
            continue
        e = chk["energy"]
        text += ["", "%s of %s on n = %d to t = %g s (%d steps): largest "
                 "growth in a step %.1e E0, %d steps with growth, %.3f E0 "
                 "kept: %s." % ("Energy" if i == 0 else
                                "Cross-check (another case's "
                                "recommendation): energy",
                                chk["setting"], chk["n"], chk["endTime"],
                                chk["steps"], e["maxGrowth"],
                                e["stepsWithGrowth"], e["kept"],
                                ("never grows" + (" (pass)" if i == 0
                                                  else "")) if chk["pass"]
                                else "GROWS" + (" (fail)" if i == 0
                                                else ""))]
    return "\n".join(text)


def write_markdown(results, path):
    b = results["build"]
    lines = [
        "# Accuracy against cost: results", "",
        "Produced by `%s` on %s in %.0f s, build %s (libTOUCH.so md5 %s).  "
        "Cost: touchFoam time-loop CPU time (ExecutionTime, the mean of the "
        "repeats); 'user CPU' is the whole process (getrusage), 'wall' the "
        "process's wall time, both means of the repeats.  `round`: 0 "
        "one factor at a time around the tutorial's setting, k > 0 added by "
        "the front closure.  `dE/E0 max`: largest one-step growth of the "
        "total energy over E0 (<= 0: never grows).  `front`: on the Pareto "
        "front of all the case's admissible runs (end reached, energy never "
        "grew)." % (results["command"], results["date"],
                    results["duration"], b["label"],
                    (b["libTOUCHmd5"] or "?")[:12]), ""]
    for name, out in results["cases"].items():
        lines += ["## %s" % name, ""]
        if name == "swingingCube":
            lines += ["Errors at t = %g s relative to the amplitudes; error = "
                      "the larger of the two." % convergence.T_END, ""]
        else:
            lines += ["Twist at 0.1 s; error = twist - %g deg (reference band "
                      "%g-%g deg)." % ((TWIST_REFERENCE,) + TWIST_BAND), ""]
        lines += [table(name, out["rows"]), ""]
        summary = out["costPerCellStage"]
        if summary:
            lines += ["Loop CPU per cell and Runge-Kutta stage [us], min / "
                      "median / max over the runs of a reconstruction on a "
                      "mesh (runs of at least %g s of loop in all):"
                      % MIN_TIMED, "",
                      "| reconstruction | " + " | ".join(
                          "n = %s" % n for n in out["meshes"]) + " |",
                      "|---|" + "---|" * len(out["meshes"])]
            for rec, d in summary.items():
                lines.append("| %s | " % rec + " | ".join(
                    "%.2f / %.2f / %.2f" % tuple(d[n]) if n in d else "-"
                    for n in out["meshes"]) + " |")
            lines.append("")
        ref = [r for r in out["rows"] if r.get("loopCPUSpread") is not None
               and r["setting"] == label(CASES[name]["default"])
               and r["n"] == CASES[name]["tutorialMesh"]]
        if ref:
            lines += ["Timing noise: the %d repeats of %s on n = %d took %s s "
                      "of loop CPU (max - min: %.0f %% of the median)."
                      % (ref[0]["repeats"], ref[0]["setting"], ref[0]["n"],
                         ", ".join("%.2f" % x for x in ref[0]["loopCPUAll"]),
                         100 * ref[0]["loopCPUSpread"]), ""]
        lines += ["### Recommended", "", recommendation_text(name, out), ""]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def plot(name, out, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: %s skipped" % os.path.basename(path))
        return
    rows = [r for r in out["rows"] if r.get("cost") and r.get("error")]
    colours = {"firstOrder": "tab:red", "linear": "tab:blue",
               "limitedLinear": "tab:green"}
    markers = dict(zip(TIME_SETTINGS, "o^sDv"))
    panels = ([("error", "error: the larger of the two"),
               ("velocity", "L2 error of v / (U0 w)"),
               ("stress", "L2 error of P_ii / P amplitude")]
              if name == "swingingCube"
              else [("error", "|twist(0.1 s) - %g deg| [deg]"
                     % TWIST_REFERENCE), ("twistDeg", "twist at 0.1 s [deg]")])
    fig, axes = plt.subplots(1, len(panels), figsize=(5.5 * len(panels), 5.8))
    for ax, (key, ylabel) in zip(axes, panels):
        by_setting = {}
        for r in rows:
            by_setting.setdefault(r["setting"], []).append(r)
        for s, pts in sorted(by_setting.items()):
            rec, scheme, cfl = parse_label(s)
            pts = sorted(pts, key=lambda r: r["n"])
            ax.plot([p["cost"] for p in pts], [p[key] for p in pts],
                    color=colours[rec], marker=markers[(scheme, cfl)],
                    lw=0.6, ms=6, mfc="none" if scheme == "RK3" else
                    colours[rec], label=s)
        bad = [r for r in rows if not admissible(r)]
        if bad:
            ax.plot([p["cost"] for p in bad], [p[key] for p in bad], "kx",
                    ms=9, label="energy grew in a step")
        if key != "twistDeg":
            front = pareto(rows, key)
            ax.plot([p["cost"] for p in front], [p[key] for p in front],
                    "k-", lw=2, alpha=0.35, label="Pareto front")
            named = set()
            for p in front:
                if p["n"] not in named:
                    named.add(p["n"])
                    ax.annotate("n=%d" % p["n"], (p["cost"], p[key]),
                                textcoords="offset points", xytext=(-6, -12),
                                fontsize=7)
            ax.set_yscale("log")
            # a run that blew up would squash the others: keep it off
            good = [r[key] for r in rows if admissible(r)]
            if good:
                ax.set_ylim(0.5 * min(good), 3 * max(good))
                off = [r for r in rows if r[key] > 3 * max(good)]
                if off:
                    ax.text(0.02, 0.98, "off the scale: %s" % ", ".join(
                        "%s n=%d (%.2g)" % (r["setting"], r["n"], r[key])
                        for r in off), transform=ax.transAxes, fontsize=6,
                        va="top")
        if name == "twistingColumn":
            if key == "error":
                ax.axhspan(1e-3, TWIST_BAND[1] - TWIST_REFERENCE,
                           color="0.85", zorder=0,
                           label="inside the reference band")
            else:
                ax.axhspan(*TWIST_BAND, color="0.85", zorder=0,
                           label="CalculiX 12x72x12: %g-%g deg" % TWIST_BAND)
                # firstOrder dissipates the twist away: keep it off the scale
                kept = [r[key] for r in rows
                        if not r["setting"].startswith("firstOrder")]
                if kept:
                    ax.set_ylim(min(kept + [TWIST_BAND[0]]) - 5,
                                max(kept) + 5)
                low = [r for r in rows if r[key] < ax.get_ylim()[0]]
                if low:
                    ax.text(0.02, 0.02, "off the scale: %d runs at %.0f-%.0f "
                            "deg (%s)" % (len(low), min(r[key] for r in low),
                                          max(r[key] for r in low),
                                          ", ".join(sorted({r["setting"] for
                                                            r in low}))),
                            transform=ax.transAxes, fontsize=6)
                for n in sorted({r["n"] for r in rows}):
                    here = [r for r in rows if r["n"] == n and r[key] >=
                            ax.get_ylim()[0]]
                    if here:
                        p = min(here, key=lambda r: r["cost"])
                        ax.annotate("n=%d" % n, (p["cost"], p[key]),
                                    textcoords="offset points",
                                    xytext=(-8, 6), fontsize=7)
        ax.set_xscale("log")
        ax.set_xlabel("touchFoam time-loop CPU time [s]")
        ax.set_ylabel(ylabel)
        ax.grid(True, which="both", lw=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center",
               ncol=4 * len(panels) - 3, fontsize=7)
    fig.suptitle("%s: error against cost (colour: reconstruction; marker: "
                 "time scheme and CFL, open = RK3)" % name, fontsize=9)
    fig.tight_layout(rect=(0, 0.12, 1, 1))
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print("wrote %s" % path)


# -- main ---------------------------------------------------------------------

def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-quick", "--quick", action="store_true",
                        help="the two coarsest meshes of each case; results "
                        "in runs/quick/")
    parser.add_argument("--case", nargs="+", choices=list(CASES),
                        default=list(CASES))
    parser.add_argument("--build-label", default=None,
                        help="name of the build when it is not the git "
                        "checkout of $TOUCH_PROJECT_DIR")
    parser.add_argument("--no-run", action="store_true",
                        help="only analyse the runs in runs/")
    args = parser.parse_args()
    start = time.monotonic()
    out_dir = os.path.join(HERE, "runs", "quick") if args.quick else HERE
    os.makedirs(out_dir, exist_ok=True)
    results = {"command": " ".join(["./accuracyVsCost.py"] + sys.argv[1:]),
               "date": datetime.date.today().isoformat(),
               "twistReference": TWIST_REFERENCE, "twistBand": TWIST_BAND,
               "norm": postprocess.NORM, "cases": {}}
    try:
        env = None
        if args.no_run:
            results["build"] = stabilityMap.build_info(args.build_label)
        else:
            run.check_openfoam()
            env, results["build"] = snapshot_build(args.build_label)
        for name in args.case:
            meshes = CASES[name]["quickMeshes" if args.quick else "meshes"]
            anchors = [] if args.quick else CASES[name].get("anchorMeshes",
                                                            [])
            rounds = None if args.no_run else sweep(name, meshes, anchors,
                                                    env, results["build"])
            out = analyse_case(name, meshes + anchors, rounds)
            out["meshes"] = meshes
            results["cases"][name] = out
        energy_checks(results, env, not args.no_run)
    except (run.RunError, OSError, ValueError) as err:
        print("accuracyVsCost: %s" % err, file=sys.stderr)
        return 1
    results["duration"] = time.monotonic() - start
    md5s = {r["libTOUCHmd5"] for out in results["cases"].values()
            for r in out["rows"]}
    results["buildsUsed"] = sorted(md5s)
    with open(os.path.join(out_dir, "results.json"), "w") as f:
        json.dump(results, f, indent=2)
    write_markdown(results, os.path.join(out_dir, "results.md"))
    for name, out in results["cases"].items():
        plot(name, out, os.path.join(out_dir, name + ".png"))
        print("\n%s\n%s" % (name, recommendation_text(name, out)))
    ok = all(out.get("energyCheck") and out["energyCheck"]["pass"]
             for out in results["cases"].values())
    print("\n%s: %s (%.0f s)" % ("PASS" if ok else "FAIL", os.path.join(
        out_dir, "results.md"), results["duration"]))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
