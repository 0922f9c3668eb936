#!/usr/bin/python3
"""The tutorials' pictures show the fields touchFoam writes.

    /usr/bin/python3 test/cases/tutorialPictures.py

Extras: --with-paraview --with-plots --with-meshing

Needs pvbatch and xvfb-run (bin/touchSetup --with-paraview); without them
it passes with the message 'skipped: pvbatch or xvfb-run not installed'.
Every tutorial but the ring and the torus (their pictures are those of
the impact tests) runs small through its own ./Allrun, which ends with
render.py in pvbatch and plot.py: taylorImpact -n 2 (60 cells, to 80 us),
barRebound -n 2 (60 cells, to 400 us), twistingColumn -n 2 (48 cells, to
0.3 s), elasticImpact -n 50, holedPlate -n 2 (gmsh), spinningCube -n 3,
swingingCube -n 4, unstructuredCube -n 4, slidingBlock -n 4 (two cells across
the height would colour its hydrostatic pressure in two hues), barCollision
-n 50, sphereImpact -n 2, projectileImpact -n 2.  Asserted:
  - no field a render.py asks for is missing from the case (the log has no
    'no cell field'), and every picture is there: taylorImpact pressure,
    sigmaEq and epsilonP at 10, 30, 50, 80 us, barRebound pressure at 30,
    60, 120, 180, 270, 400 us, the contact of the wall patch at the same
    times for both, twistingColumn pressure and sigmaEq at 0.1, 0.2,
    0.3 s, and the pictures of the others (TUTORIALS below);
  - where matplotlib is installed, the plot each plot.py writes (PLOTS);
  - each is a PNG of the size render.py asks for (read back with VTK);
  - the body is seen and the colour range shows it: in each field picture
    (the colour bar and the time label left out) at least 2 % of the
    pixels are in colour and they fall in at least 3 of 12 hue bins
    (0.1 % of the picture each); a wrong range paints the body in one
    colour, a missing warp or a lost camera leaves it white;
  - the contact pictures show the solver's contact state: red ('in
    contact') pixels exactly when the written field contact has a face of
    patch 'wall' at 1 (read from the time folder with the touchfoam
    package, not from ParaView), blue ('free') pixels exactly when one is
    at 0; barRebound has its end in contact at 30 us and none at 400 us,
    in flight (separation near 280 us: 2L/c0, the seed paper's bar rebound).
Work folders: test/runs/tutorialPictures/.
"""

import json
import os
import re
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import foamfile, run, testing  # noqa: E402

NAME = "tutorialPictures"
#: tutorial: (Allrun options, picture size, {field: time labels})
TUTORIALS = {
    "taylorImpact": (["-n", "2"], (700, 1000), {
        "pressure": ["10us", "30us", "50us", "80us"],
        "sigmaEq": ["10us", "30us", "50us", "80us"],
        "epsilonP": ["10us", "30us", "50us", "80us"],
        "contact": ["10us", "30us", "50us", "80us"]}),
    "barRebound": (["-n", "2"], (700, 1000), {
        "pressure": ["30us", "60us", "120us", "180us", "270us", "400us"],
        "contact": ["30us", "60us", "120us", "180us", "270us", "400us"]}),
    "twistingColumn": (["-n", "2"], (600, 1000), {
        "pressure": ["0.1s", "0.2s", "0.3s"],
        "sigmaEq": ["0.1s", "0.2s", "0.3s"]}),
    "elasticImpact": (["-n", "50"], (1200, 200), {
        "pressure": ["0.1ms", "0.2ms", "0.3ms", "0.4ms", "0.5ms"]}),
    "holedPlate": (["-n", "2"], (1000, 600), {
        "sigmaEq": ["2ms", "3ms", "5ms", "10ms"],
        "pressure": ["2ms", "3ms", "5ms", "10ms"]}),
    "spinningCube": (["-n", "3"], (800, 800), {
        "sigmaEq": ["0.5s", "1s", "1.4s"],
        "pressure": ["0.5s", "1s", "1.4s"]}),
    "swingingCube": (["-n", "4"], (800, 800), {
        "sigmaEq": ["1ms", "2ms", "3ms"]}),
    "unstructuredCube": (["-n", "4"], (800, 800), {
        "sigmaEq": ["1ms", "2ms", "3ms"]}),
    "slidingBlock": (["-n", "4"], (1000, 400), {
        "pressure": ["0.05s", "0.15s", "0.3s", "0.45s"]}),
    # 2.5 ms (drawn too) is left out: the equal bars are released
    # unstressed, one colour by the physics
    "barCollision": (["-n", "50"], (1400, 200), {
        "pressure": ["0.5ms", "1.5ms"]}),
    # 30 us (drawn too) is left out: at -n 2 the ball leaving the wall
    # is nearly unstressed, one colour by the physics
    "sphereImpact": (["-n", "2"], (800, 800), {
        "pressure": ["5us", "15us"]}),
    # sigmaEq at 60 us (drawn too) is left out: at -n 2 the bodies, apart
    # after the impact, carry stresses far below the range of the impact
    # (two hue bins); the plastic strain stays, its 60 us picture is kept
    "projectileImpact": (["-n", "2"], (800, 800), {
        "sigmaEq": ["5us", "15us"],
        "epsilonP.plate": ["15us", "60us"]}),
}
#: tutorial: the plot its plot.py writes (made when matplotlib is installed)
PLOTS = {"taylorImpact": "histories.png", "barRebound": "histories.png",
         "elasticImpact": "profiles.png", "holedPlate": "histories.png",
         "spinningCube": "histories.png", "swingingCube": "histories.png",
         "unstructuredCube": "histories.png", "slidingBlock": "histories.png",
         "barCollision": "histories.png", "sphereImpact": "histories.png",
         "projectileImpact": "histories.png"}
LIMITS = {"coloured": 0.02, "hueBins": 3, "hueShare": 1e-3}
#: hue bins (of 12) of the contact pictures' two colours
RED, BLUE = 11, 7
UNITS = {"us": 1e-6, "ms": 1e-3, "s": 1.0}

STATS = """
import json, sys
from touchfoam.figures import picture_colours
print("STATS " + json.dumps({p: picture_colours(p) for p in sys.argv[1:]}))
"""


def wall_contact(case, label):
    """The patch values of the written field contact on 'wall' at the time
    of the picture label ('30us')."""
    m = re.match(r"([0-9.]+)(us|ms|s)$", label)
    t = float(m.group(1)) * UNITS[m.group(2)]
    folder = run.time_dir(case, t, tol=1e-3 * t)
    text = foamfile.FoamField(os.path.join(folder, "contact")) \
        .boundary_patches()["wall"]
    value = re.search(r"\bvalue\s+(uniform\s+([^;\s]+)|nonuniform\s+"
                      r"List<scalar>\s*(\d+)\s*(\{([^}]*)\}|\(([^)]*)\)))",
                      text)
    if value.group(2) is not None:                      # uniform v
        with open(os.path.join(case, "constant", "polyMesh",
                               "boundary")) as f:
            n = re.search(r"\bwall\s*\{[^}]*\bnFaces\s+(\d+)",
                          f.read()).group(1)
        return np.full(int(n), float(value.group(2)))
    if value.group(5) is not None:                      # n{v}
        return np.full(int(value.group(3)), float(value.group(5)))
    return np.array(value.group(6).split(), float)


def pictures(root, tutorial, failures):
    options, size, expected = TUTORIALS[tutorial]
    case = os.path.join(root, tutorial)
    run.copy_case(run.tutorial_dir(tutorial), case)
    run.run(["./Allrun"] + options, case, name="Allrun",
            timeout=testing.RUN_TIMEOUT)
    with open(os.path.join(case, "log.Allrun")) as f:
        allrun = f.read()
    render_log = os.path.join(case, "log.xvfb-run.render")
    if not os.path.exists(render_log):
        failures.append("%s: no pictures made (log.Allrun: %s)"
                        % (tutorial, allrun.strip().splitlines()[-1]))
        return "%s: no pictures" % tutorial
    with open(render_log) as f:
        missing = re.findall(r"no cell field '(\w+)'", f.read())
    if missing:
        failures.append("%s: render.py asks for fields the case does not "
                        "write: %s" % (tutorial, " ".join(missing)))

    plot = PLOTS.get(tutorial)
    if plot and "plots skipped" not in allrun:
        path = os.path.join(case, plot)
        if not os.path.exists(path) or os.path.getsize(path) == 0:
            failures.append("%s: plot.py wrote no %s (log.plot.py)"
                            % (tutorial, plot))

    names = ["%s_%s.png" % (field, label)
             for field, labels in expected.items() for label in labels]
    absent = [n for n in names
              if not os.path.exists(os.path.join(case, n))
              or os.path.getsize(os.path.join(case, n)) == 0]
    if absent:
        failures.append("%s: pictures missing or empty: %s"
                        % (tutorial, " ".join(absent)))
    present = [n for n in names if n not in absent]
    if not present:
        return "%s: no pictures" % tutorial
    with open(os.path.join(case, "pictureColours.py"), "w") as f:
        f.write(STATS)
    # Three tries, the search for a free display starting at a number of
    # this process's own: two renderings starting at once race for one
    line = []
    for attempt in range(3):
        if attempt:
            time.sleep(2.0 * attempt)
        display = str(1000 + (os.getpid() % 800) * 4 + attempt)
        out = subprocess.run(["xvfb-run", "-a", "-n", display, "pvbatch",
                              "pictureColours.py"] + present, cwd=case,
                             stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT,
                             universal_newlines=True,
                             timeout=testing.RUN_TIMEOUT).stdout
        line = [s for s in out.splitlines() if s.startswith("STATS ")]
        if line:
            break
    if not line:
        raise AssertionError("%s: reading the pictures back failed:\n%s"
                             % (tutorial, out[-2000:]))
    stats = json.loads(line[0][len("STATS "):])

    worst = (1.0, None)
    contact_line = []
    for name in present:
        s = stats[name]
        hues = np.asarray(s["hues"])
        if tuple(s["size"]) != size:
            failures.append("%s/%s: %d x %d pixels, render.py asks for "
                            "%d x %d" % ((tutorial, name) + tuple(s["size"])
                                         + size))
        field, label = name[:-len(".png")].split("_")
        if field == "contact":
            faces = wall_contact(case, label)
            red, blue = hues[RED] > 0, hues[BLUE] > 0
            if red != bool(np.any(faces > 0.5)) \
                    or blue != bool(np.any(faces < 0.5)):
                failures.append(
                    "%s/%s: %s red and %s blue pixels, but %d of %d faces "
                    "of wall in contact" % (tutorial, name,
                                            "some" if red else "no",
                                            "some" if blue else "no",
                                            np.sum(faces > 0.5), len(faces)))
            contact_line.append("%s %d/%d" % (label, np.sum(faces > 0.5),
                                              len(faces)))
            continue
        bins = int(np.sum(hues >= LIMITS["hueShare"]))
        if s["coloured"] < LIMITS["coloured"] or bins < LIMITS["hueBins"]:
            failures.append("%s/%s: %.1f %% of the pixels in colour, in %d "
                            "hue bins (at least %.0f %% and %d)"
                            % (tutorial, name, 100 * s["coloured"], bins,
                               100 * LIMITS["coloured"], LIMITS["hueBins"]))
        worst = min(worst, (s["coloured"], "%s %.1f %% in colour, %d hue "
                            "bins" % (name, 100 * s["coloured"], bins)))

    if tutorial == "barRebound":
        for label, touching in (("30us", True), ("400us", False)):
            faces = wall_contact(case, label)
            if bool(np.any(faces > 0.5)) != touching:
                failures.append("barRebound: at %s %d of %d faces of wall "
                                "in contact (expected %s)"
                                % (label, np.sum(faces > 0.5), len(faces),
                                   "some" if touching else "none"))
    summary = "%s: %d pictures, least coloured %s" % (tutorial, len(present),
                                                      worst[1])
    if contact_line:
        summary += "; faces in contact " + ", ".join(contact_line)
    return summary


def body():
    missing = [p for p in ("pvbatch", "xvfb-run") if shutil.which(p) is None]
    if missing:
        return ("skipped: pvbatch or xvfb-run not installed (%s missing; "
                "bin/touchSetup --with-paraview installs them)"
                % " ".join(missing))
    root = testing.work_dir(NAME)
    failures, lines = [], []
    for tutorial in TUTORIALS:
        try:
            lines.append(pictures(root, tutorial, failures))
        except (AssertionError, run.RunError) as err:
            failures.append(str(err).split("\n")[0])
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
