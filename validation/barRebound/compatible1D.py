#!/usr/bin/python3
"""A 1D model of touchFoam's compatible update for uniaxial.py's bounce.

    /usr/bin/python3 compatible1D.py [-n N ...] [--variant NAME ...]

The bar of uniaxial.py (L = c = Z = rho = 1, v0 = 1, contact at t = 0.5,
RK2, CFL 0.3) on N cells and N + 1 points, written from the operators of
src/TOUCH/deformationUpdates/compatible and linearPointInterpolation
restricted to a plane wave on N x 1 x 1 cubes between mirror planes:

- least-squares gradients (central inside, one-sided in the end cells),
  Barth-Jespersen per field, the faces of a condition (the wall, the free
  end) bounding by the cell's own extrapolation (linearReconstruction);
- points: v_a = mean of the cells' limited extrapolations (A v), the wall
  point held at 0 in contact, plus the point upwinding -m_a phi_a f_a,
  f_a = s_L - s_R the nodal force, m_a = 1/(2Z) inside and 3/(4Z) at an
  end (the point areas of calcPointMobility with the mirror faces'
  half shares), phi_a the share of f_a the reconstructed jump keeps;
- F from the point velocities; momentum: -A^T Pi^T f plus the face
  upwinding (Z/2) phi^2 [[v]] and, at the wall in contact, -Z phi^2 v_0;
- contact when the end point reaches the wall, released when the wall's
  force (reaction + damping) would pull.

Variants (--variant) are the experiments of FINDINGS.md.  Prints per run
E/E0 at t = 0.625, 1.5 (arrival), the separation and 3.0, the wall stress
over the middle 80 % of the contact and its ringing, and the precursor
(largest tension ahead of the compressive front at t = 1.0, / Z v0) and
overshoot (largest compression beyond Z v0 behind it).
"""
import argparse
import numpy as np


def bj(allowed_up, allowed_down, up, down, tol=1e-12):
    """Barth-Jespersen factor from the allowed and asked increments."""
    rup = np.where(up > tol, allowed_up / np.where(up > tol, up, 1), 1e30)
    rdn = np.where(down < -tol, allowed_down / np.where(down < -tol, down, -1),
                   1e30)
    return np.minimum(1.0, np.minimum(rup, rdn))


def gradient(q, h):
    """Unlimited least-squares gradient: central inside, one-sided ends."""
    g = np.empty_like(q)
    g[1:-1] = (q[2:] - q[:-2]) / (2 * h)
    g[0] = (q[1] - q[0]) / h
    g[-1] = (q[-1] - q[-2]) / h
    return g


def limiter(q, g, h, kind="bj"):
    """Per cell factor of the face increments +-g h/2 (condition faces at
    the ends bound by the cell's own extrapolation)."""
    n = len(q)
    big = np.maximum(q, np.maximum(np.r_[q[1:], -np.inf], np.r_[-np.inf, q[:-1]]))
    small = np.minimum(q, np.minimum(np.r_[q[1:], np.inf], np.r_[np.inf, q[:-1]]))
    inc = 0.5 * g * h
    # end cells: the condition face's value widens the bounds
    big[0] = max(big[0], q[0] - inc[0]); small[0] = min(small[0], q[0] - inc[0])
    big[-1] = max(big[-1], q[-1] + inc[-1]); small[-1] = min(small[-1], q[-1] + inc[-1])
    up = np.abs(inc).copy()
    dn = -np.abs(inc)
    # the ends' limited faces: only the interior one
    up[0] = max(inc[0], 0); dn[0] = min(inc[0], 0)
    up[-1] = max(-inc[-1], 0); dn[-1] = min(-inc[-1], 0)
    if kind == "none":
        return np.ones(n)
    return bj(big - q, small - q, up, dn)


def share(rec, cell):
    c = cell * cell
    return np.where(c > 1e-300, np.clip(rec * cell / np.where(c > 1e-300, c, 1), 0, 1), 0.0)


class Model:
    def __init__(self, N, variant="default", cfl=0.3, rk=2):
        self.N, self.h, self.variant = N, 1.0 / N, variant
        self.dt = cfl * self.h
        self.rk = rk
        self.gap = 0.5
        self.released = False
        self.contact = False
        m = np.full(N + 1, 0.5)
        m[0] = m[-1] = 0.75
        self.mob = m

    def rates(self, v, s, u0, decide):
        N, h = self.N, self.h
        gv_u, gs_u = gradient(v, h), gradient(s, h)
        var = self.variant
        phv = limiter(v, gv_u, h, "none" if var in ("linear",) else "bj")
        phs = limiter(s, gs_u, h, "none" if var in ("linear",) else "bj")
        gv, gs = phv * gv_u, phs * gs_u
        # the point map's gradients
        if var in ("pointLimiterOff",):
            gmap = gv_u
            fac = np.ones(N)
        else:
            gmap = gv
            fac = phv
        # reconstructed face values: face a between cell a-1 (L) and a (R)
        vL = v + 0.5 * h * gv; vR = v - 0.5 * h * gv   # at right / left face
        sL = s + 0.5 * h * gs; sR = s - 0.5 * h * gs
        # nodal forces f_a = s_L - s_R (outside: 0)
        f = np.zeros(N + 1)
        f[1:-1] = s[:-1] - s[1:]
        f[0] = -s[0]; f[-1] = s[-1]
        r = np.zeros(N + 1)
        r[1:-1] = sL[:-1] - sR[1:]
        r[-1] = sL[-1]
        r[0] = -sR[0]
        rate = np.zeros(N)
        # face upwinding (Z/2) phi^2 [[v]]
        jump = v[1:] - v[:-1]
        rj = vR[1:] - vL[:-1]
        phi = share(rj, jump)
        tC = 0.5 * phi ** 2 * jump
        rate[:-1] += tC; rate[1:] -= tC
        # contact
        if decide:
            if not self.released and u0 <= -self.gap + 1e-12:
                self.contact = True
        wall_force = 0.0
        if self.contact:
            dep = v[0]
            sh = share(np.array([vR[0]]), np.array([dep]))[0] ** 2
            damp = -sh * dep
            wall_force = f[0] + damp
            if decide and wall_force < 0:
                self.contact = False
                self.released = True
        if self.contact:
            rate[0] += damp
        # point velocities
        pv = np.zeros(N + 1)
        ext_r = v + 0.5 * h * gmap   # to the right point
        ext_l = v - 0.5 * h * gmap   # to the left point
        pv[1:-1] = 0.5 * (ext_r[:-1] + ext_l[1:])
        pv[0] = ext_l[0]; pv[-1] = ext_r[-1]
        fc = f.copy()
        if self.contact:
            pv[0] = 0.0
            fc[0] = 0.0
        phia = share(r, fc)
        pv -= self.mob * phia * fc
        if self.contact:
            pv[0] = 0.0
        srate = (pv[1:] - pv[:-1]) / h
        # -A^T f (f constrained)
        g = -fc
        n_a = np.full(N + 1, 2.0); n_a[0] = n_a[-1] = 1.0
        shr = g / n_a
        rate += shr[:-1] + shr[1:]
        H = fac * (shr[1:] * 0.5 * h - shr[:-1] * 0.5 * h)
        # gradient weights: interior cell e: +-1/(2h) to e+-1; ends 1/h
        w = np.full(N, 0.5 / h); w[0] = w[-1] = 1.0 / h
        q_right = H * w  # to the right neighbour (cells 0..N-2)
        q_left = -H * w  # to the left neighbour
        q_right[-1] = 0; q_left[0] = 0
        rate[1:] += q_right[:-1]; rate[:-1] -= q_right[:-1]
        rate[:-1] += q_left[1:]; rate[1:] -= q_left[1:]
        return rate / h, srate, pv[0], wall_force

    def energy(self, v, s):
        return 0.5 * self.h * np.sum(v * v + s * s)

    def run(self, T=3.0):
        N = self.N
        v = -np.ones(N); s = np.zeros(N); u0 = 0.0
        t = 0.0
        E0 = self.energy(v, s)
        rows = []
        prof = None
        while t < T - 1e-12:
            k = min(self.dt, T - t)
            a, b, w, wf = self.rates(v, s, u0, True)
            c0 = self.contact
            v1 = v + k * a; s1 = s + k * b; u1 = u0 + k * w
            a, b, w, _ = self.rates(v1, s1, u1, False)
            v = 0.5 * (v + v1 + k * a); s = 0.5 * (s + s1 + k * b)
            u0 = 0.5 * (u0 + u1 + k * w)
            t += k
            rows.append((t, self.energy(v, s) / E0, c0, wf))
            if prof is None and t >= 1.0 - 1e-12:
                prof = s.copy()
        rows = np.array(rows)
        return rows, prof


def measure(N, variant):
    m = Model(N, variant)
    rows, prof = m.run()
    t, E, c, wf = rows.T
    on = np.nonzero(c > 0)[0]
    first = on[0]
    off = np.nonzero((c == 0) & (np.arange(len(t)) > first))[0]
    sep = off[0] if len(off) else len(t) - 1
    t0, t1 = t[first], t[sep]
    mid = (t > t0 + 0.1 * (t1 - t0)) & (t < t1 - 0.1 * (t1 - t0))
    plateau = wf[mid].mean()
    ring = np.abs(wf[mid] - plateau).max()
    x = (np.arange(N) + 0.5) / N
    ahead = x > 0.5 + 3.0 / N
    behind = x < 0.5 - 3.0 / N
    pre = max(0.0, prof[ahead].max())
    over = max(0.0, -prof[behind].min() - 1.0)
    return dict(E0625=np.interp(0.625, t, E), Earr=np.interp(1.5, t, E),
                Esep=E[sep], Eend=E[-1], tsep=t[sep], wall=plateau,
                ring=ring, pre=pre, over=over,
                rise=max(0.0, np.diff(E).max()))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, nargs="+", default=[50])
    ap.add_argument("--variant", nargs="+", default=["default"])
    a = ap.parse_args()
    for var in a.variant:
        for N in a.n:
            r = measure(N, var)
            print("%-20s N %4d  E 0.625 %.4f arr %.4f sep %.4f end %.4f "
                  "t_sep %.3f wall %.4f ring %.4f pre %.4f over %.4f rise %.1e"
                  % (var, N, r["E0625"], r["Earr"], r["Esep"], r["Eend"],
                     r["tsep"], r["wall"], r["ring"], r["pre"], r["over"],
                     r["rise"]))


if __name__ == "__main__":
    main()
