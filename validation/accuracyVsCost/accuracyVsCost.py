#!/usr/bin/python3
"""Accuracy against cost of the scheme settings (issue 11): which
reconstruction, CFL number and time scheme give the least error per second.

    ./accuracyVsCost.py [-quick] [--case swingingCube twistingColumn]
                        [--build-label LABEL] [--no-run] [--max-repeats N]

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
                    validation/twistingColumn) - reference|, the
                    converged twist and its band from both codes'
                    Richardson extrapolations
                    (validation/twistingColumn/reference.json, the
                    reference validation/calculix uses too).

Settings: reconstruction firstOrder | linear | limitedLinear, timeScheme
RK2 at CFL 0.3 0.5 0.6 and RK3 at CFL 0.5 1.0 (0.6 and 1.0 are the measured
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
cost; --max-repeats lowers the 15); the user CPU time (getrusage, the whole process with its start-up)
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

This file runs the sweep; avcAnalysis.py holds the cases, the measurements
of a run, the Pareto fronts and recommend(), avcReport.py writes results.md
and the plots.
"""

import argparse
import datetime
import json
import os
import resource
import shutil
import sys
import time

# avcAnalysis puts bin/python and validation/swingingCube, twistingColumn
# and stabilityMap on sys.path
from avcAnalysis import (CASES, HERE, MIN_TIMED, RUN_INFO, TWIST_BAND,
                         TWIST_REFERENCE, analyse_case, analyse_point,
                         case_dir, closure, label, one_at_a_time,
                         parse_label, sweep_rows)
from avcReport import plot, recommendation_text, write_markdown
from touchfoam import cases, checks, postprocess, run
import stabilityMap  # validation/stabilityMap
import twist  # validation/twistingColumn

MAX_ROUNDS = 3
MAX_REPEATS = 15
REFERENCE_REPEATS = 3   # the tutorial's setting on its mesh: the timing noise


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


# -- the sweep ----------------------------------------------------------------

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


# -- main ---------------------------------------------------------------------

def set_max_repeats(n):
    global MAX_REPEATS
    MAX_REPEATS = max(1, n)


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
    parser.add_argument("--max-repeats", type=int, default=MAX_REPEATS,
                        help="repeats of a short run for its timing at most "
                        "(default %d; validation/Allrun -quick: 3)"
                        % MAX_REPEATS)
    args = parser.parse_args()
    # The timing repeats were 89 % of a quick sweep's 1178 s on the loaded
    # machine (522 runs for 46 points); the quick check is the energy of
    # the recommended settings, which the repeats do not change
    set_max_repeats(args.max_repeats)
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
    for name, out in results["cases"].items():
        chk = out.get("energyCheck") or {}
        checks.record(HERE, "%s recommended %s: max energy growth / E0"
                      % (name, chk.get("setting")),
                      (chk.get("energy") or {}).get("maxGrowth"),
                      "<= %g" % twist.ENERGY_TOL, bool(chk.get("pass")),
                      "run failed: %s" % chk["runError"]
                      if chk.get("runError") else
                      "" if chk else "no recommended setting")
    print("\n%s: %s (%.0f s)" % ("PASS" if ok else "FAIL", os.path.join(
        out_dir, "results.md"), results["duration"]))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
