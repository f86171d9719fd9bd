#!/bin/bash
# Natural frequencies of the reference arch dam (Mesh/Source = arch dam,
# default geometry) under mesh refinement (doc/verification.md "Whole system"):
# the modal stage on a sequence of meshes with the cells over the height,
# across each block and through the thickness refined together, for Q1 and
# Q2, on rigid rock (Foundation depth = 0) and on massless rock, with an empty
# reservoir; then, on one mesh, with Westergaard added mass and with
# incompressible and compressible water. One line per run:
#   foundation water degree height across thickness cells dofs seconds f1 ... f5 [Hz]
# (seconds: wall time of the whole run on a shared machine, indicative only)
# Tables and the extrapolation: doc/verification.md ("Whole system: natural frequencies of
# the arch dam"), results in bench/RESULTS.md.
#
# usage: bash bench/modal_convergence.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
build=$(realpath "${1:-build}")
out=${2:-modal_convergence}
mkdir -p "$out"
cd "$out"

cat > modal.prm <<'EOF'
subsection Mesh
  set Source = arch dam
end
subsection Analysis
  set Stages = modal
end
subsection Modal analysis
  set Number of modes = 5
  set Write mode shapes = false
end
subsection Output
  set Field output interval = 0
  set Progress = false
  set Timer summary = false
end
EOF

# run FOUNDATION WATER DEGREE HEIGHT ACROSS THICKNESS [WATER_LEVEL]
run() {
  local foundation=$1 water=$2 degree=$3 nz=$4 nb=$5 nt=$6
  # Without water the mesh has no layer boundary at the water level (level
  # 0), so the layers are uniform and the meshes nested; the comparison of
  # the water models keeps the water level's layer boundary for all of them.
  local level=${7:-202}
  [ "$water" = none ] && [ -z "${7:-}" ] && level=0
  local name=${foundation}_${water}_q${degree}_${nz}_${nb}_${nt}_${level}
  local depth=0
  [ "$foundation" = massless ] && depth=1
  local start=$(date +%s.%N)
  "$build/archdam" modal.prm \
    --set "Analysis/Case name=$name" --set "Output/Directory=$name" \
    --set "Finite element/Degree=$degree" \
    --set "Mesh/Arch dam/Cells over height=$nz" \
    --set "Mesh/Arch dam/Cells across each block=$nb" \
    --set "Mesh/Arch dam/Cells through thickness=$nt" \
    --set "Mesh/Arch dam/Foundation depth=$depth" \
    --set "Mesh/Arch dam/Water level=$level" \
    --set "Reservoir/Model=$water" > "$name.log"
  local seconds=$(echo "$(date +%s.%N) - $start" | bc)
  /usr/bin/python3 - "$name/summary.json" "$foundation" "$water" "$degree" "$nz" "$nb" "$nt" \
    "$seconds" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
f = [s["modal"]["mode %d" % k]["frequency [Hz]"] for k in range(1, 6)]
print(" ".join(sys.argv[2:8]), s["model"]["cells"], s["model"]["dofs"],
      "%.0f" % float(sys.argv[8]), " ".join("%.5f" % v for v in f), flush=True)
EOF
}

echo "# $(date -u) $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "# foundation water degree height across thickness cells dofs seconds f1 f2 f3 f4 f5"
for level in "3 1 1" "6 2 2" "12 4 4" "24 8 8"; do
  run rigid none 1 $level
done
for level in "3 1 1" "6 2 2" "12 4 4" "24 8 8"; do
  run rigid none 2 $level
done
for level in "3 1 1" "6 2 2" "12 4 4"; do
  run massless none 2 $level
done
for water in none westergaard incompressible compressible; do
  run rigid $water 2 6 2 2 202
  run massless $water 2 6 2 2 202
done
