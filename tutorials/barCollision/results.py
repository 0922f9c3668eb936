#!/usr/bin/python3
"""The bar collision's headline numbers beside their closed forms.

    ./results.py            (in a finished case)

1D elastic waves: contact stress Z1 Z2 v/(Z1 + Z2) (Z v for two
equal bars at +-v), contact time 2 L1/c, the bars' momenta afterwards.
"""

import os
import sys

sys.path.insert(0, os.path.join(os.environ.get("TOUCH_PROJECT_DIR", ""),
                                "bin", "python"))

try:
    import numpy  # noqa: F401
except ImportError:
    print("results skipped: numpy is not installed (python3-numpy)")
    sys.exit(0)

from touchfoam.contact import analyse  # noqa: E402

r = analyse(".")
print("barCollision, variant %s" % r["variant"])
if "contactStress" in r:
    print("  contact stress on the plateau  %.6g Pa  (closed form %.6g,"
          " max deviation %.3g %%)" % (r["plateauMean"], r["contactStress"],
                                        100 * r["plateauError"]))
    print("  release (no face in contact)   %.6g s   (2 L1/c = %.6g, step"
          " %.3g)" % (r["contactTime"], r["contactTimeExact"], r["step"]))
    print("  contact stress below half      %.6g s" % r["unloadTime"])
    print("  bar momenta at the end / initial bar1's: bar1 %.5f, bar2 %.5f"
          % (r["bar1End"], r["bar2End"]))
    print("  largest penetration %.3g m, most tensile contact traction"
          " %.3g Pa" % (r["maxPenetration"], r["mostTensile"]))
    print("  total momentum drift %.2e |p0|" % r["momentumDrift"])
print("  largest energy growth in a step %.2e E0, energy at the end %.6f E0"
      % (r["energyGrowth"], r["energyEnd"]))
