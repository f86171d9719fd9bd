#!/bin/bash
# Benchmark (issue 19; doc/performance.md §9): where the time of a run and
# of one dynamic step goes, on the reference case as shipped
# (prm/paper_235m_dam.prm: its production mesh) or on a case given, for the
# first END_TIME seconds of its motion. Prints the stages' wall times, the
# peak resident memory, the factorization's size and the step's profile from
# summary.json (dynamic/time per step [s]: forward elimination, contact
# problem, backward substitution, energy balance, other recorders, the copy
# of the last good step; the foundation's boundary update), each also as a
# share of the step, and what the dynamic stage holds (dynamic/memory [MB]).
#
# usage: bash bench/step_profile.sh [BUILD_DIR] [OUTPUT_DIR] [END_TIME] [MPI_PROCESSES] [CASE.prm] [--set "S/P=V"]...
set -euo pipefail
build=$(realpath "${1:-build}")
out=$(realpath -m "${2:-step_profile}")
end=${3:-0.1}
np=${4:-1}
case_file=$(realpath "${5:-$(dirname "$0")/../prm/paper_235m_dam.prm}")
shift $(( $# < 5 ? $# : 5 ))
cd "$(dirname "$0")/.."
launcher=()
[ "$np" -gt 1 ] && launcher=(mpirun -np "$np")
/usr/bin/time -v "${launcher[@]}" "$build/archdam" "$case_file" \
  --set "Time integration/End time=$end" \
  --set "Output/Directory=$out" \
  --set "Output/Field output interval=0" \
  --set "Output/Progress=false" \
  --set "Output/Timer summary=true" "$@" > "$out.log" 2>&1
grep -E "^Mesh:|Joints:|Dynamic stage: [0-9]" "$out.log"
grep -E "^\| (setup|static|dynamic: factorization|dynamic: steps|Total)" "$out.log" | cut -c1-60
grep -E "Maximum resident set size" "$out.log"
/usr/bin/python3 - "$out/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))["dynamic"]
f = s.get("factorization", {})
if f:
    print(f"factorization: {f['factor entries']:.3g} entries, {f['operations']:.3g} operations, "
          f"{f['memory [MB]']:.0f} MB (MUMPS)")
p = dict(s.get("time per step [s]", {}))
if "foundation boundary update per step [s]" in s:
    p["foundation boundary update"] = s["foundation boundary update per step [s]"]
step = p.get("step", s["wall time per step [s]"])
print(f"{'per step':30s} {'[s]':>9s} {'/ step':>8s}")
for k, v in p.items():
    print(f"{k:30s} {v:9.4f} {v / step:8.3f}")
c = s.get("contact problem", {})
if c:
    print(f"contact problem: {c['factorizations']} factorizations, {c['updated solves']} updated solves; "
          f"{s['contact iterations per step']['average']} iterations per step on average")
m = s.get("memory [MB]", {})
if m:
    print("held in the dynamic stage [MB]: " + ", ".join(f"{k} {v:.0f}" for k, v in m.items()))
PY
