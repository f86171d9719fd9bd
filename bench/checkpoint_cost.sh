#!/bin/bash
# Benchmark: what checkpoints of the dynamic stage cost (output/checkpoint.h,
# doc/user-guide.md "Checkpoints and resuming a run"), on the paper's dam on
# the coarse mesh of scripts/compare-paper-variants.py (Q1; frictional joints,
# compressible water, massed foundation with the MTF: every kind of state a
# checkpoint holds), 0.5 s of the motion with a checkpoint every 10 steps.
# Prints the wall times of the timer table for the steps, the checkpoints
# (written, fsync'd, renamed) and the copy of the last good step kept every
# step for the divergence stop, and the size of one checkpoint.
#
# usage: bash bench/checkpoint_cost.sh [BUILD_DIR] [OUTPUT_DIR] [MPI_PROCESSES]
set -euo pipefail
build=$(realpath "${1:-build}")
out=$(realpath -m "${2:-checkpoint_cost}")
np=${3:-1}
cd "$(dirname "$0")/.."
launcher=()
[ "$np" -gt 1 ] && launcher=(mpirun -np "$np")
"${launcher[@]}" "$build/archdam" prm/paper_235m_dam.prm \
  --set "Finite element/Degree=1" \
  --set "Mesh/Arch dam/Cells across each block=1" \
  --set "Mesh/Arch dam/Cells through thickness=1" \
  --set "Mesh/Arch dam/Cells over height=9" \
  --set "Time integration/End time=0.5" \
  --set "Checkpoints/Interval (steps)=10" \
  --set "Output/Directory=$out" \
  --set "Output/Field output interval=0" \
  --set "Output/Progress=false" \
  --set "Output/Timer summary=true" > "$out.log" 2>&1
grep -E "DOFs|Dynamic stage:" "$out.log" | head -3
grep -E "dynamic: (steps|checkpoints|last good)" "$out.log"
echo "checkpoint size [bytes]: $(du -sb "$out/checkpoint" | cut -f1)"
