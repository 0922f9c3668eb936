"""The comparisons of the two codes' runs and their report, for compare.py.

compare.py reads the runs into rows, one dict per run (code, variant,
wall, cpu, steps and the errors); from these this module finds

    fastest_as_accurate_twist   column: per CalculiX element, the fastest
                                touchFoam run whose twist error is at most
                                CalculiX's (and over the reference band)
    fastest_as_accurate         cube: the same for one error
    equal_wall                  each code's error at every run's wall time

and writes results.md, the tables in README.md and column.png, cube.png
(write_reports, plot).
"""

import math
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
BEGIN, END = "<!-- results -->", "<!-- /results -->"


# -- fastest as accurate ------------------------------------------------------

def fastest_as_accurate_twist(rows, ref, band):
    """Per CalculiX element: the fastest touchFoam run with error <= its."""
    out = {}
    tf = [r for r in rows if r["code"] == "touchFoam"]
    for c in (r for r in rows if r["code"] == "CalculiX"):
        ok = sorted((r for r in tf if r["error"] <= c["error"]),
                    key=lambda r: r["wall"])
        entry = {"calculixError": c["error"], "calculixWall": c["wall"],
                 "calculixCpu": c["cpu"], "setting": None}
        # With none as accurate: the most accurate one, for the band test
        best = ok[0] if ok else min(tf, key=lambda r: r["error"],
                                    default=None)
        if best is None:
            continue
        holds = [float(b) for b in band
                 if abs(best["twist"] - b) <= abs(c["twist"] - b)]
        entry.update({
            "setting": best["variant"] if ok else None,
            "mostAccurate": best["variant"], "error": best["error"],
            "twist": best["twist"], "calculixTwist": c["twist"],
            "wall": best["wall"], "cpu": best["cpu"],
            "wallRatio": c["wall"] / best["wall"],
            "cpuRatio": c["cpu"] / best["cpu"],
            # |t - r| <= |c - r| exactly when r is on t's side of (t + c)/2
            "crossover": 0.5 * (best["twist"] + c["twist"]),
            "holdsForReferences": [min(holds), max(holds)] if holds
            else None})
        out[c["variant"]] = entry
    return out


def fastest_as_accurate(rows, key):
    """Per CalculiX element: the fastest touchFoam run whose error `key`
    is at most CalculiX's, and the wall-time ratio (None: none is)."""
    out = {}
    for c in (r for r in rows if r["code"] == "CalculiX"):
        ok = sorted((r for r in rows if r["code"] == "touchFoam"
                     and r[key] <= c[key]), key=lambda r: r["wall"])
        out[c["variant"]] = {
            "calculixError": c[key], "calculixWall": c["wall"],
            "setting": ok[0]["variant"] if ok else None,
            "error": ok[0][key] if ok else None,
            "wall": ok[0]["wall"] if ok else None,
            "wallRatio": c["wall"] / ok[0]["wall"] if ok else None,
            "cpuRatio": c["cpu"] / ok[0]["cpu"] if ok else None}
    return out


# -- equal wall time ----------------------------------------------------------

def curves(result, key):
    """{label: [(wall, error, n)]} over the meshes, sorted by wall."""
    out = {}
    for n, mesh in result["meshes"].items():
        for r in mesh["runs"]:
            label = ("%s %s" % (r["code"], r["variant"]))
            out.setdefault(label, []).append((r["wall"], r[key], int(n)))
    return {k: sorted(v) for k, v in out.items()}


def at_wall(points, wall):
    """(error, extrapolated) of a curve at a wall time, log-log linear."""
    pts = [(w, e) for w, e, _ in points if w > 0 and e > 0]
    if len(pts) < 2:
        return None, None
    i = 0
    while i < len(pts) - 2 and wall > pts[i + 1][0]:
        i += 1
    (w1, e1), (w2, e2) = pts[i], pts[i + 1]
    slope = math.log(e2 / e1) / math.log(w2 / w1)
    e = math.exp(math.log(e1) + slope * math.log(wall / w1))
    return e, not (pts[0][0] <= wall <= pts[-1][0])


def equal_wall(result, keys):
    out = {}
    for key in keys:
        cs = curves(result, key)
        rows = []
        for label, pts in cs.items():
            for w, e, n in pts:
                row = {"wall": w, "from": "%s n=%d" % (label, n),
                       "errors": {}}
                for other, opts in cs.items():
                    val, extra = at_wall(opts, w)
                    row["errors"][other] = {"error": val,
                                            "extrapolated": extra}
                rows.append(row)
        out[key] = sorted(rows, key=lambda r: r["wall"])
    return out


# -- reports ------------------------------------------------------------------

def _g(x, fmt="%.3g"):
    return "-" if x is None else fmt % x


def column_markdown(res):
    ref, band = res["reference"], res["band"]
    lines = [
        "### Twisting column, nu = %g, t = %g s" % (res["nu"], res["time"]),
        "",
        "Twist: mean rotation about +Y of the top-face points at least %g "
        "from the axis; error = |twist - %.1f deg|, reference band "
        "%.1f-%.1f deg (%s).  'all points': the mean over every top-face "
        "point but the axis." % (
            res["rmin"], ref, band[0], band[1],
            res["referenceFrom"]["source"]), "",
    ]
    record = res["referenceFrom"]
    if "runs" in record:
        lines += ["Reference runs (under nice; times not compared) and the "
                  "Richardson extrapolation from n/4, n/2, n (none when the "
                  "observed order is outside 0.5-4):", "",
                  "| run | steps | CPU [s] | twist [deg] | n/4, n/2 [deg] | "
                  "observed order | extrapolated [deg] |",
                  "|---|---|---|---|---|---|---|"]
        for code, r in record["runs"].items():
            lines.append("| %s | %s | %.0f | %.2f | %s | %s | %s |" % (
                code, r["steps"], r["cpu"], r["twist"],
                ", ".join("%.1f" % x for x in r.get("coarser", [])) or "-",
                _g(r.get("order"), "%.2f"),
                _g(r.get("extrapolated"), "%.1f")))
        lines.append("")
    lines += [
        "| mesh | code | setting | steps | dt0 [s] | wall [s] | CPU [s] | "
        "twist [deg] | all points [deg] | error [deg] | load |",
        "|---|---|---|---|---|---|---|---|---|---|---|"]
    for n, mesh in res["meshes"].items():
        for r in mesh["runs"]:
            lines.append("| %sx%dx%s | %s | %s | %s | %s | %.2f | %.2f | "
                         "%.1f | %.1f | %.1f | %.1f-%.1f |" % (
                             n, 6 * int(n), n, r["code"], r["variant"],
                             r["steps"], _g(r["dt0"]), r["wall"], r["cpu"],
                             r["twist"], r["twistAllPoints"], r["error"],
                             r["load"][0], r["load"][1]))
    lines += ["", "Fastest touchFoam setting with an error at most "
              "CalculiX's, same mesh (acceptance: >= 4x faster in wall "
              "time):", "",
              "| mesh | CalculiX | its error [deg] | its wall [s] | "
              "touchFoam setting | error [deg] | wall [s] | wall ratio | "
              "CPU ratio | as accurate for references [deg] |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    for n, mesh in res["meshes"].items():
        for el, f in mesh["fastest"].items():
            h = f.get("holdsForReferences")
            name = f["setting"] or "none (most accurate: %s)" % (
                f["mostAccurate"])
            side = "<=" if f["twist"] <= f["calculixTwist"] else ">="
            lines.append("| %sx%dx%s | %s | %.1f | %.2f | %s | %.1f | %.2f | "
                         "%.2f | %.2f | %s %.1f (in the band: %s) |" % (
                             n, 6 * int(n), n, el, f["calculixError"],
                             f["calculixWall"], name, f["error"],
                             f["wall"], f["wallRatio"], f["cpuRatio"],
                             side, f["crossover"],
                             "%.1f-%.1f" % tuple(h) if h else "none"))
    lines += equal_wall_markdown(res["equalWall"]["error"],
                                 "Twist error [deg]", "%.1f")
    return lines


def cube_markdown(res):
    lines = [
        "### Swinging cube, t = %g s" % res["time"], "",
        "e_v: velocity vector (CalculiX: nodes with trapezoidal weights); "
        "e_vx: v_x alone (validation/swingingCube); e_Pxx: "
        "P_xx (CalculiX: element stress, mean of the integration points, at "
        "the centroid).", "",
        "| N | code | setting | steps | dt0 [s] | wall [s] | CPU [s] | e_v "
        "[m/s] | e_vx [m/s] | e_Pxx [Pa] | load |",
        "|---|---|---|---|---|---|---|---|---|---|---|"]
    for n, mesh in res["meshes"].items():
        for r in mesh["runs"]:
            lines.append("| %s | %s | %s | %s | %s | %.2f | %.2f | %.3e "
                         "| %.3e | %.3e | %.1f-%.1f |" % (
                             n, r["code"], r["variant"], r["steps"],
                             _g(r["dt0"]), r["wall"], r["cpu"], r["ev"],
                             r["evx"],
                             r["ePxx"], r["load"][0], r["load"][1]))
    lines += ["", "Fastest touchFoam setting with an error at most "
              "CalculiX's, same mesh:", "",
              "| N | error | CalculiX | its error | its wall [s] | touchFoam "
              "setting | error | wall [s] | wall ratio | CPU ratio |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    for n, mesh in res["meshes"].items():
        for key, name in (("ev", "e_v"), ("ePxx", "e_Pxx")):
            for el, f in mesh["fastest"][key].items():
                lines.append("| %s | %s | %s | %.3e | %.2f | %s | %s | %s | "
                             "%s | %s |" % (
                                 n, name, el, f["calculixError"],
                                 f["calculixWall"], f["setting"] or "none",
                                 _g(f["error"], "%.3e"), _g(f["wall"], "%.2f"),
                                 _g(f["wallRatio"], "%.2f"),
                                 _g(f["cpuRatio"], "%.2f")))
    for key, name in (("ev", "e_v [m/s]"), ("ePxx", "e_Pxx [Pa]")):
        lines += equal_wall_markdown(res["equalWall"][key], name, "%.2e")
    return lines


def equal_wall_markdown(rows, name, fmt):
    if not rows:
        return []
    labels = list(rows[0]["errors"])
    if all(v["error"] is None for r in rows for v in r["errors"].values()):
        return []
    lines = ["", "%s at equal wall time (log-log between meshes; * "
             "extrapolated):" % name, "",
             "| wall [s] | run | " + " | ".join(labels) + " |",
             "|---|---|" + "---|" * len(labels)]
    for r in rows:
        cells = []
        for lab in labels:
            v = r["errors"][lab]
            cells.append("-" if v["error"] is None else (fmt % v["error"])
                         + ("*" if v["extrapolated"] else ""))
        lines.append("| %.2f | %s | %s |" % (r["wall"], r["from"],
                                             " | ".join(cells)))
    return lines


def write_reports(results):
    lines = ["# touchFoam and CalculiX 2.20: wall time and error", "",
             "Generated by compare.py (%s); touchFoam build %s; %s." % (
                 results["date"], results["build"], results["ccx"]), ""]
    if results.get("repeat", 1) > 1:
        lines += ["Every job run %d times, round robin over all of them; "
                  "wall and CPU times are the medians (each run's in "
                  "runs/*/run.json)." % results["repeat"], ""]
    if "column" in results:
        lines += column_markdown(results["column"]) + [""]
    if "cube" in results:
        lines += cube_markdown(results["cube"]) + [""]
    text = "\n".join(lines)
    with open(os.path.join(HERE, "results.md"), "w") as f:
        f.write(text)
    readme = os.path.join(HERE, "README.md")
    if os.path.exists(readme):
        with open(readme) as f:
            old = f.read()
        if BEGIN in old and END in old:
            head, rest = old.split(BEGIN, 1)
            tail = rest.split(END, 1)[1]
            body = "\n".join(lines[2:])
            with open(readme, "w") as f:
                f.write(head + BEGIN + "\n" + body + "\n" + END + tail)


def plot(results):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: plots skipped")
        return
    if "column" in results:
        res = results["column"]
        fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
        b0, b1 = res["band"]
        ax2.axhspan(b0, b1, color="0.9", label="reference band")
        ax2.axhline(res["reference"], color="0.5", lw=0.8)
        for label, pts in curves(res, "twist").items():
            style = "s--" if label.startswith("CalculiX") else "o-"
            ax2.semilogx([p[0] for p in pts], [p[1] for p in pts], style,
                         label=label)
            for p in pts:
                ax2.annotate("%d" % p[2], (p[0], p[1]), fontsize=6,
                             textcoords="offset points", xytext=(3, 3))
        ax2.set_xlabel("wall time of the solver [s]")
        ax2.set_ylabel("mean top-face twist at 0.1 s [deg]")
        ax2.legend(fontsize=7)
        for label, pts in curves(res, "error").items():
            w = [p[0] for p in pts]
            e = [max(p[1], 1e-2) for p in pts]
            twist = {(r["code"] + " " + r["variant"], int(n)): r["twist"]
                     for n, m in res["meshes"].items() for r in m["runs"]}
            lo = [max(max(0.0, b0 - twist[(label, p[2])],
                          twist[(label, p[2])] - b1), 1e-2) for p in pts]
            hi = [max(abs(twist[(label, p[2])] - b0),
                      abs(twist[(label, p[2])] - b1)) for p in pts]
            style = "s--" if label.startswith("CalculiX") else "o-"
            line, = ax.loglog(w, e, style, label=label)
            ax.errorbar(w, e, yerr=[np.subtract(e, lo), np.subtract(hi, e)],
                        fmt="none", ecolor=line.get_color(), alpha=0.4)
            for p, ei in zip(pts, e):
                ax.annotate("%d" % p[2], (p[0], ei), fontsize=6,
                            textcoords="offset points", xytext=(3, 3))
        ax.set_xlabel("wall time of the solver [s]")
        ax.set_ylabel("|twist(0.1 s) - %.1f| [deg]" % res["reference"])
        ax.set_title("Twisting column (labels: n; bars: reference %.1f-%.1f)"
                     % (b0, b1), fontsize=9)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(HERE, "column.png"), dpi=120)
        plt.close(fig)
        print("wrote column.png")
    if "cube" in results:
        res = results["cube"]
        fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
        for ax, key, name in ((axes[0], "ev", "velocity e_v [m/s]"),
                              (axes[1], "ePxx", "stress e_Pxx [Pa]")):
            for label, pts in curves(res, key).items():
                style = "s--" if label.startswith("CalculiX") else "o-"
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], style,
                          label=label)
                for p in pts:
                    ax.annotate("%d" % p[2], (p[0], p[1]), fontsize=6,
                                textcoords="offset points", xytext=(3, 3))
            ax.set_xlabel("wall time of the solver [s]")
            ax.set_ylabel(name)
            ax.legend(fontsize=7)
        axes[0].set_title("Swinging cube at t = 0.004 s (labels: N)",
                          fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(HERE, "cube.png"), dpi=120)
        plt.close(fig)
        print("wrote cube.png")
