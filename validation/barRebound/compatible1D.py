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

Variants (--variant, comma-separated key=value; "default" is none), the
experiments of FINDINGS.md:
    rec=mc|superbee|minmod|none|kX   the reconstruction's slopes (mc is
                        Barth-Jespersen on the central gradient in 1D)
    char=1              limit s -+ Z v instead of v and s
    map=rec|off|zero|constX|floorX|mc|superbee|minmod   the point map's
                        factor of the central gradient: the
                        reconstruction's (default), 1, 0, X, max(rec, X),
                        or another limiter's slope over the central one
    tvd=LIMITER:harm|min|mean   the map's slope as a alpha + b beta of
                        the one-sided differences (per face term)
    ht=c1all|c1|bj|zero|zero-kX|zero-bj|zsP   per cell and point factors:
                        c1 bounds each extrapolation by the point's two
                        cells; the suffix-less forms apply it only where
                        the cell is downstream of the wave through the
                        point (the jump across it split on s -+ Z v);
                        zero: 0 there and 1 (kX: X, bj: the cell's factor)
                        elsewhere; zsP: downstream fac^P (P = 0: 0 where
                        the limiter acts)
    fct=1|2, fctv=1     a Zalesak blend of the unlimited map into the
                        limited one per point, the cells' s (and with
                        fctv v) kept within their neighbours' values
    pshare=quad|powX, pcoef=X   the point upwinding's share phi^2 (phi^X)
                        and coefficient
    fshare=lin|one      the face upwinding's share phi (or 1), not phi^2
    wall=X              the wall's damping of the fixed direction times X
    koren=C             shares from third-order (kappa = 1/3) face values
                        with Koren's bounds (C = 2); with ht=rec the map
                        takes each cell's own increment to each point
    thinc=B, tsel=bvd|all, tvar=vs|v|s, tchar=1   shares from THINC
                        face values (tanh step of steepness B, B = step:
                        the step from the left to the right neighbour,
                        ENO-SR's front located from the average) in the
                        interior cells whose value lies between their
                        neighbours'; tsel=bvd (default) keeps per cell
                        THINC or MC, whichever gives the smaller face
                        jumps (BVD), all takes THINC wherever it applies;
                        tvar the fields it replaces (v: the face
                        upwinding's, s: the point upwinding's); tchar on
                        s -+ v instead (tvar ignored); with ht=rec the map
                        takes the same values per cell and point
    tmap=B              the map alone from the THINC(-BVD) values of v (tsel
                        as above), per cell and point factors of the
                        central gradient frozen for the stage, the shares
                        unchanged
    sfct=1              Zalesak on the shares: low order the shares 1, high
                        order the variant's, one factor per point for its
                        point and face terms, s and v kept within the
                        cells' neighbours and the low-order values
    fshare=zero         the face upwinding off (as a high order for sfct)
With --smooth sin2|gauss the bar instead carries a right-running pulse
(v = g(x - t), s = -g, width 0.5 from x = 0.1, no contact) to t = 0.3;
prints the L1 and max error of v against the exact cell averages, the L1
order against the previous N, E(T)/E0 and the largest rise in a step.
Prints per run E/E0 at t = 0.625, 1.5 (arrival), the separation and 3.0,
the wall's force over the middle 80 % of the contact and its ringing, the
precursor (largest tension ahead of the compressive front at t = 1.0,
/ Z v0) and overshoot (largest compression beyond Z v0 behind it), the
largest energy rise in a step, and the energy taken by the face
upwinding, the point upwinding and the wall's damping up to the
separation (/E0).
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


def limited_slope(a, b, kind):
    """Limited slope from the backward and forward differences a, b."""
    if kind == "none":
        return 0.5 * (a + b)
    same = a * b > 0
    A, B = np.abs(a), np.abs(b)
    if kind == "mc":
        r = np.minimum(np.minimum(2 * A, 2 * B), 0.5 * (A + B))
    elif kind == "superbee":
        r = np.maximum(np.minimum(2 * A, B), np.minimum(A, 2 * B))
    elif kind == "minmod":
        r = np.minimum(A, B)
    elif kind.startswith("k"):
        r = np.minimum(np.minimum(2 * A, 2 * B), float(kind[1:]) * 0.5 * (A + B))
    return np.where(same, np.sign(a) * r, 0.0)


def slopes(v, s, h, kind, char):
    """Limited gradients of v and s (per variable or on s -+ v); the end
    cells one-sided with Barth-Jespersen as limiter() does."""
    def one(q):
        g = np.empty_like(q)
        a = np.diff(q)
        g[1:-1] = limited_slope(a[:-1], a[1:], kind) / h
        gu = gradient(q, h)
        ph = limiter(q, gu, h, "none" if kind == "none" else "bj")
        g[0], g[-1] = ph[0] * gu[0], ph[-1] * gu[-1]
        return g
    if not char:
        return one(v), one(s)
    g1, g2 = one(s - v), one(s + v)
    return 0.5 * (g2 - g1), 0.5 * (g1 + g2)


def ratio(g, gu):
    return np.where(np.abs(gu) > 1e-300, np.clip(g / np.where(np.abs(gu) > 1e-300, gu, 1), 0, None), 0.0)


def share(rec, cell):
    c = cell * cell
    return np.where(c > 1e-300, np.clip(rec * cell / np.where(c > 1e-300, c, 1), 0, 1), 0.0)


def thinc_bvd(q, qL, qR, beta, sel="bvd", tol=1e-12):
    """THINC-BVD face values: qL, qR the limited linear (MC) values at each
    cell's right and left face.  In an interior cell whose value lies
    strictly between its neighbours' (a monotone jump), the THINC step
    q_min + dq/2 (1 + theta tanh(beta (X - X_c))), X in [0, 1] over the
    cell, X_c from the cell average (beta = inf: the step from q_{i-1} to
    q_{i+1}, ENO-SR's front located from the average); sel = bvd keeps
    per cell the candidate whose face jumps (with the neighbours' values
    of the same candidate) add up smaller (Sun, Inaba, Xiao 2016; Deng et
    al. 2018), sel = all takes THINC in every monotone cell."""
    N = len(q)
    tL, tR = qL.copy(), qR.copy()
    qm, q0, qp = q[:-2], q[1:-1], q[2:]
    d = qp - qm
    mono = ((q0 - qm) * (qp - q0) > 0) & (np.abs(d) > tol)
    if beta == np.inf:
        right, left = qp, qm
    else:
        qmin = np.minimum(qm, qp); dq = np.abs(d); th = np.sign(d)
        C = np.clip((q0 - qmin) / np.where(mono, dq, 1), 1e-12, 1 - 1e-12)
        B = np.exp(th * beta * (2 * C - 1))
        A = (B / np.cosh(beta) - 1) / np.tanh(beta)
        right = qmin + 0.5 * dq * (1 + th * (np.tanh(beta) + A) / (1 + A * np.tanh(beta)))
        left = qmin + 0.5 * dq * (1 + th * A)
    tL[1:-1] = np.where(mono, right, qL[1:-1])
    tR[1:-1] = np.where(mono, left, qR[1:-1])
    if sel == "all":
        return tL, tR

    def tbv(L, R):
        j = np.abs(L[:-1] - R[1:])     # the interior faces' jumps
        out = np.zeros(N); out[1:] += j; out[:-1] += j
        return out
    pick = tbv(tL, tR) < tbv(qL, qR)
    return np.where(pick, tL, qL), np.where(pick, tR, qR)


def tbeta(x):
    return np.inf if x in ("inf", "step") else float(x)


class Model:
    def __init__(self, N, variant="default", cfl=0.3, rk=2):
        self.N, self.h, self.variant = N, 1.0 / N, variant
        self.opt = dict(kv.split("=") for kv in variant.split(",") if "=" in kv)
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
        opt = self.opt
        gv, gs = slopes(v, s, h, opt.get("rec", "mc"), opt.get("char", "0") == "1")
        # the point map's gradients, one frozen factor per cell
        mapkind = opt.get("map", "rec")
        if mapkind == "off":
            fac = np.ones(N)
        elif mapkind == "zero":
            fac = np.zeros(N)
        elif mapkind.startswith("const"):
            fac = np.full(N, float(mapkind[5:]))
        elif mapkind.startswith("floor"):
            fac = np.maximum(ratio(gv, gv_u), float(mapkind[5:]))
        elif mapkind == "rec":
            fac = ratio(gv, gv_u)
        else:
            gm, _ = slopes(v, s, h, mapkind, opt.get("mapchar", "0") == "1")
            fac = ratio(gm, gv_u)
        wl = np.full(N, -0.5 / h) * fac; wr = np.full(N, 0.5 / h) * fac
        wl[0] = 0; wr[0] = fac[0] / h; wl[-1] = -fac[-1] / h; wr[-1] = 0
        if "tvd" in opt:
            kind, mode = opt["tvd"].split(":")
            a = v[1:-1] - v[:-2]; b = v[2:] - v[1:-1]
            sig = limited_slope(a, b, kind)
            A, B = np.abs(a), np.abs(b)
            tot = np.where(A + B > 0, A + B, 1)
            if mode == "harm":
                wa, wb = B / tot, A / tot
            elif mode == "min":
                wa = (A <= B).astype(float); wb = 1 - wa
            elif mode == "mean":
                wa = wb = 0.5 + 0 * A
            al = np.where(A > 0, sig * wa / np.where(A > 0, a, 1), 0)
            be = np.where(B > 0, sig * wb / np.where(B > 0, b, 1), 0)
            wl[1:-1] = -al / h; wr[1:-1] = be / h
        gmap = np.zeros(N)
        gmap[1:] += wl[1:] * (v[:-1] - v[1:]); gmap[:-1] += wr[:-1] * (v[1:] - v[:-1])
        # reconstructed face values: face a between cell a-1 (L) and a (R)
        vL = v + 0.5 * h * gv; vR = v - 0.5 * h * gv   # at right / left face
        sL = s + 0.5 * h * gs; sR = s - 0.5 * h * gs
        if "koren" in opt:
            # third order (kappa = 1/3), Koren's bounds (c): separate
            # increments to the right and left faces, inside cells only
            c = float(opt["koren"])
            def kor(q):
                a = q[1:-1] - q[:-2]; b = q[2:] - q[1:-1]
                same = a * b > 0; sg = np.sign(a); A, B = np.abs(a), np.abs(b)
                up = np.where(same, sg * 0.5 * np.minimum(np.minimum(c * B, (A + 2 * B) / 3), c * A), 0)
                dn = np.where(same, sg * 0.5 * np.minimum(np.minimum(c * A, (B + 2 * A) / 3), c * B), 0)
                return up, dn
            if opt.get("char", "0") == "1":
                u1, d1 = kor(s - v); u2, d2 = kor(s + v)
                uv, dv_ = 0.5 * (u2 - u1), 0.5 * (d2 - d1); us, ds_ = 0.5 * (u1 + u2), 0.5 * (d1 + d2)
            else:
                uv, dv_ = kor(v); us, ds_ = kor(s)
            vL[1:-1] = v[1:-1] + uv; vR[1:-1] = v[1:-1] - dv_
            sL[1:-1] = s[1:-1] + us; sR[1:-1] = s[1:-1] - ds_
        if "thinc" in opt or "tmap" in opt:
            sel = opt.get("tsel", "bvd")
            vL0, vR0 = vL, vR
            if "thinc" in opt:
                b = tbeta(opt["thinc"])
                if opt.get("tchar", "0") == "1":
                    # on s -+ v: w1 = s - v, w2 = s + v
                    w1L, w1R = thinc_bvd(s - v, sL - vL, sR - vR, b, sel)
                    w2L, w2R = thinc_bvd(s + v, sL + vL, sR + vR, b, sel)
                    vL, vR = 0.5 * (w2L - w1L), 0.5 * (w2R - w1R)
                    sL, sR = 0.5 * (w1L + w2L), 0.5 * (w1R + w2R)
                else:
                    tv = opt.get("tvar", "vs")
                    if "v" in tv:
                        vL, vR = thinc_bvd(v, vL, vR, b, sel)
                    if "s" in tv:
                        sL, sR = thinc_bvd(s, sL, sR, b, sel)
            if "tmap" in opt:
                self.tmapv = thinc_bvd(v, vL0, vR0, tbeta(opt["tmap"]), sel)
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
        if opt.get("fshare") == "lin":
            phi = np.sqrt(phi)
        elif opt.get("fshare") == "one":
            phi = np.ones_like(phi)
        elif opt.get("fshare") == "zero":
            phi = np.zeros_like(phi)
        tC = 0.5 * phi ** 2 * jump
        rate[:-1] += tC; rate[1:] -= tC
        self.loss = [np.sum(0.5 * phi ** 2 * jump ** 2), 0.0, 0.0]
        # contact
        if decide:
            if not self.released and u0 <= -self.gap + 1e-12:
                self.contact = True
        wall_force = 0.0
        if self.contact:
            dep = v[0]
            sh = share(np.array([vR[0]]), np.array([dep]))[0] ** 2
            damp = -sh * dep * float(self.opt.get("wall", 1))
            wall_force = f[0] + damp
            if decide and wall_force < 0:
                self.contact = False
                self.released = True
        if self.contact:
            rate[0] += damp
            self.loss[2] = -damp * v[0]
        # point velocities
        def amap(wl, wr):
            g = np.zeros(N)
            g[1:] += wl[1:] * (v[:-1] - v[1:]); g[:-1] += wr[:-1] * (v[1:] - v[:-1])
            pv = np.zeros(N + 1)
            ext_r = v + 0.5 * h * g
            ext_l = v - 0.5 * h * g
            pv[1:-1] = 0.5 * (ext_r[:-1] + ext_l[1:])
            pv[0] = ext_l[0]; pv[-1] = ext_r[-1]
            return pv
        n_a = np.full(N + 1, 2.0); n_a[0] = n_a[-1] = 1.0

        def atrans(gpt, wl, wr):
            out = np.zeros(N)
            shr = gpt / n_a
            out += shr[:-1] + shr[1:]
            H = shr[1:] * 0.5 * h - shr[:-1] * 0.5 * h
            q_right = H * wr
            q_left = H * wl
            q_right = q_right.copy(); q_left = q_left.copy()
            q_right[-1] = 0; q_left[0] = 0
            out[1:] += q_right[:-1]; out[:-1] -= q_right[:-1]
            out[:-1] += q_left[1:]; out[1:] -= q_left[1:]
            return out
        pv = amap(wl, wr)
        if "ht" in opt or "tmap" in opt:
            gu = gradient(v, h)
            extl = -0.5 * h * gu; extr = 0.5 * h * gu   # increments
            # candidate 1: bound each extrapolation by the point's cells
            def c1(inc, lo, hi):
                return np.where(inc > 1e-300, np.minimum(1, np.maximum(hi, 0) / np.where(inc > 1e-300, inc, 1)),
                                np.where(inc < -1e-300, np.minimum(1, np.minimum(lo, 0) / np.where(inc < -1e-300, inc, -1)), 1.0))
            vl = np.r_[v[0], v[:-1]]; vr = np.r_[v[1:], v[-1]]
            fl = c1(extl, np.minimum(vl, v) - v, np.maximum(vl, v) - v)
            fr = c1(extr, np.minimum(vr, v) - v, np.maximum(vr, v) - v)
            kind = opt.get("ht", "tmap")
            if kind.startswith("bj"):
                fl = fr = fac.copy()
            if not kind.endswith("all") and kind not in ("rec", "tmap"):
                # downstream: the wave through point a runs into cell e
                ds = np.diff(s); dv = np.diff(v)
                right = np.abs(ds - dv) > np.abs(ds + dv)    # per interior point
                # cell e's left point is interior point e (e >= 1): cell e
                # downstream of it if the wave runs right there
                dl = np.r_[False, right]       # cell e, its left point
                dr = np.r_[~right, False]      # cell e, its right point: left-running
                fl = np.where(dl, fl, 1.0); fr = np.where(dr, fr, 1.0)
            if kind.startswith("zero"):
                up = 1.0
                if kind == "zero-bj":
                    up = fac
                elif kind.startswith("zero-k"):
                    up = float(kind[6:])
                fl = np.where(dl, 0.0, up); fr = np.where(dr, 0.0, up)
            if kind == "rec":
                # the reconstruction's own increments to each point
                fr = ratio(vL - v, extr); fl = ratio(vR - v, extl)
            if kind == "tmap":
                # the THINC-BVD increments of v to each point
                fr = ratio(self.tmapv[0] - v, extr); fl = ratio(self.tmapv[1] - v, extl)
            if kind.startswith("zs"):
                # downstream: 0 where the cell's limiter acts, up: 1 or k
                p = float(kind[2:]) if len(kind) > 2 else 0.0
                dfac = np.where(fac < 1, 0.0, 1.0) if p == 0 else fac ** p
                fl = np.where(dl, dfac, 1.0); fr = np.where(dr, dfac, 1.0)
            if kind.startswith("dbj"):
                # downstream: the cell's BJ factor times d; upstream 1
                d = float(kind[3:])
                fl = np.where(dl, d * fac, 1.0); fr = np.where(dr, d * fac, 1.0)
            self.sides = (fl, fr)
            pv = np.zeros(N + 1)
            er = v + fr * extr; el = v + fl * extl
            pv[1:-1] = 0.5 * (er[:-1] + el[1:]); pv[0] = el[0]; pv[-1] = er[-1]
        fc = f.copy()
        if self.contact:
            pv[0] = 0.0
            fc[0] = 0.0
        phia = share(r, fc)
        if opt.get("pshare") == "quad":
            phia = phia ** 2
        elif opt.get("pshare", "").startswith("pow"):
            phia = phia ** float(opt["pshare"][3:])
        phia = phia * float(opt.get("pcoef", 1))
        self.loss[1] = np.sum(self.mob * phia * fc ** 2)
        pv -= self.mob * phia * fc
        if self.contact:
            pv[0] = 0.0
        srate = (pv[1:] - pv[:-1]) / h
        lam = None
        if "fct" in opt:
            # high order: the unlimited map; antidiffusive point velocities
            wlh = np.full(N, -0.5 / h); wrh = np.full(N, 0.5 / h)
            wlh[0] = 0; wrh[0] = 1 / h; wlh[-1] = -1 / h; wrh[-1] = 0
            ad = amap(wlh, wrh) - amap(wl, wr)
            if self.contact:
                ad[0] = 0.0
            k = self.dt
            smax = s.copy(); smin = s.copy()
            smax[1:] = np.maximum(smax[1:], s[:-1]); smax[:-1] = np.maximum(smax[:-1], s[1:])
            smin[1:] = np.minimum(smin[1:], s[:-1]); smin[:-1] = np.minimum(smin[:-1], s[1:])
            slow = s + k * srate
            if opt["fct"] == "2":
                smax = np.maximum(smax, slow); smin = np.minimum(smin, slow)
            # cell e gains (ad[e+1] - ad[e]) k/h
            Pp = k / h * (np.maximum(ad[1:], 0) + np.maximum(-ad[:-1], 0))
            Pm = k / h * (np.minimum(ad[1:], 0) + np.minimum(-ad[:-1], 0))
            Qp = np.maximum(smax - slow, 0); Qm = np.minimum(smin - slow, 0)
            Rp = np.where(Pp > 1e-300, np.minimum(1, Qp / np.where(Pp > 1e-300, Pp, 1)), 1)
            Rm = np.where(Pm < -1e-300, np.minimum(1, Qm / np.where(Pm < -1e-300, Pm, -1)), 1)
            lam = np.ones(N + 1)
            # point a: +ad to cell a-1, -ad to cell a
            pos = ad[1:-1] > 0
            lam[1:-1] = np.where(pos, np.minimum(Rp[:-1], Rm[1:]), np.minimum(Rm[:-1], Rp[1:]))
            lam[0] = np.where(ad[0] > 0, Rm[0], Rp[0])
            lam[-1] = np.where(ad[-1] > 0, Rp[-1], Rm[-1])
            if opt.get("fctv") == "1":
                # the momentum's antidiffusive parts: per point a and cell
                # e, -lam_a g_a (A_high - A_low)_ae / h
                def amat(wl_, wr_):
                    Mx = np.zeros((N + 1, N))
                    for e in range(N):
                        ue = np.zeros(N); ue[e] = 1
                        gg = np.zeros(N)
                        gg[1:] += wl_[1:] * (ue[:-1] - ue[1:]); gg[:-1] += wr_[:-1] * (ue[1:] - ue[:-1])
                        col = np.zeros(N + 1)
                        er = ue + 0.5 * h * gg; el = ue - 0.5 * h * gg
                        col[1:-1] = 0.5 * (er[:-1] + el[1:]); col[0] = el[0]; col[-1] = er[-1]
                        Mx[:, e] = col
                    return Mx
                Dm = amat(wlh, wrh) - amat(wl, wr)
                if self.contact:
                    Dm[0] = 0
                gpt = -fc
                C = (gpt[:, None] * Dm) * (k / h)   # per point and cell, times lam
                vmax = v.copy(); vmin = v.copy()
                vmax[1:] = np.maximum(vmax[1:], v[:-1]); vmax[:-1] = np.maximum(vmax[:-1], v[1:])
                vmin[1:] = np.minimum(vmin[1:], v[:-1]); vmin[:-1] = np.minimum(vmin[:-1], v[1:])
                vlow = v + k * (rate + atrans(gpt, wl, wr)) / h
                Pv = np.maximum(C, 0).sum(0); Mv = np.minimum(C, 0).sum(0)
                Qv = np.maximum(vmax - vlow, 0); Qw = np.minimum(vmin - vlow, 0)
                Rvp = np.where(Pv > 1e-300, np.minimum(1, Qv / np.where(Pv > 1e-300, Pv, 1)), 1)
                Rvm = np.where(Mv < -1e-300, np.minimum(1, Qw / np.where(Mv < -1e-300, Mv, -1)), 1)
                for a in range(N + 1):
                    for e in np.nonzero(C[a])[0]:
                        lam[a] = min(lam[a], Rvp[e] if C[a, e] > 0 else Rvm[e])
            pv = pv + lam * ad
            srate = (pv[1:] - pv[:-1]) / h
        # -A^T f (f constrained)
        g = -fc
        if "ht" in opt or "tmap" in opt:
            fl, fr = self.sides
            shr = g / n_a
            out = shr[:-1] + shr[1:]
            H = fr * shr[1:] * 0.5 * h - fl * shr[:-1] * 0.5 * h
            wlu = np.full(N, -0.5 / h); wru = np.full(N, 0.5 / h)
            wlu[0] = 0; wru[0] = 1 / h; wlu[-1] = -1 / h; wru[-1] = 0
            qr = H * wru; ql = H * wlu
            out[1:] += qr[:-1]; out[:-1] -= qr[:-1]
            out[:-1] += ql[1:]; out[1:] -= ql[1:]
            rate += out
        else:
            rate += atrans(g, wl, wr)
        if lam is not None:
            rate += atrans(lam * g, wlh, wrh) - atrans(lam * g, wl, wr)
        if "sfct" in opt:
            # Zalesak on the shares: low order the shares 1, high order the
            # variant's; one factor per point for its point and face terms
            k = self.dt
            adp = self.mob * (1 - phia) * fc          # pv_high - pv_low
            if self.contact:
                adp[0] = 0.0
            adf = -0.5 * (1 - phi ** 2) * jump        # tC_high - tC_low
            cs = np.zeros((N + 1, 2)); cv = np.zeros((N + 1, 2))  # to cells a-1, a
            cs[:, 0] = adp / h; cs[:, 1] = -adp / h
            cv[1:-1, 0] = adf / h; cv[1:-1, 1] = -adf / h
            cs[0, 0] = cs[-1, 1] = 0.0
            def to_cells(c):
                out = np.zeros(N); out += c[1:, 0]; out += c[:-1, 1]
                return out
            srate_lo = srate - to_cells(cs)
            vrate_lo = rate / h - to_cells(cv)
            def limit(q, qrate_lo, c):
                qlow = q + k * qrate_lo
                qmax = np.maximum(q, qlow); qmin = np.minimum(q, qlow)
                qmax[1:] = np.maximum(qmax[1:], q[:-1]); qmax[:-1] = np.maximum(qmax[:-1], q[1:])
                qmin[1:] = np.minimum(qmin[1:], q[:-1]); qmin[:-1] = np.minimum(qmin[:-1], q[1:])
                Pp = k * to_cells(np.maximum(c, 0)); Pm = k * to_cells(np.minimum(c, 0))
                Qp = np.maximum(qmax - qlow, 0); Qm = np.minimum(qmin - qlow, 0)
                Rp = np.where(Pp > 1e-300, np.minimum(1, Qp / np.where(Pp > 1e-300, Pp, 1)), 1)
                Rm = np.where(Pm < -1e-300, np.minimum(1, Qm / np.where(Pm < -1e-300, Pm, -1)), 1)
                Rp = np.r_[1.0, Rp, 1.0]; Rm = np.r_[1.0, Rm, 1.0]   # padded: cell a-1 at [a], a at [a+1]
                left = np.where(c[:, 0] > 0, Rp[:-1], Rm[:-1])
                right = np.where(c[:, 1] > 0, Rp[1:], Rm[1:])
                return np.minimum(left, right)
            lam = np.minimum(limit(s, srate_lo, cs), limit(v, vrate_lo, cv))
            srate = srate_lo + to_cells(lam[:, None] * cs)
            rate = h * (vrate_lo + to_cells(lam[:, None] * cv))
            pe = 1 - lam * (1 - phia)
            fe = 1 - lam[1:-1] * (1 - phi ** 2)
            self.loss[0] = np.sum(0.5 * fe * jump ** 2)
            self.loss[1] = np.sum(self.mob * pe * fc ** 2)
            pv = pv - (1 - lam) * adp
        return rate / h, srate, pv[0], wall_force

    def energy(self, v, s):
        return 0.5 * self.h * np.sum(v * v + s * s)

    def run(self, T=3.0, init=None):
        N = self.N
        v = -np.ones(N); s = np.zeros(N); u0 = 0.0
        if init is not None:
            v, s = init
        t = 0.0
        E0 = self.energy(v, s)
        rows = []
        prof = None
        while t < T - 1e-12:
            k = min(self.dt, T - t)
            a, b, w, wf = self.rates(v, s, u0, True)
            l1 = np.array(self.loss)
            c0 = self.contact
            v1 = v + k * a; s1 = s + k * b; u1 = u0 + k * w
            a, b, w, _ = self.rates(v1, s1, u1, False)
            self.lost = getattr(self, "lost", np.zeros(3)) + 0.5 * k * (l1 + np.array(self.loss)) / E0
            v = 0.5 * (v + v1 + k * a); s = 0.5 * (s + s1 + k * b)
            u0 = 0.5 * (u0 + u1 + k * w)
            t += k
            rows.append((t, self.energy(v, s) / E0, c0, wf) + tuple(self.lost))
            if prof is None and t >= 1.0 - 1e-12:
                prof = s.copy()
        rows = np.array(rows)
        return rows, prof


def measure(N, variant):
    m = Model(N, variant)
    rows, prof = m.run()
    t, E, c, wf = rows.T[:4]
    lost = rows[:, 4:]
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
                rise=max(0.0, np.diff(E).max()), lost=lost[sep])


def pulse_avg(N, t, shape, a=0.1, w=0.5):
    """Cell averages of the right-running pulse v = g(x - t), s = -g(x - t):
    sin2, g = sin^2(pi (x - a)/w) on [a, a + w] (C1); gauss, g =
    exp(-((x - a - w/2)/(w/6))^2) (C-infinity to 1e-9 at a, a + w)."""
    x0 = np.arange(N) / N - t - a; x1 = x0 + 1.0 / N
    if shape == "sin2":
        y0 = np.clip(x0, 0, w); y1 = np.clip(x1, 0, w)
        k = 2 * np.pi / w
        I = 0.5 * (y1 - y0) - 0.5 * (np.sin(k * y1) - np.sin(k * y0)) / k
    else:
        from math import erf, sqrt, pi
        sg = w / 6.0
        E = np.vectorize(erf)
        I = 0.5 * sqrt(pi) * sg * (E((x1 - 0.5 * w) / sg) - E((x0 - 0.5 * w) / sg))
    g = I * N
    return g, -g


def measure_smooth(N, variant, shape, T=0.3):
    """The pulse from its exact cell averages to T (no contact): L1 and max
    error of v against the exact cell averages, E(T)/E0, largest rise."""
    m = Model(N, variant)
    m.gap = 1e9
    v0, s0 = pulse_avg(N, 0.0, shape)
    E0 = m.energy(v0, s0)
    t = 0.0; v, s, u0 = v0.copy(), s0.copy(), 0.0
    Es = [1.0]
    while t < T - 1e-12:
        k = min(m.dt, T - t)
        a, b, w, _ = m.rates(v, s, u0, True)
        v1 = v + k * a; s1 = s + k * b; u1 = u0 + k * w
        a, b, w, _ = m.rates(v1, s1, u1, False)
        v = 0.5 * (v + v1 + k * a); s = 0.5 * (s + s1 + k * b)
        u0 = 0.5 * (u0 + u1 + k * w)
        t += k
        Es.append(m.energy(v, s) / E0)
    ve, se = pulse_avg(N, T, shape)
    return dict(L1=np.sum(np.abs(v - ve)) / N, Linf=np.abs(v - ve).max(),
                E=Es[-1], rise=max(0.0, np.diff(Es).max()))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, nargs="+", default=[50])
    ap.add_argument("--variant", nargs="+", default=["default"])
    ap.add_argument("--smooth", choices=["sin2", "gauss"],
                    help="instead of the bounce: a right-running smooth "
                    "pulse of width 0.5 from x = 0.1, to t = 0.3; prints the "
                    "L1 and max error of v, the L1 order against the "
                    "previous N, E(T)/E0 and the largest rise in a step")
    a = ap.parse_args()
    if a.smooth:
        for var in a.variant:
            prev = None
            for N in a.n:
                r = measure_smooth(N, var, a.smooth)
                order = "" if prev is None else "%5.2f" % (
                    np.log(prev[1] / r["L1"]) / np.log(N / prev[0]))
                print("%-20s N %4d  L1 %.3e order %5s  max %.3e  E %.6f rise %.1e"
                      % (var, N, r["L1"], order, r["Linf"], r["E"], r["rise"]))
                prev = (N, r["L1"])
        return
    for var in a.variant:
        for N in a.n:
            r = measure(N, var)
            print("%-20s N %4d  E 0.625 %.4f arr %.4f sep %.4f end %.4f "
                  "t_sep %.3f wall %.4f ring %.4f pre %.4f over %.4f rise %.1e"
                  % (var, N, r["E0625"], r["Earr"], r["Esep"], r["Eend"],
                     r["tsep"], r["wall"], r["ring"], r["pre"], r["over"],
                     r["rise"]) + "  lost face/point/wall %.4f %.4f %.4f" % tuple(r["lost"]))


if __name__ == "__main__":
    main()
