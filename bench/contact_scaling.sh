#!/bin/bash
# Benchmark (doc/performance.md §2, the contact problem against the number of
# node pairs): the reference case prm/paper_235m_dam.prm as shipped, its
# joints meshed finer (more quadratic cells through the thickness and over
# the height of the dam; the rock and the water as shipped), each mesh run
# alone, one after the other, in the strong motion (its rise shortened to
# 0.2 s) to END_TIME s. From each run's summary.json: the node pairs, the
# contact problem's time per step, its setup (W = B Kbar^-1 B^T built from
# the condensed factor's Schur complement, static and dynamic), its memory,
# and each one's growth against the first mesh as an exponent,
# log(value / first value) / log(pairs / first pairs): 1 is linear.
#
# usage: bash bench/contact_scaling.sh BUILD [OUTPUT_DIR] [END_TIME] [MESH]...
#   MESH: THROUGHxHEIGHT, the cells through the thickness and over the
#   height (default: 2x9, the case's own, 830 node pairs, and 3x13, 1,610;
#   the rock's cells at the dam follow the dam's, so the DOFs grow too:
#   4x20, about four times the pairs, is about 5.8e5 DOFs, which the mesh's
#   memory check refuses on a 24 GB machine)
set -euo pipefail
build=$(realpath "$1")
out=$(realpath -m "${2:-contact_scaling}")
end=${3:-1}
shift $(( $# < 3 ? $# : 3 ))
meshes=("$@")
[ ${#meshes[@]} -gt 0 ] || meshes=(2x9 3x13)
cd "$(dirname "$0")/.."
mkdir -p "$out"
for mesh in "${meshes[@]}"; do
  through=${mesh%x*}
  height=${mesh#*x}
  echo "mesh $mesh: running" >&2
  LD_LIBRARY_PATH="$build" OPENBLAS_NUM_THREADS=1 /usr/bin/time -v "$build/archdam" prm/paper_235m_dam.prm \
    --set "Mesh/Arch dam/Cells through thickness=$through" \
    --set "Mesh/Arch dam/Cells over height=$height" \
    --set "Time integration/End time=$end" \
    --set "Ground motion/Generated motion/Rise time=0.2" \
    --set "Output/Directory=$out/$mesh" --set "Output/Progress=false" \
    --set "Output/Field output interval=0" \
    --set "Checkpoints/Wall-time interval (s)=0" > "$out/$mesh.log" 2>&1 ||
    { echo "mesh $mesh: archdam failed, see $out/$mesh.log" >&2; exit 1; }
done
/usr/bin/python3 - "$out" "${meshes[@]}" <<'EOF'
import json, math, re, sys
out, meshes = sys.argv[1], sys.argv[2:]
rows = []
for mesh in meshes:
    s = json.load(open(f"{out}/{mesh}/summary.json"))
    d = s["dynamic"]
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(f"{out}/{mesh}.log").read())
    rows.append({
        "mesh": mesh, "pairs": s["joints"]["node pairs"], "dofs": s["model"]["dofs"],
        "contact": d["time per step [s]"]["contact problem"],
        "step": d["time per step [s]"]["step"],
        "substitutions": d["time per step [s]"]["forward elimination"]
                         + d["time per step [s]"]["backward substitution"],
        "setup": d["time to build the flexibility matrix [s]"]
                 + s["static"].get("time to build the flexibility matrix [s]", 0.),
        "memory": d["memory [MB]"]["contact problem"],
        "iterations": d["contact iterations per step"]["average"],
        "solves": d["contact problem"]["updated solves"] / d["steps"],
        "rss": int(rss.group(1)) / 1024**2 if rss else float("nan"),
    })
first = rows[0]
def growth(r, key):
    if r is first:
        return ""
    return f" (n^{math.log(r[key] / first[key]) / math.log(r['pairs'] / first['pairs']):.2f})"
print("| mesh (Q2, through x height) | node pairs | DOFs | contact problem per step [s] | "
      "its setup, W static + dynamic [s] | its memory [MB] | contact iterations per step | "
      "updated solves per step | substitutions per step [s] | step [s] | peak resident [GB] |")
print("|---" * 11 + "|")
for r in rows:
    print(f"| {r['mesh']} | {r['pairs']} ({r['pairs'] / first['pairs']:.2f}x) | {r['dofs']} | "
          f"{r['contact']:.4f}{growth(r, 'contact')} | {r['setup']:.2f}{growth(r, 'setup')} | "
          f"{r['memory']:.0f}{growth(r, 'memory')} | {r['iterations']:.2f} | {r['solves']:.2f} | "
          f"{r['substitutions']:.4f} | {r['step']:.4f} | {r['rss']:.2f} |")
EOF
