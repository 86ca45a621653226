#!/usr/bin/python3
"""Draws pfspheres' trade-off chart: time per frame against mismatched pixels.

    /usr/bin/python3 bench/sphere_chart.py [CSV] [PNG]

CSV defaults to bench/results_spheres.csv (written by pfspheres), PNG to
docs/images/sphere_vs_tessellation.png. The rows of the most threads the CSV holds are drawn
(bench/run_spheres measures 1 and 2). One curve per sphere count through the gluSphere levels
(labelled with their slices), and primflow's sphere primitive for that count as a star. The error
is the mismatched pixels (missing + extra + wrong sphere) against the exact image, on a symlog
axis since primflow's can be zero. Needs matplotlib (Debian python3-matplotlib).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)


def load_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def rows_for(rows, spheres, primflow):
    picked = [r for r in rows if int(r["spheres"]) == spheres and (r["method"] == "primflow") == primflow]
    return sorted(picked, key=lambda r: int(r["slices"]))


def plot_count(ax, rows, spheres, colour):
    """gluSphere's levels as a curve (points labelled with their slices), primflow as a star
    labelled with its mismatched pixels."""
    glu = rows_for(rows, spheres, primflow=False)
    label = "1 sphere" if spheres == 1 else f"{spheres} spheres"
    if glu:
        xs = [float(r["ms_per_frame"]) for r in glu]
        ys = [int(r["mismatched"]) for r in glu]
        ax.plot(xs, ys, "-o", color=colour, label=f"{label}: gluSphere (llvmpipe)")
        for r, x, y in zip(glu, xs, ys):
            ax.annotate(r["slices"], (x, y), textcoords="offset points", xytext=(5, 5), fontsize=8, color=colour)
    for r in rows_for(rows, spheres, primflow=True):
        x, y = float(r["ms_per_frame"]), int(r["mismatched"])
        ax.plot([x], [y], linestyle="none", marker="*", markersize=18, color=colour, markeredgecolor="black",
                label=f"{label}: primflow sphere primitive")
        ax.annotate(str(y), (x, y), textcoords="offset points", xytext=(10, -3), fontsize=8, color=colour)


def main(argv):
    csv_path = argv[1] if len(argv) > 1 else "bench/results_spheres.csv"
    png_path = argv[2] if len(argv) > 2 else "docs/images/sphere_vs_tessellation.png"
    rows = load_rows(csv_path)
    if not rows:
        sys.exit(f"sphere_chart.py: no rows in {csv_path}")
    most = max(int(r["threads"]) for r in rows)
    rows = [r for r in rows if int(r["threads"]) == most]
    fig, ax = plt.subplots(figsize=(9, 6), dpi=100)
    for i, spheres in enumerate(sorted({int(r["spheres"]) for r in rows})):
        plot_count(ax, rows, spheres, f"C{i}")
    first = rows[0]
    threads = "1 thread" if first["threads"] == "1" else f"{first['threads']} threads"
    ax.set_title(f"primflow's exact sphere against gluSphere tessellations\n"
                 f"{first['size']}x{first['size']}, {threads}; gluSphere points labelled with slices = stacks")
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=10)
    ax.set_ylim(-1.5, 4 * max(int(r["mismatched"]) for r in rows))  # room below 0 for a star at 0
    ax.set_xlabel("time per frame, ms (median, log scale)")
    ax.set_ylabel("mismatched pixels: missing + extra + wrong sphere (symlog)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    fig.savefig(png_path)
    print(f"wrote {png_path}")


if __name__ == "__main__":
    main(sys.argv)
