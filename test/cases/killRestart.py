#!/usr/bin/python3
"""A run killed (SIGKILL) at random moments, some of them while it writes,
restarts each time with startFrom latestTime and ends exactly where the
uninterrupted run ends.

    /usr/bin/python3 test/cases/killRestart.py [--kills 10] [--seed 31]

The swinging cube at 8 x 8 x 8 cells (its tutorial's settings:
neoHookean, writePrecision 12), written at every step (writeControl
timeStep, writeInterval 1), so that a good share of the run's wall time
is spent writing, to 100 ms (144 steps):
  reference  the run uninterrupted;
  killed     the same set-up, started --kills times and killed with
             SIGKILL each time, then run to the end.  Kills alternate
             between a random moment (uniform in 0.3 .. 1.5 s after the
             start, random.Random(seed)) and a moment while a time folder
             is being written (the first new time folder seen without its
             U, which touchFoam writes last, polled every 0.2 ms after a
             random wait).
Asserted:
  - no kill leaves a folder that stops the restart: every restart and the
    final run exit with status 0 (a restart that finds its latest folder
    cut short warns, moves it to <time>.incomplete and starts from the
    previous one);
  - at least one kill cut a folder short (a warning 'is incomplete' in
    the next restart's log), so the write path is exercised;
  - every time folder of the reference exists in the killed run's case
    and its files lm, F, D, pointD and U are byte-identical to the
    reference's (the state at 17 digits, U at 12: equal bytes, equal
    doubles of the state), including the last (100 ms), and the killed
    run's case has no later time folder (it ended where the reference
    did).  A kill after a
    folder's state and before its U leaves a folder that is complete for
    a restart; the restart writes its U (and the other fields for
    viewing) from the state read: that U may differ from the reference's
    only by the sign of zeros ('-0' written by the run on a symmetric
    plane, '0' after the restart).
Reported: the kill moments, the times each restart started from, the
folders set aside.  Work folders: test/runs/killRestart/.
"""

import argparse
import os
import random
import re
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, run, testing  # noqa: E402

NAME = "killRestart"
FILES = ("lm", "F", "gradD", "D", "pointD", "U")
CONTROL = {"endTime": 0.1, "writeControl": "timeStep", "writeInterval": 1,
           "writePrecision": 12}
TIME = re.compile(r"^[0-9][0-9.e+-]*$")
NEG_ZERO = re.compile(rb"(?<![0-9.eE])-0(?![0-9.eE])")


def times(case):
    return sorted((d for d in os.listdir(case)
                   if TIME.match(d) and d != "0"), key=float)


def prepare(root, label):
    return cases.prepare("swingingCube", os.path.join(root, label), n=8,
                         control=CONTROL)


def wait_for_write(case, proc, seen, deadline):
    """Poll until a time folder not in seen exists without its U (a write
    under way); True then, False if the run ended or the deadline passed"""
    while proc.poll() is None and time.time() < deadline:
        for name in os.listdir(case):
            if TIME.match(name) and name not in seen:
                if not os.path.exists(os.path.join(case, name, "U")):
                    return True
                seen.add(name)
        time.sleep(0.0002)
    return False


def body(kills, seed):
    root = testing.work_dir(NAME)
    failures, lines = [], []
    rng = random.Random(seed)

    reference = prepare(root, "reference")
    t0 = time.time()
    run.run(["touchFoam"], reference, timeout=testing.RUN_TIMEOUT)
    lines.append("reference %d folders in %.1f s"
                 % (len(times(reference)), time.time() - t0))

    case = prepare(root, "killed")
    moments, starts, cut = [], [], 0
    for k in range(kills + 1):
        log_path = os.path.join(case, "log.touchFoam.%d" % k)
        with open(log_path, "w") as log:
            proc = subprocess.Popen(["touchFoam"], cwd=case, stdout=log,
                                    stderr=subprocess.STDOUT)
            if k < kills:
                wait = rng.uniform(0.3, 1.5)
                if k % 2:
                    # A kill while a time folder is written
                    time.sleep(rng.uniform(0.3, 0.8))
                    seen = set(os.listdir(case))
                    hit = wait_for_write(case, proc, seen, time.time() + 30)
                    moments.append("write" if hit else "end")
                else:
                    time.sleep(wait)
                    moments.append("%.2fs" % wait)
                if proc.poll() is None:
                    proc.send_signal(signal.SIGKILL)
            status = proc.wait(timeout=testing.RUN_TIMEOUT)
        with open(log_path) as f:
            text = f.read()
        found = re.search(r"Create time\s*\n", text)
        start = re.search(r"^Time = (\S+)", text, re.M)
        starts.append(start.group(1) if start else "-")
        if "is incomplete" in text:
            cut += 1
        if k < kills and status not in (0, -signal.SIGKILL):
            failures.append("run %d: status %d" % (k, status))
        if k == kills and status != 0:
            failures.append("the final run: status %d (%s)"
                            % (status, log_path))
        if not found and k == kills:
            failures.append("the final run did not start")
        if "FOAM FATAL" in text:
            failures.append("run %d stopped with a FatalError (%s)"
                            % (k, log_path))

    aside = sorted(d for d in os.listdir(case) if d.endswith(".incomplete"))
    if cut == 0:
        failures.append("no kill cut a time folder short (moments %s)"
                        % moments)

    compared, differ, rewritten = 0, [], []
    for name in times(reference):
        for field in FILES:
            a_path = os.path.join(reference, name, field)
            b_path = os.path.join(case, name, field)
            if not os.path.exists(b_path):
                differ.append("%s/%s missing" % (name, field))
                continue
            with open(a_path, "rb") as f:
                a = f.read()
            with open(b_path, "rb") as f:
                b = f.read()
            compared += 1
            if a != b and field == "U" and \
                    NEG_ZERO.sub(b"0", a) == NEG_ZERO.sub(b"0", b):
                # Written again by the restart from its state (the kill
                # came after the state, before U): equal but for the sign
                # of zeros on the symmetric planes (-0 in the run, 0 read
                # back), which compare equal as doubles
                rewritten.append(name)
            elif a != b:
                differ.append("%s/%s" % (name, field))
    if differ:
        failures.append("%d of the reference's files differ or are missing "
                        "in the killed run: %s" % (len(differ),
                                                   " ".join(differ[:8])))
    last = times(reference)[-1]
    if times(case)[-1] != last:
        failures.append("the killed run ended at %s, the reference at %s"
                        % (times(case)[-1], last))
    lines.append("%d kills (%s), first steps of the runs to %s; %d folders cut short "
                 "and set aside (%s); %d files of %d folders byte-identical "
                 "to the uninterrupted run's (U of %s written again by the "
                 "restart, equal but for the sign of zeros), the last %s"
                 % (kills, " ".join(moments), " ".join(starts[1:]), cut,
                    " ".join(aside), compared - len(differ) - len(rewritten),
                    len(times(reference)), " ".join(rewritten) or "none",
                    last))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--kills", type=int, default=10)
    parser.add_argument("--seed", type=int, default=31)
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args.kills, args.seed)))
