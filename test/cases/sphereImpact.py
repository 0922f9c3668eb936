#!/usr/bin/python3
"""Hertz impact of elastic balls against the closed form (K.L. Johnson,
Contact Mechanics, ch. 4 and 11.4; touchfoam.hertz).

    /usr/bin/python3 test/cases/sphereImpact.py

Copies of tutorials/sphereImpact (quarter balls of radius 10 mm, graded
towards the contact point, limitedLinear, RK2 at CFL 0.3) at -n 6, the
coarsest mesh of the study (validation/sphereImpact/FINDINGS.md):

  wall    a steel ball at 10 m/s on the frictionless rigid wall (FUpdate
          compatible, rigidWall touching lowestFreePoint, hold
          touchingPoints): the peak
          contact force of the whole ball and the contact time (the first
          step with no face in contact) within TOLERANCE of the closed
          form (about 3 times the error measured on this mesh); the ball
          rebounds (p_y > 0 at the end); the energy never grows (1e-12 E0
          per step) and the scheme's dissipation stays >= 0;
  sphere  that ball on an aluminium ball of the same radius at rest
          (bodyContact, FUpdate compatible, faces that match at the
          start): the energy never grows; the peak of the force the balls
          receive (their momentum change per step) and the contact time
          within TOLERANCE of the closed form; the balls' momenta at the
          end within 0.03 |p0| of a rigid elastic exchange; the total p_y
          (no wall, the symmetric planes push along x and z only) within
          MOMENTUM_DRIFT of |p0|, the issue's 1e-12 (measured 9e-15 since
          the compatible update splits a point's reaction between the
          contact and the symmetric plane; 1.9e-3 before).  The contact
          time is 14 % short on this mesh (one face of each quarter cap is
          in contact, the contact's radius is not resolved: FINDINGS.md),
          so its tolerance guards today's value, not the issue's 5 %;
  sphere8 the two balls at -n 8 (several faces in contact, pairs of
          partly overlapping faces on a curved contact): the force the
          balls receive and the contact time within the issue's 5 % of the
          closed form (measured -3.66 % and -0.65 % on 2026-12-06; before
          the points were counted only over their partner face, +144.7 %
          with faces outside the contact held), at most 8 faces in contact
          (6), momentum as above, and the energy never growing in a step
          beyond round-off, ENERGY_GROWTH_8 (measured none; 1.1e-4 E0 in
          237 steps of the release while neighbours' sliver pairs acted,
          3.1e-3 before the points over the partner,
          validation/sphereImpact/FINDINGS.md 8 and 9);
  wall8   the ball on the wall at -n 8 (the tutorial's mesh): force and
          contact time within the issue's 5 % (measured +4.18 % and
          -1.79 % on 2026-12-07 with hold touchingPoints; +2.27 % and
          -5.07 % with hold faces, whose error grew with the mesh to
          +6.18 % at -n 16: FINDINGS.md 10), the energy never growing.
Work folders: test/runs/sphereImpact/.
"""

import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import hertz, run, testing  # noqa: E402

NAME = "sphereImpact"
N = 6

#: |measured/closed form - 1| allowed: (peak force, contact time), about
#: 3 times the errors measured at -n 6 on 2026-12-05 (FINDINGS.md); the
#: wall's contact time is held to the issue's 5 %: since the wall releases
#: faces whose force would pull (e761893) the ball leaves earlier, -3.87 %
#: (-0.76 % before, when the wall held it back with tension).  Between
#: the balls (2026-12-05, lowest free point entry, reactions split): the
#: force they receive +0.59 %, the contact time -14.2 %.  The wall with
#: hold touchingPoints (2026-12-07): +0.68 % and +4.36 %
TOLERANCE = {"wall": (0.08, 0.05), "sphere": (0.02, 0.2)}

#: the total p_y drift allowed between the balls (measured 9.1e-15 at
#: -n 6 on 2026-12-05; the issue's bound)
MOMENTUM_DRIFT = 1e-12

#: the balls' momenta at the end against a rigid elastic exchange
EXCHANGE = 0.03

#: -n 8 between the balls: (peak force, contact time) tolerance, the most
#: faces in contact, the largest energy growth in a step [E0] allowed
#: (round-off: none measured on 2026-12-06, as barCollision's bound)
TOLERANCE_8 = (0.05, 0.05)
MAX_FACES_8 = 8
ENERGY_GROWTH_8 = 1e-12


def solve(root, variant, n=N):
    case = os.path.join(root, variant if n == N else "%s_n%d" % (variant, n))
    if os.path.exists(case):
        shutil.rmtree(case)
    # No pictures or plots (tutorialPictures' business): the test's cost
    # is the two runs
    shutil.copytree(run.tutorial_dir("sphereImpact"), case,
                    ignore=shutil.ignore_patterns("render.py", "plot.py"))
    run.run(["./Allrun", "-variant", variant, "-n", str(n)], case,
            name="Allrun", timeout=testing.RUN_TIMEOUT)
    return case


def hertz_checks(variant, r, failures):
    tol_F, tol_t = TOLERANCE[variant]
    if "appliedPeak" in r:
        # Between the balls the force they receive, not the pairs'
        # Riemann traction (the compatible update applies the contact
        # through the points' constraint)
        r = dict(r, peakForce=r["appliedPeak"],
                 forceError=r["appliedForceError"])
    if not r["released"]:
        failures.append("%s: still in contact at the end" % variant)
    if abs(r["forceError"]) > tol_F:
        failures.append("%s: peak force %.5g N, %+.2f %% of the closed "
                        "form %.5g N (allowed %.0f %%)"
                        % (variant, r["peakForce"], 100 * r["forceError"],
                           r["reference"]["F"], 100 * tol_F))
    if abs(r["timeError"]) > tol_t:
        failures.append("%s: contact time %.4g us, %+.2f %% of the closed "
                        "form %.4g us (allowed %.0f %%)"
                        % (variant, 1e6 * r["contactTime"],
                           100 * r["timeError"], 1e6 * r["reference"]["tc"],
                           100 * tol_t))
    if r["energyGrowth"] > 1e-12:
        failures.append("%s: the energy grew by %.2e E0 in a step"
                        % (variant, r["energyGrowth"]))
    if r.get("dissipationMin", 0.0) < -1e-12:
        failures.append("%s: numerical dissipation %.2e E0 < 0"
                        % (variant, r["dissipationMin"]))
    return ("%s: peak force %+.2f %%, contact time %+.2f %% of the closed "
            "form (%d faces in contact at most), energy at the end %.3f E0"
            % (variant, 100 * r["forceError"], 100 * r["timeError"],
               r["maxFaces"], r["energyEnd"]))


def body():
    root = testing.work_dir(NAME)
    lines, failures = [], []

    r = hertz.analyse(solve(root, "wall"))
    lines.append(hertz_checks("wall", r, failures))
    if not r["reboundMomentum"] < 0:
        failures.append("wall: p_y at the end %.3f of p_y(0), no rebound"
                        % r["reboundMomentum"])

    r = hertz.analyse(solve(root, "sphere"))
    lines.append(hertz_checks("sphere", r, failures))
    exchange = hertz.elastic_momenta(os.path.join(root, "sphere"))
    if r["momentumDrift"] > MOMENTUM_DRIFT:
        failures.append("sphere: total p_y drifted by %.2e of |p0|"
                        % r["momentumDrift"])
    if max(abs(r["ball1End"] - exchange[0]),
           abs(r["ball2End"] - exchange[1])) > EXCHANGE:
        failures.append("sphere: ball momenta at the end %+.3f, %+.3f of "
                        "|p0|, rigid elastic %+.3f, %+.3f"
                        % ((r["ball1End"], r["ball2End"]) + exchange))
    lines.append("total p_y drift %.1e |p0|, ball momenta at the end %+.3f,"
                 " %+.3f (rigid elastic %+.3f, %+.3f)"
                 % ((r["momentumDrift"], r["ball1End"], r["ball2End"])
                    + exchange))

    r = hertz.analyse(solve(root, "sphere", 8))
    force, time = r["appliedForceError"], r["timeError"]
    lines.append("sphere n 8: force the balls receive %+.2f %%, contact "
                 "time %+.2f %% of the closed form, %d faces in contact at "
                 "most, largest energy growth in a step %.1e E0, p_y drift "
                 "%.1e |p0|" % (100 * force, 100 * time, r["maxFaces"],
                                r["energyGrowth"], r["momentumDrift"]))
    if abs(force) > TOLERANCE_8[0] or abs(time) > TOLERANCE_8[1]:
        failures.append("sphere n 8: force %+.2f %%, contact time %+.2f %% "
                        "(allowed %.0f %%, %.0f %%)"
                        % (100 * force, 100 * time, 100 * TOLERANCE_8[0],
                           100 * TOLERANCE_8[1]))
    if r["maxFaces"] > MAX_FACES_8:
        failures.append("sphere n 8: %d faces in contact (at most %d)"
                        % (r["maxFaces"], MAX_FACES_8))
    if r["energyGrowth"] > ENERGY_GROWTH_8:
        failures.append("sphere n 8: the energy grew by %.2e E0 in a step "
                        "(allowed %.1e)" % (r["energyGrowth"],
                                            ENERGY_GROWTH_8))
    if not r["released"] or r["momentumDrift"] > MOMENTUM_DRIFT:
        failures.append("sphere n 8: not released, or p_y drift %.2e"
                        % r["momentumDrift"])

    r = hertz.analyse(solve(root, "wall", 8))
    lines.append("wall n 8: " + hertz_checks("wall", r, []))
    if (abs(r["forceError"]) > TOLERANCE_8[0]
            or abs(r["timeError"]) > TOLERANCE_8[1]):
        failures.append("wall n 8: force %+.2f %%, contact time %+.2f %% "
                        "(allowed %.0f %%, %.0f %%)"
                        % (100 * r["forceError"], 100 * r["timeError"],
                           100 * TOLERANCE_8[0], 100 * TOLERANCE_8[1]))
    if r["energyGrowth"] > ENERGY_GROWTH_8 or not r["released"]:
        failures.append("wall n 8: the energy grew by %.2e E0 in a step, "
                        "or not released" % r["energyGrowth"])
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
