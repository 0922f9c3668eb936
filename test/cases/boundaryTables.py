#!/usr/bin/python3
"""Boundary values that vary in time (OpenFOAM's Function1) on a 1D bar.

    /usr/bin/python3 test/cases/boundaryTables.py [-n 200]

Copies of tutorials/elasticImpact (the tutorial is not changed): a bar of
length L = 1 on N x 1 x 1 cubic cells with symmetricPlane sides (uniaxial
strain), linear elastic, c_p = sqrt((lambda + 2 mu)/rho0) = 1000 m/s, at
rest; its end X = 0 (patch 'wall') is driven through a table, the other
end is free.  1D linear theory: whatever drives the end, sigma_xx(X, t) =
-Z v(t - X/c_p) with Z = rho0 c_p, v the end's velocity (zero for a
negative argument), until the front comes back from the free end at
t = 2 L/c_p.  Each run ends at 0.9 L/c_p.

  velocity  prescribedVelocity, velocity table ((0 0) (t_r V) ...): a ramp
            over t_r = 0.1 ms to V = 0.1 m/s, then held (RK2 asserted,
            RK3 too)
  wall      rigidWall at X = -g moving in with a table velocity: ramp to V
            over t_r, held to t_s = 0.5 ms, ramp down to 0 at t_s + t_r
            (the wall stops); g = 1.5e-5 m, so that the wall's position
            point + integral of the table reaches the bar at
            t_c = t_r + (g - V t_r/2)/V = 0.2 ms, during the hold
  pressure  traction with pressure table ((0 0) (t_r P)): P = Z V

Asserted:
  plateau    sigma_xx on the cells where the closed form is on its plateau
             (8 cells clear of a ramp's end, 20 of a jump, the impact's,
             whose ringing decays over them; 4 cells clear of the driven
             end), at every written time, against -Z V (velocity, wall)
             and -P (pressure): the largest deviation within 1 %.  The end
             cell's deviation is reported: under a prescribed traction
             the compatible F update leaves a stationary defect in the
             first cells (-0.75 P in the first at N = 200, the same for a
             pressure constant in time; none with the plain update)
  profile    the largest deviation of sigma_xx from the closed form over
             the bar but its 4 end cells (ramps included), within 5 % of the plateau
             (velocity, pressure; reported for the wall, whose impact is
             a jump)
  forms      the same velocity as 'velocity (V 0 0)', 'uniform (V 0 0)'
             and 'constant (V 0 0)' gives bit-identical results; the table
             read from a file (tableFile, velocityCoeffs) equals the inline
             table bit for bit
  contact    the wall's first step in contact ends within one step after
             t_c (the wall's position is the integral of its velocity)
  force      the wall's force (solidMonitor) on the hold, from t_c + 20 h/c_p
             to t_s, against Z V A (A = h^2 the bar's section): within 1 %;
             its impulse equals the change of p_x to 1e-10; after the wall
             stopped (t_s + t_r + 8 h/c_p) the force is below 1 % of Z V A
  stopped    the end's displacement (mean over the points of X = 0) at the
             end, against the wall's travel -g + V t_s: within 1 %
  restart    the wall run stopped during contact and restarted from its
             written fields (the table written back by the condition)
             equals the uninterrupted run bit for bit
Work folders: test/runs/boundaryTables/.
"""

import argparse
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import (cases, foamfile, impact, monitor, run,  # noqa: E402
                       testing)
from touchfoam.mesh import PolyMesh  # noqa: E402

NAME = "boundaryTables"
V = 0.1                 # end velocity on the plateau [m/s]
T_RAMP = 1e-4           # ramp time [s]
T_STOP = 5e-4           # the wall starts to stop [s]
GAP = 1.5e-5            # initial gap of the wall [m]
KINK_CELLS = 8          # cells kept clear of a kink of the closed form
JUMP_CELLS = 20         # ... and of a jump (the impact's ringing)
END_CELLS = 4           # cells kept clear of the driven end
COLUMN_N = "contactFaces(wall)"
COLUMN_F = "wallForce(wall)"
LIMITS = {"plateau": 0.01, "profile": 0.05, "force": 0.01, "after": 0.01,
          "impulse": 1e-10, "stopped": 0.01}


def vector_table(rows):
    return "table (%s)" % " ".join("(%r (%r 0 0))" % (t, v) for t, v in rows)


def scalar_table(rows):
    return "table (%s)" % " ".join("(%r %r)" % (t, v) for t, v in rows)


RAMP = [(0.0, 0.0), (T_RAMP, V)]
WALL = [(0.0, 0.0), (T_RAMP, V), (T_STOP, V), (T_STOP + T_RAMP, 0.0)]


def bar(root, label, n, wall, control=None):
    """A meshed copy of elasticImpact at rest with the given entry of the
    patch X = 0, to t = 0.9 L/c_p, written every 0.1 ms."""
    ctrl = {"endTime": 9e-4, "writeInterval": 1e-4}
    ctrl.update(cases.precise_output())
    ctrl.update(control or {})
    case = cases.prepare("elasticImpact", os.path.join(root, label), n=n,
                         control=ctrl)
    run.foam_set(case, "0/U", "internalField", "uniform (0 0 0)")
    run.foam_set(case, "0/U", "boundaryField/wall", wall)
    return case


def solve(case, name=None):
    run.run(["touchFoam"], case, name, timeout=testing.RUN_TIMEOUT)
    return case


def material(case):
    mat = cases.material(case)
    cp = impact.ElasticImpact(mat["E"], mat["nu"], mat["rho"]).cp
    return mat["rho"] * cp, cp


def history(rows, t):
    """The piecewise linear table at times t (zero before its start, held
    after its end)."""
    t = np.asarray(t, float)
    times, values = zip(*rows)
    return np.where(t < 0, 0.0, np.interp(t, times, values))


def profile_errors(case, n, sigma_end, plateau_value, plateau_from,
                   plateau_to=np.inf, clear=KINK_CELLS):
    """sigma_xx against the closed form sigma_end(t - X/c_p) at every
    written time: the largest deviation on the plateau (the cells more than
    END_CELLS from the driven end whose argument lies clear h/c_p inside
    (plateau_from, plateau_to)) relative to plateau_value, over the whole
    bar relative to |plateau_value|, and the end cell's on the plateau."""
    Z, cp = material(case)
    mesh = PolyMesh(case)
    x = mesh.cell_centres[:, 0]
    h = 1.0 / n
    worst_plateau, worst_profile, worst_end, cells = 0.0, 0.0, 0.0, 0
    first = np.argmin(x)
    for name in run.time_dirs(case).values():
        t = float(name)
        if t <= 0:
            continue
        sxx = foamfile.read_field(os.path.join(case, name, "sigma")) \
            .internal(mesh.n_cells)[:, 0]
        exact = sigma_end(t - x / cp)
        away = x > END_CELLS * h
        worst_profile = max(worst_profile, float(
            np.abs(sxx - exact)[away].max()) / abs(plateau_value))
        tau = t - x / cp
        on = (tau > plateau_from + clear * h / cp) & \
            (tau < plateau_to - clear * h / cp)
        if on[first]:
            worst_end = max(worst_end, abs(sxx[first] / plateau_value - 1))
        on &= x > END_CELLS * h
        if on.any():
            cells += int(on.sum())
            worst_plateau = max(worst_plateau, float(
                np.abs(sxx[on] / plateau_value - 1).max()))
    if cells == 0:
        raise AssertionError("%s: no cell on the plateau" % case)
    return worst_plateau, worst_profile, worst_end, cells


def fields_equal(a, b, n):
    """Whether every written field of two runs is equal bit for bit."""
    for t, name in run.time_dirs(a).items():
        if t <= 0:
            continue
        for field in ("lm", "F", "sigma"):
            fa = foamfile.read_field(os.path.join(a, name, field))
            fb = foamfile.read_field(os.path.join(b, name, field))
            if np.asarray(fa.internal(n), float).tobytes() != \
                    np.asarray(fb.internal(n), float).tobytes():
                return False
    return len(run.time_dirs(a)) == len(run.time_dirs(b))


def velocity_runs(root, n, failures):
    """The prescribed end velocity: the ramp, and the equal forms."""
    case = solve(bar(root, "velocity", n, "{ type prescribedVelocity; "
                     "velocity %s; }" % vector_table(RAMP)))
    Z, cp = material(case)
    plateau, prof, end, cells = profile_errors(
        case, n, lambda t: -Z * history(RAMP, t), -Z * V, T_RAMP)
    if plateau > LIMITS["plateau"]:
        failures.append("velocity table: plateau off -Z V by %.3f %%"
                        % (100 * plateau))
    if prof > LIMITS["profile"]:
        failures.append("velocity table: profile off by %.2f %%"
                        % (100 * prof))
    lines = ["velocity table: plateau %.3f %% (%d cell values), end cell "
             "%.3f %%, profile %.2f %% of Z V" % (100 * plateau, cells,
                                                 100 * end, 100 * prof)]

    # RK3, whose third stage works on a state at t^n + dt/2
    rk3 = os.path.join(root, "velocity_RK3")
    shutil.copytree(case, rk3, ignore=shutil.ignore_patterns(
        "0.0*", "postProcessing", "log.touchFoam"))
    run.foam_set(rk3, "system/fvSolution", "TOUCH/timeScheme", "RK3")
    plateau3, prof3, _, _ = profile_errors(
        solve(rk3), n, lambda t: -Z * history(RAMP, t), -Z * V, T_RAMP)
    if plateau3 > LIMITS["plateau"] or prof3 > LIMITS["profile"]:
        failures.append("velocity table RK3: plateau %.3f %%, profile "
                        "%.2f %%" % (100 * plateau3, 100 * prof3))
    lines.append("RK3: plateau %.3f %%, profile %.2f %%"
                 % (100 * plateau3, 100 * prof3))

    # The same table from a file
    path = os.path.join(root, "velocityTable")
    with open(path, "w") as f:
        f.write("(\n%s\n)\n" % "\n".join("    (%r (%r 0 0))" % r
                                          for r in RAMP))
    other = solve(bar(root, "velocity_tableFile", n, "{ type "
                      "prescribedVelocity; velocity tableFile; "
                      "velocityCoeffs { file \"%s\"; } }" % path))
    same = fields_equal(case, other, n)
    if not same:
        failures.append("velocity tableFile differs from the inline table")
    lines.append("tableFile %s" % ("equal" if same else "DIFFERS"))

    # A velocity constant in time, in the three forms
    forms = {}
    for label, entry in (("plain", "(%r 0 0)" % V),
                         ("uniform", "uniform (%r 0 0)" % V),
                         ("constant", "constant (%r 0 0)" % V)):
        forms[label] = solve(bar(root, "velocity_" + label, n,
                                 "{ type prescribedVelocity; velocity %s; }"
                                 % entry))
    equal = all(fields_equal(forms["plain"], forms[k], n)
                for k in ("uniform", "constant"))
    if not equal:
        failures.append("velocity (V 0 0), uniform and constant differ")
    step, _, _, _ = profile_errors(
        forms["plain"], n, lambda t: np.where(t < 0, 0.0, -Z * V), -Z * V,
        0.0, clear=JUMP_CELLS)
    if step > LIMITS["plateau"]:
        failures.append("constant velocity: plateau off -Z V by %.3f %%"
                        % (100 * step))
    lines.append("constant velocity in 3 forms %s, plateau %.3f %%"
                 % ("equal" if equal else "DIFFER", 100 * step))
    return lines


def pressure_run(root, n, failures):
    probe = bar(root, "pressure", n, "{ type traction; }")
    Z, cp = material(probe)
    P = Z * V
    rows = [(0.0, 0.0), (T_RAMP, P)]
    run.foam_set(probe, "0/U", "boundaryField/wall", "{ type traction; "
                 "pressure %s; }" % scalar_table(rows))
    case = solve(probe)
    plateau, prof, end, cells = profile_errors(
        case, n, lambda t: -history(rows, t), -P, T_RAMP)
    # The same with the plain F update, whose end cell has no defect
    other = os.path.join(root, "pressure_plain")
    shutil.copytree(probe, other, ignore=shutil.ignore_patterns(
        "0.0*", "postProcessing", "log.touchFoam"))
    run.foam_set(other, "system/fvSolution", "TOUCH/FUpdate", "plain")
    _, _, end_plain, _ = profile_errors(
        solve(other), n, lambda t: -history(rows, t), -P, T_RAMP)
    if plateau > LIMITS["plateau"]:
        failures.append("pressure table: plateau off -P by %.3f %%"
                        % (100 * plateau))
    if prof > LIMITS["profile"]:
        failures.append("pressure table: profile off by %.2f %%"
                        % (100 * prof))
    return ["pressure table (P = %.4g Pa): plateau %.3f %% (%d cell "
            "values), profile %.2f %% of P, end cell %.2f %% (plain F "
            "update: %.3f %%)" % (P, 100 * plateau, cells, 100 * prof,
                                  100 * end, 100 * end_plain)]


def wall_entry():
    return ("{ type rigidWall; point (%r 0 0); normal (1 0 0); "
            "velocity %s; }" % (-GAP, vector_table(WALL)))


def wall_run(root, n, failures):
    case = solve(bar(root, "wall", n, wall_entry()))
    Z, cp = material(case)
    h = 1.0 / n
    A = h * h
    lines = []

    # Contact when the integral of the table reaches the gap
    t_c = T_RAMP + (GAP - 0.5 * V * T_RAMP) / V
    m = monitor.read_monitor(case)
    t, c, F, px = m["Time"], m[COLUMN_N], m[COLUMN_F], m["px"]
    dt = float(np.diff(t).max())
    on = np.nonzero(c > 0)[0]
    if len(on) == 0:
        raise AssertionError("wall: no face ever in contact")
    t_first = float(t[on[0]])
    if not 0 <= t_first - t_c <= dt * (1 + 1e-6):
        failures.append("wall: first contact at %.6g s, not within one step "
                        "(%.3g) after t_c = %.6g" % (t_first, dt, t_c))
    lines.append("wall: contact at %.4f ms (closed form %.4f, step %.4f)"
                 % (1e3 * t_first, 1e3 * t_c, 1e3 * dt))

    # The stress and the force on the hold (the profile jumps at the
    # impact: reported only)
    plateau, prof, end, cells = profile_errors(
        case, n, lambda s: np.where(s < t_c, 0.0, -Z * history(WALL, s)),
        -Z * V, t_c, T_STOP, clear=JUMP_CELLS)
    hold = (t > t_c + JUMP_CELLS * h / cp) & (t <= T_STOP)
    force = float(np.abs(F[hold] / (Z * V * A) - 1).max())
    after = t > T_STOP + T_RAMP + KINK_CELLS * h / cp
    rest = float(np.abs(F[after]).max()) / (Z * V * A)
    impulse = float(np.sum(F * np.diff(np.concatenate(([0.0], t)))))
    balance = impulse / (float(px[-1]) - float(px[0])) - 1
    for key, value, what in (("plateau", plateau, "stress plateau"),
                             ("force", force, "force on the hold"),
                             ("after", rest, "force after the stop"),
                             ("impulse", abs(balance),
                              "impulse / change of p_x - 1")):
        if value > LIMITS[key]:
            failures.append("wall: %s %.3e (limit %g)"
                            % (what, value, LIMITS[key]))
    lines.append("wall stress plateau %.3f %% (%d cell values), end cell "
                 "%.3f %%, profile %.2f %%, force on the hold %.3f %% of Z V A, after the "
                 "stop %.2e, impulse / change of p_x - 1 %+.1e"
                 % (100 * plateau, cells, 100 * end, 100 * prof,
                    100 * force, rest,
                    balance))

    # Where the end stopped: the wall's travel
    mesh = PolyMesh(case)
    end = run.latest_time_dir(case)
    name = "pointD" if os.path.exists(os.path.join(end, "pointD")) \
        else "pointU"
    pu = foamfile.read_field(os.path.join(end, name)) \
        .internal(len(mesh.points))
    at_end = np.abs(mesh.points[:, 0]) < 1e-12
    travel = -GAP + V * T_STOP
    moved = float(pu[at_end, 0].mean())
    stopped = moved / travel - 1
    if abs(stopped) > LIMITS["stopped"]:
        failures.append("wall: the end moved %.6g m, the wall %.6g m "
                        "(%+.2f %%)" % (moved, travel, 100 * stopped))
    lines.append("end moved %.6g m, the wall %.6g m (%+.3f %%)"
                 % (moved, travel, 100 * stopped))
    return lines


def restart(root, n, failures):
    """Stop the wall run during contact, restart it, compare."""
    ctrl = {"writeControl": "timeStep", "writeInterval": 100000}
    base = bar(root, "restart_base", n, wall_entry(), control=ctrl)
    # To 0.6 ms (the wall has stopped), stopped at 0.3 ms (in contact)
    _, cp = material(base)
    steps = int(round(6e-4 / (0.3 / (n * cp))))
    half = steps // 2
    full = os.path.join(root, "restart_straight")
    shutil.copytree(base, full)
    run.foam_set(full, "system/controlDict", "maxSteps", steps)
    solve(full)
    case = os.path.join(root, "restart_continued")
    shutil.copytree(base, case)
    run.foam_set(case, "system/controlDict", "maxSteps", half)
    solve(case, "touchFoam.1")
    mid = run.latest_time_dir(case)
    wall = foamfile.FoamField(os.path.join(mid, "lm")) \
        .boundary_patches()["wall"]
    written = bool(re.search(r"\bvelocity\s+table\b", wall))
    if not written:
        failures.append("restart: the wall's table is not written back "
                        "(%s)" % os.path.basename(mid))
    run.foam_set(case, "system/controlDict", "maxSteps", steps - half)
    solve(case, "touchFoam.2")
    a, b = run.latest_time_dir(full), run.latest_time_dir(case)
    same = os.path.basename(a) == os.path.basename(b)
    for field in ("lm", "F", "D"):
        if not same:
            break
        fa = foamfile.read_field(os.path.join(a, field)).internal(n)
        fb = foamfile.read_field(os.path.join(b, field)).internal(n)
        same = np.asarray(fa, float).tobytes() == \
            np.asarray(fb, float).tobytes()
    if not same:
        failures.append("restart: the continued run differs from the "
                        "uninterrupted one at %s" % os.path.basename(a))
    return ["restart at step %d of %d: table written back %s, result %s"
            % (half, steps, "yes" if written else "NO",
               "equal" if same else "DIFFERS")]


def body(args):
    root = testing.work_dir(NAME)
    failures = []
    lines = velocity_runs(root, args.n, failures)
    lines += pressure_run(root, args.n, failures)
    wall_lines = wall_run(root, args.n, failures)
    lines += wall_lines
    lines += restart(root, args.n, failures)
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-n", type=int, default=200,
                        help="cells along the bar (default 200)")
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args)))
