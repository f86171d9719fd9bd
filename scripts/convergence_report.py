"""Tables and figures of the mesh convergence study (scripts/convergence-study.py report).

Reads results/convergence/<mesh>/<run>/, writes the tables to
convergence_tables.txt there (and the screen) and the figures
convergence_{static,relaxed,modal,dynamic,relaxed_dynamic,rock_beta_dynamic}.png
there or into --figures; the earthquake peaks of the dynamic_relaxed runs are
prefixed "relaxed: ", those of the dynamic_rock_beta runs "rock beta: ";
the height series on the short rock (corrected_rock_beta runs) goes to
convergence_short_rock.png and its own tables.
"""
import csv
import json
import math
import os

import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The crown block (block 7, next to the crown joint at y = 0) at the
# monitors' y, near the crest and at mid-height, on both faces (not at the
# base: the heel and the toe are re-entrant corners whose stress is
# singular and does not converge).
CROWN_Y = -11.0
CROWN_HEIGHTS = {"crest (z = 225 m)": 225.0, "mid-height (z = 117.5 m)": 117.5}


def flatten(d, prefix=""):
    out = {}
    for k, v in d.items():
        if isinstance(v, dict):
            out.update(flatten(v, prefix + k + "/"))
        else:
            out[prefix + k] = v
    return out


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return {h: [float(r[i]) for r in rows[1:]] for i, h in enumerate(rows[0])}


def time_txt(path):
    """Wall time [s] and peak resident memory [GB] from /usr/bin/time -v."""
    wall = rss = float("nan")
    if os.path.exists(path):
        for line in open(path):
            if "Elapsed (wall clock)" in line:
                parts = [float(x) for x in line.split()[-1].split(":")]
                wall = sum(p * 60 ** i for i, p in enumerate(reversed(parts)))
            if "Maximum resident set size" in line:
                rss = float(line.split()[-1]) / 1024 ** 2
    return wall, rss


def total_dofs(directory):
    """The model's DOFs (the run's "Mesh: ..., N DOFs" line: the dam-rock
    interface nodes counted once)."""
    for line in open(os.path.join(directory, "run.log")):
        if line.startswith("Mesh:") and line.rstrip().endswith("DOFs"):
            return int(line.split(",")[-1].split()[0])
    raise RuntimeError(f"{directory}/run.log: no mesh line")


def crown_stresses(directory):
    """Static arch (horizontal, along the arch) and cantilever (vertical)
    stress at the crown block's faces, from the static field
    (solution_00000.pvtu: the dam's own cells, the face found along x)."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(os.path.join(directory, "solution_00000.pvtu"))
    reader.Update()
    dam = vtk.vtkThreshold()
    dam.SetInputConnection(reader.GetOutputPort())
    dam.SetInputArrayToProcess(0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS, "material_id")
    dam.SetLowerThreshold(9.5)
    dam.SetUpperThreshold(1e9)
    dam.Update()
    locator = vtk.vtkCellLocator()
    locator.SetDataSet(dam.GetOutput())
    locator.BuildLocator()
    grid = dam.GetOutput()

    def probe(points):
        pts = vtk.vtkPoints()
        for p in points:
            pts.InsertNextPoint(*p)
        poly = vtk.vtkPolyData()
        poly.SetPoints(pts)
        f = vtk.vtkProbeFilter()
        f.SetInputData(poly)
        f.SetSourceData(grid)
        f.Update()
        out = f.GetOutput()
        valid = vtk_to_numpy(out.GetPointData().GetArray("vtkValidPointMask"))
        stress = vtk_to_numpy(out.GetPointData().GetArray("stress"))
        return valid, stress

    def faces(y, z):
        xs = [-80.0 + 0.05 * i for i in range(3200)]
        valid, _ = probe([(x, y, z) for x in xs])
        inside = [x for x, v in zip(xs, valid) if v]
        return min(inside), max(inside)

    result = {}
    for label, z in CROWN_HEIGHTS.items():
        up, down = faces(CROWN_Y, z)
        # the arch's horizontal tangent at the crown block, from the upstream face
        up_minus, _ = faces(CROWN_Y - 1.0, z)
        up_plus, _ = faces(CROWN_Y + 1.0, z)
        t = (up_plus - up_minus, 2.0, 0.0)
        n = math.hypot(t[0], t[1])
        t = (t[0] / n, t[1] / n, 0.0)
        inset = 0.01 * (down - up)
        _, stress = probe([(up + inset, CROWN_Y, z), (down - inset, CROWN_Y, z)])
        for face, s in zip(["upstream", "downstream"], stress):
            S = [[s[3 * i + j] for j in range(3)] for i in range(3)]
            arch = sum(t[i] * S[i][j] * t[j] for i in range(3) for j in range(3))
            result[f"arch stress, {label}, {face} [MPa]"] = arch / 1e6
            result[f"cantilever stress, {label}, {face} [MPa]"] = S[2][2] / 1e6
    return result


def summary(directory):
    """A run's summary.json, flattened to "a/b/c" keys, or None if it has not run."""
    path = os.path.join(directory, "summary.json")
    return flatten(json.load(open(path))) if os.path.exists(path) else None


def node_pairs(s):
    return sum(v for k, v in s.items() if k.startswith("mesh/joints/") and k.endswith("node pairs"))


def joint_openings(s, stage):
    """The 13 joints' peak openings of a stage [mm]."""
    return [1e3 * s[f"{stage}/joints/joint {j}/peak opening [m]"] for j in range(13)]


def largest_opening(s, stage):
    """The largest of the 13 joints' peak openings of a stage [mm]."""
    return max(joint_openings(s, stage))


def collect(results, mesh, window):
    """Every quantity of the study for one mesh (missing runs left out); the
    dynamic peaks over 0 to @p window seconds (a dynamic run that ends
    earlier is left out; the most open joint and the energy balance, which
    summary.json gives for the whole run, only from runs that end there)."""
    q, info = {}, {}

    def static_state(run, prefix):
        d = os.path.join(results, mesh, run)
        s = summary(d)
        if not s:
            return False
        info["DOFs"], info["node pairs"] = total_dofs(d), node_pairs(s)
        q[prefix + "crest - base, x [mm]"] = 1e3 * (s["static/crest.ux [m]"] - s["static/base.ux [m]"])
        q[prefix + "largest joint opening [mm]"] = largest_opening(s, "static")
        q.update({prefix + k: v for k, v in crown_stresses(d).items()})
        return True

    # the static state by the one solve: from the dynamic run, else from the
    # static-only run; by dynamic relaxation: the relaxed run
    if not static_state("dynamic", "static: "):
        static_state("static", "static: ")
    static_state("relaxed", "relaxed static: ")
    def peaks(run, prefix):
        d = os.path.join(results, mesh, run)
        s = summary(d)
        if not s or s["dynamic/end time [s]"] < window - 1e-9:
            return
        whole_run = s["dynamic/end time [s]"] <= window + 1e-9
        if "DOFs" not in info:
            info["DOFs"], info["node pairs"] = total_dofs(d), node_pairs(s)
        if run == "dynamic":
            info["wall time, dynamic run [s]"], info["peak memory, dynamic run [GB]"] = time_txt(
                os.path.join(d, "time.txt")
            )

        def in_window(columns):
            keep = [t <= window + 1e-9 for t in columns["time [s]"]]
            return {k: [v for v, ok in zip(vs, keep) if ok] for k, vs in columns.items()}

        h = in_window(read_csv(os.path.join(d, "histories.csv")))
        jh = in_window(read_csv(os.path.join(d, "joint_histories_dynamic.csv")))
        for c in ["x", "y"]:
            rel = [a - b for a, b in zip(h[f"crest.u{c} [m]"], h[f"base.u{c} [m]"])]
            q[f"{prefix}peak crest - base (magnitude), {c} [mm]"] = 1e3 * max(abs(v) for v in rel)
        q[f"{prefix}peak s1 at C [MPa]"] = max(h["C.s1 [Pa]"]) / 1e6
        q[f"{prefix}peak opening at A [mm]"] = 1e3 * max(jh["A.opening [m]"])
        q[f"{prefix}peak opening at B [mm]"] = 1e3 * max(jh["B.opening [m]"])
        if whole_run:
            q[f"{prefix}peak opening, most open joint [mm]"] = largest_opening(s, "dynamic")
            # a measure of the whole dam's joints, less sensitive than one
            # joint's peak to when its impacts fall
            openings = joint_openings(s, "dynamic")
            q[f"{prefix}mean of the 13 joints' peak openings [mm]"] = sum(openings) / len(openings)
            info[f"{prefix}joints' peak openings [mm]"] = openings
            q[f"{prefix}energy balance error"] = s["energy balance/balance error"]

    # the earthquake peaks from the one solve's static state, and from the
    # relaxed one (dynamic_relaxed)
    peaks("dynamic", "")
    peaks("dynamic_relaxed", "relaxed: ")
    peaks("dynamic_rock_beta", "rock beta: ")
    peaks("corrected_rock_beta", "corrected: ")
    for run, label in [("modal_massed", "massed rock"), ("modal_massless", "massless rock")]:
        d = os.path.join(results, mesh, run)
        s = summary(d)
        if s:
            for k in range(1, 6):
                q[f"f{k}, water, {label} [Hz]"] = s[f"modal/mode {k}/frequency [Hz]"]
            if "DOFs" not in info:
                info["DOFs"], info["node pairs"] = total_dofs(d), node_pairs(s)
    return q, info


def observed_order(f1, f2, f3, h1, h2, h3):
    """Order p of f(h) = f* + C h^p through three meshes of sizes h1 > h2 > h3
    (bisection on the ratio of differences; None when not monotone)."""
    d12, d23 = f1 - f2, f2 - f3
    if d12 == 0 or d23 == 0 or d12 * d23 <= 0:
        return None

    def g(p):
        return (h1 ** p - h2 ** p) / (h2 ** p - h3 ** p) - d12 / d23

    lo, hi = 0.05, 12.0
    if g(lo) * g(hi) > 0:
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if g(lo) * g(mid) <= 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def richardson(f, h):
    """The observed order of three values f on meshes of sizes h (coarsest
    first) and the Richardson estimate: (order text, estimate or None)."""
    f1, f2, f3 = f
    h1, h2, h3 = h
    p = observed_order(f1, f2, f3, h1, h2, h3)
    if p is not None:
        return f"{p:.2f}", f3 + (f3 - f2) / ((h2 / h3) ** p - 1.0)
    if (f1 - f2) * (f2 - f3) > 0:
        return "none fits (the changes shrink too slowly)", None
    return "not monotone", None


def percent(a, b):
    return 100.0 * (a - b) / abs(b) if b else float("nan")


def report(args, meshes, series, height_series):
    """meshes: name -> (degree, across, thickness, height), coarsest first;
    series: three uniformly refined meshes (h ~ 1 / cells over height), for
    the observed order and the Richardson estimate; height_series: three
    meshes refined over the height alone, for the rows of the earthquake
    peaks from the relaxed static state ("relaxed: "; "rock beta: " with the
    rock damped by its strain rate only)."""
    window = float(args.window)
    data = {m: collect(args.results, m, window) for m in meshes if os.path.isdir(os.path.join(args.results, m))}
    names = [m for m in data if data[m][0]]
    out_dir = args.figures or args.results
    os.makedirs(out_dir, exist_ok=True)
    print(f"dynamic peaks over 0-{window:g} s")
    lines = ["| mesh | degree | cells across × thickness × height | DOFs | node pairs | "
             "dynamic run: wall time [min], peak memory [GB] |", "|---|---|---|---|---|---|"]
    for m in names:
        deg, nb, nt, nz = meshes[m]
        info = data[m][1]
        run = (
            f"{info['wall time, dynamic run [s]'] / 60:.1f}, {info['peak memory, dynamic run [GB]']:.1f}"
            if "wall time, dynamic run [s]" in info
            else f"not run to {window:g} s"
        )
        lines.append(
            f"| {m} | Q{deg} | {nb} × {nt} × {nz} | {info['DOFs']:,} | {info.get('node pairs', '–')} | {run} |"
        )
    quantities = []
    for m in names:
        for k in data[m][0]:
            if k not in quantities:
                quantities.append(k)
    header = "| quantity | " + " | ".join(names) + " | finest with the quantity | each coarser mesh against it [%] | "
    header += f"observed order ({', '.join(series)}; relaxed: {', '.join(height_series)}) | "
    header += f"Richardson estimate | {series[1]} against it [%] |"
    lines += ["", header, "|---" * (len(names) + 6) + "|"]
    for k in quantities:
        values = [data[m][0].get(k) for m in names]
        have = [m for m in names if k in data[m][0]]
        finest = have[-1]
        f = data[finest][0][k]
        # the balance error is round-off: its relative changes mean nothing
        errors = "–" if "energy" in k else ", ".join(
            f"{percent(data[m][0][k], f):+.1f}" for m in have[:-1]
        )
        order = estimate = against = "–"
        three = height_series if k.startswith(("relaxed: ", "rock beta: ")) else series
        if "energy" not in k and all(m in data and k in data[m][0] for m in three):
            order, fe = richardson([data[m][0][k] for m in three], [1.0 / meshes[m][3] for m in three])
            if fe is not None:
                estimate, against = f"{fe:.4g}", f"{percent(data[series[1]][0][k], fe):+.1f}"
        cells = " | ".join(f"{v:.4g}" if v is not None else "–" for v in values)
        lines.append(f"| {k} | {cells} | {finest} | {errors} | {order} | {estimate} | {against} |")
    print("\n".join(lines))

    # each joint's peak opening on the meshes that ran the whole window
    for prefix in ["", "relaxed: ", "rock beta: "]:
        key = f"{prefix}joints' peak openings [mm]"
        have = [m for m in names if key in data[m][1]]
        if len(have) < 2:
            continue
        joints = joint_table("joint (peak opening, " + (prefix or "one solve: ") + f"0-{window:g} s [mm])",
                             have, [data[m][1][key] for m in have], against_first=False)
        lines += [""] + joints
        print("\n".join(joints))
    open(os.path.join(args.results, "convergence_tables.txt"), "w").write("\n".join(lines) + "\n")

    rock = [(m, int(m[4:])) for m in ["rock60", "rock35"] if os.path.isdir(os.path.join(args.results, m))]
    if rock and "q2-113" in data:
        rows = sorted(rock + [("q2-113", 45)], key=lambda r: -r[1])
        rdata = {m: data[m] if m in data else collect(args.results, m, window) for m, _ in rows}
        rows = [r for r in rows if rdata[r[0]][0]]
        keys = [k for k in rdata["q2-113"][0] if not k.startswith("f") and all(k in rdata[m][0] for m, _ in rows)]
        lines = ["| quantity (q2-113 dam) | " + " | ".join(f"rock {h} m" for _, h in rows) +
                 " | " + ", ".join(f"{h} m" for _, h in rows if h != 45) + " against 45 m [%] |",
                 "|---" * (len(rows) + 2) + "|",
                 "| DOFs | " + " | ".join(f"{rdata[m][1]['DOFs']:,}" for m, _ in rows) + " | |"]
        ref = rdata["q2-113"][0]
        for k in keys:
            cells = " | ".join(f"{rdata[m][0][k]:.4g}" for m, _ in rows)
            diffs = "–" if k.startswith("energy") else ", ".join(
                f"{percent(rdata[m][0][k], ref[k]):+.1f}" for m, h in rows if h != 45
            )
            lines.append(f"| {k} | {cells} | {diffs} |")
        write_lines(args, [""] + lines)

    groups = {
        "static": [k for k in quantities if k.startswith("static")],
        "relaxed": [k for k in quantities if k.startswith("relaxed static")],
        "relaxed_dynamic": [k for k in quantities if k.startswith("relaxed: ")],
        "rock_beta_dynamic": [k for k in quantities if k.startswith("rock beta: ")],
        "modal": [k for k in quantities if k.startswith("f")],
        "dynamic": [k for k in quantities if k.startswith("peak") or k.startswith("energy")],
    }
    for group, keys in groups.items():
        if keys:
            draw_panels(os.path.join(out_dir, f"convergence_{group}.png"), keys,
                        lambda k: [(data[m][1]["DOFs"], data[m][0][k], m)
                                   for m in names if k in data[m][0] and "DOFs" in data[m][1]])


def draw_panels(path, keys, points):
    """One panel per quantity k: points(k) = [(DOFs, value, label)] on a
    logarithmic DOF axis, written to @p path."""
    cols = 4
    rows = (len(keys) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4 * cols, 3 * rows), squeeze=False)
    for ax, k in zip(axes.flat, keys):
        pts = points(k)
        ax.semilogx([p[0] for p in pts], [p[1] for p in pts], "o-")
        # the meshes' DOFs as the ticks (a range within one decade
        # otherwise gets overlapping minor labels)
        ax.xaxis.set_minor_locator(matplotlib.ticker.NullLocator())
        ax.set_xticks([p[0] for p in pts], [f"{p[0] / 1e3:.0f}k" for p in pts])
        for x, y, m in pts:
            ax.annotate(m, (x, y), fontsize=7)
        ax.set_title(k, fontsize=8)
        ax.set_xlabel("DOFs", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(True, alpha=0.3)
    for ax in list(axes.flat)[len(keys):]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def short_rock_rows(args, meshes, names, window):
    """The runs corrected_rock_beta of @p names (MESH-extentNN) that reach
    the window: (name, cells (degree, across, thickness, height), the static
    state and the earthquake peaks, the run's facts, wall time, memory)."""
    run = "corrected_rock_beta"
    rows = []
    for m in names:
        d = os.path.join(args.results, m, run)
        s = summary(d)
        if not s or s["dynamic/end time [s]"] < window - 1e-9:
            continue
        q, info = collect(args.results, m, window)
        q = {k[len("corrected: "):]: v for k, v in q.items() if k.startswith("corrected: ")}
        static = {
            "static: crest - base, x [mm]": 1e3 * (s["static/crest.ux [m]"] - s["static/base.ux [m]"]),
            "static: largest joint opening [mm]": largest_opening(s, "static"),
        }
        wall, rss = time_txt(os.path.join(d, "time.txt"))
        rows.append((m, meshes[m.split("-extent")[0]], {**static, **q}, info, wall, rss))
    return rows


def run_lines(rows):
    lines = ["", "| mesh | cells | DOFs | node pairs | wall time [min], peak memory [GB] |", "|---|---|---|---|---|"]
    for m, cells, q, info, wall, rss in rows:
        lines.append(f"| {m} | {cells_name(cells)} | {info['DOFs']:,} | {info['node pairs']:,} | "
                     f"{wall / 60:.1f}, {rss:.1f} |")
    return lines


def cells_name(cells):
    """Q<degree> across x thickness x height"""
    return f"Q{cells[0]} " + " x ".join(str(n) for n in cells[1:])


def joint_table(title, labels, openings, against_first):
    """Each joint's peak opening [mm] (@p openings, one list of 13 per
    mesh, in the order of @p labels), and the first mesh against each of
    the others (@p against_first) or each coarser mesh against the last."""
    first, last = openings[0], openings[-1]
    tail = f"{labels[0]} against each [%]" if against_first else f"each coarser mesh against {labels[-1]} [%]"
    lines = [f"| {title} | " + " | ".join(labels) + f" | {tail} |", "|---" * (len(labels) + 2) + "|"]
    for j in range(13):
        values = [o[j] for o in openings]
        errors = ([percent(first[j], v) for v in values[1:]] if against_first
                  else [percent(v, last[j]) for v in values[:-1]])
        lines.append(f"| {j} | " + " | ".join(f"{v:.2f}" for v in values) + " | " +
                     ", ".join(f"{e:+.1f}" for e in errors) + " |")
    return lines


def joint_lines(rows, against_first):
    """joint_table of the short-rock runs @p rows that recorded each joint."""
    key = "corrected: joints' peak openings [mm]"
    have = [r for r in rows if key in r[3]]
    if len(have) < 2:
        return []
    return [""] + joint_table("joint", [cells_name(r[1]) for r in have], [r[3][key] for r in have], against_first)


def write_lines(args, lines):
    print("\n".join(lines))
    with open(os.path.join(args.results, "convergence_tables.txt"), "a") as f:
        f.write("\n".join(lines) + "\n")


def directions_report(args, meshes, names):
    """The first of @p names (the case's mesh on the short rock) against
    each of the others (one direction refined): the static state, the
    earthquake peaks over the window, each joint's peak opening."""
    rows = short_rock_rows(args, meshes, names, float(args.window))
    if len(rows) < 2 or rows[0][0] != names[0]:
        return
    lines = run_lines(rows)
    lines += ["", "| quantity | " + " | ".join(cells_name(r[1]) for r in rows) + " | " +
              f"{cells_name(rows[0][1])} against each [%] |", "|---" * (len(rows) + 2) + "|"]
    for k in rows[0][2]:
        values = [r[2].get(k) for r in rows]
        if any(v is None for v in values):
            continue
        errors = "–" if "energy" in k else ", ".join(f"{percent(values[0], v):+.1f}" for v in values[1:])
        lines.append(f"| {k} | " + " | ".join(f"{v:.4g}" for v in values) + f" | {errors} |")
    write_lines(args, lines + joint_lines(rows, against_first=True))


def short_rock_report(args, meshes, names):
    """The height series of @p names (MESH-extentNN, coarsest first), each
    run as corrected_rock_beta: the static state, the earthquake peaks over
    the window and each joint's peak opening, each mesh against the finest,
    the observed order and Richardson estimate of the three finest; appended
    to convergence_tables.txt, the figure convergence_short_rock.png."""
    rows = short_rock_rows(args, meshes, names, float(args.window))
    if len(rows) < 2:
        return
    lines = run_lines(rows)
    finest = rows[-1]
    three = rows[-3:] if len(rows) >= 3 else None
    header = ("| quantity | " + " | ".join(str(r[1][3]) for r in rows) + " | each coarser mesh against " +
              f"{finest[1][3]} cells [%] | observed order ({', '.join(str(r[1][3]) for r in three or [])}) | "
              "Richardson estimate | each mesh against it [%] |")
    lines += ["", header, "|---" * (len(rows) + 5) + "|"]
    keys = list(finest[2])
    for k in keys:
        values = [r[2].get(k) for r in rows]
        if any(v is None for v in values):
            continue
        cells = " | ".join(f"{v:.4g}" for v in values)
        if "energy" in k:
            lines.append(f"| {k} | {cells} | – | – | – | – |")
            continue
        errors = ", ".join(f"{percent(v, values[-1]):+.1f}" for v in values[:-1])
        order = estimate = against = "–"
        if three:
            order, fe = richardson([r[2][k] for r in three], [1.0 / r[1][3] for r in three])
            if fe is not None:
                estimate = f"{fe:.4g}"
                against = ", ".join(f"{percent(v, fe):+.1f}" for v in values)
        lines.append(f"| {k} | {cells} | {errors} | {order} | {estimate} | {against} |")
    write_lines(args, lines + joint_lines(rows, against_first=False))

    keys = [k for k in keys if "energy" not in k and all(k in r[2] for r in rows)]
    draw_panels(os.path.join(args.figures or args.results, "convergence_short_rock.png"), keys,
                lambda k: [(r[3]["DOFs"], r[2][k], f"{r[1][3]} cells") for r in rows])
