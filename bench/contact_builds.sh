#!/bin/bash
# Benchmark (doc/performance.md §9): two builds of ArchDam on the same case
# at the same time, so that both see the same machine: the contact
# problem's time per step and the whole step's, their ratio (second build
# against the first), and how far the two runs' peaks and energies differ.
# The case: the reference case on the rock reaching half the dam's height
# beyond it, as the convergence study runs it (corrected_rock_beta of
# scripts/convergence-study.py), to END_TIME s: the joints open and slide
# from about 2 s. The mesh is one of the study's (MESH, by default its
# "production", the former production mesh Q2 2 x 2 x 6 with 780 node pairs;
# q2-229 is the case's mesh, 1,170 node pairs). No checkpoints: writing one starts the contact problem's
# LU anew (doc/theory/joints.md §6), at another step in each run.
#
# Settings after MESH (--set "S/P=V") go to the first run alone: with the
# same build twice, an A/B of a setting in one binary (the former path
# first).
#
# usage: bash bench/contact_builds.sh FIRST_BUILD SECOND_BUILD [OUTPUT_DIR] [END_TIME] [MESH] [--set "S/P=V"]...
set -euo pipefail
first=$(realpath "$1")
second=$(realpath "$2")
out=$(realpath -m "${3:-contact_builds}")
end=${4:-3.5}
mesh=${5:-production}
shift $(( $# < 5 ? $# : 5 ))
first_only=("$@")
second_only=()
cd "$(dirname "$0")/.."
mapfile -t settings < <(/usr/bin/python3 - "$end" "$mesh" <<'EOF'
import importlib.util, sys
spec = importlib.util.spec_from_file_location("study", "scripts/convergence-study.py")
study = importlib.util.module_from_spec(spec)
spec.loader.exec_module(study)
for s in study.mesh_settings(sys.argv[2] + "-extent050") + study.run_settings("corrected_rock_beta", sys.argv[1]):
    print(s)
EOF
)
arguments=()
for s in "${settings[@]}"; do arguments+=(--set "$s"); done
mkdir -p "$out"
for which in first second; do
  build=${!which}
  only="${which}_only[@]"
  # the build's own library, whatever the executable's run path names
  LD_LIBRARY_PATH="$build" OPENBLAS_NUM_THREADS=1 "$build/archdam" prm/paper_235m_dam.prm "${arguments[@]}" "${!only}" \
    --set "Output/Directory=$out/$which" --set "Output/Progress=false" \
    --set "Checkpoints/Wall-time interval (s)=0" > "$out/$which.log" 2>&1 &
done
wait
/usr/bin/python3 - "$out" <<'EOF'
import json, sys
out = sys.argv[1]
def flat(d, prefix=""):
    values = {}
    for k, v in d.items():
        if isinstance(v, dict):
            values.update(flat(v, prefix + k + "/"))
        elif isinstance(v, (int, float)):
            values[prefix + k] = v
    return values
a, b = (flat(json.load(open(f"{out}/{w}/summary.json"))) for w in ["first", "second"])
print(f"DOFs {a['model/dofs']:.0f}, node pairs {a['joints/node pairs']:.0f}, steps {a['dynamic/steps']:.0f}")
for key in ["dynamic/time per step [s]/contact problem", "dynamic/time per step [s]/step",
            "dynamic/wall time per step [s]"]:
    print(f"{key}: first {a[key]:.4g}, second {b[key]:.4g}, second / first {b[key] / a[key]:.3f}")
for key in ["dynamic/contact problem/factorizations", "dynamic/contact problem/updated solves",
            "dynamic/contact problem/handed over",
            "dynamic/contact iterations per step/average"]:
    print(f"{key}: first {a.get(key, 0):.6g}, second {b.get(key, 0):.6g}")
results = [k for k in a if (k.startswith("peaks/") and k.endswith("/value"))
           or (k.startswith("dynamic/joints/joint ") and k.endswith("peak opening [m]"))
           or k.startswith("energy balance/")]
worst = max(results, key=lambda k: abs(b[k] - a[k]) / max(abs(a[k]), 1e-30))
print(f"largest relative difference of {len(results)} peaks and energies: "
      f"{abs(b[worst] - a[worst]) / max(abs(a[worst]), 1e-30):.2g} ({worst})")
EOF
