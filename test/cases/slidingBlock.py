#!/usr/bin/python3
"""Coulomb friction on the rigid wall, against closed forms.

    /usr/bin/python3 test/cases/slidingBlock.py

Copies of tutorials/slidingBlock (a block 0.1 x 0.05 m, neo-Hookean,
rho0 = 1000, E = 10 MPa, nu = 0.3, on the rigid wall y = 0 under
g = 9.81 m/s^2, launched along it at v0 = 1 m/s; friction muStatic 0.4,
muKinetic 0.3; plain update), on N = 4 (8 x 4 cells):

  slide       to 0.45 s with DebugSwitches { rigidWall 1; }, which writes
              per Runge-Kutta stage the largest |t_t| - mu p_N, the
              largest mu p_N, the largest face friction work rate and
              their sum (mu = muStatic, the law's largest coefficient);
  mu = 0      coulomb with muStatic = muKinetic = 0 against the wall
              without a friction entry, to 0.05 s at 17 digits;
  restart     stopped at 0.34 s (stopping: 3 of the 8 faces stick),
              restarted to 0.36 s, against the uninterrupted run; a
              control restarts with the written friction state (the
              'slip' entry) set to zero;
  oblique     no gravity, the block 1 mm above the wall flies at
              (0.5, -0.5) m/s onto it and rebounds, with friction and
              frictionless.
Serial = parallel with the wall cut between 2 and 3 ranks, restarted in
parallel through the stop: test/cases/contactParallel.py.

Asserted:
  - slide: mean deceleration v0/t_stop within 2 % of muKinetic g, the
    distance (integral of p_x/M over the steps) within 3 % of
    v0^2/(2 mu g) (a rigid block's), then at rest:
    speed < 1e-3 v0 from 0.02 s after the stop to the end;
  - at every stage and face |t_t| <= mu p_N (1e-12 of the largest mu p_N)
    and the face's friction work rate t_t . (v* - v_w) |S| <= 0, and the
    friction work over the run (RK2's stages weighed 1/2) <= 0; every
    step's friction force from the momentum, |dp_x/dt|, at most muStatic
    times the monitor's normal wall force (1e-9); the total energy
    (kinetic + strain + potential) never grows (1e-12 of the initial
    kinetic energy per step);
  - mu = 0: every written field (the wall's friction and slip entries
    left out) and the monitor equal the frictionless run's byte for byte;
  - restart: lm and F at 0.36 s equal the uninterrupted run's bit for
    bit (0 difference); the control, every face's written sliding velocity set to zero (the
    static coefficient instead of the kinetic one where a face slid),
    differs by more than 1e-9 (else the test would not see a lost
    friction state; measured 1.5e-8);
  - oblique: frictionless, p_x constant (1e-12 |p0|) and the spin about
    the centre of mass L - x_c ^ p stays at round-off; with friction the
    block loses tangential momentum (p_x falls by at least 10 % of
    p_x(0), at most by muKinetic times the normal impulse, the gain of
    p_y) and gains spin against its sliding (L_z about the centre < 0
    for a block sliding along +x on a wall below it), 100 times the
    frictionless one;
  - FUpdate compatible (the friction at the wall's held points, about
    their normal forces: compatible::stickWallPoints holds those that
    stick, compatible::addWallFriction pushes those that slide): the same
    deceleration, distance and rest, the per-step friction force and
    energy checks, the wall's work never rising in a step, mu = 0 equal to
    the frictionless wall byte for byte, a restart at T0 bit for bit, and
    the oblique impact's checks.
Work folders: test/runs/slidingBlock/.
"""

import filecmp
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, run, sliding, testing  # noqa: E402
from touchfoam.mesh import PolyMesh  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

NAME = "slidingBlock"
T0, T1 = 0.34, 0.36    # the restart: the block stops at 0.340 s
N = 4
G = 9.81
V0 = 1.0
MU_S, MU_K = 0.4, 0.3

FRICTION_LINE = re.compile(
    r"^rigidWall bottom friction: time (\S+) stage (\d+) "
    r"max\(\|t_t\| - mu p_N\) (\S+) max\(mu p_N\) (\S+) "
    r"max face work rate (\S+) work rate (\S+)")


def make_case(root, name, end, friction=(MU_S, MU_K), precise=False,
              debug=False, write=0.05, update="plain"):
    """A meshed copy of the tutorial; friction None: no friction entry;
    update: its FUpdate."""
    case = run.copy_case(run.tutorial_dir(NAME), os.path.join(root, name))
    run.foam_set(case, "system/fvSolution", "TOUCH/FUpdate", update)
    run.write_options(case, "system/meshOptions", {"N": N, "Nx": 2 * N})
    run.foam_set(case, "system/controlDict", "endTime", end)
    if precise:
        for key, value in cases.precise_output().items():
            run.foam_set(case, "system/controlDict", key, value)
        run.foam_set(case, "system/controlDict", "writeInterval", write)
    if debug:
        run.foam_set(case, "system/controlDict", "DebugSwitches",
                     "{ rigidWall 1; }")
    entry = "boundaryField/bottom/friction"
    if friction is None:
        run.run(["foamDictionary", "0.orig/U", "-entry", entry, "-remove"],
                case, "foamDictionary")
    else:
        run.foam_set(case, "0.orig/U", entry + "/muStatic", friction[0])
        run.foam_set(case, "0.orig/U", entry + "/muKinetic", friction[1])
    run.restore0(case)
    run.run(["blockMesh"], case)
    return case


def mass_of(case):
    return cases.material(case)["rho"] * float(PolyMesh(case).cell_volumes.sum())


def slide_against_closed_form(case, label, failures):
    """The deceleration, the distance and the rest after the stop against
    Coulomb's rigid block; the line, or None if it never stopped."""
    M = mass_of(case)
    s = sliding.slide(case, M, np.array([V0, 0, 0]), MU_K, G)
    if s["t_stop"] is None:
        failures.append("%s: never stopped" % label)
        return None
    dec = s["deceleration"] / s["deceleration_ref"] - 1
    dist = s["distance"] / s["distance_ref"] - 1
    rest = s["rest_speed"] / V0
    if abs(dec) > 0.02:
        failures.append("%s: deceleration %+.2f %% of mu g"
                        % (label, 100 * dec))
    if abs(dist) > 0.03:
        failures.append("%s: distance %+.2f %% of v0^2/(2 mu g)"
                        % (label, 100 * dist))
    if not rest < 1e-3:
        failures.append("%s: not at rest after the stop (%.1e v0)"
                        % (label, rest))
    return ("deceleration %+.2f %% of mu g, distance %+.3f %% of v0^2/(2 mu"
            " g), at rest %.1e v0 from 0.02 s after the stop (%.4f s)"
            % (100 * dec, 100 * dist, rest, s["t_stop"]))


def step_checks(case, label, failures):
    """Per step: the friction force from the momentum within muStatic
    times the monitor's normal wall force, the energy never growing; the
    line."""
    M = mass_of(case)
    mon = read_monitor(case)
    t = np.concatenate([[0.0], mon["Time"]])
    px = np.concatenate([[M * V0], mon["p"][:, 0]])
    Ft = np.abs(np.diff(px) / np.diff(t))
    Fn = mon["wallForce(bottom)"]
    over = float(np.max(Ft - MU_S * Fn)) / (M * G)
    sliding_steps = np.abs(px[1:]) > 0.01 * M * V0
    ratio = float(np.median(Ft[sliding_steps] / np.maximum(Fn[sliding_steps],
                                                            1e-300)))
    if over > 1e-9:
        failures.append("%s: |dp_x/dt| exceeds muStatic times the wall's"
                        " normal force by %.1e M g" % (label, over))
    E = mon["totalEnergy"]
    growth = float(np.max(np.diff(E))) / (0.5 * M * V0 ** 2)
    if growth > 1e-12:
        failures.append("%s: the energy grew by %.1e K0 in a step"
                        % (label, growth))
    return ("per step |dp_x/dt| - muS F_n <= %.1e M g, median |dp_x/dt|/F_n"
            " sliding %.4f (muK %.2f); energy change per step <= %.1e K0"
            % (over, ratio, MU_K, growth))


def slide_compatible(root, failures):
    """FUpdate compatible: the friction at the wall's held points
    (compatible::addWallFriction), against the same closed forms; the
    wall's work (the friction's, at the held points, and its damping's)
    never positive in a step; mu = 0 equal to the frictionless wall; a
    restart through the stop bit for bit (a point carries no state)."""
    label = "compatible"
    case = make_case(root, "slideCompatible", 0.45, update="compatible")
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    closed = slide_against_closed_form(case, label, failures)
    steps = step_checks(case, label, failures)
    mon = read_monitor(case)
    K0 = 0.5 * mass_of(case) * V0 ** 2
    work = mon["boundaryWork(bottom)"]
    rise = float(np.max(np.diff(np.concatenate([[0.0], work])))) / K0
    if rise > 1e-12:
        failures.append("compatible: the wall's work rose by %.1e K0 in a"
                        " step" % rise)
    if not work[-1] < -0.5 * K0:
        failures.append("compatible: the wall took %.3f K0, not the"
                        " block's kinetic energy" % (-work[-1] / K0))

    zero = make_case(root, "muZeroCompatible", 0.05, friction=(0, 0),
                     precise=True, update="compatible")
    none = make_case(root, "frictionlessCompatible", 0.05, friction=None,
                     precise=True, update="compatible")
    for c in (zero, none):
        run.run(["touchFoam"], c, timeout=testing.RUN_TIMEOUT)
    differ, n = same_outputs(zero, none)
    if differ or n < 1:
        failures.append("compatible: mu = 0 differs from the frictionless"
                        " wall: %s" % ", ".join(differ[:5]))

    whole = make_case(root, "wholeCompatible", T1, precise=True, write=0.01,
                      update="compatible")
    run.run(["touchFoam"], whole, timeout=testing.RUN_TIMEOUT)
    cut = make_case(root, "restartedCompatible", T0, precise=True,
                    write=0.01, update="compatible")
    run.run(["touchFoam"], cut, timeout=testing.RUN_TIMEOUT)
    run.foam_set(cut, "system/controlDict", "endTime", T1)
    run.run(["touchFoam"], cut, "touchFoam.restart",
            timeout=testing.RUN_TIMEOUT)
    nc = PolyMesh(whole).n_cells
    d_cut = max(float(np.abs(
        testing.read_internal(run.time_dir(cut, T1), f, nc)
        - testing.read_internal(run.time_dir(whole, T1), f, nc)).max())
        for f in ("lm", "F"))
    if d_cut != 0:
        failures.append("compatible: the restart at %g s differs by %.1e"
                        % (T0, d_cut))
    return ("compatible N %d: %s; %s; the wall's work -%.4f K0, never rising"
            " (largest step %+.1e K0); mu = 0: %d written times and the"
            " monitor %s the frictionless wall's; restart at %g s: lm, F at"
            " %g s %.1e off; %s"
            % (N, closed, steps, -work[-1] / K0, rise, n,
               "differ from" if differ else "equal to", T0, T1, d_cut,
               oblique(root, failures, "compatible")))


def slide_checks(root, failures):
    case = make_case(root, "slide", 0.45, debug=True)
    log = run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    closed = slide_against_closed_form(case, "slide", failures)
    if closed is None:
        return "slide: never stopped"

    # Every stage's friction checks from the wall's debug output
    rows = []
    with open(log) as f:
        for line in f:
            m = FRICTION_LINE.match(line)
            if m:
                rows.append([float(x) for x in m.groups()])
    rows = np.array(rows)
    if len(rows) < 1000:
        failures.append("slide: only %d stages reported friction"
                        % len(rows))
        return "slide: no friction output"
    excess, limit, face_power = rows[:, 2], rows[:, 3], rows[:, 4]
    area = (0.05 / N) ** 2
    cone = float(np.max(excess / limit))
    power_scale = float(np.max(limit)) * V0 * area
    worst_power = float(np.max(face_power)) / power_scale
    if cone > 1e-12:
        failures.append("slide: |t_t| exceeds mu p_N by %.1e of it" % cone)
    # The friction work over the run: RK2 weighs its two stages 1/2 each
    stage1 = rows[rows[:, 1] == 1]
    dt = np.diff(stage1[:, 0])
    work = float(np.sum(0.5 * rows[:, 5] * np.interp(rows[:, 0],
                                                      stage1[1:, 0], dt)))
    work /= 0.5 * mass_of(case) * V0 ** 2
    if not work <= 0:
        failures.append("slide: the friction work is positive (%.3e K0)"
                        % work)
    if worst_power > 1e-12:
        failures.append("slide: a face's friction work rate is positive"
                        " (%.1e of mu p_N v0 |S|)" % worst_power)

    # The friction force of every step from the momentum, against the
    # monitor's normal wall force
    steps = step_checks(case, "slide", failures)
    return ("slide N %d: %s; %d stages: max (|t_t| - mu p_N)/(mu p_N) %.1e,"
            " max face work rate %.1e mu p_N v0 |S|, friction work %.4f K0;"
            " %s" % (N, closed, len(rows), cone, worst_power, work, steps))


def strip_friction(text):
    """A written field without the wall's friction entries."""
    text = re.sub(r"\n\s*friction\s*\{[^}]*\}", "", text)
    text = re.sub(r"\n\s*slip\s+(uniform|nonuniform)[^;]*;", "", text,
                  flags=re.S)
    return text


def same_outputs(a, b):
    """Files of the written times (friction entries left out) and the
    monitor that differ between cases a and b."""
    differ = []
    times = sorted(run.time_dirs(a).items())
    for t, name in times:
        if t == 0:
            continue
        for f in sorted(os.listdir(os.path.join(a, name))):
            pa, pb = os.path.join(a, name, f), os.path.join(b, name, f)
            if not os.path.isfile(pa):
                continue
            if not os.path.exists(pb):
                differ.append("%s/%s missing" % (name, f))
                continue
            with open(pa) as fa, open(pb) as fb:
                if strip_friction(fa.read()) != strip_friction(fb.read()):
                    differ.append("%s/%s" % (name, f))
    mon = os.path.join("postProcessing", "solidMonitor", "0",
                       "solidMonitor.dat")
    if not filecmp.cmp(os.path.join(a, mon), os.path.join(b, mon),
                       shallow=False):
        differ.append("the monitor")
    return differ, len(times) - 1


def zero_mu(root, failures):
    zero = make_case(root, "muZero", 0.05, friction=(0, 0), precise=True)
    none = make_case(root, "frictionless", 0.05, friction=None,
                     precise=True)
    for case in (zero, none):
        run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    differ, n = same_outputs(zero, none)
    if differ or n < 1:
        failures.append("mu = 0 differs from the frictionless wall: %s"
                        % ", ".join(differ[:5]))
    return ("mu = 0: %d written times and the monitor %s the frictionless"
            " wall's" % (n, "differ from" if differ else "equal to"))


def restart(root, failures):
    """Stopped at T0 (the block is stopping: faces stick and slip),
    restarted to T1; the control restarts with every face's
    written sliding velocity set to zero, as if it stuck."""
    whole = make_case(root, "whole", T1, precise=True, write=0.01)
    run.run(["touchFoam"], whole, timeout=testing.RUN_TIMEOUT)
    cut = make_case(root, "restarted", T0, precise=True, write=0.01)
    run.run(["touchFoam"], cut, timeout=testing.RUN_TIMEOUT)
    control = os.path.join(root, "slipChanged")
    shutil.copytree(cut, control)
    changed = 0
    for field in ("lm", "U"):
        path = os.path.join(run.time_dir(control, T0), field)
        if os.path.exists(path):
            with open(path) as f:
                text = f.read()
            new = re.sub(r"(\n\s*slip\s+)(uniform|nonuniform)[^;]*;",
                         r"\1uniform (0 0 0);", text, flags=re.S)
            changed += new != text
            with open(path, "w") as f:
                f.write(new)
    for case in (cut, control):
        run.foam_set(case, "system/controlDict", "endTime", T1)
        run.run(["touchFoam"], case, "touchFoam.restart",
                timeout=testing.RUN_TIMEOUT)

    n = PolyMesh(whole).n_cells

    scale = {"lm": cases.material(whole)["rho"] * V0, "F": 1.0}

    def difference(case):
        """Largest difference of lm and F at T1 from the uninterrupted
        run's, relative to rho0 v0 and 1"""
        return max(np.abs(
            testing.read_internal(run.time_dir(case, T1), f, n)
            - testing.read_internal(run.time_dir(whole, T1), f, n)).max()
            / scale[f] for f in ("lm", "F"))

    d_cut, d_control = difference(cut), difference(control)
    # Bit for bit: the friction state ('slip') and the last step's dt are
    # read back (a restart was 3.5e-14 off before the step was taken from
    # uniform/time, commit 53e35a0)
    if d_cut != 0:
        failures.append("restart: lm, F at %g s differ from the"
                        " uninterrupted run by %.1e" % (T1, d_cut))
    if not changed or not d_control > 1e-9:
        failures.append("restart control: with the slip entry changed (in"
                        " %d files) the restart differs by only %.1e: the"
                        " friction state is not seen" % (changed, d_control))
    return ("restart at %g s: lm, F at %g s within %.1e of the"
            " uninterrupted run; with every face's slip set to zero"
            " %.1e" % (T0, T1, d_cut, d_control))


def oblique_run(root, name, friction, update="plain"):
    case = make_case(root, name, 0.006, friction=friction, update=update)
    os.remove(os.path.join(case, "constant", "g"))
    run.run(["transformPoints", "-translate", "(0 0.001 0)"], case)
    run.foam_set(case, "0/U", "internalField", "uniform (0.5 -0.5 0)")
    run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    M = mass_of(case)
    mon = read_monitor(case)
    t = np.concatenate([[0.0], mon["Time"]])
    p = np.vstack([[0.5 * M, -0.5 * M, 0.0], mon["p"]])
    # The centre of mass moves with p/M: trapezoids over the steps
    xc0 = np.array([0.05, 0.025 + 0.001, 0.5 * 0.05 / N])
    dx = np.cumsum(0.5 * (p[1:] + p[:-1]) * np.diff(t)[:, None], axis=0) / M
    xc = np.vstack([xc0, xc0 + dx])[1:]
    spin = mon["L"][:, 2] - (xc[:, 0] * p[1:, 1] - xc[:, 1] * p[1:, 0])
    return p, spin, M


def oblique(root, failures, update="plain"):
    tag = "" if update == "plain" else update[0].upper() + update[1:]
    p_f, spin_f, M = oblique_run(root, "obliqueFriction" + tag,
                                 (MU_S, MU_K), update)
    p_0, spin_0, _ = oblique_run(root, "obliqueFrictionless" + tag, None,
                                 update)
    p0 = np.linalg.norm(p_0[0])
    drift_0 = float(np.max(np.abs(p_0[:, 0] - p_0[0, 0]))) / p0
    lost = (p_f[0, 0] - p_f[-1, 0]) / p_f[0, 0]
    normal_impulse = p_f[-1, 1] - p_f[0, 1]
    bound = MU_K * normal_impulse / p_f[0, 0]
    spin_scale = 0.5 * M * 0.05
    rebound = p_f[-1, 1] > 0 and p_0[-1, 1] > 0
    label = "oblique" + ("" if update == "plain" else " (%s)" % update)
    if drift_0 > 1e-12:
        failures.append("%s frictionless: p_x changed by %.1e |p0|"
                        % (label, drift_0))
    if not (lost >= 0.1 and lost <= bound * (1 + 1e-6)):
        failures.append("%s: p_x fell by %.3f of p_x(0) (expected"
                        " between 0.1 and mu J_n/p_x(0) = %.3f)"
                        % (label, lost, bound))
    if not (spin_f[-1] < 0
            and abs(spin_f[-1]) > 100 * np.max(np.abs(spin_0))):
        failures.append("%s: spin with friction %.2e, frictionless"
                        " max %.2e (kg m^2/s)" % (label, spin_f[-1],
                                                  np.max(np.abs(spin_0))))
    if not rebound:
        failures.append("%s: the block did not rebound" % label)
    return ("%s impact: frictionless p_x drift %.1e |p0|, spin max"
            " %.1e of M v |H|; with friction p_x falls by %.3f of p_x(0)"
            " (<= mu J_n/p_x(0) = %.3f), spin %.3e of M v |H|"
            % (label, drift_0, np.max(np.abs(spin_0)) / spin_scale, lost,
               bound, spin_f[-1] / spin_scale))


def body():
    root = testing.work_dir(NAME)
    lines, failures = [], []
    for check in (slide_checks, zero_mu, restart, oblique,
                  slide_compatible):
        lines.append(check(root, failures))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
