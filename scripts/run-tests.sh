#!/bin/bash
# Install, build, and run the whole test suite (serial and mpirun -np 2 tests).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh
# OpenMPI refuses to run as root unless told that it is intended.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Tests are compiled by ctest itself (deal.II's test macros), two at a time.
cd build
ctest --output-on-failure -j"$(nproc)"
