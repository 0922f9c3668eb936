#!/usr/bin/python3
"""The start-up warning names the measured stable CFL number.

    /usr/bin/python3 test/cases/stabilityWarning.py

touchFoam warns at start-up when the CFL entry is above the largest CFL
number at which the chosen F update, time scheme and reconstruction were
measured stable (deformationUpdate::stableCFL; validation/stabilityMap
FINDINGS 9-11): for the compatible update RK3 1.0 and RK2 0.6 with linear
or firstOrder reconstruction (the twisting column), 0.3 with limitedLinear
and either scheme (the impacts: the Taylor bar gains energy above it, the
bar rebound inverts cells at RK3 1.0).  Runs tutorials/twistingColumn
(2 x 12 x 2, 3 steps) with each setting below and asserts that the warning
appears exactly when the CFL number is above the limit, and that it names
the limit (CFL above 1 is refused outright, badInput).
Work folders: test/runs/stabilityWarning/.
"""

import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

from touchfoam import cases, run, testing  # noqa: E402

NAME = "stabilityWarning"

#: (reconstruction, time scheme, CFL, the limit the warning must name or
#: None for no warning)
SETTINGS = [
    ("linear", "RK3", 1.0, None),
    ("linear", "RK2", 0.6, None),
    ("linear", "RK2", 0.7, 0.6),
    ("limitedLinear", "RK2", 0.3, None),
    ("limitedLinear", "RK2", 0.45, 0.3),
    ("limitedLinear", "RK3", 0.5, 0.3),
]

WARNING = re.compile(r"Entry 'CFL' = ([0-9.eE+-]+) in .* is above "
                     r"([0-9.eE+-]+), the largest CFL number")


def body():
    root = testing.work_dir(NAME)
    lines, failures = [], []
    for reconstruction, scheme, cfl, limit in SETTINGS:
        label = "%s-%s-CFL%g" % (reconstruction, scheme, cfl)
        case = cases.prepare(
            "twistingColumn", os.path.join(root, label), n=2,
            touch={"reconstruction": reconstruction, "timeScheme": scheme,
                   "CFL": cfl},
            control={"maxSteps": 3})
        run.run(["touchFoam"], case, timeout=testing.RUN_TIMEOUT)
        with open(os.path.join(case, "log.touchFoam")) as f:
            text = " ".join(f.read().split())
        found = WARNING.search(text)
        if limit is None:
            lines.append("%s: %s" % (label, "warned" if found else "quiet"))
            if found:
                failures.append("%s warned (limit %s)" % (label,
                                                          found.group(2)))
            continue
        named = float(found.group(2)) if found else None
        lines.append("%s: %s" % (label, "warned, limit %g" % named
                                 if found else "quiet"))
        if named is None:
            failures.append("%s did not warn (limit %g)" % (label, limit))
        elif abs(named - limit) > 1e-12:
            failures.append("%s named %g, not %g" % (label, named, limit))
    return testing.verdict(lines, failures)


if __name__ == "__main__":
    sys.exit(testing.run_test(NAME, body))
