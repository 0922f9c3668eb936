#!/usr/bin/python3
"""Every tutorial's ParaView state opens its case deformed and coloured,
and its Allrun ends with the headline numbers.

    /usr/bin/python3 test/cases/tutorialStates.py [--steps 20]

Extras: --with-paraview

Needs pvbatch and xvfb-run (bin/touchSetup --with-paraview); without them
it passes with the message 'skipped: pvbatch or xvfb-run not installed'.
Each tutorial is copied and its own ./Allrun run on a small mesh for a few
steps (maxSteps added to system/controlDict as text), with bin/python off
PYTHONPATH so that the pictures and plots are skipped.  Then, in the case,
pvbatch executes the tutorial's state.py as 'paraview --state=state.py'
does and saves the view (800 x 800).  Asserted per tutorial:
  - log.tutorialResults (the Allrun's last step) has its 'Headline
    numbers' block and no 'could not read';
  - the state's filter 'deformed (pointD)' warps by pointD and moves the
    points (its scale factor times the largest |pointD| at the time shown
    is above 0: a missing pointD or a zero scale fails);
  - the body is coloured by the field the state names (FIELD), which the
    case writes, at the written time nearest the state's TIME;
  - the picture shows the body in colour: between 0.5 % and 95 % of its
    pixels (the colour bar and the corner axes left out) are in colour,
    in at least 3 of 12 hue bins (0.1 % of the picture each); a blank
    view, a lost camera or a solid colour fails.
Work folders: test/runs/tutorialStates/.
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import run, testing  # noqa: E402

NAME = "tutorialStates"
#: tutorial: Allrun options (small meshes)
TUTORIALS = {
    "swingingCube": ["-n", "4"],
    "unstructuredCube": ["-n", "2"],
    "spinningCube": ["-n", "3"],
    "twistingColumn": ["-n", "2"],
    "elasticImpact": ["-n", "10"],
    "holedPlate": ["-n", "2"],
    "taylorImpact": ["-n", "2"],
    "barRebound": ["-n", "2"],
    "ringImpact": ["-n", "24"],
    "torusImpact": ["-n", "4"],
    "slidingBlock": ["-n", "2"],
    "barCollision": ["-n", "10"],
    "sphereImpact": ["-n", "2"],
    "projectileImpact": ["-n", "2"],
}
LIMITS = {"coloured": (0.005, 0.95), "hueBins": 3, "hueShare": 1e-3}

#: run by pvbatch in the case: the state, then what it shows
DRIVER = r"""
import json
state = {}
exec(compile(open("state.py").read(), "state.py", "exec"), state)
from paraview import simple as pv
from touchfoam.figures import picture_colours
view = pv.GetActiveView()
warp = pv.FindSource("deformed (pointD)")
case = pv.FindSource("case.foam")
display = pv.GetDisplayProperties(warp, view)
time = pv.GetAnimationScene().AnimationTime
case.UpdatePipeline(time)
warp.UpdatePipeline(time)
pv.SaveScreenshot("state.png", view, ImageResolution=[800, 800])
print("STATE " + json.dumps({
    "field": state["FIELD"], "time": state["TIME"], "shown": time,
    "written": list(case.TimestepValues),
    "cellFields": list(case.GetProperty("CellArrayInfo")[::2]),
    "vectors": list(warp.Vectors), "colour": list(display.ColorArrayName),
    "scale": warp.ScaleFactor,
    "pointD": warp.PointData["pointD"].GetRange(-1)[1],
    "picture": picture_colours("state.png")}))
"""


def environment():
    """os.environ with every bin/python entry taken off PYTHONPATH."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        p for p in env.get("PYTHONPATH", "").split(os.pathsep)
        if p and not p.rstrip("/").endswith(os.path.join("bin", "python")))
    return env


def add_max_steps(case, steps):
    path = os.path.join(case, "system", "controlDict")
    with open(path) as f:
        text = f.read()
    text, count = re.subn(r"(\nendTime\s+[^;]+;\n)",
                          r"\1\nmaxSteps        %d;\n" % steps, text, count=1)
    if count != 1:
        raise AssertionError("%s: no endTime entry" % path)
    with open(path, "w") as f:
        f.write(text)


def render(case):
    """The driver in pvbatch (three retries, a little later each time:
    Xvfb is at times not ready, and pvbatch then aborts without output)."""
    with open(os.path.join(case, "stateDriver.py"), "w") as f:
        f.write(DRIVER)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [os.path.join(run.project_dir(), "bin", "python")]
        + [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p])
    out = ""
    for attempt in range(4):
        if attempt:
            # Another Xvfb starting at the same moment takes the display
            # xvfb-run picked: wait before the next try
            time.sleep(2.0 * attempt)
        # The search for a free display starts at a number of this
        # process's own (and of the attempt): two renderings starting at
        # once otherwise race for the same one
        display = str(100 + (os.getpid() % 800) * 4 + attempt)
        out = subprocess.run(["xvfb-run", "-a", "-n", display, "pvbatch",
                              "stateDriver.py"],
                             cwd=case, env=env, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT,
                             universal_newlines=True,
                             timeout=testing.RUN_TIMEOUT).stdout
        line = [s for s in out.splitlines() if s.startswith("STATE ")]
        if line:
            return json.loads(line[0][len("STATE "):])
    raise AssertionError("%s: pvbatch did not render the state:\n%s"
                         % (case, out[-2000:]))


def check(root, tutorial, options, steps, env):
    case = os.path.join(root, tutorial)
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(run.tutorial_dir(tutorial), case)
    add_max_steps(case, steps)
    with open(os.path.join(case, "log.Allrun"), "w") as log:
        status = subprocess.call(["./Allrun"] + options, cwd=case, env=env,
                                 stdout=log, stderr=subprocess.STDOUT,
                                 timeout=testing.RUN_TIMEOUT)
    if status != 0:
        return None, ["%s: ./Allrun exited %d (%s/log.Allrun)"
                      % (tutorial, status, case)]
    problems = []
    results = os.path.join(case, "log.tutorialResults")
    text = open(results).read() if os.path.exists(results) else ""
    if "Headline numbers" not in text or "could not read" in text:
        problems.append("%s: no headline numbers in log.tutorialResults: %s"
                        % (tutorial, text.strip()[-300:]))

    s = render(case)
    if s["vectors"] != ["POINTS", "pointD"]:
        problems.append("%s: the warp uses %s, not pointD"
                        % (tutorial, s["vectors"]))
    moved = s["scale"] * s["pointD"]
    if not moved > 0:
        problems.append("%s: the warp moves no point (largest |pointD| "
                        "%g, scale factor %g)" % (tutorial, s["pointD"],
                                                  s["scale"]))
    if s["field"] not in s["cellFields"]:
        problems.append("%s: the state colours by %s, which the case does "
                        "not write (%s)" % (tutorial, s["field"],
                                            " ".join(s["cellFields"])))
    if s["colour"] != ["CELLS", s["field"]]:
        problems.append("%s: coloured by %s, the state names %s"
                        % (tutorial, s["colour"], s["field"]))
    nearest = min(s["written"], key=lambda t: abs(t - s["time"]))
    if abs(s["shown"] - nearest) > 1e-12 * max(1.0, nearest):
        problems.append("%s: shows t = %g, the written time nearest %g is %g"
                        % (tutorial, s["shown"], s["time"], nearest))
    picture = s["picture"]
    bins = sum(h >= LIMITS["hueShare"] for h in picture["hues"])
    lo, hi = LIMITS["coloured"]
    if not lo <= picture["coloured"] <= hi or bins < LIMITS["hueBins"]:
        problems.append("%s: %.2f %% of the picture in colour, %d hue bins "
                        "(%.1f-%.0f %% and at least %d)"
                        % (tutorial, 100 * picture["coloured"], bins,
                           100 * lo, 100 * hi, LIMITS["hueBins"]))
    line = ("%-17s %s at t = %g, %.1f %% in colour, %d hue bins, points "
            "moved up to %.3g m" % (tutorial, s["field"], s["shown"],
                              100 * picture["coloured"], bins, moved))
    return line, problems


def body(args):
    missing = [p for p in ("pvbatch", "xvfb-run") if shutil.which(p) is None]
    if missing:
        return ("skipped: pvbatch or xvfb-run not installed (%s missing; "
                "bin/touchSetup --with-paraview installs them)"
                % " ".join(missing))
    root = testing.work_dir(NAME)
    env = environment()
    lines, failures = [], []
    for tutorial, options in TUTORIALS.items():
        try:
            line, problems = check(root, tutorial, options, args.steps, env)
        except (AssertionError, subprocess.TimeoutExpired) as err:
            line, problems = None, [str(err).split("\n")[0]]
        if line:
            lines.append(line)
        failures += problems
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=20)
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args)))
