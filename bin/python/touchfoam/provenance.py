"""Where a validation result comes from: the build and the run's cost."""

import os
import subprocess
import time

from . import run

def log_steps_and_clock(case):
    """(number of steps, touchFoam ClockTime [s]) from log.touchFoam."""
    steps, clock = 0, None
    with open(os.path.join(case, "log.touchFoam"), errors="replace") as f:
        for line in f:
            if line.startswith("Time = "):
                steps += 1
            elif line.startswith("ExecutionTime"):
                clock = float(line.split("ClockTime =")[1].split()[0])
    return steps, clock

def build_label():
    """'<HEAD> (libTOUCH.so of <date>)': the commit checked out and when the
    library was built."""
    head = subprocess.run(["git", "rev-parse", "--short", "HEAD"],
                          cwd=run.project_dir(), capture_output=True,
                          text=True).stdout.strip() or "unknown"
    for root, _, names in os.walk(os.path.join(run.project_dir(),
                                               "platforms")):
        if "libTOUCH.so" in names:
            stamp = os.path.getmtime(os.path.join(root, "libTOUCH.so"))
            return "%s (libTOUCH.so of %s)" % (head, time.strftime(
                "%Y-%m-%d %H:%M", time.localtime(stamp)))
    return head
