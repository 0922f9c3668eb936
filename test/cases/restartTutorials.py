#!/usr/bin/python3
"""A restart from an impact tutorial's own output, at its own write
settings, continues exactly as the uninterrupted run.

    /usr/bin/python3 test/cases/restartTutorials.py

Three tutorials with a state beyond lm and F, at reduced meshes, with
their own system/controlDict (writeControl adjustableRunTime,
writePrecision 12, timePrecision 6, their writeInterval) but endTime:

  taylorImpact  -n 3 (240 cells), vonMisesPlastic: restart at 10 us from
                the plastic state (epsilonP, CpInv), to 20 us
  barRebound    -n 3 (240 cells), the rigid wall's contact state (the
                'contact' list of lm's wall patch): restart at 30 us, the
                end on the wall since 26.7 us, to 50 us
  ringImpact    -n 48 (96 cells), contact from 7 ms: restart at 15 ms,
                in contact, to 25 ms

Per tutorial:
  whole    the run to the end;
  restart  the run to the restart time (endTime there), then endTime set
           back and the run continued (startFrom latestTime, as in the
           tutorial).
Asserted: the restart folder holds the state that matters (taylorImpact:
epsilonP > 0 in some cell; barRebound and ringImpact: a wall face in
contact, 'contact' 1 in lm's wall patch); the continued run starts after
the restart time (its first step does); at the end, lm (with its wall
patch: the active set), F, D, pointD, U (and epsilonP, CpInv) are
byte-identical to the uninterrupted run's: the state is written with 17
digits whatever writePrecision says, so the restart starts from the same
doubles, and touchFoam lands the steps on the write times counting them
from t = 0.  OpenFOAM's adjustableRunTime (Time::adjustDeltaT) counts the
time to the next write from the run's own start time, so that the steps
shortened to land on a write time differed in the last bit after a
restart: before touchFoam took over that adjustment (measured at commit
5cbca13 with this test) barRebound's lm at 50 us differed by 2.6e-15 of
its maximum and ringImpact's, in contact, by 2.8e-12 at 25 ms; the
taylorImpact happened to stay bitwise.  A field that differs is reported
with max|restart - whole|/max|whole| (internal values).
Work folders: test/runs/restartTutorials/.
"""

import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, foamfile, run, testing  # noqa: E402

NAME = "restartTutorials"
#: tutorial, -n, restart time, end time, extra state files
CASES = (("taylorImpact", 3, "1e-05", "2e-05", ("epsilonP", "CpInv")),
         ("barRebound", 3, "3e-05", "5e-05", ()),
         ("ringImpact", 48, "0.015", "0.025", ()))
FILES = ("lm", "F", "D", "pointD", "U")


def set_end(case, end):
    run.foam_set(case, "system/controlDict", "endTime", end)


def in_contact(lm_path):
    """Whether some face of a rigidWall patch of lm is in contact"""
    patches = foamfile.FoamField(lm_path).boundary_patches()
    for text in patches.values():
        if "rigidWall" not in text:
            continue
        m = re.search(r"\bcontact\s+(uniform\s+1\b|nonuniform[^(]*"
                      r"\(([^)]*)\))", text)
        if m and (m.group(2) is None or "1" in m.group(2).split()):
            return True
    return False


def body():
    root = testing.work_dir(NAME)
    failures, lines = [], []
    for tutorial, n, mid, end, extra in CASES:
        whole = cases.prepare(tutorial, os.path.join(root, tutorial + "-whole"),
                              n=n, control={"endTime": end})
        run.run(["touchFoam"], whole, timeout=testing.RUN_TIMEOUT)
        part = cases.prepare(tutorial,
                             os.path.join(root, tutorial + "-restart"), n=n,
                             control={"endTime": mid})
        run.run(["touchFoam"], part, timeout=testing.RUN_TIMEOUT)
        restart = os.path.join(part, mid)
        if not os.path.isdir(restart):
            failures.append("%s: no folder %s to restart from"
                            % (tutorial, mid))
            continue
        if extra:
            eps = foamfile.read_field(os.path.join(restart, "epsilonP")) \
                .internal()
            state = "max epsilonP %.3g" % max(eps)
            if not max(eps) > 0:
                failures.append("%s: no plastic strain at %s" % (tutorial, mid))
        else:
            state = "wall in contact"
            if not in_contact(os.path.join(restart, "lm")):
                state = "no wall face in contact"
                failures.append("%s: no wall face in contact at %s"
                                % (tutorial, mid))
        set_end(part, end)
        log = run.run(["touchFoam"], part, name="touchFoam-restart",
                      timeout=testing.RUN_TIMEOUT)
        with open(log) as f:
            first = re.search(r"^Time = (\S+)", f.read(), re.M)
        if not first or not float(first.group(1)) > float(mid):
            failures.append("%s: the continued run did not start after %s "
                            "(first step to %s)" % (
                                tutorial, mid,
                                first.group(1) if first else None))
        same, differ = [], []
        last = run.latest_time_dir(whole)
        name = os.path.basename(last)
        for field in FILES + extra:
            a_path = os.path.join(last, field)
            b_path = os.path.join(part, name, field)
            if not os.path.exists(b_path):
                differ.append(field + " missing")
                continue
            with open(a_path, "rb") as f:
                a = f.read()
            with open(b_path, "rb") as f:
                b = f.read()
            if a == b:
                same.append(field)
                continue
            diff = testing.relative_max_difference(
                foamfile.read_field(b_path).internal(),
                foamfile.read_field(a_path).internal())
            differ.append("%s %.1e" % (field, diff))
        if differ:
            failures.append("%s: at %s after the restart at %s: %s differ"
                            % (tutorial, name, mid, " ".join(differ)))
        lines.append("%s: restart at %s (%s), at %s byte-identical %s"
                     % (tutorial, mid, state, name, " ".join(same) or "none"))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
