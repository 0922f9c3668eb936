#!/usr/bin/python3
"""A law's state is rolled back by a failed step and read back on restart,
bit for bit.

    /usr/bin/python3 test/cases/lawStateRestart.py [--steps 10] [--fail-step 6]

Runs tutorials/spinningCube (4^3 cells, free flight: the cube turns and
stretches, so |F - I| grows) with the test law historyElastic of
applications/test/stateLaw (libTOUCHtestLaws): its state maxStretch, the
largest |F - I| a cell has seen, is a field of the time folders and
softens the stress.  Output with 17 digits, so equal numbers are equal
doubles.  With N = --steps and K = --fail-step:

  C  2N steps straight, every step written: the reference;
  A  failAfter between the times of steps K-1 and K: the stress of step K
     is NaN, so touchFoam must stop (non-zero exit) after writing step K-1
     and nothing later (run with FOAM_SIGFPE=false: with the trap on, the
     NaN kills touchFoam with SIGFPE before its validity check);
  B  K-1 steps without failAfter;
  D  N steps, then N more from D's written time (startFrom latestTime);
  D0 as D, with maxStretch deleted from the restart folder (a control).

Asserted:
  failed step  maxStretch, lm and F of A at step K-1 equal B's (and C's),
               maxStretch is nonzero there (the state evolved), and it
               differs both from C's at step K and from max(s, |F - I|),
               the state stage 1 of the failed step reached (so a leak of
               the failed step would be seen);
  restart      maxStretch, lm and F of D at step 2N equal C's, maxStretch
               is nonzero at step N, and D0 ends elsewhere (so the state
               read on restart matters).
The maximum differences are reported.  Work folders:
test/runs/lawStateRestart/.
"""

import argparse
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import cases, foamfile, run, testing  # noqa: E402

NAME = "lawStateRestart"
FIELDS = ("maxStretch", "lm", "F")
LIBS = '("libTOUCH.so" "libTOUCHtestLaws.so")'


def prepare(root, n):
    """Meshed and initialised spinning cube with the test law."""
    control = cases.precise_output()
    control.update({"libs": LIBS, "endTime": 100, "writeControl": "timeStep",
                    "writeInterval": 1000, "startFrom": "latestTime"})
    case = cases.prepare("spinningCube", os.path.join(root, "base"), n=n,
                         control=control)
    run.foam_set(case, "constant/mechanicalProperties", "model",
                 "historyElastic")
    return case


def variant(base, root, label, maxSteps, writeInterval=1000, failAfter=None):
    """A copy of the base case with its own step count and output."""
    case = os.path.join(root, label)
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(base, case)
    run.foam_set(case, "system/controlDict", "maxSteps", maxSteps)
    run.foam_set(case, "system/controlDict", "writeInterval", writeInterval)
    if failAfter is not None:
        run.foam_set(case, "constant/mechanicalProperties", "failAfter",
                     repr(failAfter))
    return case


def solve(case, name="touchFoam"):
    run.run(["touchFoam"], case, name, timeout=testing.RUN_TIMEOUT)


def written(case):
    """Names of the time folders after 0, in time order."""
    times = run.time_dirs(case)
    return [times[t] for t in sorted(times) if t > 0]


def state(case, time):
    """{field: internal values} at time folder 'time' of case."""
    folder = os.path.join(case, time)
    lm = foamfile.read_field(os.path.join(folder, "lm")).internal()
    out = {"lm": np.asarray(lm, float)}
    for field in ("F", "maxStretch"):
        path = os.path.join(folder, field)
        if not os.path.exists(path):
            raise AssertionError("%s has no %s" % (folder, field))
        out[field] = np.asarray(
            foamfile.read_field(path).internal(len(lm)), float)
    return out


def same(a, b):
    """Equal doubles (bit for bit) and the largest difference."""
    equal = a.shape == b.shape and a.tobytes() == b.tobytes()
    diff = np.abs(a - b).max() if a.shape == b.shape else np.inf
    return equal, diff


def compare(label, a, b, problems, notes):
    """Record whether every field of states a and b is equal bit for bit."""
    for field in FIELDS:
        equal, diff = same(a[field], b[field])
        notes.append("%s %s %s" % (label, field,
                                   "equal" if equal else "%.1e" % diff))
        if not equal:
            problems.append("%s: %s differs by %.3e" % (label, field, diff))


def stretch(F):
    """|F - I| per cell (Frobenius norm)."""
    return np.sqrt(((F - np.eye(3).ravel()) ** 2).sum(axis=1))


def failed_step(base, root, ref, K, problems, notes):
    """Run A (failure at step K) and B (K-1 steps); check the rollback."""
    times = written(ref)
    t_good, t_fail = (float(times[K - 2]), float(times[K - 1]))
    a = variant(base, root, "A_failAfter", 10 * K,
                failAfter=0.5 * (t_good + t_fail))
    # Without FOAM_SIGFPE=false (etc/bashrc sets it true) the NaN stops
    # touchFoam with SIGFPE in the reconstruction's limiter before the
    # validity check sees it, and nothing is written.  Trapping changes no
    # arithmetic, so A stays comparable with B and C bit for bit.
    env = dict(os.environ, FOAM_SIGFPE="false", PWD=os.path.abspath(a))
    log = os.path.join(a, "log.touchFoam")
    with open(log, "w") as f:
        status = subprocess.call(["touchFoam"], cwd=a, stdout=f,
                                 stderr=subprocess.STDOUT, env=env,
                                 stdin=subprocess.DEVNULL,
                                 timeout=testing.RUN_TIMEOUT)
    with open(log, errors="replace") as f:
        text = f.read()
    if status == 0:
        raise AssertionError("A: touchFoam exited 0 although the stress of "
                             "step %d was NaN (see %s)" % (K, log))
    if "non-finite stress" not in text:
        raise AssertionError("A: the law's forced failure is not in %s "
                             "(exit %d)" % (log, status))
    if written(a) != [times[K - 2]]:
        raise AssertionError("A: wrote %s, expected only step %d's %s "
                             "(exit %d, see %s)"
                             % (written(a), K - 1, times[K - 2], status, log))

    b = variant(base, root, "B_goodSteps", K - 1)
    solve(b)
    if written(b) != [times[K - 2]]:
        raise AssertionError("B: wrote %s, expected %s"
                             % (written(b), times[K - 2]))

    sA = state(a, times[K - 2])
    compare("A=B", sA, state(b, times[K - 2]), problems, notes)
    compare("A=C", sA, state(ref, times[K - 2]), problems, notes)

    s = sA["maxStretch"]
    notes.append("max s(step %d) %.3e" % (K - 1, s.max()))
    if not s.max() > 0:
        problems.append("A: maxStretch is 0 in every cell at step %d "
                        "(the state never evolved: does the solver call "
                        "the law's hooks?)" % (K - 1))

    # A leak of the failed step: C's state one step on, or the state that
    # stage 1 of the failed step reached
    for label, leak in (("s(step %d)" % K, state(ref, times[K - 1])),
                        ("max(s, |F - I|)",
                         {"maxStretch": np.maximum(s, stretch(sA["F"]))})):
        diff = np.abs(leak["maxStretch"] - s).max()
        notes.append("A vs %s %.1e" % (label, diff))
        if not diff > 0:
            problems.append("A's maxStretch equals %s: a leak of the failed "
                            "step could not be seen" % label)


def restart(base, root, ref, N, problems, notes):
    """Run D (N + N steps, restarted) and the control D0; check D = C."""
    times = written(ref)
    d = variant(base, root, "D_restart", N)
    solve(d)
    if written(d) != [times[N - 1]]:
        raise AssertionError("D: wrote %s, expected %s"
                             % (written(d), times[N - 1]))
    sN = state(d, times[N - 1])["maxStretch"]
    notes.append("max s(step %d) %.3e" % (N, sN.max()))
    if not sN.max() > 0:
        problems.append("D: maxStretch is 0 in every cell at step %d, the "
                        "restart reads back nothing" % N)

    d0 = os.path.join(root, "D0_restartWithoutState")
    if os.path.exists(d0):
        shutil.rmtree(d0)
    shutil.copytree(d, d0)
    os.remove(os.path.join(d0, times[N - 1], "maxStretch"))

    solve(d, "touchFoam.restart")
    solve(d0, "touchFoam.restart")
    for case in (d, d0):
        if written(case)[-1] != times[2 * N - 1]:
            raise AssertionError("%s: the restart ended at %s, expected %s"
                                 % (case, written(case)[-1],
                                    times[2 * N - 1]))

    final = state(ref, times[2 * N - 1])
    compare("D=C", state(d, times[2 * N - 1]), final, problems, notes)
    equal, diff = same(state(d0, times[2 * N - 1])["maxStretch"],
                       final["maxStretch"])
    notes.append("D0 vs C maxStretch %.1e" % diff)
    if equal:
        problems.append("D0: a restart without maxStretch ends with C's "
                        "state, so the restart test cannot see a state "
                        "that is not read back")


def body(args):
    root = testing.work_dir(NAME)
    base = prepare(root, args.n)
    steps = max(2 * args.steps, args.fail_step)

    ref = variant(base, root, "C_straight", steps, writeInterval=1)
    solve(ref)
    if len(written(ref)) != steps:
        raise AssertionError("C: %d time folders for %d steps"
                             % (len(written(ref)), steps))

    problems, notes = [], []
    failed_step(base, root, ref, args.fail_step, problems, notes)
    restart(base, root, ref, args.steps, problems, notes)

    summary = ("%d^3 cells, failure at step %d, restart after %d of %d "
               "steps: %s" % (args.n, args.fail_step, args.steps,
                              2 * args.steps, "; ".join(notes)))
    if problems:
        raise AssertionError("; ".join(problems) + " (" + summary + ")")
    return summary


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-n", type=int, default=4)
    parser.add_argument("--steps", type=int, default=10)
    parser.add_argument("--fail-step", type=int, default=6)
    args = parser.parse_args()
    if args.fail_step < 2:
        parser.error("--fail-step must be at least 2")
    sys.exit(testing.run_test(NAME, lambda: body(args)))
