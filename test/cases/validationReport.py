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

Runs 'validation/Allrun -quick swingingCube plantedFail plantedNone' there
and asserts: its exit status is 1; validation/README.md says at its top
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
and a total row whose time is at least the sum of the studies'.  About a
minute (the swinging cube on 4^3, 8^3, 16^3 cells).
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
         "swingingCube", "plantedFail", "plantedNone"],
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
    for study in ("swingingCube", "plantedFail", "plantedNone"):
        if "](../validationQuick/%s)" % study not in report:
            failures.append("no link to ../validationQuick/%s" % study)
    rows = section(report, "Checks")
    recorded = {}
    for study in ("swingingCube", "plantedFail"):
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
                                          "plantedNone") if s in studies]
    total = studies.get("total")
    if len(times) != 3 or not total or int(total[4]) < sum(times):
        failures.append("run times %s, total %s" % (times, total))
    else:
        lines.append("run times %s s, total %s s" % (times, total[4]))
    if head and total and head.group(3) != total[4]:
        failures.append("total run time at the top %s s, in the table %s s"
                        % (head.group(3), total[4]))
    elif head:
        lines.append("top: quick run, %s, commit %s, %s s"
                     % head.group(1, 2, 3))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
