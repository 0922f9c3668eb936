"""Contact between bodies: the contact function's rows and the bar
collision's closed forms of 1D elastic waves (tutorials/barCollision).

postProcessing/contact/<startTime>/contact.dat holds, at the first
Runge-Kutta stage of every step,
    # Time nFaces normalForce area maxPenetration mostTensileTraction
(force and area summed over the face pairs), with friction also
    maxFrictionRatio maxPairFrictionPower frictionPower maxPairFrictionRatio.
The bars of barCollision:
rho0 = 1400, E = 1.04e9, nu = 0.3 (c = 1000 m/s, Z = 1.4e6 Pa s/m), bar2's
modulus E2 (system/meshOptions), lengths L1, L2, velocities v1, v2.
"""

import glob
import math
import os

import numpy as np

from .foamfile import read_field
from .monitor import read_monitor
from .run import time_dirs

RHO = 1400.0
E = 1.04e9
NU = 0.3


def read_contact(case):
    """The contact rows as a dict of columns (folders of restarts joined,
    a later start replacing the rows it overlaps)."""
    names = ["Time", "nFaces", "normalForce", "area", "maxPenetration",
             "mostTensileTraction"]
    rows = []
    for path in sorted(glob.glob(os.path.join(
            case, "postProcessing", "contact", "*", "contact.dat")),
            key=lambda p: float(os.path.basename(os.path.dirname(p)))):
        # With friction the header names three more columns
        with open(path) as f:
            for line in f:
                if line.startswith("# Time"):
                    names = line.lstrip("#").split()
        data = np.loadtxt(path, comments="#", ndmin=2)
        if rows and len(data):
            rows = [r for r in rows if r[0] < data[0, 0]]
        rows.extend(list(data))
    data = np.array(rows).reshape(-1, len(names))
    return {name: data[:, i] for i, name in enumerate(names)}


def options(case):
    """The variant's settings of system/meshOptions (numbers and words)."""
    values = {}
    with open(os.path.join(case, "system", "meshOptions")) as f:
        for line in f:
            parts = line.replace(";", " ").split()
            if len(parts) == 2 and parts[0][0].isalpha() \
                    and parts[0] not in ("version", "format", "class",
                                         "object"):
                try:
                    values[parts[0]] = float(parts[1])
                except ValueError:
                    values[parts[0]] = parts[1]
    return values


def wave(modulus):
    """Speed and impedance of a uniaxial-strain wave."""
    lam = modulus * NU / ((1 + NU) * (1 - 2 * NU))
    mu = modulus / (2 * (1 + NU))
    c = math.sqrt((lam + 2 * mu) / RHO)
    return c, RHO * c


def bar_momenta(case, time_name, n1, n2):
    """The x-momentum per unit cross-section area of each bar (n1, n2
    cells along them, M x M across)."""
    o = options(case)
    k = int(o.get("M", 1)) ** 2
    lm = read_field(os.path.join(case, time_name, "lm")).internal(
        k * (n1 + n2))
    h = o["L1"] / n1
    return (h * np.sum(lm[:k * n1, 0]) / k,
            h * np.sum(lm[k * n1:k * (n1 + n2), 0]) / k)


def analyse(case):
    """The measured quantities of a barCollision case against their
    closed forms; a dict."""
    o = options(case)
    n1, n2 = int(o["N1"]), int(o["N2"])
    if o["variant"] == "wall":
        n2 = 0
    c1, z1 = wave(E)
    c2, z2 = wave(o.get("E2", E))
    v = o["v1"] - o["v2"]                     # approach speed
    area0 = (int(o.get("M", 1)) * o["L1"] / n1) ** 2

    rows = read_contact(case) if o["variant"] != "wall" else None
    m = read_monitor(case)
    out = {"variant": o["variant"], "c1": c1, "Z1": z1, "Z2": z2}

    # Momentum scale: the bodies' |p| at the start
    p0 = RHO * area0 * (o["L1"] * abs(o["v1"])
                        + (o["L2"] * abs(o["v2"]) if n2 else 0))
    out["momentumDrift"] = np.max(np.abs(m["px"] - m["px"][0])) / p0
    e = m["totalEnergy"]
    out["energyGrowth"] = max(0.0, np.max(np.diff(e))) / e[0]
    out["energyEnd"] = e[-1] / e[0]

    if rows is None:
        return out

    t = rows["Time"]
    stress = np.where(rows["area"] > 0,
                      rows["normalForce"] / np.maximum(rows["area"], 1e-300),
                      0.0)
    # The closed forms: Z1 Z2 v/(Z1 + Z2) (Z v/2 for one material; Z v for
    # two equal bars at +-v, whose approach speed is 2 v)
    sigma = z1 * z2 * v / (z1 + z2)
    tc = 2 * o["L1"] / c1
    if o["variant"] == "bimaterial":
        tc = min(tc, 2 * o["L2"] / c2)
    plateau = (t > 0.2 * tc) & (t < 0.8 * tc)
    out["contactStress"] = sigma
    out["plateauError"] = np.max(np.abs(stress[plateau] - sigma)) / sigma
    out["plateauMean"] = np.mean(stress[plateau])
    touching = np.nonzero(rows["nFaces"] > 0)[0]
    # The contact ends with the release (no face in contact); bars that
    # stay touching at rest (unequal) carry no stress after the unloading
    # front, whose middle (half the closed form's stress; the scheme
    # spreads it over a few cells) is taken then
    released = np.nonzero((t > 0.5 * tc) & (rows["nFaces"] == 0))[0]
    unloaded = np.nonzero((t > 0.5 * tc) & (stress < 0.5 * sigma))[0]
    out["contactTime"] = t[released[0]] if len(released) else np.inf
    out["unloadTime"] = t[unloaded[0]] if len(unloaded) else np.inf
    out["released"] = bool(len(released))
    out["contactTimeExact"] = 2 * o["L1"] / c1
    out["step"] = np.max(np.diff(t))
    out["maxPenetration"] = np.max(rows["maxPenetration"])
    out["mostTensile"] = np.max(rows["mostTensileTraction"][touching]) \
        if len(touching) else 0.0

    # The bars' momenta at the end against the initial ones
    times = time_dirs(case)
    end = times[max(times)]
    q1, q2 = bar_momenta(case, end, n1, n2)
    out["bar1End"] = q1 / (RHO * o["L1"] * o["v1"])
    out["bar2End"] = q2 / (RHO * o["L1"] * o["v1"])
    return out


def compare_with_wall(collision, wall):
    """max relative differences of bar1 of a collision case from the bar of
    the wall case, and of bar2 from bar1 mirrored, over the written times;
    (bar1, mirror) as dicts per field."""
    o = options(collision)
    n1, n2 = int(o["N1"]), int(o["N2"])
    first, mirror, scale = {}, {}, {}
    folders = time_dirs(collision)
    times = [folders[t] for t in sorted(folders) if t > 0]
    for name in times:
        for field in ("lm", "gradD", "sigma"):
            both = read_field(os.path.join(collision, name,
                                           field)).internal(n1 + n2)
            one = read_field(os.path.join(wall, name, field)).internal(n1)
            # Mirror x -> -x: a vector's x component and a tensor's xy,
            # xz, yx, zx components change sign
            sign = np.ones(both.shape[1])
            if both.shape[1] == 3:
                sign[0] = -1
            elif both.shape[1] == 6:
                sign[[1, 2]] = -1
            else:
                sign[[1, 2, 3, 6]] = -1
            mirrored = both[n1:][::-1] * sign
            first[field] = max(first.get(field, 0.0),
                               np.max(np.abs(both[:n1] - one)))
            mirror[field] = max(mirror.get(field, 0.0),
                                np.max(np.abs(mirrored - both[:n1])))
            # Relative to the field's largest magnitude over the run (gradD
            # = F - I: F's own digits end at 2.2e-12 of a strain of 1e-4)
            scale[field] = max(scale.get(field, 1e-300),
                               np.max(np.abs(one)))
    for field in scale:
        first[field] /= scale[field]
        mirror[field] /= scale[field]
    return first, mirror, len(times)


def depth_below_surface(x, points, faces, up=1):
    """How far each of the points x[points] lies below the surface drawn by
    the faces (lists of point labels into x), along the axis `up` (0, 1, 2):
    the surface's height over the point's position in the other two
    coordinates less the point's own, positive inside; -inf where no face
    lies over the point.  Each face is fanned into triangles about the mean
    of its points (the drawn surface within a face's sagitta)."""
    plane = [k for k in range(3) if k != up]
    tri = []
    for face in faces:
        corners = x[list(face)]
        centre = corners.mean(axis=0)
        for k in range(len(face)):
            tri.append((corners[k], corners[(k + 1) % len(face)], centre))
    tri = np.asarray(tri)                          # (T, 3 vertices, 3)
    a, b, c = (tri[:, k, :] for k in range(3))
    p = x[list(points)]                            # (P, 3)
    # Barycentric coordinates in the plane of the two other axes
    v0 = (b - a)[:, plane]
    v1 = (c - a)[:, plane]
    v2 = p[:, None, plane] - a[None, :, plane]     # (P, T, 2)
    det = v0[:, 0] * v1[:, 1] - v0[:, 1] * v1[:, 0]
    det = np.where(np.abs(det) > 0, det, np.inf)
    s = (v2[..., 0] * v1[None, :, 1] - v2[..., 1] * v1[None, :, 0]) / det
    t = (v0[None, :, 0] * v2[..., 1] - v0[None, :, 1] * v2[..., 0]) / det
    inside = (s >= -1e-12) & (t >= -1e-12) & (s + t <= 1 + 1e-12)
    height = (a[None, :, up] + s * (b - a)[None, :, up]
              + t * (c - a)[None, :, up])
    depth = np.where(inside, height - p[:, None, up], -np.inf)
    return depth.max(axis=1)
