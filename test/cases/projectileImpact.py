#!/usr/bin/python3
"""A steel ball denting a free aluminium plate, both von Mises, with
Coulomb friction mu = 0.2 between them (tutorials/projectileImpact,
touchfoam.projectile), against the balances that hold whatever the mesh
and simple independent estimates.

    /usr/bin/python3 test/cases/projectileImpact.py

A copy of the tutorial at -n 4 (1 184 cells, quarter model, FUpdate
compatible with the plate's top held on the ball as side nodes, 50 m/s,
to 60 us).  Asserted:
  - the total p_y (no wall acts along y: the plate is free and the
    symmetric planes push along x and z only) constant within
    MOMENTUM_DRIFT of |p0| (measured 4.9e-15 on 2026-12-07; 4.4e-15 with
    FUpdate plain);
  - the energy never grows: kinetic + strain energy, and that sum with the
    plastic and friction dissipation (what the bodies hold and what the
    laws dissipated), by no more than 1e-12 E0 in any step;
  - Coulomb's cone at every pair and step: the largest |t_t|/|t_n| of a
    pair (contact.dat's maxPairFrictionRatio; with side nodes the held
    points' |F_t|/N) <= mu (1 + 1e-12), and the friction power of every
    pair <= 0; the friction dissipation > 0;
  - the plastic dissipation at the end positive and within PLASTIC_BAND of
    the energy estimate E0 - p_b^2/(2 m_b) - p_p^2/(2 M_p) (the energy the
    bodies' rigid motions do not carry; it holds the plate's vibrations
    and the scheme's dissipation too, so the plastic work falls below it:
    measured 0.673 of it with side nodes, 0.423 with FUpdate plain:
    validation/projectileImpact/FINDINGS.md 8 to 10);
  - the dent (the plate's top at the impact point below the plate's
    centre of mass) within DENT_BAND of Tabor's rigid-plastic estimate
    h = sqrt(W/(3 pi Y R)) (measured 0.78 of it; rough: hardening, rate
    and bending are left out of the estimate, so the band is wide);
  - side auto on both contact patches: the plate (the softer) reported
    as taking side nodes, the ball as both (a few steps);
  - the ball rebounds (p_y of the ball > 0 at the end), the contact is
    released and never pulls (the most tensile contact traction <= 0);
  - no ball point deeper inside the plate than POINT_DEPTH of the
    smallest plate face, below the top surface the plate's points draw, at
    the written times (measured 0.0073 on this mesh, 0.0048 at -n 6;
    FUpdate plain 0.050 and 0.028: the issue's 0.05;
    validation/projectileImpact/FINDINGS.md 9, 10);
  - the gap of a pair's face planes at their overlap's centroid
    (contact.dat: the planes with the normals of the cells' F, up to 30
    deg off the drawn faces in the dent; 0 with side nodes, whose pairs
    are the held points) below PENETRATION of that face.
Work folders: test/runs/projectileImpact/.
"""

import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import projectile, run, testing  # noqa: E402

NAME = "projectileImpact"
N = 4

#: the total p_y drift allowed: about 3 times the 4.4e-15 (plain) and
#: 4.9e-15 (side nodes) measured at -n 4 on 2026-12-06 and 07
MOMENTUM_DRIFT = 1.5e-14

#: plastic dissipation over the energy estimate (measured 0.673 on
#: 2026-12-07 with side nodes, 0.436 on 2026-12-06 with FUpdate plain)
PLASTIC_BAND = (0.3, 1.0)

#: the dent over Tabor's estimate (measured 0.78)
DENT_BAND = (0.5, 2.0)

#: the deepest ball point inside the plate over the smallest plate face
#: (measured 0.0073 on 2026-12-07 with side nodes; 0.0499 on
#: 2026-12-06 with FUpdate plain, 0.37 before the points a face pushed on
#: counted in the plain update's entry test)
POINT_DEPTH = 0.1

#: the largest gap of a pair's planes over the smallest plate face
#: (measured 0 with side nodes; 0.183 with FUpdate plain, 0.353 before)
PENETRATION = 0.5


def auto_side(root, meshed, failures):
    """side auto on both contact patches of the meshed tutorial: the
    aluminium plate (rho c_p about 2.7 times lower than the steel ball's)
    takes side nodes, as the tutorial gives it, and the ball keeps both;
    a few steps, the choice read from the log."""
    case = os.path.join(root, "autoSide")
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(meshed, case, ignore=lambda d, names: [
        n for n in names if d == meshed and (
            n.startswith("log.") or n.startswith("processor")
            or n == "postProcessing"
            or (n != "0" and n.replace(".", "").replace("e-", "").isdigit()))])
    for patch in ("ballSurface", "plateTop"):
        run.foam_set(case, "0/U", "boundaryField/%s/side" % patch, "auto")
    run.foam_set(case, "system/controlDict", "endTime", 1e-7)
    log = run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
    with open(log) as f:
        text = f.read()
    for patch, side in (("plateTop", "nodes"), ("ballSurface", "both")):
        if "bodyContact %s: side auto -> %s" % (patch, side) not in text:
            failures.append("side auto: %s not reported as %s"
                            % (patch, side))
    return "side auto on both: plateTop (softer) nodes, ballSurface both"


def body():
    root = testing.work_dir(NAME)
    case = os.path.join(root, "n%d" % N)
    if os.path.exists(case):
        shutil.rmtree(case)
    # No pictures or plots (tutorialPictures' business)
    shutil.copytree(run.tutorial_dir(NAME), case,
                    ignore=shutil.ignore_patterns("render.py", "plot.py"))
    run.run(["./Allrun", "-n", str(N)], case, name="Allrun",
            timeout=testing.RUN_TIMEOUT)
    r = projectile.analyse(case)

    failures = []
    if not r["momentumDrift"] <= MOMENTUM_DRIFT:
        failures.append("total p_y drifted by %.2e of |p0| (allowed %.1e)"
                        % (r["momentumDrift"], MOMENTUM_DRIFT))
    if not r["energyGrowth"] <= 1e-12:
        failures.append("kinetic + strain energy grew by %.2e E0 in a step"
                        % r["energyGrowth"])
    if not r["accountedGrowth"] <= 1e-12:
        failures.append("kinetic + strain + plastic + friction grew by "
                        "%.2e E0 in a step" % r["accountedGrowth"])
    mu = r["mu"]
    if not mu > 0:
        failures.append("the tutorial has no friction (mu %g)" % mu)
    if "pairFrictionRatio" not in r:
        failures.append("contact.dat has no maxPairFrictionRatio")
    elif not r["pairFrictionRatio"] <= mu * (1 + 1e-12):
        failures.append("|t_t|/|t_n| of a pair %.6f > mu %g"
                        % (r["pairFrictionRatio"], mu))
    if not r.get("pairFrictionPower", 1.0) <= 0:
        failures.append("a pair's friction power %.3e > 0"
                        % r.get("pairFrictionPower", float("nan")))
    if not r["friction"] > 0:
        failures.append("friction dissipation %.3e E0, not > 0"
                        % r["friction"])
    share = r["plastic"] / r["plasticEstimate"]
    if not (r["plastic"] > 0
            and PLASTIC_BAND[0] <= share <= PLASTIC_BAND[1]):
        failures.append("plastic dissipation %.4f E0, %.3f of the estimate "
                        "%.4f E0 (allowed %.2f to %.2f)"
                        % (r["plastic"], share, r["plasticEstimate"],
                           PLASTIC_BAND[0], PLASTIC_BAND[1]))
    if r["dent"] is None:
        failures.append("no pointD written: no dent")
        dent = float("nan")
    else:
        dent = r["dent"] / r["dentEstimate"]
        if not DENT_BAND[0] <= dent <= DENT_BAND[1]:
            failures.append("dent %.3f mm, %.2f of Tabor's %.3f mm (allowed"
                            " %.2f to %.2f)" % (1e3 * r["dent"], dent,
                                                1e3 * r["dentEstimate"],
                                                DENT_BAND[0], DENT_BAND[1]))
    if not r["ballMomentum"] > 0:
        failures.append("the ball does not rebound: p_y %.4f |p0|"
                        % r["ballMomentum"])
    if not r["released"]:
        failures.append("the ball is still in contact at the end")
    if not r["mostTensile"] <= 0:
        failures.append("a contact pulled: %.3e Pa" % r["mostTensile"])
    depth = float("nan")
    if r["pointDepth"] is None:
        failures.append("no pointD written: no depth of the ball's points")
    else:
        depth = r["pointDepth"] / r["faceSize"]
        if not depth <= POINT_DEPTH:
            failures.append("a ball point %.4f mm inside the plate, %.3f of "
                            "the smallest plate face (allowed %.2f)"
                            % (1e3 * r["pointDepth"], depth, POINT_DEPTH))
    pen = r["penetration"] / r["faceSize"]
    if not pen <= PENETRATION:
        failures.append("penetration %.4f mm, %.3f of the smallest plate "
                        "face (allowed %.2f)" % (1e3 * r["penetration"], pen,
                                                 PENETRATION))

    auto = auto_side(root, case, failures)

    lines = [
        auto,
        "p_y drift %.1e |p0|; energy growth in a step %+.1e E0 (with the "
        "dissipations %+.1e E0)" % (r["momentumDrift"], r["energyGrowth"],
                                    r["accountedGrowth"]),
        "|t_t|/|t_n| of a pair %.4f (mu %g), of a face %.4f; friction "
        "dissipation %.4f E0" % (r.get("pairFrictionRatio", float("nan")),
                                 mu, r.get("faceFrictionRatio",
                                           float("nan")), r["friction"]),
        "plastic dissipation %.4f E0 = %.3f of the estimate %.4f E0; dent "
        "%.3f mm = %.2f of Tabor's %.3f mm" % (
            r["plastic"], share, r["plasticEstimate"],
            1e3 * (r["dent"] or float("nan")), dent,
            1e3 * r["dentEstimate"]),
        "ball %+.3f m/s at the end; deepest ball point %.4f, pair-plane "
        "gap %.3f of the smallest plate face" % (r["ballVelocity"], depth,
                                                 pen),
    ]
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
