"""Closed-form solutions and initial fields of the benchmarks.

Conventions: X is an (n, 3) array of reference positions; a tensor T is
returned as (n, 3, 3) with T[:, i, j] = T_ij, which flattened row by row is
OpenFOAM's component order (xx xy xz yx yy yz zx zy zz).  The deformation
gradient is F_ij = delta_ij + du_i/dX_j.
"""

import numpy as np


def lame(E, nu):
    """(lambda, mu) from Young's modulus and Poisson's ratio."""
    mu = E / (2.0 * (1.0 + nu))
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    return lam, mu


def p_wave_speed(E, nu, rho):
    lam, mu = lame(E, nu)
    return np.sqrt((lam + 2.0 * mu) / rho)


def flatten_tensor(T):
    """(n, 3, 3) -> (n, 9) in OpenFOAM's order."""
    return np.asarray(T).reshape(len(T), 9)


class SwingingCube:
    """Low-dispersion cube, doc/benchmarks.md section 1.

        u(X, t) = U0 cos(w t) g(X),   g_i = sin(a X_i) prod_{k != i} cos(a X_k)

    with a = pi/2 and w = sqrt(3)/2 c_d pi, c_d = sqrt((lambda + 2 mu)/rho0).
    It solves rho0 u_tt = (lambda + mu) grad div u + mu lap u because
    lap g = -3 a^2 g and grad div g = -3 a^2 g.  X = 0 planes are rollers
    (normal u and shear zero), X = 1 planes skew-symmetric (tangential u and
    normal stress zero), matching the case's boundary conditions.
    """

    def __init__(self, E=1.7e7, nu=0.3, rho=1100.0, U0=5e-4,
                 amplitudes=(1.0, 1.0, 1.0)):
        self.E, self.nu, self.rho, self.U0 = E, nu, rho, U0
        self.A = np.asarray(amplitudes, dtype=float)
        self.lam, self.mu = lame(E, nu)
        self.cd = np.sqrt((self.lam + 2.0 * self.mu) / rho)
        self.a = 0.5 * np.pi
        self.omega = 0.5 * np.sqrt(3.0) * self.cd * np.pi

    def _sc(self, X):
        X = np.asarray(X, dtype=float)
        return np.sin(self.a * X), np.cos(self.a * X)

    def shape(self, X):
        """g(X), (n, 3)."""
        s, c = self._sc(X)
        g = np.empty_like(s)
        for i in range(3):
            j, k = (i + 1) % 3, (i + 2) % 3
            g[:, i] = self.A[i] * s[:, i] * c[:, j] * c[:, k]
        return g

    def shape_gradient(self, X):
        """dg_i/dX_j, (n, 3, 3)."""
        s, c = self._sc(X)
        G = np.empty((len(s), 3, 3))
        for i in range(3):
            for j in range(3):
                if i == j:
                    G[:, i, i] = self.a * c[:, 0] * c[:, 1] * c[:, 2]
                else:
                    k = 3 - i - j
                    G[:, i, j] = -self.a * s[:, i] * s[:, j] * c[:, k]
            G[:, i, :] *= self.A[i]
        return G

    def displacement(self, X, t):
        return self.U0 * np.cos(self.omega * t) * self.shape(X)

    def velocity(self, X, t):
        return -self.U0 * self.omega * np.sin(self.omega * t) * self.shape(X)

    def displacement_gradient(self, X, t):
        return self.U0 * np.cos(self.omega * t) * self.shape_gradient(X)

    def deformation_gradient(self, X, t):
        return np.eye(3) + self.displacement_gradient(X, t)

    def stress(self, X, t):
        """Small-strain P = mu (H + H^T) + lambda tr(H) I, H = grad u."""
        H = self.displacement_gradient(X, t)
        tr = np.trace(H, axis1=1, axis2=2)
        return (self.mu * (H + np.transpose(H, (0, 2, 1)))
                + self.lam * tr[:, None, None] * np.eye(3))

    def stress_amplitude(self):
        """max over X and t of |P_xx| (= (3 lambda + 2 mu) a U0 when A = 1)."""
        return (self.lam * self.A.sum() + 2.0 * self.mu * self.A.max()) \
            * self.a * self.U0

    def velocity_amplitude(self):
        return self.U0 * self.omega * self.A.max()


class TwistingColumn:
    """Twisting column, doc/benchmarks.md section 2: v0 = omega x X with
    omega = (0, Omega sin(pi Y / (2 L)), 0)."""

    def __init__(self, Omega=105.0, L=6.0, rho=1100.0):
        self.Omega, self.L, self.rho = Omega, L, rho

    def velocity(self, X):
        X = np.asarray(X, dtype=float)
        wy = self.Omega * np.sin(np.pi * X[:, 1] / (2.0 * self.L))
        # (0, wy, 0) x (X, Y, Z) = (wy Z, 0, -wy X)
        return np.stack([wy * X[:, 2], np.zeros(len(X)), -wy * X[:, 0]],
                        axis=1)


def rigid_velocity(X, translation, omega):
    """v = v_t + omega x X."""
    X = np.asarray(X, dtype=float)
    return np.asarray(translation, float) + np.cross(
        np.asarray(omega, float), X)


def twist_angle(X, u):
    """Rotation about +Y of points from (X, Z) to (X + ux, Z + uz).

    Rotating by theta about +Y maps (Z, X) like a counter-clockwise turn in
    the (Z, X) plane (Y = Z x X), so theta = atan2(Z0 X1 - X0 Z1,
    Z0 Z1 + X0 X1).  Returns angles in (-pi, pi] for each point.
    """
    X = np.asarray(X, dtype=float)
    x0, z0 = X[:, 0], X[:, 2]
    x1, z1 = x0 + u[:, 0], z0 + u[:, 2]
    return np.arctan2(z0 * x1 - x0 * z1, z0 * z1 + x0 * x1)
