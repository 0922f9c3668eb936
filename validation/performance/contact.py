#!/usr/bin/python3
"""The cost of contact and of gravity (issue 28): a benchmark, not a test.

    validation/performance/contact.py [-cases full,partial,gravity]
        [-steps 150] [-repeat 5] [-builds DIR[,DIR2]] [-no-run]

Each case is run in variants that differ in one thing, on the same mesh,
one run at a time, alternating: variant 1, 2, .., then again, -repeat
times, so that the drift of a shared machine's speed falls on every
variant alike.  Per run, s/step is the CPU time of the time loop without
its first and last steps (start-up and writing), as performance.py reads
it from log.touchFoam (ExecutionTime); cell-steps/s = cells/(s/step).

Cases (about 100,000 cells each; README.md, "Contact and gravity"):
  full     two blocks 32 x 40 x 40 (102,400 cells) meeting face to face at
           +-0.1 m/s, the tutorial barCollision's mesh and material with a
           40 x 40 section: the whole end of each (1,600 faces) in contact
           from the first step to the last; sides symmetricPlane
             contact   the two ends bodyContact
             free      the same ends traction-free (the blocks pass
                       through each other: no contact code at all)
             nodes     contact with bar1End's side nodes
             friction  contact with Coulomb friction (mu 0.3) and side
                       auto on both ends (bar1End, the first, takes
                       nodes): the friction and sticking at the points
  partial  a block 34 x 48 x 48 hit at +-0.1 m/s by one 34 x 24 x 24 on
           the middle of its end (97,920 cells, free sides): a quarter of
           the larger end (576 of its 2,304 faces) in contact
             contact   the two ends bodyContact
             free      both traction-free
             allContact every boundary face of both blocks bodyContact
                       (15,000 faces searched, each may touch any)
  gravity  the twisting column (performance.py's baseline) at n = 26
           (105,456 cells), a single body
             noG       no constant/g: no gravity object
             gZero     constant/g (0 0 0): the body force loop runs (as
                       for any g: the same loop)

-builds A,B runs every variant with each build (a folder holding
touchFoam and libTOUCH.so, or a project tree: its platforms/*/bin and
lib), alternating builds as it alternates variants: the same case with
and without a change, side by side.

The ratios are taken pair by pair: the i-th run of a variant over the
i-th run of the case's reference (free, noG; first build), which ran
next to it; their minimum and median are given with the fastest and the
median s/step.  Writes results-contact.json and results-contact.md;
the runs go to runs/contact (git-ignored).  -no-run re-reads them.
"""

import argparse
import glob
import json
import os
import re
import shutil
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

from touchfoam import cases, run  # noqa: E402
from touchfoam.foamfile import header_text  # noqa: E402

import performance  # noqa: E402

RUNS = os.path.join(HERE, "runs", "contact")

#: Every run: maxSteps ends it, the fields written once, at the end
CONTROL = {"endTime": 1000, "writeControl": "timeStep",
           "writeInterval": performance.NEVER}

#: The friction of the full case's friction variant
FRICTION = "friction { type coulomb; muStatic 0.3; muKinetic 0.3; }"

#: Per case: reference variant, {variant: {patch: type or (type, further
#: entries)}} (two-block cases) or {variant: constant/g value or None}
#: (gravity)
CASES = {
    "full": ("free", {
        "contact": {"bar1End": "bodyContact", "bar2End": "bodyContact"},
        "free": {"bar1End": "traction", "bar2End": "traction"},
        "nodes": {"bar1End": ("bodyContact", "side nodes;"),
                  "bar2End": "bodyContact"},
        "friction": {"bar1End": ("bodyContact", "side auto; " + FRICTION),
                     "bar2End": ("bodyContact", "side auto; " + FRICTION)}}),
    "partial": ("free", {
        "contact": {"bar1End": "bodyContact", "bar2End": "bodyContact"},
        "free": {"bar1End": "traction", "bar2End": "traction"},
        "allContact": {"bar1End": "bodyContact", "bar2End": "bodyContact",
                       "ends": "bodyContact", "sides": "bodyContact"}}),
    "gravity": ("noG", {"noG": None, "gZero": "(0 0 0)"}),
}

#: The side patches of each two-block case
SIDES = {"full": "symmetricPlane", "partial": "traction"}


# -- cases -----------------------------------------------------------------

def partial_block_mesh():
    """blockMeshDict of the partial case: bar1 34 x 48 x 48 cells on
    [-L, 0] x [0, W]^2, bar2 34 x 24 x 24 on [0, L] x [W/4, 3W/4]^2, cubic
    cells h = 1/34 m; the blocks share no vertex (two bodies)."""
    n, m = 34, 48
    h = 1.0 / n
    w = m * h
    a, b = w / 4, 3 * w / 4
    v = [(-1, 0, 0), (0, 0, 0), (0, w, 0), (-1, w, 0),
         (-1, 0, w), (0, 0, w), (0, w, w), (-1, w, w),
         (0, a, a), (1, a, a), (1, b, a), (0, b, a),
         (0, a, b), (1, a, b), (1, b, b), (0, b, b)]
    verts = "\n".join("    (%.17g %.17g %.17g)" % p for p in v)
    return header_text("dictionary", "blockMeshDict", "system") + """
scale 1;

vertices
(
%s
);

blocks
(
    hex (0 1 2 3 4 5 6 7) bar1 (%d %d %d) simpleGrading (1 1 1)
    hex (8 9 10 11 12 13 14 15) bar2 (%d %d %d) simpleGrading (1 1 1)
);

boundary
(
    bar1End { type patch; faces ((1 2 6 5)); }
    bar2End { type patch; faces ((8 12 15 11)); }
    ends    { type patch; faces ((0 4 7 3) (9 10 14 13)); }
    sides
    {
        type patch;
        faces
        (
            (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)
            (8 9 13 12) (11 15 14 10) (8 11 10 9) (12 13 14 15)
        );
    }
);
""" % (verts, n, m, m, n, m // 2, m // 2)


def velocity_file(types, sides):
    """0/U of a two-block case with the given end patch types."""
    text = header_text("volVectorField", "U", "0") + """
dimensions      [0 1 -1 0 0 0 0];

internalField   uniform (0 0 0);

boundaryField
{
"""
    patches = {"bar1End": "traction", "bar2End": "traction",
               "ends": "traction", "sides": sides}
    patches.update(types)
    for name, kind in patches.items():
        kind, extra = kind if isinstance(kind, tuple) else (kind, "")
        text += ("    %s\n    {\n        type            %s;\n"
                 "        %s\n        value           uniform (0 0 0);\n"
                 "    }\n" % (name, kind, extra))
    return text + "}\n"


def two_block_mesh(name, steps):
    """runs/contact/<name>/mesh: the blocks meshed, at +-0.1 m/s (the
    tutorial barCollision's set-up and material)."""
    dst = os.path.join(RUNS, name, "mesh")
    run.copy_case(run.tutorial_dir("barCollision"), dst)
    for key, value in dict(CONTROL, maxSteps=steps).items():
        run.foam_set(dst, "system/controlDict", key, value)
    if name == "full":
        run.write_options(dst, "system/meshOptions",
                          {"variant": "equal", "N1": 32, "N2": 32, "L1": 1,
                           "L2": 1, "M": 40, "M2": 40, "v1": 0.1,
                           "v2": -0.1, "E2": 1.04e9})
    else:
        with open(os.path.join(dst, "system", "blockMeshDict"), "w") as f:
            f.write(partial_block_mesh())
    run.run(["blockMesh"], dst)
    return dst


def gravity_mesh(steps):
    dst = os.path.join(RUNS, "gravity", "mesh")
    cases.prepare("twistingColumn", dst, n=26,
                  control=dict(CONTROL, maxSteps=steps),
                  touch=performance.BASELINE_TOUCH)
    return dst


def variant_case(base, name, setting, case):
    """A copy of the base case (the mesh linked) with the variant's
    patch types, velocities set by setExprFields, or its constant/g."""
    dst = os.path.join(os.path.dirname(base), name)
    if os.path.exists(dst):
        shutil.rmtree(dst)
    shutil.copytree(base, dst, ignore=lambda d, names: [
        x for x in names if x.startswith("log.")
        or (os.path.basename(d) == "constant" and x == "polyMesh")])
    os.symlink(os.path.join("..", "..", "mesh", "constant", "polyMesh"),
               os.path.join(dst, "constant", "polyMesh"))
    if case == "gravity":
        if setting is not None:
            with open(os.path.join(dst, "constant", "g"), "w") as f:
                f.write(header_text("uniformDimensionedVectorField", "g",
                                    "constant")
                        + "\ndimensions      [0 1 -2 0 0 0 0];\n"
                        + "value           %s;\n" % setting)
    else:
        zero = os.path.join(dst, "0")
        shutil.rmtree(zero, ignore_errors=True)
        os.makedirs(zero)
        with open(os.path.join(zero, "U"), "w") as f:
            f.write(velocity_file(setting, SIDES[case]))
        run.run(["setExprFields"], dst)
    return dst


# -- builds ----------------------------------------------------------------

def build_env(folder):
    """PATH and LD_LIBRARY_PATH that select the touchFoam and libTOUCH.so
    of a folder (or of a project tree's platforms/*/bin and lib)."""
    folder = os.path.abspath(folder)
    bins = glob.glob(os.path.join(folder, "platforms", "*", "bin"))
    if bins:
        bin_dir = bins[0]
        lib_dir = os.path.join(os.path.dirname(bin_dir), "lib")
    else:
        bin_dir = lib_dir = folder
    for path in (os.path.join(bin_dir, "touchFoam"),
                 os.path.join(lib_dir, "libTOUCH.so")):
        if not os.path.exists(path):
            sys.exit("contact.py: -builds %s: no %s" % (folder, path))
    return {"PATH": bin_dir + os.pathsep + os.environ.get("PATH", ""),
            "LD_LIBRARY_PATH": lib_dir + os.pathsep
            + os.environ.get("LD_LIBRARY_PATH", "")}


def run_once(case, repeat, build, env):
    """touchFoam in case, to log.touchFoam.<build>.<repeat>; the outputs
    of the run removed afterwards."""
    for t, name in run.time_dirs(case).items():
        if t != 0:
            shutil.rmtree(os.path.join(case, name))
    shutil.rmtree(os.path.join(case, "postProcessing"), ignore_errors=True)
    log = "touchFoam.%d.%d" % (build, repeat)
    label = (performance.build() if env is None else "touchFoam of %s"
             % env["PATH"].split(os.pathsep)[0])
    with open(os.path.join(case, "run." + log), "w") as f:
        f.write("loadavg %s\nbuild %s\n"
                % (open("/proc/loadavg").read().split()[0], label))
    run.run(["touchFoam"], case, log, env=env)
    for t, name in run.time_dirs(case).items():
        if t != 0:
            shutil.rmtree(os.path.join(case, name))
    return os.path.join(case, "log." + log)


# -- results ---------------------------------------------------------------

def contact_faces(case):
    """The bodyContact faces of a case (from its 0/U and the boundary)."""
    boundary = os.path.join(case, "constant", "polyMesh", "boundary")
    text = open(boundary).read()
    sizes = {}
    for name, body in re.findall(
            r"(\w+)\s*\{([^}]*)\}", text):
        m = re.search(r"nFaces\s+(\d+)", body)
        if m:
            sizes[name] = int(m.group(1))
    u = os.path.join(case, "0", "U")
    if not os.path.exists(u):
        return 0
    utext = open(u).read()
    n = 0
    for name, size in sizes.items():
        m = re.search(r"\b%s\s*\{[^}]*?type\s+(\w+)" % name,
                                    utext)
        if m and m.group(1) == "bodyContact":
            n += size
    return n


def analyse(names, nbuilds, labels):
    rows = []
    for case in names:
        reference, variants = CASES[case]
        base = os.path.join(RUNS, case)
        cells = performance.mesh_counts(os.path.join(base, "mesh"))[0]
        runs = {}
        for b in range(nbuilds):
            for v in variants:
                logs = sorted(glob.glob(os.path.join(
                    base, v, "log.touchFoam.%d.*" % b)),
                    key=lambda p: int(p.rsplit(".", 1)[1]))
                runs[b, v] = [performance.read_log(p) for p in logs]
        ref = runs[0, reference]
        for b in range(nbuilds):
            for v in variants:
                mine = runs[b, v]
                if not mine:
                    continue
                s = [r["secondsPerStep"] for r in mine]
                ratios = [r["secondsPerStep"] / q["secondsPerStep"]
                          for r, q in zip(mine, ref)]
                rows.append({
                    "case": case, "variant": v, "build": labels[b],
                    "cells": cells,
                    "contactFaces": contact_faces(os.path.join(base, v)),
                    "runs": len(s), "steps": mine[0]["steps"],
                    "secondsPerStepAll": s,
                    "secondsPerStepMin": min(s),
                    "secondsPerStepMedian": statistics.median(s),
                    "cellStepsPerSecondMax": cells / min(s),
                    "cellStepsPerSecondMedian": cells / statistics.median(s),
                    "timeRatioAll": ratios,
                    "timeRatioMin": min(ratios),
                    "timeRatioMedian": statistics.median(ratios),
                    "loadAverageAll": [r["loadAverage"] for r in mine],
                    "builds": sorted(set(r["build"] for r in mine
                                         if r["build"]))})
    return rows


def markdown(rows, labels):
    out = ["# Contact and gravity: cost (validation/performance/contact.py)",
           "",
           "Runs alternated variant by variant (and build by build); s/step"
           " is the CPU time of the time loop without its first and last"
           " steps.  ratio = s/step over the reference's (free, noG) run"
           " of the same round, pair by pair: above 1 costs more; "
           "throughput relative to the reference = 1/ratio.", ""]
    if len(labels) > 1:
        out += ["Builds: " + ", ".join("%d = %s" % (i, l)
                                       for i, l in enumerate(labels)), ""]
    out += ["| case | variant | build | cells | contact faces | runs x steps"
            " | s/step min / median | cell-steps/s max / median"
            " | ratio min / median | load |",
            "|---|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        loads = [x for x in r["loadAverageAll"] if x is not None]
        out.append(
            "| %s | %s | %s | %d | %d | %d x %d | %.4f / %.4f | %.3g M / "
            "%.3g M | %.3f / %.3f | %s |"
            % (r["case"], r["variant"],
               labels.index(r["build"]) if len(labels) > 1 else "-",
               r["cells"], r["contactFaces"], r["runs"], r["steps"],
               r["secondsPerStepMin"], r["secondsPerStepMedian"],
               r["cellStepsPerSecondMax"] / 1e6,
               r["cellStepsPerSecondMedian"] / 1e6,
               r["timeRatioMin"], r["timeRatioMedian"],
               "%.1f-%.1f" % (min(loads), max(loads)) if loads else "?"))
    builds = sorted(set(b for r in rows for b in r["builds"]))
    out += ["", "Measured with: " + "; ".join(builds), ""]
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("-cases", default="full,partial,gravity",
                    help="comma-separated, of: " + ", ".join(CASES))
    ap.add_argument("-steps", type=int, default=150,
                    help="steps a run, >= 3 (default 150)")
    ap.add_argument("-repeat", type=int, default=5,
                    help="runs of each variant (default 5)")
    ap.add_argument("-builds", default="",
                    help="one or two folders of touchFoam and libTOUCH.so "
                    "(default: the ones on PATH)")
    ap.add_argument("-no-run", action="store_true",
                    help="re-read runs/contact instead of running")
    args = ap.parse_args()

    names = [c for c in args.cases.split(",") if c]
    unknown = [c for c in names if c not in CASES]
    if unknown:
        ap.error("unknown cases: %s" % ",".join(unknown))
    if args.steps < 3 or args.repeat < 1:
        ap.error("needs steps >= 3 and repeat >= 1")
    folders = [f for f in args.builds.split(",") if f]
    envs = [build_env(f) for f in folders] or [None]
    labels = [os.path.abspath(f) for f in folders] or ["PATH"]

    if not args.no_run:
        run.check_openfoam()
        for case in names:
            reference, variants = CASES[case]
            base = (gravity_mesh(args.steps) if case == "gravity"
                    else two_block_mesh(case, args.steps))
            todo = [variant_case(base, v, s, case)
                    for v, s in variants.items()]
            # Round robin over the variants and the builds
            for repeat in range(1, args.repeat + 1):
                for path in todo:
                    for b, env in enumerate(envs):
                        print("%s %s build %d run %d:"
                              % (case, os.path.basename(path), b, repeat),
                              end=" ", flush=True)
                        r = performance.read_log(
                            run_once(path, repeat, b, env))
                        print("%.4g s/step" % r["secondsPerStep"],
                              flush=True)

    rows = analyse(names, len(envs), labels)
    with open(os.path.join(HERE, "results-contact.json"), "w") as f:
        json.dump({"labels": labels, "rows": rows}, f, indent=1)
    md = markdown(rows, labels)
    with open(os.path.join(HERE, "results-contact.md"), "w") as f:
        f.write(md)
    print(md)


if __name__ == "__main__":
    main()
