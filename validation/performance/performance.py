#!/usr/bin/python3
"""Throughput and memory of touchFoam (issue 11): a benchmark, not a test.

    ./performance.py [-sizes 12,26,56] [-steps 40] [-variants all]
                     [-repeat 1] [-parallel [N]] [-method scotch] [-no-run]

The twisting column (tutorials/twistingColumn, neoHookean, nu 0.45) on
n x 6n x n cells, each size of -sizes (12, 26, 56: 10,368, 105,456 and
1,053,696 cells), each variant of VARIANTS below (the tutorial's settings
with one feature switched), -steps steps each (controlDict maxSteps; the
fields are written once, at the end, and removed).  Runs one case at a
time; -repeat R runs every case of a size R times, round robin, and keeps
the fastest (a shared machine's busy spells only slow a run down).

Per run, from log.touchFoam and GNU time (/usr/bin/time -v):
  s/step        (ExecutionTime after step K-1 - ExecutionTime after step 1)
                /(K - 2), K = steps: the CPU time of the time loop alone,
                without the start-up (in step 1's figure) and the writing
                (in step K's); a step is all its Runge-Kutta stages;
  cell-steps/s  cells/(s/step), per core (the serial runs use one);
  peak kB/cell  peak resident set size/cells; 'net' subtracts the peak of
                the same run on a 2 x 12 x 2 column (48 cells), the fixed
                cost of the OpenFOAM libraries; the differences between two
                sizes of a variant, (peak_2 - peak_1)/(cells_2 - cells_1),
                are listed apart.
Machine: the triad a = b + s c of triad.c (gcc -O2, 3 arrays of 80 MB,
best of 20), and the bound it puts on throughput with the byte count of
traffic.py: cell-steps/s at bandwidth = bandwidth/(bytes per cell-step).

-parallel [N] (default 32: 196,608 cells) adds the baseline on n = N in
serial and on 2 ranks (decomposePar, -method, default scotch): parallel
efficiency T1/(2 T2), T the s/step of each (the master rank's CPU time;
Open MPI polls while it waits, so it is close to the wall time).

Writes results.json and results.md; -no-run re-reads runs/.  Checks
(checks.json, gathered by validation/Allrun; exit status 1 when one
fails): the net peak memory per cell of every run <= 2.5 kB, and the time
ratios to the baseline measured side by side (RATIO_BOUNDS: RK3 in [1.15,
2.5], firstOrder <= 1.2); no absolute timing is checked.
"""

import argparse
import glob
import json
import os
import platform
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

from touchfoam import cases, checks, run  # noqa: E402
from touchfoam.provenance import build_label  # noqa: E402

import traffic  # noqa: E402

RUNS = os.path.join(HERE, "runs")

#: A large interval: never reached by a benchmark run
NEVER = 100000000

#: Every run: maxSteps caps it, fields written once, at the end
CONTROL = {"endTime": 1000, "writeControl": "timeStep",
           "writeInterval": NEVER}

#: (name, what differs from the tutorial, TOUCH entries, controlDict
#: entries, constant/materialOptions entries)
VARIANTS = [
    ("baseline", "limitedLinear, compatible, RK2, CFL 0.3 (BASELINE_TOUCH), "
     "angular momentum preservation off, monitor every step", {}, {}, {}),
    ("linear", "reconstruction linear (no limiter)",
     {"reconstruction": "linear"}, {}, {}),
    ("firstOrder", "reconstruction firstOrder",
     {"reconstruction": "firstOrder"}, {}, {}),
    ("angularMomentum", "angularMomentumPreservation on",
     {"angularMomentumPreservation": "on"}, {}, {}),
    ("monitorOff", "solidMonitor executeInterval and writeInterval 1e8",
     {}, {"functions/solidMonitor/executeControl": "timeStep",
          "functions/solidMonitor/executeInterval": NEVER,
          "functions/solidMonitor/writeInterval": NEVER}, {}),
    ("noPointUpwinding", "pointUpwinding 0",
     {"pointUpwinding": 0}, {}, {}),
    ("plastic", "vonMisesPlastic, yieldStress 1e12 (never yields), "
     "hardeningModulus 0", {}, {},
     {"model": "vonMisesPlastic",
      "vonMisesPlasticCoeffs": {"yieldStress": 1e12,
                                "hardeningModulus": 0}}),
    ("RK3", "timeScheme RK3", {"timeScheme": "RK3"}, {}, {}),
    ("constrained", "FUpdate constrained", {"FUpdate": "constrained"},
     {}, {}),
    ("plain", "FUpdate plain", {"FUpdate": "plain"}, {}, {}),
]
VARIANT_NAMES = [v[0] for v in VARIANTS]

#: The column of the fixed memory cost (48 cells)
FIXED_N = 2

def cells_of(n):
    return 6 * n ** 3


# -- cases -----------------------------------------------------------------

#: The baseline's scheme, pinned: the column tutorial's setting when the
#: benchmark was written (the tutorial has run linear RK3 at CFL 0.8 since
#: issue 11, which the variants 'linear' and 'RK3' measure apart)
BASELINE_TOUCH = {"reconstruction": "limitedLinear", "timeScheme": "RK2",
                  "CFL": 0.3}


def base_case(n, steps):
    """runs/n<n>/mesh: the tutorial meshed and initialised at n, with the
    baseline's scheme."""
    dst = os.path.join(RUNS, "n%d" % n, "mesh")
    control = dict(CONTROL, maxSteps=steps)
    cases.prepare("twistingColumn", dst, n=n, control=control,
                  touch=BASELINE_TOUCH)
    return dst


def variant_case(base, variant):
    """A copy of the base case with the variant's entries; the mesh is
    linked, not copied."""
    name, _, touch, control, material = variant
    dst = os.path.join(os.path.dirname(base), name)
    if os.path.exists(dst):
        shutil.rmtree(dst)
    shutil.copytree(base, dst, ignore=lambda d, names: [
        x for x in names if x.startswith("log.")
        or (os.path.basename(d) == "constant" and x == "polyMesh")])
    os.symlink(os.path.join("..", "..", "mesh", "constant", "polyMesh"),
               os.path.join(dst, "constant", "polyMesh"))
    for key, value in touch.items():
        cases.set_touch(dst, key, value)
    for key, value in control.items():
        run.foam_set(dst, "system/controlDict", key, value)
    run.write_options(dst, "constant/materialOptions", material,
                      "Written by validation/performance")
    return dst


def run_touchfoam(case, repeat=1, nprocs=1, method="scotch"):
    """touchFoam under GNU time (its report goes to the log's end), to
    log.touchFoam, or log.touchFoam.<repeat> from the 2nd on; a repetition
    starts again from 0 (the outputs of the previous one are removed)."""
    for t, name in run.time_dirs(case).items():
        if t != 0:
            shutil.rmtree(os.path.join(case, name))
    shutil.rmtree(os.path.join(case, "postProcessing"), ignore_errors=True)
    log = "touchFoam" if repeat == 1 else "touchFoam.%d" % repeat
    with open(os.path.join(case, "run." + log), "w") as f:
        f.write("loadavg %s\nbuild %s\n"
                % (open("/proc/loadavg").read().split()[0], build()))
    app = ["/usr/bin/time", "-v", "touchFoam"]
    if nprocs == 1:
        run.run(app, case, log)
    else:
        run.write_options(case, "system/decomposeOptions",
                          {"numberOfSubdomains": nprocs, "method": method})
        run.run(["decomposePar", "-force"], case)
        run.run_parallel(app, case, nprocs, log)
    # The fields written at the end are of no use here (1M cells: 0.5 GB)
    for name in os.listdir(case):
        if name.startswith("processor"):
            shutil.rmtree(os.path.join(case, name))
    for t, name in run.time_dirs(case).items():
        if t != 0:
            shutil.rmtree(os.path.join(case, name))
    return os.path.join(case, "log." + log)


def build():
    """The commit and the dates of libTOUCH.so and touchFoam: a library
    rebuilt under a running benchmark shows as two builds."""
    exe = shutil.which("touchFoam")
    stamp = time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(
        os.path.getmtime(exe))) if exe else "?"
    return "%s, touchFoam of %s" % (build_label(), stamp)


# -- reading the runs ------------------------------------------------------

def read_log(log):
    """Steps, s/step, peak RSS [kB] (summed over ranks) of one run."""
    times, peaks, reached = [], [], False
    with open(log, errors="replace") as f:
        for line in f:
            if line.startswith("ExecutionTime = "):
                times.append(float(line.split()[2]))
            elif "Maximum resident set size" in line:
                peaks.append(int(line.split()[-1]))
            elif line.startswith("Reached maxSteps"):
                reached = True
    if not reached or len(times) < 3:
        raise run.RunError("%s: the run did not reach maxSteps (>= 3 steps)"
                           % log)
    k = len(times)
    out = {"steps": k, "timedSteps": k - 2,
           "secondsPerStep": (times[k - 2] - times[0]) / (k - 2),
           "timedSeconds": times[k - 2] - times[0],
           "peakKB": sum(peaks), "ranks": len(peaks),
           "startupSeconds": times[0], "loadAverage": None, "build": None}
    info = os.path.join(os.path.dirname(log),
                        "run." + os.path.basename(log)[4:])
    if os.path.exists(info):
        for line in open(info):
            key, _, value = line.partition(" ")
            if key == "loadavg":
                out["loadAverage"] = float(value)
            elif key == "build":
                out["build"] = value.strip()
    return out


def read_run(case):
    """The fastest repetition of a case (s/step), the largest peak RSS,
    and every repetition's s/step, load average and build."""
    logs = sorted(glob.glob(os.path.join(case, "log.touchFoam*")))
    if not logs:
        raise run.RunError("%s: no log.touchFoam" % case)
    runs = [read_log(log) for log in logs]
    best = dict(min(runs, key=lambda r: r["secondsPerStep"]))
    best.update(repeats=len(runs),
                secondsPerStepAll=[r["secondsPerStep"] for r in runs],
                loadAverageAll=[r["loadAverage"] for r in runs],
                peakKB=max(r["peakKB"] for r in runs),
                builds=sorted(set(r["build"] for r in runs if r["build"])))
    return best


def mesh_counts(case):
    """nCells, nInternalFaces, nPoints from the polyMesh owner header."""
    path = os.path.join(case, "constant", "polyMesh", "owner")
    with open(path, errors="replace") as f:
        head = f.read(2000)
    counts = dict((k, int(v)) for k, v in re.findall(r"(n\w+):\s*(\d+)", head))
    return counts["nCells"], counts["nInternalFaces"], counts["nPoints"]


def triad(exe, out):
    """The triad's figures (run it unless out exists and exe does not)."""
    if exe:
        text = subprocess.run([exe], capture_output=True, text=True,
                              check=True).stdout
        with open(out, "w") as f:
            f.write(text)
    words = open(out).read().split()[1:]
    d = dict(zip(words[::2], words[1::2]))
    return {"elements": int(d["n"]), "repetitions": int(d["repetitions"]),
            "bestSeconds": float(d["best_s"]),
            "GBps3arrays": float(d["GBps_3arrays"]),
            "GBps4arrays": float(d["GBps_4arrays"])}


def machine():
    model = platform.processor() or "unknown"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    mem = None
    try:
        for line in open("/proc/meminfo"):
            if line.startswith("MemTotal"):
                mem = int(line.split()[1]) // 1024
    except OSError:
        pass
    l3 = None
    try:
        size = open("/sys/devices/system/cpu/cpu0/cache/index3/size").read()
        l3 = int(size.strip().rstrip("K")) * 1024
    except (OSError, ValueError):
        pass
    return {"cpu": model, "cores": os.cpu_count(), "memoryMB": mem,
            "L3bytes": l3, "perf": perf_probe()}


def perf_probe():
    """Whether perf can count LLC-load-misses here (a VM often cannot)."""
    if not shutil.which("perf"):
        return "perf absent"
    out = subprocess.run(["perf", "stat", "-x,", "-e", "LLC-load-misses",
                          "true"], capture_output=True, text=True)
    text = out.stdout + out.stderr
    if out.returncode or "not supported" in text or "<not" in text:
        return "perf present, LLC-load-misses not supported"
    return "perf counts LLC-load-misses (not used by this benchmark)"


def source_modified():
    """Files under src/ or applications/ that differ from HEAD: the build
    measured may hold them."""
    out = subprocess.run(["git", "status", "--porcelain", "--",
                          "src", "applications"], cwd=run.project_dir(),
                         capture_output=True, text=True).stdout
    return [line[3:] for line in out.splitlines()]


# -- results ---------------------------------------------------------------

def analyse(sizes, variants, parallel, method, bandwidth):
    rows = []
    for n in sizes:
        counts = mesh_counts(os.path.join(RUNS, "n%d" % n, "mesh"))
        for name in variants:
            r = read_run(os.path.join(RUNS, "n%d" % n, name))
            r.update(variant=name, n=n, cells=counts[0],
                     cellStepsPerSecond=counts[0] / r["secondsPerStep"],
                     kBPerCell=r["peakKB"] / counts[0])
            rows.append(r)
    fixed = read_run(os.path.join(RUNS, "n%d" % FIXED_N, "baseline"))
    for r in rows:
        base = [b for b in rows if b["n"] == r["n"]
                and b["variant"] == "baseline"]
        r["timeRatio"] = (r["secondsPerStep"] / base[0]["secondsPerStep"]
                          if base else None)
        r["netKBPerCell"] = (r["peakKB"] - fixed["peakKB"]) / r["cells"]

    differences = []
    for name in variants:
        mine = [r for r in rows if r["variant"] == name]
        for a, b in zip(mine, mine[1:]):
            differences.append({
                "variant": name, "cells": [a["cells"], b["cells"]],
                "kBPerCell": (b["peakKB"] - a["peakKB"])
                / (b["cells"] - a["cells"])})

    bound = []
    for n in sizes:
        nc, nf, npt = mesh_counts(os.path.join(RUNS, "n%d" % n, "mesh"))
        est = traffic.estimate(nc, nf, npt, stages=2, monitor=True)
        measured = [r for r in rows if r["n"] == n
                    and r["variant"] == "baseline"]
        at_bw = bandwidth["GBps4arrays"] * 1e9 / est["bytesPerCellStep"]
        bound.append({
            "n": n, "cells": nc,
            "bytesPerCellStep": est["bytesPerCellStep"],
            "facesPerCell": est["facesPerCell"],
            "pointsPerCell": est["pointsPerCell"],
            "cellStepsPerSecondAtBandwidth": at_bw,
            "measuredOverBound": (measured[0]["cellStepsPerSecond"] / at_bw
                                  if measured else None)})

    par = None
    if parallel:
        cells = cells_of(parallel)
        one = read_run(os.path.join(RUNS, "n%d" % parallel, "serial"))
        two = read_run(os.path.join(RUNS, "n%d" % parallel, "twoRanks"))
        par = {"n": parallel, "cells": cells, "method": method,
               "serial": one, "twoRanks": two,
               "efficiency": one["secondsPerStep"]
               / (2 * two["secondsPerStep"]),
               "cellStepsPerSecondPerCore2": cells
               / two["secondsPerStep"] / 2}

    stage_model = traffic.estimate(*mesh_counts(os.path.join(
        RUNS, "n%d" % sizes[-1], "mesh")))
    return {
        "what": "touchFoam throughput and memory, twistingColumn "
                "(neoHookean, nu 0.45), n x 6n x n cells",
        "build": sorted(set(b for r in rows + [fixed] for b in r["builds"])),
        "sourceModified": source_modified(),
        "date": time.strftime("%Y-%m-%d %H:%M", time.localtime(max(
            os.path.getmtime(log) for log in glob.glob(
                os.path.join(RUNS, "n*", "*", "log.touchFoam*"))))),
        "machine": machine(),
        "steps": rows[0]["steps"],
        "variants": {v[0]: v[1] for v in VARIANTS if v[0] in variants},
        "fixedMemory": {"n": FIXED_N, "cells": cells_of(FIXED_N),
                        "peakKB": fixed["peakKB"]},
        "runs": rows,
        "memoryDifferences": differences,
        "triad": bandwidth,
        "traffic": {"model": "traffic.py (compulsory traffic of each "
                             "loop, write-allocate counted)",
                    "sizes": bound,
                    "perStage": stage_model["perStage"],
                    "perStep": stage_model["perStep"]},
        "parallel": par,
    }


def markdown(res):
    lines = ["# touchFoam performance: twisting column", "",
             "Build %s; run %s on %s, %d cores. Written by ./Allrun."
             % ("; ".join(res["build"]), res["date"], res["machine"]["cpu"],
                res["machine"]["cores"]), ""]
    if len(res["build"]) > 1:
        lines += ["**The build changed during the benchmark**: the runs "
                  "are not comparable (results.json gives each run's).", ""]
    if res["sourceModified"]:
        lines += ["Uncommitted changes under src/ or applications/ when "
                  "measured: %s." % ", ".join(res["sourceModified"]), ""]
    coarse = max(0.02 / r["timedSeconds"] if r["timedSeconds"] > 0
                 else 1.0 for r in res["runs"])
    repeats = max(r["repeats"] for r in res["runs"])
    lines += ["%d steps a run, timed over the %d between the first and the "
              "last; one core; the fastest of %d run%s of each case. "
              "ExecutionTime has 0.01 s steps: s/step is good to %.1f %% or "
              "better here."
              % (res["steps"], res["steps"] - 2, repeats,
                 "s" if repeats > 1 else "", 100 * coarse), "",
              "| variant | cells | steps | s/step | cell-steps/s | "
              "ratio to baseline (s/step) | peak kB/cell | net kB/cell | "
              "load |",
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in res["runs"]:
        lines.append("| %s | %d | %d | %.4g | %.4g | %s | %.2f | %.2f | %s |"
                     % (r["variant"], r["cells"], r["timedSteps"],
                        r["secondsPerStep"], r["cellStepsPerSecond"],
                        "%.3f" % r["timeRatio"] if r["timeRatio"] else "-",
                        r["kBPerCell"], r["netKBPerCell"],
                        "%.1f" % r["loadAverage"]
                        if r["loadAverage"] is not None else "-"))
    fx = res["fixedMemory"]
    lines += ["", "steps: the timed ones. net kB/cell: peak minus %d kB, "
              "the peak of the same baseline on %d cells (n = %d). load: "
              "the 1-minute load average before the fastest run (%d "
              "cores)." % (fx["peakKB"], fx["cells"], fx["n"],
                           res["machine"]["cores"]), ""]
    if res["memoryDifferences"]:
        lines += ["Memory per cell from the difference of two sizes:", "",
                  "| variant | cells | kB/cell |", "|---|---|---:|"]
        for d in res["memoryDifferences"]:
            lines.append("| %s | %d -> %d | %.3f |" % (
                d["variant"], d["cells"][0], d["cells"][1], d["kBPerCell"]))
        lines.append("")
    t = res["triad"]
    lines += ["Triad a = b + s c (%d doubles an array, best of %d): "
              "%.1f GB/s counting 3 arrays (STREAM), %.1f GB/s counting 4 "
              "(write-allocate: the traffic the memory sees)."
              % (t["elements"], t["repetitions"], t["GBps3arrays"],
                 t["GBps4arrays"]), "",
              "| cells | bytes/cell-step (model) | cell-steps/s at "
              "bandwidth | measured/bound | state/L3 |",
              "|---:|---:|---:|---:|---:|"]
    l3 = res["machine"]["L3bytes"]
    for b in res["traffic"]["sizes"]:
        base = [r for r in res["runs"] if r["cells"] == b["cells"]
                and r["variant"] == "baseline"]
        state = base[0]["netKBPerCell"] * 1024 * b["cells"] if base else 0
        lines.append("| %d | %.0f | %.4g | %s | %s |" % (
            b["cells"], b["bytesPerCellStep"],
            b["cellStepsPerSecondAtBandwidth"],
            "%.3f" % b["measuredOverBound"]
            if b["measuredOverBound"] is not None else "-",
            "%.2f" % (state / l3) if l3 else "-"))
    if l3:
        lines += ["", "state/L3: the baseline's net peak memory over the %d "
                  "MB L3; where it is below 1 or near it, the state is "
                  "largely cache-resident and the bound does not apply. %s."
                  % (l3 // 2 ** 20, res["machine"]["perf"])]
    else:
        lines += ["", "state/L3: not computed, this machine does not give "
                  "its L3 size (/sys/devices/system/cpu/cpu0/cache/index3 "
                  "is absent). %s." % res["machine"]["perf"]]
    p = res["parallel"]
    if p:
        lines += ["", "Parallel, baseline on %d cells (%s): 1 rank %.4g "
                  "s/step, 2 ranks %.4g s/step (%.4g cell-steps/s per core); "
                  "efficiency T1/(2 T2) = %.3f; peak kB/cell %.2f (1 rank), "
                  "%.2f (2 ranks summed)."
                  % (p["cells"], p["method"], p["serial"]["secondsPerStep"],
                     p["twoRanks"]["secondsPerStep"],
                     p["cellStepsPerSecondPerCore2"], p["efficiency"],
                     p["serial"]["peakKB"] / p["cells"],
                     p["twoRanks"]["peakKB"] / p["cells"])]
    return "\n".join(lines) + "\n"


# -- checks ----------------------------------------------------------------

#: Time ratios to the baseline measured side by side in one run (CPU time,
#: the fastest repetition), with generous bounds for a shared machine:
#: (variant, low, high, why)
RATIO_BOUNDS = [
    ("RK3", 1.15, 2.5, "three stages against two: 1.5 (measured 1.39 / "
     "1.37 / 2.08 on 10k / 100k / 1M cells, 2026-12-02)"),
    ("firstOrder", 0.0, 1.2, "no gradient and no limiter: less work than "
     "the baseline (measured 0.79 / 0.71 / 0.80)"),
]
#: Peak memory per cell, the fixed cost of the libraries taken off (net):
#: measured 1.45-2.06 kB over every variant and size, 2026-12-02
MAX_NET_KB_PER_CELL = 2.5


def record_checks(res):
    """checks.json (validation/Allrun): time ratios measured side by side
    and the net memory per cell; no absolute timing is checked.  Returns
    the exit status."""
    checks.start(HERE)
    for r in res["runs"]:
        checks.record(HERE, "net peak memory per cell, %s, %d cells"
                      % (r["variant"], r["cells"]), r["netKBPerCell"],
                      "<= %g kB" % MAX_NET_KB_PER_CELL,
                      r["netKBPerCell"] <= MAX_NET_KB_PER_CELL,
                      "peak minus the 48-cell run's (the libraries)")
    for name, lo, hi, why in RATIO_BOUNDS:
        for r in res["runs"]:
            if r["variant"] != name or r["timeRatio"] is None:
                continue
            checks.record(HERE, "time a step %s / baseline, %d cells"
                          % (name, r["cells"]), r["timeRatio"],
                          "[%g, %g]" % (lo, hi) if lo > 0 else "<= %g" % hi,
                          lo <= r["timeRatio"] <= hi,
                          "%s; %d timed steps, fastest of %d"
                          % (why, r["timedSteps"], r["repeats"]))
    return checks.status(HERE)


# -- main ------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("-sizes", default="12,26,56",
                    help="n of the n x 6n x n columns (default 12,26,56)")
    ap.add_argument("-steps", type=int, default=40,
                    help="steps a run, >= 3 (default 40)")
    ap.add_argument("-variants", default="all",
                    help="comma-separated, of: all, "
                    + ", ".join(VARIANT_NAMES))
    ap.add_argument("-parallel", type=int, nargs="?", const=32, default=None,
                    metavar="N", help="1 and 2 ranks on n = N (default 32)")
    ap.add_argument("-method", default="scotch",
                    help="decomposePar method for -parallel (default scotch)")
    ap.add_argument("-triad", default=os.path.join(RUNS, "triad"),
                    help="the compiled triad.c (./Allrun builds it)")
    ap.add_argument("-repeat", type=int, default=1,
                    help="runs of each case, the fastest kept (default 1)")
    ap.add_argument("-no-run", action="store_true",
                    help="re-read runs/ instead of running")
    args = ap.parse_args()

    sizes = [int(s) for s in args.sizes.split(",") if s]
    variants = (VARIANT_NAMES if args.variants == "all"
                else args.variants.split(","))
    unknown = [v for v in variants if v not in VARIANT_NAMES]
    if unknown:
        ap.error("unknown variants: %s" % ",".join(unknown))
    if args.steps < 3 or args.repeat < 1 or not sizes or min(sizes) < 4:
        ap.error("needs steps >= 3, repeat >= 1 and sizes n >= 4 (a smaller "
                 "column's loop is too short to time)")
    if "baseline" not in variants:
        variants = ["baseline"] + variants

    triad_out = os.path.join(RUNS, "triad.out")
    if not args.no_run:
        run.check_openfoam()
        os.makedirs(RUNS, exist_ok=True)
        print("triad:", end=" ", flush=True)
        bandwidth = triad(args.triad, triad_out)
        print("%.1f GB/s (3 arrays), %.1f (4 arrays)"
              % (bandwidth["GBps3arrays"], bandwidth["GBps4arrays"]))

        def measure(case, label, repeat, nprocs=1):
            print("n %s %s, run %d:" % (label, os.path.basename(case),
                                        repeat), end=" ", flush=True)
            r = read_log(run_touchfoam(case, repeat, nprocs, args.method))
            print("%.4g s/step, %.0f kB peak"
                  % (r["secondsPerStep"], r["peakKB"]))

        todo = [(FIXED_N, ["baseline"], 1)] + [(n, variants, args.repeat)
                                               for n in sizes]
        for n, names, repeats in todo:
            base = base_case(n, args.steps)
            todo_cases = [variant_case(base, v) for v in VARIANTS
                          if v[0] in names]
            # Round robin: a busy spell of the machine spreads over the
            # variants instead of falling on one
            for repeat in range(1, repeats + 1):
                for case in todo_cases:
                    measure(case, "%d (%d cells)" % (n, cells_of(n)), repeat)
        if args.parallel:
            n = args.parallel
            base = base_case(n, args.steps)
            baseline = VARIANTS[0]
            pair = [(variant_case(base, (name,) + baseline[1:]), nprocs)
                    for name, nprocs in (("serial", 1), ("twoRanks", 2))]
            for repeat in range(1, args.repeat + 1):
                for case, nprocs in pair:
                    measure(case, "%d (%d cells)" % (n, cells_of(n)), repeat,
                            nprocs)
    else:
        bandwidth = triad(None, triad_out)

    res = analyse(sizes, variants, args.parallel, args.method, bandwidth)
    with open(os.path.join(HERE, "results.json"), "w") as f:
        json.dump(res, f, indent=1)
    md = markdown(res)
    with open(os.path.join(HERE, "results.md"), "w") as f:
        f.write(md)
    print(md)
    status = record_checks(res)
    print("checks.json: %s" % ("every check passes" if status == 0
                               else "a check FAILS"))
    return status


if __name__ == "__main__":
    sys.exit(main())
