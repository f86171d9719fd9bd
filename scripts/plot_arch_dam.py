#!/usr/bin/python3
"""Pictures of the parametric arch dam model (doc/arch-dam-geometry.md).

Reads the data file written by the test tests/arch_dam_default.cc
(arch_dam_model.txt in its run directory: the model's boundary faces, the
joint faces and the geometry's curves, all computed by the C++ code) and
writes four PNG files:

  arch_dam_plan.png     plan view of the arches at five elevations
  arch_dam_crown.png    the crown cantilever section
  arch_dam_blocks.png   3-D view of the dam from downstream, blocks coloured
  arch_dam_model.png    3-D view of the whole model (rock, dam, water)

Usage:
  /usr/bin/python3 scripts/plot_arch_dam.py \
      build/tests/arch_dam_default/arch_dam_model.txt doc/figures
  /usr/bin/python3 scripts/plot_arch_dam.py \
      build/tests/arch_dam_vertical_joints/arch_dam_model_vertical.txt doc/figures
(the second, the vertical joints' layout: arch_dam_blocks_vertical.png and
arch_dam_model_vertical.png)
"""
import sys
import os

import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def read(path):
    faces, arches, crown, canyon = [], [], [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w or w[0].startswith("#"):
                continue
            if w[0] == "face":
                xyz = np.array(w[3:], dtype=float).reshape(4, 3)
                faces.append((int(w[1]), int(w[2]), xyz))
            elif w[0] == "arch":
                xy = np.array(w[3:], dtype=float).reshape(-1, 2)
                arches.append((float(w[1]), float(w[2]), xy))
            elif w[0] == "crown":
                crown.append([float(v) for v in w[1:4]])
            elif w[0] == "canyon":
                canyon.append([float(v) for v in w[1:3]])
    return faces, arches, np.array(crown), np.array(canyon)


def plan_view(arches, canyon, out):
    fig, ax = plt.subplots(figsize=(7, 6))
    elevations = sorted({z for z, _, _ in arches})
    colors = plt.cm.viridis(np.linspace(0, 0.9, len(elevations)))
    for z, c in zip(elevations, colors):
        for zz, s, xy in arches:
            if zz != z:
                continue
            style = "-" if s != 0.5 else ":"
            ax.plot(xy[:, 0], xy[:, 1], style, color=c, lw=1.5 if s != 0.5 else 0.8,
                    label=f"z = {z:.0f} m" if s == 0.0 else None)
        # abutment (radial) lines
        up = [xy for zz, s, xy in arches if zz == z and s == 0.0][0]
        dn = [xy for zz, s, xy in arches if zz == z and s == 1.0][0]
        for end in (0, -1):
            ax.plot([up[end, 0], dn[end, 0]], [up[end, 1], dn[end, 1]], "-", color=c, lw=1.5)
    ax.axhline(0, color="0.6", lw=0.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x (downstream) [m]")
    ax.set_ylabel("y (along the dam axis) [m]")
    ax.set_title("Arches: upstream and downstream faces, mid-thickness line (dotted)")
    ax.legend(loc="lower left", fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


def crown_view(crown, canyon, water_level, out):
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(9, 6), gridspec_kw={"width_ratios": [1, 1.3]})
    z, xu, xd = crown[:, 0], crown[:, 1], crown[:, 2]
    ax.fill_betweenx(z, xu, xd, color="0.75")
    ax.plot(xu, z, "k-", lw=1.2, label="upstream face $x_u(z)$")
    ax.plot(xd, z, "k--", lw=1.2, label="downstream face $x_d(z)$")
    if water_level > 0:
        ax.axhline(water_level, color="tab:blue", lw=1)
        ax.text(xu.min() - 45, water_level + 3, f"water level {water_level:.0f} m",
                color="tab:blue", fontsize=8)
    ax.set_xlim(xu.min() - 50, xd.max() + 20)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.set_title("Crown cantilever (y = 0)")
    ax.legend(loc="lower left", fontsize=8)
    zc, b = canyon[:, 0], canyon[:, 1]
    ax2.fill_betweenx(zc, -b, b, color="0.9")
    ax2.plot(b, zc, "k-", -b, zc, "k-")
    ax2.set_aspect("equal")
    ax2.set_xlabel("y [m]")
    ax2.set_title("Canyon: half-width b(z) at the dam")
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


def view3d(ax, polys, colors, elev, azim, edge=0.15):
    pc = Poly3DCollection(polys, facecolors=colors, edgecolors=(0, 0, 0, 0.35),
                          linewidths=edge)
    ax.add_collection3d(pc)
    pts = np.concatenate(polys)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(hi - lo)
    ax.view_init(elev=elev, azim=azim)
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.set_major_locator(matplotlib.ticker.MaxNLocator(4))
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")


def shade(base, xyz, light=np.array([0.3, -0.5, 0.8])):
    n = np.cross(xyz[2] - xyz[0], xyz[3] - xyz[1])
    n = n / (np.linalg.norm(n) + 1e-30)
    f = 0.55 + 0.45 * abs(np.dot(n, light / np.linalg.norm(light)))
    return tuple(np.clip(np.array(base[:3]) * f, 0, 1)) + (base[3],)


def blocks_view(faces, out):
    dam = [(m, t, xyz) for m, t, xyz in faces if m >= 10]
    nb = max(m for m, _, _ in dam) - 9
    cmap = plt.cm.tab20(np.linspace(0, 1, 20))
    polys, colors = [], []
    for m, t, xyz in dam:
        if t in (0, 200, 201):  # the dam's outer surface (no joints: they are inside)
            polys.append(xyz)
            colors.append(shade(cmap[(m - 10) % 20], xyz))
    fig = plt.figure(figsize=(9, 7))
    ax = fig.add_subplot(projection="3d")
    view3d(ax, polys, colors, elev=15, azim=15)
    ax.set_title(f"Dam seen from downstream: {nb} blocks (material ids 10..{9 + nb}), "
                 "block 0 on the left bank (+y)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


def model_view(faces, out):
    id_color = {0: (0.78, 0.72, 0.62, 1.0), 1: (0.55, 0.45, 0.35, 1.0),
                2: (0.65, 0.55, 0.45, 1.0), 3: (0.35, 0.6, 0.95, 0.9),
                4: (0.25, 0.45, 0.85, 0.9), 5: (0.2, 0.35, 0.7, 0.9)}
    polys, colors = [], []
    for m, t, xyz in faces:
        if t >= 100 or (m >= 10 and t != 0):
            continue
        if m >= 10:
            base = (0.85, 0.85, 0.88, 1.0)
        else:
            base = id_color[t]
        polys.append(xyz)
        colors.append(shade(base, xyz))
    fig = plt.figure(figsize=(10, 7))
    ax = fig.add_subplot(projection="3d")
    view3d(ax, polys, colors, elev=28, azim=-130, edge=0.1)
    ax.set_title("Whole model: rock (brown; bottom id 1, sides id 2, ground id 0), dam (grey),\n"
                 "reservoir (blue; surface id 3, upstream end id 4, bottom/banks beyond the rock id 5)",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(1)
    path, outdir = sys.argv[1], sys.argv[2]
    os.makedirs(outdir, exist_ok=True)
    faces, arches, crown, canyon = read(path)
    water = [xyz[:, 2].max() for m, t, xyz in faces if t == 3]
    water_level = max(water) if water else 0.0
    # arch_dam_model_LAYOUT.txt (tests/arch_dam_vertical_joints.cc) draws
    # the blocks and the model of that joint layout as *_LAYOUT.png
    stem = os.path.splitext(os.path.basename(path))[0]
    suffix = stem[len("arch_dam_model"):] if stem.startswith("arch_dam_model") else ""
    if not suffix:
        plan_view(arches, canyon, os.path.join(outdir, "arch_dam_plan.png"))
        crown_view(crown, canyon, water_level, os.path.join(outdir, "arch_dam_crown.png"))
    blocks_view(faces, os.path.join(outdir, f"arch_dam_blocks{suffix}.png"))
    model_view(faces, os.path.join(outdir, f"arch_dam_model{suffix}.png"))


if __name__ == "__main__":
    main()
