#!/usr/bin/python3
"""Contact between deformable bodies: two bars meeting end to end against
the closed forms of 1D elastic waves.

    /usr/bin/python3 test/cases/barCollision.py

Copies of tutorials/barCollision (bars along x in uniaxial strain,
rho0 = 1400, c = 1000 m/s, Z = 1.4e6 Pa s/m; bodyContact on the two ends
that meet, limitedLinear, RK2 at CFL 0.3), 50 cells per metre, each
with FUpdate compatible (the default) and plain:

  equal       two 1 m bars at +-0.1 m/s: contact stress Z v on the
              plateau (0.2 to 0.8 of 2L/c) within 1 %, release at 2L/c
              within one step plus 1 %; each bar's fields (lm,
              gradD = F - I, sigma) those of the same bar on a rigid
              wall (variant wall) to 1e-12 of their magnitudes, bar2 the
              mirror image of bar1 to 1e-12 (plain: 1e-2, see
              PLAIN_WALL_TOLERANCE); the bars' momenta reversed
              (reported: they equal the wall's rebound, 0.960 of the
              initial on this mesh);
  tutorial    equal (compatible) on the tutorial's 100 cells a metre:
              all of the above;
  rebound     equal (compatible) on 800 cells a metre: all of the above
              (the bar on the wall to 1e-12: 4e-8 while F was the state,
              whose unit in the last place is 2.2e-12 of a strain of
              1e-4), and the momenta reversed within 1 % of the initial
              ones (issue 28, acceptance 2, on one mesh; the rebound
              converges as about h^0.6, the loss at the fronts of issue
              35);
  unequal     bar1 (1 m, 0.1 m/s) hits bar2 (2 m) at rest: contact stress
              Z v/2 within 1 %; at the end bar1's momentum below 1 % of
              its initial one, bar2's within 1 % of it;
  bimaterial  as unequal, bar2 with 4 E (impedance ratio 2): contact
              stress Z1 Z2 v/(Z1 + Z2) within 1 %;
  every one   total momentum constant to 1e-12 of the bodies' |p0|, the
              energy never grows (1e-12 E0 per step), no contact pulls
              (most tensile traction of a face in contact < 0) and
              the penetration below 5 % of a face's size; the
              compatible runs do not warn that the two sides' forces
              part (their faces match, or are flat: test stiffPartner
              has the warning);
  restart     equal (compatible) stopped at 1 ms in contact and
              continued: lm, F, sigma at 2 and 3 ms those of the
              uninterrupted run bit for bit (the active set is written
              as lm's 'contact' entry and read back);
  nonmatching equal, compatible and plain, bar1 2 x 2 and bar2 3 x 3
              faces across (forces by the pairs' overlap areas): contact
              stress within 1 % and the checks of every variant above
              (plain: but the energy, which grows with matching faces
              of several cells across too); and compatible with 3 x 3
              against 5 x 5 (pairs of which neither centre lies over the
              other face do not act there: 0.41 % measured);
Serial = parallel on 2 and 3 ranks with the contact patches cut between
them: test/cases/contactParallel.py.
Work folders: test/runs/barCollision/.
"""

import os
import re
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import run, testing  # noqa: E402
from touchfoam.contact import analyse, compare_with_wall  # noqa: E402
from touchfoam.foamfile import read_field  # noqa: E402

NAME = "barCollision"
N = 50
#: The mesh on which the equal bars' velocities come out reversed within
#: 1 % (0.9602 on 50, 0.9743 on 100, 0.9898 on 400, 0.99365 on 800:
#: validation/barCollision/FINDINGS.md 2)
N_REBOUND = 800
#: Each bar's fields against the bar on the rigid wall (and bar2 against
#: bar1's mirror image), on their largest magnitudes over the run: issue
#: 28 asks 1e-10; measured 2.3e-15 to 2.7e-13 on 50 to 800 cells a metre
#: with gradD = F - I the state (2026-12-08; with F the state 1.5e-11 to 4e-8)
WALL_TOLERANCE = 1e-12
#: The same for FUpdate plain: its scheme has a grid-scale (odd-even) mode
#: behind a front that grows by e^1.7 per cell crossing from round-off
#: (with gradD the state; F's quantisation hid it) until it saturates
#: near the front's own ringing, so that the pair's and the wall's
#: different round-off parts them: measured 7.0e-5 against the wall's
#: bar, 2.6e-3 against the mirror, and 1.2e-3 between the run and the
#: same with its initial velocity 1e-14 larger (2026-12-08; validation/
#: barCollision/FINDINGS.md 8)
PLAIN_WALL_TOLERANCE = 1e-2

#: The restart's report: each field's difference on its size at an O(1)
#: deformation (rho0 c, 1, lambda + 2 mu); asserted to be zero
FLOOR = {"lm": 1400.0 * 1000.0, "F": 1.0, "sigma": 1.4e9}


def tutorial_case(root, name, args, update="compatible"):
    case = os.path.join(root, name)
    shutil.copytree(run.tutorial_dir("barCollision"), case)
    with open(os.path.join(case, "system", "solverOptions"), "w") as f:
        f.write("FUpdate %s;\n" % update)
    run.run(["./Allrun"] + args, case, name="Allrun",
            env=testing.without_pictures(), timeout=testing.RUN_TIMEOUT)
    return case


def common(name, r, failures, energy=True):
    """The checks of every two-body variant (energy: whether its growth is
    asserted); their line."""
    h = 1.0 / N
    if r["momentumDrift"] > 1e-12:
        failures.append("%s: momentum drift %.2e |p0|"
                        % (name, r["momentumDrift"]))
    if energy and r["energyGrowth"] > 1e-12:
        failures.append("%s: energy grew %.2e E0 in a step"
                        % (name, r["energyGrowth"]))
    if r["mostTensile"] >= 0:
        failures.append("%s: a face in contact pulled (%.3g Pa)"
                        % (name, r["mostTensile"]))
    if r["maxPenetration"] > 0.05 * h:
        failures.append("%s: penetration %.3g m" % (name,
                                                    r["maxPenetration"]))
    return ("momentum drift %.1e |p0|, energy growth %.1e E0, most tensile"
            " %.3g Pa, penetration %.1e m"
            % (r["momentumDrift"], r["energyGrowth"], r["mostTensile"],
               r["maxPenetration"]))


def plateau(name, r, failures):
    if r["plateauError"] > 0.01:
        failures.append("%s: contact stress off by %.3g %% of %.6g"
                        % (name, 100 * r["plateauError"],
                           r["contactStress"]))
    return ("contact stress %.6g Pa (closed form %.6g, max deviation"
            " %.2g %%)" % (r["plateauMean"], r["contactStress"],
                           100 * r["plateauError"]))


def equal(root, failures, update, n=N, reversed_within=None,
          as_wall=WALL_TOLERANCE):
    """reversed_within: the bars' end momenta asserted within this
    fraction of the initial ones, reversed (None: only that they move
    back, the rebound is reported); as_wall: the tolerance of the bars'
    fields against the bar on the wall and its mirror (None: reported)."""
    suffix = "" if n == N else "-n%d" % n
    collision = tutorial_case(root, "equal-" + update + suffix,
                              ["-n", str(n)], update)
    wall = tutorial_case(root, "wall-" + update + suffix,
                         ["-n", str(n), "-variant", "wall"], update)
    r = analyse(collision)
    lines = ["equal (%s, %d cells a metre): " % (update, n)
             + plateau("equal", r, failures)]

    exact = r["contactTimeExact"]
    if abs(r["contactTime"] - exact) > r["step"] + 0.01 * exact:
        failures.append("equal: released at %.6g s, 2L/c = %.6g s"
                        % (r["contactTime"], exact))
    lines.append("release %.6g s (2L/c %.6g, step %.2g)"
                 % (r["contactTime"], exact, r["step"]))

    # Reversed: bar1 moves back, bar2 its mirror
    bound = -0.9 if reversed_within is None else -(1 - reversed_within)
    if not (r["bar1End"] < bound and abs(r["bar1End"] + r["bar2End"])
            < 1e-12):
        failures.append("equal (%d): momenta at the end %.5f, %.5f of the"
                        " initial" % (n, r["bar1End"], r["bar2End"]))
    wall_r = analyse(wall)
    lines.append("momenta at the end %.5f, %.5f of the initial (wall"
                 " rebound: energy %.6f E0 both)"
                 % (r["bar1End"], r["bar2End"], wall_r["energyEnd"]))

    first, mirror, n_times = compare_with_wall(collision, wall)
    worst = max(first.values())
    worst_mirror = max(mirror.values())
    if n_times < 5 or (as_wall is not None
                       and max(worst, worst_mirror) > as_wall):
        failures.append("equal (%d): bar1 off the wall's bar by %.2e, bar2"
                        " off the mirror by %.2e (%d times)"
                        % (n, worst, worst_mirror, n_times))
    lines.append("bar1 = the bar on the rigid wall to %.1e, bar2 = its"
                 " mirror to %.1e (%d times%s)"
                 % (worst, worst_mirror, n_times,
                    "" if as_wall is not None else ", not asserted"))
    lines.append(common("equal", r, failures))
    return ", ".join(lines)


def unequal(root, failures, update):
    r = analyse(tutorial_case(root, "unequal-" + update,
                              ["-n", str(N), "-variant", "unequal"], update))
    line = "unequal (%s): " % update + plateau("unequal", r, failures)
    if abs(r["bar1End"]) > 0.01 or abs(r["bar2End"] - 1) > 0.01:
        failures.append("unequal: momenta at the end %.5f, %.5f of bar1's"
                        " initial" % (r["bar1End"], r["bar2End"]))
    return (line + ", momenta at the end %.1e (short), %.6f (long) of the"
            " initial, " % (r["bar1End"], r["bar2End"])
            + common("unequal", r, failures))


def bimaterial(root, failures, update):
    r = analyse(tutorial_case(root, "bimaterial-" + update,
                              ["-n", str(N), "-variant", "bimaterial"],
                              update))
    if r["Z2"] / r["Z1"] < 2 - 1e-12:
        failures.append("bimaterial: impedance ratio %.3g"
                        % (r["Z2"] / r["Z1"]))
    return ("bimaterial (%s, Z2/Z1 %.2g): " % (update, r["Z2"] / r["Z1"])
            + plateau("bimaterial", r, failures) + ", "
            + common("bimaterial", r, failures))


def restart(root, failures):
    """equal (compatible) stopped at 1 ms, in contact, and continued to the
    end, against the uninterrupted run of equal()."""
    whole = os.path.join(root, "equal-compatible")
    case = os.path.join(root, "restart")
    shutil.copytree(run.tutorial_dir("barCollision"), case)
    run.foam_set(case, "system/controlDict", "endTime", "1e-3")
    run.run(["./Allrun", "-n", str(N)], case, name="Allrun",
            env=testing.without_pictures(), timeout=testing.RUN_TIMEOUT)
    run.foam_set(case, "system/controlDict", "endTime", "3e-3")
    run.run(["touchFoam"], case, name="touchFoam.restart",
            timeout=testing.RUN_TIMEOUT)
    n_cells = 2 * N
    worst = 0.0
    for name in ("0.002", "0.003"):
        for field in ("lm", "F", "sigma"):
            a = read_field(os.path.join(case, name, field)).internal(n_cells)
            b = read_field(os.path.join(whole, name, field)).internal(
                n_cells)
            worst = max(worst, np.max(np.abs(a - b))
                        / max(np.max(np.abs(b)), FLOOR[field]))
    with open(os.path.join(case, "0.001", "lm")) as f:
        text = f.read()
    start = text.find("bar1End")
    in_contact = re.search(r"contact\s+uniform 1;",
                           text[start:text.find("}", start)]) is not None
    if not in_contact or worst != 0:
        failures.append("restart: %.2e off the uninterrupted run (active"
                        " set written at 1 ms: %s)" % (worst, in_contact))
    return ("restart at 1 ms (in contact: %s): %.1e off the uninterrupted"
            " run at 2 and 3 ms" % (in_contact, worst))


def nonmatching(root, failures, update, sections=(2, 3)):
    """bar1 2 x 2 faces across, bar2 3 x 3 (or the sections given): the
    pairs' overlap areas load every face, so the contact stress, the
    exchange of momentum, the energy and the penetration are held as on
    matching faces.  3 x 3 against 5 x 5 (compatible) has pairs of which
    neither face's centre lies over the other, which the compatible
    update leaves to the held points (contactSurfaces::opposed)."""
    name = "nonmatching-" + update + (
        "" if sections == (2, 3) else "-%d%d" % sections)
    case = tutorial_case(root, name,
                         ["-n", "30", "-section", str(sections[0]),
                          "-section2", str(sections[1])],
                         update)
    r = analyse(case)
    if r["plateauError"] > 0.01:
        failures.append("%s: contact stress off by %.3g %%"
                        % (name, 100 * r["plateauError"]))
    # plain on sections of several cells gains energy in some steps with
    # matching faces as well (2 x 2 against 2 x 2 at this step: the same
    # 2.6e-4 E0 at 60 us; validation/barCollision/FINDINGS.md 5): not
    # asserted there
    return ("nonmatching %d x %d / %d x %d faces (%s): contact stress within"
            " %.2g %%, %s%s" % (sections[0], sections[0], sections[1],
                                sections[1], update, 100 * r["plateauError"],
                                common(name, r, failures,
                                       update == "compatible"),
                                "" if update == "compatible"
                                else " (not asserted)"))


def body():
    root = testing.work_dir(NAME)
    lines, failures = [], []
    lines.append(equal(root, failures, "compatible"))
    lines.append(equal(root, failures, "plain",
                       as_wall=PLAIN_WALL_TOLERANCE))
    for update in ("compatible", "plain"):
        for check in (unequal, bimaterial):
            lines.append(check(root, failures, update))
    # The tutorial's mesh: the bars the bar on the wall (2e-8
    # before the limiter's round-off tolerance was each body's own)
    lines.append(equal(root, failures, "compatible", 100))
    # The rebound converges as about h^0.6 (the limited scheme's loss at
    # the fronts, issue 35): reversed within 1 % from 800 cells a metre,
    # and there too the bars are the bar on the wall (4e-8 while F was
    # the state: validation/barCollision/FINDINGS.md 2)
    lines.append(equal(root, failures, "compatible", N_REBOUND, 0.01))
    lines.append(restart(root, failures))
    for update in ("compatible", "plain"):
        lines.append(nonmatching(root, failures, update))
    lines.append(nonmatching(root, failures, "compatible", (3, 5)))
    warned = []
    for name in sorted(os.listdir(root)):
        log = os.path.join(root, name, "log.touchFoam")
        if "compatible" in name and os.path.exists(log):
            with open(log) as f:
                if "sides' forces of the contact between bodies" in f.read():
                    warned.append(name)
    if warned:
        failures.append("the two sides' forces part (warning) in %s"
                        % ", ".join(warned))
    lines.append("no imbalance warning in the compatible runs")
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
