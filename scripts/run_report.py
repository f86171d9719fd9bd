#!/usr/bin/python3
"""Write the report of a run (or of a record suite) as one self-contained HTML page.

The page gathers what an engineer hands to a reviewer (doc/user-guide.md,
"The run report"): the case and the model's size, the input motion, the
static state, the peaks, the joints' openings and slips, the stress and DCR
maps of the faces, the energy balance and the warnings, each figure beside
its numbers. Everything is read from the run's own result files
(summary.json and the CSV tables); the figures are PNGs drawn with
matplotlib (Agg) and embedded as data URIs, so the page opens in a browser
from the file alone, without a server.

A folder holding suite.csv (Record suite/Records) gets the suite's page: its
records, every peak's statistics, a figure of the joints' peak openings per
record, and links to the records' own reports.

usage: run_report.py RESULTS_FOLDER [--output FILE]   (default FOLDER/report.html)
"""
import argparse
import base64
import csv
import html
import io
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stress_envelope_plot  # noqa: E402

STYLE = """
body { font-family: sans-serif; margin: 1.5em; color: #222; max-width: 1400px; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; }
h2 { font-size: 1.2em; border-bottom: 1px solid #aaa; margin-top: 1.6em; }
.row { display: flex; flex-wrap: wrap; gap: 1.5em; align-items: flex-start; }
.fig img { max-width: 760px; width: 100%; border: 1px solid #ddd; }
table { border-collapse: collapse; font-size: 0.85em; }
td, th { border: 1px solid #ccc; padding: 2px 6px; text-align: right; }
th { background: #eee; }
td.key, th.key { text-align: left; }
.note { color: #555; font-size: 0.9em; }
.warning { color: #a40; }
"""


def flatten(tree, path=""):
    """The leaves of a JSON object as {"a/b/c": value}."""
    leaves = {}
    for key, value in tree.items():
        here = f"{path}/{key}" if path else key
        if isinstance(value, dict):
            leaves.update(flatten(value, here))
        else:
            leaves[here] = value
    return leaves


def number(value):
    """A value as the page prints it: 6 significant digits."""
    if isinstance(value, (int, float)):
        return f"{value:.6g}"
    return html.escape(str(value))


def table(rows, header=None):
    out = ["<table>"]
    if header and any(header):
        out.append("<tr>" + "".join(
            f'<th class="{"key" if i == 0 else ""}">{html.escape(h)}</th>'
            for i, h in enumerate(header)) + "</tr>")
    for row in rows:
        out.append("<tr>" + "".join(
            f'<td class="{"key" if i == 0 else ""}">{number(v) if i else html.escape(str(v))}</td>'
            for i, v in enumerate(row)) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def figure_data(fig):
    """A matplotlib figure as a PNG data URI."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=90, bbox_inches="tight")
    plt.close(fig)
    return "data:image/png;base64," + base64.b64encode(buffer.getvalue()).decode("ascii")


def file_data(path):
    with open(path, "rb") as f:
        return "data:image/png;base64," + base64.b64encode(f.read()).decode("ascii")


def section(title, numbers, image=None, note=None):
    parts = [f"<section><h2>{html.escape(title)}</h2>"]
    if note:
        parts.append(f'<p class="note">{note}</p>')
    parts.append('<div class="row">')
    if image:
        parts.append(f'<div class="fig"><img alt="{html.escape(title)}" src="{image}"></div>')
    parts.append(f'<div class="nums">{numbers}</div></div></section>')
    return "\n".join(parts)


def read_csv(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r]
    return rows[0], rows[1:]


# Once the page has loaded, the body says how many of its figures the
# browser decoded (scripts/check-report-in-browser.sh reads it).
CHECK = """<script>
window.addEventListener("load", function () {
  var images = document.images, loaded = 0;
  for (var k = 0; k < images.length; k++)
    if (images[k].complete && images[k].naturalWidth > 0) loaded++;
  document.body.setAttribute("data-figures-loaded", loaded + " of " + images.length);
});
</script>"""


def page(title, body):
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>{html.escape(title)}</title><style>{STYLE}</style></head>\n"
            f"<body>\n{body}\n{CHECK}\n</body></html>\n")


# ---------------------------------------------------------------- one run

def joints_of(leaves, stage):
    """{joint: {quantity: value}} from the summary's STAGE/joints/joint N/..."""
    joints = {}
    prefix = f"{stage}/joints/joint "
    for key, value in leaves.items():
        if key.startswith(prefix):
            j, _, quantity = key[len(prefix):].partition("/")
            joints.setdefault(int(j), {})[quantity] = value
    return joints


def joint_rows(leaves):
    """[joint, static opening, peak opening, at t, at z, peak slip] per joint, mm."""
    static, dynamic = joints_of(leaves, "static"), joints_of(leaves, "dynamic")
    rows = []
    for j in sorted(set(static) | set(dynamic)):
        d = dynamic.get(j, {})
        rows.append([j, static.get(j, {}).get("peak opening [m]", 0.) * 1e3,
                     d.get("peak opening [m]", 0.) * 1e3, d.get("peak opening time [s]", 0.),
                     d.get("peak opening z [m]", 0.), d.get("peak slip [m]", 0.) * 1e3])
    return rows


def joint_figure(rows):
    fig, ax = plt.subplots(figsize=(8, 3.6))
    width = 0.4
    numbers = [r[0] for r in rows]
    ax.bar([j - width / 2 for j in numbers], [r[1] for r in rows], width, label="static")
    ax.bar([j + width / 2 for j in numbers], [r[2] for r in rows], width, label="dynamic peak")
    ax.set_xlabel("joint")
    ax.set_ylabel("largest opening [mm]")
    ax.set_xticks(numbers)
    ax.legend()
    ax.grid(axis="y", alpha=0.3)
    return figure_data(fig)


def headline_section(leaves, rows):
    """The first screen: the numbers an engineer asks first, beside the joints' openings."""
    facts = []
    if rows:
        top = max(rows, key=lambda r: r[2])
        facts.append([f"largest joint opening [mm] (joint {top[0]}, t = {top[3]:.3g} s, "
                      f"z = {top[4]:.4g} m)", top[2]])
        slip = max(rows, key=lambda r: r[5])
        facts.append([f"largest joint slip [mm] (joint {slip[0]})", slip[5]])
    for key, value in leaves.items():
        # the monitors' displacements and tensions here; all their peaks below
        name = key[len("peaks/"):-len("/value")]
        if key.startswith("peaks/") and key.endswith("/value") and (
                name.endswith(("[m]", ".s1 [Pa]")) or "major principal" in name):
            facts.append([f"peak {name}", value])
    for face in ("upstream", "downstream"):
        for quantity in ("max major principal stress [Pa]/value", "arch DCR/largest",
                         "cantilever DCR/largest"):
            key = f"stress envelope/{face}/{quantity}"
            if key in leaves:
                facts.append([f"{face} face: {quantity.replace('/value', '').replace('/', ' ')}",
                              leaves[key]])
    if "evaluation/verdict" in leaves:
        # EM 1110-2-6053's reading of a linear analysis (doc/theory/results.md §3)
        facts.append(["evaluation: verdict", leaves["evaluation/verdict"]])
        if leaves.get("evaluation/limits exceeded"):
            facts.append(["evaluation: limits exceeded", leaves["evaluation/limits exceeded"]])
    for key in ("energy balance/balance error", "joints/steps not converged", "model/dofs",
                "joints/node pairs", "dynamic/steps"):
        if key in leaves:
            facts.append([key.replace("/", ": "), leaves[key]])
    return section("At a glance", table(facts, ["", ""]),
                   joint_figure(rows) if rows else None,
                   "Openings and slips are relative displacements of the node pairs since "
                   "grouting (doc/theory/joints.md); stresses are total (static plus dynamic), "
                   "tension positive.")


def joint_section(folder, rows):
    if not rows:
        return ""
    text = table([[f"joint {r[0]}"] + r[1:] for r in rows],
                 ["joint", "static opening [mm]", "peak opening [mm]", "at t [s]", "at z [m]",
                  "peak slip [mm]"])
    out = section("Contraction joints: openings and slips", text)
    envelope = os.path.join(folder, "joint_envelopes_dynamic.csv")
    if os.path.exists(envelope):
        _, data = read_csv(envelope)
        by_joint = {}
        for j, z, opening in data:
            by_joint.setdefault(int(j), []).append((float(z), float(opening) * 1e3))
        fig, ax = plt.subplots(figsize=(6, 5))
        for j, points in sorted(by_joint.items()):
            points.sort()
            if max(p[1] for p in points) > 1e-6:
                ax.plot([p[1] for p in points], [p[0] for p in points], marker=".",
                        label=f"joint {j}")
        ax.set_xlabel("largest opening over the run [mm]")
        ax.set_ylabel("z [m]")
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, ncol=2)
        largest = [[f"joint {j}", max(p[1] for p in points)]
                   for j, points in sorted(by_joint.items())]
        out += section("Joint openings along the height", table(largest, ["joint",
                       "largest opening [mm]"]), figure_data(fig))
    return out


def histories_section(folder, leaves):
    peaks = {}
    for key, value in leaves.items():
        if key.startswith("peaks/") and key.count("/") >= 2:
            name, _, quantity = key[len("peaks/"):].rpartition("/")
            peaks.setdefault(name, {})[quantity] = value
    if not peaks:
        return ""
    rows = [[name, p.get("value", 0.), p.get("time [s]", 0.)] for name, p in peaks.items()]
    image = None
    path = os.path.join(folder, "histories.csv")
    if os.path.exists(path):
        header, data = read_csv(path)
        shown = [i for i, h in enumerate(header) if "[m]" in h][:6]
        if shown:
            fig, ax = plt.subplots(figsize=(8, 3.8))
            t = [float(r[0]) for r in data]
            for i in shown:
                ax.plot(t, [float(r[i]) * 1e3 for r in data], label=header[i], lw=0.8)
            ax.set_xlabel("t [s]")
            ax.set_ylabel("displacement [mm]")
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7)
            image = figure_data(fig)
    return section("Peaks of the monitored quantities", table(rows, ["quantity", "peak",
                   "at t [s]"]), image)


def stress_section(folder, leaves, title):
    path = os.path.join(folder, "stress_envelope_dynamic.csv")
    if not os.path.exists(path):
        return ""
    rows = [[key[len("stress envelope/"):], value] for key, value in leaves.items()
            if key.startswith("stress envelope/") and not key.endswith(("x [m]", "y [m]",
                                                                          "z [m]"))]
    png = os.path.join(folder, ".report_stress.png")
    out = ""
    try:
        stress_envelope_plot.draw(path, png, f"{title}: largest major principal stress")
        out = section("Stresses on the faces", table(rows, ["quantity", "value"]),
                      file_data(png), "Total stresses (static plus dynamic), tension "
                      "positive; the faces as an engineer looks at them.")
        header, _ = read_csv(path)
        for column in ("largest arch DCR", "largest cantilever DCR"):
            if column in header:
                stress_envelope_plot.draw(path, png, f"{title}: {column}", column=column,
                                          scale=1.0, value_label=column)
                out += section(f"Demand-capacity ratio: {column[len('largest '):]}",
                               "<p class=\"note\">The DCR levels, CIDs and overstressed "
                               "areas are in the table above (doc/theory/results.md).</p>",
                               file_data(png))
    finally:
        if os.path.exists(png):
            os.remove(png)
    return out


def energy_section(leaves):
    terms = [(key[len("energy balance/"):], value) for key, value in leaves.items()
             if key.startswith("energy balance/")]
    if not terms:
        return ""
    shown = [(k, v) for k, v in terms if k.endswith("[J]") and "," not in k
             and not k.startswith("damping dissipation in")]
    fig, ax = plt.subplots(figsize=(8, 3.5))
    ax.barh([k.replace(" [J]", "") for k, _ in shown], [v for _, v in shown])
    ax.set_xlabel("energy [J]")
    ax.grid(axis="x", alpha=0.3)
    fig.tight_layout()
    return section("Energy balance", table(terms, ["term", "value"]), figure_data(fig),
                   "Over the dynamic stage (doc/theory/results.md §7): the input work against "
                   "what the dam, rock and water hold and dissipate.")


def prefixed(leaves, prefix):
    return [[key[len(prefix):], value] for key, value in leaves.items()
            if key.startswith(prefix)]


def run_page(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        leaves = flatten(json.load(f))
    title = str(leaves.get("case", os.path.basename(os.path.abspath(folder))))
    rows = joint_rows(leaves)
    body = [f"<h1>ArchDam run report: {html.escape(title)}</h1>",
            f'<p class="note">Results folder: {html.escape(os.path.abspath(folder))}</p>']
    stopped = prefixed(leaves, "stopped/")
    if stopped:
        body.append(section("The run stopped early", table(stopped, ["", ""])))
    body.append(headline_section(leaves, rows))
    warnings = [v for k, v in leaves.items() if k.startswith("warnings/")]
    body.append(section("Warnings", "<ul>" + "".join(
        f'<li class="warning">{html.escape(str(w))}</li>' for w in warnings) + "</ul>"
        if warnings else "<p>none</p>"))
    body.append(section("Input motion", table(prefixed(leaves, "ground motion/"), ["", ""])))
    model = [[k, v] for k, v in prefixed(leaves, "mesh/") + prefixed(leaves, "model/")
             if not k.startswith("joints/joint ")]
    body.append(section("Model", table(model, ["", ""])))
    static = [[k, v] for k, v in prefixed(leaves, "static/") if not k.startswith("joints/")]
    if static:
        body.append(section("Static state", table(static, ["", ""])))
    body.append(joint_section(folder, rows))
    body.append(histories_section(folder, leaves))
    body.append(stress_section(folder, leaves, title))
    body.append(energy_section(leaves))
    return page(f"ArchDam: {title}", "\n".join(b for b in body if b))


# ---------------------------------------------------------------- a suite

def suite_page(folder):
    header, rows = read_csv(os.path.join(folder, "suite.csv"))
    records = header[1:header.index("mean")]
    openings = [r for r in rows if r[0].startswith("dynamic/joints/") and
                r[0].endswith("peak opening [m]")]
    body = [f"<h1>ArchDam record suite: {len(records)} records</h1>",
            '<p class="note">Design value: the mean with seven records or more, else the '
            'largest (doc/user-guide.md, "Record suites").</p>',
            "<p>Records: " + ", ".join(
                f'<a href="{html.escape(r)}/report.html">{html.escape(r)}</a>'
                for r in records) + "</p>"]
    if openings:
        fig, ax = plt.subplots(figsize=(9, 4))
        joints = [int(r[0].split("joint ")[1].split("/")[0]) for r in openings]
        width = 0.8 / len(records)
        for k, name in enumerate(records):
            ax.bar([j - 0.4 + (k + 0.5) * width for j in joints],
                   [float(r[1 + k]) * 1e3 for r in openings], width, label=name)
        design = header.index("design value")
        ax.plot(joints, [float(r[design]) * 1e3 for r in openings], "k_", markersize=14,
                label="design value")
        ax.set_xlabel("joint")
        ax.set_ylabel("peak opening [mm]")
        ax.set_xticks(joints)
        ax.legend(fontsize=8)
        ax.grid(axis="y", alpha=0.3)
        body.append(section("Peak joint openings per record", table(
            [[r[0].split("/")[2]] + [float(v) * 1e3 for v in r[1:]] for r in openings],
            ["joint"] + [f"{h} [mm]" for h in header[1:]]), figure_data(fig)))
    body.append(section("Every peak over the records", table(
        [[r[0]] + [float(v) for v in r[1:]] for r in rows], header)))
    return page("ArchDam record suite", "\n".join(body))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--output", default=None)
    args = parser.parse_args()
    output = args.output or os.path.join(args.folder, "report.html")
    text = (suite_page(args.folder) if os.path.exists(os.path.join(args.folder, "suite.csv"))
            else run_page(args.folder))
    temporary = output + ".tmp"
    with open(temporary, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(temporary, output)
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
