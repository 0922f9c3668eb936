#!/usr/bin/python3
"""Our pictures and plots beside the seed paper's figures.

    ./seedFigures.py [--quick] [--only TUTORIAL ...]

The seed paper (Haider, Lee, Gil, Bonet, Huerta, 2016; doc/benchmarks.md
sections 1-6) shows six examples in figures 2-10.  Its figures are not
available to us as pictures, only their captions and the text around them,
so for each example this script writes, in section.md, what the seed
figure shows and the values its text and axes give (in our words), and
beside it our picture or plot of the same view and time with our numbers
and their references:

  1 swingingCube    figure 2: the L2 errors against h at t = 0.004 s: the
                    plot of the swingingCube study of the same run
                    (../swingingCube/convergence.png and results.json,
                    not run here)
  2 twistingColumn  figure 3: the column at 0.1 s, pressure (render.py)
  3 taylorImpact    figure 5: pressure and plastic strain at 10-80 us
  4 barRebound      figures 6, 7: pressure at 30-270 us, end displacements
  5 ringImpact      figures 8, 9: pressure at 0.18 s, momentum histories
  6 torusImpact     figure 10: pressure at 2-38 ms

Tutorials 2-6 run here through their own ./Allrun -n N in runs/<tutorial>
(which ends with render.py under pvbatch, plot.py and tutorialResults), one
at a time, on the tutorial's default mesh or, with --quick, a coarse one
(QUICK: seconds each, the pictures still show the body and its colours;
the numbers of a coarse mesh are far from converged, and the section says
so).  Where ParaView (pvbatch, xvfb-run) or matplotlib is not installed,
or a picture was not made, the section says so in place of the picture:
it never links to a file that is not there.  Links are relative to
validation/README.md, where validation/Allrun puts the section ('Beside
the seed figures').

Checks (checks.json): each tutorial's Allrun ran to its end and printed
its headline numbers.
"""

import argparse
import json
import os
import shutil
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, ".."))  # validation/ or its copy
sys.path.insert(0, os.path.join(HERE, "..", "..", "bin", "python"))

import numpy as np  # noqa: E402

from touchfoam import checks, postprocess, run  # noqa: E402
from touchfoam.figures import slab_thickness  # noqa: E402
from touchfoam.monitor import read_monitor  # noqa: E402

#: the report the links are relative to: validation/README.md
REPORT_DIR = os.path.join(os.path.dirname(TOP), "validation")

#: tutorial: (-n of the default run, -n of the quick run)
SIZES = {"twistingColumn": (8, 4), "taylorImpact": (6, 2),
         "barRebound": (6, 2), "ringImpact": (96, 48),
         "torusImpact": (16, 8)}

#: What each seed figure shows, in our words, and the values the seed's
#: text, captions and axes give.  pictures: [(file, caption)]; rows: the
#: tutorialResults rows (name as printed) shown as ours; seed: {row name:
#: the seed's value}.
EXAMPLES = [
    ("swingingCube", "Swinging cube", "figure 2",
     "Two log-log plots of the L2 norm of the error against the grid size "
     "h at t = 0.004 s: (a) the three velocity components, (b) the three "
     "diagonal components of the first Piola stress, on h = 1/4 to 1/32 "
     "with a slope-2 line: both converge at second order.  The norm's "
     "normalisation is not stated; the values read off the plot are "
     "about 2.2e-5 (velocity) and 2.1e-5 (stress) on h = 1/4, 1.8e-7 "
     "and 2.1e-7 on h = 1/32.  Ours: the same plot from the swingingCube "
     "study (our norm, stated in its results.md; the seed's values are "
     "drawn dashed), linear reconstruction.",
     [], [], {}),
    ("twistingColumn", "Twisting column", "figure 3",
     "The column (1 x 6 x 1 m, base clamped, nu = 0.45, initial angular "
     "velocity 105 sin(pi Y/12) rad/s about its axis) deformed at "
     "t = 0.1 s and coloured by pressure, on 4 x 24 x 4, 8 x 48 x 8 and "
     "40 x 240 x 40 cells, seen from above a corner: the pressure is "
     "smooth on every mesh.  The seed gives no number for the twist; "
     "figure 4 (nu = 0.495, other methods) is not reproduced.",
     [("pressure_0.1s.png", "pressure at 0.1 s"),
      ("sigmaEq_0.1s.png", "von Mises stress at 0.1 s")],
     ["twist of the top face at 0.1 s", "total energy at the end / E0",
      "smallest J = det F (written times)"],
     {"twist of the top face at 0.1 s": "not given"}),
    ("taylorImpact", "Taylor impact", "figure 5",
     "A quarter of the copper bar (r0 = 3.2 mm, L = 32.4 mm, 227 m/s onto "
     "a rigid wall), deformed and coloured by (a) pressure and (b) "
     "equivalent plastic strain at 10, 30, 50 and 80 us: the foot "
     "spreads into a mushroom and both fields are smooth.  The seed gives "
     "no final dimensions; the references are the literature's "
     "(doc/benchmarks.md 3).",
     [("pressure_%s.png" % t, "pressure at %s" % t)
      for t in ("10us", "30us", "50us", "80us")]
     + [("epsilonP_%s.png" % t, "plastic strain at %s" % t)
        for t in ("10us", "30us", "50us", "80us")],
     ["final length [mm]", "foot radius [mm]",
      "peak equivalent plastic strain"],
     {"final length [mm]": "not given", "foot radius [mm]": "not given",
      "peak equivalent plastic strain": "not given"}),
    ("barRebound", "Bar rebound", "figures 6 and 7",
     "Figure 6: the bar (neo-Hookean, E = 585 MPa, 150 m/s, 4 mm above the "
     "wall) deformed and coloured by pressure at five times labelled 3, "
     "6, 12, 18 and 27; the text puts the deepest compression, all the "
     "kinetic energy stored, at '12 ms', which can only be 120 us for a "
     "bar whose 2L/c0 is 0.25 ms, so we read the labels as 30 to 270 us.  "
     "Figure 7: the vertical displacement of the centres of the top and "
     "bottom faces against time to 0.3 ms on 2,880 and 23,040 cells "
     "(axis -20 to +8 mm): the two meshes' curves lie on each other.",
     [("pressure_%s.png" % t, "pressure at %s" % t)
      for t in ("30us", "60us", "120us", "180us", "270us")]
     + [("histories.png", "end displacements and momenta (figure 7)")],
     ["contact starts [us]", "deepest compression [us]", "separation [us]",
      "velocity at the end [m/s]", "total energy at the end / E0"],
     {"deepest compression [us]": "120 (text: '12 ms')",
      "contact starts [us]": "26.67 (gap 4 mm / 150 m/s)"}),
    ("ringImpact", "Ring impact", "figures 8 and 9",
     "Figure 8: the rubber ring (radii 0.03 and 0.04 m, 0.59 m/s, 4 mm "
     "above the wall) deformed and coloured by pressure at t = 0.18 s on "
     "420 and 6,400 cells: the same shape on both.  Figure 9: the three "
     "components of (a) the linear momentum and (b) the angular momentum "
     "against time to 0.04 s on 420, 3,660 and 25,760 cells: p_y starts "
     "near -1.3 kg m/s (axis -1.5 to 1.5; -M v0 = -1.297 per metre of "
     "thickness), turns positive through the contact, and p_x, p_z and "
     "the angular momentum stay at zero.",
     [("pressure_180ms.png", "pressure at 0.18 s (figure 8)"),
      ("histories.png", "momenta (figure 9)")],
     ["p_y(0) per metre [kg m/s]", "max |p_x|, |p_z| / |p_y(0)|",
      "max |L| / (|p_y(0)| R)", "contact starts [ms]", "last contact [ms]",
      "p_y at the end / |p_y(0)|"],
     {"p_y(0) per metre [kg m/s]": "about -1.3 (axis)",
      "max |p_x|, |p_z| / |p_y(0)|": "0 (drawn flat)",
      "max |L| / (|p_y(0)| R)": "0 (drawn flat)",
      "p_y at the end / |p_y(0)|": "> 0 (reverses)"}),
    ("torusImpact", "Torus impact", "figure 10",
     "The rubber torus (inner radius 0.03, outer 0.04 m, 3 m/s onto the "
     "wall) deformed and coloured by pressure at 2, 4, 8, 17, 28 and "
     "38 ms: it flattens on the wall and rebounds; at impact its outer "
     "part is in compression and its inner part in tension, with a "
     "smooth pressure.",
     [("pressure_%s.png" % t, "pressure at %s" % t)
      for t in ("2ms", "4ms", "8ms", "17ms", "28ms", "38ms")],
     ["contact starts [ms]", "last contact [ms]", "p_y at the end / |p_y(0)|",
      "smallest J = det F (written times)", "total energy at the end / E0"],
     {"smallest J = det F (written times)": "> 0 (no inverted cell)"}),
]


def have(*programs):
    return all(shutil.which(p) for p in programs)


def link(path):
    return os.path.relpath(path, REPORT_DIR)


def read_rows(case):
    """{quantity: (measured, reference)} of log.tutorialResults (its rows
    are '  %-36s %-24s %-22s %s')."""
    path = os.path.join(case, "log.tutorialResults")
    rows = {}
    if not os.path.exists(path):
        return rows
    with open(path) as f:
        for line in f:
            if not line.startswith("  ") or len(line) < 40:
                continue
            rows[line[2:38].strip()] = (line[39:63].strip(),
                                        line[64:86].strip())
    return rows


def extra_rows(tutorial, case, rows):
    """Values the seed figure shows that tutorialResults does not print."""
    try:
        mon = read_monitor(case)
    except (OSError, ValueError):
        return
    if tutorial == "barRebound":
        deepest = mon["Time"][int(np.argmin(mon["kineticEnergy"]))]
        rows["deepest compression [us]"] = (
            "%.1f" % (1e6 * deepest), "least kinetic energy")
    elif tutorial == "ringImpact":
        p0 = postprocess.initial_momenta(case)[0]
        rows["p_y(0) per metre [kg m/s]"] = (
            "%.4f" % (p0[1] / slab_thickness(case, axis=2)),
            "-M v0 = -1.297")


def run_tutorial(tutorial, n, case):
    run.copy_case(run.tutorial_dir(tutorial), case)
    start = time.time()
    error = None
    try:
        run.run(["./Allrun", "-n", str(n)], case, "Allrun",
                env={"TOUCH_N": ""})
    except run.RunError as err:
        error = str(err).split("\n")[0]
    return time.time() - start, error


def why_missing(case, name):
    """Why the picture or plot 'name' is not there, in one phrase."""
    if name == "histories.png":
        if not _matplotlib() or "plots skipped" in _log(case):
            return "not made: matplotlib is not installed here " \
                   "(bin/touchSetup --with-plots)"
        return "not made: plot.py failed (log.plot.py)"
    if not have("pvbatch", "xvfb-run"):
        return "not made: ParaView (pvbatch) or xvfb-run is not " \
               "installed here (bin/touchSetup --with-paraview)"
    if "pictures skipped" in _log(case):
        return "not made: %s" % [l for l in _log(case).splitlines()
                                 if "pictures skipped" in l][0]
    return "not made: render.py did not write it (the run did not reach " \
           "that time, or see log.xvfb-run.render)"


def _log(case):
    path = os.path.join(case, "log.Allrun")
    if not os.path.exists(path):
        return ""
    with open(path) as f:
        return f.read()


def pictures_md(case, pictures):
    shown, missing = [], []
    for name, caption in pictures:
        path = os.path.join(case, name)
        if os.path.exists(path) and os.path.getsize(path) > 0:
            shown.append("![%s](%s)" % (caption, link(path)))
        else:
            missing.append("- %s (%s): %s" % (caption, name,
                                              why_missing(case, name)))
    out = []
    if shown:
        out += [" ".join(shown), ""]
    if missing:
        out += ["Pictures not made:", ""] + missing + [""]
    return out


def cube_md(quick):
    """Seed figure 2: the swingingCube study's plot and numbers."""
    study = os.path.join(TOP, "swingingCube")
    out = []
    png = os.path.join(study, "convergence.png")
    results = os.path.join(study, "results.json")
    ran = os.path.exists(results) and (not quick or os.path.exists(
        os.path.join(study, "results.md")))
    if ran and os.path.exists(png) and os.path.getsize(png) > 0:
        out += ["![L2 errors against h at 0.004 s (swingingCube study)]"
                "(%s)" % link(png), ""]
    elif ran:
        out += ["Plot not made: convergence.png is not there (matplotlib "
                "not installed: bin/touchSetup --with-plots).", ""]
    else:
        out += ["Plot not made: the swingingCube study was not run in this "
                "report (validation/Allrun%s swingingCube)."
                % (" -quick" if quick else ""), ""]
        return out, False
    with open(results) as f:
        r = json.load(f)
    scheme = "linear" if "linear" in r["schemes"] else next(iter(r["schemes"]))
    data = r["schemes"][scheme]
    h = r["h"]
    out += ["| quantity | seed (read off figure 2) | ours (%s) | reference |"
            % scheme, "|---|---|---|---|"]
    ref = r["reference"]
    for comp, key in (("vx", "velocity"), ("Pxx", "stress")):
        for i, hh in enumerate(h):
            seed = ref[key][ref["h"].index(hh)] if hh in ref["h"] else None
            out.append("| L2 error of %s, h = 1/%d | %s | %.2e | closed form "
                       "(different norm) |" % (comp, round(1 / hh),
                                               "%.1e" % seed if seed else "-",
                                               data[comp]["L2"][i]))
        orders = [o for o in data[comp]["orders"] if o is not None]
        if orders:
            out.append("| observed order of %s, h = 1/%d to 1/%d | 2 | %.2f "
                       "| 2 |" % (comp, round(1 / h[-2]), round(1 / h[-1]),
                                  orders[-1]))
    return out + [""], True


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true",
                        help="coarse meshes (validation/Allrun -quick)")
    parser.add_argument("--only", nargs="+", choices=[e[0] for e in EXAMPLES],
                        help="only these examples (the others are listed "
                        "as not run)")
    args = parser.parse_args()
    run.check_openfoam()
    checks.start(HERE)
    lines = [
        "The seed paper's figures are not available to us as pictures: for "
        "each of its six examples, what its figure shows and the values its "
        "text and axes give, in our words, and beside it our picture or plot "
        "of the same view and time with our numbers.  %s  Where a picture "
        "could not be made the reason is given in its place."
        % ("Coarse meshes (-quick): the pictures show the fields' pattern; "
           "the numbers are a coarse mesh's, not the published ones "
           "(the tutorials' READMEs)." if args.quick else
           "The tutorials' default meshes."),
        "",
        "ParaView (pictures): %s.  matplotlib (plots): %s."
        % ("installed" if have("pvbatch", "xvfb-run") else
           "**not installed** (bin/touchSetup --with-paraview)",
           "installed" if _matplotlib() else
           "**not installed** (bin/touchSetup --with-plots)"), ""]
    failed = 0
    for number, (tutorial, title, figure, seed_text, pictures, wanted,
                 seed) in enumerate(EXAMPLES, 1):
        if args.only and tutorial not in args.only:
            lines += ["### %d. %s (seed %s)" % (number, title, figure), "",
                      "Not run in this report (--only).", ""]
            continue
        if tutorial == "swingingCube":
            lines += ["### %d. %s (seed %s; the swingingCube study)"
                      % (number, title, figure), "",
                      "**Seed %s.** %s" % (figure, seed_text), ""]
            cube, ok = cube_md(args.quick)
            lines += cube
            checks.record(HERE, "%s: the study's plot and errors" % tutorial,
                          "there" if ok else "not run", "there", ok,
                          "../swingingCube/results.json")
            failed += not ok
            continue
        n = SIZES[tutorial][1 if args.quick else 0]
        case = os.path.join(HERE, "runs", tutorial)
        print("running %s -n %d in %s" % (tutorial, n, case), flush=True)
        seconds, error = run_tutorial(tutorial, n, case)
        rows = read_rows(case)
        extra_rows(tutorial, case, rows)
        ok = error is None and bool(rows)
        checks.record(HERE, "%s -n %d: Allrun ran, headline numbers printed"
                      % (tutorial, n), "yes" if ok else "no", "yes", ok,
                      error or "%.0f s" % seconds)
        failed += not ok
        lines += ["### %d. %s (seed %s; `tutorials/%s/Allrun -n %d`, "
                  "%.0f s)" % (number, title, figure, tutorial, n, seconds),
                  "", "**Seed %s.** %s" % (figure, seed_text), ""]
        if error:
            lines += ["**The run failed**: %s (%s/log.Allrun)."
                      % (error, link(case)), ""]
        lines += pictures_md(case, pictures)
        lines += ["| quantity | seed | ours | reference |",
                  "|---|---|---|---|"]
        for name in wanted:
            measured, reference = rows.get(name, ("not printed", ""))
            lines.append("| %s |" % " | ".join(
                cell.replace("|", "\\|") for cell in
                (name, seed.get(name, "-"), measured, reference)))
        lines.append("")
    with open(os.path.join(HERE, "section.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %s" % os.path.join(HERE, "section.md"))
    return checks.status(HERE)


def _matplotlib():
    try:
        import matplotlib  # noqa: F401
        return True
    except ImportError:
        return False


if __name__ == "__main__":
    sys.exit(main())
