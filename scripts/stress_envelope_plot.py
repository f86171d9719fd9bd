#!/usr/bin/python3
"""Draw the stress envelope of a dynamic run on the dam faces (PNG, Agg).

Reads `stress_envelope_dynamic.csv` (columns: face, x [m], y [m], z [m],
max s1 [Pa], time of max s1 [s], min s3 [Pa], time of min s3 [s], then the
arch and cantilever extremes) and draws
the largest major principal stress s1 over the run (tension positive, MPa) on
the upstream and the downstream face as two panels, each face seen as an
engineer looks at it: the upstream face from the reservoir (looking
downstream, +y to the left), the downstream face from downstream (+y to the
right). The horizontal coordinate is y along the dam axis, or with a radius R
the developed arc position R atan2(y, R - x) (the arch centre on the crown
plane x = R). Both panels share one colour scale; the largest value of each
face is marked.

From Python:
    import stress_envelope_plot
    stress_envelope_plot.draw("results/stress_envelope_dynamic.csv",
                              "envelope.png", "Reference dam", radius=None)
From the shell:
    /usr/bin/python3 scripts/stress_envelope_plot.py results/stress_envelope_dynamic.csv \
        envelope.png --title "Reference dam" [--radius 170]
"""
import argparse
import csv
import math

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
from matplotlib.colors import TwoSlopeNorm
from matplotlib.ticker import MaxNLocator


def read(csv_path, column="max s1 [Pa]"):
    """The rows of the file, by face: {face: [(x, y, z, value, t), ...]}, value
    the column named @p column, t its time (that of the column "time of
    max s1 [s]" for max s1; NaN for a column without one). For a DCR column,
    only the points the evaluation counts (column "evaluated" 1: not in the
    band left out at the base)."""
    faces = {}
    with open(csv_path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        if column not in header:
            raise SystemExit(f"{csv_path}: no column '{column}'")
        i = header.index(column)
        time_name = "time of " + column.replace(" [Pa]", "") + " [s]"
        k = header.index(time_name) if time_name in header else None
        counted = header.index("evaluated") if "DCR" in column and "evaluated" in header else None
        for row in reader:
            if row and (counted is None or row[counted] == "1"):
                x, y, z = (float(v) for v in row[1:4])
                t = float(row[k]) if k is not None else float("nan")
                faces.setdefault(row[0], []).append((x, y, z, float(row[i]), t))
    return faces


def developed(x, y, radius):
    return y if radius is None else radius * math.atan2(y, radius - x)


def draw(csv_path, png_path, title, radius=None, column="max s1 [Pa]", scale=1e-6,
         value_label="largest major principal stress s1 [MPa] (tension +)"):
    """Draw the column @p column (times @p scale; default s1 in MPa)."""
    faces = read(csv_path, column)
    panels = [("upstream", "upstream face, seen from the reservoir"),
              ("downstream", "downstream face, seen from downstream")]
    values = [p[3] * scale for face, _ in panels for p in faces.get(face, [])]
    if not values:
        raise SystemExit(f"{csv_path}: no upstream or downstream points")
    low, high = min(values), max(values)
    norm = TwoSlopeNorm(0.0, min(low, -1e-6), max(high, 1e-6))
    # contour levels and colour-bar ticks at round numbers (1, 2 or 5 times
    # a power of ten) that cover the values
    ticks = MaxNLocator(nbins=10, steps=[1, 2, 5, 10]).tick_values(low, high)
    levels = (np.linspace(ticks[0], ticks[-1], 2 * (len(ticks) - 1) + 1) if high > low
              else np.linspace(low - 1, high + 1, 3))

    fig, axes = plt.subplots(1, 2, figsize=(13, 5.5))
    z_all = [p[2] for face, _ in panels for p in faces.get(face, [])]
    mappable = None
    for ax, (face, label) in zip(axes, panels):
        points = faces.get(face, [])
        ax.set_title(label, fontsize=10)
        ax.set_ylim(min(z_all), max(z_all))
        ax.set_xlabel("y [m]" if radius is None else f"arc position at R = {radius:g} m [m]")
        if len(points) < 3:
            ax.text(0.5, 0.5, "no points", transform=ax.transAxes, ha="center")
            continue
        h = [developed(p[0], p[1], radius) for p in points]
        z = [p[2] for p in points]
        s1 = [p[3] * scale for p in points]
        triangles = mtri.Triangulation(h, z)
        # Drop the long thin triangles that Delaunay adds across the outline
        # of a curved face (longer than 3x the median edge).
        def lengths(t):
            return [math.dist((h[a], z[a]), (h[b], z[b]))
                    for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))]

        edges = sorted(e for t in triangles.triangles for e in lengths(t))
        limit = 3 * edges[len(edges) // 2]
        triangles.set_mask([max(lengths(t)) > limit for t in triangles.triangles])
        mappable = ax.tricontourf(triangles, s1, levels=levels, cmap="RdBu_r", norm=norm)
        k = max(range(len(points)), key=lambda i: s1[i])
        ax.plot([h[k]], [z[k]], "k*", markersize=10, clip_on=False)
        when = "" if points[k][4] != points[k][4] else f" at t = {points[k][4]:.2f} s"
        unit = " MPa" if scale == 1e-6 else ""
        ax.set_title(f"{label}\n(*) largest: {s1[k]:.3g}{unit}{when}, "
                     f"y = {points[k][1]:.0f} m, z = {points[k][2]:.0f} m", fontsize=10)
        ax.set_aspect("equal", adjustable="box")
        if face == "upstream":
            ax.invert_xaxis()  # looking downstream, +y is on the left
    for ax in axes:
        ax.set_ylabel("z [m]")
    if mappable is not None:
        fig.colorbar(mappable, ax=axes, shrink=0.85, ticks=ticks if high > low else None,
                     format="%g", label=value_label)
    fig.suptitle(title)
    fig.savefig(png_path, dpi=120)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="Stress envelope")
    parser.add_argument("--radius", type=float, default=None,
                        help="develop the faces on arcs of this radius [m]")
    args = parser.parse_args()
    draw(args.csv, args.png, args.title, args.radius)


if __name__ == "__main__":
    main()
