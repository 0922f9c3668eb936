"""A steel ball denting a free aluminium plate (tutorials/projectileImpact):
the measured balance of momentum and energy, the friction bound, the
ball's rebound and the dent, beside simple independent estimates.

Quarter model (symmetric planes x = 0 and z = 0): the planes push along x
and z only and no wall acts, so the total p_y of the two bodies is
constant.  The estimates (rough, and said so in the README):
  - the plastic work: the energy not carried away by the two bodies' rigid
    motions, W = E0 - p_b^2/(2 m_b) - p_p^2/(2 M_p), with the momenta at
    the end (p_b + p_p = p0) and the masses of the meshed bodies (m_b =
    |p0|/V, M_p = rho W W T); it also holds the plate's elastic
    vibrations and the scheme's dissipation, so the plastic dissipation
    falls below it;
  - the dent: a rigid ball pressed into a rigid-perfectly-plastic
    half-space at the mean pressure 3 Y (D. Tabor, The Hardness of Metals,
    OUP 1951), contact radius a^2 = 2 R h, absorbs W = 3 pi Y R h^2, so
    h = sqrt(W/(3 pi Y R)) (the whole ball's W, four quarters), with the
    initial yield stress Y: hardening, the rate-free law and the free
    plate's bending all move it.
The dent measured: the plate's top point at the impact point below the
plate's centre of mass (the time integral of p_p/M_p), at the last written
time.
"""

import math
import os
import re

import numpy as np

from .contact import depth_below_surface, options, read_contact
from .foamfile import read_field
from .mesh import PolyMesh
from .monitor import read_monitor
from . import run as _run
from .run import time_dirs

#: the whole model over the quarter model
QUARTER = 4.0


def _number(text, name, default=None):
    m = re.search(r"^\s*%s\s+([-+0-9.eE]+)\s*;" % name, text, re.M)
    if m:
        return float(m.group(1))
    if default is None:
        raise ValueError("no entry %s" % name)
    return default


def materials(case):
    """{projectile, plate: {rho, E, nu, yieldStress, hardeningModulus}}."""
    with open(os.path.join(case, "constant", "mechanicalProperties")) as f:
        text = f.read()
    out = {}
    for zone in ("projectile", "plate"):
        m = re.search(r"\b%s\s*\{(.*?\{[^{}]*\}[^{}]*)\}" % zone, text, re.S)
        body = m.group(1)
        out[zone] = {k: float(v) for k, v in re.findall(
            r"\b(rho|E|nu|yieldStress|hardeningModulus)\s+([-+0-9.eE]+)\s*;",
            body)}
    return out


def geometry(case):
    """R, W, T of system/blockMeshDict (meters)."""
    with open(os.path.join(case, "system", "blockMeshDict")) as f:
        text = f.read()
    return {k: _number(text, k) for k in ("R", "W", "T")}


def initial_energy(case):
    """E0 of the solidMonitor's header."""
    import glob
    for path in sorted(glob.glob(os.path.join(
            case, "postProcessing", "solidMonitor", "*", "solidMonitor.dat"))):
        with open(path) as f:
            for line in f:
                if line.startswith("# E0"):
                    return float(line.split(":")[-1])
    raise ValueError("%s: no E0 in the solidMonitor's header" % case)


def dent(case, m, t, py_plate, M_plate):
    """The plate's top point at the origin below the plate's centre of
    mass at the last written time (m), and that time (s); None without a
    written pointD."""
    times = {v: d for v, d in time_dirs(case).items() if v > 0}
    if not times:
        return None, None
    last = times[max(times)]
    path = os.path.join(case, last, "pointD")
    if not os.path.exists(path):
        return None, None
    D = np.asarray(read_field(path).values).reshape(-1, 3)
    mesh = PolyMesh(case)
    top = mesh.patch_points("plateTop")
    X = mesh.points[top]
    origin = top[np.argmin(np.sum(X ** 2, axis=1))]
    # The plate's centre of mass: the impulse it received over its mass
    tl = float(last)
    keep = t <= tl + 1e-12
    tt = np.concatenate([[0.0], t[keep]])
    vv = np.concatenate([[0.0], py_plate[keep]]) / M_plate
    ycm = float(np.sum(0.5 * (vv[1:] + vv[:-1]) * np.diff(tt)))
    return ycm - float(D[origin, 1]), tl


def analyse(case):
    """The headline numbers and their estimates; a dict."""
    o = options(case)
    mat = materials(case)
    g = geometry(case)
    mon = read_monitor(case)
    t = np.asarray(mon["Time"])
    E0 = initial_energy(case)
    E = mon["totalEnergy"]

    pb = mon["py(projectile)"]
    pp = mon["py(plate)"]
    p0 = abs(pb[0] + pp[0])
    py = mon["p"][:, 1]
    V = o["V"]
    m_ball = p0 / V
    M_plate = mat["plate"]["rho"] * g["W"] ** 2 * g["T"]

    out = {"E0": E0, "p0": p0, "V": V, "tEnd": float(t[-1]),
           "steps": len(t)}
    out["momentumDrift"] = float(np.max(np.abs(py - py[0]))) / p0
    growth = np.diff(np.concatenate([[E0], E]))
    out["energyGrowth"] = float(np.max(growth)) / E0
    out["energyEnd"] = float(E[-1]) / E0
    out["plastic"] = float(mon["plasticDissipation"][-1]) / E0
    out["friction"] = float(mon["frictionDissipation"][-1]) / E0 \
        if "frictionDissipation" in mon else 0.0
    out["numerical"] = float(mon["numericalDissipation"][-1]) / E0
    out["numericalMin"] = float(np.min(mon["numericalDissipationFraction"]))
    # What the bodies hold and lost: kinetic + strain + plastic + friction
    # never grows (the contact is dissipative, the scheme too)
    S = E + mon["plasticDissipation"] + (mon["frictionDissipation"]
                                        if "frictionDissipation" in mon
                                        else 0.0)
    out["accountedGrowth"] = float(np.max(np.diff(S))) / E0
    out["accountedEnd"] = float(S[-1]) / E0
    out["ballVelocity"] = float(pb[-1]) / m_ball
    out["plateVelocity"] = float(pp[-1]) / M_plate
    out["ballMomentum"] = float(pb[-1]) / p0
    out["plateMomentum"] = float(pp[-1]) / p0
    rigid = (pb[-1] ** 2 / (2 * m_ball) + pp[-1] ** 2 / (2 * M_plate)) / E0
    out["plasticEstimate"] = 1.0 - rigid
    W = QUARTER * E0 * out["plasticEstimate"]
    Y = mat["plate"]["yieldStress"]
    out["dentEstimate"] = math.sqrt(W / (3 * math.pi * Y * g["R"]))
    out["dent"], out["dentTime"] = dent(case, mon, t, pp, M_plate)

    c = read_contact(case)
    out["maxFaces"] = int(np.max(c["nFaces"]))
    out["released"] = bool(c["nFaces"][-1] == 0 and np.max(c["nFaces"]) > 0)
    out["penetration"] = float(np.max(c["maxPenetration"]))
    out["mostTensile"] = float(np.max(c["mostTensileTraction"]))
    out["peakForce"] = QUARTER * float(np.max(c["normalForce"]))
    if "maxFrictionRatio" in c:
        out["faceFrictionRatio"] = float(np.max(c["maxFrictionRatio"]))
        out["pairFrictionPower"] = float(np.max(c["maxPairFrictionPower"]))
    if "maxPairFrictionRatio" in c:
        out["pairFrictionRatio"] = float(np.max(c["maxPairFrictionRatio"]))
    out["sideNodes"] = side_nodes(case)
    out["mu"] = friction_coefficient(case)
    # The smallest face of the plate's top (the penetration's scale)
    mesh = PolyMesh(case)
    fa = np.linalg.norm(mesh.face_areas[list(mesh.patch_faces("plateTop"))],
                        axis=1)
    out["faceSize"] = math.sqrt(float(np.min(fa)))
    out["pointDepth"], out["pointDepthTime"] = deepest_point(case, mesh)
    return out


def deepest_point(case, mesh):
    """How deep the ball's surface points lie inside the plate, below the
    top surface its points draw, the most over the written times (m), and
    that time (s); None without a written pointD."""
    ball = mesh.patch_points("ballSurface")
    top = [mesh.faces[f] for f in mesh.patch_faces("plateTop")]
    deepest, when = None, None
    for t, name in sorted(time_dirs(case).items()):
        path = os.path.join(case, name, "pointD")
        if t <= 0 or not os.path.exists(path):
            continue
        D = np.asarray(read_field(path).values).reshape(-1, 3)
        depth = float(np.max(depth_below_surface(mesh.points + D, ball,
                                                 top)))
        if deepest is None or depth > deepest:
            deepest, when = depth, t
    return deepest, when


def friction_coefficient(case):
    """muKinetic of the ball's bodyContact in 0/U (0 without friction)."""
    path = os.path.join(case, "0", "U")
    if not os.path.exists(path):
        path = os.path.join(case, "0.orig", "U")
    with open(path) as f:
        text = f.read()
    m = re.search(r"muKinetic\s+([-+0-9.eE]+)\s*;", text)
    return float(m.group(1)) if m else 0.0


def side_nodes(case):
    """Whether a bodyContact patch of the case's 0/U has side nodes (its
    points held on the partner: contact.dat's pair columns are then the
    held points')."""
    path = os.path.join(case, "0", "U")
    if not os.path.exists(path):
        path = os.path.join(case, "0.orig", "U")
    with open(path) as f:
        return re.search(r"\bside\s+nodes\s*;", f.read()) is not None


def elastic_copy(root, name, materials, nu, end_time, nodes=None):
    """A copy of tutorials/projectileImpact in root/name for the contact
    tests: each zone linearElastic with (zone, rho, E) of materials and
    Poisson's ratio nu, frictionless, FUpdate compatible, to end_time;
    nodes: the bodyContact patch given 'side nodes' (None: both patches
    'side both', whatever the tutorial gives)."""
    import shutil
    case = os.path.join(root, name)
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(_run.tutorial_dir("projectileImpact"), case,
                    ignore=shutil.ignore_patterns("render.py", "plot.py",
                                                  "state.py"))
    for zone, rho, modulus in materials:
        prefix = "materials/%s/" % zone
        _run.run(["foamDictionary", "constant/mechanicalProperties",
                  "-entry", prefix + "vonMisesPlasticCoeffs", "-remove"],
                 case, "foamDictionary")
        for key, value in (("model", "linearElastic"), ("rho", rho),
                           ("E", modulus), ("nu", nu)):
            _run.foam_set(case, "constant/mechanicalProperties",
                          prefix + key, value)
    for patch in ("ballSurface", "plateTop"):
        _run.run(["foamDictionary", "0.orig/U", "-entry",
                  "boundaryField/%s/friction" % patch, "-remove"],
                 case, "foamDictionary")
        _run.foam_set(case, "0.orig/U", "boundaryField/%s/side" % patch,
                      "nodes" if patch == nodes else "both")
    _run.write_options(case, "system/solverOptions",
                       {"FUpdate": "compatible"},
                       "The compatible update (the tutorial's too)")
    _run.foam_set(case, "system/controlDict", "endTime", end_time)
    return case


def invariant_failures(growth, remainder, drift, allowed_drift):
    """The contact tests' failures of the invariants: kinetic + strain
    energy grown by growth (E0) in a step, the numerical remainder fallen
    by -remainder (E0), the total momentum drifted by drift (|p0|)."""
    failures = []
    if not growth <= 1e-12:
        failures.append("kinetic + strain energy grew by %.2e E0 in a step"
                        % growth)
    if not remainder >= -1e-12:
        failures.append("the numerical remainder fell by %.2e E0 in a step"
                        % -remainder)
    if not drift <= allowed_drift:
        failures.append("total p_y drifted by %.2e of |p0| (allowed %.0e)"
                        % (drift, allowed_drift))
    return failures
