#!/usr/bin/python3
"""validation/Allrun -quick writes a report with pass or fail for every
check of every study, FAIL rows first, and the run times.

    /usr/bin/python3 test/cases/validationReport.py

Builds a copy of the project in test/runs/validationReport/ (every
top-level entry a link to the project's, validation/ a fresh folder with
the project's validation/Allrun), so that the project's own
validationQuick/ and validation/README.md are left alone, with three
studies:

  swingingCube   the project's study (validation/swingingCube, its -quick
                 size: meshes 4 8 16, linear), whose script records its
                 checks with touchfoam.checks.record: the observed order
                 of each velocity and stress component against >= 1.8;
  plantedFail    a made-up study recording one passing and one failing
                 check and exiting with checks.status (must be 1);
  plantedNone    a made-up study that records nothing and exits 0.

  seedFigures    the project's study of our pictures beside the seed
                 paper's figures, limited (its Allrun in the copy adds
                 '--only swingingCube ringImpact') to the swinging cube
                 (the swingingCube study's plot) and the ring (-n 48).

Runs 'validation/Allrun -quick swingingCube plantedFail plantedNone
seedFigures' there and asserts: its exit status is 1; validation/README.md says at its top
that it is a quick run, with the date, the commit and the total run time
(the same as the total row), and links each study to
../validationQuick/<study>; it has a Checks
table with one row per recorded check (as many as the checks.json files
hold) plus one for plantedNone, every row 'pass' or '**FAIL**'; the
planted failing check and plantedNone's 'no check recorded' row are
FAIL and come before every pass row; swingingCube's rows pass (the
study's own reference, order >= 1.8 on 8/16); the studies' table gives
each study's verdict (plantedFail: FAIL by its exit status, plantedNone:
FAIL, no check recorded) and run time
and a total row whose time is at least the sum of the studies'.
The section 'Beside the seed figures' has the six seed examples in
order (### 1. Swinging cube ... ### 6. Torus impact), the four not run
saying so; the swinging cube's links to the study's convergence.png and
its L2 error rows (ours a number); the ring's pressure at 0.18 s and
momentum histories (links, or where pvbatch or matplotlib is missing a
line saying 'not made' and why), and its rows with our numbers
(p_y(0) per metre within 1 % of -M v0 = -1.297 kg m/s, p_y at the end
> 0); every picture link of the report names a file that is there.  Then
seedFigures.py runs once more, the ring alone, with pvbatch and xvfb-run
hidden from the PATH: its section must link no picture of the ring and
say 'not made: ParaView' for each.  About three minutes (the swinging
cube on 4^3, 8^3, 16^3 cells, the ring twice).
"""

import json
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import testing  # noqa: E402

NAME = "validationReport"
TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

PLANTED_FAIL = """#!/usr/bin/python3
import os, sys
from touchfoam import checks
HERE = os.path.dirname(os.path.abspath(__file__))
checks.record(HERE, "planted passing check", 1.0, "<= 2", True)
checks.record(HERE, "planted failing check", 3.0, "<= 2", False,
              "made up by test/cases/validationReport.py")
sys.exit(checks.status(HERE))
"""


#: the seedFigures study limited to two examples (cost)
SEED_ALLRUN = """#!/bin/sh
cd "${0%/*}" || exit
exec /usr/bin/python3 ./seedFigures.py "$@" --only swingingCube ringImpact
"""
SEED_TITLES = ["Swinging cube", "Twisting column", "Taylor impact",
               "Bar rebound", "Ring impact", "Torus impact"]
RING_PICTURES = ("pressure_180ms.png", "histories.png")


def seed_section(report, root, failures, lines):
    """The section 'Beside the seed figures' of the report."""
    if "\n## Beside the seed figures\n" not in report:
        failures.append("no section 'Beside the seed figures'")
        return
    part = report.split("\n## Beside the seed figures\n", 1)[1] \
        .split("\n## ", 1)[0]
    heads = re.findall(r"^### (\d)\. ([^(]+?) \(", part, re.M)
    if [(int(i), t) for i, t in heads] != list(enumerate(SEED_TITLES, 1)):
        failures.append("seed examples %s, expected 1-6 %s"
                        % (heads, SEED_TITLES))
        return
    blocks = dict(zip(SEED_TITLES, re.split(r"^### \d\. ", part,
                                            flags=re.M)[1:]))
    not_run = [t for t in SEED_TITLES if "Not run in this report" in
               blocks[t]]
    if not_run != SEED_TITLES[1:4] + SEED_TITLES[5:]:
        failures.append("examples said not run: %s" % not_run)
    report_dir = os.path.join(root, "validation")
    cube = blocks["Swinging cube"]
    if "](../validationQuick/swingingCube/convergence.png)" not in cube \
            and "not made" not in cube.lower():
        failures.append("swinging cube: neither the study's plot nor why not")
    errors = re.findall(r"^\| L2 error of (vx|Pxx), h = 1/(\d+) \| [^|]* \| "
                        r"([0-9.e+-]+) \|", cube, re.M)
    if len(errors) != 6:
        failures.append("swinging cube: %d L2 error rows with a number, "
                        "expected 6 (vx, Pxx on 4, 8, 16)" % len(errors))
    ring = blocks["Ring impact"]
    for name in RING_PICTURES:
        target = "../validationQuick/seedFigures/runs/ringImpact/" + name
        if "](%s)" % target not in ring and not re.search(
                r"\(%s\): not made: " % re.escape(name), ring):
            failures.append("ring: neither %s nor why it is not made" % name)
    rows = {r[0]: r for r in (
        [c.strip().replace("\\|", "|")
         for c in re.split(r"(?<!\\)\|", line)[1:-1]]
        for line in ring.splitlines() if line.startswith("| "))}
    try:
        py0 = float(rows["p_y(0) per metre [kg m/s]"][2])
        pyEnd = float(rows["p_y at the end / |p_y(0)|"][2])
    except (KeyError, ValueError, IndexError):
        failures.append("ring: rows without our numbers: %s" % rows)
        return
    if abs(py0 / -1.297 - 1) > 0.01 or not pyEnd > 0:
        failures.append("ring: p_y(0) %.4f per metre (-M v0 = -1.297), p_y "
                        "end %+.4f |p_y(0)|" % (py0, pyEnd))
    links = re.findall(r"!\[[^]]*\]\(([^)]+)\)", report)
    broken = [l for l in links
              if not os.path.isfile(os.path.join(report_dir, l))]
    if broken:
        failures.append("picture links to files not there: %s" % broken)
    shown = [n for n in RING_PICTURES if "ringImpact/%s)" % n in ring]
    lines.append("seed figures: 6 examples, %d L2 rows of the cube, ring "
                 "p_y(0) %.4f per metre, p_y end %+.4f, pictures shown %s; "
                 "%d links, none broken" % (len(errors), py0, pyEnd,
                                            shown, len(links)))


def without_paraview(root, work, failures, lines):
    """seedFigures.py, the ring alone, with pvbatch and xvfb-run hidden."""
    hidden = ("pvbatch", "xvfb-run")
    shadow = os.path.join(work, "shadowBin")
    path = []
    for folder in os.environ["PATH"].split(os.pathsep):
        if not any(os.path.exists(os.path.join(folder, h)) for h in hidden):
            path.append(folder)
            continue
        mirror = os.path.join(shadow, str(len(path)))
        os.makedirs(mirror)
        for entry in os.listdir(folder):
            if entry not in hidden:
                os.symlink(os.path.join(folder, entry),
                           os.path.join(mirror, entry))
        path.append(mirror)
    env = dict(os.environ, PATH=os.pathsep.join(path))
    study = os.path.join(root, "validationQuick", "seedFigures")
    proc = subprocess.run(
        ["/usr/bin/python3", "seedFigures.py", "--quick", "--only",
         "ringImpact"], cwd=study, env=env, stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT, universal_newlines=True, timeout=600)
    with open(os.path.join(work, "log.withoutParaView"), "w") as f:
        f.write(proc.stdout)
    with open(os.path.join(study, "section.md")) as f:
        text = f.read()
    said = re.findall(r"\(pressure_180ms\.png\): not made: ParaView", text)
    if "ringImpact/pressure_180ms.png)" in text or not said \
            or "ParaView (pictures): **not installed**" not in text:
        failures.append("without pvbatch the ring's section does not say "
                        "plainly that its picture was not made")
    else:
        lines.append("without pvbatch: 'not made: ParaView ...', no link")


def make_tree(root):
    """The copy of the project: links, and validation/ with the studies."""
    os.makedirs(root)
    for entry in os.listdir(TOP):
        if entry in ("validation", "validationQuick", "test", ".git"):
            continue
        os.symlink(os.path.join(TOP, entry), os.path.join(root, entry))
    os.makedirs(os.path.join(root, "validation"))
    shutil.copy2(os.path.join(TOP, "validation", "Allrun"),
                 os.path.join(root, "validation", "Allrun"))
    shutil.copytree(os.path.join(TOP, "validation", "swingingCube"),
                    os.path.join(root, "validation", "swingingCube"),
                    ignore=shutil.ignore_patterns("runs", "checks.json"))
    shutil.copytree(os.path.join(TOP, "validation", "seedFigures"),
                    os.path.join(root, "validation", "seedFigures"),
                    ignore=shutil.ignore_patterns("runs", "checks.json",
                                                  "section.md"))
    with open(os.path.join(root, "validation", "seedFigures", "Allrun"),
              "w") as f:
        f.write(SEED_ALLRUN)
    for study, script in (("plantedFail", PLANTED_FAIL),
                          ("plantedNone", "#!/bin/sh\nexit 0\n")):
        folder = os.path.join(root, "validation", study)
        os.makedirs(folder)
        with open(os.path.join(folder, "Allrun"), "w") as f:
            f.write(script)
        os.chmod(os.path.join(folder, "Allrun"), 0o755)


def section(text, title):
    """The table rows (split cells) of the section '## title'."""
    part = text.split("## %s\n" % title, 1)[1].split("\n## ", 1)[0]
    return [[c.strip() for c in re.split(r"(?<!\\)\|", line)[1:-1]]
            for line in part.splitlines()
            if line.startswith("|") and not line.startswith("|---")][1:]


def body():
    work = testing.work_dir(NAME)
    root = os.path.join(work, "project")
    make_tree(root)
    proc = subprocess.run(
        ["bash", os.path.join(root, "validation", "Allrun"), "-quick",
         "swingingCube", "plantedFail", "plantedNone", "seedFigures"],
        cwd=root, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
        universal_newlines=True, timeout=600)
    with open(os.path.join(work, "log.Allrun"), "w") as f:
        f.write(proc.stdout)
    lines, failures = [], []
    if proc.returncode != 1:
        failures.append("validation/Allrun exit status %d, expected 1 (a "
                        "planted failure)" % proc.returncode)
    with open(os.path.join(root, "validation", "README.md")) as f:
        report = f.read()
    top = report.split("\n## ", 1)[0]
    head = re.search(r"\*\*Quick run\*\*.*?(\d{4}-\d\d-\d\d) .*?commit "
                     r"(\w+).*?total run time (\d+) s", top, re.S)
    if not head:
        failures.append("the report's top does not say quick run, date, "
                        "commit and total run time: %r" % top[:400])
    for study in ("swingingCube", "plantedFail", "plantedNone",
                  "seedFigures"):
        if "](../validationQuick/%s)" % study not in report:
            failures.append("no link to ../validationQuick/%s" % study)
    rows = section(report, "Checks")
    recorded = {}
    for study in ("swingingCube", "plantedFail", "seedFigures"):
        path = os.path.join(root, "validationQuick", study, "checks.json")
        with open(path) as f:
            recorded[study] = json.load(f)
    expected = sum(len(c) for c in recorded.values()) + 1
    if len(rows) != expected:
        failures.append("%d check rows, expected %d" % (len(rows), expected))
    verdicts = [r[4] for r in rows]
    bad = [v for v in verdicts if v not in ("pass", "**FAIL**")]
    if bad or not rows:
        failures.append("rows without pass/fail: %s" % bad)
    fails = [(r[0], r[1]) for r in rows if r[4] == "**FAIL**"]
    first = [(r[0], r[1]) for r in rows[:len(fails)]]
    if first != fails:
        failures.append("FAIL rows not first: %s" % verdicts)
    if ("plantedFail", "planted failing check") not in fails:
        failures.append("the planted failing check is not a FAIL row")
    if not any(s == "plantedNone" and "no check" in q for s, q in fails):
        failures.append("no FAIL row for the study without checks")
    cube = [r for r in rows if r[0] == "swingingCube"]
    if len(cube) != len(recorded["swingingCube"]) or len(cube) < 2 or any(
            r[4] != "pass" for r in cube):
        failures.append("swingingCube rows %s, expected %d passing"
                        % (cube, len(recorded["swingingCube"])))
    lines.append("%d check rows (%d FAIL, planted), swingingCube %s"
                 % (len(rows), len(fails), ", ".join(
                     "%s %s" % (r[1].split(":")[0], r[2]) for r in cube)))
    studies = {r[0].split("]")[0].lstrip("["): r for r in
               section(report, "Studies")}
    for study in ("plantedFail", "plantedNone"):
        if not studies.get(study, [""] * 3)[2].startswith("FAIL"):
            failures.append("%s's verdict is not FAIL: %s"
                            % (study, studies.get(study)))
    times = [int(studies[s][4]) for s in ("swingingCube", "plantedFail",
                                          "plantedNone", "seedFigures")
             if s in studies]
    total = studies.get("total")
    if len(times) != 4 or not total or int(total[4]) < sum(times):
        failures.append("run times %s, total %s" % (times, total))
    else:
        lines.append("run times %s s, total %s s" % (times, total[4]))
    if head and total and head.group(3) != total[4]:
        failures.append("total run time at the top %s s, in the table %s s"
                        % (head.group(3), total[4]))
    elif head:
        lines.append("top: quick run, %s, commit %s, %s s"
                     % head.group(1, 2, 3))
    seed_section(report, root, failures, lines)
    without_paraview(root, work, failures, lines)
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
