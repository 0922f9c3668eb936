"""Small frame for the case-level tests in test/cases.

Each test script is a function returning a one-line summary, or raising
(AssertionError, RunError, ...) with the reason; run_test() prints exactly
one line 'PASS name: ...' or 'FAIL name: ...' and returns the exit status.
Work folders go to test/runs/<name>/ (ignored by git) and are kept for
inspection.
"""

import os
import shutil
import sys
import traceback

import numpy as np

from . import foamfile
from .run import RunError, check_openfoam, have_solver, project_dir

#: seconds after which a solver run of a test is stopped (the tests are
#: sized to take well under two minutes; a run that ignores 'maxSteps'
#: would otherwise go on to endTime)
RUN_TIMEOUT = 600


def work_dir(name):
    """A fresh test/runs/<name> folder."""
    d = os.path.join(project_dir(), "test", "runs", name)
    if os.path.exists(d):
        shutil.rmtree(d)
    os.makedirs(d)
    return d


def require_solver():
    if not have_solver():
        raise RunError("touchFoam not found in the PATH "
                       "(build it with ./Allwmake, source etc/bashrc)")


def run_test(name, body, needs_solver=True):
    try:
        check_openfoam()
        if needs_solver:
            require_solver()
        summary = body()
    except Exception as err:
        # The reason on the one result line; the traceback for debugging
        reason = " ".join(str(err).split("\n")[:1]) or type(err).__name__
        print("FAIL %s: %s" % (name, reason))
        traceback.print_exc(file=sys.stderr)
        return 1
    print("PASS %s: %s" % (name, summary))
    return 0


def verdict(lines, failures):
    """The one-line summary of a test's measurements ('; '-joined lines);
    raises AssertionError naming the failures first when there are any."""
    summary = "; ".join(lines)
    if failures:
        raise AssertionError("; ".join(failures) + " | " + summary)
    return summary


def relative_max_difference(a, b, floor=1e-300):
    """max|a - b| / max|b|, with the denominator at least floor."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    return np.abs(a - b).max() / max(np.abs(b).max(), floor)


def without_pictures():
    """Environment entries for a tutorial's Allrun run by a test: bin/python
    off PYTHONPATH, so that its pictures and plots (minutes of pvbatch on a
    loaded machine) are skipped; its tutorialResults finds the package by
    its own path."""
    kept = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep)
            if p and not p.rstrip("/").endswith(os.path.join("bin",
                                                             "python"))]
    return {"PYTHONPATH": os.pathsep.join(kept)}


def read_internal(case_time_dir, field, n):
    return foamfile.read_field(os.path.join(case_time_dir, field)).internal(n)
