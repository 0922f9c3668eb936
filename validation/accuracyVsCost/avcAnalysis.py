"""The cases and settings of accuracyVsCost.py, the measurements of one run
folder, the Pareto fronts and the recommendation, and the analysis of a
case's runs.

Imported by accuracyVsCost.py (the sweep) and avcReport.py (results.md and
the plots); accuracyVsCost.py's docstring has every rule.  Importing it puts
bin/python and validation/swingingCube, twistingColumn and stabilityMap on
sys.path.
"""

import json
import math
import os
import statistics
import sys

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
import twist  # noqa: E402  (validation/twistingColumn)

RECONSTRUCTIONS = ["firstOrder", "linear", "limitedLinear"]
# (timeScheme, CFL); the largest of each scheme is its measured limit
TIME_SETTINGS = [("RK2", 0.3), ("RK2", 0.5), ("RK2", 0.6),
                 ("RK3", 0.5), ("RK3", 1.0)]
MIN_TIMED = 2.0         # repeat a run until its loop times add up to this [s]
EXTRAPOLATE = 4.0       # log-log extrapolation beyond the finest mesh's cost
COST_TIE = 0.1          # loop times closer than this (relative) are a tie
ERROR_TIE = 0.1         # errors at equal cost closer than this: a tie
RUN_INFO = "accuracyVsCost.json"

#: the converged mean top twist at 0.1 s and its band [deg]: both codes'
#: Richardson extrapolations, validation/twistingColumn/reference.py (the
#: one reference validation/calculix uses too)
with open(os.path.join(VALIDATION, "twistingColumn", "reference.json")) as _f:
    _converged = json.load(_f)
TWIST_REFERENCE = round(_converged["reference"], 2)
TWIST_BAND = tuple(round(b, 2) for b in _converged["band"])

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


# -- a case's runs ------------------------------------------------------------

def sweep_rows(name, meshes):
    """Rows of every sweep run folder of case `name` on `meshes`."""
    folder = os.path.join(HERE, "runs", name, "sweep")
    rows = []
    for entry in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        row = analyse_point(os.path.join(folder, entry))
        if row and row["n"] in meshes:
            rows.append(row)
    return rows


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
