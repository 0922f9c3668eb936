#!/usr/bin/python3
"""Taylor impact (doc/benchmarks.md section 3): mesh convergence against the
literature and against CalculiX.

    ./taylor.py [--n 3 6 9] [--calculix 4,4,34 6,6,50] [--no-calculix]
                [--no-run]

For each n, copies tutorials/taylorImpact to runs/n<n>/ and runs its
'./Allrun -n n' (n cells across the radius; 3, 6, 9 give 240, 1952 and
6552 cells; CFL 0.3 as in the tutorial), one case at a time, then reads
the 80 us time folder:

  length       max current y of the mesh points (the wall is y = 0);
  foot radius  max current sqrt(x^2 + z^2) of the points of the wall
               patch (reference y = 0);
  peak strain  max cell epsilonP;
  steps        'Time =' lines of log.touchFoam; wall time: touchFoam's
               ClockTime (and the whole Allrun, pictures included).

Each is compared with the literature range (LITERATURE below) and across
the meshes: the differences between successive meshes, whether they
shrink, whether the finest mesh is nearer the range than the one before,
and the limit of v = v0 + a h^p through the three (when 0.5 <= p <= 4).
The same quantities are kept for every written time, with the range of
J; run health from the solidMonitor: growth of the total energy (it can
only fall) and the first step that raised it by more than 1e-6 E_0, and
the contact-set changes and largest wall force after 40 us.

Checker-board index of a cell field q (pressure, epsilonP) at 80 us, on
the reference mesh: for every cell e, r_e = q_e - the mean of q over the
cells that share a face with e, and

    C = RMS_e(r) / (2 RMS_e(q - mean_e q)),

over the interior cells (no boundary face) and over all cells (boundary
cells have only their face neighbours, so the pictures' surface cells
count too).  C = 0 for a field that is linear on a uniform mesh, C = 1
for a perfect +1/-1 checker-board (r = +-2).  The same index of three
reference fields on the same mesh is given to judge the numbers: a
linear field of the reference coordinates (C_smooth), the best +1/-1
two-colouring of the cells (C_checker; the O-grid has three cells round
the block corner, so a few faces cannot alternate) and independent
normal random values (C_noise, about 0.54: rough, but not alternating).
A grid-scale mode keeps its C under refinement; a resolved field's C
falls with h.

CalculiX: the quarter-bar deck of ../calculix/decks.py (C3D8R, O-grid
N,M,NY of --calculix, the increment capped at 6e-9 s: CalculiX's own goes
unstable near 45 us; one thread), in runs/calculix/; final length (max
current y of the nodes), radius of the impact face and peak PEEQ
(integration points) read back from its .frd and .dat, wall time of the
ccx process.

Writes results.json, results.md and taylor.png (when matplotlib is
available).  --no-run re-analyses runs/ (wall times are stored there).
Exit status 1 when acceptance line 1 of issue 10 fails on the finest
mesh (ranges, convergence toward them, C <= 0.2 over all cells, energy
growth below 1e-3 E_0); on fewer or coarser meshes than the published
(validation/Allrun -quick: --n 3 6), when one of quick_checks' checks
fails (direction of convergence, the range widened by the mesh error,
C, energy).  Either way the checks are in checks.json.
"""

import argparse
import json
import math
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

# The project's copy of the CalculiX tools, also from a quick copy of
# this study under validationQuick/
sys.path.insert(0, os.path.join(HERE, "..", "..", "validation", "calculix"))

from touchfoam.provenance import log_steps_and_clock  # noqa: E402
from touchfoam import checks, run  # noqa: E402
from touchfoam.foamfile import read_dict, read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

from taylorLiterature import (CHECKER_FIELDS, CHECKER_FREE,  # noqa: E402,F401
                              LITERATURE, ONSET, ORDER_RANGE, QUANTITIES)
from taylorReport import plot, write_markdown  # noqa: E402
import ccx  # noqa: E402
import decks  # noqa: E402

T_END = 8e-5
V0 = 227.0              # impact speed [m/s] (doc/benchmarks.md 3)
TUTORIAL = "taylorImpact"
CCX_DTMAX = 6e-9        # CalculiX's own increment (1.2e-8 s) diverges
CCX_FREQ = 667          # output every ~4 us


def case_dir(n):
    return os.path.join(HERE, "runs", "n%d" % n)


def ccx_dir():
    return os.path.join(HERE, "runs", "calculix")


def ccx_job(mesh):
    return "B_C3D8R_%dx%dx%d_dt%s" % (tuple(mesh) + (
        ("%g" % CCX_DTMAX).replace("e-0", "e-"),))


# -- runs ---------------------------------------------------------------------

def run_touch(n):
    """Copy of the tutorial at runs/n<n>, its Allrun -n n; the wall times
    go to runs/n<n>/wallTime.json.  Returns an error message or None."""
    case = case_dir(n)
    print("running %s -n %d in %s" % (TUTORIAL, n, case), flush=True)
    run.copy_case(run.tutorial_dir(TUTORIAL), case)
    env = {"TOUCH_N": ""}
    start = time.time()
    error = None
    try:
        run.run(["./Allrun", "-n", str(n)], case, "Allrun", env=env)
    except run.RunError as err:
        print(err, file=sys.stderr)
        error = str(err).split("\n")[0]
    wall = time.time() - start
    with open(os.path.join(case, "wallTime.json"), "w") as f:
        json.dump({"Allrun_s": wall, "error": error}, f, indent=1)
    print("  done in %.0f s" % wall, flush=True)
    return error


def run_calculix(mesh):
    """CalculiX on the O-grid mesh (N, M, NY) in runs/calculix/: the deck
    of ../calculix/decks.py (C3D8R, increment capped at CCX_DTMAX), ccx on
    one thread; its wall and CPU time go to <job>.time.json."""
    ccx.check_ccx()
    job = ccx_job(mesh)
    os.makedirs(ccx_dir(), exist_ok=True)
    print("running CalculiX %s in %s" % (job, ccx_dir()), flush=True)
    decks.taylor_deck(os.path.join(ccx_dir(), job + ".inp"), *mesh,
                      element="C3D8R", t_end=T_END, dt_max=CCX_DTMAX,
                      output_every=CCX_FREQ)
    wall, cpu = ccx.run_ccx(ccx_dir(), job)
    with open(os.path.join(ccx_dir(), job + ".time.json"), "w") as f:
        json.dump({"wall": wall, "cpu": cpu}, f, indent=1)
    print("  done in %.0f s" % wall, flush=True)


# -- our measurements ---------------------------------------------------------

def face_neighbours(mesh):
    """Owner and neighbour of the internal faces, and the mask of the
    cells with no boundary face."""
    nint = mesh.n_internal_faces
    boundary = np.zeros(mesh.n_cells, bool)
    boundary[mesh.owner[nint:]] = True
    return mesh.owner[:nint], mesh.neighbour, ~boundary


def checker_index(q, own, nbr, cells):
    """C = RMS(q - mean_nb q) / (2 RMS(q - mean q)) over the cells mask."""
    n = len(q)
    count = np.bincount(own, minlength=n) + np.bincount(nbr, minlength=n)
    total = (np.bincount(own, weights=q[nbr], minlength=n)
             + np.bincount(nbr, weights=q[own], minlength=n))
    r = q - total / np.maximum(count, 1)
    spread = q[cells] - q[cells].mean()
    denom = 2.0 * math.sqrt(np.mean(spread ** 2))
    return float(math.sqrt(np.mean(r[cells] ** 2)) / denom) if denom > 0 \
        else 0.0


def two_colouring(n, own, nbr):
    """+1/-1 per cell by breadth-first search over the face graph; the
    fraction of internal faces whose two cells got the same colour."""
    adj = [[] for _ in range(n)]
    for a, b in zip(own, nbr):
        adj[a].append(b)
        adj[b].append(a)
    colour = np.zeros(n)
    for seed in range(n):
        if colour[seed]:
            continue
        colour[seed] = 1.0
        queue = [seed]
        while queue:
            nxt = []
            for c in queue:
                for d in adj[c]:
                    if not colour[d]:
                        colour[d] = -colour[c]
                        nxt.append(d)
            queue = nxt
    same = float(np.mean(colour[own] == colour[nbr]))
    return colour, same


class Cells:
    """The reference mesh of a case with what the indices need."""

    def __init__(self, case):
        self.mesh = PolyMesh(case)
        self.foot = self.mesh.patch_points("wall")
        self.own, self.nbr, self.interior = face_neighbours(self.mesh)
        self.every = np.ones(self.mesh.n_cells, bool)

    def checker(self, q):
        """{'allCells': C, 'interior': C} of the cell field q."""
        return {"allCells": checker_index(q, self.own, self.nbr, self.every),
                "interior": checker_index(q, self.own, self.nbr,
                                          self.interior)}

    def read(self, folder, name, points=False):
        n = len(self.mesh.points) if points else self.mesh.n_cells
        return read_field(os.path.join(folder, name)).internal(n)


def at_time(cells, folder):
    """Length, foot radius, peak strain, J range and the checker-board
    indices of pressure and epsilonP at one written time."""
    m = cells.mesh
    x = m.points + cells.read(folder, "pointD", points=True)
    eps = cells.read(folder, "epsilonP")
    J = cells.read(folder, "J")
    return {
        "time": float(os.path.basename(folder)),
        "length_mm": 1e3 * float(x[:, 1].max()),
        "footRadius_mm": 1e3 * float(np.hypot(x[cells.foot, 0],
                                              x[cells.foot, 2]).max()),
        "peakPlasticStrain": float(eps.max()),
        "peakPlasticStrainCell": int(eps.argmax()),
        "peakPlasticStrainAt_mm": (1e3 * m.cell_centres[eps.argmax()])
        .tolist(),
        "minJ": float(J.min()),
        "maxJ": float(J.max()),
        "checkerBoard": {f: cells.checker(cells.read(folder, f))
                         for f in CHECKER_FIELDS},
    }


def energy_budget(case, cells, folder):
    """Where the initial kinetic energy E_0 = rho V v0^2 / 2 went by 80 us:
    the plastic work sum_e V_e (sigma_y0 epsbar_p + H epsbar_p^2 / 2) (the
    yield stress is a Kirchhoff one: per reference volume), what is left
    (kinetic + stored, from the monitor) and the rest, which the scheme's
    upwinding dissipated (a frictionless wall does no work)."""
    props = read_dict(os.path.join(case, "constant", "mechanicalProperties"))
    rho = float(props["rho"])
    coeffs = props["vonMisesPlasticCoeffs"]
    sigma_y0 = float(coeffs["yieldStress"])
    H = float(coeffs["hardeningModulus"])
    V = cells.mesh.cell_volumes
    eps = cells.read(folder, "epsilonP")
    E0 = 0.5 * rho * V.sum() * V0 ** 2
    plastic = float((V * (sigma_y0 * eps + 0.5 * H * eps ** 2)).sum())
    left = float(read_monitor(case)["totalEnergy"][-1])
    return {"E0_J": E0, "plasticWorkRelative": plastic / E0,
            "remainingRelative": left / E0,
            "upwindDissipationRelative": 1 - (plastic + left) / E0}


def run_health(case):
    """From the monitor: growth of the total energy (plasticity and a
    frictionless wall only dissipate), max_n (E_n - min_{m<=n} E_m) / E_0,
    and the first time a step raised E by more than ONSET E_0; the steps
    at which the number of wall faces in contact changed and the largest
    wall force, in the second half of the run (the bar is slowing down,
    the foot stays on the wall)."""
    mon = read_monitor(case)
    t, E = mon["Time"], mon["totalEnergy"]
    growth = float(np.max(E - np.minimum.accumulate(E)) / E[0])
    jumps = np.nonzero(np.diff(E) > ONSET * E[0])[0]
    late = t >= 0.5 * T_END
    faces = mon["contactFaces(wall)"][late]
    return {"initialEnergy_J": float(E[0]),
            "maxGrowthRelative": growth,
            "maxStepIncreaseRelative": float(np.max(np.diff(E)) / E[0]),
            "onsetTime": float(t[jumps[0] + 1]) if len(jumps) else None,
            "contactChangesSecondHalf": int(np.sum(np.diff(faces) != 0)),
            "maxWallForceSecondHalf_N":
            float(mon["wallForce(wall)"][late].max())}


def measure(case):
    cells = Cells(case)
    mesh = cells.mesh
    steps, clock = log_steps_and_clock(case)
    with open(os.path.join(case, "wallTime.json")) as f:
        wall = json.load(f)
    times = run.time_dirs(case)
    history = [at_time(cells, os.path.join(case, times[t]))
               for t in sorted(times) if t > 0]
    final = history[-1]
    if abs(final["time"] - T_END) > 1e-9 * T_END:
        raise run.RunError("%s: last time %g, not %g"
                           % (case, final["time"], T_END))
    out = {"cells": mesh.n_cells, "steps": steps,
           "touchFoamClockTime_s": clock,
           "AllrunWallTime_s": wall["Allrun_s"], "runError": wall["error"]}
    out.update(final)
    out["energy"] = run_health(case)
    out["energyBudget"] = energy_budget(case, cells,
                                        os.path.join(case, times[max(times)]))
    out["history"] = history
    # The reference fields, to judge C
    colour, same = two_colouring(mesh.n_cells, cells.own, cells.nbr)
    rng = np.random.default_rng(1)
    refs = {"smooth": mesh.cell_centres @ np.array([1.0, 2.0, 3.0]),
            "noise": rng.standard_normal(mesh.n_cells),
            "checker": colour}
    out["checkerBoard"].update({k: cells.checker(q) for k, q in refs.items()})
    out["checkerSameColourFaces"] = same
    out["interiorCells"] = int(cells.interior.sum())
    return out


def richardson(n, v):
    """Observed order p and limit of v(h) = v0 + a h^p, h = 1/n, from the
    last three meshes; None when the differences do not shrink
    monotonically."""
    if len(v) < 3:
        return None
    h = [1.0 / x for x in n[-3:]]
    d1, d2 = v[-2] - v[-3], v[-1] - v[-2]
    if d1 * d2 <= 0 or abs(d2) >= abs(d1):
        return None

    def excess(p):      # (h1^p - h2^p) / (h2^p - h3^p) - d1/d2
        return (h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p) - d1 / d2

    lo, hi = 0.05, 8.0
    if excess(lo) * excess(hi) > 0:
        return None
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if excess(lo) * excess(mid) <= 0:
            hi = mid
        else:
            lo = mid
    p = 0.5 * (lo + hi)
    a = d2 / (h[2] ** p - h[1] ** p)
    limit = v[-1] - a * h[2] ** p
    ok = ORDER_RANGE[0] <= p <= ORDER_RANGE[1]
    return {"order": p, "limit": limit if ok else None,
            "limitOutsideOrderRange": None if ok else limit}


def convergence(n, values):
    """Differences of successive meshes, whether they shrink, the
    direction, and whether the finest is nearer the range than the one
    before (distance 0 inside the range)."""
    out = {}
    for key, (lo, hi) in LITERATURE.items():
        v = [r[key] for r in values]
        d = [b - a for a, b in zip(v, v[1:])]
        dist = [max(lo - x, x - hi, 0.0) for x in v]
        out[key] = {
            "values": v,
            "differences": d,
            "shrinking": bool(all(abs(b) < abs(a) for a, b in zip(d, d[1:])))
            if len(d) >= 2 else None,
            "monotone": bool(all(a * b > 0 for a, b in zip(d, d[1:])))
            if len(d) >= 2 else None,
            "distanceToRange": dist,
            "finestInRange": bool(lo <= v[-1] <= hi),
            "approaching": bool(dist[-1] <= dist[-2]) if len(v) >= 2
            else None,
            "richardson": richardson(n, v),
        }
    return out


# -- CalculiX -----------------------------------------------------------------

def calculix_result(mesh):
    """Final length (max current y of the nodes, and of the axis' top
    node), impact-face radius (max current sqrt(x^2 + z^2) of the nodes at
    y = 0) and peak PEEQ (integration points, and nodal) at the last
    increment, from the .frd and .dat of run_calculix."""
    job = ccx_job(mesh)
    base = os.path.join(ccx_dir(), job)
    with open(base + ".time.json") as f:
        timing = json.load(f)
    nodes, last = ccx.read_frd(base + ".frd", ("DISP", "PE"))
    disp = last["DISP"]
    current = {i: np.add(x, disp[i][:3]) for i, x in nodes.items()}
    impact = [i for i, x in nodes.items() if abs(x[1]) < 1e-12]
    blocks = ccx.read_dat(base + ".dat")
    monitored = ccx.last_block(blocks, "displacements", "NMON")
    peeq = ccx.last_block(blocks, "equivalent", "EALL")
    axis = [i for i, x in nodes.items() if abs(x[0]) < 1e-12
            and abs(x[2]) < 1e-12]
    top = max(axis, key=lambda i: nodes[i][1])
    N, M, NY = mesh
    return {
        "mesh": "%d/%d/%d" % (N, M, NY),
        "job": job,
        "elements": (N * N + 2 * N * M) * NY,
        "increments": ccx.increments(base + ".frd"),
        "time": monitored["time"],
        "ccxWallTime_s": timing["wall"],
        "length_mm": 1e3 * max(x[1] for x in current.values()),
        "lengthAxis_mm": 1e3 * current[top][1],
        "footRadius_mm": 1e3 * max(math.hypot(current[i][0], current[i][2])
                                   for i in impact),
        "peakPlasticStrain": max(row[-1] for row in peeq["rows"]),
        "peakPlasticStrainNodal": max(v[0] for v in last["PE"].values()),
    }


# -- output -------------------------------------------------------------------

def acceptance(out):
    """Acceptance line 1 of issue 10 on the finest mesh."""
    n, fine = list(out["meshes"].items())[-1]
    conv = out["convergence"]
    res = {"mesh": n}
    for key, (lo, hi) in LITERATURE.items():
        res[key] = bool(lo <= fine[key] <= hi)
    res["converging"] = {k: bool(c["shrinking"] and c["approaching"])
                         for k, c in conv.items()}
    res["checkerFree"] = {
        f: bool(fine["checkerBoard"][f]["allCells"] <= CHECKER_FREE)
        for f in CHECKER_FIELDS}
    res["energyGrowthBelow1e-3"] = bool(
        fine["energy"]["maxGrowthRelative"] < 1e-3)
    res["pass"] = bool(all(res[k] for k in LITERATURE)
                       and all(res["converging"].values())
                       and all(res["checkerFree"].values())
                       and res["energyGrowthBelow1e-3"])
    record_checks(out, res)
    return res


#: The direction each quantity moves under refinement: the published
#: meshes (n 3 6 9) and CalculiX C3D8R (4/4/34 -> 6/6/50: 21.473 -> 21.448
#: mm, 6.774 -> 6.965 mm, 2.744 -> 3.051) agree: the length falls, the
#: foot radius and the peak strain grow
DIRECTION = {"length_mm": -1, "footRadius_mm": +1, "peakPlasticStrain": +1}
#: Factor on the remaining mesh error estimated from the last two meshes
BAND_FACTOR = 2.0


def published(out):
    """Whether the meshes are the published ones (three, finest n >= 9)."""
    return len(out["meshes"]) >= 3 and int(list(out["meshes"])[-1]) >= 9


def record_checks(out, res):
    """The verdicts of acceptance() in checks.json (validation/Allrun) on
    the published meshes; on fewer or coarser meshes (validation/Allrun
    -quick: n 3 6) what such meshes can promise (quick_checks)."""
    if not published(out):
        quick_checks(out)
        return
    n, fine = list(out["meshes"].items())[-1]
    for key, (lo, hi) in LITERATURE.items():
        checks.record(HERE, "n%s %s" % (n, key), fine[key],
                      "[%g, %g] (literature)" % (lo, hi), res[key])
    for key, ok in res["converging"].items():
        c = out["convergence"][key]
        checks.record(HERE, "%s converging (differences shrink, finest "
                      "nearer the range)" % key,
                      " ".join("%.4g" % v for v in c["values"]),
                      "shrinking, approaching", ok)
    for f, ok in res["checkerFree"].items():
        checks.record(HERE, "n%s checker-board C of %s" % (n, f),
                      fine["checkerBoard"][f]["allCells"],
                      "<= %g" % CHECKER_FREE, ok)
    checks.record(HERE, "n%s max energy growth / E0" % n,
                  fine["energy"]["maxGrowthRelative"], "< 1e-3",
                  res["energyGrowthBelow1e-3"])


def quick_checks(out):
    """On meshes coarser or fewer than the published ones: each quantity
    moves in the direction of DIRECTION between the last two meshes, and
    the finest lies within the literature range widened by BAND_FACTOR
    times the remaining mesh error estimated from the last difference
    d = v(n2) - v(n1) as first order, |d| / (n2/n1 - 1) (the order the
    published meshes show for the length, 0.6-0.8, is lower still; the
    range itself is asserted on the published meshes only); the
    checker-board index of the finest mesh and the energy growth of every
    mesh as on the published meshes."""
    ns = [int(n) for n in out["meshes"]]
    values = list(out["meshes"].values())
    n, fine = ns[-1], values[-1]
    sizes = "meshes n %s (the published study: n 3 6 9)" % " ".join(
        map(str, ns))
    for key, (lo, hi) in LITERATURE.items():
        v = [m[key] for m in values]
        if len(v) >= 2:
            d = v[-1] - v[-2]
            checks.record(
                HERE, "%s moves with refinement as on the published "
                "meshes and in CalculiX (n%d -> n%d)" % (key, ns[-2], n),
                d, "%s 0" % ("<" if DIRECTION[key] < 0 else ">"),
                d * DIRECTION[key] > 0, sizes)
            widen = BAND_FACTOR * abs(d) / (float(n) / ns[-2] - 1.0)
            checks.record(
                HERE, "n%d %s within the literature range widened by "
                "the mesh error" % (n, key), v[-1],
                "[%.4g, %.4g] ([%g, %g] +- %.3g)" % (
                    lo - widen, hi + widen, lo, hi, widen),
                lo - widen <= v[-1] <= hi + widen,
                "widening %g |d| / (n2/n1 - 1), d = %.3g; %s"
                % (BAND_FACTOR, d, sizes))
    for f in CHECKER_FIELDS:
        c = fine["checkerBoard"][f]["allCells"]
        checks.record(HERE, "n%d checker-board C of %s" % (n, f), c,
                      "<= %g" % CHECKER_FREE, c <= CHECKER_FREE)
    for m, r in zip(ns, values):
        g = r["energy"]["maxGrowthRelative"]
        checks.record(HERE, "n%d max energy growth / E0" % m, g, "< 1e-3",
                      g < 1e-3)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, nargs="+", default=[3, 6, 9])
    parser.add_argument("--calculix", nargs="+", default=["4,4,34",
                                                           "6,6,50"],
                        help="CalculiX meshes N,M,NY (decks.taylor_deck)")
    parser.add_argument("--no-calculix", action="store_true")
    parser.add_argument("--no-run", action="store_true",
                        help="only post-process the existing runs")
    args = parser.parse_args()
    args.n = sorted(args.n)
    ccx = [] if args.no_calculix else [
        tuple(int(v) for v in m.split(",")) for m in args.calculix]
    if any(len(m) != 3 for m in ccx):
        parser.error("--calculix takes N,M,NY triples")
    try:
        if not args.no_run:
            run.check_openfoam()
            for n in args.n:
                run_touch(n)
            for m in ccx:
                run_calculix(m)
        out = {"time": T_END, "literature": LITERATURE,
               "checkerBoardDefinition":
               "C = RMS(q_e - mean_nb(q)) / (2 RMS(q - mean q)), over the "
               "interior cells (no boundary face) and over all cells; "
               "mean_nb: mean over the cells sharing a face",
               "date": time.strftime("%Y-%m-%d", time.localtime(
                   os.path.getmtime(os.path.join(case_dir(args.n[-1]),
                                                 "wallTime.json")))),
               "meshes": {str(n): measure(case_dir(n)) for n in args.n}}
        out["convergence"] = convergence(args.n,
                                         list(out["meshes"].values()))
        out["calculix"] = [calculix_result(m) for m in ccx]
        out["acceptance"] = acceptance(out)
    except (run.RunError, OSError, ValueError, KeyError) as err:
        print("taylor: %s" % err, file=sys.stderr)
        return 1
    with open(os.path.join(HERE, "results.json"), "w") as f:
        json.dump(out, f, indent=2)
    write_markdown(out, os.path.join(HERE, "results.md"))
    plot(out, os.path.join(HERE, "taylor.png"))
    with open(os.path.join(HERE, "results.md")) as f:
        print(f.read())
    ok = out["acceptance"]["pass"]
    print("%s (issue 10, acceptance 1): results.json, results.md"
          % ("PASS" if ok else "FAIL"))
    if not published(out):
        # Acceptance 1 is for the published meshes; these are judged by
        # what they can promise (quick_checks)
        ok = checks.status(HERE) == 0
        print("%s (checks of meshes coarser than the published): "
              "checks.json" % ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
