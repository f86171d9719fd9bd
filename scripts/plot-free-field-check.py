#!/usr/bin/python3
"""The figure of a free-field check (`archdam CASE.prm --free-field-check`,
doc/theory/foundation.md §4): per component the 5 %-damped spectra of the
control motion and of the rock column at the free surface, and of the free
field and the column at the dam's base; below, their ratios.

Usage: plot-free-field-check.py RESULTS_DIR [OUTPUT.png]
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def columns(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    directory = sys.argv[1]
    output = sys.argv[2] if len(sys.argv) > 2 else os.path.join(directory, "free_field_check.png")
    components = [c for c in "xyz" if os.path.exists(os.path.join(directory, f"free_field_{c}_spectra.csv"))]
    if not components:
        sys.exit(f"{directory}: no free_field_*_spectra.csv (run archdam CASE.prm --free-field-check)")
    fig, axes = plt.subplots(2, len(components), figsize=(5.5 * len(components), 7), squeeze=False,
                             sharex=True, gridspec_kw={"height_ratios": [2, 1]})
    for j, c in enumerate(components):
        _, rows = columns(os.path.join(directory, f"free_field_{c}_spectra.csv"))
        T = [r[0] for r in rows]
        control, surface, base, free_field = ([r[i] / 9.81 for r in rows] for i in (1, 2, 3, 4))
        top, bottom = axes[0][j], axes[1][j]
        top.plot(T, control, "k-", lw=2, label="control motion (target)")
        top.plot(T, surface, "C0--", label="rock column, free surface")
        top.plot(T, free_field, "C1-", label="free field, dam's base")
        top.plot(T, base, "C3--", label="rock column, dam's base")
        top.set_xscale("log")
        top.set_ylabel("5 % pseudo-acceleration [g]")
        top.set_title(f"component {c}")
        top.grid(True, which="both", alpha=0.3)
        top.legend(fontsize=8)
        bottom.plot(T, [s / t for s, t in zip(surface, control)], "C0-", label="column surface / control")
        bottom.plot(T, [b / f for b, f in zip(base, free_field)], "C3-", label="column base / free field")
        for y in (0.95, 1.05):
            bottom.axhline(y, color="grey", lw=0.8, ls=":")
        bottom.set_xlabel("period [s]")
        bottom.set_ylabel("ratio")
        bottom.grid(True, which="both", alpha=0.3)
        bottom.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(output, dpi=110)
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
