#!/usr/bin/python3
"""The solidMonitor's energy balance and its bodies, against closed forms.

    /usr/bin/python3 test/cases/energyBalance.py

    E0 + boundaryWork = K + S + V + plasticDissipation + numericalDissipation

  uniform strain  tutorials/elasticImpact (bar [0, 1] along x, N = 8 cubic
                  cells, linear elastic), reconstruction linear: the end
                  x = 0 and the sides symmetric planes (mirrors: a cell
                  of a one-cell-thick bar reconstructs from its reflections
                  across them, and every gradient is then exact for a
                  linear field), the end x = 1 pulled
                  at a prescribedVelocity v0 = 1 m/s, the cells at
                  U = v0 X/L.  The exact solution keeps that velocity and
                  stretches the bar uniformly, F = I + (v0 t/L) e_x e_x:
                  the stress is uniform, no jump is damped, and the
                  scheme's solution is the exact one (F linear in t, the
                  stress linear in F, the power linear in t, which every
                  Runge-Kutta quadrature integrates exactly).  So
                  W(t) = S(t) - S(0) = (lambda + 2 mu)/2 (v0 t/L)^2 V and
                  the numerical dissipation vanishes.  RK2 and RK3.
  Taylor bar      tutorials/taylorImpact -n 3 (240 cells, von Mises, rigid
                  wall) to 80 us: the numerical dissipation >= 0 at every
                  step; the plastic dissipation against the written
                  epsilonP: with linear hardening the work of the flow is
                  sum_e V_e (sigma_y0 epsbar_p + H epsbar_p^2/2), the
                  integral of the yield stress over epsbar_p.
  bar rebound     tutorials/barRebound -n 3 (neo-Hookean, rigid wall, the
                  bar leaves it): numerical dissipation >= 0 at every step,
                  the fixed frictionless wall does no work.
  moving wall     rigidWallBounce's bar (N = 50) at rest, hit by a
                  rigid wall moving at v0: the wall's work is v0 times the
                  momentum it gave, v0 (p - p0), exactly.  With the plain
                  update the momentum rate is the flux's, so W equals it to
                  round-off; the compatible update applies the wall's force
                  as its constraint's nodal reaction, which differs from
                  the faces' flux t^C |C_f| (rigidWall.H): W differs by
                  0.4 % (measured), and the numerical dissipation takes
                  the difference, staying >= 0.
  two bodies      two blocks of one blockMesh, 1 x 0.5 x 0.5 m and a gap
                  of 0.5 m, cellZones left and right, traction free,
                  flying apart with velocities that vary over each block
                  (so that waves run through them): two bodies named
                  after their zones; the momentum of each constant to
                  1e-12 of its initial one (no force acts on either);
                  the bodies' momenta, energies, work and numerical
                  dissipation add up to the totals; each body's
                  numerical dissipation >= 0; on two ranks (each
                  block cut) every column equals the serial one.  Under
                  gravity g = (0, -9.81, 3): each body's momentum is
                  p0 + rho V g t (V = 0.25 m^3) to 1e-12, the bodies'
                  potential energies add up to the total.

Asserted: uniform strain: |numericalDissipation| <= 1e-10 of the stored
energy at every step, boundaryWork and strainEnergy within 1e-10 of the
closed form at the end, the kinetic energy constant to 1e-10 (round-off:
F = 1.002 keeps the strain 2e-3 to about 1e-13 a step; measured 1e-12),
no per-body columns for one body; Taylor bar and bar rebound: numericalDissipation
>= -1e-12 E0 at every step (round-off), plastic dissipation within 1e-10
of the field's; two bodies: 2 ranks = serial to 1e-10 of each column's scale (the
momenta's own, the energies' at least 1e-3 of the largest kinetic
energy); moving wall: W within 1e-10 (plain) and 1e-2 (compatible)
of v0 (p - p0), numerical dissipation >= 0 at every step; two bodies: as above.
Work folders: test/runs/energyBalance/.
"""

import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, run, testing  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

NAME = "energyBalance"
V0 = 1.0


def vector_list(values):
    return "nonuniform List<vector> %d (%s)" % (
        len(values), " ".join("(%r %r %r)" % tuple(v) for v in values))


def uniform_strain(root, scheme, failures):
    end = 2e-3
    case = cases.prepare(
        "elasticImpact", os.path.join(root, "uniformStrain" + scheme), n=8,
        touch={"reconstruction": "linear", "timeScheme": scheme,
               "symmetricPlanes": "mirror"},
        control=dict(cases.precise_output(), endTime=end,
                     writeInterval=end))
    run.foam_set(case, "0/U", "boundaryField/wall",
                 "{ type symmetricPlane; value uniform (0 0 0); }")
    run.foam_set(case, "0/U", "boundaryField/free",
                 "{ type prescribedVelocity; velocity uniform (%r 0 0); }"
                 % V0)
    mesh = PolyMesh(case)
    X = mesh.cell_centres
    U = np.zeros_like(X)
    U[:, 0] = V0 * X[:, 0]
    run.foam_set(case, "0/U", "internalField", vector_list(U))
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)

    mat = cases.material(case)
    E, nu = mat["E"], mat["nu"]
    M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))    # lambda + 2 mu
    volume = np.sum(mesh.cell_volumes)
    m = read_monitor(case)
    t = m["Time"]
    exact = 0.5 * M * (V0 * t) ** 2 * volume
    scale = exact[-1]
    numerical = np.max(np.abs(m["numericalDissipation"])) / scale
    work = abs(m["boundaryWork"][-1] - exact[-1]) / scale
    strain = abs(m["strainEnergy"][-1] - exact[-1]) / scale
    kinetic = np.max(np.abs(m["kineticEnergy"] - m["kineticEnergy"][0])) \
        / m["kineticEnergy"][0]
    per_body = [k for k in m if "(" in k and k.split("(")[0] in ("px",
                                                                 "kineticEnergy")]
    line = ("uniform strain %s: %d steps to %g s, W = %.6g J against"
            " (lambda + 2 mu)/2 (v0 t)^2 V = %.6g J (%.1e), S off by %.1e,"
            " max |numerical dissipation| %.1e of it, K constant to %.1e"
            % (scheme, len(t), t[-1], m["boundaryWork"][-1], exact[-1],
               work, strain, numerical, kinetic))
    if abs(t[-1] - end) > 1e-9 * end:
        failures.append("uniform strain %s: ran to %g" % (scheme, t[-1]))
    if max(numerical, work, strain, kinetic) > 1e-10:
        failures.append("uniform strain %s: balance off (numerical %.1e,"
                        " work %.1e, strain %.1e, kinetic %.1e; limit"
                        " 1e-10)" % (scheme, numerical, work, strain,
                                     kinetic))
    if per_body or "boundaryWork(free)" not in m:
        failures.append("uniform strain %s: one body has per-body columns"
                        " %s or no boundaryWork(free)" % (scheme, per_body))
    return line


def remainder_check(label, m, failures):
    E0 = m["totalEnergy"][0] + m["numericalDissipation"][0] \
        + m.get("plasticDissipation", np.zeros(1))[0] \
        - m["boundaryWork"][0]
    numerical = m["numericalDissipation"]
    worst = np.min(numerical) / E0
    drop = np.min(np.diff(numerical)) / E0
    if worst < -1e-12:
        failures.append("%s: numerical dissipation %.2e E0 < 0"
                        % (label, worst))
    return E0, worst, drop


def taylor_bar(root, failures):
    end = 8e-5
    case = cases.prepare(
        "taylorImpact", os.path.join(root, "taylorBar"), n=3,
        control=dict(cases.precise_output(), endTime=end,
                     writeInterval=end))
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    m = read_monitor(case)
    E0, worst, drop = remainder_check("Taylor bar", m, failures)

    mat = cases.material(case)
    sy = float(mat.get("yieldStress", 0.4e9))
    H = float(mat.get("hardeningModulus", 0.1e9))
    mesh = PolyMesh(case)
    name = run.latest_time_dir(case)
    eps = read_field(os.path.join(case, name, "epsilonP")).internal(
        mesh.n_cells)
    field = np.sum(mesh.cell_volumes * (sy * eps + 0.5 * H * eps ** 2))
    plastic = m["plasticDissipation"][-1]
    off = abs(plastic - field) / field
    if off > 1e-10:
        failures.append("Taylor bar: plastic dissipation %.8g J, the"
                        " written epsilonP's %.8g J (%.1e)"
                        % (plastic, field, off))
    if np.max(np.abs(m["boundaryWork"])) > 1e-12 * E0:
        failures.append("Taylor bar: the fixed frictionless wall did work")
    return ("Taylor bar -n 3: %d steps, numerical dissipation min %.2e E0,"
            " end %.4f E0 (smallest change in a step %.1e E0), plastic %.4f E0"
            " (field's to %.1e), left K + S %.4f E0"
            % (len(m["Time"]), worst, m["numericalDissipation"][-1] / E0,
               drop, plastic / E0, off,
               m["totalEnergy"][-1] / E0))


def bar_rebound(root, failures):
    case = cases.prepare("barRebound", os.path.join(root, "barRebound"),
                         n=3, control=cases.precise_output())
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    m = read_monitor(case)
    E0, worst, drop = remainder_check("bar rebound", m, failures)
    if np.max(np.abs(m["boundaryWork"])) > 1e-12 * E0:
        failures.append("bar rebound: the fixed frictionless wall did work")
    return ("bar rebound -n 3: %d steps, numerical dissipation min %.2e E0,"
            " end %.4f E0 (smallest change in a step %.1e E0)"
            % (len(m["Time"]), worst, m["numericalDissipation"][-1] / E0,
               drop))


def moving_wall(root, update, limit, failures):
    """The bar of rigidWallBounce at rest, hit by a wall moving at +v0: the
    wall's work is v0 times the momentum it gives (its velocity is uniform
    and constant)."""
    import rigidWallBounce as rwb
    v0, gap, end = rwb.V0, 2.5e-5, 2.5e-3
    case = rwb.bar(root, "movingWall_" + update, 50,
                   rwb.wall_entry(gap, v0), end, at_rest=True,
                   update=update, control=cases.precise_output())
    m = rwb.solve(case)
    W = m["boundaryWork"]
    exact = v0 * (m["px"] - m["px"][0])
    # The first row is after the first step; the bar is not touched before
    # gap/v0
    off = np.max(np.abs(W - exact)) / np.max(np.abs(exact))
    numerical = m["numericalDissipation"]
    worst = np.min(numerical) / W[-1]
    if off > limit:
        failures.append("moving wall (%s): work off v0 (p - p0) by %.2e"
                        " (limit %.0e)" % (update, off, limit))
    if worst < -1e-12:
        failures.append("moving wall (%s): numerical dissipation %.2e W"
                        % (update, worst))
    return ("moving wall (%s, N 50): W = %.6g J, v0 (p - p0) = %.6g J (off"
            " by %.1e), numerical dissipation %.3f W at the end, min %.1e"
            % (update, W[-1], exact[-1], off, numerical[-1] / W[-1], worst))


TWO_BLOCKS = """
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
scale 1;
vertices
(
    (0 0 0) (1 0 0) (1 0.5 0) (0 0.5 0)
    (0 0 0.5) (1 0 0.5) (1 0.5 0.5) (0 0.5 0.5)
    (1.5 0 0) (2.5 0 0) (2.5 0.5 0) (1.5 0.5 0)
    (1.5 0 0.5) (2.5 0 0.5) (2.5 0.5 0.5) (1.5 0.5 0.5)
);
blocks
(
    hex (0 1 2 3 4 5 6 7) left (4 2 2) simpleGrading (1 1 1)
    hex (8 9 10 11 12 13 14 15) right (4 2 2) simpleGrading (1 1 1)
);
defaultPatch { name free; type patch; }
boundary ();
"""


def two_bodies(root, failures):
    end = 2e-3
    case = os.path.join(root, "twoBodies")
    run.copy_case(run.tutorial_dir("elasticImpact"), case)
    with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
        f.write(TWO_BLOCKS)
    for key, value in dict(cases.precise_output(), endTime=end,
                           writeInterval=end).items():
        run.foam_set(case, "system/controlDict", key, value)
    run.restore0(case)
    run.run(["blockMesh"], case)
    mesh = PolyMesh(case)
    X = mesh.cell_centres
    left = X[:, 0] < 1.25
    U = np.zeros_like(X)
    U[left] = np.column_stack([-1 + 0.5 * X[left, 1], 0.3 + 0 * X[left, 0],
                               -0.4 * X[left, 2]])
    U[~left] = np.column_stack([2 + 0 * X[~left, 0], -0.1 * X[~left, 0],
                                0.2 + 0.3 * X[~left, 1]])
    with open(os.path.join(case, "0", "U"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class volVectorField;"
                " object U; }\ndimensions [0 1 -1 0 0 0 0];\n"
                "internalField %s;\nboundaryField\n{\n    free { type"
                " traction; value uniform (0 0 0); }\n}\n" % vector_list(U))
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    m = read_monitor(case)

    # The same on two ranks, each block cut between them
    par = os.path.join(root, "twoBodiesParallel")
    # The mesh and 0/ too (copy_case takes the inputs only)
    shutil.copytree(case, par, ignore=shutil.ignore_patterns(
        "postProcessing", "processor*", "log.*", "%g" % end))
    with open(os.path.join(par, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary;"
                " object decomposeParDict; }\nnumberOfSubdomains 2;\n"
                "method simple;\ncoeffs { n (1 2 1); }\n")
    run.run(["decomposePar", "-force"], par)
    run.run_parallel(["touchFoam"], par, 2, timeout=testing.RUN_TIMEOUT)
    mp = read_monitor(par)
    worst_par = 0.0
    for column in m:
        if column in ("p", "L"):
            continue
        if column not in mp or len(mp[column]) != len(m[column]):
            failures.append("two bodies: 2 ranks lack column %s or rows"
                            % column)
            break
        scale = max(np.max(np.abs(m[column])),
                    1e-3 * np.max(m["kineticEnergy"]), 1e-300)
        if column[0] in "pL" or column == "Time":
            scale = max(np.max(np.abs(m[column])), 1e-300)
        worst_par = max(worst_par,
                        np.max(np.abs(mp[column] - m[column])) / scale)
    if worst_par > 1e-10:
        failures.append("two bodies: 2 ranks differ from serial by %.1e"
                        % worst_par)

    lines = []
    if not all(k in m for k in ("px(left)", "px(right)")):
        failures.append("two bodies: no columns of bodies left and right"
                        " (%s)" % [k for k in m if "(" in k])
        return "two bodies: no per-body columns"
    worst_p = 0.0
    for body in ("left", "right"):
        p = np.column_stack([m["p%s(%s)" % (c, body)] for c in "xyz"])
        worst_p = max(worst_p, np.max(np.linalg.norm(p - p[0], axis=1))
                      / np.linalg.norm(p[0]))
        if np.min(m["numericalDissipation(%s)" % body]) \
                < -1e-12 * m["kineticEnergy(%s)" % body][0]:
            failures.append("two bodies: numerical dissipation of %s < 0"
                            % body)
    worst_sum = 0.0
    for column in ("px", "py", "pz", "Lx", "Ly", "Lz", "kineticEnergy",
                   "strainEnergy", "boundaryWork", "numericalDissipation"):
        parts = m[column + "(left)"] + m[column + "(right)"]
        scale = max(np.max(np.abs(m[column])), 1e-300)
        if column in ("Lx", "Ly", "Lz", "boundaryWork",
                      "numericalDissipation", "strainEnergy"):
            scale = max(scale, np.max(m["kineticEnergy"]) * 1e-3)
        worst_sum = max(worst_sum, np.max(np.abs(parts - m[column])) / scale)
    E0 = m["totalEnergy"][0]
    lines.append("two bodies (left, right; %d steps): each body's momentum"
                 " constant to %.1e, bodies sum to the totals to %.1e,"
                 " numerical dissipation %.2e E0 at the end; 2 ranks"
                 " equal serial to %.1e"
                 % (len(m["Time"]), worst_p, worst_sum,
                    m["numericalDissipation"][-1] / E0, worst_par))
    if worst_p > 1e-12:
        failures.append("two bodies: a body's momentum changed by %.1e"
                        % worst_p)
    if worst_sum > 1e-12:
        failures.append("two bodies: the bodies' columns add up to the"
                        " totals only to %.1e" % worst_sum)
    return "; ".join(lines)


def falling_bodies(root, failures):
    """The two blocks under gravity: each body's momentum grows by its
    weight, p_B(t) = p_B(t1) + rho V_B g (t - t1), and the bodies'
    potential energies add up to the total."""
    g = np.array([0.0, -9.81, 3.0])
    case = os.path.join(root, "fallingBodies")
    shutil.copytree(os.path.join(root, "twoBodies"), case,
                    ignore=shutil.ignore_patterns(
                        "postProcessing", "processor*", "log.*", "0.002"))
    with open(os.path.join(case, "constant", "g"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class"
                " uniformDimensionedVectorField; object g; }\n"
                "dimensions [0 1 -2 0 0 0 0];\nvalue (%r %r %r);\n"
                % tuple(g))
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    m = read_monitor(case)
    rho = cases.material(case)["rho"]
    t = m["Time"] - m["Time"][0]
    worst = 0.0
    for body in ("left", "right"):
        p = np.column_stack([m["p%s(%s)" % (c, body)] for c in "xyz"])
        exact = p[0] + rho * 0.25 * np.outer(t, g)
        worst = max(worst, np.max(np.abs(p - exact)) / np.linalg.norm(p[0]))
    parts = m["potentialEnergy(left)"] + m["potentialEnergy(right)"]
    off = np.max(np.abs(parts - m["potentialEnergy"])) \
        / np.max(np.abs(m["potentialEnergy"]))
    negative = min(np.min(m["numericalDissipation(%s)" % b]) for b in
                   ("left", "right")) / m["totalEnergy"][0]
    if worst > 1e-12 or off > 1e-12 or negative < -1e-12:
        failures.append("falling bodies: momentum off rho V g t by %.1e,"
                        " potential energies off the total by %.1e,"
                        " numerical dissipation %.1e E0 (limits 1e-12)"
                        % (worst, off, negative))
    return ("falling bodies (g = (0, -9.81, 3)): each body's momentum"
            " against p0 + rho V g t to %.1e, potential energies sum to"
            " the total to %.1e, numerical dissipation min %.1e E0"
            % (worst, off, negative))


def body():
    root = testing.work_dir(NAME)
    lines, failures = [], []
    lines.append(uniform_strain(root, "RK2", failures))
    lines.append(uniform_strain(root, "RK3", failures))
    lines.append(taylor_bar(root, failures))
    lines.append(bar_rebound(root, failures))
    lines.append(moving_wall(root, "plain", 1e-10, failures))
    lines.append(moving_wall(root, "compatible", 1e-2, failures))
    lines.append(two_bodies(root, failures))
    lines.append(falling_bodies(root, failures))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
