#!/usr/bin/python3
"""Run the reference case and its variants, and draw the paper's figures.

The reference case is prm/paper_235m_dam.prm; each variant
(prm/paper_235m_dam_<variant>.prm) includes it and changes one thing. This
script runs the cases asked for (a case whose summary.json exists is not run
again unless --rerun), then draws from whatever results exist:

  opening_A_B.png          joint opening at A and B over time (paper's points)
  stress_C_joints.png      major principal stress at C with and without joints
  max_opening_water.png    maximum opening of each joint along the dam axis,
                           compressible / incompressible / Westergaard water
  crest_displacement.png   stream displacement of the crest, every case run
  max_opening_records.png  maximum opening of each joint at the crest under the
                           design motion and each record of the suite, with
                           the records' largest (the design value of fewer
                           than seven records)
  suite.csv                the record suite's statistics (a copy of the one
                           archdam --gather writes)
  opening_envelopes.png    per joint, the maximum opening over the height
  stress_envelope_<case>.png  largest major principal stress over the run on
                           the upstream and downstream faces (reference and
                           glued; scripts/stress_envelope_plot.py)
  comparison.csv           one row per case: the peaks the figures show
  dcr_<stress>_<case>.png  the largest arch and cantilever DCR on the faces
                           (reference and glued, with Evaluation/Evaluate)
  evaluation.csv           per case, face and stress: the largest DCR, the
                           longest CID above each level, the overstressed
                           share above DCR 1, the areas evaluated and left
                           out, and the verdict (doc/theory/results.md §3)
  data/<case>.json         what the figures and comparison.csv read of each
                           case's run (a few hundred kB, with the version
                           that ran it): a case without results here is
                           drawn from it, so the figures can be completed
                           with cases run at another time (not the stress
                           envelope maps, which need the run's own file)

Usage (from the project root):
  /usr/bin/python3 scripts/compare-paper-variants.py [--run all|CASE,...|none]
      [--mesh default|coarse] [--end-time S] [--results DIR] [--figures DIR]
      [--archdam build/archdam] [--rerun]

--mesh coarse runs every case on a coarse linear mesh (1 cell across a block
and through the thickness, 9 over the height, the fewest that give every
block of the as-built layout its own foundation step): a quick look, not the
production mesh of doc/performance.md §3. The results go to DIR/<case>[_coarse].
"""
import argparse
import csv
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stress_envelope_plot  # noqa: E402

# The records of prm/paper_235m_dam_suite.prm: each is a case of its own here,
# run as the suite runs it (archdam SUITE.prm --record NAME), and the suite's
# statistics are gathered once all three have run (--gather).
RECORDS = ["elcentro", "rinaldi", "sanfernando"]
CASES = ["reference", "glued", "incompressible", "westergaard", "massless", "pacoima"] + RECORDS
LABELS = {
    "reference": "reference (compressible, joints, massed rock)",
    "glued": "joints glued",
    "incompressible": "incompressible water",
    "westergaard": "Westergaard added mass",
    "massless": "massless foundation",
    "pacoima": "Pacoima record",
    "elcentro": "El Centro 1940 (suite)",
    "rinaldi": "Rinaldi 1994 (suite)",
    "sanfernando": "Pacoima Dam 1971 (suite)",
}
COARSE = [
    "Finite element/Degree=1",
    "Mesh/Arch dam/Cells across each block=1",
    "Mesh/Arch dam/Cells through thickness=1",
    "Mesh/Arch dam/Cells over height=9",
]


def prm_file(case):
    if case in RECORDS:
        return "prm/paper_235m_dam_suite.prm"
    return "prm/paper_235m_dam.prm" if case == "reference" else f"prm/paper_235m_dam_{case}.prm"


def suite_dir(args):
    return os.path.join(args.results, "paper_235m_dam_suite" + ("_coarse" if args.mesh == "coarse" else ""))


def result_dir(args, case):
    if case in RECORDS:
        return os.path.join(suite_dir(args), case)
    name = "paper_235m_dam" if case == "reference" else f"paper_235m_dam_{case}"
    return os.path.join(args.results, name + ("_coarse" if args.mesh == "coarse" else ""))


def archdam_command(args, case_file, out, more):
    command = [args.archdam, case_file, "--set", f"Output/Directory={out}"] + more
    for s in (COARSE if args.mesh == "coarse" else []) + (
        [f"Time integration/End time={args.end_time}"] if args.end_time else []
    ):
        command += ["--set", s]
    return command


def gather_suite(args):
    """The suite's statistics from its records' runs (archdam --gather), once
    all of them have run."""
    if not all(os.path.exists(os.path.join(result_dir(args, r), "summary.json")) for r in RECORDS):
        return
    command = archdam_command(args, prm_file(RECORDS[0]), suite_dir(args), ["--gather"])
    print("suite: gathering", " ".join(f'"{c}"' if " " in c else c for c in command), flush=True)
    if subprocess.run(command).returncode != 0:
        print("suite: archdam --gather refused (above); the figures are drawn without suite.csv",
              flush=True)


def run(args, case):
    out = result_dir(args, case)
    # --resume continues a run that stopped (interrupted, or killed) from
    # its checkpoint, with the same case and settings (archdam --resume).
    summary = os.path.join(out, "summary.json")
    state = json.load(open(summary)) if os.path.exists(summary) else None
    finished = state is not None and "stopped" not in state and "dynamic" in state
    checkpoint = os.path.exists(os.path.join(out, "checkpoint", "manifest.txt"))
    resume = args.resume and not finished and checkpoint
    if state is not None and not args.rerun and not resume:
        print(f"{case}: results in {out} (kept; --rerun to run again" +
              ("" if finished or not checkpoint else
               "; it stopped before its end: --resume continues it") + ")")
        return
    # A record of the suite runs as the suite runs it, into the suite's
    # folder's subfolder of its name.
    more = ["--resume"] if resume else []
    command = (archdam_command(args, prm_file(case), suite_dir(args), ["--record", case] + more)
               if case in RECORDS else archdam_command(args, prm_file(case), out, more))
    print(f"{case}: {'continuing' if resume else 'running'}",
          " ".join(f'"{c}"' if " " in c else c for c in command), flush=True)
    os.makedirs(out, exist_ok=True)
    # The run's progress is streamed to the terminal as it comes, and kept
    # in run.log beside the results (a continued run's after the first part's).
    with open(os.path.join(out, "run.log"), "a" if resume else "w") as log:
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   text=True, bufsize=1)
        for line in process.stdout:
            sys.stdout.write(f"  {case} | {line}")
            sys.stdout.flush()
            log.write(line)
            log.flush()
        status = process.wait()
    if status != 0:
        sys.exit(f"{case}: archdam failed with exit code {status}; see {out}/run.log")


def read_csv(path):
    """Columns of a CSV file as lists of floats, keyed by header."""
    with open(path) as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {h: [float(r[i]) for r in body] for i, h in enumerate(header)}


def load(args, case):
    """The results of a case from its result directory, else from the figure
    data kept beside the figures (store()), or None if it has neither."""
    d = result_dir(args, case)
    if not os.path.exists(os.path.join(d, "summary.json")):
        kept = os.path.join(args.figures, "data", case + ".json")
        if not os.path.exists(kept):
            return None
        r = json.load(open(kept))
        print(f"{case}: no results in {d}; its figure data from {kept} (run {r['run']})")
        return r
    r = {"dir": d, "summary": json.load(open(os.path.join(d, "summary.json")))}
    for key, name in [
        ("histories", "histories.csv"),
        ("joints", "joint_histories_dynamic.csv"),
        ("crest", "joint_crest_dynamic.csv"),
        ("envelopes", "joint_envelopes_dynamic.csv"),
    ]:
        path = os.path.join(d, name)
        r[key] = read_csv(path) if os.path.exists(path) else None
    r["faces"] = face_maxima(os.path.join(d, "stress_envelope_dynamic.csv"))
    return r


STORED_COLUMNS = {"histories": ["time [s]", "crest.ux [m]", "base.ux [m]", "C.s1 [Pa]"],
                  "joints": ["time [s]", "A.opening [m]", "B.opening [m]"]}


def store(args, case, r):
    """Keep what the figures and comparison.csv read of a case's run in
    FIGURES/data/<case>.json (a few hundred kB), so that the figures can be
    drawn again with cases run at another time (each file says which run)."""
    if "run" in r:
        return
    def columns(table, keep):
        return {k: v for k, v in table.items() if k in keep} if table else None
    summary = r["summary"]
    kept = {
        "run": f"{summary.get('case', case)}, ArchDam {summary.get('version', 'unknown')}",
        "summary": {k: summary[k] for k in ["energy balance", "wall time [s]", "dynamic",
                                             "stress envelope", "evaluation"] if k in summary},
        "histories": columns(r["histories"], STORED_COLUMNS["histories"]),
        "joints": columns(r["joints"], STORED_COLUMNS["joints"]),
        "crest": r["crest"],
        "envelopes": r["envelopes"],
        "faces": r["faces"],
    }
    kept["summary"]["dynamic"] = {"memory [MB]": summary.get("dynamic", {}).get("memory [MB]", {})}
    os.makedirs(os.path.join(args.figures, "data"), exist_ok=True)
    path = os.path.join(args.figures, "data", case + ".json")
    with open(path, "w") as f:
        json.dump(kept, f, separators=(",", ":"))
    print("wrote", path)


def crest_deformation(r):
    """Crest minus base stream displacement (on massed rock the monitors move
    with the ground), from the static state."""
    h = r["histories"]
    base = h.get("base.ux [m]", [0.0] * len(h["crest.ux [m]"]))
    d = [c - b for c, b in zip(h["crest.ux [m]"], base)]
    return [v - d[0] for v in d]


FACES = ["crest", "upstream face", "downstream face"]


def face_maxima(path):
    """{face: (largest s1 over the run [Pa], its height z [m])} of a stress
    envelope file (faces named crest, upstream, downstream)."""
    if not os.path.exists(path):
        return {}
    best = {}
    for face, points in stress_envelope_plot.read(path).items():
        x, y, z, s1, t = max(points, key=lambda p: p[3])
        best[face if face == "crest" else face + " face"] = (s1, z)
    return best


def peak(values):
    return max(values, key=abs) if values else float("nan")


MESH_NOTES = {"coarse": "coarse mesh, not converged: a quick look",
              "default": "the case's own mesh (Q2 2 x 2 x 9)"}


def figure(path, draw, title, xlabel, ylabel, mesh):
    fig, ax = plt.subplots(figsize=(8, 4.5))
    draw(ax)
    ax.set_title(f"{title}\n({MESH_NOTES[mesh]})", fontsize=10)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    handles = ax.get_legend_handles_labels()[0]
    if len(handles) > 1:  # one curve needs no legend: the title names it
        ax.legend(fontsize=8, ncol=2 if len(handles) > 3 else 1)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print("wrote", path)


def draw_all(args, results):
    os.makedirs(args.figures, exist_ok=True)
    ref = results.get("reference")
    if ref and ref["joints"]:
        j = ref["joints"]

        def openings(ax):
            for point in ["A", "B"]:
                key = f"{point}.opening [m]"
                if key in j:
                    ax.plot(j["time [s]"], [1e3 * v for v in j[key]], label=f"{point}")

        figure(os.path.join(args.figures, "opening_A_B.png"), openings,
               "Joint opening at A (crown joint) and B (quarter-span joint), crest",
               "time [s]", "opening [mm]", args.mesh)

    with_c = [c for c in ["reference", "glued"] if results.get(c) and "C.s1 [Pa]" in results[c]["histories"]]
    if with_c:
        def stress(ax):
            for c in with_c:
                h = results[c]["histories"]
                ax.plot(h["time [s]"], [v / 1e6 for v in h["C.s1 [Pa]"]],
                        label="with joints" if c == "reference" else "joints glued")

        figure(os.path.join(args.figures, "stress_C_joints.png"), stress,
               "Major principal stress at C (crown block, downstream face near the crest)",
               "time [s]", "major principal stress [MPa] (tension > 0)", args.mesh)

    water = [c for c in ["reference", "incompressible", "westergaard"] if results.get(c) and results[c]["crest"]]
    if water:
        def along_axis(ax):
            for c in water:
                crest = results[c]["crest"]
                ax.plot(crest["joint"], [1e3 * v for v in crest["max opening [m]"]], "o-",
                        label={"reference": "compressible", "incompressible": "incompressible",
                               "westergaard": "Westergaard"}[c])
            ax.set_xticks(range(13))

        figure(os.path.join(args.figures, "max_opening_water.png"), along_axis,
               "Maximum joint opening at the crest along the dam axis",
               "joint (0 = left bank)", "maximum opening [mm]", args.mesh)

    records = [c for c in ["reference"] + RECORDS if results.get(c) and results[c]["crest"]]
    if any(c in RECORDS for c in records):
        def along_axis_records(ax):
            for c in records:
                crest = results[c]["crest"]
                ax.plot(crest["joint"], [1e3 * v for v in crest["max opening [m]"]],
                        "o-" if c in RECORDS else "s--",
                        label="design motion (reference)" if c == "reference" else LABELS[c])
            # the design value of fewer than seven records is their largest
            # (doc/user-guide.md, "Record suites"), here of the crest openings
            suite = [results[c]["crest"]["max opening [m]"] for c in records if c in RECORDS]
            if len(suite) == len(RECORDS) < 7:
                ax.plot(results[records[-1]]["crest"]["joint"], [1e3 * max(v) for v in zip(*suite)],
                        "k-", lw=2, alpha=0.4, label="the records' largest (the design value)")
            ax.set_xticks(range(13))

        figure(os.path.join(args.figures, "max_opening_records.png"), along_axis_records,
               "Maximum joint opening at the crest: the design motion and the suite's records",
               "joint (0 = left bank)", "maximum opening [mm]", args.mesh)
    suite_csv = os.path.join(suite_dir(args), "suite.csv")
    if os.path.exists(suite_csv):
        with open(suite_csv) as f, open(os.path.join(args.figures, "suite.csv"), "w") as g:
            g.write(f.read())
        print("wrote", os.path.join(args.figures, "suite.csv"))

    # the variants under the design motion (the records shake it otherwise:
    # max_opening_records.png compares them)
    crest_cases = [c for c in CASES if c not in RECORDS and results.get(c)
                   and "crest.ux [m]" in results[c]["histories"]]
    if crest_cases:
        def crest(ax):
            for c in crest_cases:
                ax.plot(results[c]["histories"]["time [s]"], [1e3 * v for v in crest_deformation(results[c])],
                        label=LABELS[c], lw=0.8)

        figure(os.path.join(args.figures, "crest_displacement.png"), crest,
               "Stream displacement of the crest relative to the dam base, from the static state",
               "time [s]", "displacement [mm]", args.mesh)

    if ref and ref["envelopes"]:
        def envelopes(ax):
            e = ref["envelopes"]
            joints = sorted(set(int(v) for v in e["joint"]))
            # one colour per joint (13 and more: the default cycle repeats after 10)
            colours = plt.cm.turbo(np.linspace(0.05, 0.95, len(joints)))
            for k, colour in zip(joints, colours):
                rows = [i for i, v in enumerate(e["joint"]) if int(v) == k]
                ax.plot([1e3 * e["max opening [m]"][i] for i in rows], [e["z [m]"][i] for i in rows],
                        label=f"joint {k}", color=colour)

        figure(os.path.join(args.figures, "opening_envelopes.png"), envelopes,
               "Maximum opening over the height of each joint (reference case)",
               "maximum opening [mm]", "elevation z [m]", args.mesh)

    for c in ["reference", "glued"]:
        envelope = results.get(c) and "dir" in results[c] and os.path.join(results[c]["dir"],
                                                                            "stress_envelope_dynamic.csv")
        if envelope and os.path.exists(envelope):
            png = os.path.join(args.figures, f"stress_envelope_{c}.png")
            stress_envelope_plot.draw(envelope, png, f"Largest major principal stress, {LABELS[c]} "
                                      f"({MESH_NOTES[args.mesh]})")
            print("wrote", png)

    for c in ["reference", "glued"]:
        envelope = results.get(c) and "dir" in results[c] and os.path.join(results[c]["dir"],
                                                                            "stress_envelope_dynamic.csv")
        if not envelope or not os.path.exists(envelope):
            continue
        with open(envelope) as f:
            header = f.readline()
        for stress in ["arch", "cantilever"]:
            if f"largest {stress} DCR" in header:
                png = os.path.join(args.figures, f"dcr_{stress}_{c}.png")
                stress_envelope_plot.draw(envelope, png, f"Largest {stress} DCR, {LABELS[c]} "
                                          f"({MESH_NOTES[args.mesh]})", column=f"largest {stress} DCR",
                                          scale=1.0, value_label=f"largest {stress} DCR")
                print("wrote", png)
    write_evaluation(args, results)

    path = os.path.join(args.figures, "comparison.csv")
    with open(path, "w") as f:
        w = csv.writer(f)
        w.writerow(["case", "peak opening A [m]", "peak opening B [m]", "largest crest opening [m]",
                    "joint", "mean of the joints' peak crest openings [m]", "peak s1 at C [Pa]",
                    "peak crest ux relative to the base [m]"]
                   + [f"largest s1 on the {face} [Pa]" for face in FACES]
                   + [f"its height on the {face} [m]" for face in FACES]
                   + ["energy balance error", "wall time [s]", "peak resident memory [GB]"])
        for c in CASES:
            r = results.get(c)
            if not r:
                continue
            j, h, crest, summary = r["joints"], r["histories"], r["crest"], r["summary"]
            largest = max(range(len(crest["joint"])), key=lambda i: crest["max opening [m]"][i]) if crest else None
            faces = r["faces"]
            memory = summary.get("dynamic", {}).get("memory [MB]", {}).get("peak resident, all processes")
            w.writerow([
                c,
                max(j["A.opening [m]"]) if j else "",
                max(j["B.opening [m]"]) if j else "",
                crest["max opening [m]"][largest] if crest else "",
                int(crest["joint"][largest]) if crest else "",
                sum(crest["max opening [m]"]) / len(crest["joint"]) if crest else "",
                max(h["C.s1 [Pa]"]),
                peak(crest_deformation(r)),
            ] + [faces[face][0] if face in faces else "" for face in FACES]
              + [faces[face][1] if face in faces else "" for face in FACES]
              + [summary.get("energy balance", {}).get("balance error", ""),
                 sum(summary.get("wall time [s]", {}).values()),
                 1e-3 * memory if memory else ""])
    print("wrote", path)


def write_evaluation(args, results):
    """evaluation.csv: the demand-capacity evaluation of each case that has one."""
    rows = []
    for c in CASES:
        r = results.get(c)
        envelope = r and r["summary"].get("stress envelope", {})
        verdict = r and r["summary"].get("evaluation", {}).get("verdict", "")
        for face in ["upstream", "downstream"]:
            part = (envelope or {}).get(face, {})
            for stress in ["arch", "cantilever"]:
                d = part.get(f"{stress} DCR")
                if not d:
                    continue
                levels = sorted((k for k in d if k.startswith("above ") and isinstance(d[k], dict)),
                                key=lambda k: float(k[len("above "):]))
                rows.append([c, face, stress, d["largest"]]
                            + [d[k]["longest CID [s]"] for k in levels]
                            + [d.get("overstressed share of the area above 1", ""),
                               part.get("evaluated area [m^2]", ""),
                               part.get("area left out at the base [m^2]", ""),
                               d.get("verdict", ""), verdict])
                header = (["case", "face", "stress", "largest DCR"]
                          + [f"longest CID {k} [s]" for k in levels]
                          + ["overstressed share above DCR 1", "evaluated area [m^2]",
                             "area left out at the base [m^2]", "verdict of this stress",
                             "verdict of the run"])
    if not rows:
        return
    path = os.path.join(args.figures, "evaluation.csv")
    with open(path, "w") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    print("wrote", path)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--run", default="all", help="all, none, or a comma-separated list of " + ", ".join(CASES))
    p.add_argument("--mesh", choices=["default", "coarse"], default="default")
    p.add_argument("--end-time", type=float, default=0, help="override the cases' end time [s]")
    p.add_argument("--results", default="results")
    p.add_argument("--figures", default=None, help="default: RESULTS/figures[_coarse]")
    p.add_argument("--archdam", default="build/archdam")
    p.add_argument("--rerun", action="store_true")
    p.add_argument("--resume", action="store_true",
                   help="continue each case that has a checkpoint from it (archdam --resume)")
    args = p.parse_args()
    if args.figures is None:
        args.figures = os.path.join(args.results, "figures" + ("_coarse" if args.mesh == "coarse" else ""))
    runs = {"all": CASES, "none": []}.get(args.run, args.run.split(","))
    for c in runs:
        if c not in CASES:
            sys.exit(f"--run: unknown case '{c}' (known: {', '.join(CASES)})")
        run(args, c)
    if any(c in RECORDS for c in runs) or not os.path.exists(os.path.join(suite_dir(args), "suite.csv")):
        gather_suite(args)
    results = {c: load(args, c) for c in CASES}
    if not any(results.values()):
        sys.exit(f"no results under {args.results} for --mesh {args.mesh}: run some cases first")
    for c, r in results.items():
        if r:
            store(args, c, r)
    draw_all(args, results)


if __name__ == "__main__":
    main()
