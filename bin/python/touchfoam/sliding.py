"""A block sliding on a rigid wall with Coulomb friction under gravity.

The closed form of a rigid block launched at v0 along the wall: it
decelerates at muKinetic g, stops after t_s = v0/(mu g) having slid
v0^2/(2 mu g), and stays at rest (Coulomb's law for a rigid body).  A deformable
block does so on average once its waves settle.
"""

import numpy as np

from .foamfile import read_dict
from .monitor import read_monitor


def _vector(text):
    return np.array([float(x) for x in str(text).strip().strip("()").split()])


def case_data(case, patch="bottom"):
    """v0 (internal U, uniform), |g|, muKinetic and muStatic of a case."""
    U = read_dict("%s/0/U" % case)
    v0 = _vector(str(U["internalField"]).replace("uniform", ""))
    friction = U["boundaryField"][patch]["friction"]
    g = _vector(read_dict("%s/constant/g" % case)["value"])
    return v0, float(np.linalg.norm(g)), float(friction["muKinetic"]), \
        float(friction["muStatic"])


def slide(case, mass, v0, mu, g, rest=1e-3, settle=0.02):
    """The measured slide against the closed form.

    Velocities are the monitor's momenta over the mass; the distance is
    their integral (trapezoids over the steps, from v0 at t = 0).  The
    stop is the first time the speed falls below rest v0; at rest is the
    largest speed settle seconds after it.
    """
    mon = read_monitor(case)
    t = np.concatenate([[0.0], mon["Time"]])
    v = np.vstack([v0, mon["p"] / mass])
    speed0 = float(np.linalg.norm(v0))
    along = v @ (v0 / speed0)
    speed = np.linalg.norm(v, axis=1)
    below = np.nonzero(speed < rest * speed0)[0]
    out = {"t": t, "v": v,
           "distance": float(np.sum(0.5 * (along[1:] + along[:-1])
                                    * np.diff(t))),
           "distance_ref": speed0 ** 2 / (2 * mu * g),
           "deceleration_ref": mu * g,
           "t_stop": None, "deceleration": None, "rest_speed": None}
    if len(below):
        ts = float(t[below[0]])
        out["t_stop"] = ts
        out["deceleration"] = speed0 / ts
        late = t > ts + settle
        if np.any(late):
            out["rest_speed"] = float(np.max(speed[late]))
    return out
