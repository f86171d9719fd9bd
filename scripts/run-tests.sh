#!/bin/bash
# Install, build, and run the whole test suite (serial and mpirun -np 2 tests).
# Time budget (doc/performance.md §2): the whole of this script from a fresh
# clone, every build included, within 25 minutes on the 2 cores of the
# project's machines; it prints the ten slowest tests after the suite. While
# working, the quick tier: `cd build && ctest -L quick -j2` (under 5 minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh
# OpenMPI refuses to run as root unless told that it is intended.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Build every test executable first: ctest only runs them.
cmake --build build -j"$(nproc)" --target test_executables
cd build
status=0
ctest --output-on-failure -j"$(nproc)" | tee ctest.log || status=$?
# The ten slowest tests of this run (ctest keeps each test's time in its cost
# data), then ctest's own closing line again, so that it stays the last one.
echo "The ten slowest tests [s]:"
# (awk, not head, takes the first ten: it reads sort's output to the end, so
# that sort never writes into a closed pipe, which pipefail would report.)
awk '/^---/ { exit } { print }' Testing/Temporary/CTestCostData.txt | sort -k3 -g -r |
  awk 'NR <= 10 { printf "  %8.1f  %s\n", $3, $1 }'
grep 'tests passed' ctest.log | tail -1 || true
exit "$status"
