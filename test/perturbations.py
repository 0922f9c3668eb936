#!/usr/bin/python3
"""Show that every group of reference tests fails when its reference or the
code it checks is perturbed.

    . etc/bashrc
    /usr/bin/python3 test/perturbations.py [--list] [name ...]

A test that passes whatever the code does proves nothing.  For each group
of tests against an independent reference (issue: the twisting column's
converged twist, the swinging cube's closed form over a period, the bar on
the rigid wall against the 1D closed form, the ring's end of contact
against its mesh-converged value, the temporal order, the stable
step's closed form, the Riemann solver's closed-form fluxes, the laws'
closed-form stresses, the strain energy recomputed from F) this script
runs the group's test once with a perturbation and asserts that it fails:

  reference   the test's own option perturbs its reference (a converged
              twist 5 deg off, a frequency 1 % off, an expected order one
              higher, mu 0.1 % off in the energy formula): no code change;
  setting     the case is run with another scheme setting (first order
              instead of linear reconstruction): the numbers move;
  code        one line of the library is changed (a factor of 1.01 or
              1.05 in a stress, a wave speed, a step, a Runge-Kutta
              weight), libTOUCH rebuilt, the test run, and the line and
              the library restored and rebuilt whatever happens.  Refused
              when the file has changes not committed to git (nothing a
              user wrote is touched).

Each perturbation passes when the test exits non-zero and prints FAIL.
The unperturbed tests are the controls: ./Alltest runs them and they
pass.  Writes test/perturbations.md (the table: group, perturbation, what
the test printed) and exits 1 when a perturbed test still passed.  About
15 minutes on one core (four rebuilds of one library file).
"""

import argparse
import datetime
import os
import re
import subprocess
import sys
import time

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
PYTHON = "/usr/bin/python3"


def case_test(name, *options):
    return [PYTHON, os.path.join(TOP, "test", "cases", name + ".py")] \
        + list(options)


def unit_test(app):
    """A Test-* application on the hexahedral unit mesh Alltest makes."""
    return ["./Alltest", "-unit"], app


#: name: (group, kind, description, command, code change or None).
#: A code change is (file, the exact text, its replacement).
PERTURBATIONS = [
    ("twistReference", "twisting column", "reference",
     "converged twist 337.2 deg instead of 332.2",
     case_test("twistingColumnConvergence", "--reference", "337.2"), None),
    ("twistFirstOrder", "twisting column", "setting",
     "reconstruction firstOrder",
     case_test("twistingColumnConvergence", "--touch",
               "reconstruction=firstOrder"), None),
    ("cubeFrequency", "swinging cube", "reference",
     "closed-form frequency 1 % high",
     case_test("swingingCubePeriod", "--omega-scale", "1.01", "--skip-tet"),
     None),
    ("cubeShearModulus", "swinging cube", "code",
     "linear elastic stress with 1.01 mu",
     case_test("swingingCubePeriod", "--skip-tet"),
     ("src/TOUCH/mechanicalLaws/linearElastic/linearElastic.C",
      "return mu_*(F + F.T() - 2*tensor::I)",
      "return 1.01*mu_*(F + F.T() - 2*tensor::I)")),
    ("reboundFirstOrder", "bar on the rigid wall", "setting",
     "reconstruction firstOrder",
     case_test("rigidWallBounce", "--perturb-reconstruction", "firstOrder"),
     None),
    ("wallImpedance", "bar on the rigid wall", "code",
     "the wall's acoustic impedance 1.02 Up",
     case_test("rigidWallBounce"),
     ("src/TOUCH/contact/rigidWall/"
      "rigidWallFvPatchVectorFieldFlux.C",
      "nn & (s.t[facei] - s.Up[facei]*(s.p[facei] - wallMomentum));",
      "nn & (s.t[facei] - 1.02*s.Up[facei]*(s.p[facei] - wallMomentum));")),
    ("orderExpected", "temporal order", "reference",
     "RK2 expected at order 3",
     case_test("timeOrder", "--schemes", "RK2", "--expect", "3"), None),
    ("rk3Weight", "temporal order", "code",
     "RK3 third-stage weight 0.34 instead of 1/3",
     case_test("timeOrder", "--schemes", "RK3"),
     ("src/TOUCH/rungeKutta/rungeKutta.C",
      "return scalarList({0, 0.75, 1.0/3.0});",
      "return scalarList({0, 0.75, 0.34});")),
    ("stableStepCode", "stable step", "code",
     "dt 1.05 times CFL h/Up",
     case_test("stableStep"),
     ("src/TOUCH/stableTimeStep/stableTimeStep.C",
      "return CFL_*returnReduce(crossing, minOp<scalar>())/Up_;",
      "return 1.05*CFL_*returnReduce(crossing, minOp<scalar>())/Up_;")),
    ("riemannShear", "Riemann solver", "code",
     "shear upwinding with 1.01 Us",
     unit_test("Test-riemannSolver"),
     ("src/TOUCH/riemannSolvers/acoustic/acoustic.C",
      "tC = 0.5*(tL + tR) + 0.5*(Up_*dpn + Us_*(dp - dpn));",
      "tC = 0.5*(tL + tR) + 0.5*(Up_*dpn + 1.01*Us_*(dp - dpn));")),
    ("neoHookeanStress", "laws' closed-form stresses", "code",
     "neo-Hookean volumetric stress with 1.01 kappa",
     unit_test("Test-mechanicalLaws"),
     ("src/TOUCH/mechanicalLaws/neoHookean/neoHookean.C",
      "+ kappa_*(J - 1)*H;",
      "+ 1.01*kappa_*(J - 1)*H;")),
    ("ringReference", "ring on the rigid wall", "reference",
     "converged contact duration 3 % longer",
     case_test("ringReference", "--reference-scale", "contactDuration=1.03"),
     None),
    ("ringFirstOrder", "ring on the rigid wall", "setting",
     "reconstruction firstOrder",
     case_test("ringReference", "--touch", "reconstruction=firstOrder"),
     None),
    ("strainEnergyMu", "strain energy from F", "reference",
     "mu 0.1 % high in the energy formula",
     case_test("strainEnergyFromF", "--mu-scale", "1.001"), None),
]


def run(command, log):
    with open(log, "w") as f:
        proc = subprocess.run(command, cwd=TOP, stdout=f,
                              stderr=subprocess.STDOUT)
    with open(log) as f:
        return proc.returncode, f.read()


def rebuild(log):
    status, text = run(["wmake", "libso", "src/TOUCH"], log)
    if status != 0:
        raise RuntimeError("libTOUCH did not build (%s)" % log)


def dirty(path):
    out = subprocess.run(["git", "status", "--porcelain", "--", path],
                         cwd=TOP, capture_output=True, text=True)
    return out.returncode != 0 or out.stdout.strip() != ""


def verdict_of(status, text, command):
    """(failed, the line saying so)."""
    if isinstance(command, tuple):
        # Alltest -unit: the application's verdict, and the first check
        # that failed from its own log
        app = command[1]
        failed = any(l.split()[:2] == ["FAIL", app]
                     for l in text.split("\n") if l.strip())
        log = os.path.join(TOP, "test", "runs", "log." + app)
        first = ""
        if os.path.isfile(log):
            first = next((l.strip() for l in open(log)
                          if l.strip().startswith("FAIL")), "")
        return failed, "%s: %s" % (app, first or "no FAIL line in its log")
    lines = [l.strip() for l in text.split("\n")
             if l.strip().startswith("FAIL ")]
    return status != 0 and bool(lines), (lines[0] if lines else
                                         text.strip()[-300:])


def perturb(entry, logs):
    name, group, kind, what, command, change = entry
    log = os.path.join(logs, name + ".log")
    argv = command[0] if isinstance(command, tuple) else command
    if change is None:
        status, text = run(argv, log)
        return verdict_of(status, text, command)
    path, old, new = change
    source = os.path.join(TOP, path)
    if dirty(path):
        raise RuntimeError("%s has uncommitted changes: not touched" % path)
    with open(source) as f:
        original = f.read()
    if original.count(old) != 1:
        raise RuntimeError("%s: the line to perturb is not there once: %s"
                           % (path, old))
    try:
        with open(source, "w") as f:
            f.write(original.replace(old, new))
        rebuild(os.path.join(logs, name + ".build.log"))
        status, text = run(argv, log)
        return verdict_of(status, text, command)
    finally:
        with open(source, "w") as f:
            f.write(original)
        rebuild(os.path.join(logs, name + ".restore.log"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("names", nargs="*")
    parser.add_argument("--list", action="store_true")
    args = parser.parse_args()
    known = [p[0] for p in PERTURBATIONS]
    for name in args.names:
        if name not in known:
            print("perturbations: no perturbation '%s'; valid: %s"
                  % (name, " ".join(known)), file=sys.stderr)
            return 1
    chosen = [p for p in PERTURBATIONS
              if not args.names or p[0] in args.names]
    if args.list:
        for p in chosen:
            print("%-18s %-28s %-9s %s" % (p[0], p[1], p[2], p[3]))
        return 0

    logs = os.path.join(TOP, "test", "runs", "perturbations")
    os.makedirs(logs, exist_ok=True)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=TOP,
                            capture_output=True, text=True).stdout.strip()
    rows, stayed = [], []
    start = time.time()
    for entry in chosen:
        t0 = time.time()
        failed, line = perturb(entry, logs)
        seconds = time.time() - t0
        print("%-18s %s (%.0f s): %s" % (entry[0], "fails as it must"
                                          if failed else "STILL PASSES",
                                          seconds, line[:200]), flush=True)
        if not failed:
            stayed.append(entry[0])
        rows.append("| %s | %s | %s | %s | %s |" % (
            entry[1], entry[2], entry[3],
            "fails" if failed else "**still passes**",
            line.replace("|", "/")[:240]))

    # The page of the whole list; a selection's goes with the logs
    page = os.path.join(TOP, "test", "perturbations.md") if not args.names \
        else os.path.join(logs, "perturbations.md")
    with open(page, "w") as f:
        f.write("# Perturbed references and code\n\n"
                "`test/perturbations.py` (its docstring says how): each group"
                " of reference tests run with its reference or the code"
                " perturbed must fail.  Run on %s at commit %s in %.0f s.\n\n"
                "| group | kind | perturbation | verdict | the test's"
                " first failure |\n|---|---|---|---|---|\n"
                % (datetime.date.today().isoformat(), commit,
                   time.time() - start))
        f.write("\n".join(rows) + "\n")
    print("wrote %s; %d of %d perturbations failed the test as they must"
          % (os.path.relpath(page, TOP), len(rows) - len(stayed), len(rows)))
    return 1 if stayed else 0


if __name__ == "__main__":
    sys.exit(main())
