#!/usr/bin/python3
"""Draws pffields' trade-off chart: time per frame against depth error, per 3D model.

    /usr/bin/python3 bench/fields_chart.py [CSV] [PNG]

CSV defaults to bench/results_fields.csv (written by pffields), PNG to
docs/images/fields_time_vs_error.png. One panel per 3D model; one curve per method (march
through its step counts, labelled with M; interval and analytic as single points). The error is
the maximum depth error in world units against the double-precision reference, on a log axis
(floored at 1e-9); points with coverage mismatches say how many. Needs matplotlib (Debian
python3-matplotlib).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

MARKERS = {"interval": "o", "analytic": "*", "march": "s", "sphere": "^", "newton": "D", "regula-falsi": "v"}


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "bench/results_fields.csv"
    dst = sys.argv[2] if len(sys.argv) > 2 else "docs/images/fields_time_vs_error.png"
    with open(src, newline="") as f:
        rows = list(csv.DictReader(f))
    rows = [r for r in rows if r["threads"] == "1"]  # one thread: the methods' own costs
    # 3D models: those marched with more than one step (2D models are marched with one).
    models = [m for m in dict.fromkeys(r["model"] for r in rows)
              if any(r["model"] == m and r["method"] == "march" and float(r["param"]) > 1 for r in rows)]
    fig, axes = plt.subplots(1, len(models), figsize=(4.2 * len(models), 3.6), squeeze=False)
    for ax, model in zip(axes[0], models):
        mine = [r for r in rows if r["model"] == model]
        for method in dict.fromkeys(r["method"] for r in mine):
            pts = sorted((r for r in mine if r["method"] == method), key=lambda r: float(r["ms_median"]))
            xs = [float(r["ms_median"]) for r in pts]
            ys = [max(float(r["max_depth_error"]), 1e-9) for r in pts]
            ax.plot(xs, ys, marker=MARKERS.get(method, "x"), label=method)
            for r, x, y in zip(pts, xs, ys):
                tag = ("M=%s" % r["param"]) if method in ("march", "newton", "regula-falsi") else ""
                if int(r["coverage_mismatches"]):
                    tag += (" " if tag else "") + "%s px off" % r["coverage_mismatches"]
                if tag:
                    ax.annotate(tag, (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title("%s (%s px, 1 thread)" % (model, mine[0]["size"]))
        ax.set_xlabel("time per frame (ms)")
        ax.set_ylabel("max depth error (world units)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(dst, dpi=110)


if __name__ == "__main__":
    main()
