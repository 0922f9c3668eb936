"""Hertz impact of elastic spheres (tutorials/sphereImpact): the closed
form and the measured contact time and peak force.

The closed form (K.L. Johnson, Contact Mechanics, CUP 1985, ch. 4 and
11.4), approach speed V, valid while
V << c and the contact radius a << R:
    1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,  1/R* = 1/R1 + 1/R2,
    1/m* = 1/m1 + 1/m2   (a rigid wall: E2, R2, m2 -> infinity)
    delta_max = (15 m* V^2 / (16 E* sqrt(R*)))^(2/5)
    F_max = 4/3 E* sqrt(R*) delta_max^(3/2),  a_max = sqrt(R* delta_max)
    t_c = 2.94 delta_max / V
The tutorial's balls are quarter models (symmetric planes x = 0, z = 0):
the whole ball's force is four times the quarter's.  F(t): the rigid
wall's force of every step (solidMonitor column wallForce(contact1)), or
the contact force between the balls (postProcessing/contact,
touchfoam.contact.read_contact).  Contact starts at t = 0 (the poles
touch); it ends at the first step after the peak with no face in contact.
"""

import math
import os
import re

import numpy as np

from .contact import options, read_contact
from .monitor import read_monitor

#: the whole ball over the quarter model
QUARTER = 4.0


def closed_form(V, R1, E1, nu1, rho1, R2=None, E2=None, nu2=None, rho2=None):
    """delta_max, F_max, a_max, t_c (and E*, R*, m*) for a ball of radius
    R1 meeting a ball of radius R2 (None: a rigid wall) at speed V."""
    m1 = rho1 * 4.0 / 3.0 * math.pi * R1 ** 3
    inv_E = (1 - nu1 ** 2) / E1
    inv_R = 1.0 / R1
    inv_m = 1.0 / m1
    if R2 is not None:
        inv_E += (1 - nu2 ** 2) / E2
        inv_R += 1.0 / R2
        inv_m += 1.0 / (rho2 * 4.0 / 3.0 * math.pi * R2 ** 3)
    Es, Rs, ms = 1.0 / inv_E, 1.0 / inv_R, 1.0 / inv_m
    delta = (15.0 * ms * V ** 2 / (16.0 * Es * math.sqrt(Rs))) ** 0.4
    return {"delta": delta,
            "F": 4.0 / 3.0 * Es * math.sqrt(Rs) * delta ** 1.5,
            "a": math.sqrt(Rs * delta),
            "tc": 2.94 * delta / V,
            "Estar": Es, "Rstar": Rs, "mstar": ms}


def materials(case):
    """{zone: {rho, E, nu}} of constant/mechanicalProperties' materials
    (the balls' sub-dictionaries, read whatever #ifeq is around them)."""
    with open(os.path.join(case, "constant", "mechanicalProperties")) as f:
        text = f.read()
    out = {}
    for zone, body in re.findall(r"\b(ball\d)\s*\{([^{}]*)\}", text):
        values = dict(re.findall(r"\b(rho|E|nu)\s+([-+0-9.eE]+)\s*;", body))
        out[zone] = {k: float(v) for k, v in values.items()}
    return out


def case_closed_form(case):
    """The closed form of a sphereImpact case (system/meshOptions)."""
    o = options(case)
    mat = materials(case)
    b1 = mat["ball1"]
    V = o["V1"] + o.get("V2", 0.0)
    if o["variant"] == "wall":
        return closed_form(V, o["R1"], b1["E"], b1["nu"], b1["rho"])
    b2 = mat.get("ball2", b1)
    return closed_form(V, o["R1"], b1["E"], b1["nu"], b1["rho"],
                       o["R2"], b2["E"], b2["nu"], b2["rho"])


def force_history(case):
    """(t, F of the whole ball, faces in contact) of every step."""
    if options(case)["variant"] == "wall":
        m = read_monitor(case)
        return (m["Time"], QUARTER * np.abs(m["wallForce(contact1)"]),
                m["contactFaces(contact1)"])
    rows = read_contact(case)
    return rows["Time"], QUARTER * np.abs(rows["normalForce"]), \
        rows["nFaces"]


def analyse(case):
    """Contact time and peak force against the closed form, the energy
    and, between the balls, the momentum exchange; a dict."""
    o = options(case)
    ref = case_closed_form(case)
    t, F, faces = force_history(case)
    peak = int(np.argmax(F))
    after = np.nonzero((np.arange(len(t)) > peak) & (faces == 0))[0]
    out = {"variant": o["variant"], "reference": ref,
           "peakForce": float(F[peak]), "peakTime": float(t[peak]),
           "released": bool(len(after)),
           "contactTime": float(t[after[0]]) if len(after) else np.inf,
           "step": float(np.max(np.diff(t))) if len(t) > 1 else 0.0,
           "maxFaces": int(np.max(faces))}
    out["forceError"] = out["peakForce"] / ref["F"] - 1
    out["timeError"] = out["contactTime"] / ref["tc"] - 1

    m = read_monitor(case)
    E = m["totalEnergy"]
    out["energyGrowth"] = max(0.0, float(np.max(np.diff(E)))) / E[0]
    out["energyEnd"] = float(E[-1] / E[0])
    if "numericalDissipationFraction" in m:
        out["dissipationMin"] = float(np.min(
            m["numericalDissipationFraction"]))
    py = m["p"][:, 1]
    out["reboundMomentum"] = float(py[-1] / py[0])
    if o["variant"] != "wall":
        # No wall, no fixed boundary along y (the symmetric planes push
        # along x and z only): the balls' total p_y is constant
        p0 = abs(m["py(ball1)"][0]) + abs(m["py(ball2)"][0])
        out["momentumDrift"] = float(np.max(np.abs(py - py[0]))) / p0
        out["ball1End"] = float(m["py(ball1)"][-1] / p0)
        out["ball2End"] = float(m["py(ball2)"][-1] / p0)
        # The force the balls receive (their momentum change over each
        # step, the mean of the two), not the pairs' Riemann traction:
        # with the compatible update the contact acts through the points'
        # constraint, whose reaction is the force applied
        tm = np.asarray(m["Time"])
        dp = 0.5 * (np.diff(m["py(ball2)"]) - np.diff(m["py(ball1)"]))
        Fa = QUARTER * np.abs(dp / np.diff(tm))
        out["appliedPeak"] = float(np.max(Fa))
        out["appliedForceError"] = out["appliedPeak"] / ref["F"] - 1
    return out


def elastic_momenta(case):
    """The balls' y-momenta after an elastic collision of rigid balls, over
    ball1's initial |p| (ball1 at -V1, ball2 at V2 along y)."""
    o = options(case)
    mat = materials(case)
    b1 = mat["ball1"]
    b2 = mat.get("ball2", b1)
    m1 = b1["rho"] * o["R1"] ** 3
    m2 = b2["rho"] * o["R2"] ** 3
    v1, v2 = -o["V1"], o.get("V2", 0.0)
    w1 = ((m1 - m2) * v1 + 2 * m2 * v2) / (m1 + m2)
    w2 = ((m2 - m1) * v2 + 2 * m1 * v1) / (m1 + m2)
    p0 = m1 * abs(v1) + m2 * abs(v2)
    return m1 * w1 / p0, m2 * w2 / p0


def force_curve(ref, V, n=2000):
    """(t, F) of the Hertz impact, m* delta'' = -4/3 E* sqrt(R*)
    delta^(3/2) from delta = 0 at speed V, integrated (RK4, n steps over
    the closed form's t_c) until delta returns to 0."""
    k = 4.0 / 3.0 * ref["Estar"] * math.sqrt(ref["Rstar"]) / ref["mstar"]
    dt = ref["tc"] / n

    def rate(y):
        return np.array([y[1], -k * max(y[0], 0.0) ** 1.5])

    y, t = np.array([0.0, V]), 0.0
    ts, ds = [0.0], [0.0]
    while True:
        k1 = rate(y)
        k2 = rate(y + 0.5 * dt * k1)
        k3 = rate(y + 0.5 * dt * k2)
        k4 = rate(y + dt * k3)
        y = y + dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
        t += dt
        if y[0] <= 0:
            break
        ts.append(t)
        ds.append(y[0])
    ts.append(t)
    ds.append(0.0)
    d = np.array(ds)
    return np.array(ts), k * ref["mstar"] * d ** 1.5


def initial_energy(case):
    """E0 of the solidMonitor's header (kinetic + strain + potential energy
    at its start): the balls' laws differ by zone, so the single-material
    readers do not apply."""
    import glob
    for path in sorted(glob.glob(os.path.join(
            case, "postProcessing", "solidMonitor", "*", "solidMonitor.dat"))):
        with open(path) as f:
            for line in f:
                if line.startswith("# E0"):
                    return float(line.split(":")[-1])
    raise ValueError("%s: no E0 in the solidMonitor's header" % case)
