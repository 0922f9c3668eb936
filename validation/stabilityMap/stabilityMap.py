#!/usr/bin/python3
"""Stability map of the twisting column: where the scheme holds and where not.

    ./stabilityMap.py --quick                       (7 runs, ~20 s)
    ./stabilityMap.py --preset baseline             (35 runs, ~8 min)
    ./stabilityMap.py [--n 2 3 4 8] [--nu 0.45 0.499 0.4999]
                      [--cfl 0.3 0.5 0.6 0.7 0.9]
                      [--update compatible constrained plain]
                      [--scheme RK2 RK3] [--mesh hex poly tet]
                      [--end 0.3] [--jobs 1] [--no-run] [--list]

Runs a copy of tutorials/twistingColumn (neo-Hookean, Omega = 105 rad/s,
tutorial TOUCH settings otherwise) for every combination of the settings
given (the defaults are the whole envelope, 720 runs: choose a subset),
each in runs/<label>/, to t = end, writing the fields every 0.01 s and the
solidMonitor every step.

    --n       mesh n x 6n x n (hex) or the polyhedral dual of it (poly)
    --mesh    hex: blockMesh; poly: blockMesh, then
              'polyDualMesh 80 -overwrite -concaveMultiCells'; tet: the hex
              mesh cut into 6 tetrahedra a hexahedron (gmsh.py,
              gmshToFoam), run with nodalAveraging deformation; 0/ restored
              from 0.orig and initialised again on the new cells
    --update  TOUCH FUpdate;  --scheme  TOUCH timeScheme;  --cfl  TOUCH CFL
    --nu      Poisson's ratio (constant/materialOptions)
    --preset  a named list of grids (quick, baseline; --quick = --preset
              quick); exclusive with the grid options above
    --jobs    runs at a time (default 1; the machine is shared)
    --no-run  only analyse the existing runs/ of the selected settings
    --list    print the labels of the selected settings and stop

For each run (a run that stops early, e.g. on an inverted cell, is a row
with what it reached):
    reached      end time reached (touchFoam exit 0), else the last time
    dE/E0 max    largest (E_{k+1} - E_k) / E0 over the steps, E the
                 monitor's total energy, E_0 = sum V |p|^2 / (2 rho0) of 0/lm
                 taken as the energy before the first step
    E_end/E0     total energy at the last step / E0
    min J        min over cells and written times (0.01 s and the last good
                 state) of the J field
    twist        mean top-face twist at 0.1 s (postprocess.column_twist), deg
    steps        monitor samples (one per step); wall: touchFoam wall time

Writes results.json (every row and the build used) and the table between
'<!-- table -->' and '<!-- /table -->' in README.md.  The build is the
touchFoam found in the PATH (etc/bashrc); --build-label names it when it is
not the git checkout of $TOUCH_PROJECT_DIR.
"""

import argparse
import concurrent.futures
import datetime
import hashlib
import itertools
import json
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

from touchfoam import cases, checks, gmsh, postprocess, run  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

TUTORIAL = "twistingColumn"
T_TWIST = 0.1
WRITE_INTERVAL = 0.01
POLY_DUAL = ["polyDualMesh", "80", "-overwrite", "-concaveMultiCells"]
RUN_INFO = "stabilityMap.json"     # per run: settings, exit, wall time
TABLE_BEGIN, TABLE_END = "<!-- table -->", "<!-- /table -->"

GRID_KEYS = ("mesh", "n", "nu", "cfl", "update", "scheme")
DEFAULT_GRID = {
    "mesh": ["hex", "poly"],
    "n": [2, 3, 4, 8],
    "nu": [0.45, 0.499, 0.4999],
    "cfl": [0.3, 0.5, 0.6, 0.7, 0.9],
    "update": ["compatible", "constrained", "plain"],
    "scheme": ["RK2", "RK3"],
}


def grid(**kw):
    """A grid: DEFAULT_GRID's keys, every value a list."""
    return {k: list(kw[k]) for k in GRID_KEYS}


PRESETS = {
    # 4 x 24 x 4 at two CFL numbers and both schemes, one polyhedral run,
    # and each other FUpdate at its stated RK2 limit (ENVELOPE): every row
    # inside the envelope, so every row a check
    "quick": [
        grid(mesh=["hex"], n=[4], nu=[0.45], cfl=[0.3, 0.6],
             update=["compatible"], scheme=["RK2", "RK3"]),
        grid(mesh=["poly"], n=[4], nu=[0.45], cfl=[0.3],
             update=["compatible"], scheme=["RK2"]),
        grid(mesh=["hex"], n=[4], nu=[0.45], cfl=[0.6],
             update=["constrained"], scheme=["RK2"]),
        grid(mesh=["hex"], n=[4], nu=[0.45], cfl=[0.3],
             update=["plain"], scheme=["RK2"]),
    ],
    # The default update across CFL and mesh size, nu -> 0.5, polyhedra,
    # tetrahedra
    "baseline": [
        grid(mesh=["hex"], n=[2, 4, 8], nu=[0.45], cfl=[0.3, 0.5, 0.6, 0.7],
             update=["compatible"], scheme=["RK2", "RK3"]),
        grid(mesh=["hex"], n=[4], nu=[0.499, 0.4999], cfl=[0.3],
             update=["compatible"], scheme=["RK2", "RK3"]),
        grid(mesh=["hex"], n=[8], nu=[0.499, 0.4999], cfl=[0.3],
             update=["compatible"], scheme=["RK2"]),
        grid(mesh=["poly"], n=[6], nu=[0.45], cfl=[0.3],
             update=["compatible"], scheme=["RK2", "RK3"]),
        grid(mesh=["tet"], n=[4], nu=[0.45], cfl=[0.3, 0.5, 0.7],
             update=["compatible"], scheme=["RK2"]),
    ],
}


#: The envelope the project states (doc/method.md section 8, the updates'
#: stableCFL): {(FUpdate, timeScheme): (largest CFL, the same on the very
#: coarse n = 2 column, largest energy growth in a step / E0)}.  The
#: compatible and plain updates never gain energy inside it; the
#: constrained update's own statement (constrained.C) is a growth of at
#: most 1e-3 E0 in a step at any CFL, and a run to the end
ENVELOPE = {
    ("compatible", "RK2"): (0.6, 0.3, 0.0),
    ("compatible", "RK3"): (1.0, 0.8, 0.0),
    ("constrained", "RK2"): (0.6, 0.6, 1e-3),
    ("constrained", "RK3"): (1.0, 1.0, 1e-3),
    ("plain", "RK2"): (0.3, 0.3, 0.0),
    ("plain", "RK3"): (0.4, 0.4, 0.0),
}


def envelope(s):
    """(largest CFL, energy growth bound) of setting s."""
    cfl, coarse, growth = ENVELOPE[(s["update"], s["scheme"])]
    return (coarse if s["n"] <= 2 else cfl), growth


def inside(s):
    return s["cfl"] <= envelope(s)[0] + 1e-12


def record_checks(rows, preset):
    """One check for every row inside the envelope: it reached the end,
    its energy never grew by more than the envelope's bound in a step,
    and min J > 0.  Rows outside are in the table, not asserted.  The
    quick preset must cover both time schemes and every FUpdate."""
    checks.start(HERE)
    for r in rows:
        if not inside(r):
            continue
        bound = envelope(r)[1]
        growth, minj = r.get("maxEnergyIncrease"), r.get("minJ")
        ok = bool(r.get("reachedEnd") and growth is not None
                  and growth <= bound and minj is not None and minj > 0)
        checks.record(
            HERE, "%s (CFL limit %g)" % (r["label"], envelope(r)[0]),
            "reached %s, dE/E0 max %s, min J %s" % (
                "yes" if r.get("reachedEnd") else "no (%s)" % (
                    r.get("error") or "t = %s" % r.get("timeReached")),
                _f(growth, "%.2g"), _f(minj, "%.3f")),
            "reaches %g s, dE/E0 max <= %g, min J > 0" % (
                r.get("endTime", 0.3), bound), ok,
            "inside the stated envelope (doc/method.md 8); dE/E0: the "
            "largest growth of the monitor's total energy in one step")
    if preset == "quick":
        have = {(r["update"], r["scheme"]) for r in rows if inside(r)}
        updates = sorted({u for u, _ in have})
        schemes = sorted({t for _, t in have})
        ok = (set(updates) == {u for u, _ in ENVELOPE}
              and set(schemes) == {t for _, t in ENVELOPE})
        checks.record(HERE, "quick preset covers every FUpdate and time "
                      "scheme inside the envelope",
                      " ".join(updates + schemes),
                      "compatible constrained plain RK2 RK3", ok)
    return checks.status(HERE) if checks.load(HERE) else 0


def settings_of(grids):
    """The settings (dicts) of a list of grids, in order, no repeats."""
    out, seen = [], set()
    for g in grids:
        for values in itertools.product(*(g[k] for k in GRID_KEYS)):
            s = dict(zip(GRID_KEYS, values))
            if label(s) not in seen:
                seen.add(label(s))
                out.append(s)
    return out


def label(s):
    return "%s-n%d-nu%s-cfl%s-%s-%s" % (s["mesh"], s["n"], s["nu"], s["cfl"],
                                        s["update"], s["scheme"])


def case_dir(s):
    return os.path.join(HERE, "runs", label(s))


# -- build ------------------------------------------------------------------

def _md5(path):
    h = hashlib.md5()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def library_path(name="libTOUCH.so"):
    """The first name in LD_LIBRARY_PATH, as dlopen finds it."""
    for d in os.environ.get("LD_LIBRARY_PATH", "").split(":"):
        if d and os.path.isfile(os.path.join(d, name)):
            return os.path.join(d, name)
    return None


def build_info(build_label=None):
    """Which touchFoam and libTOUCH the runs use, and what they are."""
    solver, lib = shutil.which("touchFoam"), library_path()
    info = {"touchFoam": solver, "libTOUCH": lib,
            "libTOUCHmd5": _md5(lib) if lib else None,
            "libTOUCHmtime": datetime.datetime.fromtimestamp(
                os.path.getmtime(lib)).isoformat(timespec="seconds")
            if lib else None}
    if build_label:
        info["label"] = build_label
        return info
    project = os.environ.get("TOUCH_PROJECT_DIR", run.project_dir())
    try:
        top = subprocess.check_output(
            ["git", "-C", project, "rev-parse", "--show-toplevel"],
            stderr=subprocess.DEVNULL, text=True).strip()
        if os.path.realpath(top) != os.path.realpath(project):
            # e.g. an exported copy inside another checkout
            raise OSError("not the top of a git checkout")
        commit = subprocess.check_output(
            ["git", "-C", project, "log", "-1", "--format=%h"],
            stderr=subprocess.DEVNULL, text=True).strip()
        dirty = subprocess.check_output(
            ["git", "-C", project, "status", "--porcelain", "--",
             "src", "applications"], text=True).strip()
        info["label"] = commit + (" + uncommitted changes in src/ or "
                                  "applications/" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        info["label"] = "unknown (%s is not a git checkout)" % project
    return info


# -- one run ------------------------------------------------------------------

def prepare(s, end):
    """Meshed, initialised copy of the tutorial for setting s."""
    case = case_dir(s)
    control = cases.precise_output()
    control.update({"endTime": end, "writeInterval": WRITE_INTERVAL})
    touch = {"CFL": s["cfl"], "FUpdate": s["update"],
             "timeScheme": s["scheme"]}
    if s["mesh"] == "tet":
        # The setting for tetrahedra (src/TOUCH/nodalAveraging)
        touch["nodalAveraging"] = "deformation"
    hex_mesh = s["mesh"] == "hex"
    cases.prepare(TUTORIAL, case, n=s["n"], nu=s["nu"], touch=touch,
                  control=control, initialise=hex_mesh)
    if s["mesh"] == "poly":
        # polyDualMesh maps 0/ onto the dual cells (and keeps the patches
        # base and free)
        run.run(POLY_DUAL, case)
    elif s["mesh"] == "tet":
        # The same n x 6n x n hexahedra cut into 6 tetrahedra each
        faces = {f: "free" for f in gmsh.PATCHES}
        faces["Y0"] = "base"
        n = s["n"]
        gmsh.write_box_msh(os.path.join(case, "column.msh"), (n, 6 * n, n),
                           (-0.5, 0.0, -0.5), (0.5, 6.0, 0.5), faces,
                           "column")
        run.run(["gmshToFoam", "column.msh"], case)
    if not hex_mesh:
        # the initial lm depends on the cell centres: 0/ is restored and
        # initialised again on the new cells
        run.restore0(case)
        cases.set_initial_state(case)
    run.run(["checkMesh"], case)
    return case


_CELL_RE = re.compile(r"touchSolid: (cell \d+) at \(.*?\) \(reference "
                      r"(\(.*?\))\): det F = (\S+?),")
_STEP_RE = re.compile(r"during the step to time (\S+)")


def fatal_message(log):
    """What stopped a solver run, in one line, from its log (None: no error).

    touchFoam's inverted-cell stop becomes 'inverted cell or non-finite
    value in the step to t = ...: cell N (reference X), det F = ...'.
    """
    try:
        with open(log, errors="replace") as f:
            lines = f.read().splitlines()
    except OSError:
        return None
    msg = None
    for i, line in enumerate(lines):
        if "FOAM FATAL" in line:
            msg = next((x.strip() for x in lines[i + 1:] if x.strip()), line)
            break
    if msg is None:
        return None
    step = _STEP_RE.search(msg)
    cells = [m for m in map(_CELL_RE.search, lines) if m]
    if not (step and cells):
        return msg
    c = cells[-1]
    return ("inverted cell or non-finite value in the step to t = %.4g: "
            "%s (reference %s), det F = %.3g"
            % (float(step.group(1)), c.group(1), c.group(2),
               float(c.group(3))))


def run_one(s, end, build):
    """Prepare and run one setting; writes runs/<label>/stabilityMap.json."""
    case = case_dir(s)
    lib = build["libTOUCH"]
    info = {"settings": s, "label": label(s), "endTime": end,
            "build": build, "libTOUCHmd5": _md5(lib) if lib else None,
            "date": datetime.date.today().isoformat(),
            "exitOK": False, "error": None, "wallTime": None}
    try:
        prepare(s, end)
    except (run.RunError, OSError, ValueError) as err:
        info["error"] = "set-up failed: %s" % str(err).split("\n")[0]
        os.makedirs(case, exist_ok=True)
        _write_json(os.path.join(case, RUN_INFO), info)
        return info
    start = time.time()
    try:
        run.run(["touchFoam"], case)
        info["exitOK"] = True
    except run.RunError as err:
        info["error"] = (fatal_message(os.path.join(case, "log.touchFoam"))
                         or str(err).split("\n")[0])
    info["wallTime"] = time.time() - start
    _write_json(os.path.join(case, RUN_INFO), info)
    return info


def _write_json(path, data):
    with open(path, "w") as f:
        json.dump(data, f, indent=2)


# -- analysis -----------------------------------------------------------------

def mesh_ok(case):
    try:
        with open(os.path.join(case, "log.checkMesh")) as f:
            return "Mesh OK." in f.read()
    except OSError:
        return None


def min_J(case, n_cells):
    """min over cells and written times t > 0 of the J field."""
    values = []
    for t, name in run.time_dirs(case).items():
        path = os.path.join(case, name, "J")
        if t > 0 and os.path.exists(path):
            values.append(float(read_field(path).internal(n_cells).min()))
    return min(values) if values else None


def analyse(s, end):
    """The row of setting s from its run folder."""
    case = case_dir(s)
    row = dict(s)
    row["label"] = label(s)
    try:
        with open(os.path.join(case, RUN_INFO)) as f:
            info = json.load(f)
    except (OSError, ValueError):
        row["error"] = "not run"
        return row
    if not info["exitOK"] and info["wallTime"] is not None:
        info["error"] = (fatal_message(os.path.join(case, "log.touchFoam"))
                         or info["error"])
    row.update({"exitOK": info["exitOK"], "error": info["error"],
                "date": info.get("date"),
                "wallTime": info["wallTime"],
                "libTOUCHmd5": info["libTOUCHmd5"],
                "build": info.get("build", {}).get("label")})
    try:
        m = PolyMesh(case)
    except Exception as err:  # noqa: BLE001 (no mesh: set-up failed)
        row["error"] = row["error"] or str(err)
        return row
    row["cells"], row["meshOK"] = m.n_cells, mesh_ok(case)
    try:
        E0 = postprocess.initial_energy(case)
        mon = read_monitor(case)
    except (OSError, ValueError) as err:
        row["error"] = row["error"] or str(err)
        return row
    E, t = mon["totalEnergy"], mon["Time"]
    row["E0"] = E0
    row["steps"] = len(t)
    row["timeReached"] = float(t[-1]) if len(t) else 0.0
    row["reachedEnd"] = bool(info["exitOK"] and len(t)
                             and t[-1] >= end * (1 - 1e-9))
    if len(t):
        first = (E[0] - E0) / E0            # the step from the initial state
        rest = (postprocess.energy_increase(case, reference=E0)[0]
                if len(t) > 1 else -math.inf)
        row["maxEnergyIncrease"] = float(max(first, rest))
        row["energyKept"] = float(E[-1] / E0)
    row["minJ"] = min_J(case, m.n_cells)
    try:
        twist = [a for tt, a in postprocess.column_twist(case, t_end=T_TWIST)
                 if abs(tt - T_TWIST) < 1e-9]
        row["twist0.1deg"] = math.degrees(twist[0]) if twist else None
    except (OSError, ValueError, run.RunError) as err:
        row["twist0.1deg"] = None
        row["twistError"] = str(err)
    return row


# -- report -------------------------------------------------------------------

def _f(x, fmt):
    return "-" if x is None else fmt % x


def table(rows):
    head = ["mesh", "n", "cells", "nu", "CFL", "FUpdate", "scheme",
            "reached", "dE/E0 max", "E_end/E0", "min J", "twist 0.1 s [deg]",
            "steps", "wall [s]"]
    lines = ["| " + " | ".join(head) + " |",
             "|" + "|".join("---" for _ in head) + "|"]
    for r in rows:
        if "steps" not in r:
            reached = "failed: %s" % r.get("error")
        elif r["reachedEnd"]:
            reached = "yes"
        else:
            reached = "no, t = %.4g" % r["timeReached"]
        lines.append("| " + " | ".join([
            r["mesh"], str(r["n"]), _f(r.get("cells"), "%d"), str(r["nu"]),
            str(r["cfl"]), r["update"], r["scheme"], reached,
            _f(r.get("maxEnergyIncrease"), "%.1e"),
            _f(r.get("energyKept"), "%.3f"), _f(r.get("minJ"), "%.3f"),
            _f(r.get("twist0.1deg"), "%.1f"), _f(r.get("steps"), "%d"),
            _f(r.get("wallTime"), "%.1f")]) + " |")
    return "\n".join(lines)


def notes(rows, build):
    out = []
    failed = [r for r in rows if r.get("error")]
    for r in failed:
        out.append("- %s: %s" % (r["label"], r["error"]))
    bad_mesh = [r["label"] for r in rows if r.get("meshOK") is False]
    if bad_mesh:
        out.append("- checkMesh reports failed checks: %s"
                   % ", ".join(bad_mesh))
    md5s = {r.get("libTOUCHmd5") for r in rows if r.get("libTOUCHmd5")}
    if len(md5s) > 1:
        out.append("- WARNING: libTOUCH.so changed during the map (%d "
                   "different builds); rows are not comparable" % len(md5s))
    return out


def block(rows, out):
    b = out["build"]
    text = [
        "Produced by `%s` on %s, build %s (libTOUCH.so md5 %s), end time "
        "%g s." % (out["command"], out["date"], b["label"],
                   (b["libTOUCHmd5"] or "?")[:12], out["endTime"]),
        "",
        "Columns: `n`: hex n x 6n x n, poly its polyDualMesh, tet its hexahedra "
        "cut into 6 tetrahedra each (nodalAveraging deformation); `reached`: the "
        "end time, else the last time touchFoam reached before stopping; "
        "`dE/E0 max`: the largest growth of the monitor's total energy in one "
        "step over E0, the kinetic energy of 0/lm (<= 0: never grows); "
        "`E_end/E0`: total energy kept at the last step; `min J`: over cells "
        "and the written times (every 0.01 s, and the last good state of a "
        "run that stopped); `twist`: mean top-face rotation at 0.1 s; "
        "`steps`: time steps taken; `wall`: touchFoam wall time.",
        "",
        table(rows),
    ]
    outside = [r["label"] for r in rows if not inside(r)]
    text += ["", "Every row inside the envelope (doc/method.md 8: "
             "compatible RK2 CFL 0.6, 0.3 on n = 2, RK3 1.0, 0.8 on n = 2; "
             "constrained 0.6 / 1.0, energy growth up to 1e-3 E0 a step; "
             "plain 0.3 / 0.4) is a check in checks.json: it reaches the "
             "end, dE/E0 max <= 0 (constrained: <= 1e-3) and min J > 0. "
             + ("Outside it, reported and not asserted: %s."
                % ", ".join(outside) if outside
                else "Every row is inside it.")]
    n = notes(rows, b)
    if n:
        text += ["", "Runs that stopped or could not start:" if any(
            r.get("error") for r in rows) else "Notes:"] + n
    return "\n".join(text)


def write_readme(text, path):
    """Replace the marked block of README.md (append it when absent)."""
    body = ""
    if os.path.exists(path):
        with open(path) as f:
            body = f.read()
    new = "%s\n%s\n%s" % (TABLE_BEGIN, text, TABLE_END)
    pattern = re.compile(re.escape(TABLE_BEGIN) + ".*?" + re.escape(TABLE_END),
                         re.S)
    if pattern.search(body):
        body = pattern.sub(lambda _: new, body)
    else:
        body = body.rstrip("\n") + ("\n\n" if body else "") + new + "\n"
    with open(path, "w") as f:
        f.write(body)


# -- main ---------------------------------------------------------------------

def parse(argv):
    p = argparse.ArgumentParser(
        description=__doc__.split("\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="Defaults: " + "; ".join(
            "--%s %s" % (k, " ".join(map(str, v)))
            for k, v in DEFAULT_GRID.items()))
    p.add_argument("--n", type=int, nargs="+")
    p.add_argument("--nu", type=float, nargs="+")
    p.add_argument("--cfl", type=float, nargs="+")
    p.add_argument("--update", nargs="+",
                   choices=["compatible", "constrained", "plain"])
    p.add_argument("--scheme", nargs="+", choices=["RK2", "RK3"])
    p.add_argument("--mesh", nargs="+", choices=["hex", "poly", "tet"])
    p.add_argument("--preset", choices=sorted(PRESETS))
    p.add_argument("--quick", action="store_const", const="quick",
                   dest="preset", help="= --preset quick")
    p.add_argument("--end", type=float, default=0.3)
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--no-run", action="store_true")
    p.add_argument("--list", action="store_true")
    p.add_argument("--build-label",
                   help="name of the build in the report (default: git "
                        "commit of $TOUCH_PROJECT_DIR)")
    args = p.parse_args(argv)
    given = {k: getattr(args, k) for k in GRID_KEYS
             if getattr(args, k) is not None}
    if args.preset and given:
        p.error("--preset/--quick and --%s exclude each other"
                % " --".join(given))
    if args.end < T_TWIST:
        p.error("--end must be at least %g (twist at %g s)"
                % (T_TWIST, T_TWIST))
    if args.jobs < 1:
        p.error("--jobs must be at least 1")
    args.grids = (PRESETS[args.preset] if args.preset
                  else [grid(**dict(DEFAULT_GRID, **given))])
    return args


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    args = parse(argv)
    settings = settings_of(args.grids)
    if args.list:
        for s in settings:
            print(label(s))
        print("%d runs" % len(settings))
        return 0
    # The command that made the runs (a --no-run analysis names it too)
    command = "validation/stabilityMap/stabilityMap.py " + " ".join(
        shlex.quote(a) for a in argv if a != "--no-run")
    build = build_info(args.build_label)
    if not args.no_run:
        try:
            run.check_openfoam()
        except run.RunError as err:
            print("stabilityMap: %s" % err, file=sys.stderr)
            return 1
        if not run.have_solver():
            print("stabilityMap: touchFoam not in the PATH (Allwmake, "
                  "etc/bashrc)", file=sys.stderr)
            return 1
        print("%d runs, build %s (%s), %d at a time"
              % (len(settings), build["label"], build["libTOUCH"], args.jobs),
              flush=True)
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            jobs = {pool.submit(run_one, s, args.end, build): s
                    for s in settings}
            for k, job in enumerate(concurrent.futures.as_completed(jobs)):
                info = job.result()
                print("[%d/%d] %-44s %s%s" % (
                    k + 1, len(settings), info["label"],
                    "ok" if info["exitOK"] else "STOPPED",
                    "" if info["wallTime"] is None
                    else " (%.1f s)" % info["wallTime"]), flush=True)
    rows = [analyse(s, args.end) for s in settings]
    for r in rows:
        r["endTime"] = args.end
        r["insideEnvelope"] = inside(r)
    if args.no_run:
        # The build that made the runs, not the one in the PATH now
        labels = sorted({r["build"] for r in rows if r.get("build")})
        if labels:
            build["label"] = " / ".join(labels)
            md5s = {r.get("libTOUCHmd5") for r in rows} - {None}
            build["libTOUCHmd5"] = md5s.pop() if len(md5s) == 1 else None
    dates = sorted({r["date"] for r in rows if r.get("date")})
    out = {"command": command,
           "date": " to ".join(dates[::len(dates) - 1] if len(dates) > 1
                               else dates)
           or datetime.date.today().isoformat(),
           "build": build, "endTime": args.end, "tutorial": TUTORIAL,
           "writeInterval": WRITE_INTERVAL, "twistTime": T_TWIST,
           "rows": rows}
    _write_json(os.path.join(HERE, "results.json"), out)
    text = block(rows, out)
    write_readme(text, os.path.join(HERE, "README.md"))
    print(text)
    status = record_checks(rows, args.preset)
    print("wrote results.json, README.md and checks.json (%d checks, %s)"
          % (len(checks.load(HERE) or []), "all pass" if status == 0
             else "some FAIL"))
    return status


if __name__ == "__main__":
    sys.exit(main())
