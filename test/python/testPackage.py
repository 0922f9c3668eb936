#!/usr/bin/python3
"""Unit tests of bin/python/touchfoam (no touchFoam needed).

    /usr/bin/python3 test/python/testPackage.py

Checks the field reader/writer round trip, the analytic solutions (against
finite differences of themselves and the governing equations), the Gmsh
tetrahedral mesh, the monitor reader and, when OpenFOAM is in the PATH,
the Python cell centres and volumes against OpenFOAM's own (postProcess
-func writeCellCentres / writeCellVolumes) on a hex and a tet mesh.
Prints one PASS/FAIL line per check; exit status 1 if any failed.
"""

import os
import shutil
import sys
import tempfile
import traceback

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import analytic, checks, foamfile, gmsh, hertz  # noqa: E402
from touchfoam import mesh, monitor  # noqa: E402
from touchfoam import run as frun  # noqa: E402
from touchfoam.cases import prepare  # noqa: E402

TESTS = []


def test(fn):
    TESTS.append(fn)
    return fn


@test
def field_round_trip(tmp):
    rng = np.random.default_rng(1)
    n = 50
    boundary = {"X0": {"type": "calculated", "value": "uniform 0"},
                "\"(a|b)\"": {"type": "zeroGradient"}}
    worst = 0.0
    for cls, ncomp in (("volScalarField", 1), ("volVectorField", 3),
                       ("volSymmTensorField", 6), ("volTensorField", 9),
                       ("pointVectorField", 3)):
        shape = (n,) if ncomp == 1 else (n, ncomp)
        values = rng.standard_normal(shape) * 10.0 ** rng.integers(
            -300, 300, shape)
        fld = foamfile.new_field(cls, "q", "[0 1 -1 0 0 0 0]", boundary)
        fld.set_internal(values)
        path = os.path.join(tmp, cls)
        fld.write(path)
        back = foamfile.read_field(path)
        assert back.type == foamfile.primitive_type(cls)
        assert np.array_equal(back.values, values), cls   # bit for bit
        types = back.patch_types()
        assert types == {"X0": "calculated", "(a|b)": "zeroGradient"}, types
        # Rewriting keeps the boundary text verbatim
        back.set_internal(values * 2)
        back.write(path + ".2")
        again = foamfile.read_field(path + ".2")
        assert again.suffix == back.suffix and again.prefix == back.prefix
        worst = max(worst, np.abs(again.values - 2 * values).max())
    assert worst == 0.0
    return "5 field classes, bit-exact"


@test
def field_forms(tmp):
    text = foamfile.header_text("volVectorField", "lm", "0") + """
dimensions [1 -2 -1 0 0 0 0];
// internalField uniform (9 9 9);  a comment must not be read
internalField   uniform (1 2 3);
boundaryField
{
    base { type clamped; value nonuniform List<vector> 2((0 0 0)(1 1 1)); }
    /* internalField nonuniform List<vector> 0(); */
    free { type traction; internalField uniform (7 7 7); }
}
"""
    path = os.path.join(tmp, "lm")
    with open(path, "w") as f:
        f.write(text)
    fld = foamfile.read_field(path)
    assert fld.uniform and np.array_equal(fld.values, [1, 2, 3])
    assert fld.internal(4).shape == (4, 3)
    assert fld.patch_types() == {"base": "clamped", "free": "traction"}
    fld.write(path + ".out")
    again = foamfile.read_field(path + ".out")
    assert again.uniform and np.array_equal(again.values, [1, 2, 3])

    # Compact uniform list N{value}, and a scalar list
    with open(path, "w") as f:
        f.write(foamfile.header_text("volScalarField", "J") + """
dimensions [0 0 0 0 0 0 0];
internalField nonuniform List<scalar> 3{1.5};
boundaryField {}
""")
    assert np.array_equal(foamfile.read_field(path).values, [1.5] * 3)

    # Binary files are refused with a message naming the fix
    with open(path, "w") as f:
        f.write(text.replace("format      ascii", "format      binary"))
    try:
        foamfile.read_field(path)
    except foamfile.FoamFileError as err:
        assert "ascii" in str(err)
    else:
        raise AssertionError("binary file accepted")
    return "uniform, comments, N{v}, binary refused"


@test
def read_dict_includes(tmp):
    with open(os.path.join(tmp, "mechanicalProperties"), "w") as f:
        f.write(foamfile.header_text("dictionary", "mechanicalProperties") +
                "model neoHookean;\nrho 1100; // c\nnu 0.45;\n"
                "sub { a (1 2 3); b 2; }\n"
                '#includeIfPresent "materialOptions"\n'
                '#includeIfPresent "missing"\n')
    with open(os.path.join(tmp, "materialOptions"), "w") as f:
        f.write("nu 0.495;\n")
    d = foamfile.read_dict(os.path.join(tmp, "mechanicalProperties"))
    assert d["model"] == "neoHookean" and d["rho"] == 1100.0
    assert d["nu"] == 0.495, d
    assert d["sub"] == {"a": "(1 2 3)", "b": 2.0}, d["sub"]
    return "override by #includeIfPresent"


@test
def swinging_cube_analytic(tmp):
    sol = analytic.SwingingCube()
    rng = np.random.default_rng(2)
    X = rng.random((200, 3))
    t = 0.0013
    h = 1e-5

    # grad u against central differences of u
    G = sol.displacement_gradient(X, t)
    for j in range(3):
        dX = np.zeros(3)
        dX[j] = h
        fd = (sol.displacement(X + dX, t) - sol.displacement(X - dX, t)) / (
            2 * h)
        assert np.abs(fd - G[:, :, j]).max() < 1e-8 * sol.U0
    # v = du/dt
    ht = 1e-8
    fd = (sol.displacement(X, t + ht) - sol.displacement(X, t - ht)) / (2 * ht)
    assert np.abs(fd - sol.velocity(X, t)).max() < 1e-6 * \
        sol.velocity_amplitude()

    # Momentum balance rho u_tt = div P, by differences of the exact P
    divP = np.zeros_like(X)
    for j in range(3):
        dX = np.zeros(3)
        dX[j] = h
        divP += (sol.stress(X + dX, t)[:, :, j]
                 - sol.stress(X - dX, t)[:, :, j]) / (2 * h)
    utt = -sol.omega ** 2 * sol.displacement(X, t)
    resid = np.abs(sol.rho * utt - divP).max() / np.abs(divP).max()
    assert resid < 1e-6, resid

    # Boundary conditions: rollers at 0, skew-symmetric at 1
    for i in range(3):
        Xb = X.copy()
        Xb[:, i] = 0.0
        u, P = sol.displacement(Xb, t), sol.stress(Xb, t)
        assert np.abs(u[:, i]).max() < 1e-20
        others = [k for k in range(3) if k != i]
        assert np.abs(P[:, others, i]).max() < 1e-9
        Xb[:, i] = 1.0
        u, P = sol.displacement(Xb, t), sol.stress(Xb, t)
        assert np.abs(u[:, others]).max() < 1e-19
        assert np.abs(P[:, i, i]).max() < 1e-9

    # Numbers quoted in the docs
    lam, mu = analytic.lame(1.7e7, 0.3)
    assert abs(sol.cd - np.sqrt((lam + 2 * mu) / 1100)) < 1e-12
    assert abs(sol.omega - np.sqrt(3) / 2 * sol.cd * np.pi) < 1e-9
    return "grad u, v, div P = rho u_tt (resid %.1e), BCs; c_d = %.4g m/s" % (
        resid, sol.cd)


@test
def twist_angle_and_column(tmp):
    col = analytic.TwistingColumn()
    X = np.array([[0.5, 6.0, 0.0], [0.0, 3.0, 0.5], [0.3, 0.0, 0.2]])
    v = col.velocity(X)
    # omega x X with omega = (0, Omega, 0) at the top
    assert np.allclose(v[0], [0, 0, -105 * 0.5])
    assert np.allclose(v[1], [105 * np.sin(np.pi / 4) * 0.5, 0, 0])
    assert np.allclose(v[2], 0)
    # A rigid rotation by theta about +Y is measured as theta
    theta = 2.5
    R = np.array([[np.cos(theta), 0, np.sin(theta)], [0, 1, 0],
                  [-np.sin(theta), 0, np.cos(theta)]])
    Xs = np.random.default_rng(3).random((20, 3)) - 0.5
    u = Xs @ R.T - Xs
    assert np.allclose(analytic.twist_angle(Xs, u), theta)
    # and its direction is that of the initial spin: v = omega x X
    small = 1e-6 * col.velocity(np.c_[Xs[:, 0], 6 + 0 * Xs[:, 1], Xs[:, 2]])
    assert np.all(analytic.twist_angle(Xs, small) > 0)
    return "rotation about +Y recovered"


@test
def gmsh_cube(tmp):
    n = 3
    points, tets = gmsh.cube_tets(n)
    p = points[tets]
    vol = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0],
                                         p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
    assert np.all(vol > 0) and abs(vol.sum() / 6 - 1) < 1e-14
    faces = np.sort(np.concatenate([tets[:, [0, 1, 2]], tets[:, [0, 1, 3]],
                                    tets[:, [0, 2, 3]], tets[:, [1, 2, 3]]]),
                    axis=1)
    _, count = np.unique(faces, axis=0, return_counts=True)
    # Conforming: every face is shared by 2 tets or lies on the boundary
    assert set(count) == {1, 2}
    tris = gmsh.boundary_triangles(tets, points)
    assert all(len(t) == 2 * n * n for t in tris.values())
    assert (count == 1).sum() == 12 * n * n
    path = os.path.join(tmp, "cube.msh")
    assert gmsh.write_msh(path, n) == ((n + 1) ** 3, 6 * n ** 3)
    return "%d tets, conforming, volume 1" % len(tets)


@test
def monitor_reader(tmp):
    for start, times in (("0", [0.0, 1.0, 2.0, 3.0]), ("2", [2.0, 2.5])):
        d = os.path.join(tmp, "postProcessing", "solidMonitor", start)
        os.makedirs(d)
        with open(os.path.join(d, "solidMonitor.dat"), "w") as f:
            f.write("# Solid monitor\n# Time\tpx\tpy\tpz\tLx\tLy\tLz\t"
                    "kineticEnergy\tstrainEnergy\ttotalEnergy\n")
            for t in times:
                f.write("%g" % t + " %g" % (10 * t) * 9 + "\n")
    m = monitor.read_monitor(tmp)
    assert list(m["Time"]) == [0.0, 1.0, 2.0, 2.5], m["Time"]
    assert m["p"].shape == (4, 3) and m["L"].shape == (4, 3)
    return "restart folders joined"


@test
def validation_checks(tmp):
    """checks.record rewrites checks.json on a run's first record, the
    status is 1 with a failing check or none, and the table puts FAIL rows
    (and a study without checks) first."""
    a, b, c = (os.path.join(tmp, s) for s in ("a", "b", "c"))
    for d in (a, b, c):
        os.makedirs(d)
    with open(checks.path(a), "w") as f:
        f.write('[{"quantity": "stale"}]')
    assert checks.record(a, "x", np.float64(0.5), "<= 1", True) is True
    checks.record(a, "y", 2, "<= 1", False, "a | note")
    checks.record(b, "z", 1e-12, 1e-10, True)
    rows = checks.load(a)
    assert [r["quantity"] for r in rows] == ["x", "y"], rows
    assert rows[0]["measured"] == 0.5 and rows[1]["note"] == "a | note"
    assert (checks.status(a), checks.status(b), checks.status(c)) == (1, 0, 1)
    lines, failed, total = checks.table([b, a, c])
    assert (failed, total) == (2, 4), (failed, total)
    order = [line.split(" | ")[:2] for line in lines[2:]]
    assert [r[0] for r in order] == ["| a", "| c", "| b", "| a"], order
    assert [order[i][1] for i in (0, 2, 3)] == ["y", "z", "x"], order
    assert "**FAIL**" in lines[2] and "no check" in lines[3], lines
    assert "pass" in lines[4] and "1e-12" in lines[4] and "1e-10" in lines[4]
    assert "a \\| note" in lines[2], lines[2]
    return "%d rows, %d FAIL first" % (total, failed)


@test
def geometry_matches_openfoam(tmp):
    if shutil.which("postProcess") is None:
        return "SKIP (OpenFOAM not in the PATH)"
    worst = []
    for tutorial, n in (("twistingColumn", 2), ("unstructuredCube", 2)):
        case = prepare(tutorial, os.path.join(tmp, tutorial), n=n,
                       control={"writePrecision": 17}, initialise=False)
        # OpenFOAM's own centres and volumes, for comparison only
        frun.run(["postProcess", "-func", "writeCellCentres", "-time", "0"],
                 case, "writeCellCentres")
        frun.run(["postProcess", "-func", "writeCellVolumes", "-time", "0"],
                 case, "writeCellVolumes")
        m = mesh.PolyMesh(case)
        C = foamfile.read_field(os.path.join(case, "0", "C")).internal(
            m.n_cells)
        V = foamfile.read_field(os.path.join(case, "0", "V")).internal(
            m.n_cells)
        ec = np.abs(m.cell_centres - C).max()
        ev = np.abs(m.cell_volumes - V).max() / V.max()
        assert ec < 1e-14 and ev < 1e-14, (tutorial, ec, ev)
        volume = 6.0 if tutorial == "twistingColumn" else 1.0
        assert abs(m.cell_volumes.sum() - volume) < 1e-12
        worst.append("%s %d cells: |dC| %.1e, |dV|/V %.1e"
                     % (tutorial, m.n_cells, ec, ev))
    return "; ".join(worst)


@test
def hertz_closed_form(tmp):
    """Hertz: two equal balls at +-V/2 are one ball on a wall at V/2 (each
    ball's share of the approach), the closed form's t_c = 2.94 delta/V
    against its other form 2.868 (m*^2/(R* E*^2 V))^(1/5) and against the
    integrated m* delta'' = -4/3 E* sqrt(R*) delta^(3/2)."""
    wall = hertz.closed_form(5.0, 0.01, 2e11, 0.3, 7800)
    pair = hertz.closed_form(10.0, 0.01, 2e11, 0.3, 7800,
                             0.01, 2e11, 0.3, 7800)
    eF = abs(pair["F"] / wall["F"] - 1)
    ed = abs(pair["delta"] / (2 * wall["delta"]) - 1)
    assert eF < 1e-12 and ed < 1e-12, (eF, ed)
    r = hertz.closed_form(10.0, 0.01, 7e10, 0.33, 2700,
                          0.02, 2e11, 0.3, 7800)
    other = 2.868 * (r["mstar"] ** 2 / (r["Rstar"] * r["Estar"] ** 2
                                        * 10.0)) ** 0.2
    e_form = abs(other / r["tc"] - 1)
    assert e_form < 2e-3, e_form
    t, F = hertz.force_curve(r, 10.0)
    e_ode = abs(t[-1] / r["tc"] - 1)
    e_peak = abs(F.max() / r["F"] - 1)
    assert e_ode < 3e-3 and e_peak < 1e-6, (e_ode, e_peak)
    return ("pair = wall at V/2 to %.0e; t_c forms agree to %.1e, the ODE's "
            "t_c to %.1e, its peak force to %.0e" % (max(eF, ed), e_form,
                                                   e_ode, e_peak))


def main():
    failed = 0
    root = tempfile.mkdtemp(prefix="touchfoamTest.")
    for fn in TESTS:
        tmp = os.path.join(root, fn.__name__)
        os.makedirs(tmp)
        try:
            msg = fn(tmp)
            print("PASS %s: %s" % (fn.__name__, msg))
        except Exception as err:  # report every failure, then carry on
            failed += 1
            print("FAIL %s: %s" % (fn.__name__, err or type(err).__name__))
            traceback.print_exc(file=sys.stderr)
    if not failed:
        shutil.rmtree(root)
    else:
        print("(work files kept in %s)" % root)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
