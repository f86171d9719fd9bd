#!/usr/bin/python3
"""Plot a ground motion: acceleration, velocity and displacement histories and
its response spectrum against a target (PNG, matplotlib's Agg backend).

Its data comes from `archdam-motion ... --plot FILE`, which writes the two
CSV inputs and prints the command that runs this script on them:
  --histories: time [s], acceleration [m/s^2], velocity [m/s], displacement [m]
  --spectrum:  period [s], SD [m], PSV [m/s], PSA [m/s^2][, target PSA [m/s^2]]
It can also be run by hand on such files:
  /usr/bin/python3 scripts/plot_motion.py --histories h.csv --spectrum s.csv \
      --title "Pacoima Dam 164" --output motion.png
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

G = 9.80665  # standard gravity, m/s^2


def read_columns(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header, data = rows[0], rows[1:]
    columns = list(zip(*[[float(x) for x in r] for r in data]))
    return header, [list(c) for c in columns]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--histories", required=True)
    parser.add_argument("--spectrum", required=True)
    parser.add_argument("--output", required=True)
    parser.add_argument("--title", default="")
    parser.add_argument("--damping", type=float, default=0.05)
    parser.add_argument("--match-range", default="",
                        help="TMIN:TMAX shaded on the spectrum (matched periods)")
    args = parser.parse_args()

    _, (t, a, v, d) = read_columns(args.histories)
    header, spectrum = read_columns(args.spectrum)
    periods, psa = spectrum[0], spectrum[3]
    target = spectrum[4] if len(spectrum) > 4 else None

    fig = plt.figure(figsize=(12, 7))
    grid = fig.add_gridspec(3, 2, width_ratios=[1.5, 1], hspace=0.35, wspace=0.25)
    panels = [
        ([x / G for x in a], "acceleration [g]", "tab:blue"),
        ([x * 100 for x in v], "velocity [cm/s]", "tab:green"),
        ([x * 100 for x in d], "displacement [cm]", "tab:red"),
    ]
    for row, (y, label, color) in enumerate(panels):
        ax = fig.add_subplot(grid[row, 0])
        ax.plot(t, y, color=color, linewidth=0.6)
        k = max(range(len(y)), key=lambda i: abs(y[i]))
        ax.plot([t[k]], [y[k]], "o", color="black", markersize=3)
        ax.annotate(f"peak {abs(y[k]):.3g} at {t[k]:.2f} s", (t[k], y[k]),
                    textcoords="offset points", xytext=(5, 5), fontsize=8)
        ax.set_ylabel(label)
        ax.grid(True, linewidth=0.3)
        ax.set_xlim(t[0], t[-1])
        if row == 2:
            ax.set_xlabel("time [s]")

    ax = fig.add_subplot(grid[:, 1])
    ax.plot(periods, [x / G for x in psa], color="tab:blue", linewidth=1.2,
            label=f"PSA, {100 * args.damping:g} % damping")
    if target is not None:
        tg = [x / G for x in target]
        ax.plot(periods, tg, color="black", linewidth=1.2, label="target")
        ax.fill_between(periods, [0.9 * x for x in tg], [1.1 * x for x in tg],
                        color="gray", alpha=0.25, label="target ±10 %")
    if args.match_range:
        lo, hi = (float(x) for x in args.match_range.split(":"))
        ax.axvspan(lo, hi, color="tab:orange", alpha=0.07,
                   label=f"matched {lo:g}–{hi:g} s")
    ax.set_xscale("log")
    ax.set_xlabel("period [s]")
    ax.set_ylabel("pseudo-spectral acceleration [g]")
    ax.set_xlim(periods[0], periods[-1])
    ax.set_ylim(bottom=0)
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend(fontsize=8, loc="upper right")

    if args.title:
        fig.suptitle(args.title, fontsize=11)
    fig.savefig(args.output, dpi=110, bbox_inches="tight")
    return 0


if __name__ == "__main__":
    sys.exit(main())
