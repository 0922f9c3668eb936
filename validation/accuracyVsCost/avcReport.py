"""results.md and the plots of accuracyVsCost.py: the table of a case's
runs, the text of its recommendation, and error against cost."""

import os

from avcAnalysis import (CASES, COST_TIE, ERROR_TIE, EXTRAPOLATE, MIN_TIMED,
                         TIME_SETTINGS, TWIST_BAND, TWIST_REFERENCE,
                         admissible, label, parse_label, pareto)
import convergence  # validation/swingingCube, on sys.path (avcAnalysis)


def _f(x, fmt):
    return "-" if x is None else fmt % x


def table(name, rows):
    cube = name == "swingingCube"
    head = ["n", "cells", "setting", "round", "steps", "loop CPU [s]",
            "repeats", "us/cell-stage", "user CPU [s]", "wall [s]"]
    head += (["e(v)/(U0 w)", "e(P)/P_amp", "error"] if cube
             else ["twist 0.1 s [deg]", "error [deg]"])
    head += ["dE/E0 max", "E_end/E0", "front"]
    lines = ["| " + " | ".join(head) + " |",
             "|" + "|".join("---" for _ in head) + "|"]
    for r in rows:
        e = r.get("energy", {})
        cells = [str(r["n"]), _f(r.get("cells"), "%d"), r["setting"],
                 _f(r.get("round"), "%d"), _f(r.get("steps"), "%d"),
                 _f(r.get("cost"), "%.2f"), str(r["repeats"]),
                 _f(r.get("usPerCellStage"), "%.2f"),
                 _f(r.get("userCPU"), "%.2f"), _f(r.get("wall"), "%.2f")]
        if cube:
            cells += [_f(r.get("velocity"), "%.2e"),
                      _f(r.get("stress"), "%.2e"), _f(r.get("error"), "%.2e")]
        else:
            cells += [_f(r.get("twistDeg"), "%.1f"),
                      _f(r.get("signedErrorDeg"), "%+.1f")]
        cells += [_f(e.get("maxGrowth"), "%.1e"), _f(e.get("kept"), "%.3f"),
                  "**yes**" if r["onFront"] else ""]
        lines.append("| " + " | ".join(cells) + " |")
    failed = [r for r in rows if r.get("runError")]
    if failed:
        lines += ["", "Runs that stopped:"] + [
            "- %s n = %d: %s" % (r["setting"], r["n"], r["runError"])
            for r in failed]
    return "\n".join(lines)


def recommendation_text(name, out):
    rec, chk = out["recommended"], out.get("energyCheck")
    if not rec:
        return "No recommendation: the tutorial's setting was not run."
    fmt = "%.3g deg" if name == "twistingColumn" else "%.3g"
    grows = [x["setting"] for x in rec["ranking"] if x["energyGrows"]]
    text = ["Reference: the tutorial's setting %s on n = %d, %.2f s of loop "
            "CPU, error %s; its error %s with every refinement."
            % (rec["defaultSetting"], rec["mesh"], rec["referenceCost"],
               fmt % rec["referenceError"],
               "falls" if rec["defaultConverges"] else "does NOT fall"), ""]
    if rec["rule"] == "equalCost":
        text += ["Each setting's error at the reference's cost and its cost "
                 "at the reference's error, interpolated in log-log along "
                 "its meshes (x: extrapolated at most %gx beyond the finest "
                 "mesh's cost; E: gained energy in a step on some mesh):"
                 % EXTRAPOLATE, "",
                 "| setting | error at %.2f s | loop CPU for error %s |"
                 % (rec["referenceCost"], fmt % rec["referenceError"]),
                 "|---|---|---|"]
        for x in rec["ranking"]:
            text.append("| %s%s%s | %s | %s |" % (
                x["setting"], " x" if x["extrapolated"] else "",
                " E" if x["energyGrows"] else "",
                _f(x["errorAtCost"], fmt), _f(x["costAtError"], "%.2f s")))
    else:
        text += ["The error is then no discretisation error that refinement "
                 "removes (a smaller one on a coarser mesh is a "
                 "cancellation), so the settings are compared on n = %d: the "
                 "cheapest whose %s is within %g of the reference setting's "
                 "(%.1f; E: gained energy in a step on some mesh):"
                 % (rec["mesh"], rec["quantity"], rec["tolerance"],
                    rec["referenceQuantity"]), "",
                 "| setting | loop CPU [s] | %s | difference |"
                 % rec["quantity"], "|---|---|---|---|"]
        for x in rec["ranking"]:
            text.append("| %s%s | %.2f | %.1f | %+.1f%s |" % (
                x["setting"], " E" if x["energyGrows"] else "", x["cost"],
                x["quantity"], x["deviation"],
                "" if x["within"] else " (outside)"))
    if len(rec.get("tied", [])) > 1:
        text += ["", ("Within %.0f %% of the cheapest loop time (a tie, won "
                      "by the smaller difference): %s." if rec["rule"] ==
                      "tolerance" else "Within %.0f %% of the least error "
                      "at that cost (a tie within the timing noise): %s.")
                 % (100 * (COST_TIE if rec["rule"] == "tolerance"
                           else ERROR_TIE), ", ".join(rec["tied"]))]
    text += ["", "Recommended (energy never grew in its runs): **%s**%s.  "
             "Pareto front on n = %d (cheapest first): %s."
             % (rec["setting"], "" if rec["setting"] ==
                rec["bestIgnoringEnergy"] else
                " (%s ranks first but gained energy)"
                % rec["bestIgnoringEnergy"], rec["mesh"],
                ", ".join(rec["frontOnMesh"]))]
    if grows:
        text += ["", "Gained energy in a step on some mesh: %s."
                 % ", ".join(sorted(grows))]
    for i, chk in enumerate([chk] + out.get("energyCrossChecks", [])):
        if not chk:
            continue
        e = chk["energy"]
        text += ["", "%s of %s on n = %d to t = %g s (%d steps): largest "
                 "growth in a step %.1e E0, %d steps with growth, %.3f E0 "
                 "kept: %s." % ("Energy" if i == 0 else
                                "Cross-check (another case's "
                                "recommendation): energy",
                                chk["setting"], chk["n"], chk["endTime"],
                                chk["steps"], e["maxGrowth"],
                                e["stepsWithGrowth"], e["kept"],
                                ("never grows" + (" (pass)" if i == 0
                                                  else "")) if chk["pass"]
                                else "GROWS" + (" (fail)" if i == 0
                                                else ""))]
    return "\n".join(text)


def write_markdown(results, path):
    b = results["build"]
    lines = [
        "# Accuracy against cost: results", "",
        "Produced by `%s` on %s in %.0f s, build %s (libTOUCH.so md5 %s).  "
        "Cost: touchFoam time-loop CPU time (ExecutionTime, the mean of the "
        "repeats); 'user CPU' is the whole process (getrusage), 'wall' the "
        "process's wall time, both means of the repeats.  `round`: 0 "
        "one factor at a time around the tutorial's setting, k > 0 added by "
        "the front closure.  `dE/E0 max`: largest one-step growth of the "
        "total energy over E0 (<= 0: never grows).  `front`: on the Pareto "
        "front of all the case's admissible runs (end reached, energy never "
        "grew)." % (results["command"], results["date"],
                    results["duration"], b["label"],
                    (b["libTOUCHmd5"] or "?")[:12]), ""]
    for name, out in results["cases"].items():
        lines += ["## %s" % name, ""]
        if name == "swingingCube":
            lines += ["Errors at t = %g s relative to the amplitudes; error = "
                      "the larger of the two." % convergence.T_END, ""]
        else:
            lines += ["Twist at 0.1 s; error = twist - %g deg (reference band "
                      "%g-%g deg)." % ((TWIST_REFERENCE,) + TWIST_BAND), ""]
        lines += [table(name, out["rows"]), ""]
        summary = out["costPerCellStage"]
        if summary:
            lines += ["Loop CPU per cell and Runge-Kutta stage [us], min / "
                      "median / max over the runs of a reconstruction on a "
                      "mesh (runs of at least %g s of loop in all):"
                      % MIN_TIMED, "",
                      "| reconstruction | " + " | ".join(
                          "n = %s" % n for n in out["meshes"]) + " |",
                      "|---|" + "---|" * len(out["meshes"])]
            for rec, d in summary.items():
                lines.append("| %s | " % rec + " | ".join(
                    "%.2f / %.2f / %.2f" % tuple(d[n]) if n in d else "-"
                    for n in out["meshes"]) + " |")
            lines.append("")
        ref = [r for r in out["rows"] if r.get("loopCPUSpread") is not None
               and r["setting"] == label(CASES[name]["default"])
               and r["n"] == CASES[name]["tutorialMesh"]]
        if ref:
            lines += ["Timing noise: the %d repeats of %s on n = %d took %s s "
                      "of loop CPU (max - min: %.0f %% of the median)."
                      % (ref[0]["repeats"], ref[0]["setting"], ref[0]["n"],
                         ", ".join("%.2f" % x for x in ref[0]["loopCPUAll"]),
                         100 * ref[0]["loopCPUSpread"]), ""]
        lines += ["### Recommended", "", recommendation_text(name, out), ""]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def plot(name, out, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: %s skipped" % os.path.basename(path))
        return
    rows = [r for r in out["rows"] if r.get("cost") and r.get("error")]
    colours = {"firstOrder": "tab:red", "linear": "tab:blue",
               "limitedLinear": "tab:green"}
    markers = dict(zip(TIME_SETTINGS, "o^sDv"))
    panels = ([("error", "error: the larger of the two"),
               ("velocity", "L2 error of v / (U0 w)"),
               ("stress", "L2 error of P_ii / P amplitude")]
              if name == "swingingCube"
              else [("error", "|twist(0.1 s) - %g deg| [deg]"
                     % TWIST_REFERENCE), ("twistDeg", "twist at 0.1 s [deg]")])
    fig, axes = plt.subplots(1, len(panels), figsize=(5.5 * len(panels), 5.8))
    for ax, (key, ylabel) in zip(axes, panels):
        by_setting = {}
        for r in rows:
            by_setting.setdefault(r["setting"], []).append(r)
        for s, pts in sorted(by_setting.items()):
            rec, scheme, cfl = parse_label(s)
            pts = sorted(pts, key=lambda r: r["n"])
            ax.plot([p["cost"] for p in pts], [p[key] for p in pts],
                    color=colours[rec], marker=markers[(scheme, cfl)],
                    lw=0.6, ms=6, mfc="none" if scheme == "RK3" else
                    colours[rec], label=s)
        bad = [r for r in rows if not admissible(r)]
        if bad:
            ax.plot([p["cost"] for p in bad], [p[key] for p in bad], "kx",
                    ms=9, label="energy grew in a step")
        if key != "twistDeg":
            front = pareto(rows, key)
            ax.plot([p["cost"] for p in front], [p[key] for p in front],
                    "k-", lw=2, alpha=0.35, label="Pareto front")
            named = set()
            for p in front:
                if p["n"] not in named:
                    named.add(p["n"])
                    ax.annotate("n=%d" % p["n"], (p["cost"], p[key]),
                                textcoords="offset points", xytext=(-6, -12),
                                fontsize=7)
            ax.set_yscale("log")
            # a run that blew up would squash the others: keep it off
            good = [r[key] for r in rows if admissible(r)]
            if good:
                ax.set_ylim(0.5 * min(good), 3 * max(good))
                off = [r for r in rows if r[key] > 3 * max(good)]
                if off:
                    ax.text(0.02, 0.98, "off the scale: %s" % ", ".join(
                        "%s n=%d (%.2g)" % (r["setting"], r["n"], r[key])
                        for r in off), transform=ax.transAxes, fontsize=6,
                        va="top")
        if name == "twistingColumn":
            if key == "error":
                ax.axhspan(1e-3, TWIST_BAND[1] - TWIST_REFERENCE,
                           color="0.85", zorder=0,
                           label="inside the reference band")
            else:
                ax.axhspan(*TWIST_BAND, color="0.85", zorder=0,
                           label="reference band: %g-%g deg" % TWIST_BAND)
                # firstOrder dissipates the twist away: keep it off the scale
                kept = [r[key] for r in rows
                        if not r["setting"].startswith("firstOrder")]
                if kept:
                    ax.set_ylim(min(kept + [TWIST_BAND[0]]) - 5,
                                max(kept) + 5)
                low = [r for r in rows if r[key] < ax.get_ylim()[0]]
                if low:
                    ax.text(0.02, 0.02, "off the scale: %d runs at %.0f-%.0f "
                            "deg (%s)" % (len(low), min(r[key] for r in low),
                                          max(r[key] for r in low),
                                          ", ".join(sorted({r["setting"] for
                                                            r in low}))),
                            transform=ax.transAxes, fontsize=6)
                for n in sorted({r["n"] for r in rows}):
                    here = [r for r in rows if r["n"] == n and r[key] >=
                            ax.get_ylim()[0]]
                    if here:
                        p = min(here, key=lambda r: r["cost"])
                        ax.annotate("n=%d" % n, (p["cost"], p[key]),
                                    textcoords="offset points",
                                    xytext=(-8, 6), fontsize=7)
        ax.set_xscale("log")
        ax.set_xlabel("touchFoam time-loop CPU time [s]")
        ax.set_ylabel(ylabel)
        ax.grid(True, which="both", lw=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center",
               ncol=4 * len(panels) - 3, fontsize=7)
    fig.suptitle("%s: error against cost (colour: reconstruction; marker: "
                 "time scheme and CFL, open = RK3)" % name, fontsize=9)
    fig.tight_layout(rect=(0, 0.12, 1, 1))
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print("wrote %s" % path)
