#!/usr/bin/python3
"""Gravity, the body force rho0 g of constant/g, against closed forms.

    /usr/bin/python3 test/cases/gravity.py

Copies of tutorials/elasticImpact (a bar of length L = 1 along x on
N x 1 x 1 cubic cells, linear elastic, rho0 = 1400, c_p = 1000 m/s):

  free fall   N = 8, every patch traction free, a uniform initial velocity
              U0 = (0.3, -0.2, 0.1) m/s, g = (1, -9.81, 2) m/s^2 in no
              particular direction, angular momentum preservation on:
              the body stays unstressed and moves as a rigid body, so
              lm = rho0 (U0 + g t) in every cell (the two-stage scheme
              integrates a constant rate exactly), kinetic + potential
              energy constant.
  column      N = 40, at rest and unstressed, clamped at its base X = 0
              with g = (-9.81, 0, 0) towards it and symmetricPlane sides
              (uniaxial strain): released at t = 0 it oscillates about
              the static state sigma_xx = -rho0 g (L - X) (it carries
              the weight above X).  In 1D every mode of the step
              response has a period T/(2k - 1), T = 4 L/c_p, so the mean
              over one period T of sigma_xx at any X is the static
              value; the mean is taken over 200 writes (trapezoids).
  control     the column without constant/g: nothing moves, and no
              potential energy column.

Asserted:
  - free fall: lm of every cell at every written time against
    rho0 (U0 + g t), 1e-12 relative to |lm|; the total energy (kinetic +
    strain + potential, the monitor's) constant to 1e-12 of the kinetic
    energy's scale M |U|^2; the stress-free body's strain energy 0 to
    round-off;
  - column: the period-mean of sigma_xx within 1 % of rho0 g L of the
    static -rho0 g (L - X) at every cell centre, and its peak over the
    run about twice the static value at the base (between 1.5 and 2.5:
    a sudden load); the energy never grows (1e-12 relative per step);
  - control: lm = 0 at the end and no potentialEnergy column.
Work folders: test/runs/gravity/.
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, run, testing  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

NAME = "gravity"
U0 = np.array([0.3, -0.2, 0.1])
G_FREE = np.array([1.0, -9.81, 2.0])
G_COLUMN = 9.81
WRITES = 200


def write_g(case, g):
    with open(os.path.join(case, "constant", "g"), "w") as f:
        f.write("FoamFile\n{\n    version 2.0;\n    format ascii;\n"
                "    class uniformDimensionedVectorField;\n"
                "    location \"constant\";\n    object g;\n}\n"
                "dimensions [0 1 -2 0 0 0 0];\n"
                "value (%r %r %r);\n" % tuple(g))


def written_times(case):
    times = []
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if t > 0 and os.path.isdir(os.path.join(case, name)):
            times.append((t, name))
    return sorted(times)


def free_fall(root, failures):
    end = 2e-3
    case = cases.prepare(
        "elasticImpact", os.path.join(root, "freeFall"), n=8,
        touch={"angularMomentumPreservation": "on"},
        control=dict(cases.precise_output(), endTime=end,
                     writeInterval=end / 4))
    free = "{ type traction; value uniform (0 0 0); }"
    for patch in ("wall", "free", "sides"):
        run.foam_set(case, "0/U", "boundaryField/" + patch, free)
    run.foam_set(case, "0/U", "internalField", "uniform (%r %r %r)"
                 % tuple(U0))
    write_g(case, G_FREE)
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)

    rho = cases.material(case)["rho"]
    n = PolyMesh(case).n_cells
    worst = 0.0
    times = written_times(case)
    for t, name in times:
        lm = read_field(os.path.join(case, name, "lm")).internal(n)
        exact = rho * (U0 + G_FREE * t)
        worst = max(worst, np.max(np.abs(lm - exact))
                    / np.linalg.norm(exact))
    m = read_monitor(case)
    if "potentialEnergy" not in m:
        failures.append("free fall: no potentialEnergy column")
        return "free fall: no potentialEnergy column"
    scale = np.max(m["kineticEnergy"])
    drift = np.max(np.abs(m["totalEnergy"] - m["totalEnergy"][0])) / scale
    strain = np.max(np.abs(m["strainEnergy"])) / scale
    ok = len(times) == 4 and worst <= 1e-12 and drift <= 1e-12 \
        and strain <= 1e-12
    line = ("free fall: %d times, max |lm - rho0 (U0 + g t)| / |lm| = %.2e,"
          " total energy drift %.2e, strain energy %.2e (of max kinetic)"
            % (len(times), worst, drift, strain))
    if not ok:
        failures.append("free fall: lm %.2e, energy %.2e, strain %.2e"
                        " (limits 1e-12), %d times"
                        % (worst, drift, strain, len(times)))
    return line


def column(root, label, g, failures):
    n_cells = 40
    case = cases.prepare("elasticImpact", os.path.join(root, label),
                         n=n_cells, control={})
    mat = cases.material(case)
    rho = mat["rho"]
    E, nu = mat["E"], mat["nu"]
    cp = np.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho)
    period = 4.0 / cp
    for key, value in dict(cases.precise_output(), endTime=period,
                           writeInterval=period / WRITES,
                           writeControl="adjustableRunTime").items():
        run.foam_set(case, "system/controlDict", key, value)
    run.foam_set(case, "0/U", "internalField", "uniform (0 0 0)")
    if g:
        write_g(case, (-g, 0, 0))
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    return case, rho, period


def column_checks(root, failures):
    case, rho, period = column(root, "column", G_COLUMN, failures)
    mesh = PolyMesh(case)
    X = mesh.cell_centres[:, 0]
    times = written_times(case)
    t = np.array([0.0] + [tt for tt, _ in times])
    sxx = [np.zeros(len(X))]
    for _, name in times:
        sigma = read_field(os.path.join(case, name, "sigma")).internal(
            len(X))
        sxx.append(sigma[:, 0])
    sxx = np.array(sxx)
    mean = np.trapz(sxx, t, axis=0) / (t[-1] - t[0])
    static = -rho * G_COLUMN * (1.0 - X)
    scale = rho * G_COLUMN * 1.0
    error = np.max(np.abs(mean - static)) / scale
    base = int(np.argmin(X))
    peak = np.min(sxx[:, base]) / static[base]
    m = read_monitor(case)
    E = m["totalEnergy"]
    growth = np.max(np.diff(E)) / np.max(np.abs(E))
    line = ("column: %d writes over T = %.4g s (t_end %.6g); period-mean"
          " sigma_xx against -rho0 g (L - X): max error %.3e of rho0 g L;"
          " base peak %.3f x static; energy growth per step %.2e"
            % (len(times), period, t[-1], error, peak, growth))
    if abs(t[-1] - period) > 1e-9 * period or len(times) < WRITES * 0.9:
        failures.append("column: ran to %g with %d writes, expected %g and"
                        " %d" % (t[-1], len(times), period, WRITES))
    if error > 0.01:
        failures.append("column: period-mean stress off the static one by"
                        " %.3e of rho0 g L (limit 0.01)" % error)
    if not 1.5 <= peak <= 2.5:
        failures.append("column: base peak %.3f x static, not about 2"
                        % peak)
    if growth > 1e-12:
        failures.append("column: energy grew by %.2e in a step" % growth)
    return line


def control(root, failures):
    n_cells = 8
    case = cases.prepare("elasticImpact", os.path.join(root, "control"),
                         n=n_cells, control={"endTime": 1e-4,
                                             "writeInterval": 1e-4})
    run.foam_set(case, "0/U", "internalField", "uniform (0 0 0)")
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    lm = read_field(os.path.join(case, written_times(case)[-1][1],
                                 "lm")).internal(n_cells)
    m = read_monitor(case)
    line = ("control (no constant/g): max |lm| = %.1e, potentialEnergy"
            " column %s" % (np.max(np.abs(lm)),
                            "present" if "potentialEnergy" in m
                            else "absent"))
    if np.max(np.abs(lm)) != 0 or "potentialEnergy" in m:
        failures.append("control: a case without constant/g moved or"
                        " reported a potential energy")
    return line


def body():
    root = testing.work_dir(NAME)
    lines, failures = [], []
    for check in (free_fall, column_checks, control):
        lines.append(check(root, failures))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
