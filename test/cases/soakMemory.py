#!/usr/bin/python3
"""A long run with many writes keeps its resident memory flat.

    /usr/bin/python3 test/cases/soakMemory.py [--steps 20000] [--n 4]
        [--write-every 100]

The swinging cube at n^3 cells (its tutorial: neoHookean, the solidMonitor
function object every step) run for --steps steps (maxSteps), written
every --write-every steps (writeControl timeStep) with purgeWrite 5, so
that the test writes a few hundred time folders and removes most of them
again.  The resident set size of touchFoam (VmRSS of /proc/<pid>/status)
is sampled every 0.1 s (the trace: test/runs/soakMemory/rss.dat):
  start  the first sample after a tenth of the run's wall time (the
         start-up, the first writes and the first progress line allocate
         once: 56.4 MB after the second write, 56.5 MB from step 1500 on at
         --n 4);
  end    the last sample before the run ends.
Asserted: the run ends with status 0 after the steps asked for, at least
20 samples were taken, and the anonymous part of the resident set
(RssAnon: heap, stack, the fields) grows by (end - start)/start < 1 %.
VmRSS, which adds the resident pages of the mapped files (the libraries),
and its peak VmHWM are reported: on the shared machine the file pages
come and go with the other processes' load (measured: VmRSS +2.4 % over
10^5 steps while touchFoam was rebuilt beside it, +0.00 % in a quieter
run: validation/reliability/FINDINGS.md).  validation/reliability/FINDINGS.md records the same
script at 10^5 steps.  Work folders: test/runs/soakMemory/.
"""

import argparse
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, testing  # noqa: E402

NAME = "soakMemory"
LIMIT = 0.01
TIME = re.compile(r"^[0-9][0-9.e+-]*$")


def status_kb(pid, key):
    try:
        with open("/proc/%d/status" % pid) as f:
            for line in f:
                if line.startswith(key + ":"):
                    return int(line.split()[1])
    except OSError:
        pass
    return None


def body(steps, n, every):
    root = testing.work_dir(NAME)
    failures, lines = [], []
    case = cases.prepare("swingingCube", os.path.join(root, "soak"), n=n,
                         control={"maxSteps": steps, "endTime": 1e6,
                                  "writeControl": "timeStep",
                                  "writeInterval": every, "purgeWrite": 5,
                                  "writePrecision": 12})
    log_path = os.path.join(case, "log.touchFoam")
    samples, first, peak = [], None, None
    t0 = time.time()
    with open(log_path, "w") as log:
        proc = subprocess.Popen(["touchFoam"], cwd=case, stdout=log,
                                stderr=subprocess.STDOUT)
        written = 0
        while proc.poll() is None:
            rss = status_kb(proc.pid, "VmRSS")
            anon = status_kb(proc.pid, "RssAnon")
            hwm = status_kb(proc.pid, "VmHWM")
            if rss is not None and anon is not None:
                if first is None:
                    written = sum(1 for d in os.listdir(case)
                                  if TIME.match(d) and d != "0")
                    if written >= 2:
                        first = rss
                else:
                    samples.append((time.time() - t0, rss, anon))
                peak = hwm or peak
            if time.time() - t0 > testing.RUN_TIMEOUT:
                proc.kill()
                failures.append("the run took over %d s" % testing.RUN_TIMEOUT)
                break
            time.sleep(0.1)
        status = proc.wait()
    with open(log_path) as f:
        text = f.read()
    done = re.search(r"Reached maxSteps (\d+)", text)
    if status != 0 or not done or int(done.group(1)) != steps:
        failures.append("status %d, maxSteps reached: %s"
                        % (status, done.group(1) if done else None))
    if first is None or len(samples) < 20:
        failures.append("%d RSS samples after the second write (too short a "
                        "run to measure)" % len(samples))
        return testing.verdict(lines, failures)
    with open(os.path.join(root, "rss.dat"), "w") as f:
        f.write("# wall time [s], VmRSS and RssAnon [kB] of touchFoam\n")
        f.writelines("%.2f %d %d\n" % sample for sample in samples)
    duration = samples[-1][0]
    start = next(s for s in samples if s[0] >= 0.1*duration)
    end = samples[-1]
    growth = (end[1] - start[1])/start[1]
    growth_anon = (end[2] - start[2])/start[2]
    if not growth_anon < LIMIT:
        failures.append("the anonymous resident memory grew by %.2f %% "
                        "(limit %g %%)" % (100*growth_anon, 100*LIMIT))
    rss = [s[1] for s in samples]
    lines.append("%d steps of %d cells, written every %d (purgeWrite 5) in "
                 "%.0f s: RssAnon %d kB at a tenth of the run, %d kB at the "
                 "end (%+.2f %%); VmRSS %d kB after the second write, %d kB "
                 "at a tenth, %d kB at the end (%+.2f %%), min %d max %d of "
                 "%d samples, peak (VmHWM) %s kB"
                 % (steps, n**3, every, time.time() - t0, start[2], end[2],
                    100*growth_anon, first, start[1], end[1], 100*growth,
                    min(rss), max(rss), len(samples), peak))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=20000)
    parser.add_argument("--n", type=int, default=4)
    parser.add_argument("--write-every", type=int, default=100)
    args = parser.parse_args()
    sys.exit(testing.run_test(NAME, lambda: body(args.steps, args.n,
                                                 args.write_every)))
